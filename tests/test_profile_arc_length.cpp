// ArcLengthProfile: a sampled spline or Bezier path re-parameterised by arc length (profile/
// arc_length_parameterised.hpp). Checked: unit speed, the chain-rule derivatives (orders 1-3, and u''' on its
// own) against central differences, curvature equal to the base's, wrapping of closed contours, the exactly
// linear arc length, the exact circle x(s) = r (cos s/r, sin s/r), the reference example with the parabola
// re-parameterised (sampled: same theta5 as the native chord-length parameter; exact Bezier: same as the
// analytic parabola), and the scene key "parameter".
#define BOOST_TEST_MODULE profile_arc_length
#include <boost/test/unit_test.hpp>

#include "discretised.hpp"
#include "test_support.hpp"

#include "rollkin/io/scene/reader.hpp"
#include "rollkin/profile/arc_length_parameterised.hpp"
#include "rollkin/solve/continuation.hpp"

#include <chrono>
#include <cstdio>
#include <iomanip>
#include <sstream>

using namespace rollkin;
using namespace rollkin::testing;

namespace {

SampledProfile<double> sampled_parabola_spline(int n = 97) {
  SplineOptions<double> o;
  o.end = SplineEnd::NotAKnot;
  return SampledProfile<double>(load_shape<double>(shape_file("parabola", n)), o);
}

SampledProfile<double> sampled_circle_spline(int n = 64) {
  SplineOptions<double> o;
  o.closed = true;
  return SampledProfile<double>(load_shape<double>(shape_file("circle", n)), o);
}

/// A G1 (not C2) open Bezier path: a quadratic followed by a cubic whose first leg is twice as long.
BezierPath<double> g1_bezier() {
  BezierSegment<double> a{{Vec2<double>(0, 0), Vec2<double>(1, 1), Vec2<double>(2, 1)}, {}};
  BezierSegment<double> b{{Vec2<double>(2, 1), Vec2<double>(4, 1), Vec2<double>(5, 0), Vec2<double>(6, 2)}, {}};
  return BezierPath<double>({a, b}, false);
}

struct Case {
  std::string name;
  ArcLengthProfile<double> profile;
};

std::vector<Case> cases() {
  return {{"sampled parabola", ArcLengthProfile<double>(sampled_parabola_spline())},
          {"sampled closed circle", ArcLengthProfile<double>(sampled_circle_spline())},
          {"bezier parabola", ArcLengthProfile<double>(BezierPath<double>::parabola(0.5, -2, 2))},
          {"bezier circle", ArcLengthProfile<double>(BezierPath<double>::circle(Vec2<double>(1, -1), 2.5))},
          {"bezier ellipse", ArcLengthProfile<double>(BezierPath<double>::ellipse(Vec2<double>(0, 0), 3, 1, 0.3))},
          {"bezier G1 path", ArcLengthProfile<double>(g1_bezier())}};
}

/// Arc lengths at the middle of every piece of the base (away from knots, where p''' of a spline jumps),
/// plus a few at quarter points.
std::vector<double> interior_points(const ArcLengthProfile<double>& a) {
  std::vector<double> s;
  std::visit(
      [&](const auto& b) {
        const std::size_t n = b.piece_count();
        const std::size_t stride = std::max<std::size_t>(1, n / 24);
        for (std::size_t i = 0; i < n; i += stride)
          for (double f : {0.25, 0.5, 0.7}) s.push_back(a.arc_length_at(b.knot(i) + f * (b.knot(i + 1) - b.knot(i))));
      },
      a.base());
  return s;
}

Vec2<double> derivative(const Jet<double>& j, int k) { return k == 0 ? j.p : (k == 1 ? j.d1 : (k == 2 ? j.d2 : j.d3)); }

/// u', u'', u''' of u(s) from the base's jet at u(s), with the formulas of the header.
std::array<double, 3> u_derivatives(const ArcLengthProfile<double>& a, double s) {
  const double u = a.base_param(s);
  const Jet<double> j = std::visit([&](const auto& b) { return b.jet(u, 3); }, a.base());
  const double sigma = j.d1.norm(), pp = j.d1.dot(j.d2);
  const double sigma_u = pp / sigma;
  const double sigma_uu = (j.d2.squaredNorm() + j.d1.dot(j.d3)) / sigma - pp * pp / (sigma * sigma * sigma);
  return {1 / sigma, -sigma_u / std::pow(sigma, 3), (3 * sigma_u * sigma_u - sigma * sigma_uu) / std::pow(sigma, 5)};
}

}  // namespace

BOOST_AUTO_TEST_CASE(unit_speed_everywhere) {
  for (const Case& c : cases()) {
    const double L = c.profile.length();
    double worst = 0;
    for (int k = 0; k <= 4000; ++k) {
      const double s = L * k / 4000.0;
      worst = std::max(worst, std::abs(c.profile.jet(s, 1).d1.norm() - 1));
    }
    BOOST_TEST_MESSAGE(c.name << ": max | |x'(s)| - 1 | = " << worst);
    BOOST_TEST(worst < 1e-12, c.name);
    BOOST_TEST((c.profile.parameter_kind() == ParamKind::Length));
    BOOST_TEST(c.profile.domain().lo == 0.0);
    BOOST_TEST(c.profile.domain().hi == L);
  }
}

BOOST_AUTO_TEST_CASE(jet_matches_central_differences) {
  for (const Case& c : cases()) {
    const double h = 1e-4 * std::max(1.0, c.profile.length() / 10);
    double worst[4] = {0, 0, 0, 0};
    for (double s : interior_points(c.profile)) {
      const Jet<double> j = c.profile.jet(s, 3), jp = c.profile.jet(s + h, 3), jm = c.profile.jet(s - h, 3);
      for (int k = 1; k <= 3; ++k) {
        const Vec2<double> fd = (derivative(jp, k - 1) - derivative(jm, k - 1)) / (2 * h);
        worst[k] = std::max(worst[k], (fd - derivative(j, k)).norm() / (1 + derivative(j, k).norm()));
      }
    }
    BOOST_TEST_MESSAGE(c.name << ": central differences vs jet, relative: d1 " << worst[1] << ", d2 " << worst[2]
                              << ", d3 " << worst[3] << " (h = " << h << ")");
    BOOST_TEST(worst[1] < 1e-7, c.name);
    BOOST_TEST(worst[2] < 1e-7, c.name);
    BOOST_TEST(worst[3] < 1e-6, c.name);
  }
}

BOOST_AUTO_TEST_CASE(u_derivatives_match_central_differences) {
  for (const Case& c : cases()) {
    const double h = 1e-4 * std::max(1.0, c.profile.length() / 10);
    double worst[3] = {0, 0, 0};
    for (double s : interior_points(c.profile)) {
      const auto d = u_derivatives(c.profile, s), dp = u_derivatives(c.profile, s + h), dm = u_derivatives(c.profile, s - h);
      // u' against differences of u(s) itself, u'' and u''' against differences of the formulas one order down.
      const double fd1 = (c.profile.base_param(s + h) - c.profile.base_param(s - h)) / (2 * h);
      worst[0] = std::max(worst[0], std::abs(fd1 - d[0]) / (1 + std::abs(d[0])));
      for (int k = 1; k < 3; ++k)
        worst[k] = std::max(worst[k], std::abs((dp[k - 1] - dm[k - 1]) / (2 * h) - d[k]) / (1 + std::abs(d[k])));
    }
    BOOST_TEST_MESSAGE(c.name << ": u', u'', u''' vs central differences, relative: " << worst[0] << ", " << worst[1]
                              << ", " << worst[2]);
    BOOST_TEST(worst[0] < 1e-7, c.name);
    BOOST_TEST(worst[1] < 1e-7, c.name);
    BOOST_TEST(worst[2] < 1e-6, c.name);
  }
}

BOOST_AUTO_TEST_CASE(curvature_is_the_base_curvature) {
  for (const Case& c : cases()) {
    double worst = 0;
    const double L = c.profile.length();
    for (int k = 0; k <= 500; ++k) {
      const double s = L * (k + 0.37) / 501.0;
      const double u = c.profile.base_param(s);
      const Jet<double> base = std::visit([&](const auto& b) { return b.jet(u, 2); }, c.profile.base());
      const ContourPoint<double> a = contour_point(c.profile.jet(s, 2), 2), b = contour_point(base, 2);
      worst = std::max(worst, std::abs(a.curvature() - b.curvature()) / (1 + std::abs(b.curvature())));
      BOOST_TEST((a.p - b.p).norm() == 0.0);
      BOOST_TEST((a.tangent - b.tangent).norm() < 1e-14);
      BOOST_TEST(std::abs(a.speed - 1) < 1e-14);
      BOOST_TEST(std::abs(a.speed_rate) < 1e-12);
    }
    BOOST_TEST_MESSAGE(c.name << ": max relative curvature difference " << worst);
    BOOST_TEST(worst < 1e-12, c.name);
  }
}

BOOST_AUTO_TEST_CASE(exact_circle_is_parameterised_by_arc_length) {
  const double r = 2.5;
  const Vec2<double> centre(1, -1);
  const ArcLengthProfile<double> a(BezierPath<double>::circle(centre, r));
  BOOST_TEST(std::abs(a.length() - 2 * pi<double>() * r) < 1e-12);
  double worst = 0;
  for (int k = -300; k <= 900; ++k) {
    const double s = 0.0317 * k;
    const Jet<double> j = a.jet(s, 3);
    const double t = s / r;
    const Vec2<double> p = centre + r * Vec2<double>(std::cos(t), std::sin(t));
    const Vec2<double> d1(-std::sin(t), std::cos(t)), d2 = -Vec2<double>(std::cos(t), std::sin(t)) / r;
    const Vec2<double> d3 = -d1 / (r * r);
    worst = std::max({worst, (j.p - p).norm(), (j.d1 - d1).norm(), (j.d2 - d2).norm(), (j.d3 - d3).norm()});
  }
  BOOST_TEST_MESSAGE("exact Bezier circle: max |x^(k)(s) - closed form|, k <= 3: " << worst);
  BOOST_TEST(worst < 1e-12);
}

BOOST_AUTO_TEST_CASE(closed_contours_wrap) {
  for (const Case& c : cases()) {
    if (!c.profile.domain().closed) continue;
    const double L = c.profile.length();
    BOOST_TEST(c.profile.domain().period() == L);
    double worst = 0;
    for (int k = 0; k < 200; ++k) {
      const double s = L * k / 200.0 + 0.013;
      for (double turns : {-2.0, -1.0, 1.0, 3.0}) {
        const Jet<double> a = c.profile.jet(s, 3), b = c.profile.jet(s + turns * L, 3);
        for (int d = 0; d <= 2; ++d) worst = std::max(worst, (derivative(a, d) - derivative(b, d)).norm());
      }
    }
    BOOST_TEST_MESSAGE(c.name << ": max jet difference after whole turns " << worst);
    BOOST_TEST(worst < 1e-11, c.name);
    // Across the seam s = 0 = L the curve is smooth: central differences of the position give the tangent.
    const double h = 1e-5;
    const Vec2<double> fd = (c.profile.jet(h, 0).p - c.profile.jet(-h, 0).p) / (2 * h);
    BOOST_TEST((fd - c.profile.jet(0, 1).d1).norm() < 1e-8, c.name);
    BOOST_TEST((c.profile.jet(L, 0).p - c.profile.jet(0, 0).p).norm() < 1e-14, c.name);
  }
}

BOOST_AUTO_TEST_CASE(arc_length_is_exactly_linear) {
  for (const Case& c : cases()) {
    const double L = c.profile.length();
    double worst_geom = 0, worst_inverse = 0;
    for (int k = 0; k <= 100; ++k) {
      const double s0 = L * k / 137.0, s1 = L * (100 - k) / 91.0;
      BOOST_TEST(c.profile.arc_length(s0, s1) == s1 - s0);
      BOOST_TEST(c.profile.param_at_arc_length(s0, s1) == s0 + s1);
      // The base agrees: the arc length between the base parameters of s0 and s1 is s1 - s0 (open contours
      // inside the domain only; the base extrapolates its end pieces beyond).
      if (c.profile.domain().closed || (s1 <= L && s0 <= L)) {
        const double u0 = c.profile.base_param(s0), u1 = c.profile.base_param(s1);
        const double base = std::visit([&](const auto& b) { return b.arc_length(u0, u1); }, c.profile.base());
        const double expected = c.profile.domain().closed ? c.profile.domain().wrap(s1) - c.profile.domain().wrap(s0) : s1 - s0;
        worst_geom = std::max(worst_geom, std::abs(base - expected));
        worst_inverse = std::max(worst_inverse, std::abs(c.profile.arc_length_at(u1) - c.profile.domain().wrap(s1)));
      }
    }
    BOOST_TEST_MESSAGE(c.name << ": |base arc length - (s1 - s0)| <= " << worst_geom << ", |s(u(s)) - s| <= " << worst_inverse);
    BOOST_TEST(worst_geom < 1e-12, c.name);
    BOOST_TEST(worst_inverse < 1e-12, c.name);
  }
  // Totals agree with the base's own table.
  for (const Case& c : cases()) {
    const double total = std::visit([](const auto& b) { return b.total_length(); }, c.profile.base());
    BOOST_TEST(std::abs(c.profile.length() - total) < 1e-13 * total, c.name);
  }
}

BOOST_AUTO_TEST_CASE(open_ends_extrapolate_continuously) {
  const ArcLengthProfile<double> a(sampled_parabola_spline());
  const double L = a.length();
  for (double s : {0.0, L}) {
    const Jet<double> in = a.jet(s, 1);
    for (double d : {-1e-6, 1e-6}) {
      const Jet<double> j = a.jet(s + d, 1);
      BOOST_TEST((j.p - (in.p + d * in.d1)).norm() < 1e-10);
      BOOST_TEST(std::abs(j.d1.norm() - 1) < 1e-12);
    }
  }
}

BOOST_AUTO_TEST_CASE(contour_sees_through_and_casts) {
  SampledProfile<double> spline = sampled_parabola_spline(49);
  const Contour<double> native("native", 1, spline, SE2<double>(0.3, Vec2<double>(1, 2)), true);
  const Contour<double> by_arc("by_arc", 1, ArcLengthProfile<double>(spline), SE2<double>(0.3, Vec2<double>(1, 2)), true);
  BOOST_TEST(native.representation_error() > 0.0);
  BOOST_TEST(by_arc.representation_error() == native.representation_error());
  BOOST_TEST(by_arc.continuity() == 2);
  BOOST_TEST((by_arc.parameter_kind() == ParamKind::Length));
  // Reversed contour: parameter -s, arc length still linear, unit speed.
  BOOST_TEST(by_arc.arc_length(-1.0, -2.5) == -1.5);
  BOOST_TEST(by_arc.param_at_arc_length(-1.0, 0.25) == -0.75);
  BOOST_TEST(std::abs(by_arc.jet(-1.2, 1).d1.norm() - 1) < 1e-12);
  const ArcLengthProfile<double> a(spline);
  const ArcLengthProfile<double> back = a.cast<double>();
  BOOST_TEST(back.length() == a.length());
  BOOST_TEST((back.jet(1.7, 3).d3 - a.jet(1.7, 3).d3).norm() == 0.0);
  const ArcLengthProfile<double> bez(BezierPath<double>::parabola(0.5, -2, 2));
  BOOST_TEST(bez.bezier() != nullptr);
  BOOST_TEST(bez.sampled() == nullptr);
  const Contour<double> bc("bez", 1, bez, SE2<double>(), false);
  BOOST_TEST(bc.representation_error() == 0.0);
}

BOOST_AUTO_TEST_CASE(jet_timing) {
  // Not asserted: the cost of one order-3 jet against the base's (printed for the report).
  auto time_per_call = [](const auto& profile, double lo, double hi) {
    const int n = 200000;
    double sink = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; k < n; ++k) sink += profile.jet(lo + (hi - lo) * ((k * 7919) % n) / double(n), 3).d3.x();
    const auto t1 = std::chrono::steady_clock::now();
    BOOST_TEST(std::isfinite(sink));
    return std::chrono::duration<double, std::nano>(t1 - t0).count() / n;
  };
  auto sweep_per_call = [](const auto& profile, double lo, double hi) {  // continuously moving, as the solver does
    const int n = 200000;
    double sink = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; k < n; ++k) sink += profile.jet(lo + (hi - lo) * k / double(n), 3).d3.x();
    const auto t1 = std::chrono::steady_clock::now();
    BOOST_TEST(std::isfinite(sink));
    return std::chrono::duration<double, std::nano>(t1 - t0).count() / n;
  };
  const SampledProfile<double> spline = sampled_parabola_spline(193);
  const ArcLengthProfile<double> a(spline);
  const BezierPath<double> bez = BezierPath<double>::parabola(0.5, -2, 2);
  const ArcLengthProfile<double> ab(bez);
  std::ostringstream os;
  os << std::fixed << std::setprecision(0) << "jet(order 3), ns per call, scattered / sweeping: spline (193 samples) "
     << time_per_call(spline, 0, spline.domain().hi) << " / " << sweep_per_call(spline, 0, spline.domain().hi) << ", by arc length "
     << time_per_call(a, 0, a.length()) << " / " << sweep_per_call(a, 0, a.length()) << "; Bezier parabola "
     << time_per_call(bez, 0, 1) << " / " << sweep_per_call(bez, 0, 1) << ", by arc length " << time_per_call(ab, 0, ab.length())
     << " / " << sweep_per_call(ab, 0, ab.length());
  BOOST_TEST_MESSAGE(os.str());
}

// ---- the reference example ------------------------------------------------------------------------------

namespace {

enum Var { theta2, x, theta23, theta34, theta4, theta5 };

SweepResult<double> solve(const Fixture<double>& f) {
  SolveData<double> sd(f.mech);
  VectorX<double> q0;
  const SolveReport<double> assembly = assemble_fixture(f, q0, sd);
  BOOST_TEST_REQUIRE(assembly.ok());
  SweepResult<double> r = sweep(f.mech, sd, q0, assembly, 0, degrees<double>(-50, 100));
  BOOST_TEST_REQUIRE(r.all_solved());
  return r;
}

double max_theta5_difference(const SweepResult<double>& a, const SweepResult<double>& b) {
  double worst = 0;
  for (std::size_t i = 0; i < a.poses.size(); ++i)
    worst = std::max(worst, std::abs(wrap_angle(a.poses[i].q(theta5) - b.poses[i].q(theta5))));
  return worst;
}

/// The parabola of `shape` re-parameterised by arc length, the vertex mapped to its arc length.
ParabolaShape<double> by_arc_length(const ParabolaShape<double>& shape) {
  ArcLengthProfile<double> a = std::visit(
      [](const auto& p) -> ArcLengthProfile<double> {
        using P = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<P, SampledProfile<double>> || std::is_same_v<P, BezierPath<double>>) return ArcLengthProfile<double>(p);
        else throw std::logic_error("not a piecewise profile");
      },
      shape.shape);
  const double vertex = a.arc_length_at(shape.vertex);
  return {std::move(a), vertex};
}

}  // namespace

BOOST_AUTO_TEST_CASE(reference_example_sampled_parabola_by_arc_length) {
  const ParabolaShape<double> native = sampled_parabola<double>(load_shape<double>(shape_file("parabola", 97)));
  const Fixture<double> fa = paper_fourbar_shapes(native, analytic_disk(1.0), analytic_disk(4.0));
  const Fixture<double> fb = paper_fourbar_shapes(by_arc_length(native), analytic_disk(1.0), analytic_disk(4.0));
  const auto t0 = std::chrono::steady_clock::now();
  const SweepResult<double> a = solve(fa);
  const auto t1 = std::chrono::steady_clock::now();
  const SweepResult<double> b = solve(fb);
  const auto t2 = std::chrono::steady_clock::now();
  using ms = std::chrono::duration<double, std::milli>;
  const double ms_chord = ms(t1 - t0).count(), ms_arc = ms(t2 - t1).count();
  BOOST_TEST_MESSAGE("assembly + 151-pose sweep: chord length " << ms_chord << " ms, arc length " << ms_arc << " ms");
  const double d = max_theta5_difference(a, b);
  BOOST_TEST_MESSAGE("reference example, sampled parabola (97 samples): max |theta5(arc length) - theta5(chord length)| = " << d
                                                                                                                           << " rad");
  BOOST_TEST(d < 1e-10);
}

BOOST_AUTO_TEST_CASE(reference_example_bezier_parabola_by_arc_length) {
  const SweepResult<double> analytic = solve(paper_fourbar<double>());
  const SweepResult<double> b = solve(paper_fourbar_shapes(by_arc_length(bezier_parabola<double>()), analytic_disk(1.0), analytic_disk(4.0)));
  const double d = max_theta5_difference(analytic, b);
  BOOST_TEST_MESSAGE("reference example, exact Bezier parabola by arc length: max |theta5 - theta5(analytic)| = " << d << " rad");
  BOOST_TEST(d < 1e-10);
  // Contact parameter A.x is the arc length from the parabola's start: its changes are the arc lengths rolled.
  for (const auto& p : b.poses) BOOST_TEST(std::isfinite(p.q(x)));
}

// ---- scene ----------------------------------------------------------------------------------------------

namespace {

/// The paper example with its parabola as the exact Bezier quadratic; `parameter` is the JSON text of the
/// contour's "parameter" entry (empty: none) and `vertex` the contact value of the vertex.
std::string bezier_paper_scene(const std::string& parameter, double vertex) {
  std::ostringstream os;
  os << std::setprecision(17);
  os << R"({"units": {"length": "m", "angle": "deg"},
  "links": [
    {"name": "link1", "ground": true},
    {"name": "link2", "contours": [
      {"name": "parabola", "type": "bezier", "segments": [{"points": [[-2, 2], [0, -2], [2, 2]]}],
       "at": {"x": 2, "y": 0, "angle": 90})"
     << (parameter.empty() ? "" : ", \"parameter\": " + parameter) << R"(}]},
    {"name": "link3", "contours": [{"name": "rim", "type": "circle", "radius": 1}]},
    {"name": "link4", "contours": [{"name": "rim", "type": "circle", "radius": 4, "at": {"x": 2, "y": 0}}]}
  ],
  "pairs": [
    {"name": "O_A", "type": "revolute", "links": ["link1", "link2"], "variable": "theta2", "value": 0},
    {"name": "A", "type": "rolling", "contours": ["link2.parabola", "link3.rim"], "variables": ["x", "theta23"], "values": [)"
     << vertex << R"(, 180], "hold": [true, true]},
    {"name": "B", "type": "rolling", "contours": ["link3.rim", "link4.rim"], "variables": ["theta34", "theta4"], "values": [-3, 117]},
    {"name": "O_B", "type": "revolute", "links": ["link1", "link4"], "at": [{"x": 7, "y": -2}, {}], "variable": "theta5", "value": 60}
  ],
  "inputs": ["O_A.theta2"],
  "sweep": {"input": "O_A.theta2", "from": -50, "to": 100, "step": 1}
})";
  return os.str();
}

SweepResult<double> solve_scene(const io::Scene& scene) {
  SolveData<double> sd(scene.mechanism);
  VectorX<double> q = scene.guess;
  const SolveReport<double> assembly = assemble(scene.mechanism, q, sd, scene.held);
  BOOST_TEST_REQUIRE(assembly.ok());
  SweepResult<double> r = sweep(scene.mechanism, sd, q, assembly, scene.sweep->driver, sweep_inputs(*scene.sweep));
  BOOST_TEST_REQUIRE(r.all_solved());
  return r;
}

}  // namespace

BOOST_AUTO_TEST_CASE(scene_parameter_arc_length) {
  // Half the parabola y = x^2 / 2, x in [-2, 2]: integral_0^2 sqrt(1 + x^2) dx = (2 sqrt 5 + asinh 2) / 2.
  const double half = (2 * std::sqrt(5.0) + std::asinh(2.0)) / 2;
  const io::Scene by_arc = io::parse_scene(bezier_paper_scene("\"arc_length\"", half), "arc.json");
  const io::Scene native = io::parse_scene(bezier_paper_scene("\"native\"", 0.5), "native.json");
  const io::Scene plain = io::parse_scene(bezier_paper_scene("", 0.5), "plain.json");
  const auto& shape = by_arc.mechanism.contours[0].shape();
  BOOST_TEST(std::holds_alternative<ArcLengthProfile<double>>(shape));
  BOOST_TEST(std::holds_alternative<BezierPath<double>>(native.mechanism.contours[0].shape()));
  BOOST_TEST(std::holds_alternative<BezierPath<double>>(plain.mechanism.contours[0].shape()));
  BOOST_TEST(std::abs(std::get<ArcLengthProfile<double>>(shape).length() - 2 * half) < 1e-12);
  // The contact variable is a length in scene units.
  int var_x = -1;
  for (std::size_t i = 0; i < by_arc.mechanism.variables.size(); ++i)
    if (by_arc.mechanism.variables[i].kind == ParamKind::Length) var_x = static_cast<int>(i);
  BOOST_TEST_REQUIRE(var_x >= 0);
  BOOST_TEST(by_arc.unit_of(var_x) == 1.0);
  BOOST_TEST(by_arc.unit_label(var_x) == "m");
  const SweepResult<double> a = solve_scene(by_arc), b = solve_scene(native);
  const SweepResult<double> ref = solve(paper_fourbar<double>());
  const double d_native = max_theta5_difference(a, b), d_analytic = max_theta5_difference(a, ref);
  BOOST_TEST_MESSAGE("scene with \"parameter\": \"arc_length\": max theta5 difference to native " << d_native << ", to analytic "
                                                                                                   << d_analytic);
  BOOST_TEST(d_native < 1e-10);
  BOOST_TEST(d_analytic < 1e-10);
}

BOOST_AUTO_TEST_CASE(scene_parameter_errors) {
  const std::string bad = input_error_of([] { io::parse_scene(bezier_paper_scene("\"arclength\"", 0.5), "bad.json"); });
  BOOST_TEST_MESSAGE(bad);
  BOOST_TEST(contains(bad, "bad.json"));
  BOOST_TEST(contains(bad, "links[1].contours[0].parameter"));
  BOOST_TEST(contains(bad, "\"arclength\""));
  BOOST_TEST(contains(bad, "\"native\", \"arc_length\""));
  const std::string not_string = input_error_of([] { io::parse_scene(bezier_paper_scene("1", 0.5), "bad.json"); });
  BOOST_TEST(contains(not_string, "links[1].contours[0].parameter"));
  // Not a key of analytic contours.
  std::string text = bezier_paper_scene("", 0.5);
  const std::string rim = R"("type": "circle", "radius": 1)";
  text.replace(text.find(rim), rim.size(), rim + R"(, "parameter": "arc_length")");
  const std::string analytic = input_error_of([&] { io::parse_scene(text, "bad.json"); });
  BOOST_TEST(contains(analytic, "links[2].contours[0]"));
  BOOST_TEST(contains(analytic, "parameter"));
}

BOOST_AUTO_TEST_CASE(scene_samples_by_arc_length) {
  // A closed sampled disk (64 rim points of radius 1) rolling on a line: each sample's arc length is known.
  std::ostringstream pts;
  pts << std::setprecision(17) << "[";
  for (int k = 0; k < 64; ++k) pts << (k ? ", " : "") << "[" << std::cos(2 * pi<double>() * k / 64) << ", " << std::sin(2 * pi<double>() * k / 64) << "]";
  pts << "]";
  const std::string text = R"({"links": [{"name": "ground", "ground": true, "contours": [{"name": "floor", "type": "line", "from": -20, "to": 20}]},
    {"name": "disk", "contours": [{"name": "rim", "type": "samples", "closed": true, "parameter": "arc_length", "points": )" +
                           pts.str() + R"(}]}],
    "pairs": [{"name": "t", "type": "rolling", "contours": ["ground.floor", "disk.rim"], "values": [0, 4.5]}],
    "inputs": ["t.u"]})";
  const io::Scene s = io::parse_scene(text, "disk.json");
  const auto& shape = s.mechanism.contours[1].shape();
  BOOST_TEST_REQUIRE(std::holds_alternative<ArcLengthProfile<double>>(shape));
  const ArcLengthProfile<double>& a = std::get<ArcLengthProfile<double>>(shape);
  BOOST_TEST(a.sampled() != nullptr);
  BOOST_TEST(a.domain().closed);
  BOOST_TEST(std::abs(a.length() - 2 * pi<double>()) < 1e-5);  // spline through 64 rim points
  BOOST_TEST(s.mechanism.contours[1].representation_error() > 0.0);
}
