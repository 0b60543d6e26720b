#define BOOST_TEST_MODULE profile_bezier
#include <boost/test/unit_test.hpp>

#include "rollkin/profile/bezier.hpp"
#include "rollkin/scalar_mpfr.hpp"

#include <boost/math/special_functions/ellint_2.hpp>

#include <cmath>
#include <cstdio>

using rollkin::BezierPath;
using rollkin::BezierSegment;
using V = rollkin::Vec2<double>;
using Seg = BezierSegment<double>;

namespace {

/// s(x) = x/2 sqrt(1 + 4a^2x^2) + asinh(2ax)/(4a) (docs/method.md section 5).
double parabola_arc(double a, double x) { return x / 2 * std::sqrt(1 + 4 * a * a * x * x) + std::asinh(2 * a * x) / (4 * a); }

std::string message_of(const std::vector<Seg>& segs, bool closed) {
  try {
    BezierPath<double> p(segs, closed);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

BOOST_AUTO_TEST_CASE(derivatives_match_central_differences) {
  // A rational cubic followed by a polynomial quintic (tangent-continuous joint at (3, 1)).
  const Seg cubic{{V(0, 0), V(1, 1.5), V(2, 1), V(3, 1)}, {1.0, 0.6, 2.3, 1.0}};
  const Seg quintic{{V(3, 1), V(4, 1), V(5, 0), V(6, 2), V(7, -1), V(8, 0.5)}, {}};
  const BezierPath<double> path({cubic, quintic}, false);
  const double h = 1e-5;
  for (double u : {0.1, 0.37, 0.8, 1.2, 1.55, 1.9}) {
    const auto j = path.jet(u, 3), jp = path.jet(u + h, 3), jm = path.jet(u - h, 3);
    BOOST_TEST((j.d1 - (jp.p - jm.p) / (2 * h)).norm() < 1e-8 * (1 + j.d1.norm()));
    BOOST_TEST((j.d2 - (jp.d1 - jm.d1) / (2 * h)).norm() < 1e-7 * (1 + j.d2.norm()));
    BOOST_TEST((j.d3 - (jp.d2 - jm.d2) / (2 * h)).norm() < 1e-6 * (1 + j.d3.norm()));
  }
  BOOST_TEST(path.continuity() == 1);  // the joint is G1, not C2
}

BOOST_AUTO_TEST_CASE(exact_circle_points_and_curvature) {
  const V c(1.5, -0.5);
  const double r = 2.0;
  const auto circle = BezierPath<double>::circle(c, r);
  BOOST_TEST(circle.domain().closed);
  BOOST_TEST(circle.domain().hi == 4.0);
  double worst_r = 0, worst_k = 0;
  for (int k = 0; k <= 4000; ++k) {
    const auto j = circle.jet(k / 1000.0, 2);
    worst_r = std::max(worst_r, std::abs((j.p - c).norm() - r));
    worst_k = std::max(worst_k, std::abs(rollkin::contour_point(j, 2).curvature() - 1 / r));
  }
  std::printf("rational circle r = 2: max | |p - c| - r | = %.2e, max |kappa - 1/r| = %.2e\n", worst_r, worst_k);
  BOOST_TEST(worst_r < 1e-14);
  BOOST_TEST(worst_k < 1e-14);
  // Quarter points at integer u; counter-clockwise (material inside, on the left).
  BOOST_TEST((circle.jet(1.0, 0).p - V(1.5, 1.5)).norm() < 1e-15);
  BOOST_TEST(rollkin::cross2(V(circle.jet(0.0, 0).p - c), circle.jet(0.0, 1).d1) > 0);
  BOOST_TEST(circle.continuity() == 1);  // tangent-continuous; the speed's rate flips sign at the joints

  // An arc of arbitrary angles, both directions.
  for (double a1 : {2.5, -2.0}) {
    const auto arc = BezierPath<double>::circle_arc(c, r, 0.3, a1);
    BOOST_TEST(arc.segments().size() == 2u);  // 126 and 132 degrees: two pieces each
    const V end = arc.jet(arc.domain().hi, 0).p;
    BOOST_TEST((end - (c + r * V(std::cos(a1), std::sin(a1)))).norm() < 1e-14);
    for (double u = 0; u <= arc.domain().hi; u += 0.01) {
      const auto j = arc.jet(u, 2);
      BOOST_TEST(std::abs((j.p - c).norm() - r) < 1e-14);
      BOOST_TEST(std::abs(rollkin::contour_point(j, 2).curvature() - (a1 > 0.3 ? 1 : -1) / r) < 1e-13);
    }
    BOOST_TEST(std::abs(arc.total_length() - r * std::abs(a1 - 0.3)) < 1e-14 * r);
  }
}

BOOST_AUTO_TEST_CASE(circle_arc_length_matches_angle) {
  const double r = 0.75;
  const auto circle = BezierPath<double>::circle(V(0, 0), r);
  BOOST_TEST(std::abs(circle.total_length() - 2 * M_PI * r) < 1e-14 * 2 * M_PI * r);
  auto angle = [&](double u) {
    const V p = circle.jet(u, 0).p;
    return std::atan2(p.y(), p.x());
  };
  for (double u0 : {0.0, 0.3, 1.7})
    for (double u1 : {0.45, 2.9, 3.99}) {
      double da = angle(u1) - angle(u0);
      if (u1 > u0 && da < 0) da += 2 * M_PI;
      if (u1 < u0 && da > 0) da -= 2 * M_PI;
      BOOST_TEST(std::abs(circle.arc_length(u0, u1) - r * da) < 1e-14);
    }
  // Whole turns on the closed path.
  BOOST_TEST(std::abs(circle.arc_length(0.5, 0.5 + 8.0) - 4 * M_PI * r) < 1e-13);
  BOOST_TEST(std::abs(circle.arc_length(3.5, -0.5) + 2 * M_PI * r) < 1e-13);  // back one turn
}

BOOST_AUTO_TEST_CASE(exact_ellipse) {
  const double a = 3, b = 1.2;
  const auto e = BezierPath<double>::ellipse(V(0, 0), a, b);
  for (int k = 0; k <= 400; ++k) {
    const V p = e.jet(k / 100.0, 0).p;
    BOOST_TEST(std::abs(p.x() * p.x() / (a * a) + p.y() * p.y() / (b * b) - 1) < 1e-14);
  }
  // Perimeter 4 a E(k), k = sqrt(1 - b^2/a^2) (complete elliptic integral of the second kind).
  const double perimeter = 4 * a * boost::math::ellint_2(std::sqrt(1 - b * b / (a * a)));
  std::printf("ellipse perimeter: bezier %.16f, 4aE(k) %.16f\n", e.total_length(), perimeter);
  BOOST_TEST(std::abs(e.total_length() - perimeter) < 1e-14 * perimeter);
  // Curvature at the vertices: a/b^2 at (a, 0), b/a^2 at (0, b).
  BOOST_TEST(std::abs(rollkin::contour_point(e.jet(0.0, 2), 2).curvature() - a / (b * b)) < 1e-13);
  BOOST_TEST(std::abs(rollkin::contour_point(e.jet(1.0, 2), 2).curvature() - b / (a * a)) < 1e-13);
  // Rotated ellipse passes through its rotated vertex.
  const auto rot = BezierPath<double>::ellipse(V(1, 2), a, b, M_PI / 6);
  BOOST_TEST((rot.jet(0.0, 0).p - V(1 + a * std::cos(M_PI / 6), 2 + a * std::sin(M_PI / 6))).norm() < 1e-14);
}

BOOST_AUTO_TEST_CASE(exact_parabola) {
  const double a = 0.5, x0 = -2, x1 = 2;
  const auto p = BezierPath<double>::parabola(a, x0, x1);
  BOOST_TEST(p.continuity() == 2);
  for (int k = 0; k <= 100; ++k) {
    const double u = k / 100.0, x = x0 + (x1 - x0) * u;
    const auto j = p.jet(u, 3);
    BOOST_TEST(std::abs(j.p.x() - x) < 1e-15);
    BOOST_TEST(std::abs(j.p.y() - a * x * x) < 1e-14);
    const double kappa = 2 * a / std::pow(1 + 4 * a * a * x * x, 1.5);
    BOOST_TEST(std::abs(rollkin::contour_point(j, 2).curvature() - kappa) < 1e-14);
    BOOST_TEST(j.d3.norm() == 0.0);
  }
  const double exact = parabola_arc(a, x1) - parabola_arc(a, x0);
  std::printf("parabola arc length: bezier %.16f exact %.16f\n", p.total_length(), exact);
  BOOST_TEST(std::abs(p.total_length() - exact) < 1e-14 * exact);
  BOOST_TEST(std::abs(p.arc_length(0.25, 0.9) - (parabola_arc(a, 1.6) - parabola_arc(a, -1.0))) < 1e-14);
}

BOOST_AUTO_TEST_CASE(inverse_arc_length_round_trips) {
  const auto p = BezierPath<double>::parabola(0.5, -2, 2);
  for (double u0 : {0.0, 0.4})
    for (double u1 : {0.0, 0.1, 0.5, 1.0}) BOOST_TEST(std::abs(p.param_at_arc_length(u0, p.arc_length(u0, u1)) - u1) < 1e-14);
  const auto e = BezierPath<double>::ellipse(V(0, 0), 2, 1);
  for (double u1 : {-3.3, 0.2, 1.0, 2.5, 9.75}) BOOST_TEST(std::abs(e.param_at_arc_length(0.7, e.arc_length(0.7, u1)) - u1) < 1e-13);
  // Inverse against the closed form on the circle: ds = r * angle.
  const auto c = BezierPath<double>::circle(V(0, 0), 2.0);
  const double u = c.param_at_arc_length(0.0, 2.0 * 2.0);  // 2 radians
  BOOST_TEST((c.jet(u, 0).p - 2.0 * V(std::cos(2.0), std::sin(2.0))).norm() < 1e-14);
}

BOOST_AUTO_TEST_CASE(closed_path_wraps) {
  const auto e = BezierPath<double>::ellipse(V(0.5, 0), 2, 1);
  for (double u : {0.0, 0.3, 2.99}) {
    const auto a = e.jet(u, 3), b = e.jet(u + 4, 3), m = e.jet(u - 8, 3);
    BOOST_TEST((a.p - b.p).norm() < 1e-14);
    BOOST_TEST((a.d3 - m.d3).norm() < 1e-12);
  }
}

BOOST_AUTO_TEST_CASE(validation_names_segments_and_joints) {
  const Seg s0{{V(0, 0), V(1, 0)}, {}};
  const Seg gap{{V(1, 0.1), V(2, 0.1)}, {}};
  const Seg corner{{V(1, 0), V(1, 1)}, {}};
  const Seg smooth{{V(1, 0), V(2, 0), V(3, 1)}, {}};
  BOOST_TEST(message_of({s0, gap}, false).find("segment 1 starts at") != std::string::npos);
  BOOST_TEST(message_of({s0, corner}, false).empty());  // a corner splits the path (next test)
  BOOST_TEST(message_of({s0, smooth}, false).empty());
  BOOST_TEST(message_of({s0, smooth}, true).find("closed path") != std::string::npos);
  BOOST_TEST(message_of({Seg{{V(1, 1), V(1, 1)}, {}}}, false).find("degenerate") != std::string::npos);
  BOOST_TEST(message_of({Seg{{V(0, 0), V(1, 1)}, {1.0, -1.0}}}, false).find("weights") != std::string::npos);
  BOOST_TEST(message_of({Seg{{V(0, 0)}, {}}}, false).find("segment 0") != std::string::npos);
}

// Corners split the path: listed with the segment that starts there, the point and the signed turn; the
// smooth pieces between them keep their own continuity.
BOOST_AUTO_TEST_CASE(corners_are_listed_and_split_the_path) {
  // A unit square, counter-clockwise: four left turns of 90 degrees, the closing one at u = 0.
  const std::vector<Seg> square{Seg{{V(0, 0), V(1, 0)}, {}}, Seg{{V(1, 0), V(1, 1)}, {}}, Seg{{V(1, 1), V(0, 1)}, {}},
                                Seg{{V(0, 1), V(0, 0)}, {}}};
  const BezierPath<double> closed(square, true);
  BOOST_REQUIRE_EQUAL(closed.corners().size(), 4u);
  const std::vector<V> vertex{V(0, 0), V(1, 0), V(1, 1), V(0, 1)};
  for (const auto& c : closed.corners()) {
    BOOST_TEST((c.point - vertex[c.piece]).norm() == 0.0);
    BOOST_TEST(std::abs(c.turn - M_PI / 2) < 1e-15);
  }
  BOOST_TEST(closed.corners().back().piece == 0u);  // the closing joint comes last
  const BezierPath<double> open(std::vector<Seg>(square.begin(), square.end() - 1), false);
  BOOST_TEST(open.corners().size() == 2u);  // an open path has no corner at its ends
  BOOST_TEST(open.continuity() == 2);       // each piece is a straight segment
  // A right turn is negative; a G1 joint is no corner.
  const Seg s0{{V(0, 0), V(1, 0)}, {}};
  const BezierPath<double> right({s0, Seg{{V(1, 0), V(1, -1)}, {}}}, false);
  BOOST_TEST(std::abs(right.corners().front().turn + M_PI / 2) < 1e-15);
  BOOST_TEST(BezierPath<double>({s0, Seg{{V(1, 0), V(2, 0), V(3, 1)}, {}}}, false).corners().empty());
}

BOOST_AUTO_TEST_CASE(zero_end_derivative_uses_next_control_point) {
  // Segment 0 ends with P2 == P3: its end tangent comes from P1 -> P3, direction (1, 0), matching segment 1.
  const Seg a{{V(0, 1), V(-1, 0), V(2, 0), V(2, 0)}, {}};
  const Seg b{{V(2, 0), V(3, 0), V(4, 1)}, {}};
  const BezierPath<double> path({a, b}, false);
  BOOST_TEST(path.stationary_params().size() == 1u);
  BOOST_TEST(path.stationary_params()[0] == 1.0);
  BOOST_TEST(path.jet(1.0, 1).d1.x() > 0);  // speed of segment 1 at its start
  BOOST_TEST(std::abs(path.arc_length(0.0, 2.0) - path.arc_length(0.0, 1.0) - path.arc_length(1.0, 2.0)) < 1e-14);
}

BOOST_AUTO_TEST_CASE(c2_joint_detected) {
  // Uniform cubic B-spline spans converted to Bezier are C2 at the joints.
  const V d0(0, 0), d1(1, 2), d2(3, 2), d3(4, 0), d4(6, 1);
  auto span = [](V a, V b, V c, V d) {
    return Seg{{(a + 4 * b + c) / 6, (2 * b + c) / 3, (b + 2 * c) / 3, (b + 4 * c + d) / 6}, {}};
  };
  const BezierPath<double> path({span(d0, d1, d2, d3), span(d1, d2, d3, d4)}, false);
  BOOST_TEST(path.continuity() == 2);
}

BOOST_AUTO_TEST_CASE(mpfr_exact_circle) {
  using mp = rollkin::mpfr50;
  const mp r = mp(3) / mp(2);
  const rollkin::Vec2<mp> c(mp(1) / mp(3), mp(-2));
  const auto circle = BezierPath<mp>::circle(c, r);
  mp worst_r(0), worst_k(0);
  for (int k = 0; k <= 400; ++k) {
    const auto j = circle.jet(mp(k) / mp(100), 2);
    worst_r = std::max(worst_r, mp(abs((j.p - c).norm() - r)));
    worst_k = std::max(worst_k, mp(abs(rollkin::contour_point(j, 2).curvature() - 1 / r)));
  }
  std::printf("MPFR rational circle: max radial error %.2e, max curvature error %.2e\n", double(worst_r), double(worst_k));
  BOOST_TEST(double(worst_r) < 1e-40);
  BOOST_TEST(double(worst_k) < 1e-40);
  const mp perimeter = 2 * rollkin::pi<mp>() * r;
  BOOST_TEST(double(abs(circle.total_length() - perimeter)) < 1e-40);
  const mp u = circle.param_at_arc_length(mp(0), r);  // one radian
  BOOST_TEST(double(abs(circle.arc_length(mp(0), u) - r)) < 1e-40);
  const rollkin::Vec2<mp> p = circle.jet(u, 0).p - c;
  BOOST_TEST(double(abs(atan2(p.y(), p.x()) - 1)) < 1e-40);
  // cast back to double keeps the exact circle.
  const BezierPath<double> d = circle.cast<double>();
  BOOST_TEST(std::abs(d.total_length() - 3 * M_PI) < 1e-14);
}
