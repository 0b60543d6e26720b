// NURBS -> rational Bezier pieces (profile/nurbs.hpp): the exact circle as a rational quadratic NURBS lies on
// the circle and has length 2 pi r; cubic NURBS (clamped with interior and double knots, and unclamped) agree
// point by point with an independent evaluation written here from the definition (Cox-de Boor recursion for
// the basis, eq. 2.5 of The NURBS Book, then the rational sum), in double and in MPFR; corners are found at
// kinked C0 knots only; invalid curves are refused with messages that say what is wrong.
#define BOOST_TEST_MODULE profile_nurbs
#include <boost/test/unit_test.hpp>

#include "rollkin/profile/nurbs.hpp"
#include "rollkin/scalar_mpfr.hpp"

#include <cstdio>
#include <string>
#include <vector>

using rollkin::BezierPath;
using rollkin::Nurbs;
using rollkin::NurbsPieces;
using rollkin::Vec2;
using rollkin::mpfr50;

namespace {

/// N_{i,p}(u) by the Cox-de Boor recursion, straight from the definition (0/0 taken as 0). The last non-empty
/// knot span is closed on the right so that u = u_n is inside the curve's range.
template <class S> S basis(const std::vector<S>& U, std::size_t i, int p, const S& u, const S& hi) {
  if (p == 0) {
    if (U[i] <= u && u < U[i + 1]) return S(1);
    if (u == hi && U[i] < U[i + 1] && U[i + 1] == hi) return S(1);
    return S(0);
  }
  S left(0), right(0);
  const std::size_t q = static_cast<std::size_t>(p);
  if (U[i + q] > U[i]) left = (u - U[i]) / (U[i + q] - U[i]) * basis(U, i, p - 1, u, hi);
  if (U[i + q + 1] > U[i + 1]) right = (U[i + q + 1] - u) / (U[i + q + 1] - U[i + 1]) * basis(U, i + 1, p - 1, u, hi);
  return left + right;
}

template <class S> Vec2<S> reference_point(const Nurbs<S>& c, const S& u) {
  Vec2<S> num = Vec2<S>::Zero();
  S den(0);
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    const S b = basis(c.knots, i, c.degree, u, c.hi()) * c.weight(i);
    num += b * c.points[i];
    den += b;
  }
  return num / den;
}

/// The path's point at NURBS parameter u: the piece whose [break_i, break_{i+1}] holds u, t linear in u.
template <class S> Vec2<S> path_point(const BezierPath<S>& path, const NurbsPieces<S>& pieces, const S& u) {
  std::size_t i = 0;
  while (i + 2 < pieces.breaks.size() && u >= pieces.breaks[i + 1]) ++i;
  const S t = (u - pieces.breaks[i]) / (pieces.breaks[i + 1] - pieces.breaks[i]);
  return path.jet(S(i) + t, 0).p;
}

/// max |C_path(u) - C_reference(u)| over `samples` equally spaced parameters, relative to the control extent.
template <class S> double worst_relative_difference(const Nurbs<S>& c, int samples) {
  const NurbsPieces<S> pieces = rollkin::nurbs_to_bezier(c);
  BOOST_REQUIRE(pieces.corners.empty());
  const BezierPath<S> path(pieces.segments, pieces.closed);
  Vec2<S> lo = c.points[0], hi = c.points[0];
  for (const auto& p : c.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const S extent = (hi - lo).norm();
  S worst(0);
  for (int k = 0; k <= samples; ++k) {
    const S u = c.lo() + (c.hi() - c.lo()) * S(k) / S(samples);
    const S d = (path_point(path, pieces, u) - reference_point(c, u)).norm() / extent;
    if (d > worst) worst = d;
  }
  return rollkin::to_double(worst);
}

template <class S> Nurbs<S> exact_circle(const S& r) {
  using std::sqrt;
  Nurbs<S> c;
  c.degree = 2;
  const int xs[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, ys[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
  for (int i = 0; i < 9; ++i) {
    c.points.emplace_back(r * S(xs[i]), r * S(ys[i]));
    c.weights.push_back(i % 2 == 0 ? S(1) : sqrt(S(2)) / S(2));
  }
  c.knots = {S(0), S(0), S(0), S(1) / S(4), S(1) / S(4), S(1) / S(2), S(1) / S(2), S(3) / S(4), S(3) / S(4), S(1), S(1), S(1)};
  c.closed = true;
  return c;
}

/// Clamped cubic with weights, simple interior knots and a double knot (C1 there, smooth in shape).
template <class S> Nurbs<S> clamped_cubic() {
  Nurbs<S> c;
  c.degree = 3;
  const int xy[8][2] = {{0, 0}, {1, 2}, {3, 3}, {5, 2}, {6, 0}, {8, -1}, {9, 1}, {11, 2}};
  const int w[8] = {1, 3, 2, 5, 1, 4, 2, 1};  // weights in quarters
  for (int i = 0; i < 8; ++i) {
    c.points.emplace_back(S(xy[i][0]) / S(2), S(xy[i][1]) / S(3));
    c.weights.push_back(S(w[i]) / S(4));
  }
  c.knots = {S(0), S(0), S(0), S(0), S(1) / S(5), S(2) / S(5), S(2) / S(5), S(7) / S(10), S(1), S(1), S(1), S(1)};
  return c;
}

/// Unclamped (uniform) cubic with weights: the curve lives on [u_3, u_7].
template <class S> Nurbs<S> unclamped_cubic() {
  Nurbs<S> c;
  c.degree = 3;
  const int xy[7][2] = {{0, 0}, {2, 3}, {5, 4}, {7, 1}, {9, -2}, {12, 0}, {13, 3}};
  const int w[7] = {2, 1, 3, 2, 5, 1, 2};
  for (int i = 0; i < 7; ++i) {
    c.points.emplace_back(S(xy[i][0]), S(xy[i][1]));
    c.weights.push_back(S(w[i]) / S(2));
  }
  for (int i = 0; i < 11; ++i) c.knots.push_back(S(i) / S(3));
  return c;
}

/// Unclamped cubic whose last knot of the range, u_n, is double and followed by larger knots: inserting u_n
/// must not read knots past the end (found by fuzzing the DXF reader).
template <class S> Nurbs<S> double_end_knot_cubic() {
  Nurbs<S> c = unclamped_cubic<S>();
  c.knots = {S(0), S(1), S(2), S(3), S(4), S(5), S(6), S(7), S(7), S(9), S(10)};
  return c;
}

template <class F> std::string invalid_message(F&& make) {
  try {
    rollkin::nurbs_to_bezier(make());
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

bool has(const std::string& s, const std::string& part) {
  if (s.find(part) != std::string::npos) return true;
  BOOST_TEST_MESSAGE("\"" << s << "\" does not contain \"" << part << "\"");
  return false;
}

}  // namespace

BOOST_AUTO_TEST_CASE(exact_circle_lies_on_the_circle_and_has_length_two_pi_r) {
  const double r = 2.5;
  const auto pieces = rollkin::nurbs_to_bezier(exact_circle(r));
  BOOST_TEST(pieces.segments.size() == 4u);
  BOOST_TEST(pieces.closed);
  BOOST_TEST(pieces.corners.empty());
  const BezierPath<double> path(pieces.segments, true);
  double worst = 0;
  for (int k = 0; k <= 4000; ++k) worst = std::max(worst, std::abs(path.jet(k / 1000.0, 0).p.norm() - r) / r);
  std::printf("NURBS circle r = 2.5: max | |p| - r | / r = %.2e, length error %.2e\n", worst,
              std::abs(path.total_length() - 2 * M_PI * r) / (2 * M_PI * r));
  BOOST_TEST(worst < 1e-14);
  BOOST_TEST(std::abs(path.total_length() - 2 * M_PI * r) < 1e-14 * 2 * M_PI * r);
}

BOOST_AUTO_TEST_CASE(exact_circle_in_mpfr) {
  const mpfr50 r = mpfr50(5) / mpfr50(2);
  const auto pieces = rollkin::nurbs_to_bezier(exact_circle(r));
  const BezierPath<mpfr50> path(pieces.segments, true);
  mpfr50 worst(0);
  for (int k = 0; k <= 400; ++k) {
    const mpfr50 d = abs(path.jet(mpfr50(k) / mpfr50(100), 0).p.norm() - r) / r;
    if (d > worst) worst = d;
  }
  BOOST_TEST(rollkin::to_double(worst) < 1e-45);
}

BOOST_AUTO_TEST_CASE(cubics_match_cox_de_boor_in_double) {
  const double clamped = worst_relative_difference(clamped_cubic<double>(), 1000);
  const double unclamped = worst_relative_difference(unclamped_cubic<double>(), 1000);
  std::printf("cubic NURBS vs Cox-de Boor (double, 1001 parameters): clamped %.2e, unclamped %.2e\n", clamped, unclamped);
  BOOST_TEST(clamped < 1e-13);
  BOOST_TEST(unclamped < 1e-13);
  BOOST_TEST(worst_relative_difference(double_end_knot_cubic<double>(), 1000) < 1e-13);
}

BOOST_AUTO_TEST_CASE(cubics_match_cox_de_boor_in_mpfr) {
  const double clamped = worst_relative_difference(clamped_cubic<mpfr50>(), 1000);
  const double unclamped = worst_relative_difference(unclamped_cubic<mpfr50>(), 1000);
  std::printf("cubic NURBS vs Cox-de Boor (MPFR 50 digits): clamped %.2e, unclamped %.2e\n", clamped, unclamped);
  BOOST_TEST(clamped < 1e-45);
  BOOST_TEST(unclamped < 1e-45);
  BOOST_TEST(worst_relative_difference(double_end_knot_cubic<mpfr50>(), 1000) < 1e-45);
}

BOOST_AUTO_TEST_CASE(polynomial_curve_gives_polynomial_pieces) {
  Nurbs<double> c = clamped_cubic<double>();
  c.weights.clear();
  const auto pieces = rollkin::nurbs_to_bezier(c);
  BOOST_TEST(pieces.segments.size() == 4u);  // spans [0, .2], [.2, .4], [.4, .7], [.7, 1]
  for (const auto& s : pieces.segments) BOOST_TEST(!s.rational());
  BOOST_TEST(worst_relative_difference(c, 1000) < 1e-13);
}

BOOST_AUTO_TEST_CASE(kinked_double_knot_is_a_corner_and_a_smooth_one_is_not) {
  Nurbs<double> c;
  c.degree = 2;
  c.points = {Vec2<double>(0, 0), Vec2<double>(1, 0), Vec2<double>(2, 0), Vec2<double>(2, 1), Vec2<double>(2, 2)};
  c.knots = {0, 0, 0, 1, 1, 2, 2, 2};
  const auto kinked = rollkin::nurbs_to_bezier(c);
  BOOST_REQUIRE(kinked.corners.size() == 1u);
  BOOST_TEST(kinked.corners[0].piece == 1u);
  BOOST_TEST((kinked.corners[0].point - Vec2<double>(2, 0)).norm() == 0.0);
  BOOST_TEST(std::abs(kinked.corners[0].turn - M_PI / 2) < 1e-15);

  c.points = {Vec2<double>(0, 0), Vec2<double>(1, 0), Vec2<double>(2, 0), Vec2<double>(3, 0), Vec2<double>(4, 1)};
  BOOST_TEST(rollkin::nurbs_to_bezier(c).corners.empty());
}

BOOST_AUTO_TEST_CASE(invalid_curves_are_refused_with_messages) {
  BOOST_TEST(has(invalid_message([] { auto c = clamped_cubic<double>(); c.degree = 0; return c; }), "degree 0 must be at least 1"));
  BOOST_TEST(has(invalid_message([] { auto c = clamped_cubic<double>(); c.knots.pop_back(); return c; }),
                 "11 knots given; 8 control points of degree 3 need points + degree + 1 = 12"));
  BOOST_TEST(has(invalid_message([] { auto c = clamped_cubic<double>(); c.knots[5] = 0.1; return c; }),
                 "knots must be non-decreasing; knot 5 = 0.10000000000000001 is less than knot 4"));
  BOOST_TEST(has(invalid_message([] { auto c = clamped_cubic<double>(); c.weights[2] = 0; return c; }), "weight 2 = 0 must be positive"));
  BOOST_TEST(has(invalid_message([] { auto c = clamped_cubic<double>(); c.weights.pop_back(); return c; }),
                 "7 weights given for 8 control points"));
  BOOST_TEST(has(invalid_message([] { auto c = clamped_cubic<double>(); c.points.resize(3); c.knots.resize(7); return c; }),
                 "3 control points are too few for degree 3"));
  BOOST_TEST(has(invalid_message([] { auto c = clamped_cubic<double>(); c.knots = {0, 0, 0, 0, 0.5, 0.5, 0.5, 0.5, 1, 1, 1, 1}; return c; }),
                 "knot value 0.5 has multiplicity 4"));
  BOOST_TEST(has(invalid_message([] { auto c = clamped_cubic<double>(); c.knots.assign(12, 1.0); return c; }), "empty parameter range"));
  BOOST_TEST(has(invalid_message([] { auto c = clamped_cubic<double>(); c.points[2].x() = NAN; return c; }), "control point 2 is not finite"));
  BOOST_TEST(has(invalid_message([] { auto c = clamped_cubic<double>(); c.closed = true; return c; }), "marked closed but its end"));
}
