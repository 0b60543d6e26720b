// Bounded work and scale invariance (docs/reliability.md, "Numbers"): every step and tolerance of the solve layer is
// relative to the scene's size, so a scene scaled by 1e-6 or 1e6 costs the same Newton evaluations and gives the
// same angles; the sub-step estimate that bounds a request's work is checked against its definition.
#define BOOST_TEST_MODULE solve_scale
#include <boost/test/unit_test.hpp>

#include "rollkin/samples/mechanisms.hpp"
#include "rollkin/solve/continuation.hpp"

#include <cmath>

using namespace rollkin;
using namespace rollkin::testing;

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180;

struct Run {
  SweepResult<double> result;
  long evaluations = 0;
};

template <class F> Run solve_counted(F& f, const std::vector<double>& inputs) {
  SolveData<double> sd(f.mech);
  VectorX<double> q;
  const auto rep = assemble_fixture(f, q, sd);
  Run r{sweep(f.mech, sd, q, rep, 0, inputs)};
  for (const auto& p : r.result.poses) r.evaluations += p.report.evaluations;
  return r;
}

}  // namespace

BOOST_AUTO_TEST_CASE(paper_example_scaled_by_1e_minus6_and_1e6_costs_the_same_and_agrees) {
  const auto inputs = degrees<double>(-50, 100);
  auto unit = paper_fourbar<double>(1.0);
  const Run base = solve_counted(unit, inputs);
  BOOST_TEST_REQUIRE(base.result.all_solved());
  for (double scale : {1e-6, 1e6}) {
    auto f = paper_fourbar<double>(scale);
    const Run run = solve_counted(f, inputs);
    BOOST_TEST_REQUIRE(run.result.all_solved(), "scale " << scale);
    BOOST_TEST_MESSAGE("paper example, 151 poses: " << base.evaluations << " Newton evaluations at scale 1, "
                                                   << run.evaluations << " at scale " << scale);
    BOOST_TEST(run.evaluations <= 3 * base.evaluations, "scale " << scale << ": " << run.evaluations << " vs " << base.evaluations);
    BOOST_TEST(3 * run.evaluations >= base.evaluations, "scale " << scale);
    for (std::size_t i = 0; i < inputs.size(); ++i)
      for (int v : {2, 3, 4, 5}) {  // theta23, theta34, theta4, theta5
        const double d = std::abs(run.result.poses[i].q(v) - base.result.poses[i].q(v)) / kDeg;
        BOOST_TEST(d < 1e-9, "scale " << scale << " theta2 " << inputs[i] / kDeg << " variable " << v << ": " << d << " deg");
      }
  }
}

BOOST_AUTO_TEST_CASE(prismatic_driver_steps_scale_with_the_scene) {
  // A disk rolling on a line, driven by its slider over ten radii: the sub-steps are relative to the disk's
  // size, so r = 1e-4 and 1e4 take the same steps as r = 1, and the disk turns -x/r in each (cycloid).
  std::vector<double> xs;
  for (int k = 0; k <= 20; ++k) xs.push_back(0.5 * k);
  auto unit = disk_on_line<double>(1.0);
  const Run base = solve_counted(unit, xs);
  BOOST_TEST_REQUIRE(base.result.all_solved());
  for (double r : {1e-4, 1e4}) {
    auto f = disk_on_line<double>(r);
    std::vector<double> scaled;
    for (double x : xs) scaled.push_back(x * r);
    const Run run = solve_counted(f, scaled);
    BOOST_TEST_REQUIRE(run.result.all_solved(), "r " << r);
    BOOST_TEST(run.evaluations <= 3 * base.evaluations, "r " << r << ": " << run.evaluations << " vs " << base.evaluations);
    BOOST_TEST(3 * run.evaluations >= base.evaluations, "r " << r);
    for (const auto& p : run.result.poses) BOOST_TEST(std::abs(p.q(1) + p.input / r) / kDeg < 1e-9, "r " << r);
  }
}

BOOST_AUTO_TEST_CASE(substep_estimate_is_travel_over_the_largest_step_plus_the_values) {
  // Paper example assembled at theta2 = 0, swept -50..100 deg: travel 50 + 100 deg in 5 deg sub-steps, 151 values.
  auto f = paper_fourbar<double>(1.0);
  const double paper = estimate_substeps(f.mech, f.guess, 0, degrees<double>(-50, 100));
  BOOST_TEST(std::abs(paper - (150.0 / 5 + 151)) < 1e-9);
  // All values on one side: the travel is from the assembly input to the far end.
  BOOST_TEST(std::abs(estimate_substeps(f.mech, f.guess, 0, degrees<double>(10, 20, 10)) - (20.0 / 5 + 2)) < 1e-9);
  // A prismatic driver: lengths in units of the scene's scale, so scaling the scene leaves the estimate.
  auto unit_disk = disk_on_line<double>(1.0);
  const double unit_steps = estimate_substeps(unit_disk.mech, unit_disk.guess, 0, std::vector<double>{-3, 7});
  for (double r : {1e-6, 1.0, 1e6}) {
    auto disk = disk_on_line<double>(r);
    const double steps = estimate_substeps(disk.mech, disk.guess, 0, std::vector<double>{-3 * r, 7 * r});
    const double expected = 10 * r / (ContinuationSettings<double>().max_step * disk.mech.length_scale) + 2;
    BOOST_TEST(std::abs(steps - expected) < 1e-9 * expected, "r " << r);
    BOOST_TEST(std::abs(steps - unit_steps) < 1e-6 * steps, "r " << r);
  }
}
