// Parabola y = a x^2 in its contour frame, parameter u = x, traversed with x increasing: the material is
// on the left, i.e. the region y > a x^2 (for a > 0 the inside of the cup, a convex region).
// Closed forms (docs/method.md section 5): s(x) = x/2 sqrt(1 + 4a^2x^2) + asinh(2ax)/(4a),
// tangent angle atan(2ax), curvature 2a/(1 + 4a^2x^2)^(3/2).
#pragma once

#include "rollkin/profile/arc_length.hpp"

#include <stdexcept>

namespace rollkin {

template <class S> class Parabola {
 public:
  using Scalar = S;
  Parabola(const S& a, const S& lo, const S& hi, ArcLengthMethod method = {})
      : a_(a), domain_{lo, hi, false}, method_(method) {
    using std::isfinite;
    if (a == S(0)) throw std::invalid_argument("parabola: a must be non-zero (use a line)");
    if (!isfinite(a)) throw std::invalid_argument("parabola: a must be finite");
    require_parameter_range(lo, hi, "parabola");
  }

  const S& a() const { return a_; }
  Domain<S> domain() const { return domain_; }
  ParamKind parameter_kind() const { return ParamKind::Length; }
  int continuity() const { return 3; }
  Jet<S> jet(const S& x, int /*order*/) const {
    Jet<S> j;
    j.p = Vec2<S>(x, a_ * x * x);
    j.d1 = Vec2<S>(S(1), S(2) * a_ * x);
    j.d2 = Vec2<S>(S(0), S(2) * a_);
    return j;
  }
  /// Closed-form primitive of sqrt(1 + (2 a x)^2) (eq. 4 for f = a x^2).
  S arc_length_primitive(const S& x) const {
    using std::asinh;
    using std::sqrt;
    const S t = S(2) * a_ * x;
    return x / S(2) * sqrt(S(1) + t * t) + asinh(t) / (S(4) * a_);
  }
  /// The closed form has a primitive; the quadrature variants (kept for comparison) do not.
  bool has_arc_length_primitive() const { return method_.closed_form; }
  S arc_length(const S& x0, const S& x1) const {
    if (method_.closed_form) return arc_length_primitive(x1) - arc_length_primitive(x0);
    return arc_length_by_quadrature(*this, x0, x1, method_.rule);
  }
  S param_at_arc_length(const S& x0, const S& ds) const { return param_at_arc_length_newton(*this, x0, ds); }

  template <class T> Parabola<T> cast() const {
    return Parabola<T>(scalar_cast<T>(a_), scalar_cast<T>(domain_.lo), scalar_cast<T>(domain_.hi), method_);
  }

 private:
  S a_;
  Domain<S> domain_;
  ArcLengthMethod method_;
};

}  // namespace rollkin
