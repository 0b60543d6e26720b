// The contract every profile kind keeps (include/rollkin/profile/jet.hpp, "profile concept"), checked by
// one typed test body over every (kind, scalar) pair, in double and in MPFR at 50 digits:
//  - the parameter range: lo < hi, the jet finite inside and at the ends;
//  - the jet against central finite differences of itself: p' from p, p'' from p', and the curvature
//    (p' x p'')/|p'|^3 from second differences of p alone; steps and tolerances follow the scalar's epsilon
//    (first differences: h = eps^(1/3) L, error ~ eps^(2/3); second: h = eps^(1/4) L, error ~ eps^(1/2));
//  - arc length against an independent Gauss-Legendre quadrature of |p'(u)| (profile/quadrature.hpp);
//  - closed kinds wrap (jet(u + period) = jet(u)); open kinds do not claim to;
//  - invalid construction throws std::invalid_argument.
// Test points and arc-length intervals lie inside one piece of every piecewise kind used here (pieces of
// equal parameter length 1/8, 1/4, 1/2 of the domain), where the curve is analytic.
//
// A new kind joins by one factory struct below (make, refuse, closed) and one entry in Kinds.
#define BOOST_TEST_MODULE profile_contract
#include <boost/mp11/algorithm.hpp>
#include <boost/test/unit_test.hpp>

#include "rollkin/profile/profile.hpp"
#include "rollkin/scalar_mpfr.hpp"

#include <tuple>
#include <vector>

using namespace rollkin;
using M = mpfr_scalar<50>;

namespace {

// ---- one factory per kind: make<S>() builds a valid profile, refuse<S>() tries invalid ones ---------

struct LineKind {
  static constexpr bool closed = false;
  template <class S> static Line<S> make() { return Line<S>(S(-1) / S(2), S(3)); }
  template <class S> static void refuse() {
    BOOST_CHECK_THROW(Line<S>(S(1), S(1)), std::invalid_argument);
    BOOST_CHECK_THROW(Line<S>(S(2), S(1)), std::invalid_argument);
    BOOST_CHECK_THROW(Line<S>(S(0), std::numeric_limits<S>::infinity()), std::invalid_argument);
  }
};

struct CircleKind {
  static constexpr bool closed = true;
  template <class S> static Circle<S> make() { return Circle<S>(S(3) / S(2)); }
  template <class S> static void refuse() {
    BOOST_CHECK_THROW(Circle<S>(S(0)), std::invalid_argument);
    BOOST_CHECK_THROW(Circle<S>(S(-1)), std::invalid_argument);
    BOOST_CHECK_THROW(Circle<S>(std::numeric_limits<S>::quiet_NaN()), std::invalid_argument);
  }
};

struct CircleArcKind {
  static constexpr bool closed = false;
  template <class S> static Circle<S> make() { return Circle<S>(S(2), S(-1) / S(3), S(2)); }
  template <class S> static void refuse() {
    BOOST_CHECK_THROW(Circle<S>(S(0), S(0), S(1)), std::invalid_argument);
    BOOST_CHECK_THROW(Circle<S>(S(-2), S(0), S(1)), std::invalid_argument);
    BOOST_CHECK_THROW(Circle<S>(S(1), S(1), S(1)), std::invalid_argument);
    BOOST_CHECK_THROW(Circle<S>(S(1), S(1), S(0)), std::invalid_argument);
  }
};

struct ParabolaKind {
  static constexpr bool closed = false;
  template <class S> static Parabola<S> make() { return Parabola<S>(S(1) / S(4), S(-2), S(3)); }
  template <class S> static void refuse() {
    BOOST_CHECK_THROW(Parabola<S>(S(0), S(-1), S(1)), std::invalid_argument);
    BOOST_CHECK_THROW(Parabola<S>(S(1), S(1), S(1)), std::invalid_argument);
    BOOST_CHECK_THROW(Parabola<S>(S(1), S(2), S(-1)), std::invalid_argument);
  }
};

struct EllipseKind {
  static constexpr bool closed = true;
  template <class S> static Ellipse<S> make() { return Ellipse<S>(S(3), S(2)); }
  template <class S> static void refuse() {
    BOOST_CHECK_THROW(Ellipse<S>(S(0), S(1)), std::invalid_argument);
    BOOST_CHECK_THROW(Ellipse<S>(S(1), S(-1)), std::invalid_argument);
  }
};

/// Arc length by its own quadrature (Gauss-Legendre, 20 points on 2 panels) instead of the closed form.
struct EllipseQuadratureKind {
  static constexpr bool closed = true;
  template <class S> static Ellipse<S> make() {
    ArcLengthMethod am;
    am.closed_form = false;
    am.rule.order = 20;
    am.rule.panels = 2;
    return Ellipse<S>(S(2), S(7) / S(2), am);
  }
  template <class S> static void refuse() {
    BOOST_CHECK_THROW(Ellipse<S>(S(-3), S(1), ArcLengthMethod{}), std::invalid_argument);
  }
};

/// n samples equally spaced on a circle of radius r from angle 0 to `turn` (a whole turn: closed, without
/// repeating the first): equal chords, hence knots of equal spacing in the chord-length parameter.
template <class S> std::vector<Vec2<S>> arc_samples(int n, const S& r, const S& turn, bool closed) {
  std::vector<Vec2<S>> out;
  using std::cos;
  using std::sin;
  for (int i = 0; i < n; ++i) {
    const S a = turn * S(i) / S(closed ? n : n - 1);
    out.emplace_back(r * cos(a), r * sin(a));
  }
  return out;
}

template <class S> SplineOptions<S> spline_options(bool closed) {
  SplineOptions<S> o;
  o.closed = closed;
  return o;
}

template <class S> void refuse_samples(bool closed) {
  const std::vector<Vec2<S>> three = {Vec2<S>(S(0), S(0)), Vec2<S>(S(1), S(0)), Vec2<S>(S(1), S(1))};
  // Too few samples: an open (natural) spline needs 2, a closed one 3.
  const std::vector<Vec2<S>> too_few(three.begin(), three.begin() + (closed ? 2 : 1));
  BOOST_CHECK_THROW(SampledProfile<S>(too_few, spline_options<S>(closed)), std::invalid_argument);
  std::vector<Vec2<S>> repeated = three;
  repeated.insert(repeated.begin() + 1, three[0]);  // two equal consecutive samples
  repeated.push_back(Vec2<S>(S(0), S(2)));
  BOOST_CHECK_THROW(SampledProfile<S>(repeated, spline_options<S>(closed)), std::invalid_argument);
  SplineOptions<S> negative = spline_options<S>(closed);
  negative.smoothing_tolerance = S(-1);
  BOOST_CHECK_THROW(SampledProfile<S>(arc_samples<S>(8, S(1), S(2), closed), negative), std::invalid_argument);
}

struct SamplesOpenKind {
  static constexpr bool closed = false;
  template <class S> static SampledProfile<S> make() {
    return SampledProfile<S>(arc_samples<S>(9, S(2), S(3), false), spline_options<S>(false));
  }
  template <class S> static void refuse() { refuse_samples<S>(false); }
};

struct SamplesClosedKind {
  static constexpr bool closed = true;
  template <class S> static SampledProfile<S> make() {
    return SampledProfile<S>(arc_samples<S>(8, S(2), S(2) * pi<S>(), true), spline_options<S>(true));
  }
  template <class S> static void refuse() { refuse_samples<S>(true); }
};

template <class S> BezierSegment<S> segment(std::vector<Vec2<S>> points, std::vector<S> weights = {}) {
  return BezierSegment<S>{std::move(points), std::move(weights)};
}

/// Two cubic segments meeting with a continuous tangent at (2, 1).
template <class S> BezierPath<S> two_cubics() {
  auto P = [](int x, int y) { return Vec2<S>(S(x), S(y)); };
  return BezierPath<S>({segment<S>({P(0, 0), P(1, 0), P(1, 1), P(2, 1)}), segment<S>({P(2, 1), P(3, 1), P(4, 3), P(5, 2)})},
                       false);
}

/// An exact ellipse (semi-axes 2 and 1) as four rational quadratic quarter arcs (weights 1, 1/sqrt 2, 1).
template <class S> BezierPath<S> rational_ellipse() {
  using std::sqrt;
  const S w = S(1) / sqrt(S(2));
  std::vector<BezierSegment<S>> segs;
  const Vec2<S> c[4] = {Vec2<S>(S(2), S(0)), Vec2<S>(S(0), S(1)), Vec2<S>(S(-2), S(0)), Vec2<S>(S(0), S(-1))};
  for (int k = 0; k < 4; ++k) {
    const Vec2<S> a = c[k], b = c[(k + 1) % 4];
    segs.push_back(segment<S>({a, a + b, b}, {S(1), w, S(1)}));
  }
  return BezierPath<S>(std::move(segs), true);
}

template <class S> void refuse_bezier() {
  const Vec2<S> o(S(0), S(0)), x(S(1), S(0));
  BOOST_CHECK_THROW(BezierPath<S>({}, false), std::invalid_argument);
  BOOST_CHECK_THROW(BezierPath<S>({segment<S>({o})}, false), std::invalid_argument);
  BOOST_CHECK_THROW(BezierPath<S>({segment<S>({o, o, o})}, false), std::invalid_argument);
  BOOST_CHECK_THROW(BezierPath<S>({segment<S>({o, x}, {S(1), S(0)})}, false), std::invalid_argument);
  BOOST_CHECK_THROW(BezierPath<S>({segment<S>({o, x}, {S(1)})}, false), std::invalid_argument);
}

struct BezierKind {
  static constexpr bool closed = false;
  template <class S> static BezierPath<S> make() { return two_cubics<S>(); }
  template <class S> static void refuse() { refuse_bezier<S>(); }
};

struct RationalBezierKind {
  static constexpr bool closed = true;
  template <class S> static BezierPath<S> make() { return rational_ellipse<S>(); }
  template <class S> static void refuse() { refuse_bezier<S>(); }
};

/// Re-parameterised by arc length: the closed sampled circle (8 congruent spans, each of length L/8).
struct ArcLengthSamplesKind {
  static constexpr bool closed = true;
  template <class S> static ArcLengthProfile<S> make() { return ArcLengthProfile<S>(SamplesClosedKind::make<S>()); }
  template <class S> static void refuse() { refuse_samples<S>(true); }  // it only takes a valid base
};

/// Re-parameterised by arc length: the rational ellipse (four congruent quarters, pieces of length L/4).
struct ArcLengthBezierKind {
  static constexpr bool closed = true;
  template <class S> static ArcLengthProfile<S> make() { return ArcLengthProfile<S>(rational_ellipse<S>()); }
  template <class S> static void refuse() { refuse_bezier<S>(); }
};

using Kinds = std::tuple<LineKind, CircleKind, CircleArcKind, ParabolaKind, EllipseKind, EllipseQuadratureKind,
                         SamplesOpenKind, SamplesClosedKind, BezierKind, RationalBezierKind, ArcLengthSamplesKind,
                         ArcLengthBezierKind>;
using Scalars = std::tuple<double, M>;

template <class Kind, class S> struct Case {
  using kind = Kind;
  using scalar = S;
};
using Cases = boost::mp11::mp_product<Case, Kinds, Scalars>;

// ---- helpers ------------------------------------------------------------------------------------------

template <class S> bool finite(const Vec2<S>& v) {
  using std::isfinite;
  return isfinite(v.x()) && isfinite(v.y());
}

/// Interior test parameters: fractions 0.02, 0.27, 0.52, 0.77 of the domain (plus half an interval, see
/// interval()), inside one piece for pieces of 1/8, 1/4, 1/2 of the domain.
template <class S> std::vector<S> test_parameters(const Domain<S>& d) {
  std::vector<S> out;
  for (int k : {2, 27, 52, 77}) out.push_back(d.lo + d.period() * S(k) / S(100));
  return out;
}
/// Length of the arc-length test intervals: 1/64 of the domain.
template <class S> S interval(const Domain<S>& d) { return d.period() / S(64); }

/// Size of the curve: the largest |p| at the test points and ends, or 1.
template <class P, class S = typename P::Scalar> S curve_scale(const P& p) {
  const Domain<S> d = p.domain();
  S scale(1);
  using std::max;
  for (const S& u : test_parameters(d)) scale = max(scale, S(p.jet(u, 0).p.norm()));
  scale = max(scale, S(p.jet(d.lo, 0).p.norm()));
  return scale;
}

}  // namespace

BOOST_AUTO_TEST_CASE_TEMPLATE(parameter_range_and_jet_defined, C, Cases) {
  using S = typename C::scalar;
  const auto profile = C::kind::template make<S>();
  const Domain<S> d = profile.domain();
  BOOST_TEST(d.lo < d.hi);
  std::vector<S> at = test_parameters(d);
  at.push_back(d.lo);
  if (!d.closed) at.push_back(d.hi);
  for (const S& u : at) {
    const Jet<S> j = profile.jet(u, 3);
    BOOST_TEST((finite(j.p) && finite(j.d1) && finite(j.d2) && finite(j.d3)));
    BOOST_TEST(j.d1.norm() > S(0));  // a regular curve: the tangent is defined
  }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(jet_against_finite_differences, C, Cases) {
  using S = typename C::scalar;
  using std::cbrt;
  using std::sqrt;
  const auto profile = C::kind::template make<S>();
  const Domain<S> d = profile.domain();
  const S eps = epsilon<S>();
  const S L = d.period();
  const S h1 = cbrt(eps) * L, h2 = sqrt(sqrt(eps)) * L;
  const S scale = curve_scale(profile);
  const S tol1 = S(200) * cbrt(eps) * cbrt(eps), tol2 = S(200) * sqrt(eps);
  for (const S& u0 : test_parameters(d)) {
    const S u = u0 + interval(d) / S(2);
    const Jet<S> j = profile.jet(u, 3);
    auto p = [&](const S& v) { return profile.jet(v, 0).p; };
    auto d1 = [&](const S& v) { return profile.jet(v, 1).d1; };
    auto d2 = [&](const S& v) { return profile.jet(v, 2).d2; };
    // p' and p'' against central differences of p and p' (relative to the curve's size per unit of u).
    const Vec2<S> fd1 = (p(u + h1) - p(u - h1)) / (S(2) * h1);
    const Vec2<S> fd2 = (d1(u + h1) - d1(u - h1)) / (S(2) * h1);
    const Vec2<S> fd3 = (d2(u + h1) - d2(u - h1)) / (S(2) * h1);
    const S per_u = scale / L;
    BOOST_TEST((j.d1 - fd1).norm() <= tol1 * (j.d1.norm() + per_u));
    BOOST_TEST((j.d2 - fd2).norm() <= tol1 * (j.d2.norm() + j.d1.norm() / L + per_u / L));
    // The third derivative has the largest truncation term (h^2 p^(5) / 6, large for the arc-length
    // ellipse): 10 times the margin.
    BOOST_TEST((j.d3 - fd3).norm() <= S(10) * tol1 * (j.d3.norm() + j.d2.norm() / L + per_u / (L * L)));
    // Unit tangent and curvature against second differences of p alone.
    const ContourPoint<S> cp = contour_point(j, 2);
    const Vec2<S> q1 = (p(u + h2) - p(u - h2)) / (S(2) * h2);
    const Vec2<S> q2 = (p(u + h2) - S(2) * p(u) + p(u - h2)) / (h2 * h2);
    const S kappa_fd = cross2(q1, q2) / (q1.norm() * q1.squaredNorm());
    BOOST_TEST((cp.tangent - q1.normalized()).norm() <= tol2);
    using std::abs;
    BOOST_TEST(abs(cp.curvature() - kappa_fd) <= tol2 * (abs(cp.curvature()) + S(1) / scale) * S(10));
  }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(arc_length_against_quadrature, C, Cases) {
  using S = typename C::scalar;
  const auto profile = C::kind::template make<S>();
  const Domain<S> d = profile.domain();
  QuadratureRule rule;
  rule.kind = Quadrature::GaussLegendre;
  rule.order = 40;
  rule.panels = 2;
  const S tol = S(1000) * epsilon<S>();
  for (const S& u0 : test_parameters(d)) {
    const S u1 = u0 + interval(d);
    const S truth = integrate<S>([&](const S& u) { return S(profile.jet(u, 1).d1.norm()); }, u0, u1, rule);
    using std::abs;
    BOOST_TEST(abs(profile.arc_length(u0, u1) - truth) <= tol * truth);
    BOOST_TEST(abs(profile.arc_length(u1, u0) + truth) <= tol * truth);  // signed
    if (profile.has_arc_length_primitive())
      BOOST_TEST(abs(profile.arc_length_primitive(u1) - profile.arc_length_primitive(u0) - truth) <= tol * curve_scale(profile));
  }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(closed_kinds_wrap, C, Cases) {
  using S = typename C::scalar;
  const auto profile = C::kind::template make<S>();
  const Domain<S> d = profile.domain();
  BOOST_TEST(d.closed == C::kind::closed);
  if (!d.closed) return;
  const S tol = S(64) * epsilon<S>();
  const S scale = curve_scale(profile);
  for (const S& u : test_parameters(d)) {
    for (int turns : {-1, 1, 2}) {
      const Jet<S> a = profile.jet(u, 2), b = profile.jet(u + S(turns) * d.period(), 2);
      BOOST_TEST((a.p - b.p).norm() <= tol * scale * S(4));
      BOOST_TEST((a.d1 - b.d1).norm() <= tol * S(4) * (a.d1.norm() + scale / d.period()) * S(16));
    }
  }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(invalid_construction_refused, C, Cases) {
  using S = typename C::scalar;
  C::kind::template refuse<S>();
}
