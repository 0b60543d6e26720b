// Numerical stress tests of the double solver (each well under 30 s):
//  - approach to the paper example's dead point: located to 1e-6 against the 50-digit location
//    (tests/golden/paper_fourbar_dead_point_50digits.txt, from test_solve_mpfr), continuity of every pose on
//    a fine sweep toward it, and no flip of the assembly mode;
//  - the osculating variant: reported singular, never a Converged pose with a singular Jacobian;
//  - the paper example scaled by 1e-3 and 1e4: the same angles as at scale 1;
//  - long sweeps: 10^5 steps over 100 turns of elliptical gears, 100 revolutions of a planet in a ring, and
//    the paper example swept back and forth: constraints stay at round-off, no drift, closed forms hold;
//  - sampled and Bezier contours: coarse, noisy (smoothed), nearly collinear samples, contact exactly at a
//    sample and at a Bezier joint: converges, within the contour's own sampling error of the analytic answer.
#define BOOST_TEST_MODULE stress
#include <boost/test/unit_test.hpp>

#include "rollkin/samples/mechanisms.hpp"
#include "rollkin/solve/continuation.hpp"
#include "rollkin/builder.hpp"
#include "rollkin/io/units.hpp"

#include <chrono>
#include <fstream>
#include <random>
#include <string>

using namespace rollkin;
using namespace rollkin::testing;

namespace {

enum Var { theta2, x, theta23, theta34, theta4, theta5 };

struct Timer {
  std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); }
};

struct Run {
  Fixture<double> f;
  SolveData<double> sd;
  VectorX<double> q0;
  SolveReport<double> assembly;
  explicit Run(Fixture<double> fixture) : f(std::move(fixture)), sd(f.mech) { assembly = assemble_fixture(f, q0, sd); }
  SweepResult<double> sweep_to(const std::vector<double>& inputs, const VectorX<double>* from = nullptr) {
    return sweep(f.mech, sd, from ? *from : q0, assembly, 0, inputs);
  }
};

/// Largest |residual| (loops and rolling rows) at q, arc lengths from the assembly pose q0.
double max_residual(const Mechanism<double>& m, const VectorX<double>& q0, const VectorX<double>& q) {
  KinematicsData<double> d(m);
  d.reference = q0;
  evaluate_pairs<double>(m, q, nullptr, 1, d);
  compute_constraints(m, q, d);
  return d.residual.cwiseAbs().maxCoeff();
}

/// The 50-digit dead point of the paper example (theta2 in radians), as test_solve_mpfr located it.
double mpfr_dead_point() {
  std::ifstream in(std::string(ROLLKIN_SOURCE_DIR) + "/tests/golden/paper_fourbar_dead_point_50digits.txt");
  BOOST_TEST_REQUIRE(in.good());
  std::string comment, t;
  std::getline(in, comment);
  in >> t;
  return deg_to_rad(std::stod(t));
}

/// Assembly-mode indicator of the paper example: which side of the line O_B -> disk 3's centre disk 4's
/// centre lies on (the two assemblies are mirror images about that line).
double assembly_mode(const Mechanism<double>& m, const VectorX<double>& q) {
  KinematicsData<double> d(m);
  evaluate_pairs<double>(m, q, nullptr, 1, d);
  const auto pose = link_poses(m, d);
  const Vec2<double> ob(7, -2), c3 = pose[2].translation(), c4 = pose[3].act(Vec2<double>(2, 0));
  return cross2<double>(c3 - ob, c4 - ob);
}

/// The paper example (docs/method.md section 4) with link 2's parabola given as `shape` (same placement, x
/// increasing along the shape), assembled with the contact at parameter u_vertex (the parabola's vertex).
Fixture<double> paper_with_profile(ProfileShape<double> shape, double u_vertex) {
  MechanismBuilder<double> b;
  const int l1 = b.link("link1", true), l2 = b.link("link2"), l3 = b.link("link3"), l4 = b.link("link4");
  const int par = b.contour(l2, "parabola", std::move(shape), SE2<double>(pi<double>() / 2, Vec2<double>(2, 0)));
  const int rim3 = b.contour(l3, "rim", Circle<double>(1));
  const int rim4 = b.contour(l4, "rim", Circle<double>(4), SE2<double>(0, Vec2<double>(2, 0)));
  const int oa = b.revolute("O_A", l1, l2, SE2<double>(), SE2<double>(), "theta2");
  b.contact("A", true, par, rim3, "x", "theta23");
  b.contact("B", true, rim3, rim4, "theta34", "theta4");
  b.revolute("O_B", l1, l4, SE2<double>(0, Vec2<double>(7, -2)), SE2<double>(), "theta5");
  b.driver(oa);
  Fixture<double> f{b.build(), VectorX<double>(6), {1, 2}};
  const double deg = pi<double>() / 180;
  f.guess << 0, u_vertex, 180 * deg, -3 * deg, 117 * deg, 60 * deg;
  return f;
}

/// Largest distance from the shape (parameter range [lo, hi]) to the parabola y = x^2 / 2 in its frame,
/// measured vertically on a fine grid: the contour's own sampling error.
template <class Shape> double parabola_deviation(const Shape& s, double lo, double hi) {
  double worst = 0;
  for (int k = 0; k <= 4000; ++k) {
    const Vec2<double> p = s.jet(lo + (hi - lo) * k / 4000.0, 0).p;
    worst = std::max(worst, std::abs(p.y() - 0.5 * p.x() * p.x()));
  }
  return worst;
}

/// Pair angles theta23, theta34, theta4, theta5 of a profile variant against the analytic paper example
/// over theta2 in [-50, 100] deg (these do not depend on how link 2's contour is parametrised).
double angle_error_vs_analytic(const Fixture<double>& f, const std::string& what) {
  Run analytic(paper_fourbar<double>());
  Run run(f);
  BOOST_TEST_REQUIRE(run.assembly.ok(), what << ": " << run.assembly.detail);
  const auto inputs = degrees<double>(-50, 100, 2);
  const auto ra = analytic.sweep_to(inputs), rs = run.sweep_to(inputs);
  BOOST_TEST_REQUIRE(ra.all_solved());
  BOOST_TEST_REQUIRE(rs.all_solved(), what);
  double worst = 0, worst_res = 0;
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    for (int v : {theta23, theta34, theta4, theta5})
      worst = std::max(worst, std::abs(rs.poses[k].q(v) - ra.poses[k].q(v)));
    worst_res = std::max(worst_res, max_residual(run.f.mech, run.q0, rs.poses[k].q));
  }
  BOOST_TEST(worst_res < 1e-10, what << ": residual " << worst_res);
  return worst;
}

std::vector<Vec2<double>> parabola_samples(const std::vector<double>& xs, double noise = 0, unsigned seed = 1) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-noise, noise);
  std::vector<Vec2<double>> s;
  for (double xx : xs) s.emplace_back(xx, 0.5 * xx * xx + (noise > 0 ? u(gen) : 0.0));
  return s;
}

std::vector<double> grid(double lo, double hi, int n) {
  std::vector<double> v;
  for (int k = 0; k < n; ++k) v.push_back(lo + (hi - lo) * k / (n - 1));
  return v;
}

}  // namespace

// ---- dead points -----------------------------------------------------------------------------------------

BOOST_AUTO_TEST_CASE(approach_to_dead_point_is_continuous_and_stays_on_its_branch) {
  Timer timer;
  Run p(paper_fourbar<double>());
  BOOST_TEST_REQUIRE(p.assembly.ok());
  const double t_ref = mpfr_dead_point();
  // Located by the continuation (sweep past it).
  const auto past = p.sweep_to(degrees<double>(-70, 0, 1));
  BOOST_TEST_REQUIRE(past.limits.size() == 1u);
  BOOST_TEST(past.limits[0].status == SolveStatus::DeadPoint);
  const double located = past.limits[0].limit_input;
  BOOST_TEST_MESSAGE("dead point: continuation " << rad_to_deg(located) << " deg, 50-digit reference "
                                                 << rad_to_deg(t_ref) << " deg, error " << std::abs(located - t_ref) << " rad");
  BOOST_TEST(std::abs(located - t_ref) < 1e-6);
  BOOST_TEST(located >= t_ref);  // never past the true limit

  // Fine sweep toward the limit: 0.05 deg steps down to 1 deg away, then geometrically to 1e-6 rad away.
  std::vector<double> inputs;
  for (double d = 0; d > rad_to_deg(t_ref) + 1; d -= 0.05) inputs.push_back(deg_to_rad(d));
  for (double gap = deg_to_rad(1.0); gap >= 1e-6 * 0.999; gap /= 1.5) inputs.push_back(t_ref + gap);
  inputs.push_back(t_ref + 1e-6);
  const auto r = p.sweep_to(inputs);
  BOOST_TEST_REQUIRE(r.all_solved(), "the sweep must converge up to 1e-6 from the limit");
  const double mode0 = assembly_mode(p.f.mech, p.q0);
  double smallest_mode = std::abs(mode0), worst_ratio = 0;
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    const auto& pose = r.poses[k];
    const double mode = assembly_mode(p.f.mech, pose.q);
    BOOST_TEST((mode > 0) == (mode0 > 0), "assembly mode flipped at " << rad_to_deg(pose.input) << " deg");
    smallest_mode = std::min(smallest_mode, std::abs(mode));
    BOOST_TEST(max_residual(p.f.mech, p.q0, pose.q) < 1e-12);
    if (k == 0) continue;
    // |speed| grows monotonically toward a fold, so a step's change is bounded by the larger end speed.
    const auto& prev = r.poses[k - 1];
    const double dt = std::abs(pose.input - prev.input);
    for (int v = 1; v < 6; ++v) {
      const double bound = std::max(std::abs(pose.qdot(v)), std::abs(prev.qdot(v))) * dt * 1.05 + 1e-12;
      const double jump = std::abs(pose.q(v) - prev.q(v));
      worst_ratio = std::max(worst_ratio, jump / bound);
      BOOST_TEST(jump <= bound, "variable " << v << " jumps " << jump << " > " << bound << " at " << pose.input);
    }
  }
  BOOST_TEST_MESSAGE("approach to the dead point: " << inputs.size() << " poses, last at limit + 1e-6 rad, speed there "
                                                    << r.poses.back().qdot.cwiseAbs().maxCoeff()
                                                    << ", largest jump / (speed x step) " << worst_ratio
                                                    << ", assembly-mode indicator from " << mode0 << " down to "
                                                    << smallest_mode << " (no flip); " << timer.seconds() << " s");
  // Past the reference limit this branch has no pose: the continuation from the last pose stops with a dead
  // point; plain Newton started there either fails or lands on a distant pose of another branch (which the
  // continuation's branch check is there to reject).
  // (Started this close to the fold the classification says no_convergence rather than dead_point: the
  // dead-point test compares the condition with the sweep's start, which is already near-singular here.)
  const VectorX<double> last_q = r.poses.back().q;
  const auto on = p.sweep_to({t_ref - 1e-6}, &last_q);
  BOOST_TEST(!on.poses[0].report.ok());
  BOOST_TEST((on.poses[0].report.status == SolveStatus::DeadPoint || on.poses[0].report.status == SolveStatus::NoConvergence));
  VectorX<double> beyond = r.poses.back().q;
  beyond(theta2) = t_ref - 1e-6;
  const auto b = solve_position(p.f.mech, beyond, p.sd);
  const double newton_jump = (beyond - r.poses.back().q).cwiseAbs().maxCoeff();
  BOOST_TEST_MESSAGE("plain Newton 1e-6 past the limit: " << b.status << ", moved " << newton_jump
                                                          << ", assembly-mode indicator " << assembly_mode(p.f.mech, beyond));
  BOOST_TEST((!b.ok() || newton_jump > 0.1));
}

BOOST_AUTO_TEST_CASE(osculating_contact_is_reported_singular_never_answered) {
  auto f = paper_fourbar<double>(1.0, true);
  SolveData<double> sd(f.mech);
  VectorX<double> q;
  const auto rep = assemble_fixture(f, q, sd);
  BOOST_TEST(!rep.ok());
  BOOST_TEST(rep.rank < rep.unknowns);
  BOOST_TEST_MESSAGE("osculating assembly: " << rep.status << ", rank " << rep.rank << " of " << rep.unknowns << ": " << rep.detail);
  // A sweep on top of it reports the assembly failure for every input, never a pose.
  const auto r = sweep(f.mech, sd, q, rep, 0, degrees<double>(-20, 20, 5));
  for (const auto& p : r.poses) BOOST_TEST(!p.report.ok());
  // Newton from perturbed guesses near the osculating pose: whatever it returns, a Converged pose must
  // have a full-rank, finite-condition Jacobian (no wrong answer from a singular system).
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1e-3, 1e-3);
  int converged = 0, refused = 0;
  double worst_condition = 0;
  for (int trial = 0; trial < 200; ++trial) {
    VectorX<double> g = f.guess;
    for (int i = 1; i < 6; ++i) g(i) += u(gen);
    const auto rr = assemble(f.mech, g, sd, f.held);
    if (rr.ok()) {
      ++converged;
      BOOST_TEST(rr.rank == rr.unknowns);
      BOOST_TEST(rr.condition < 1e14);  // near-osculating (|x| ~ 1e-3), but not singular
      worst_condition = std::max(worst_condition, rr.condition);
      BOOST_TEST(max_residual(f.mech, sd.kin.reference, g) < 1e-10);
    } else {
      ++refused;
      BOOST_TEST((rr.status == SolveStatus::Underdetermined || rr.status == SolveStatus::CannotAssemble ||
                  rr.status == SolveStatus::NoConvergence));
    }
  }
  BOOST_TEST_MESSAGE("osculating neighbourhood: " << converged << " full-rank poses (largest condition "
                                              << worst_condition << "), " << refused << " refused");
}

// ---- scale -----------------------------------------------------------------------------------------------

BOOST_AUTO_TEST_CASE(scaled_mechanisms_give_the_same_angles) {
  Run unit(paper_fourbar<double>());
  const auto inputs = degrees<double>(-50, 100, 5);
  const auto ru = unit.sweep_to(inputs);
  BOOST_TEST_REQUIRE(ru.all_solved());
  for (double scale : {1e-3, 1e4}) {
    auto f = paper_fourbar<double>(scale);
    f.guess(x) *= scale;
    Run s(f);
    BOOST_TEST_REQUIRE(s.assembly.ok());
    const auto rs = s.sweep_to(inputs);
    BOOST_TEST_REQUIRE(rs.all_solved(), "scale " << scale);
    double worst_angle = 0, worst_x = 0;
    for (std::size_t k = 0; k < inputs.size(); ++k) {
      for (int v : {theta23, theta34, theta4, theta5})
        worst_angle = std::max(worst_angle, std::abs(rs.poses[k].q(v) - ru.poses[k].q(v)));
      worst_x = std::max(worst_x, std::abs(rs.poses[k].q(x) / scale - ru.poses[k].q(x)));
    }
    BOOST_TEST_MESSAGE("scale " << scale << ": max angle difference " << worst_angle << " rad, x/scale " << worst_x);
    BOOST_TEST(worst_angle < 1e-10);
    BOOST_TEST(worst_x < 1e-10);
  }
}

// ---- long sweeps -----------------------------------------------------------------------------------------

BOOST_AUTO_TEST_CASE(hundred_thousand_steps_over_hundred_turns_of_elliptical_gears) {
  Timer timer;
  const double a = 2, e = 0.3;
  Run g(elliptical_gears<double>(a, e, true));
  BOOST_TEST_REQUIRE(g.assembly.ok());
  const int steps = 100000, turns = 100;
  std::vector<double> inputs(steps);
  for (int k = 0; k < steps; ++k) inputs[k] = 2 * pi<double>() * turns * (k + 1) / steps;
  const auto r = g.sweep_to(inputs);
  BOOST_TEST_REQUIRE(r.all_solved());
  double worst_res = 0, worst_closed = 0;
  for (int k = 999; k < steps; k += 1000) {  // every 1000th pose: constraints and the closed form
    const auto& p = r.poses[k];
    worst_res = std::max(worst_res, max_residual(g.f.mech, g.q0, p.q));
    const double expected = -2 * std::atan((1 - e) / (1 + e) * std::tan(p.input / 2));
    worst_closed = std::max(worst_closed, std::abs(wrap_angle(p.q(3) - expected)));
  }
  const auto& last = r.poses.back();
  const double end_res = max_residual(g.f.mech, g.q0, last.q);
  // After whole turns gear 2 has turned back exactly as many: phi2 = -phi1 (not only modulo 2 pi).
  const double drift = std::abs(last.q(3) + last.input);
  BOOST_TEST_MESSAGE("elliptical gears, " << steps << " steps over " << turns << " turns (" << timer.seconds()
                                          << " s): residual at the end " << end_res << ", max along " << worst_res
                                          << ", phi2 vs closed form max " << worst_closed << ", final phi2 + phi1 = "
                                          << drift);
  BOOST_TEST(end_res < 1e-9);
  BOOST_TEST(worst_res < 1e-9);
  BOOST_TEST(worst_closed < 1e-9);
  BOOST_TEST(drift < 1e-9);
}

BOOST_AUTO_TEST_CASE(hundred_revolutions_of_a_planet_in_a_ring) {
  Timer timer;
  const double R = 4, rr = 1;
  Run p(planet_on_arm<double>(R, rr, false));
  BOOST_TEST_REQUIRE(p.assembly.ok());
  const auto inputs = degrees<double>(1, 36000, 1);  // 100 revolutions of the arm, 1 degree steps
  const auto r = p.sweep_to(inputs);
  BOOST_TEST_REQUIRE(r.all_solved());
  const auto& last = r.poses.back();
  const double end_res = max_residual(p.f.mech, p.q0, last.q);
  const double planet_err = std::abs(last.q(0) + last.q(1) - (-(R - rr) / rr * last.input));
  BOOST_TEST_MESSAGE("planet in ring, 100 revolutions (" << timer.seconds() << " s): residual " << end_res
                                                         << ", planet angle vs -(R - r)/r phi: " << planet_err << " rad");
  BOOST_TEST(end_res < 1e-9);
  BOOST_TEST(planet_err < 1e-9);
}

BOOST_AUTO_TEST_CASE(paper_example_back_and_forth_does_not_drift) {
  Timer timer;
  Run p(paper_fourbar<double>());
  BOOST_TEST_REQUIRE(p.assembly.ok());
  std::vector<double> up, down;
  for (int k = -499; k <= 1000; ++k) up.push_back(deg_to_rad(k * 0.1));     // -49.9 .. 100
  for (int k = 999; k >= -500; --k) down.push_back(deg_to_rad(k * 0.1));    // 99.9 .. -50
  VectorX<double> q = p.q0;
  // Start at -50 deg, then 10 round trips -50 -> 100 -> -50 (30000 poses), each leg a sweep from the last pose.
  {
    const auto r = p.sweep_to({deg_to_rad(-50.0)});
    BOOST_TEST_REQUIRE(r.all_solved());
    q = r.poses[0].q;
  }
  const VectorX<double> start = q;
  double worst_res = 0;
  for (int trip = 0; trip < 10; ++trip) {
    for (const auto* leg : {&up, &down}) {
      const auto r = p.sweep_to(*leg, &q);
      BOOST_TEST_REQUIRE(r.all_solved());
      q = r.poses.back().q;
      worst_res = std::max(worst_res, max_residual(p.f.mech, p.q0, q));
    }
  }
  const double drift = (q - start).cwiseAbs().maxCoeff();
  BOOST_TEST_MESSAGE("paper example, 10 round trips -50 <-> 100 deg by 0.1 deg (30000 poses, " << timer.seconds()
                                                                                               << " s): drift " << drift
                                                                                               << ", residual " << worst_res);
  BOOST_TEST(drift < 1e-9);
  BOOST_TEST(worst_res < 1e-9);
}

// ---- sampled and Bezier contours ------------------------------------------------------------------------

BOOST_AUTO_TEST_CASE(bezier_parabola_with_a_joint_at_the_contact) {
  // Two exact quadratic segments split at the vertex: the assembly contact lies exactly on the joint (u = 1)
  // and the sweep crosses it. Exact geometry: only the arc-length quadrature differs from the closed form.
  const double a = 0.5;
  auto seg = [&](double x0, double x1) {
    return BezierSegment<double>{{Vec2<double>(x0, a * x0 * x0), Vec2<double>((x0 + x1) / 2, a * x0 * x1),
                                  Vec2<double>(x1, a * x1 * x1)},
                                 {}};
  };
  BezierPath<double> path({seg(-2, 0), seg(0, 2)}, false);
  BOOST_TEST(path.continuity() >= 1);
  const double err = angle_error_vs_analytic(paper_with_profile(path, 1.0), "Bezier joint at the vertex");
  BOOST_TEST_MESSAGE("Bezier parabola, joint at the contact: max angle error vs analytic " << err);
  BOOST_TEST(err < 1e-10);
}

BOOST_AUTO_TEST_CASE(sampled_parabola_coarse_fine_and_contact_at_a_sample) {
  // Samples including the vertex, so the assembly contact lies exactly on a sample; the error follows the
  // spline's own deviation from the parabola (4th order) and vanishes with it.
  double previous = 1;
  for (int n : {9, 17, 33, 65, 129}) {
    SplineOptions<double> opt;
    opt.end = SplineEnd::NotAKnot;
    const SampledProfile<double> s(parabola_samples(grid(-2, 2, n)), opt);
    const double u_vertex = s.knots()[n / 2];
    const double dev = parabola_deviation(s, 0, s.knots().back());
    const double err = angle_error_vs_analytic(paper_with_profile(s, u_vertex), "sampled n = " + std::to_string(n));
    BOOST_TEST_MESSAGE("sampled parabola, " << n << " samples: contour deviation " << dev << ", max angle error " << err);
    BOOST_TEST(err < 50 * dev + 1e-12);  // within the sampling error (angles ~ displacements / O(1) lengths)
    BOOST_TEST(err < previous);
    previous = err;
  }
}

BOOST_AUTO_TEST_CASE(noisy_samples_smoothed_stay_within_the_noise) {
  const double noise = 1e-5;
  SplineOptions<double> opt;
  opt.smoothing_tolerance = 2 * noise;
  const SampledProfile<double> s(parabola_samples(grid(-2, 2, 201), noise, 42), opt);
  const std::vector<double>& k = s.knots();
  const double u_vertex = k[100];  // a sample at x = 0 (plus noise in y)
  const double dev = parabola_deviation(s, 0, k.back());
  const double err = angle_error_vs_analytic(paper_with_profile(s, u_vertex), "noisy samples");
  BOOST_TEST_MESSAGE("noisy samples (+-" << noise << ", smoothed to " << 2 * noise << "): contour deviation " << dev
                                         << ", max angle error " << err);
  BOOST_TEST(dev < 5 * noise);
  BOOST_TEST(err < 1e-3);  // the noise's slope error integrated over the sweep, far below the geometry
}

BOOST_AUTO_TEST_CASE(nearly_collinear_samples_floor) {
  // A disk rolling on a floor given by exactly collinear samples with wildly uneven spacing (chords from
  // 1e-6 to 1) and a sample exactly under the assembly contact: the spline is the line to rounding, and the
  // disk must follow the cycloid closed form.
  std::vector<Vec2<double>> floor;
  for (double xx : {-10.0, -9.0, -5.0, -1.0, -1e-3, -1e-6, 0.0, 1e-6, 2e-6, 1e-3, 0.5, 1.0, 3.0, 7.0, 10.0})
    floor.emplace_back(xx, 0.0);
  const SampledProfile<double> s(floor);
  const double r = 0.75;
  MechanismBuilder<double> b;
  const int ground = b.link("ground", true), slider = b.link("slider"), disk = b.link("disk");
  // The floor's material lies below it: samples along +x, material on the right (reversed, u -> -u).
  const int line = b.contour(ground, "floor", s, SE2<double>(), true);
  const int rim = b.contour(disk, "rim", Circle<double>(r));
  const int drive = b.prismatic("slide", ground, slider, SE2<double>(0, Vec2<double>(0, r)), SE2<double>(), "x");
  b.revolute("axle", slider, disk, SE2<double>(), SE2<double>(), "theta");
  b.contact("tread", true, line, rim, "u", "v");
  b.driver(drive);
  Fixture<double> f{b.build(), VectorX<double>(4), {}};
  f.guess << 0, 0, -s.knots()[6], -pi<double>() / 2;  // contact on the sample at x = 0
  Run run(f);
  BOOST_TEST_REQUIRE(run.assembly.ok(), run.assembly.detail);
  std::vector<double> xs;
  for (int k = -40; k <= 40; ++k) xs.push_back(k * 0.2);
  const auto res = run.sweep_to(xs);
  BOOST_TEST_REQUIRE(res.all_solved());
  double worst = 0;
  for (const auto& p : res.poses) worst = std::max(worst, std::abs(p.q(1) + p.input / r));
  BOOST_TEST_MESSAGE("collinear uneven samples: disk angle vs cycloid, max error " << worst);
  BOOST_TEST(worst < 1e-10);
}
