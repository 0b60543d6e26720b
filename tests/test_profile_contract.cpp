// The contract every profile kind keeps (include/rollkin/profile/jet.hpp, "profile concept"), checked by
// one typed test body over every (kind, scalar) pair, in double and in MPFR at 50 digits:
//  - the parameter range: lo < hi, the jet finite inside and at the ends;
//  - the jet against central finite differences of itself: p' from p, p'' from p', and the curvature
//    (p' x p'')/|p'|^3 from second differences of p alone; steps and tolerances follow the scalar's epsilon
//    (first differences: h = eps^(1/3) L, error ~ eps^(2/3); second: h = eps^(1/4) L, error ~ eps^(1/2));
//  - arc length against an independent Gauss-Legendre quadrature of |p'(u)| (profile/quadrature.hpp);
//  - closed kinds wrap (jet(u + period) = jet(u)); open kinds do not claim to;
//  - invalid construction throws std::invalid_argument;
//  - as a Contour (either direction, placed), an open kind goes on along its tangent line beyond its ends
//    (profile/profile.hpp): jet, arc length and its inverse there against the closed form of that line,
//    also a million lengths out (bounded work), and unchanged on the domain; a closed kind is not extended:
//    its arc lengths over whole turns, also from a fixed origin, are whole lengths of the contour (kinds with
//    an arc-length primitive: closed form or table).
// Test points and arc-length intervals lie inside one piece of every piecewise kind used here (pieces of
// equal parameter length 1/8, 1/4, 1/2 of the domain), where the curve is analytic.
//
// A new kind joins by one factory struct and one entry in Kinds (profile_kinds.hpp).
#define BOOST_TEST_MODULE profile_contract
#include <boost/mp11/algorithm.hpp>
#include <boost/test/unit_test.hpp>

#include "profile_kinds.hpp"
#include "rollkin/scalar_mpfr.hpp"

#include <tuple>
#include <vector>

using namespace rollkin;
using namespace rollkin::testing;
using M = mpfr_scalar<50>;
using Scalars = std::tuple<double, M>;

namespace {

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

BOOST_AUTO_TEST_CASE_TEMPLATE(open_contours_continue_along_their_tangent_beyond_their_ends, C, Cases) {
  using S = typename C::scalar;
  using std::abs;
  const auto profile = C::kind::template make<S>();
  const S scale = curve_scale(profile);
  const SE2<S> placement(S(1) / S(3), Vec2<S>(S(2), S(-1)));
  for (const bool reversed : {false, true}) {
    const Contour<S> c("k", 0, ProfileShape<S>(profile), placement, reversed);
    const Domain<S> d = c.domain();
    const S mid = (d.lo + d.hi) / S(2);
    // On the domain the contour is the placed profile (its own direction or reversed).
    const S inside = d.lo + d.period() / S(3);
    const Jet<S> pj = profile.jet(reversed ? S(-inside) : inside, 1);
    BOOST_TEST((c.jet(inside, 1).p - placement.act(pj.p)).norm() <= S(16) * epsilon<S>() * scale);
    if (d.closed) {  // no extension: whole turns wrap, from a fixed origin too (a rolling pair's, eq. 4)
      using std::abs;
      if (!profile.has_arc_length_primitive()) continue;  // lengths by quadrature: approximate over turns
      const S turn = c.arc_length(d.lo, d.lo + d.period() / S(2)) + c.arc_length(d.lo + d.period() / S(2), d.hi);
      const ArcOrigin<S> origin = c.arc_origin(inside);
      for (int turns : {-2, 1, 3}) {
        const S u = inside + S(turns) * d.period();
        BOOST_TEST(abs(c.arc_length(inside, u) - S(turns) * turn) <= S(1000) * epsilon<S>() * abs(S(turns) * turn));
        BOOST_TEST(abs(c.arc_length_from(origin, u) - S(turns) * turn) <= S(1000) * epsilon<S>() * abs(S(turns) * turn));
        BOOST_TEST((c.jet(u, 1).p - c.jet(inside, 1).p).norm() <= S(64) * epsilon<S>() * scale * S(std::abs(turns) + 1));
      }
      continue;
    }
    const S tol = S(1000) * epsilon<S>();
    for (const bool at_hi : {true, false}) {
      const S end = at_hi ? d.hi : d.lo, out = at_hi ? S(1) : S(-1);
      const Jet<S> e = c.jet(end, 1);
      const S speed = e.d1.norm();
      for (const S& beyond : {d.period() / S(1000), d.period(), S(1000000) * d.period()}) {
        const S u = end + out * beyond;
        const Jet<S> j = c.jet(u, 3);
        const Vec2<S> line = e.p + (u - end) * e.d1;  // the tangent line at the end
        BOOST_TEST((j.p - line).norm() <= tol * (scale + line.norm()));
        BOOST_TEST((j.d1 - e.d1).norm() <= tol * speed);
        BOOST_TEST(j.d2.norm() == S(0));
        BOOST_TEST(j.d3.norm() == S(0));
        const S along = c.arc_length(end, u), total = c.arc_length(mid, u);
        BOOST_TEST(abs(along - (u - end) * speed) <= tol * abs(along));
        BOOST_TEST(abs(total - (c.arc_length(mid, end) + along)) <= tol * abs(total));
        BOOST_TEST(abs(c.arc_length(u, mid) + total) <= tol * abs(total));  // signed
        BOOST_TEST(abs(c.param_at_arc_length(mid, total) - u) <= tol * (abs(u) + d.period()));
        BOOST_TEST(d.contains(u) == false);
      }
      BOOST_TEST(d.contains(end));
    }
    const S nan = std::numeric_limits<S>::quiet_NaN();
    BOOST_TEST(d.contains(nan) == false);
  }
}
