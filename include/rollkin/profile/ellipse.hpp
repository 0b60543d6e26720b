// Ellipse p(t) = (A cos t, B sin t) about the contour frame's origin (t the eccentric anomaly),
// counter-clockwise with the material inside. Its foci lie at (+-c, 0), c = sqrt(A^2 - B^2) when A >= B.
// Arc length through the incomplete elliptic integral of the second kind E(phi, k) (Boost.Math, any S):
//   A >= B: |p'| = A sqrt(1 - e^2 cos^2 t), s(t) = A [E(t - pi/2, e) + E(pi/2, e)],  e^2 = 1 - B^2/A^2
//   A <  B: |p'| = B sqrt(1 - e^2 sin^2 t), s(t) = B E(t, e),                        e^2 = 1 - A^2/B^2
#pragma once

#include "rollkin/profile/arc_length.hpp"

#include <boost/math/special_functions/ellint_2.hpp>

#include <stdexcept>

namespace rollkin {

template <class S> class Ellipse {
 public:
  using Scalar = S;
  Ellipse(const S& semi_x, const S& semi_y, ArcLengthMethod method = {})
      : a_(semi_x), b_(semi_y), domain_{S(0), S(2) * pi<S>(), true}, method_(method) {
    require_positive(semi_x, "ellipse", "the semi-axis A");
    require_positive(semi_y, "ellipse", "the semi-axis B");
    // The constants of s(t), computed once: the larger semi-axis, e, and for A >= B the shift and E(pi/2, e).
    using std::sqrt;
    const bool wide = a_ >= b_;
    major_ = wide ? a_ : b_;
    const S ratio = (wide ? b_ : a_) / major_;
    e_ = sqrt(S(1) - ratio * ratio);
    shift_ = wide ? S(pi<S>() / S(2)) : S(0);
    complete_ = wide ? S(boost::math::ellint_2(e_, shift_)) : S(0);
  }

  const S& semi_x() const { return a_; }
  const S& semi_y() const { return b_; }
  Domain<S> domain() const { return domain_; }
  ParamKind parameter_kind() const { return ParamKind::Angle; }
  int continuity() const { return 3; }
  Jet<S> jet(const S& t, int order) const {
    S c, s;
    sin_cos(t, s, c);
    Jet<S> j;
    j.p = Vec2<S>(a_ * c, b_ * s);
    j.d1 = Vec2<S>(-a_ * s, b_ * c);
    if (order >= 2) j.d2 = Vec2<S>(-a_ * c, -b_ * s);
    if (order >= 3) j.d3 = Vec2<S>(a_ * s, -b_ * c);
    return j;
  }
  bool has_arc_length_primitive() const { return method_.closed_form; }
  /// s(t) = A [E(t - pi/2, e) + E(pi/2, e)] or B E(t, e) (see the top of this file).
  S arc_length_primitive(const S& t) const { return major_ * (boost::math::ellint_2(e_, S(t - shift_)) + complete_); }
  S arc_length(const S& t0, const S& t1) const {
    if (method_.closed_form) return arc_length_primitive(t1) - arc_length_primitive(t0);
    return arc_length_by_quadrature(*this, t0, t1, method_.rule);
  }
  S param_at_arc_length(const S& t0, const S& ds) const { return param_at_arc_length_newton(*this, t0, ds); }

  template <class T> Ellipse<T> cast() const { return Ellipse<T>(scalar_cast<T>(a_), scalar_cast<T>(b_), method_); }

 private:
  S a_, b_;
  S major_, e_, shift_, complete_;  // s(t) = major (E(t - shift, e) + complete)
  Domain<S> domain_;
  ArcLengthMethod method_;
};

}  // namespace rollkin
