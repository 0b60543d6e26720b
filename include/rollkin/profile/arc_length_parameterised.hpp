// A piecewise profile (sampled spline or Bezier path) re-parameterised by its arc length s.
//
// With u the base profile's own parameter (chord length for a spline, segment parameter for a Bezier path)
// and s(u) = integral_{u_lo}^{u} |p'| du its arc length from the start (eq. 4), the wrapped profile is
//   x(s) = p(u(s)),   s in [0, L]   (L = total length; closed contours wrap with period L),
// a Length parameter. Then arc_length(s0, s1) = s1 - s0 exactly and param_at_arc_length(s0, ds) = s0 + ds:
// the rolling constraint D_i = D_{i-1} (eq. 3) becomes linear in the contact parameters.
//
// Derivatives by the chain rule. With sigma = |p'(u)| and, differentiating in u,
//   sigma'  = p'.p'' / sigma,
//   sigma'' = (p''.p'' + p'.p''') / sigma - (p'.p'')^2 / sigma^3,
// the derivatives of u(s) are (d/ds = (1/sigma) d/du):
//   u'   = 1 / sigma,
//   u''  = d/ds (1/sigma)            = -sigma' / sigma^2 * u'                      = -sigma' / sigma^3,
//   u''' = d/ds (-sigma' sigma^-3)  = (-sigma'' sigma^-3 + 3 sigma'^2 sigma^-4) u' = (3 sigma'^2 - sigma sigma'') / sigma^5,
// and those of x(s) = p(u(s)) (Faa di Bruno):
//   x'   = p' u',
//   x''  = p'' u'^2 + p' u'',
//   x''' = p''' u'^3 + 3 p'' u' u'' + p' u'''.
// So |x'| = 1, x'' = kappa * (left normal) and x''' = kappa_s * (left normal) - kappa^2 * t; the curvature
// is the base's at the same point. (u''' is checked against central differences of u(s) in
// tests/test_profile_arc_length.cpp.)
//
// u(s): a table of nodes u_k with their arc lengths s_k and speeds, built once: the base's knots, and for a
// Bezier path also 32 equal steps in u inside every segment (its quadrature over a whole segment needs many
// panels, over 1/32 of it one or a few). s_k accumulates the base's own piece quadrature, so s(u) agrees with
// base.arc_length(u_lo, u) to round-off. Then a binary search for the interval, a cubic Hermite guess from
// the end values (s_k, u_k) and end slopes du/ds = 1/sigma (O(h^4) accurate, so Newton needs one or two
// steps), and Newton on s_k + integral_{u_k}^{u} |p'| - s with derivative |p'(u)|, kept inside the
// interval's bracket by bisection. No mutable state: const use from several threads is race-free (the
// base spline's span hint is itself atomic).
//
// Continuity: the base's continuity in u (at a G1 joint of a Bezier path the tangent length jumps but the
// unit tangent does not, so the arc-length curve is in fact C1 there too; reported as the base reports it).
// At a stationary point of a Bezier path (p' = 0) u'(s) is infinite and the jet is not defined.
#pragma once

#include "rollkin/profile/bezier.hpp"
#include "rollkin/profile/jet.hpp"
#include "rollkin/profile/spline.hpp"

#include <algorithm>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace rollkin {

template <class S> class ArcLengthProfile {
 public:
  using Scalar = S;
  /// The closed set of profiles that can be re-parameterised (piecewise, with an arc-length table).
  using Base = std::variant<SampledProfile<S>, BezierPath<S>>;

  explicit ArcLengthProfile(SampledProfile<S> base) : base_(std::move(base)) { build_table(); }
  explicit ArcLengthProfile(BezierPath<S> base) : base_(std::move(base)) { build_table(); }

  Domain<S> domain() const { return Domain<S>{S(0), length(), base_domain().closed}; }
  ParamKind parameter_kind() const { return ParamKind::Length; }
  int continuity() const { return visit([](const auto& b) { return b.continuity(); }); }
  S length() const { return arc_.back(); }

  /// x(s) and its derivatives with respect to arc length up to `order`.
  Jet<S> jet(const S& s, int order) const {
    const S u = base_param(s);
    const Jet<S> j = visit([&](const auto& b) { return b.jet(u, order); });
    if (order < 1) return j;
    Jet<S> r;
    r.p = j.p;
    const S sigma2 = j.d1.squaredNorm();
    const S sigma = sqrt_of(sigma2);
    const S u1 = S(1) / sigma;
    r.d1 = j.d1 * u1;
    if (order >= 2) {
      const S pp = j.d1.dot(j.d2);
      const S sigma_u = pp / sigma;                     // sigma'
      const S u2 = -sigma_u / (sigma2 * sigma);         // u''
      r.d2 = j.d2 * (u1 * u1) + j.d1 * u2;
      if (order >= 3) {
        const S sigma_uu = (j.d2.squaredNorm() + j.d1.dot(j.d3)) / sigma - pp * pp / (sigma2 * sigma);  // sigma''
        const S u3 = (S(3) * sigma_u * sigma_u - sigma * sigma_uu) / (sigma2 * sigma2 * sigma);           // u'''
        r.d3 = j.d3 * (u1 * u1 * u1) + j.d2 * (S(3) * u1 * u2) + j.d1 * u3;
      }
    }
    return r;
  }

  S arc_length(const S& s0, const S& s1) const { return s1 - s0; }
  bool has_arc_length_primitive() const { return true; }
  S arc_length_primitive(const S& s) const { return s; }
  S param_at_arc_length(const S& s0, const S& ds) const { return s0 + ds; }

  /// The base profile's parameter u at arc length s from its start (closed: s wraps, u in [lo, hi)).
  S base_param(const S& s) const {
    const S w = domain().wrap(s);
    const std::size_t k = interval_at_length(w);
    return visit([&](const auto& b) { return solve_in_interval(b, k, w); });
  }
  /// Arc length from the start to the base parameter u (inverse of base_param; closed: u wraps).
  S arc_length_at(const S& u) const {
    const Domain<S> d = base_domain();
    const S w = d.wrap(u);
    return visit([&](const auto& b) {
      const std::size_t i = b.piece_of(w);
      const S t = (w - b.knot(i)) / (b.knot(i + 1) - b.knot(i)) * S(static_cast<int>(steps_));
      using std::floor;
      std::size_t j = t < S(0) ? 0 : static_cast<std::size_t>(to_double(floor(t)));
      const std::size_t k = i * steps_ + std::min(j, steps_ - 1);
      return arc_[k] + b.piece_length(i, node_[k], w);
    });
  }

  const Base& base() const { return base_; }
  /// The wrapped spline, or nullptr for a Bezier path.
  const SampledProfile<S>* sampled() const { return std::get_if<SampledProfile<S>>(&base_); }
  const BezierPath<S>* bezier() const { return std::get_if<BezierPath<S>>(&base_); }

  template <class T> ArcLengthProfile<T> cast() const {
    return visit([](const auto& b) { return ArcLengthProfile<T>(b.template cast<T>()); });
  }

 private:
  template <class F> decltype(auto) visit(F&& f) const { return std::visit(std::forward<F>(f), base_); }
  Domain<S> base_domain() const { return visit([](const auto& b) { return b.domain(); }); }
  static S sqrt_of(const S& x) {
    using std::sqrt;
    return sqrt(x);
  }

  void build_table() {
    visit([this](const auto& b) {
      using B = std::decay_t<decltype(b)>;
      steps_ = std::is_same_v<B, BezierPath<S>> ? 32 : 1;
      const std::size_t n = b.piece_count();
      node_.clear();
      arc_.assign(1, S(0));
      speed_start_.clear();
      speed_end_.clear();
      for (std::size_t i = 0; i < n; ++i) {
        const S a = b.knot(i), e = b.knot(i + 1);
        S u = a;
        for (std::size_t j = 0; j < steps_; ++j) {
          const S next = j + 1 == steps_ ? e : a + (e - a) * S(static_cast<int>(j + 1)) / S(static_cast<int>(steps_));
          node_.push_back(u);
          arc_.push_back(arc_.back() + b.piece_length(i, u, next));
          speed_start_.push_back(b.speed(i, u));
          speed_end_.push_back(b.speed(i, next));
          u = next;
        }
      }
      node_.push_back(b.knot(n));
    });
  }

  /// Interval k with s_k <= s < s_{k+1}; lengths outside [0, L] go to the end intervals.
  std::size_t interval_at_length(const S& s) const {
    const std::size_t n = arc_.size() - 1;
    const auto it = std::upper_bound(arc_.begin(), arc_.end(), s);
    const std::size_t k = it == arc_.begin() ? 0 : static_cast<std::size_t>(it - arc_.begin()) - 1;
    return std::min(k, n - 1);
  }

  /// Cubic Hermite guess of u on interval k from (s_k, a, 1/sigma_a) and (s_{k+1}, b, 1/sigma_b); linear where
  /// an end speed is zero (stationary point) or s lies outside the interval (extrapolated open ends).
  S guess(std::size_t k, const S& a, const S& b, const S& s) const {
    const S s0 = arc_[k], len = arc_[k + 1] - s0;
    const S t = (s - s0) / len;
    const S sa = speed_start_[k], sb = speed_end_[k];
    if (t < S(0)) return sa > S(0) ? a + (s - s0) / sa : a + (b - a) * t;
    if (t > S(1)) return sb > S(0) ? b + (s - arc_[k + 1]) / sb : a + (b - a) * t;
    if (!(sa > S(0)) || !(sb > S(0))) return a + (b - a) * t;
    const S t2 = t * t, t3 = t2 * t;
    const S h00 = S(2) * t3 - S(3) * t2 + S(1), h10 = t3 - S(2) * t2 + t, h01 = S(3) * t2 - S(2) * t3, h11 = t3 - t2;
    const S u = h00 * a + h10 * len / sa + h01 * b + h11 * len / sb;
    return std::clamp(u, a, b);
  }

  /// Solves s_k + integral_{u_k}^{u} |p'| = s for u by Newton from the Hermite guess, bisecting inside the
  /// interval's bracket whenever a step leaves it (open ends, s outside [0, L]: unbracketed Newton).
  template <class B> S solve_in_interval(const B& b, std::size_t k, const S& s) const {
    using std::abs;
    const std::size_t i = k / steps_;  // the base's piece
    const S a = node_[k], e = node_[k + 1];
    const S r = s - arc_[k];
    const bool bracketed = r >= S(0) && s <= arc_[k + 1];
    S lo = a, hi = e;
    S u = guess(k, a, e, s);
    const S tol = epsilon<S>() * S(8) * (abs(a) + abs(e) + (e - a));
    for (int it = 0; it < 100; ++it) {
      const S f = b.piece_length(i, a, u) - r;
      if (f < S(0)) lo = u; else hi = u;
      S next = u - f / b.speed(i, u);
      if (bracketed && !(next >= lo && next <= hi)) next = (lo + hi) / S(2);
      const S step = abs(next - u);
      u = next;
      if (step <= tol) break;
    }
    return u;
  }

  Base base_;
  std::size_t steps_ = 1;                   // table intervals per piece of the base
  std::vector<S> node_;                     // u_k: piece i, step j is node i * steps_ + j; last: the end knot
  std::vector<S> arc_;                      // s_k: arc length from the start to node k
  std::vector<S> speed_start_, speed_end_;  // |p'| at both ends of interval k (its piece's own formula)
};

}  // namespace rollkin
