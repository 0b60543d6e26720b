// Planar rigid transforms: the 3x3 homogeneous matrices of the Sheth-Uicker method, stored as a rotation
// (cos, sin) and a translation. Twists are 3-vectors (vx, vy, omega); the hat map is
//     xi^ = [ omega*J  v ; 0 0 ],  J = [0 -1; 1 0].
// Derivatives of pair matrices are returned as *spatial* twists lambda = (dP/dq) P^-1, expressed in the
// frame on the left of P, so that a loop product's derivative is a sum of adjoint-mapped twists.
#pragma once

#include "rollkin/scalar.hpp"

#include <type_traits>

namespace rollkin {

template <class S> using Twist = Vec3<S>;

template <class S> class SE2 {
 public:
  SE2() : c_(1), s_(0), t_(S(0), S(0)) {}
  SE2(const S& angle, const Vec2<S>& t) : t_(t) { sin_cos(angle, s_, c_); }
  /// From a unit direction (c, s) of the x-axis and the origin t.
  static SE2 from_axis(const S& c, const S& s, const Vec2<S>& t) {
    SE2 g;
    g.c_ = c;
    g.s_ = s;
    g.t_ = t;
    return g;
  }
  static SE2 rotation(const S& angle) { return SE2(angle, Vec2<S>(S(0), S(0))); }
  static SE2 translation(const Vec2<S>& t) { return from_axis(S(1), S(0), t); }

  /// Exactly the identity (Mechanism::finalize() flags such joint frames; evaluation skips composing them).
  bool is_identity() const { return c_ == S(1) && s_ == S(0) && t_.x() == S(0) && t_.y() == S(0); }

  const S& cos_angle() const { return c_; }
  const S& sin_angle() const { return s_; }
  const Vec2<S>& translation() const { return t_; }
  S angle() const {
    using std::abs;
    using std::atan2;
    if constexpr (std::is_same_v<S, double>) {
      // Near the identity, where every closed loop is evaluated: atan(t), t = s/c, by its series
      // t - t^3/3 + t^5/5 - t^7/7, whose truncation t^9/9 is below eps/9 relative for |t| <= eps^(1/8) = 0.011;
      // several times cheaper than the libm call.
      if (c_ > 0 && abs(s_) <= 0.011 * c_) {
        const double t = s_ / c_, t2 = t * t;
        return t * (1 + t2 * (-1.0 / 3 + t2 * (1.0 / 5 - t2 / 7)));
      }
    }
    return atan2(s_, c_);
  }

  // Products and actions are written coordinate by coordinate: as a sum of 2-vectors (rotate(p) + t), GCC
  // packs the rotated coordinates through memory and the packed load stalls on them (store forwarding),
  // which cost about a third of a loop product.
  SE2 operator*(const SE2& b) const { return from_axis(c_ * b.c_ - s_ * b.s_, s_ * b.c_ + c_ * b.s_, act(b.t_)); }
  SE2 inverse() const {
    const Vec2<S> ti(-(c_ * t_.x() + s_ * t_.y()), s_ * t_.x() - c_ * t_.y());
    return from_axis(c_, -s_, ti);
  }
  Vec2<S> rotate(const Vec2<S>& v) const { return Vec2<S>(c_ * v.x() - s_ * v.y(), s_ * v.x() + c_ * v.y()); }
  Vec2<S> act(const Vec2<S>& p) const {
    return Vec2<S>(c_ * p.x() - s_ * p.y() + t_.x(), s_ * p.x() + c_ * p.y() + t_.y());
  }

  /// Ad_g xi = (R v - omega J t, omega): the twist xi seen from the frame g is expressed in.
  Twist<S> adjoint(const Twist<S>& xi) const {
    const Vec2<S> v = rotate(Vec2<S>(xi.x(), xi.y()));
    return Twist<S>(v.x() + xi.z() * t_.y(), v.y() - xi.z() * t_.x(), xi.z());
  }

  Eigen::Matrix<S, 3, 3> matrix() const {
    Eigen::Matrix<S, 3, 3> m;
    m << c_, -s_, t_.x(), s_, c_, t_.y(), S(0), S(0), S(1);
    return m;
  }

  template <class T> SE2<T> cast() const {
    return SE2<T>::from_axis(scalar_cast<T>(c_), scalar_cast<T>(s_), t_.template cast<T>());
  }

 private:
  S c_, s_;
  Vec2<S> t_;
};

/// Lie bracket ad_a b = [a^, b^] = (omega_a J v_b - omega_b J v_a, 0).
template <class S> Twist<S> lie_bracket(const Twist<S>& a, const Twist<S>& b) {
  return Twist<S>(-a.z() * b.y() + b.z() * a.y(), a.z() * b.x() - b.z() * a.x(), S(0));
}

/// Rate of the residual (x, y, angle) of a transform T = [R, p] moving with spatial twist V:
/// Tdot = V^ T gives pdot = v + omega J p, angledot = omega.
template <class S> Vec3<S> residual_rate(const SE2<S>& T, const Twist<S>& V) {
  const Vec2<S>& p = T.translation();
  return Vec3<S>(V.x() - V.z() * p.y(), V.y() + V.z() * p.x(), V.z());
}

}  // namespace rollkin
