// sweep_summary() against summarise(sweep()) on the same requests (solve/sweep_summary.hpp): the same status
// for every input, the same largest residual, limits and singular poses, with the limits and singular poses
// where the mechanisms put them (the paper example's dead point and parabola end, the anti-parallelogram's
// change points at 90 and 270 degrees). On fine grids the summary interpolates the poses between its strides
// (dense output, solve/continuation.hpp): those poses are checked against the solved ones of sweep() and
// against the residual tolerance.
#define BOOST_TEST_MODULE solve_sweep_summary
#include <boost/test/unit_test.hpp>

#include "rollkin/samples/mechanisms.hpp"
#include "rollkin/solve/continuation.hpp"

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

/// Same statuses, limits and singular poses; the same largest residual where both solved the same poses
/// (`same_poses`), otherwise both within Newton's tolerance.
void check_equal(const SweepSummary<double>& a, const SweepSummary<double>& b, bool same_poses = true) {
  BOOST_TEST_REQUIRE(a.size() == b.size());
  for (std::size_t k = 0; k < a.size(); ++k) BOOST_TEST((a.status[k] == b.status[k]), "input " << k);
  if (same_poses) BOOST_TEST(a.max_residual == b.max_residual);
  const double tolerance = NewtonSettings<double>{}.residual_tolerance;
  BOOST_TEST((a.max_residual <= tolerance && b.max_residual <= tolerance));
  BOOST_TEST_REQUIRE(a.limits.size() == b.limits.size());
  for (std::size_t i = 0; i < a.limits.size(); ++i) {
    BOOST_TEST((a.limits[i].status == b.limits[i].status));
    BOOST_TEST(a.limits[i].limit_input == b.limits[i].limit_input);
  }
  BOOST_TEST_REQUIRE(a.singular.size() == b.singular.size());
  for (std::size_t i = 0; i < a.singular.size(); ++i) BOOST_TEST(a.singular[i].index == b.singular[i].index);
}

/// What the summary's continuation reports into a sink that keeps no values (sweep_into), with the values it
/// passes for every pose (those a SweepSummary drops): the interpolated poses' values, for comparison with sweep()'s solved ones.
struct Recorded final : SweepSink<double> {
  MatrixX<double> q;
  std::vector<SolveReport<double>> reports, limits;
  std::vector<bool> interpolated;
  bool keeps_values() const override { return false; }
  void add_limit(const SolveReport<double>& limit) override { limits.push_back(limit); }
  void set_pose(std::size_t k, const VectorX<double>& x, const VectorX<double>&, const SolveReport<double>& r) override {
    q.col(static_cast<Eigen::Index>(k)) = x;
    set_report(k, r);
  }
  void set_interpolated_pose(std::size_t k, const VectorX<double>& x, const SolveReport<double>& r) override {
    set_pose(k, x, x, r);
    interpolated[k] = true;
  }
  void set_report(std::size_t k, const SolveReport<double>& r) override { reports[k] = r; }
  void share_report(std::size_t k, std::size_t like) override { reports[k] = reports[like]; }
};

/// Dense output on `inputs` against sweep(): the same status for every input; every plainly solved pose
/// within `tolerance` (scaled) of the solved one and with a residual within Newton's tolerance. Returns the
/// number of interpolated poses, which the summary counts too.
std::size_t check_interpolated(const Fixture<double>& f, const std::vector<double>& inputs, double tolerance) {
  const Both b = sweep_both_ways(f, inputs);
  check_equal(b.alone, b.of_result, false);
  SolveData<double> sd(f.mech);
  VectorX<double> q;
  const SolveReport<double> assembly = assemble_fixture(f, q, sd);
  Recorded r;
  r.q = MatrixX<double>::Zero(q.size(), static_cast<Eigen::Index>(inputs.size()));
  r.reports.assign(inputs.size(), SolveReport<double>{});
  r.interpolated.assign(inputs.size(), false);
  sweep_into(f.mech, sd, q, assembly, 0, inputs, ContinuationSettings<double>{}, r);
  std::size_t interpolated = 0;
  double worst = 0;
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    BOOST_TEST((r.reports[k].status == b.result.status(k)), "input " << k);
    if (!b.result.ok(k)) continue;
    BOOST_TEST(r.reports[k].residual <= sd.settings.residual_tolerance, "input " << k);
    for (Eigen::Index i = 0; i < q.size(); ++i)
      worst = std::max(worst, std::abs(r.q(i, static_cast<Eigen::Index>(k)) - b.result.q(k)(i)) / f.mech.variable_scale(static_cast<int>(i)));
    if (r.interpolated[k]) ++interpolated;
  }
  BOOST_TEST(worst <= tolerance);
  BOOST_TEST(b.alone.interpolated == interpolated);
  BOOST_TEST_MESSAGE(interpolated << " of " << inputs.size() << " poses interpolated, largest difference " << worst);
  return interpolated;
}

}  // namespace

BOOST_AUTO_TEST_CASE(fine_grid_is_interpolated_to_round_off) {
  // The paper example from -50 to 100 degrees in steps of 0.005: the strides span about 0.02 degrees (four
  // or five steps), so most poses are interpolated; they agree with the solved ones (checked against MPFR in test_solve_mpfr)
  // to round-off.
  std::vector<double> inputs;
  for (int k = 0; k <= 30000; ++k) inputs.push_back((-50 + k * 0.005) * pi<double>() / 180);
  const std::size_t interpolated = check_interpolated(paper_fourbar<double>(), inputs, 1e-13);
  BOOST_TEST(interpolated > inputs.size() / 2);
}

BOOST_AUTO_TEST_CASE(fine_grid_at_the_round_off_floor_keeps_interpolating) {
  // Trains of 3, 9 and 65 pivoted rolling disks from 0 to 360 degrees in steps of 0.1: every variable is
  // linear in the input (phi_k = +-(r_0 / r_k) phi_0, contacts fixed on the line of centres), so the cubic is
  // exact and the interpolated poses' residuals are round-off alone, which grows with the number of rows; the
  // old rule (aiming at 8 epsilon) shrank the span whenever it was above 5.2 epsilon. It must not shrink on
  // round-off:
  // the old rule interpolated 2,473, 1,963 and 340 of these 3,601 poses with 3, 9 and 65 disks. Nor when the
  // stride's end lies below that round-off: with 65 disks (condition 9.5e3) Newton refines the stride ends
  // to 2-4 epsilon while the interpolated poses' round-off reaches 8; compared with the end's residual alone,
  // the span shrank at most strides (3,520, 3,518 and 3,271 interpolated, 288 strides with 65 disks against
  // 80 with 9). With the residuals next to the stride's ends as the round-off level: 3,519, 3,520 and 3,473.
  // Each interpolated pose agrees with sweep()'s solved one to 1e-13, and to 1e-12 with 65 disks, whose 192
  // unknowns are solved only to their larger condition times round-off.
  std::vector<double> inputs;
  for (int k = 0; k <= 3600; ++k) inputs.push_back(k * 0.1 * pi<double>() / 180);
  for (int n : {2, 8, 64}) {
    BOOST_TEST_CONTEXT("train of " << n + 1 << " disks") {
      const std::size_t interpolated = check_interpolated(disk_train<double>(n), inputs, n < 64 ? 1e-13 : 1e-12);
      BOOST_TEST(interpolated > inputs.size() * 19 / 20);
    }
  }
}

BOOST_AUTO_TEST_CASE(fine_grid_through_change_points_keeps_statuses) {
  // The anti-parallelogram from -360 to 360 degrees in steps of 0.01: the strides stop at the change points
  // (singular poses reported as by sweep(), at the same inputs), and next to them, where the condition grows,
  // the interpolated poses agree with the solved ones as closely as those are accurate there.
  std::vector<double> inputs;
  for (int k = 36000; k >= -36000; --k) inputs.push_back(k * 0.01 * pi<double>() / 180);
  const std::size_t interpolated = check_interpolated(antiparallelogram<double>(), inputs, 1e-9);
  BOOST_TEST(interpolated > inputs.size() / 2);
}

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
