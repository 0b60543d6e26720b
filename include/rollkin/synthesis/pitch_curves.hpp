// Synthesis of a non-circular gear pair from its transmission function (docs/method.md section 5).
//
// Given phi2 = f(phi1), f monotone increasing (f' > 0), and the centre distance E, the pitch curves roll on
// each other without slip while their contact point stays on the line of centres, at distances
//   r1 = E f'/(1 + f')   from pivot 1,       r2 = E/(1 + f')   from pivot 2,      r1 + r2 = E,
// (equal contact speeds r1 dphi1 = r2 dphi2). The gears are closed when f(phi1 + 2 pi) = f(phi1) + 2 pi.
//
// Frames and signs. Gear 1 turns by +phi1 about pivot 1 at the origin; gear 2 by -f(phi1) (the other way)
// about pivot 2 at (E, 0). The contact point is C = (r1, 0) in the world. In the body frames (each gear's
// pivot at its origin, body x-axis along the world x-axis at phi1 = 0):
//   gear 1:  Rot(-phi1) C           = r1 (cos(-phi1), sin(-phi1)),        body polar angle  -phi1
//   gear 2:  Rot(f(phi1)) (C - P2)  = r2 (cos(pi + f), sin(pi + f)),      body polar angle  pi + f(phi1)
// so as gear 1 turns forward its contact point runs clockwise round gear 1 and counter-clockwise round
// gear 2. Both pitch curves are returned counter-clockwise (material inside, rollkin's convention), sampled
// at equal body polar angles start + 2 pi j / n: gear 1 at phi1 = -(body angle), gear 2 at
// phi1 = f^-1(body angle - pi) (safeguarded Newton on the monotone f).
//
// In the analysis (two revolutes at distance E and a rolling pair of the two curves) the revolute angle of
// gear 2 is then -f(phi1), and at phi1 = 0 the contact is gear 1's body point at polar angle 0 and gear 2's
// at polar angle pi.
#pragma once

#include "rollkin/scalar.hpp"

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rollkin {

/// phi2 = f(phi1) with its derivative; f' > 0 everywhere.
template <class S> struct TransmissionFunction {
  std::function<S(const S&)> f, df;

  /// f(p) = p + k sin p, |k| < 1: closed gears, f' = 1 + k cos p in [1 - |k|, 1 + |k|].
  static TransmissionFunction sinusoidal(const S& k) {
    using std::abs;
    if (!(abs(k) < S(1))) throw std::invalid_argument("sinusoidal transmission: need |k| < 1 for f' > 0");
    return {[k](const S& p) {
              using std::sin;
              return S(p + k * sin(p));
            },
            [k](const S& p) {
              using std::cos;
              return S(S(1) + k * cos(p));
            }};
  }

  /// phi1 with f(phi1) = y: Newton from y (bracketed by bisection when a step leaves the bracket).
  /// Needs f(p) - p bounded by |bound| (closed gears: f(p) - p is 2 pi-periodic, hence bounded).
  S inverse(const S& y, const S& bound) const {
    using std::abs;
    S lo = y - abs(bound) - S(1), hi = y + abs(bound) + S(1);
    S p = y;
    for (int it = 0; it < 200; ++it) {
      const S r = f(p) - y;
      if (r < S(0)) lo = p; else hi = p;
      S next = p - r / df(p);
      if (!(next > lo && next < hi)) next = (lo + hi) / S(2);
      const S step = abs(next - p);
      p = next;
      if (step <= epsilon<S>() * S(4) * (S(1) + abs(p))) break;
    }
    return p;
  }
};

/// Pitch radii at input angle phi1 (docs/method.md section 5).
template <class S> struct PitchRadii {
  S r1, r2;
};
template <class S> PitchRadii<S> pitch_radii(const TransmissionFunction<S>& t, const S& E, const S& phi1) {
  const S d = t.df(phi1);
  if (!(d > S(0))) throw std::invalid_argument("gear synthesis: f' must be positive (monotone transmission)");
  return {E * d / (S(1) + d), E / (S(1) + d)};
}

/// Body polar angles of the contact point at input phi1 (see the header comment).
template <class S> S gear1_body_angle(const S& phi1) { return -phi1; }
template <class S> S gear2_body_angle(const TransmissionFunction<S>& t, const S& phi1) { return pi<S>() + t.f(phi1); }

template <class S> struct GearPair {
  S centre_distance;
  std::vector<Vec2<S>> gear1, gear2;  // pitch curves in the body frames, counter-clockwise, not repeating
                                      // the first point; sample j at body polar angle 2 pi j / n
};

/// Closed non-circular gear pair: n1 samples of gear 1's pitch curve and n2 of gear 2's. Throws
/// std::invalid_argument if f is not closed (f(p + 2 pi) != f(p) + 2 pi at the sample angles, to sqrt(eps))
/// or not monotone. `bound` bounds |f(p) - p| (for the inverse; 2 pi is always safe for closed f).
template <class S> GearPair<S> synthesise_gear_pair(const TransmissionFunction<S>& t, const S& E, std::size_t n1,
                                                    std::size_t n2, const S& bound = S(2) * pi<S>()) {
  using std::abs;
  using std::cos;
  using std::sin;
  if (!(E > S(0))) throw std::invalid_argument("gear synthesis: centre distance must be positive");
  if (n1 < 3 || n2 < 3) throw std::invalid_argument("gear synthesis: at least 3 samples per gear");
  const S two_pi = S(2) * pi<S>();
  GearPair<S> g;
  g.centre_distance = E;
  for (std::size_t j = 0; j < n1; ++j) {
    const S theta = two_pi * S(static_cast<long>(j)) / S(static_cast<long>(n1));
    const S phi1 = -theta;  // gear1_body_angle(phi1) == theta
    const S closure = t.f(phi1 + two_pi) - t.f(phi1) - two_pi;
    if (abs(closure) > tolerance<S>(S(1) / S(2)) * (S(1) + abs(t.f(phi1))))
      throw std::invalid_argument("gear synthesis: f(p + 2 pi) != f(p) + 2 pi, the gears would not close");
    const S r1 = pitch_radii(t, E, phi1).r1;
    g.gear1.emplace_back(r1 * cos(theta), r1 * sin(theta));
  }
  for (std::size_t j = 0; j < n2; ++j) {
    const S psi = two_pi * S(static_cast<long>(j)) / S(static_cast<long>(n2));
    const S phi1 = t.inverse(psi - pi<S>(), bound);  // gear2_body_angle(phi1) == psi
    const S r2 = pitch_radii(t, E, phi1).r2;
    g.gear2.emplace_back(r2 * cos(psi), r2 * sin(psi));
  }
  return g;
}

}  // namespace rollkin
