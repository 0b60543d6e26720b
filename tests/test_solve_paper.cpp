// The reference example of docs/method.md section 4 over theta2 in [-50, 100] degrees: loop closure, no slip
// (arc lengths from the closed form of eq. 4, independent of the profile code), velocities and
// accelerations against finite differences, every pose of a fine sweep against an independent 2-unknown
// solver, and the two limits: the dead point and the parabola's end.
#define BOOST_TEST_MODULE solve_paper
#include <boost/test/unit_test.hpp>

#include "rollkin/samples/mechanisms.hpp"
#include "rollkin/solve/continuation.hpp"
#include "../bench/hand_paper.hpp"

using namespace rollkin;
using namespace rollkin::testing;

namespace {

enum Var { theta2, x, theta23, theta34, theta4, theta5 };

struct Paper {
  Fixture<double> f = paper_fourbar<double>();
  SolveData<double> sd{f.mech};
  VectorX<double> q0;
  SolveReport<double> assembly;
  Paper() { assembly = assemble_fixture(f, q0, sd); }
  SweepResult<double> run(const std::vector<double>& inputs) { return sweep(f.mech, sd, q0, assembly, 0, inputs); }
  /// Pose at one input by continuation from the assembly.
  VectorX<double> at(double input) {
    const auto r = run({input});
    BOOST_TEST_REQUIRE(r.poses[0].report.ok());
    return r.poses[0].q;
  }
};

/// Closed-form parabola arc length primitive, docs/method.md section 5 (a = 0.5).
double parabola_s(double xx) {
  const double a = 0.5, t = 2 * a * xx;
  return xx / 2 * std::sqrt(1 + t * t) + std::asinh(t) / (4 * a);
}

}  // namespace

BOOST_AUTO_TEST_CASE(assembly_matches_the_described_pose) {
  Paper p;
  BOOST_TEST_REQUIRE(p.assembly.ok());
  BOOST_TEST(p.assembly.rank == 5);
  BOOST_TEST(p.assembly.redundant() == 0);
  BOOST_TEST(p.q0(x) == 0.0);
  BOOST_TEST(p.q0(theta23) == pi<double>(), boost::test_tools::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(sweep_closes_loops_and_rolls_without_slip) {
  Paper p;
  const auto inputs = degrees<double>(-50, 100);
  const auto r = p.run(inputs);
  BOOST_TEST_REQUIRE(r.all_solved());
  BOOST_TEST(r.poses.size() == 151u);
  KinematicsData<double> d(p.f.mech);
  d.reference = p.q0;
  double worst_loop = 0, worst_slip_a = 0, worst_slip_b = 0;
  for (const auto& pose : r.poses) {
    BOOST_TEST(pose.q(theta2) == pose.input);
    evaluate_pairs<double>(p.f.mech, pose.q, nullptr, 1, d);
    compute_constraints<double>(p.f.mech, pose.q, d);
    worst_loop = std::max(worst_loop, d.residual.head<3>().cwiseAbs().maxCoeff());
    // eq. (7a)/(7b) with this project's signs: arc on one body equals minus the arc on the other.
    const double r3 = 1, r4 = 4;
    const double slip_a = (parabola_s(pose.q(x)) - parabola_s(p.q0(x))) + r3 * (pose.q(theta23) - p.q0(theta23));
    const double slip_b = r3 * (pose.q(theta34) - p.q0(theta34)) + r4 * (pose.q(theta4) - p.q0(theta4));
    worst_slip_a = std::max(worst_slip_a, std::abs(slip_a));
    worst_slip_b = std::max(worst_slip_b, std::abs(slip_b));
  }
  BOOST_TEST_MESSAGE("max loop residual " << worst_loop << ", slip A " << worst_slip_a << ", slip B " << worst_slip_b);
  BOOST_TEST(worst_loop < 1e-12);
  BOOST_TEST(worst_slip_a < 1e-12);
  BOOST_TEST(worst_slip_b < 1e-12);
}

BOOST_AUTO_TEST_CASE(a_fine_sweep_lands_every_pose_at_round_off_with_one_evaluation_each) {
  // Against bench/hand_paper.hpp, an independent solver of the same mechanism in 2 unknowns (closed-form
  // Jacobian and arc lengths) that steps Newton to round-off. Poses accepted as Newton left them (residual up
  // to the 64 eps tolerance) were up to 1.4e-13 off, and the next prediction, which extrapolates them, then
  // needed a Newton step: 1.5 evaluations per pose. The continuation's closing step keeps every pose exact.
  Paper p;
  const long n = 15001;  // -50 .. 100 degrees by 0.01
  std::vector<double> inputs(static_cast<std::size_t>(n));
  for (long k = 0; k < n; ++k) inputs[static_cast<std::size_t>(k)] = (-50 + 0.01 * static_cast<double>(k)) * pi<double>() / 180;
  const auto r = p.run(inputs);
  BOOST_TEST_REQUIRE(r.all_solved());
  std::vector<hand_paper::Unknowns> hand;
  BOOST_TEST_REQUIRE(hand_paper::sweep(-50, 0.01, n, hand) > 0);
  KinematicsData<double> d(p.f.mech);
  d.reference = p.q0;
  long evaluations = 0;
  double worst_residual = 0, worst_error = 0;
  for (std::size_t k = 0; k < r.size(); ++k) {
    evaluations += r.report(k).evaluations;
    evaluate_pairs<double>(p.f.mech, r.q(k), nullptr, 1, d);
    compute_constraints<double>(p.f.mech, r.q(k), d);
    worst_residual = std::max(worst_residual, weighted_max_norm<double>(d.residual, p.sd.row_weight));
    worst_error = std::max({worst_error, std::abs(r.q(k)(x) - hand[k].X), std::abs(r.q(k)(theta5) - hand[k].phi)});
  }
  const double eps = std::numeric_limits<double>::epsilon();
  BOOST_TEST_MESSAGE(double(evaluations) / n << " evaluations per pose, largest scaled residual " << worst_residual / eps
                                             << " eps, largest difference from the 2-unknown solver " << worst_error);
  BOOST_TEST(evaluations <= n + n / 20);
  BOOST_TEST(worst_residual <= 16 * eps);
  BOOST_TEST(worst_error <= 2e-14);
}

BOOST_AUTO_TEST_CASE(velocities_and_accelerations_match_finite_differences) {
  Paper p;
  const double h = 1e-4;
  for (int deg : {-45, -10, 0, 30, 95}) {
    const double t = deg * pi<double>() / 180;
    const auto r = p.run({t - h, t, t + h});
    BOOST_TEST_REQUIRE(r.all_solved());
    const VectorX<double> fd_vel = (r.poses[2].q - r.poses[0].q) / (2 * h);
    const VectorX<double>& vel = r.poses[1].qdot;
    BOOST_TEST((fd_vel - vel).cwiseAbs().maxCoeff() < 1e-6, "velocity at " << deg);
    // Accelerations at unit crank speed, zero crank acceleration, against differences of velocities.
    VectorX<double> q = r.poses[1].q;
    BOOST_TEST_REQUIRE(solve_position(p.f.mech, q, p.sd).ok());
    const VectorX<double> acc = solve_acceleration(p.f.mech, q, p.sd, vel, VectorX<double>(VectorX<double>::Zero(1)));
    const VectorX<double> fd_acc = (r.poses[2].qdot - r.poses[0].qdot) / (2 * h);
    BOOST_TEST((fd_acc - acc).cwiseAbs().maxCoeff() < 1e-5 * (1 + acc.cwiseAbs().maxCoeff()), "acceleration at " << deg);
  }
}

BOOST_AUTO_TEST_CASE(sweep_beyond_motion_limit_reports_dead_point) {
  Paper p;
  const auto r = p.run(degrees<double>(-70, 0));
  BOOST_TEST_REQUIRE(r.limits.size() == 1u);
  const auto& lim = r.limits[0];
  BOOST_TEST(lim.status == SolveStatus::DeadPoint);
  const double t_lim = lim.limit_input;
  BOOST_TEST_MESSAGE("dead point at theta2 = " << t_lim * 180 / pi<double>() << " deg");
  BOOST_TEST(t_lim < -50 * pi<double>() / 180);
  // Requested values past it are reported, nearer ones solved.
  for (const auto& pose : r.poses)
    BOOST_TEST(pose.report.ok() == (pose.input > t_lim), "input " << pose.input);
  // Located to 1e-6: a pose exists 1e-6 inside, none 1e-6 outside (Newton from the inside pose fails).
  const auto inside = p.run({t_lim + 1e-6});
  BOOST_TEST_REQUIRE(inside.poses[0].report.ok());
  VectorX<double> beyond = inside.poses[0].q;
  beyond(theta2) = t_lim - 1e-6;
  BOOST_TEST(!solve_position(p.f.mech, beyond, p.sd).ok());
  // And the unknowns' Jacobian is nearly singular there: 1e-6 from a fold the smallest singular value is
  // of order sqrt(1e-6), so the condition is hundreds of times the assembly's.
  VectorX<double> at = inside.poses[0].q;
  const auto rep = solve_position(p.f.mech, at, p.sd);
  BOOST_TEST(rep.condition > 300 * p.assembly.condition);
}

BOOST_AUTO_TEST_CASE(sweep_beyond_parabola_end_reports_domain_exit) {
  Paper p;
  const auto r = p.run(degrees<double>(95, 120));
  BOOST_TEST_REQUIRE(r.limits.size() == 1u);
  const auto& lim = r.limits[0];
  BOOST_TEST(lim.status == SolveStatus::DomainExit);
  BOOST_TEST(p.f.mech.pairs[lim.pair].name == "A");
  BOOST_TEST(p.f.mech.contours[lim.contour].name() == "link2.parabola");
  BOOST_TEST_MESSAGE("contact leaves the parabola at theta2 = " << lim.limit_input * 180 / pi<double>() << " deg");
  // At the reported input the contact sits at the end of the parabola, x = -2 (to the location tolerance
  // times dx/dtheta2).
  const VectorX<double> q = p.at(lim.limit_input);
  BOOST_TEST(std::abs(q(x) - (-2.0)) < 1e-7);
}

BOOST_AUTO_TEST_CASE(osculating_variant_is_reported_singular) {
  // Disk of radius 1/(2a) inside the cup: curvatures cancel at the vertex (docs/method.md sections 4-5).
  auto f = paper_fourbar<double>(1.0, true);
  SolveData<double> sd(f.mech);
  VectorX<double> q;
  const auto rep = assemble_fixture(f, q, sd);
  BOOST_TEST(!rep.ok());
  BOOST_TEST((rep.status == SolveStatus::Underdetermined || rep.status == SolveStatus::CannotAssemble));
  BOOST_TEST(rep.rank < rep.unknowns);
}
