// One DXF entity to exact Bezier segments (dxf/detail.hpp): lines, circular and elliptical arcs as rational
// quadratics, polylines with bulges, SPLINEs as NURBS converted by knot insertion.
#include "detail.hpp"

#include "rollkin/io/units.hpp"
#include "rollkin/profile/nurbs.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <string>
#include <vector>

namespace rollkin::io::dxf {

Segment reversed(Segment s) {
  std::reverse(s.points.begin(), s.points.end());
  std::reverse(s.weights.begin(), s.weights.end());
  return s;
}

namespace {

// ---- conversion of one entity ------------------------------------------------------------------------------



/// The unit circle arc from t0 to t1 (radians), exact rational quadratics, mapped by p -> c + p.x M + p.y m.
std::vector<Segment> affine_arc(double t0, double t1, const V& c, const V& M, const V& m) {
  std::vector<Segment> segs = BezierPath<double>::circle_arc(V(0, 0), 1.0, t0, t1).segments();
  for (Segment& s : segs)
    for (V& p : s.points) p = c + p.x() * M + p.y() * m;
  return segs;
}

/// Extrusion directions within this angle (radians) of +Z or -Z are +Z or -Z.
constexpr double kExtrusionTolerance = 1e-12;

/// An ELLIPSE's axis ratio beyond this (or below its inverse) is one axis vanishing against the join tolerance.
constexpr double kLargestAxisRatio = 1 / kDxfJoinTolerance;

/// Angles within this fraction of a turn of a whole turn count as a whole turn (rounding of written values).
constexpr double kTurnTolerance = 1e-12;

bool full_turn(double sweep) { return sweep >= 2 * M_PI * (1 - kTurnTolerance); }

/// Counter-clockwise sweep from `from` to `to`, in (0, turn]: reduced by fmod (no loop, whatever the values);
/// a sweep of (nearly) zero or a whole turn is a whole turn.
double ccw_sweep(double from, double to, double turn) {
  double sweep = std::fmod(to - from, turn);
  if (sweep <= turn * kTurnTolerance) sweep += turn;
  return sweep;
}

// ---- polyline bulges (docs/scene_format.md, "dxf contours") -------------------------------------------------
//
// The piece from vertex a to b with bulge k = tan(theta / 4) (theta the included angle, counter-clockwise for
// k > 0) is built from the chord and the bulge alone, never from the centre, which lies (1 - k^2) / (4 k)
// chords away: for a small bulge its round-off would swamp the arc. With m the chord's midpoint, h half its
// length and n = perp(b - a) its left normal (|n| = 2 h):
//  - an arc of at most 90 degrees is one rational quadratic whose middle control point is the end tangents'
//    intersection, h tan(theta / 2) to the right of m: m - n k / (1 - k^2) (tan(theta / 2) = 2 k / (1 - k^2)),
//    with weight cos(theta / 2) = (1 - k^2) / (1 + k^2);
//  - a larger arc is halved at its middle point m - n k / 2 (its sagitta is h k), each half with bulge
//    tan(theta / 8) = k / (1 + sqrt(1 + k^2));
//  - a bulge of at most the double round-off eps is a line: its sagitta h |k| <= eps max(|a|, |b|) is below
//    the round-off of the vertices themselves (max(|a|, |b|) >= h);
//  - a bulge above kLargestBulge is refused: the arc's ends are 2 / (|k| + 1 / |k|) of its diameter apart,
//    below the join tolerance, and cannot be told from a whole circle.

/// tan(pi / 8) = sqrt(2) - 1 (a quarter turn), with room for the rounding of the halving.
constexpr double kQuarterTurnBulge = 0.41421356237310;
constexpr double kLargestBulge = 2 / kDxfJoinTolerance;

/// The middle point of the arc a -> b with bulge k: its sagitta h k to the right of the chord's middle.
V arc_middle(const V& a, const V& b, double k) { return (a + b) / 2 - perp(V(b - a)) * (k / 2); }

void append_bulge_pieces(const V& a, const V& b, double bulge, std::vector<Segment>& out) {
  if (std::abs(bulge) <= std::numeric_limits<double>::epsilon()) {
    out.push_back({{a, b}, {}});
    return;
  }
  const V m = (a + b) / 2, n = perp(V(b - a));
  if (std::abs(bulge) > kQuarterTurnBulge) {
    const V middle = arc_middle(a, b, bulge);
    const double half = bulge / (1 + std::hypot(1.0, bulge));
    append_bulge_pieces(a, middle, half, out);
    append_bulge_pieces(middle, b, half, out);
    return;
  }
  const double k2 = bulge * bulge;
  out.push_back({{a, m - n * (bulge / (1 - k2)), b}, {1.0, (1 - k2) / (1 + k2), 1.0}});
}

/// Distance from p to the circle through a and c that bulge k (!= 0) makes, in the chord's frame (origin its
/// middle, y its left normal, h half its length: centre (0, yc), signed radius r), without forming the
/// centre: (|p - C|^2 - r^2) / (|p - C| + |r|), where yc^2 - r^2 = -h^2 exactly.
double off_bulge_circle(const V& a, const V& c, double k, const V& p) {
  const double h = (c - a).norm() / 2, yc = h * (1 - k * k) / (2 * k), r = h * (1 + k * k) / (2 * k);
  const V along = (c - a) / (2 * h), left = perp(along), q = p - (a + c) / 2;
  const double x = q.dot(along), y = q.dot(left);
  return std::abs((x - h) * (x + h) + y * y - 2 * y * yc) / (std::hypot(x, y - yc) + std::abs(r));
}

/// Round-off of points: 16 eps of their largest coordinate.
double round_off(std::initializer_list<V> points) {
  double m = 0;
  for (const V& p : points) m = std::max(m, p.cwiseAbs().maxCoeff());
  return 16 * std::numeric_limits<double>::epsilon() * m;
}

// Consecutive bulge arcs of one circle are one arc, one piece of the native parameter: along arcs of
// different lengths on one circle its speed would jump at every vertex, as along a straight run of lines
// (docs/scene_format.md, "Straight runs"). This is the only place rollkin joins arcs (ARC entities, SVG arcs
// and the arcs of different polylines are kept as drawn). Rule (docs/reliability.md, "CAD readers (issue
// 37)"): arcs are joined only when they are one circle, centre and radius. Arcs with bulges k and k' are one
// arc when they turn the same way, together less than a whole turn, and every drawn arc lies on the circle of
// the whole arc (bulge tan(theta / 4) for the sum of their angles: (k + k') / (1 - k k'), tangent addition):
// its ends (the vertices) and its middle point, within round-off plus kOneArcTolerance of the whole chord.
// Two circles through the same two points are farthest apart at the middle of the arc between them, so the
// middle decides; the vertices alone do not: two tangent arcs of radii 1 and 2 have their common vertex on
// the circle of the joined bulge (radius 1.581), which is another circle.

/// The bulge of an arc of bulge `whole` followed by one of bulge `next` taken as one, or 0 when they turn
/// different ways, reach a whole turn, or exceed kLargestBulge together.
double joined_bulge(double whole, double next) {
  if (next == 0 || !std::isfinite(next) || (next > 0) != (whole > 0) || !(whole * next < 1)) return 0;
  const double joined = (whole + next) / (1 - whole * next);
  return std::abs(joined) <= kLargestBulge ? joined : 0;
}

/// Whether the point m lies on the circle of the arc a -> c with bulge `whole`: within round-off and
/// kOneArcTolerance of its chord (the tangent additions that give `whole` round at each arc: over a run of a
/// thousand, its circle moves by some 1e-14 of its size). Stricter than any tolerance of the drawing's size,
/// which is at least the chord: an arc not joined is never wrong, only a joint more.
constexpr double kOneArcTolerance = 1e-12;
bool on_arc_circle(const V& a, const V& c, double whole, const V& m) {
  return off_bulge_circle(a, c, whole, m) <= round_off({a, m, c}) + kOneArcTolerance * (c - a).norm();
}

/// Whether the arcs p[i] -> p[i + 1] (bulge k[i]) .. p[j] -> p[j + 1] are all on the circle of the arc
/// p[i] -> p[j + 1] with bulge `whole`: every inner vertex and every arc's middle point on it.
bool arcs_on_one_circle(const std::vector<V>& p, const std::vector<double>& k, std::size_t i, std::size_t j, double whole) {
  for (std::size_t m = i; m <= j; ++m) {
    if (m > i && !on_arc_circle(p[i], p[j + 1], whole, p[m])) return false;
    if (!on_arc_circle(p[i], p[j + 1], whole, arc_middle(p[m], p[m + 1], k[m]))) return false;
  }
  return true;
}

class Converter {
 public:
  explicit Converter(std::string file) : file_(std::move(file)) {}

  Piece convert(const RawEntity& e) const {
    Piece piece;
    piece.label = e.label();
    if (!e.defect.empty()) throw InputError(file_, e.defect_where, e.label() + ": " + e.defect);
    check_extrusion(e);
    if (e.type == "LINE") line(e, piece);
    else if (e.type == "ARC" || e.type == "CIRCLE") arc(e, piece);
    else if (e.type == "ELLIPSE") ellipse(e, piece);
    else if (e.type == "LWPOLYLINE" || e.type == "POLYLINE") polyline(e, piece);
    else if (e.type == "SPLINE") spline(e, piece);
    if (piece.segments.empty() && !piece.zero_length) fail(e, "has no extent (zero length)");
    return piece;
  }

 private:
  [[noreturn]] void fail(const RawEntity& e, const std::string& what) const {
    throw InputError(file_, "line " + std::to_string(e.line), e.label() + " " + what);
  }

  bool mirrored(const RawEntity& e) const { return e.type != "SPLINE" && e.extrusion[2] < 0; }

  /// The extrusion direction must be +Z or -Z: its angle to the Z axis at most kExtrusionTolerance radians
  /// (round-off of a written unit normal, 0.99999999999999989 for 1), which the arbitrary axis algorithm
  /// makes exactly (0, 0, +-1) after normalising it; the sign is then that of its z (mirrored()).
  /// A SPLINE's normal (0, 0, 0) (written by some LibreCAD versions) is +Z, as CAD programs read it; its control
  /// points are world coordinates, so its normal never mirrors it (mirrored()).
  void check_extrusion(const RawEntity& e) const {
    const auto& n = e.extrusion;
    if (e.type == "SPLINE" && n[0] == 0 && n[1] == 0 && n[2] == 0) return;
    if (!(n[2] != 0 && std::hypot(n[0], n[1]) <= kExtrusionTolerance * std::abs(n[2])))
      fail(e, "has extrusion direction (" + exact_number(n[0]) + ", " + exact_number(n[1]) + ", " + exact_number(n[2]) +
                  "): only drawings in the XY plane are read, extrusion (0, 0, 1) or (0, 0, -1) within " +
                  number(kExtrusionTolerance) + " radians");
  }

  /// OCS to WCS for extrusion (0, 0, -1): the arbitrary axis algorithm gives Ax = (-1, 0, 0), Ay = (0, 1, 0).
  V ocs(const RawEntity& e, double x, double y) const { return mirrored(e) ? V(-x, y) : V(x, y); }

  void line(const RawEntity& e, Piece& piece) const {
    if (e.v[2] != e.v[5]) fail(e, "is not parallel to the XY plane (z " + exact_number(e.v[2]) + " and " + exact_number(e.v[5]) + ")");
    const V a(e.v[0], e.v[1]), b(e.v[3], e.v[4]);
    if (a == b) {
      piece.zero_length = true;  // dropped from a chain; alone, an error (dxf/selection.cpp)
      piece.segments.push_back({{a, b}, {}});
      return;
    }
    piece.segments.push_back({{a, b}, {}});
  }

  void arc(const RawEntity& e, Piece& piece) const {
    const double r = e.v[3];
    if (!(r > 0)) fail(e, "has radius " + exact_number(r) + "; it must be positive");
    double sweep = 2 * M_PI, t0 = 0;
    if (e.type == "ARC") {
      // DXF arcs run counter-clockwise from the start to the end angle; equal angles make a full circle.
      t0 = deg_to_rad(std::fmod(e.v[4], 360.0));
      sweep = deg_to_rad(ccw_sweep(e.v[4], e.v[5], 360.0));
    }
    const double x_sign = mirrored(e) ? -1 : 1;
    piece.segments = affine_arc(t0, t0 + sweep, ocs(e, e.v[0], e.v[1]), V(x_sign * r, 0), V(0, r));
    piece.closed = full_turn(sweep);
  }

  void ellipse(const RawEntity& e, Piece& piece) const {
    const V c(e.v[0], e.v[1]), M(e.v[3], e.v[4]);
    const double ratio = e.v[6];
    if (e.v[5] != 0) fail(e, "has a major axis out of the XY plane (z component " + exact_number(e.v[5]) + ")");
    if (!(M.norm() > 0)) fail(e, "has a zero major axis");
    if (!(ratio > 0 && ratio <= kLargestAxisRatio))
      fail(e, "has axis ratio " + exact_number(ratio) + "; it must be positive (and at most " + number(kLargestAxisRatio) + ")");
    // Minor axis: ratio (N x M), N the extrusion (0, 0, +-1). A ratio above 1 (QCAD writes them) makes it the
    // longer axis: the same curve as major axis m, ratio 1 / ratio and parameter t - pi / 2 (the axes swapped),
    // here without the swap, which would round M and the parameters.
    const V m = mirrored(e) ? V(ratio * M.y(), -ratio * M.x()) : V(-ratio * M.y(), ratio * M.x());
    const double t0 = std::fmod(e.v[7], 2 * M_PI);
    const double sweep = ccw_sweep(e.v[7], e.v[8], 2 * M_PI);
    piece.segments = affine_arc(t0, t0 + (full_turn(sweep) ? 2 * M_PI : sweep), c, M, m);
    piece.closed = full_turn(sweep);
  }

  /// The piece from vertex a to vertex b with bulge `bulge` (append_bulge_pieces), or the error naming the vertex.
  void bulge_piece(const RawEntity& e, std::size_t vertex, const V& a, const V& b, double bulge, Piece& piece) const {
    if (!std::isfinite(bulge)) fail(e, "has a bulge that is not finite at vertex " + std::to_string(vertex));
    if (std::abs(bulge) > kLargestBulge)
      fail(e, "at vertex " + std::to_string(vertex) + ": bulge " + exact_number(bulge) + " makes an arc whose ends are " +
                  number(2 / (std::abs(bulge) + 1 / std::abs(bulge))) + " of its diameter apart, below the join tolerance (" +
                  number(kDxfJoinTolerance) + "): it cannot be told from a whole circle; a bulge is at most " +
                  number(kLargestBulge) + " (draw a whole circle as a CIRCLE)");
    append_bulge_pieces(a, b, bulge, piece.segments);
  }

  void polyline(const RawEntity& e, Piece& piece) const {
    if (e.type == "POLYLINE" && (e.flags & (16 | 64)))
      fail(e, "is a polygon or polyface mesh (group 70 = " + std::to_string(e.flags) + "), not a curve");
    if (e.type == "POLYLINE" && (e.flags & (2 | 4)))
      fail(e, "is curve-fit or spline-fit (group 70 = " + std::to_string(e.flags) +
                  "); its fitted shape is not stored exactly: convert it to a SPLINE in the CAD program");
    const bool three_d = e.type == "POLYLINE" && (e.flags & 8);  // 3D polyline: WCS coordinates, no bulges
    std::vector<Vertex> vs;
    for (const Vertex& v : e.vertices) {
      if (three_d && v.z != e.vertices.front().z) fail(e, "is a 3D polyline that leaves the XY plane");
      if (vs.empty() || vs.back().x != v.x || vs.back().y != v.y) vs.push_back(v);
      else vs.back().bulge = v.bulge;  // a repeated vertex: the bulge of the last copy leads on
    }
    const bool closed = (e.flags & 1) != 0;
    if (closed && vs.size() > 1 && vs.front().x == vs.back().x && vs.front().y == vs.back().y) vs.pop_back();
    const std::size_t n = vs.size(), pieces = closed ? n : n - 1;
    if (n < 2) fail(e, "has fewer than two distinct vertices");
    std::vector<V> p;  // world points, the first again at the end of a closed polyline
    std::vector<double> k;  // world bulges of the pieces
    for (std::size_t i = 0; i <= pieces; ++i) {
      const Vertex& v = vs[i % n];
      p.push_back(three_d ? V(v.x, v.y) : ocs(e, v.x, v.y));
      // Mirroring the OCS x axis reverses the sense of rotation, hence the bulge's sign.
      if (i < pieces) k.push_back(three_d ? 0.0 : (mirrored(e) ? -v.bulge : v.bulge));
    }
    for (std::size_t i = 0; i < pieces;) {
      // the longest run of arcs from piece i that are one arc (the start of a closed polyline stays a vertex)
      std::size_t j = i;
      double whole = k[i];
      if (k[i] != 0 && std::abs(k[i]) <= kLargestBulge)
        for (std::size_t next = i + 1; next < pieces; ++next) {
          const double joined = joined_bulge(whole, k[next]);
          if (joined == 0 || !on_arc_circle(p[i], p[next + 1], joined, p[next]) ||
              !on_arc_circle(p[i], p[next + 1], joined, arc_middle(p[i], p[i + 1], k[i])) ||
              !on_arc_circle(p[i], p[next + 1], joined, arc_middle(p[next], p[next + 1], k[next])))
            break;
          j = next;
          whole = joined;
        }
      if (j > i && !arcs_on_one_circle(p, k, i, j, whole)) {  // drifted off one circle: the arcs as drawn
        for (std::size_t m = i; m <= j; ++m) bulge_piece(e, m, p[m], p[m + 1], k[m], piece);
      } else {
        bulge_piece(e, i, p[i], p[j + 1], whole, piece);
      }
      i = j + 1;  // each vertex is looked at once or twice: linear in the vertices
    }
    piece.closed = closed;
  }

  void spline(const RawEntity& e, Piece& piece) const {
    if (e.n10 == 0) {
      if (e.n11 > 0)
        fail(e, "has only fit points (" + std::to_string(e.n11) +
                    "), no control points: a fit-point spline's shape depends on the CAD program's fitting; save it "
                    "with control points (or convert it to a control-point spline) and export again");
      fail(e, "has no control points");
    }
    Nurbs<double> c;
    c.degree = e.degree;
    c.knots = e.knots;
    for (const auto& q : e.control) {
      if (q[2] != e.control.front()[2]) fail(e, "has control points at different z: it is not in the XY plane");
      c.points.emplace_back(q[0], q[1]);
      if (e.n41 > 0) c.weights.push_back(q[3]);
    }
    const bool wrapped = wrap_periodic(e, c);
    std::vector<Segment> spans;
    try {
      spans = nurbs_to_bezier(c).segments;
    } catch (const std::invalid_argument& ex) {
      fail(e, std::string("is not a valid NURBS curve: ") + ex.what());
    }
    piece.segments = without_zero_length_spans(e, spans);
    piece.closed = (e.flags & 1) != 0 || wrapped;
  }

  /// A periodic SPLINE (group 70 bit 2) may store n control points with n + 1 knots, the knots of its n spans
  /// (the AutoCAD DXF reference, SPLINE: "if the spline is periodic, the length of the knot vector will be
  /// greater than the length of the control array by 1"). Its standard form wraps the first p control points
  /// (and weights) after the last and extends the knots periodically, k_{i+n} = k_i + (k_n - k_0), by p on
  /// each side: n + p points, n + 2 p + 1 knots, the curve on [k_0, k_n]. Returns whether it wrapped.
  bool wrap_periodic(const RawEntity& e, Nurbs<double>& c) const {
    const std::size_t n = c.points.size(), p = static_cast<std::size_t>(std::max(c.degree, 0));
    if (!(e.flags & 2) || c.knots.size() != n + 1 || p < 1 || n < p) return false;
    const double period = c.knots[n] - c.knots[0];
    std::vector<double> knots;
    for (std::size_t i = 0; i < p; ++i) knots.push_back(c.knots[n - p + i] - period);
    knots.insert(knots.end(), c.knots.begin(), c.knots.end());
    for (std::size_t i = 1; i <= p; ++i) knots.push_back(c.knots[i] + period);
    c.knots = knots;
    for (std::size_t i = 0; i < p; ++i) c.points.push_back(c.points[i]);
    if (!c.weights.empty())
      for (std::size_t i = 0; i < p; ++i) c.weights.push_back(c.weights[i]);
    c.closed = true;
    return true;
  }

  /// Spans of a spline whose control points all coincide (repeated control points: p + 1 of them in a row)
  /// are points, not curve: dropped, the next span starting where the previous one ends. When every span is a
  /// point, the error names the repeated control points.
  std::vector<Segment> without_zero_length_spans(const RawEntity& e, const std::vector<Segment>& spans) const {
    double extent = 0;
    for (const auto& q : e.control) extent = std::max(extent, std::max(std::abs(q[0]), std::abs(q[1])));
    const double point_like = 64 * std::numeric_limits<double>::epsilon() * extent;
    std::vector<Segment> kept;
    for (const Segment& s : spans) {
      double reach = 0;
      for (const V& q : s.points) reach = std::max(reach, (q - s.points.front()).norm());
      if (reach <= point_like) continue;
      kept.push_back(s);
      if (kept.size() > 1) kept.back().points.front() = kept[kept.size() - 2].points.back();
    }
    if (kept.empty() && !spans.empty()) {
      std::string repeats;
      for (std::size_t i = 1; i < e.control.size(); ++i)
        if (e.control[i][0] == e.control[i - 1][0] && e.control[i][1] == e.control[i - 1][1])
          repeats += (repeats.empty() ? "" : ", ") + std::to_string(i - 1) + " = " + std::to_string(i);
      fail(e, "has zero length: every span is a single point" +
                  (repeats.empty() ? std::string() : " (repeated control points " + repeats + ")") +
                  "; give the spline distinct control points");
    }
    return kept;
  }

  std::string file_;
};

}  // namespace

Piece convert_entity(const RawEntity& e, const std::string& file) { return Converter(file).convert(e); }

}  // namespace rollkin::io::dxf
