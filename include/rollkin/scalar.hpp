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
template <class S> inline S deg_to_rad(const S& deg) { return deg * pi<S>() / S(180); }
template <class S> inline S rad_to_deg(const S& rad) { return rad * S(180) / pi<S>(); }

/// Conversion between scalar types (double -> MPFR is exact; MPFR -> double rounds).
template <class T, class S> inline T scalar_cast(const S& x) { return static_cast<T>(x); }
template <class S> inline double to_double(const S& x) { return static_cast<double>(x); }

/// z-component of the planar cross product a x b.
template <class S> inline S cross2(const Vec2<S>& a, const Vec2<S>& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Left normal J a (rotation by +90 degrees).
template <class S> inline Vec2<S> perp(const Vec2<S>& a) { return Vec2<S>(-a.y(), a.x()); }

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

}  // namespace rollkin
