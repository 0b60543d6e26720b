// The solver in MPFR (50 digits): the same templates as in double, checked against closed forms at a
// tolerance double cannot reach by accident (1e-40 .. 1e-45), and used as the reference for the double
// solver's accuracy (target: every pair variable to 1e-12 rad over the paper example's range).
//  - paper example, theta2 in [-50, 100] deg by 1 deg: double vs MPFR, MPFR loop residual, MPFR no-slip
//    against the parabola's closed-form arc length (docs/method.md section 5);
//  - hypocycloid, epicycloid and twin elliptical gears against their closed forms;
//  - Gauss-Legendre arc length (instead of the closed form) converging to the closed-form solution;
//  - the paper example's dead point located to ~1e-45 (fold of theta2 along the motion parametrised by the
//    contact parameter x), kept in tests/golden/paper_fourbar_dead_point_50digits.txt for test_stress.
// This is the one test translation unit that instantiates the solver in mpfr50.
#define BOOST_TEST_MODULE solve_mpfr
#include <boost/test/unit_test.hpp>

#include "rollkin/samples/mechanisms.hpp"
#include "rollkin/io/units.hpp"
#include "rollkin/scalar_mpfr.hpp"
#include "rollkin/solve/mpfr50_instances.hpp"

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <string>

using namespace rollkin;
using namespace rollkin::testing;
using M = mpfr50;

namespace {

enum Var { theta2, x, theta23, theta34, theta4, theta5 };

M dec(const char* s) { return M(std::string(s)); }

template <class S> struct Run {
  Fixture<S> f;
  SolveData<S> sd;
  VectorX<S> q0;
  SolveReport<S> assembly;
  explicit Run(Fixture<S> fixture) : f(std::move(fixture)), sd(f.mech) { assembly = assemble_fixture(f, q0, sd); }
  SweepResult<S> sweep_to(const std::vector<S>& inputs) { return sweep(f.mech, sd, q0, assembly, 0, inputs); }
};

template <class S> S max_residual(const Mechanism<S>& m, const VectorX<S>& q0, const VectorX<S>& q) {
  KinematicsData<S> d(m);
  d.reference = q0;
  evaluate_pairs<S>(m, q, nullptr, 1, d);
  compute_constraints(m, q, d);
  return d.residual.cwiseAbs().maxCoeff();
}

/// Closed-form parabola arc length primitive (docs/method.md section 5), in MPFR.
M parabola_s(const M& xx, const M& a) {
  using std::asinh;
  using std::sqrt;
  const M t = M(2) * a * xx;
  return xx / M(2) * sqrt(M(1) + t * t) + asinh(t) / (M(4) * a);
}

std::vector<M> to_mpfr(const std::vector<double>& v) {
  std::vector<M> out;
  for (double d : v) out.push_back(M(d));
  return out;
}

const std::string dead_point_file = std::string(ROLLKIN_SOURCE_DIR) + "/tests/golden/paper_fourbar_dead_point_50digits.txt";

}  // namespace

BOOST_AUTO_TEST_CASE(paper_fourbar_double_vs_mpfr_residual_and_no_slip) {
  const auto t0 = std::chrono::steady_clock::now();
  Run<double> d(paper_fourbar<double>());
  // The same mechanism, every double number taken exactly: the comparison measures solver error alone.
  Fixture<M> fm{d.f.mech.cast<M>(), d.f.guess.cast<M>(), d.f.held};
  Run<M> mp(fm);
  BOOST_TEST_REQUIRE(d.assembly.ok());
  BOOST_TEST_REQUIRE(mp.assembly.ok());
  const auto inputs = degrees<double>(-50, 100);
  const auto rd = d.sweep_to(inputs);
  const auto rm = mp.sweep_to(to_mpfr(inputs));
  BOOST_TEST_REQUIRE(rd.all_solved());
  BOOST_TEST_REQUIRE(rm.all_solved());

  const auto& m = d.f.mech;
  std::vector<double> worst(m.variable_count(), 0.0);
  M worst_residual(0), worst_slip_a(0), worst_slip_b(0);
  const M a = M(1) / M(2), r3(1), r4(4);
  const VectorX<M>& q0 = mp.q0;
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    const VectorX<M>& q = rm.poses[k].q;
    for (int i = 0; i < m.variable_count(); ++i)
      worst[i] = std::max(worst[i], to_double(abs(M(rd.poses[k].q(i)) - q(i))) / m.variable_scale(i));
    worst_residual = std::max(worst_residual, max_residual(mp.f.mech, q0, q));
    // eq. (7a)/(7b) with this project's signs (test_solve_paper.cpp), arc lengths from the closed form.
    worst_slip_a = std::max(worst_slip_a, M(abs(parabola_s(q(x), a) - parabola_s(q0(x), a) + r3 * (q(theta23) - q0(theta23)))));
    worst_slip_b = std::max(worst_slip_b, M(abs(r3 * (q(theta34) - q0(theta34)) + r4 * (q(theta4) - q0(theta4)))));
  }
  double overall = 0;
  for (int i = 0; i < m.variable_count(); ++i) {
    BOOST_TEST_MESSAGE("double vs MPFR50, " << m.variables[i].name << ": max error " << worst[i]);
    BOOST_TEST(worst[i] < 1e-12, m.variables[i].name);
    overall = std::max(overall, worst[i]);
  }
  BOOST_TEST_MESSAGE("double vs MPFR50 over 151 poses: max error of any pair variable " << overall << " rad");
  BOOST_TEST_MESSAGE("MPFR50: max loop/rolling residual " << worst_residual.str(3) << ", slip A " << worst_slip_a.str(3)
                                                          << ", slip B " << worst_slip_b.str(3));
  const M tol = dec("1e-45");
  BOOST_TEST(worst_residual < tol);
  BOOST_TEST(worst_slip_a < tol);
  BOOST_TEST(worst_slip_b < tol);
  BOOST_TEST_MESSAGE("paper example double + MPFR50 sweep: "
                     << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s");
}

BOOST_AUTO_TEST_CASE(hypocycloid_and_epicycloid_closed_forms_to_1e_40) {
  const M tol = dec("1e-40");
  for (auto [R, r, outside] : {std::tuple{4, 1, false}, std::tuple{2, 1, false}, std::tuple{5, 2, false}, std::tuple{3, 1, true}}) {
    Run<M> run(planet_on_arm<M>(M(R), M(r), outside));
    BOOST_TEST_REQUIRE(run.assembly.ok());
    BOOST_TEST(run.assembly.redundant() == 1);  // consistent to 50 digits
    const auto res = run.sweep_to(degrees<M>(-360, 360, 30));
    BOOST_TEST_REQUIRE(res.all_solved());
    M worst(0);
    const M ratio = outside ? M(M(R + r) / M(r)) : M(-M(R - r) / M(r));
    for (const auto& p : res.poses) worst = std::max(worst, M(abs(p.q(0) + p.q(1) - ratio * p.input)));
    BOOST_TEST_MESSAGE("planet R " << R << " r " << r << (outside ? " outside" : " inside") << ": max error "
                                   << worst.str(3));
    BOOST_TEST(worst < tol);
  }
}

BOOST_AUTO_TEST_CASE(elliptical_gears_transmission_function_to_1e_40) {
  const M tol = dec("1e-40");
  for (const char* ecc : {"0.5", "0.3"}) {
    const M a(2), e = dec(ecc);
    Run<M> run(elliptical_gears<M>(a, e, true));
    BOOST_TEST_REQUIRE(run.assembly.ok());
    const auto res = run.sweep_to(degrees<M>(-170, 530, 20));
    BOOST_TEST_REQUIRE(res.all_solved());
    M worst(0);
    using std::atan;
    using std::tan;
    for (const auto& p : res.poses) {
      const M expected = M(-2) * atan((M(1) - e) / (M(1) + e) * tan(p.input / M(2)));
      worst = std::max(worst, M(abs(wrap_angle(M(p.q(3) - expected)))));
    }
    BOOST_TEST_MESSAGE("elliptical gears e = " << ecc << ": max error of phi2 " << worst.str(3));
    BOOST_TEST(worst < tol);
  }
}

BOOST_AUTO_TEST_CASE(gauss_legendre_arc_length_converges_to_the_closed_form) {
  // The same paper example with eq. (4) integrated by Gauss-Legendre instead of the closed form.
  const auto inputs = degrees<M>(-50, 100, 50);
  Run<M> exact(paper_fourbar<M>());
  const auto ref = exact.sweep_to(inputs);
  BOOST_TEST_REQUIRE(ref.all_solved());
  double previous = 1;
  for (auto [order, panels] : {std::pair{4, 1}, std::pair{8, 2}, std::pair{16, 2}, std::pair{24, 4}, std::pair{32, 6}}) {
    const ArcLengthMethod method{false, QuadratureRule{Quadrature::GaussLegendre, order, panels}};
    Run<M> quad(paper_fourbar<M>(M(1), false, method));
    BOOST_TEST_REQUIRE(quad.assembly.ok());
    const auto res = quad.sweep_to(inputs);
    BOOST_TEST_REQUIRE(res.all_solved());
    M worst(0);
    for (std::size_t k = 0; k < inputs.size(); ++k)
      worst = std::max(worst, M((res.poses[k].q - ref.poses[k].q).cwiseAbs().maxCoeff()));
    // And the arc length itself over the whole parabola.
    const Parabola<M> closed(M(1) / M(2), M(-2), M(2)), gl(M(1) / M(2), M(-2), M(2), method);
    const M arc_err = abs(gl.arc_length(M(-2), M(2)) - closed.arc_length(M(-2), M(2)));
    BOOST_TEST_MESSAGE("Gauss-Legendre " << order << " x " << panels << " panels: max pose error " << worst.str(3)
                                         << ", arc length error over [-2, 2] " << arc_err.str(3));
    const double w = to_double(worst);
    BOOST_TEST((w < previous || w < 1e-45), "order " << order);  // converges (until round-off)
    previous = std::max(w, 1e-300);
    if (order == 32) {
      BOOST_TEST(worst < dec("1e-40"));
      BOOST_TEST(arc_err < dec("1e-40"));
    }
  }
}

BOOST_AUTO_TEST_CASE(dead_point_located_to_50_digits) {
  // Near the fold theta2 is not a good parameter, the contact parameter x is: drive by x and find the
  // extremum of theta2(x), dtheta2/dx = 0, by the secant method on the velocity solution.
  Run<double> d(paper_fourbar<double>());
  const auto rd = d.sweep_to(degrees<double>(-70, 0, 10));
  BOOST_TEST_REQUIRE(rd.limits.size() == 1u);
  BOOST_TEST_REQUIRE(rd.limits[0].status == SolveStatus::DeadPoint);
  const double t_double = rd.limits[0].limit_input;
  const auto near = d.sweep_to({t_double + 1e-4});
  BOOST_TEST_REQUIRE(near.poses[0].report.ok());

  Fixture<M> fm = paper_fourbar<M>();
  Run<M> mp(fm);
  BOOST_TEST_REQUIRE(mp.assembly.ok());
  Mechanism<M> by_x = mp.f.mech;
  by_x.drivers = {x};
  by_x.finalize();
  SolveData<M> sd(by_x);
  sd.kin.reference = mp.q0;  // arc lengths from the same assembly pose
  VectorX<M> q = near.poses[0].q.cast<M>();
  const VectorX<M> one = VectorX<M>::Constant(1, M(1));
  auto rate = [&](const M& xx, VectorX<M>& pose) {  // dtheta2/dx at x = xx
    pose(x) = xx;
    const auto rep = solve_position(by_x, pose, sd);
    BOOST_TEST_REQUIRE(rep.ok(), to_string(rep.status) << " at x = " << xx.str(20) << ": " << rep.detail);
    return M(solve_velocity(by_x, sd, one)(theta2));
  };
  M x0 = q(x), x1 = q(x) + M(1) / M(1000);
  VectorX<M> p1 = q;
  M g0 = rate(x0, q), g1 = rate(x1, p1);
  int it = 0;
  for (; it < 60 && abs(g1) > dec("1e-46"); ++it) {
    const M x2 = x1 - g1 * (x1 - x0) / (g1 - g0);
    x0 = x1;
    g0 = g1;
    x1 = x2;
    g1 = rate(x1, p1);
  }
  BOOST_TEST(abs(g1) < dec("1e-44"));
  const M limit_deg = p1(theta2) * M(180) / pi<M>();
  BOOST_TEST_MESSAGE("dead point (MPFR50, " << it << " secant steps): theta2 = " << limit_deg.str(50) << " deg at x = "
                                            << p1(x).str(50) << "; double sweep located it at "
                                            << rad_to_deg(t_double) << " deg, error "
                                            << to_double(abs(M(t_double) - p1(theta2))) << " rad");
  BOOST_TEST(to_double(abs(M(t_double) - p1(theta2))) < 1e-6);  // continuation's location (min_step 1e-9)
  // It is a minimum of theta2 on this branch: the sweep stops going down.
  BOOST_TEST(p1(theta2) < M(-50) * pi<M>() / M(180));

  const char* env = std::getenv("ROLLKIN_WRITE_GOLDEN");
  if (env && std::string(env) == "1") {
    std::ofstream out(dead_point_file);
    out << "# paper_fourbar dead point (fold of theta2), 50 digits: theta2_deg x; written by test_solve_mpfr\n"
        << limit_deg.str(50) << ' ' << p1(x).str(50) << '\n';
  }
  std::ifstream in(dead_point_file);
  BOOST_TEST_REQUIRE(in.good(), "missing " << dead_point_file);
  std::string line, t_str, x_str;
  std::getline(in, line);  // comment
  in >> t_str >> x_str;
  BOOST_TEST(abs(M(t_str) - limit_deg) < dec("1e-40"));
  BOOST_TEST(abs(M(x_str) - p1(x)) < dec("1e-40"));
}
