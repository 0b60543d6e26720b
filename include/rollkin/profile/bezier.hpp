// A contour made of Bezier segments of any degree, each optionally rational, so that conics are exact.
//
// Segment i covers u in [i, i+1] with t = u - i (ParamKind::Unitless); a closed path wraps with period
// nseg. With control points P_k, weights w_k (all 1 for a polynomial segment) and Bernstein polynomials
// B_k^n, the homogeneous curve is
//   H(t) = sum_k B_k^n(t) (w_k P_k, w_k) = (A(t), w(t)),   p(t) = A(t) / w(t),
// and its derivatives are Bezier curves of the forward differences (the hodograph),
//   H^(j)(t) = n! / (n-j)! sum_k B_k^{n-j}(t) Delta^j (w P, w)_k,
// evaluated by de Casteljau. The derivatives of p follow from A = w p by Leibniz' rule:
//   p'   = (A'   - w' p) / w
//   p''  = (A''  - 2 w' p' - w'' p) / w
//   p''' = (A''' - 3 w' p'' - 3 w'' p' - w''' p) / w.
// A circular arc of opening 2 phi is the rational quadratic with end weights 1 and middle weight cos(phi)
// whose middle control point is the intersection of the end tangents.
//
// Validation: adjacent segments share their end points. A joint where the tangent direction jumps is a
// corner: the path is split there into smooth pieces (corners()), and a contact may not pass it (the
// continuation stops with status `corner`, solve/continuation.hpp). The end tangent direction of a segment
// is that of the first control point distinct from the end point, so a zero end derivative (coincident
// control points) is accepted; such a point has zero speed, it is reported by stationary_params().
#pragma once

#include "rollkin/profile/jet.hpp"
#include "rollkin/profile/piecewise_arc_length.hpp"
#include "rollkin/profile/quadrature.hpp"

#include <algorithm>
#include <array>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace rollkin {

template <class S> struct BezierSegment {
  std::vector<Vec2<S>> points;  // degree + 1 control points
  std::vector<S> weights;       // empty: polynomial; otherwise one positive weight per control point

  int degree() const { return static_cast<int>(points.size()) - 1; }
  bool rational() const { return !weights.empty(); }
  S weight(std::size_t k) const { return weights.empty() ? S(1) : weights[k]; }

  template <class T> BezierSegment<T> cast() const {
    BezierSegment<T> c;
    for (const auto& p : points) c.points.push_back(p.template cast<T>());
    for (const auto& w : weights) c.weights.push_back(scalar_cast<T>(w));
    return c;
  }
};

/// A joint of a Bezier path where the tangent direction jumps.
template <class S> struct PathCorner {
  std::size_t piece = 0;  // index of the segment that starts at the corner (its native parameter u = piece)
  Vec2<S> point;          // the corner
  S turn = S(0);          // signed turn of the tangent direction, radians (counter-clockwise positive)
};

/// The joints of a chain of Bezier segments (segment j's end to segment j + 1's start, and the last to the first
/// when closed) where the tangent direction turns by more than corner_tolerance radians, in joint order. A
/// direction is taken towards the first control point farther than `gap` from the joint; a segment without
/// one gives no corner.
template <class S>
std::vector<PathCorner<S>> path_corners(const std::vector<BezierSegment<S>>& segments, bool closed, const S& gap,
                                        const S& corner_tolerance) {
  using std::abs;
  using std::atan2;
  auto direction = [&](const BezierSegment<S>& s, bool at_end) -> Vec2<S> {
    const std::size_t n = s.points.size() - 1;
    const Vec2<S>& e = at_end ? s.points[n] : s.points[0];
    for (std::size_t k = 1; k <= n; ++k) {
      const Vec2<S> d = at_end ? Vec2<S>(e - s.points[n - k]) : Vec2<S>(s.points[k] - e);
      if (d.norm() > gap) return d / d.norm();
    }
    return Vec2<S>::Zero();
  };
  std::vector<PathCorner<S>> corners;
  const std::size_t count = segments.size();
  const std::size_t joints = count == 0 ? 0 : (closed ? count : count - 1);
  for (std::size_t j = 0; j < joints; ++j) {
    const std::size_t next = (j + 1) % count;
    const Vec2<S> a = direction(segments[j], true), b = direction(segments[next], false);
    if (a.isZero() || b.isZero()) continue;
    const S turn = atan2(cross2(a, b), a.dot(b));
    if (abs(turn) > corner_tolerance) corners.push_back({next, segments[next].points.front(), turn});
  }
  return corners;
}

template <class S> struct BezierPathOptions {
  S joint_tolerance = tolerance<S>(S(1) / S(2));   // end point gap, relative to the path's extent
  S corner_tolerance = tolerance<S>(S(1) / S(2));  // tangent direction jump at a joint, radians

  template <class T> BezierPathOptions<T> cast() const {
    return {scalar_cast<T>(joint_tolerance), scalar_cast<T>(corner_tolerance)};
  }
};

template <class S> class BezierPath {
 public:
  using Scalar = S;

  BezierPath(std::vector<BezierSegment<S>> segments, bool closed, const BezierPathOptions<S>& options = {})
      : segments_(std::move(segments)), closed_(closed), options_(options) {
    if (segments_.empty()) throw std::invalid_argument("BezierPath: no segments");
    for (std::size_t i = 0; i < segments_.size(); ++i) check_segment(i);
    extent_ = control_extent();
    for (std::size_t i = 0; i < segments_.size(); ++i) hodographs_.push_back(hodograph(segments_[i]));
    check_joints();
    corners_ = path_corners(segments_, closed_, gap_tolerance(), options_.corner_tolerance);
    continuity_ = joint_continuity();
    find_stationary_points();
    choose_panels();
    arc_ = PiecewiseArcLength<S>(*this);
  }

  // ---- exact conics -------------------------------------------------------------------------------------

  /// Circular arc from angle a0 to a1 (radians; counter-clockwise when a1 > a0), split into rational
  /// quadratic pieces of at most 90 degrees.
  static BezierPath circle_arc(const Vec2<S>& center, const S& r, const S& a0, const S& a1) {
    using std::abs;
    using std::ceil;
    using std::cos;
    using std::sin;
    const S quarter = pi<S>() / S(2);
    const int pieces = std::max(1, static_cast<int>(to_double(ceil(abs(a1 - a0) / quarter - tolerance<S>(S(1) / S(2))))));
    std::vector<BezierSegment<S>> segs;
    Vec2<S> start = center + r * Vec2<S>(cos(a0), sin(a0));
    for (int k = 0; k < pieces; ++k) {
      const S ta = a0 + (a1 - a0) * S(k) / S(pieces), tb = a0 + (a1 - a0) * S(k + 1) / S(pieces);
      const S half = (tb - ta) / S(2), mid = (ta + tb) / S(2);
      const Vec2<S> end = center + r * Vec2<S>(cos(tb), sin(tb));
      segs.push_back({{start, center + (r / cos(half)) * Vec2<S>(cos(mid), sin(mid)), end}, {S(1), cos(half), S(1)}});
      start = end;
    }
    return BezierPath(std::move(segs), false);
  }

  /// Full circle, counter-clockwise from angle 0 (material inside): four exact quarter arcs, u = 1 at 90 deg.
  static BezierPath circle(const Vec2<S>& center, const S& r) { return ellipse(center, r, r, S(0)); }

  /// Full ellipse with semi-axes a (along the direction `angle`) and b, counter-clockwise from the end of
  /// the a-axis: the affine image of the four exact quarter circles (weights are affine invariant).
  static BezierPath ellipse(const Vec2<S>& center, const S& a, const S& b, const S& angle = S(0)) {
    using std::cos;
    using std::sin;
    using std::sqrt;
    const S c = cos(angle), s = sin(angle);
    auto map = [&](const S& x, const S& y) { return Vec2<S>(center.x() + c * a * x - s * b * y, center.y() + s * a * x + c * b * y); };
    const S w = sqrt(S(2)) / S(2);  // cos(45 deg)
    const int corner_x[5] = {1, 0, -1, 0, 1}, corner_y[5] = {0, 1, 0, -1, 0};
    std::vector<BezierSegment<S>> segs;
    for (int k = 0; k < 4; ++k) {
      const S x0(corner_x[k]), y0(corner_y[k]), x1(corner_x[k + 1]), y1(corner_y[k + 1]);
      segs.push_back({{map(x0, y0), map(x0 + x1, y0 + y1), map(x1, y1)}, {S(1), w, S(1)}});
    }
    return BezierPath(std::move(segs), true);
  }

  /// y = a x^2 for x in [x0, x1] as one polynomial quadratic (x linear in u): control points
  /// (x0, a x0^2), ((x0 + x1)/2, a x0 x1), (x1, a x1^2).
  static BezierPath parabola(const S& a, const S& x0, const S& x1) {
    BezierSegment<S> seg{{Vec2<S>(x0, a * x0 * x0), Vec2<S>((x0 + x1) / S(2), a * x0 * x1), Vec2<S>(x1, a * x1 * x1)}, {}};
    return BezierPath({seg}, false);
  }

  // ---- the profile concept ------------------------------------------------------------------------------

  Domain<S> domain() const { return Domain<S>{S(0), S(segments_.size()), closed_}; }
  ParamKind parameter_kind() const { return ParamKind::Unitless; }
  /// Of the smooth pieces between corners: 2 if p' and p'' agree at every other joint (a single open segment
  /// counts as smooth), else 1 (G1: the tangent direction is continuous, its length may jump).
  int continuity() const { return continuity_; }
  /// The joints where the tangent direction jumps, in joint order (a closed path's last joint, at u = 0,
  /// comes last).
  const std::vector<PathCorner<S>>& corners() const { return corners_; }
  /// Whether the joint at the start of segment `piece` is a corner: a binary search of corners(), which holds
  /// the pieces in ascending order, a closed path's piece 0 last (asked for every joint, a linear search made
  /// a path with as many corners as segments quadratic: 80,000 took 11 s).
  bool corner_at(std::size_t piece) const {
    if (piece == 0) return !corners_.empty() && corners_.back().piece == 0;
    const auto first_not_before = std::lower_bound(corners_.begin(), corners_.end(), piece, [](const PathCorner<S>& c, std::size_t p) {
      return c.piece != 0 && c.piece < p;
    });
    return first_not_before != corners_.end() && first_not_before->piece == piece;
  }

  Jet<S> jet(const S& u, int order) const {
    const S w = domain().wrap(u);
    const std::size_t i = piece_of(w);
    return segment_jet(i, w - S(i), order);
  }

  S arc_length(const S& u0, const S& u1) const { return arc_.between(*this, domain(), u0, u1); }
  /// The table's pieces are whole segments, so s(u) costs a quadrature from the segment's start: no cheaper
  /// than integrating from the rolling origin, which for the usual short motions stays inside one segment
  /// and integrates over a shorter interval. The contour integrates from the origin instead.
  bool has_arc_length_primitive() const { return false; }
  S arc_length_primitive(const S& u) const { return arc_.primitive(*this, domain(), u); }
  S param_at_arc_length(const S& u0, const S& ds) const { return arc_.param_at(*this, domain(), u0, ds); }
  S total_length() const { return arc_.total(); }

  const std::vector<BezierSegment<S>>& segments() const { return segments_; }
  /// Parameters where p' = 0 (segment ends with coincident control points): contact frames are undefined there.
  const std::vector<S>& stationary_params() const { return stationary_; }

  template <class T> BezierPath<T> cast() const {
    std::vector<BezierSegment<T>> segs;
    for (const auto& s : segments_) segs.push_back(s.template cast<T>());
    return BezierPath<T>(std::move(segs), closed_, options_.template cast<T>());
  }

  /// Segment i's point and derivatives in its own t in [0, 1] (both sides of a joint: t = 1 of i, t = 0 of i + 1).
  Jet<S> segment_jet(std::size_t i, const S& t, int order) const {
    const Hodograph& h = hodographs_[i];
    Vec3<S> H[4];
    for (int j = 0; j < 4; ++j) H[j] = (j <= order && !h[j].empty()) ? de_casteljau(h[j], t) : Vec3<S>::Zero();
    const S w = H[0].z();
    auto A = [&](int j) -> Vec2<S> { return H[j].template head<2>(); };
    auto dw = [&](int j) -> S { return H[j].z(); };
    Jet<S> r;
    r.p = A(0) / w;
    if (order >= 1) r.d1 = (A(1) - dw(1) * r.p) / w;
    if (order >= 2) r.d2 = (A(2) - S(2) * dw(1) * r.d1 - dw(2) * r.p) / w;
    if (order >= 3) r.d3 = (A(3) - S(3) * dw(1) * r.d2 - S(3) * dw(2) * r.d1 - dw(3) * r.p) / w;
    return r;
  }

  // ---- the `Pieces` interface of PiecewiseArcLength ----
  std::size_t piece_count() const { return segments_.size(); }
  S knot(std::size_t k) const { return S(k); }
  std::size_t piece_of(const S& u) const {
    using std::floor;
    const std::size_t n = segments_.size();
    if (!(u >= S(1))) return 0;
    if (u >= S(n - 1)) return n - 1;
    return static_cast<std::size_t>(to_double(floor(u)));
  }
  S speed(std::size_t i, const S& u) const { return segment_jet(i, u - S(i), 1).d1.norm(); }
  /// Composite Gauss-Legendre with the segment's panel count (chosen at construction), scaled to [a, b].
  S piece_length(std::size_t i, const S& a, const S& b) const {
    using std::abs;
    using std::ceil;
    QuadratureRule rule = segment_rule();
    // The segment's panels per unit of t, at most twice the segment's own count: only the contour's tangent
    // extension (profile.hpp) asks for lengths beyond the segment, so the work is bounded for every input.
    const double wanted = std::ceil(panels_[i] * to_double(abs(b - a)));
    rule.panels = wanted >= 1 ? static_cast<int>(std::min(wanted, 2.0 * panels_[i])) : 1;
    return integrate<S>([&](const S& u) { return speed(i, u); }, a, b, rule);
  }

 private:
  using Hodograph = std::vector<std::vector<Vec3<S>>>;  // [j][k]: j-th derivative control points, j <= 3

  static QuadratureRule segment_rule() {
    QuadratureRule r;
    r.kind = Quadrature::GaussLegendre;
    r.order = std::clamp(std::numeric_limits<S>::digits10 * 3 / 5 + 1, 8, 40);
    return r;
  }

  static std::string number_text(const S& x) {
    std::ostringstream os;
    os << to_double(x);
    return os.str();
  }
  static std::string point_text(const Vec2<S>& p) { return "(" + number_text(p.x()) + ", " + number_text(p.y()) + ")"; }

  void check_segment(std::size_t i) const {
    const BezierSegment<S>& s = segments_[i];
    const std::string where = "BezierPath: segment " + std::to_string(i) + ": ";
    if (s.points.size() < 2) throw std::invalid_argument(where + "needs at least 2 control points");
    if (s.rational() && s.weights.size() != s.points.size())
      throw std::invalid_argument(where + "needs one weight per control point");
    for (const S& w : s.weights)
      if (!(w > S(0))) throw std::invalid_argument(where + "weights must be positive");
  }

  S control_extent() const {
    Vec2<S> lo = segments_[0].points[0], hi = lo;
    for (const auto& s : segments_)
      for (const auto& p : s.points) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
    return (hi - lo).norm();
  }

  /// Homogeneous control points (w P, w) and their scaled forward differences n!/(n-j)! Delta^j, j <= 3.
  static Hodograph hodograph(const BezierSegment<S>& s) {
    const int n = s.degree();
    Hodograph h(4);
    for (int k = 0; k <= n; ++k) {
      const S w = s.weight(k);
      h[0].emplace_back(w * s.points[k].x(), w * s.points[k].y(), w);
    }
    for (int j = 1; j <= 3 && j <= n; ++j)
      for (std::size_t k = 0; k + 1 < h[j - 1].size(); ++k) h[j].push_back(S(n - j + 1) * (h[j - 1][k + 1] - h[j - 1][k]));
    return h;
  }

  /// De Casteljau's algorithm on a working copy: on the stack up to degree 7 (every conic and cubic), on the
  /// heap beyond, so evaluation (called at every quadrature node) does not allocate for usual paths.
  static Vec3<S> de_casteljau(const std::vector<Vec3<S>>& points, const S& t) {
    constexpr std::size_t kInline = 8;
    std::array<Vec3<S>, kInline> inline_copy;
    std::vector<Vec3<S>> heap_copy;
    Vec3<S>* c = inline_copy.data();
    if (points.size() > kInline) {
      heap_copy = points;
      c = heap_copy.data();
    } else {
      std::copy(points.begin(), points.end(), c);
    }
    const S s = S(1) - t;
    for (std::size_t level = points.size(); level-- > 1;)
      for (std::size_t k = 0; k < level; ++k) c[k] = s * c[k] + t * c[k + 1];
    return c[0];
  }

  S gap_tolerance() const { return options_.joint_tolerance * extent_; }

  /// Unit tangent direction leaving the start (at_end = false) or arriving at the end of segment i: towards
  /// (or from) the first control point distinct from that end point.
  Vec2<S> end_direction(std::size_t i, bool at_end) const {
    const auto& pts = segments_[i].points;
    const std::size_t n = pts.size() - 1;
    const Vec2<S>& end = at_end ? pts[n] : pts[0];
    for (std::size_t k = 1; k <= n; ++k) {
      const Vec2<S>& q = at_end ? pts[n - k] : pts[k];
      const Vec2<S> d = at_end ? Vec2<S>(end - q) : Vec2<S>(q - end);
      if (d.norm() > gap_tolerance()) return d.normalized();
    }
    throw std::invalid_argument("BezierPath: segment " + std::to_string(i) + " is degenerate (all control points coincide)");
  }

  std::size_t joint_count() const { return closed_ ? segments_.size() : segments_.size() - 1; }

  /// Joint j joins the end of segment j to the start of segment (j + 1) mod n.
  void check_joints() const {
    const std::size_t n = segments_.size();
    for (std::size_t i = 0; i < n; ++i) end_direction(i, false);  // reports degenerate segments
    for (std::size_t j = 0; j < joint_count(); ++j) {
      const std::size_t next = (j + 1) % n;
      const Vec2<S>& end = segments_[j].points.back();
      const Vec2<S>& start = segments_[next].points.front();
      if ((end - start).norm() > gap_tolerance())
        throw std::invalid_argument("BezierPath: segment " + std::to_string(next) + " starts at " + point_text(start) +
                                    " but segment " + std::to_string(j) + " ends at " + point_text(end) +
                                    (closed_ && next == 0 ? " (closed path)" : "") +
                                    "; adjacent segments must share their end points");
    }
  }

  /// |a - b| <= tol (|a| + |b|) with tol = sqrt(eps) (zero on both sides counts as equal).
  static bool nearly_equal(const Vec2<S>& a, const Vec2<S>& b) {
    return (a - b).norm() <= tolerance<S>(S(1) / S(2)) * (a.norm() + b.norm());
  }

  int joint_continuity() const {
    const std::size_t n = segments_.size();
    for (std::size_t j = 0; j < joint_count(); ++j) {
      const std::size_t next = (j + 1) % n;
      if (corner_at(next)) continue;
      const Jet<S> l = segment_jet(j, S(1), 2), r = segment_jet(next, S(0), 2);
      if (!nearly_equal(l.d1, r.d1) || !nearly_equal(l.d2, r.d2)) return 1;
    }
    return 2;
  }

  void find_stationary_points() {
    for (std::size_t i = 0; i < segments_.size(); ++i) {
      const auto& pts = segments_[i].points;
      if ((pts[1] - pts[0]).norm() <= gap_tolerance()) stationary_.push_back(S(i));
      if ((pts[pts.size() - 1] - pts[pts.size() - 2]).norm() <= gap_tolerance()) stationary_.push_back(S(i + 1));
    }
  }

  /// Panels per segment: doubled until two successive composite Gauss-Legendre estimates of the segment
  /// length agree to 64 eps (relative), at most 2^14.
  void choose_panels() {
    using std::abs;
    const S target = epsilon<S>() * S(64);
    for (std::size_t i = 0; i < segments_.size(); ++i) {
      QuadratureRule rule = segment_rule();
      auto length = [&](int panels) {
        rule.panels = panels;
        return integrate<S>([&](const S& t) { return segment_jet(i, t, 1).d1.norm(); }, S(0), S(1), rule);
      };
      int panels = 1;
      S coarse = length(panels);
      for (; panels < (1 << 14); panels *= 2) {
        const S fine = length(2 * panels);
        const bool converged = abs(fine - coarse) <= target * fine;
        coarse = fine;
        if (converged) break;
      }
      panels_.push_back(std::min(2 * panels, 1 << 14));
    }
  }

  std::vector<BezierSegment<S>> segments_;
  bool closed_;
  BezierPathOptions<S> options_;
  S extent_ = S(0);
  std::vector<Hodograph> hodographs_;
  int continuity_ = 1;
  std::vector<PathCorner<S>> corners_;
  std::vector<S> stationary_;
  std::vector<int> panels_;
  PiecewiseArcLength<S> arc_;
};

}  // namespace rollkin
