// Circle p(u) = r (cos u, sin u) about the contour frame's origin, counter-clockwise, material inside
// (a disk). A ring (material outside) is the same circle with the material side flipped in the scene.
// s(u) = r u in closed form.
#pragma once

#include "rollkin/profile/jet.hpp"

namespace rollkin {

template <class S> class Circle {
 public:
  using Scalar = S;
  /// Full circle (closed, u in [0, 2 pi)). Throws std::invalid_argument unless radius > 0 (finite).
  explicit Circle(const S& radius) : r_(radius), domain_{S(0), S(2) * pi<S>(), true} {
    require_positive(radius, "circle", "the radius");
  }
  /// Open arc u in [lo, hi] (radians). Throws std::invalid_argument unless radius > 0 and lo < hi.
  Circle(const S& radius, const S& lo, const S& hi) : r_(radius), domain_{lo, hi, false} {
    require_positive(radius, "circle", "the radius");
    require_parameter_range(lo, hi, "circle arc");
  }

  const S& radius() const { return r_; }
  Domain<S> domain() const { return domain_; }
  ParamKind parameter_kind() const { return ParamKind::Angle; }
  int continuity() const { return 3; }
  Jet<S> jet(const S& u, int order) const {
    S c, s;
    sin_cos(u, s, c);
    c *= r_;
    s *= r_;
    Jet<S> j;
    j.p = Vec2<S>(c, s);
    j.d1 = Vec2<S>(-s, c);
    if (order >= 2) j.d2 = Vec2<S>(-c, -s);
    if (order >= 3) j.d3 = Vec2<S>(s, -c);
    return j;
  }
  S arc_length(const S& u0, const S& u1) const { return r_ * (u1 - u0); }
  bool has_arc_length_primitive() const { return true; }
  S arc_length_primitive(const S& u) const { return r_ * u; }
  S param_at_arc_length(const S& u0, const S& ds) const { return u0 + ds / r_; }

  template <class T> Circle<T> cast() const {
    Circle<T> c(scalar_cast<T>(r_));
    c.domain_ = domain_.template cast<T>();
    return c;
  }

 private:
  template <class> friend class Circle;
  S r_;
  Domain<S> domain_;
};

}  // namespace rollkin
