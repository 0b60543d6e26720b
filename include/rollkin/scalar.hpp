// Scalar-generic helpers. Everything numeric in rollkin is a template on the scalar type S so that the same
// code runs in double and in Boost.Multiprecision MPFR (see scalar_mpfr.hpp). Rules kept here:
//  - no double literals inside templates: write S(1) / S(6), never S(1./6.);
//  - no fixed epsilons: tolerances derive from std::numeric_limits<S>::epsilon();
//  - unqualified math calls after `using std::sin;` so that ADL finds the MPFR overloads.
#pragma once

#include <Eigen/Core>
#include <boost/math/constants/constants.hpp>

#include <cmath>
#include <limits>

namespace rollkin {

template <class S> using Vec2 = Eigen::Matrix<S, 2, 1>;
template <class S> using Vec3 = Eigen::Matrix<S, 3, 1>;

template <class S> inline S pi() { return boost::math::constants::pi<S>(); }
template <class S> inline S epsilon() { return std::numeric_limits<S>::epsilon(); }

/// Conversion between scalar types (double -> MPFR is exact; MPFR -> double rounds).
template <class T, class S> inline T scalar_cast(const S& x) { return static_cast<T>(x); }
template <class S> inline double to_double(const S& x) { return static_cast<double>(x); }

/// z-component of the planar cross product a x b.
template <class S> inline S cross2(const Vec2<S>& a, const Vec2<S>& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Left normal J a (rotation by +90 degrees).
template <class S> inline Vec2<S> perp(const Vec2<S>& a) { return Vec2<S>(-a.y(), a.x()); }

namespace detail {

/// sin and cos of r, |r| <= pi/4 (a little beyond is fine), by their Taylor series through r^17 and r^18;
/// the first terms left out, (pi/4)^19/19! and (pi/4)^20/20!, are below 1e-19.
inline void sin_cos_kernel(double r, double& s, double& c) {
  const double z = r * r;
  const double ps = -1.0 / 6 + z * (1.0 / 120 + z * (-1.0 / 5040 + z * (1.0 / 362880 + z * (-1.0 / 39916800 +
                    z * (1.0 / 6227020800 + z * (-1.0 / 1307674368000 + z * (1.0 / 355687428096000)))))));
  const double pc = 1.0 / 24 + z * (-1.0 / 720 + z * (1.0 / 40320 + z * (-1.0 / 3628800 + z * (1.0 / 479001600 +
                    z * (-1.0 / 87178291200 + z * (1.0 / 20922789888000 + z * (-1.0 / 6402373705728000)))))));
  s = r + r * z * ps;
  c = 1.0 - 0.5 * z + z * z * pc;
}

/// sin and cos of x for |x| <= 1e5 (false otherwise, and for NaN): x = k pi/2 + r with pi/2 split in three
/// parts (Cody and Waite; the first two have 33 significant bits, so k times them is exact for |k| < 2^20),
/// then the kernel and the quadrant k mod 4. k is x 2/pi rounded to nearest by adding and removing 1.5 2^52.
inline bool sin_cos_reduced(double x, double& s, double& c) {
  if (!(std::abs(x) <= 1e5)) return false;
  constexpr double kRound = 0x1.8p52;
  const double k = (x * 0x1.45f306dc9c883p-1 + kRound) - kRound;  // 2/pi
  const double r = ((x - k * 0x1.921fb544p+0) - k * 0x1.0b4611a6p-34) - k * 0x1.3198a2e037073p-69;
  double sr, cr;
  sin_cos_kernel(r, sr, cr);
  switch (static_cast<long>(k) & 3) {
    case 0: s = sr, c = cr; break;
    case 1: s = cr, c = -sr; break;
    case 2: s = -sr, c = -cr; break;
    default: s = -cr, c = sr; break;
  }
  return true;
}

}  // namespace detail

/// s = sin x, c = cos x. In double, angles up to 1e5 rad take an inline reduction and series (within 2 eps
/// absolute of MPFR's sin and cos, tests/test_scalar_mpfr.cpp) at about a third of the cost of the libm
/// call; other scalar types call their own sin and cos.
template <class S> inline void sin_cos(const S& x, S& s, S& c) {
  using std::cos;
  using std::sin;
  s = sin(x);
  c = cos(x);
}
inline void sin_cos(const double& x, double& s, double& c) {
  if (!detail::sin_cos_reduced(x, s, c)) {
    s = std::sin(x);
    c = std::cos(x);
  }
}

/// Degrees to radians and back.
template <class S> inline S deg_to_rad(const S& deg) { return deg * pi<S>() / S(180); }
template <class S> inline S rad_to_deg(const S& rad) { return rad * S(180) / pi<S>(); }

/// Wraps an angle to (-pi, pi].
template <class S> inline S wrap_angle(const S& a) {
  using std::atan2;
  using std::cos;
  using std::sin;
  return atan2(sin(a), cos(a));
}

/// A tolerance that scales with the working precision: eps^power (power 1/2 for "half the digits").
template <class S> inline S tolerance(const S& power) {
  using std::pow;
  return pow(epsilon<S>(), power);
}

/// eps^(num/den), computed once per scalar type and power: for a tolerance used per pose, where a pow per
/// call costs as much as the work it bounds.
template <class S, int num, int den> const S& tolerance_once() {
  static const S t = tolerance<S>(S(num) / S(den));
  return t;
}

}  // namespace rollkin
