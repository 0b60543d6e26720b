// sweep_summary() against summarise(sweep()) on the same requests (solve/sweep_summary.hpp): the same status
// for every input, the same largest residual, limits and singular poses, with the limits and singular poses
// where the mechanisms put them (the paper example's dead point and parabola end, the anti-parallelogram's
// change points at 90 and 270 degrees).
#define BOOST_TEST_MODULE solve_sweep_summary
#include <boost/test/unit_test.hpp>

#include "mechanisms.hpp"

using namespace rollkin;
using namespace rollkin::testing;

namespace {

struct Both {
  SweepSummary<double> alone, of_result;
  SweepResult<double> result;
};

Both sweep_both_ways(const Fixture<double>& f, const std::vector<double>& inputs) {
  SolveData<double> sd(f.mech);
  VectorX<double> q;
  const SolveReport<double> assembly = assemble_fixture(f, q, sd);
  BOOST_TEST_REQUIRE(assembly.ok());
  Both b;
  b.result = sweep(f.mech, sd, q, assembly, 0, inputs);
  b.of_result = summarise(b.result);
  SolveData<double> sd2(f.mech);
  VectorX<double> q2;
  assemble_fixture(f, q2, sd2);
  b.alone = sweep_summary(f.mech, sd2, q2, assembly, 0, inputs);
  return b;
}

void check_equal(const SweepSummary<double>& a, const SweepSummary<double>& b) {
  BOOST_TEST_REQUIRE(a.size() == b.size());
  for (std::size_t k = 0; k < a.size(); ++k) BOOST_TEST((a.status[k] == b.status[k]), "input " << k);
  BOOST_TEST(a.max_residual == b.max_residual);
  BOOST_TEST_REQUIRE(a.limits.size() == b.limits.size());
  for (std::size_t i = 0; i < a.limits.size(); ++i) {
    BOOST_TEST((a.limits[i].status == b.limits[i].status));
    BOOST_TEST(a.limits[i].limit_input == b.limits[i].limit_input);
  }
  BOOST_TEST_REQUIRE(a.singular.size() == b.singular.size());
  for (std::size_t i = 0; i < a.singular.size(); ++i) BOOST_TEST(a.singular[i].index == b.singular[i].index);
}

}  // namespace

BOOST_AUTO_TEST_CASE(paper_example_past_both_limits) {
  // Down from the assembly (0 deg) to the dead point near -57 deg, up to the parabola's end near 107 deg.
  const std::vector<double> inputs = degrees<double>(-70, 120);
  const Both b = sweep_both_ways(paper_fourbar<double>(), inputs);
  check_equal(b.alone, b.of_result);
  BOOST_TEST_REQUIRE(b.alone.limits.size() == 2u);
  const SolveReport<double>& dead = b.alone.limits[0].status == SolveStatus::DeadPoint ? b.alone.limits[0] : b.alone.limits[1];
  const SolveReport<double>& end = b.alone.limits[0].status == SolveStatus::DomainExit ? b.alone.limits[0] : b.alone.limits[1];
  BOOST_TEST((dead.status == SolveStatus::DeadPoint && end.status == SolveStatus::DomainExit));
  // Solved exactly between the limits, the largest residual that of the stored poses.
  double largest = 0;
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    const bool inside = inputs[k] > dead.limit_input && inputs[k] < end.limit_input;
    BOOST_TEST((b.alone.status[k] == SolveStatus::Converged) == inside, "input " << inputs[k]);
    if (b.result.ok(k)) largest = std::max(largest, b.result.report(k).residual);
  }
  BOOST_TEST(b.alone.solved() == 163u);  // -56 .. 106 degrees: the dead point lies at -56.98, the end at 106.71
  BOOST_TEST(b.alone.max_residual == largest);
  BOOST_TEST(b.alone.singular.empty());
}

BOOST_AUTO_TEST_CASE(anti_parallelogram_singular_poses_in_input_order) {
  // From the assembly at 0 deg up to 360 and down to -360: the change points at 90 and 270 deg (and -90,
  // -270) are on the grid, reported singular in the order of the inputs whichever side reached them first.
  std::vector<double> inputs;
  for (int d = 360; d >= -360; d -= 1) inputs.push_back(d * pi<double>() / 180);
  const Both b = sweep_both_ways(antiparallelogram<double>(), inputs);
  check_equal(b.alone, b.of_result);
  for (std::size_t i = 0; i < b.alone.singular.size(); ++i) {
    const double deg = inputs[b.alone.singular[i].index] * 180 / pi<double>();
    BOOST_TEST(std::abs(std::remainder(deg - 90, 180.0)) < 1e-9, "singular at " << deg << " deg");
    if (i > 0) BOOST_TEST(b.alone.singular[i].index > b.alone.singular[i - 1].index);
  }
  BOOST_TEST_MESSAGE(b.alone.singular.size() << " singular poses");
  BOOST_TEST(b.alone.limits.empty());
  BOOST_TEST(b.alone.solved() + b.alone.singular.size() == inputs.size());
}
