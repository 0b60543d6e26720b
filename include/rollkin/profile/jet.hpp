// The profile concept and the differential geometry every contour shares.
//
// A *profile* is a planar parametric curve p(u) in its own contour frame, traversed with the link's
// material on its LEFT (outward normal on the right, docs/method.md section 3). Every profile type (analytic,
// sampled spline, Bezier path) is a class template on the scalar S with these members:
//
//   using Scalar = S;
//   Domain<S> domain() const;                  // parameter interval; closed contours wrap
//   ParamKind parameter_kind() const;          // Angle (degrees in files), Length (scene units), Unitless
//   int continuity() const;                    // k of C^k in u (analytic curves: 3, i.e. "C3 or better")
//   Jet<S> jet(const S& u, int order) const;   // p and its derivatives d^k p / du^k for k <= order <= 3
//   S arc_length(const S& u0, const S& u1) const;        // signed arc length from u0 to u1 (eq. 4)
//   S param_at_arc_length(const S& u0, const S& ds) const; // inverse: u with arc_length(u0, u) = ds
//   bool has_arc_length_primitive() const;     // whether s(u) below is available (closed form or table)
//   S arc_length_primitive(const S& u) const;  // s(u), arc_length(u0, u1) = s(u1) - s(u0)
//   template <class T> Type<T> cast() const;   // same profile in another scalar type
//
// The contact pair (pair/pair.hpp) needs only the jet and the arc length; everything else below is
// derived from the jet here, once, so all profile types agree on signs and formulas.
#pragma once

#include "rollkin/scalar.hpp"

#include <stdexcept>
#include <string>

namespace rollkin {

/// How a contact parameter is reported: angles in degrees, lengths in scene units, a Bezier path's
/// segment parameter as a plain number.
enum class ParamKind { Angle, Length, Unitless };

inline const char* to_string(ParamKind k) {
  return k == ParamKind::Angle ? "angle" : (k == ParamKind::Length ? "length" : "unitless");
}

template <class S> struct Domain {
  S lo, hi;
  bool closed = false;  // closed: u is periodic with period hi - lo

  S period() const { return hi - lo; }
  /// Whether a contact at u lies on the drawn contour: any u of a closed contour; on an open one
  /// lo <= u <= hi up to round-off of the range (16 eps of its largest magnitude), so that a contact assembled
  /// at an end is on it. A NaN is on no open contour. The one rule for assembly and sweeps
  /// (solve/contact_limits.hpp).
  bool contains(const S& u) const {
    using std::abs;
    using std::max;
    if (closed) return true;
    const S slack = S(16) * epsilon<S>() * max(max(abs(lo), abs(hi)), S(hi - lo));
    return u >= lo - slack && u <= hi + slack;
  }
  /// Maps u into [lo, hi) for closed contours; identity for open ones.
  S wrap(const S& u) const {
    if (!closed) return u;
    using std::floor;
    return u - period() * floor((u - lo) / period());
  }
  /// Parameter of sample i of n equally spaced in u: an open domain includes both ends, a closed one covers
  /// one period without repeating its first point.
  S sample(int i, int n) const { return lo + (hi - lo) * S(i) / S(closed ? n : n - 1); }
  /// Number of whole periods between lo and u (closed contours): u = wrap(u) + turns(u) * period().
  S turns(const S& u) const {
    using std::floor;
    return closed ? floor((u - lo) / period()) : S(0);
  }
  template <class T> Domain<T> cast() const { return {scalar_cast<T>(lo), scalar_cast<T>(hi), closed}; }
};

/// Throws std::invalid_argument("<what>: ...") unless lo < hi, both finite (a profile's parameter range).
template <class S> void require_parameter_range(const S& lo, const S& hi, const char* what) {
  using std::isfinite;
  if (!isfinite(lo) || !isfinite(hi) || !(lo < hi))
    throw std::invalid_argument(std::string(what) + ": the parameter range must be finite with lo < hi");
}

/// Throws std::invalid_argument("<what>: ...") unless x is finite and > 0 (a radius, a semi-axis).
template <class S> void require_positive(const S& x, const char* what, const char* name) {
  using std::isfinite;
  if (!isfinite(x) || !(x > S(0))) throw std::invalid_argument(std::string(what) + ": " + name + " must be finite and > 0");
}

/// p(u) and its first three derivatives with respect to the parameter u.
template <class S> struct Jet {
  Vec2<S> p, d1, d2, d3;
  Jet() : p(Vec2<S>::Zero()), d1(Vec2<S>::Zero()), d2(Vec2<S>::Zero()), d3(Vec2<S>::Zero()) {}
};

/// Differential geometry at one point of a contour, derived from its jet. With sigma = |p'|:
///   tangent t = p'/sigma, outward normal n = -J t (right of t), signed curvature
///   kappa = (p' x p'')/sigma^3 (positive where the material side is convex),
/// and the body twist of the contact frame along u, eta = (sigma, 0, kappa*sigma) (docs/method.md section 2).
template <class S> struct ContourPoint {
  Vec2<S> p, tangent;
  S speed;          // sigma = ds/du
  S turn_rate;      // kappa * sigma = d(tangent angle)/du
  S speed_rate;     // d sigma / du                      (order >= 2)
  S turn_accel;     // d (kappa sigma) / du               (order >= 3)

  S curvature() const { return turn_rate / speed; }
  Vec2<S> outward_normal() const { return Vec2<S>(tangent.y(), -tangent.x()); }
};

/// order 1: point and tangent; order 2: adds curvature and speed_rate; order 3: adds turn_accel.
template <class S> ContourPoint<S> contour_point(const Jet<S>& j, int order) {
  using std::sqrt;
  ContourPoint<S> c;
  c.p = j.p;
  const S sigma2 = j.d1.squaredNorm();
  c.speed = sqrt(sigma2);
  const S per_speed = S(1) / c.speed;  // one division, then products (divisions were most of this function)
  c.tangent = j.d1 * per_speed;
  c.turn_rate = S(0);
  c.speed_rate = S(0);
  c.turn_accel = S(0);
  if (order >= 2) {
    const S k = cross2(j.d1, j.d2);
    c.turn_rate = k * per_speed * per_speed;      // (p' x p'') / sigma^2
    c.speed_rate = j.d1.dot(j.d2) * per_speed;    // (p' . p'') / sigma
    if (order >= 3) {
      // d/du [(p' x p'') / sigma^2] = (p' x p''') / sigma^2 - 2 (p' x p'')(p' . p'') / sigma^4
      c.turn_accel = cross2(j.d1, j.d3) / sigma2 - S(2) * k * j.d1.dot(j.d2) / (sigma2 * sigma2);
    }
  }
  return c;
}

}  // namespace rollkin
