// Straight line contour p(u) = u (cos phi, sin phi) in its contour frame; u is arc length.
#pragma once

#include "rollkin/profile/jet.hpp"

namespace rollkin {

template <class S> class Line {
 public:
  using Scalar = S;
  /// Along the contour frame's x-axis from u = lo to u = hi; material on the left (+y side).
  /// Throws std::invalid_argument unless lo < hi (finite).
  Line(const S& lo, const S& hi) : domain_{lo, hi, false} { require_parameter_range(lo, hi, "line"); }

  Domain<S> domain() const { return domain_; }
  ParamKind parameter_kind() const { return ParamKind::Length; }
  int continuity() const { return 3; }
  Jet<S> jet(const S& u, int /*order*/) const {
    Jet<S> j;
    j.p = Vec2<S>(u, S(0));
    j.d1 = Vec2<S>(S(1), S(0));
    return j;
  }
  S arc_length(const S& u0, const S& u1) const { return u1 - u0; }
  bool has_arc_length_primitive() const { return true; }
  S arc_length_primitive(const S& u) const { return u; }
  S param_at_arc_length(const S& u0, const S& ds) const { return u0 + ds; }

  template <class T> Line<T> cast() const { return Line<T>(scalar_cast<T>(domain_.lo), scalar_cast<T>(domain_.hi)); }

 private:
  Domain<S> domain_;
};

}  // namespace rollkin
