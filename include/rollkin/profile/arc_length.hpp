// Arc length (eq. 4) shared by all profile types: quadrature of the speed |p'(u)| and the inverse
// u(s) by safeguarded Newton (s(u) is strictly increasing because profiles are regular, |p'| > 0).
#pragma once

#include "rollkin/profile/jet.hpp"
#include "rollkin/profile/quadrature.hpp"

namespace rollkin {

/// How an analytic profile evaluates s(u): its closed form, or a quadrature rule (for comparison).
struct ArcLengthMethod {
  bool closed_form = true;
  QuadratureRule rule;
};

template <class Profile, class S> S arc_length_by_quadrature(const Profile& c, const S& u0, const S& u1,
                                                            const QuadratureRule& rule) {
  return integrate<S>([&](const S& u) { return c.jet(u, 1).d1.norm(); }, u0, u1, rule);
}

/// Solves arc_length(u0, u) = ds for u by Newton's method on s(u) - ds with derivative |p'(u)|, kept inside
/// a bracket that is widened geometrically from u0 and bisected whenever a Newton step leaves it.
template <class Profile, class S> S param_at_arc_length_newton(const Profile& c, const S& u0, const S& ds) {
  using std::abs;
  if (ds == S(0)) return u0;
  const S sign = ds > S(0) ? S(1) : S(-1);
  // Bracket [lo, hi] (in the direction of ds) with s(lo) - ds <= 0 <= s(hi) - ds in that direction.
  S lo = u0;
  S step = abs(ds) / c.jet(u0, 1).d1.norm();
  S hi = u0 + sign * step;
  for (int k = 0; k < 200 && sign * (c.arc_length(u0, hi) - ds) < S(0); ++k) {
    lo = hi;
    step *= S(2);
    hi = u0 + sign * step;
  }
  S u = (lo + hi) / S(2);
  const S tol = epsilon<S>() * S(8);
  for (int it = 0; it < 200; ++it) {
    const S f = c.arc_length(u0, u) - ds;
    if (sign * f > S(0)) hi = u; else lo = u;
    S next = u - f / c.jet(u, 1).d1.norm();
    const bool inside = sign > S(0) ? (next > lo && next < hi) : (next < lo && next > hi);
    if (!inside) next = (lo + hi) / S(2);
    if (abs(next - u) <= tol * (S(1) + abs(u))) return next;
    u = next;
  }
  return u;
}

}  // namespace rollkin
