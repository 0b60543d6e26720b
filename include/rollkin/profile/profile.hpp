// A contour as the mechanism sees it: one profile from the closed set of profile types, placed in its
// link's frame, with the material side applied. Dispatch over the closed set is static (std::visit).
//
// Material side: every profile type defines a natural direction (see its header); when the scene says the
// material lies on the other side, the contour runs the profile backwards, u -> -u, so that the material is
// on the left again (docs/method.md section 3). Derivatives of odd order change sign under that reversal.
//
// Beyond the ends of an open contour: the contour is defined on its domain only, and a contact there is
// refused (Domain::contains; solve/contact_limits.hpp). Newton's iterates may still stray past an end on the
// way to a solution, so every query of the contour is defined for every u: beyond an end the contour goes on
// along its tangent line at that end, p(e) + (u - e) p'(e), with arc length (u - e) |p'(e)|. This extension is
// C1, cheap and bounded for every profile kind (no extrapolated spline, rational pole or quadrature over the
// undrawn part: an iterate far outside costs what one inside costs), and it never changes a value on the
// domain. docs/reliability.md, "Contacts stay on the drawn contour".
#pragma once

#include "rollkin/profile/arc_length_parameterised.hpp"
#include "rollkin/profile/bezier.hpp"
#include "rollkin/profile/circle.hpp"
#include "rollkin/profile/ellipse.hpp"
#include "rollkin/profile/line.hpp"
#include "rollkin/profile/parabola.hpp"
#include "rollkin/profile/spline.hpp"
#include "rollkin/se2.hpp"

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace rollkin {

/// The closed set of profile types: analytic curves, sampled contours (spline), Bezier paths, and a spline
/// or Bezier path re-parameterised by arc length.
template <class S>
using ProfileShape = std::variant<Line<S>, Circle<S>, Parabola<S>, Ellipse<S>, SampledProfile<S>, BezierPath<S>,
                                  ArcLengthProfile<S>>;

/// A fixed origin of arc length on a contour (see Contour::arc_origin).
template <class S> struct ArcOrigin {
  S u0;
  S primitive;         // s(u0), when has_primitive
  bool has_primitive;  // false: arc lengths from u0 are integrated (quadrature variants of analytic curves)
};

/// A corner of a contour (a joint of a Bezier path where the tangent jumps): a contact is defined on either
/// side of it but may not pass it (solve/continuation.hpp stops there with status `corner`).
template <class S> struct ContourCorner {
  S u;                // the contour's parameter at the corner (a closed contour: any u + k * period too)
  Vec2<S> point;      // in the contour's own frame (the profile's coordinates)
  std::string label;  // where it comes from, for messages (e.g. the DXF entities that meet there)
};

template <class S> class Contour {
 public:
  using Scalar = S;
  /// corner_labels: one description per corner of the profile, in the order the profile lists them
  /// (BezierPath::corners()); missing ones are described by the joint's segment numbers.
  Contour(std::string name, int link, ProfileShape<S> shape, SE2<S> placement, bool reversed,
          std::vector<std::string> corner_labels = {})
      : name_(std::move(name)),
        link_(link),
        shape_(std::move(shape)),
        placement_(placement),
        placed_(!placement.is_identity()),
        reversed_(reversed),
        corner_labels_(std::move(corner_labels)),
        domain_(profile_domain()) {
    find_corners();
  }

  const std::string& name() const { return name_; }
  int link() const { return link_; }
  const SE2<S>& placement() const { return placement_; }
  bool reversed() const { return reversed_; }
  const ProfileShape<S>& shape() const { return shape_; }

  /// The parameter range of the drawn contour, in this contour's (possibly reversed) parameter.
  const Domain<S>& domain() const { return domain_; }
  ParamKind parameter_kind() const { return visit([](const auto& p) { return p.parameter_kind(); }); }
  /// The centre of a circle (or of an arc of one) in the link frame, which is its centre of curvature at every
  /// point; none for every other kind. A circle touching a cam stands for a roller on its pin there
  /// (analysis.hpp, the pressure angle).
  std::optional<Vec2<S>> circle_centre() const {
    if (!std::holds_alternative<Circle<S>>(shape_)) return std::nullopt;
    return placement_.translation();
  }
  /// Tangent discontinuities, in this contour's (possibly reversed) parameter.
  const std::vector<ContourCorner<S>>& corners() const { return corners_; }
  int continuity() const { return visit([](const auto& p) { return p.continuity(); }); }

  /// Jet in the LINK frame, material on the left (an identity placement is skipped: it changes no digit).
  /// Beyond an open end: the tangent-line extension (file comment).
  Jet<S> jet(const S& u, int order) const {
    if (!beyond_end(u)) return jet_on_domain(u, order);
    const S e = nearest_end(u);
    Jet<S> j = jet_on_domain(e, 1);
    j.p += (u - e) * j.d1;
    j.d2.setZero();
    j.d3.setZero();
    return j;
  }
  /// Signed arc length from u0 to u1 in this contour's (possibly reversed) parameter.
  S arc_length(const S& u0, const S& u1) const {
    if (!beyond_end(u0) && !beyond_end(u1)) return arc_length_on_domain(u0, u1);
    const S e0 = nearest_end(u0), e1 = nearest_end(u1);
    return arc_length_on_domain(e0, e1) + overhang(u1, e1) - overhang(u0, e0);
  }
  /// Origin u0 of arc lengths measured from a fixed parameter (a rolling pair's assembly contact), with the
  /// primitive s(u0) evaluated once when the profile has one (closed form or cumulative table).
  ArcOrigin<S> arc_origin(const S& u0) const {
    const bool has = visit([](const auto& p) { return p.has_arc_length_primitive(); });
    return ArcOrigin<S>{u0, has ? primitive(u0) : S(0), has};
  }
  /// Signed arc length from the origin to u (eq. 4): s(u) - s(u0) from the primitive, else by quadrature
  /// from u0.
  S arc_length_from(const ArcOrigin<S>& origin, const S& u) const {
    return origin.has_primitive ? S(primitive(u) - origin.primitive) : arc_length(origin.u0, u);
  }
  /// u with arc_length(u0, u) = ds (on the tangent-line extension where that lies beyond an open end).
  S param_at_arc_length(const S& u0, const S& ds) const {
    if (domain_.closed) return param_on_domain(u0, ds);
    const S e0 = nearest_end(u0);
    const S along = ds + overhang(u0, e0);  // arc length from e0
    const S to_hi = arc_length_on_domain(e0, domain_.hi);
    if (along > to_hi) return domain_.hi + (along - to_hi) / speed_on_domain(domain_.hi);
    const S to_lo = arc_length_on_domain(e0, domain_.lo);
    if (along < to_lo) return domain_.lo + (along - to_lo) / speed_on_domain(domain_.lo);
    return param_on_domain(e0, along);
  }

  /// How far the profile may lie from the contour it stands for: zero for analytic and Bezier profiles (exact
  /// by definition); for a cubic spline through samples the interpolation error estimated from the jumps of
  /// the third derivative at the knots, e ~ (5/384) h^4 |p^(4)| ~ (5/384) h^3 |jump p^(3)|, plus the
  /// smoothing deviation. A spline re-parameterised by arc length is the same curve: its base spline's error.
  S representation_error() const {
    using std::max;
    const SampledProfile<S>* spline = std::get_if<SampledProfile<S>>(&shape_);
    if (const auto* al = std::get_if<ArcLengthProfile<S>>(&shape_)) spline = al->sampled();
    if (spline == nullptr) return S(0);
    const std::size_t n = spline->span_count();
    S worst(0);
    Vec2<S> previous = spline->jet(mid_span(*spline, 0), 3).d3;
    for (std::size_t k = 1; k <= n; ++k) {
      if (k == n && !spline->domain().closed) break;
      const std::size_t span = k % n;
      const Vec2<S> d3 = spline->jet(mid_span(*spline, span), 3).d3;
      const S h = spline->knot(span + 1) - spline->knot(span);
      worst = max(worst, S(S(5) / S(384) * h * h * h * (d3 - previous).norm()));
      previous = d3;
    }
    return worst + spline->max_deviation();
  }

  template <class T> Contour<T> cast() const {
    ProfileShape<T> shape = std::visit([](const auto& p) -> ProfileShape<T> { return p.template cast<T>(); }, shape_);
    return Contour<T>(name_, link_, std::move(shape), placement_.template cast<T>(), reversed_, corner_labels_);
  }

 private:
  template <class F> auto visit(F&& f) const { return std::visit(std::forward<F>(f), shape_); }
  Domain<S> profile_domain() const {
    const Domain<S> d = visit([](const auto& p) { return p.domain(); });
    if (!reversed_) return d;
    return Domain<S>{-d.hi, -d.lo, d.closed};
  }

  // ---- the tangent-line extension beyond an open end (file comment) ----
  bool beyond_end(const S& u) const { return !domain_.closed && (u < domain_.lo || u > domain_.hi); }
  /// u itself on the domain (or on a closed contour), else the end it lies beyond.
  S nearest_end(const S& u) const { return !beyond_end(u) ? u : (u < domain_.lo ? domain_.lo : domain_.hi); }
  /// Arc length along the extension from end e out to u: (u - e) |p'(e)|; zero on the domain.
  S overhang(const S& u, const S& e) const { return u == e ? S(0) : S((u - e) * speed_on_domain(e)); }
  S speed_on_domain(const S& u) const { return jet_on_domain(u, 1).d1.norm(); }

  // ---- the profile itself, in this contour's parameter and frame ----
  Jet<S> jet_on_domain(const S& u, int order) const {
    Jet<S> j = visit([&](const auto& p) { return p.jet(reversed_ ? S(-u) : u, order); });
    if (reversed_) {
      j.d1 = -j.d1;
      j.d3 = -j.d3;
    }
    if (!placed_) return j;
    j.p = placement_.act(j.p);
    j.d1 = placement_.rotate(j.d1);
    if (order >= 2) j.d2 = placement_.rotate(j.d2);
    if (order >= 3) j.d3 = placement_.rotate(j.d3);
    return j;
  }
  S arc_length_on_domain(const S& u0, const S& u1) const {
    if (!reversed_) return visit([&](const auto& p) { return p.arc_length(u0, u1); });
    return -visit([&](const auto& p) { return p.arc_length(S(-u0), S(-u1)); });
  }
  S param_on_domain(const S& u0, const S& ds) const {
    if (!reversed_) return visit([&](const auto& p) { return p.param_at_arc_length(u0, ds); });
    return -visit([&](const auto& p) { return p.param_at_arc_length(S(-u0), S(-ds)); });
  }
  /// The profile's arc-length primitive in this contour's parameter (reversed, s(u) = -s_profile(-u)),
  /// continued along the extension.
  S primitive(const S& u) const {
    const S e = nearest_end(u);
    const S s = reversed_ ? S(-visit([&](const auto& p) { return p.arc_length_primitive(S(-e)); }))
                          : visit([&](const auto& p) { return p.arc_length_primitive(e); });
    return s + overhang(u, e);
  }
  static S mid_span(const SampledProfile<S>& p, std::size_t k) { return (p.knot(k) + p.knot(k + 1)) / S(2); }

  /// The corners of a Bezier path, directly (u = the segment's index) or re-parameterised by arc length.
  void find_corners() {
    const BezierPath<S>* path = std::get_if<BezierPath<S>>(&shape_);
    const ArcLengthProfile<S>* by_length = std::get_if<ArcLengthProfile<S>>(&shape_);
    if (by_length) path = by_length->bezier();
    if (!path) return;
    const std::vector<PathCorner<S>>& found = path->corners();
    for (std::size_t k = 0; k < found.size(); ++k) {
      const PathCorner<S>& c = found[k];
      const S u = by_length ? by_length->arc_length_at(S(c.piece)) : S(c.piece);
      std::string label = k < corner_labels_.size()
                              ? corner_labels_[k]
                              : "joint of segments " + std::to_string(c.piece == 0 ? path->segments().size() - 1 : c.piece - 1) +
                                    " and " + std::to_string(c.piece);
      corners_.push_back({reversed_ ? S(-u) : u, c.point, std::move(label)});
    }
  }

  std::string name_;
  int link_;
  ProfileShape<S> shape_;
  SE2<S> placement_;
  bool placed_;  // placement is not the identity
  bool reversed_;
  std::vector<std::string> corner_labels_;
  std::vector<ContourCorner<S>> corners_;
  Domain<S> domain_;  // in this contour's parameter (profile_domain())
};

}  // namespace rollkin
