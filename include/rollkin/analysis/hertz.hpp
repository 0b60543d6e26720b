// Hertz line contact of two long bodies of face width L pressed together by the normal force N
// (K. L. Johnson, Contact Mechanics, 1985, sections 4.2 and 5.6; docs/forces.md):
//   1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2,   1/R = kappa1 + kappa2 (the relative curvature, analysis/motion.hpp)
//   b  = sqrt(4 N R / (pi L E*))             half-width of the contact strip
//   p0 = 2 N / (pi b L) = sqrt(N E* / (pi L R))   largest contact pressure
// Below the surface on the line of symmetry, at depth z = zeta b (plane strain; McEwen's stresses):
//   sigma_z = -p0 / sqrt(1 + zeta^2),  sigma_x = -p0 ((1 + 2 zeta^2) / sqrt(1 + zeta^2) - 2 zeta),
//   sigma_y = nu (sigma_x + sigma_z)
// and the largest principal shear stress (max sigma - min sigma) / 2 peaks at 0.300 p0, zeta = 0.786 for
// nu = 0.3 (where sigma_y lies between the others; a smaller nu makes (sigma_y - sigma_z) / 2 the larger).
// A convex-concave pair (kappa2 < 0) is included; a flat face has kappa 0. Where kappa1 + kappa2 is not
// positive (parallel flats, osculating or interpenetrating contours) the relative radius is infinite or
// negative: there is no Hertz contact, and hertz_line says so instead of returning a number.
#pragma once

#include "rollkin/scalar.hpp"

#include <algorithm>
#include <cmath>

namespace rollkin {

/// The largest principal shear stress below a line contact per unit p0 (`ratio`) and its depth per unit b
/// (`depth`) in a body of Poisson's ratio nu.
template <class S> struct ShearPeak {
  S ratio, depth;
};

namespace detail {

/// (max - min) / 2 of the three principal stresses at depth zeta (per unit p0): the top of hertz.hpp.
template <class S> S principal_shear(const S& zeta, const S& nu) {
  using std::max;
  using std::min;
  using std::sqrt;
  const S root = sqrt(S(1) + zeta * zeta);
  const S sz = S(-1) / root;
  const S sx = -((S(1) + S(2) * zeta * zeta) / root - S(2) * zeta);
  const S sy = nu * (sx + sz);
  return (max(max(sx, sy), sz) - min(min(sx, sy), sz)) / S(2);
}

}  // namespace detail

/// The peak of detail::principal_shear over depth: golden-section search on zeta in [0, 3] (one peak there)
/// to a zeta tolerance of eps^(1/2), where the peak's value is exact to round-off.
template <class S> ShearPeak<S> subsurface_shear_peak(const S& nu) {
  using std::abs;
  using std::sqrt;
  const S golden = (sqrt(S(5)) - S(1)) / S(2);
  S lo(0), hi(3);
  S x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo);
  S f1 = detail::principal_shear(x1, nu), f2 = detail::principal_shear(x2, nu);
  while (hi - lo > tolerance_once<S, 1, 2>()) {
    if (f1 < f2) {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + golden * (hi - lo);
      f2 = detail::principal_shear(x2, nu);
    } else {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - golden * (hi - lo);
      f1 = detail::principal_shear(x1, nu);
    }
  }
  const S zeta = (lo + hi) / S(2);
  return {detail::principal_shear(zeta, nu), zeta};
}

/// The Hertz line contact's numbers (top of this file). `valid` false where the relative curvature is not
/// positive (no Hertz contact: the caller names the pair and the pose).
template <class S> struct HertzLine {
  bool valid = false;
  S pressure = S(0), half_width = S(0), max_shear = S(0), max_shear_depth = S(0);
};

/// The effective modulus E* of two bodies (moduli e1, e2, Poisson's ratios nu1, nu2).
template <class S> S effective_modulus(const S& e1, const S& nu1, const S& e2, const S& nu2) {
  return S(1) / ((S(1) - nu1 * nu1) / e1 + (S(1) - nu2 * nu2) / e2);
}

/// The contact of normal force `normal` over face width `width` with relative curvature `relative_curvature`
/// (1 / length) and effective modulus `modulus`; `peak` the larger of the two bodies' subsurface shear peaks.
/// A normal force that is not positive presses nothing: every number 0.
template <class S> HertzLine<S> hertz_line(const S& normal, const S& relative_curvature, const S& width, const S& modulus,
                                           const ShearPeak<S>& peak) {
  using std::sqrt;
  HertzLine<S> h;
  if (!(relative_curvature > S(0))) return h;
  h.valid = true;
  if (!(normal > S(0))) return h;
  const S radius = S(1) / relative_curvature;
  h.half_width = sqrt(S(4) * normal * radius / (pi<S>() * width * modulus));
  h.pressure = S(2) * normal / (pi<S>() * h.half_width * width);
  h.max_shear = peak.ratio * h.pressure;
  h.max_shear_depth = peak.depth * h.half_width;
  return h;
}

}  // namespace rollkin
