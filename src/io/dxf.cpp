// DXF contour reader (io/dxf.hpp): libdxflib parses, a DL_CreationAdapter collects the entities of the
// ENTITIES section with their type, handle and layer (from processCodeValuePair, which libdxflib calls for
// every group before interpreting it) and the geometry libdxflib reports; then the selected entities are
// converted to exact Bezier segments and chained.
#include "rollkin/io/dxf.hpp"
#include "rollkin/io/units.hpp"

#include "rollkin/profile/nurbs.hpp"

#include <dxflib/dl_creationadapter.h>
#include <dxflib/dl_dxf.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <sstream>

namespace rollkin {
namespace {

using V = Vec2<double>;
using Segment = BezierSegment<double>;

constexpr std::size_t kMaxLine = 1000;  // libdxflib reads lines of at most 1023 characters

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}
std::string point_text(const V& p) { return "(" + number(p.x()) + ", " + number(p.y()) + ")"; }

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string trim(const std::string& s) {
  std::size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return s.substr(a, b - a);
}

bool parse_long(const std::string& text, long& out) {
  const std::string t = trim(text);
  if (t.empty()) return false;
  char* end = nullptr;
  errno = 0;
  out = std::strtol(t.c_str(), &end, 10);
  return errno == 0 && end == t.c_str() + t.size();
}

bool parse_real(const std::string& text) {
  const std::string t = trim(text);
  if (t.empty()) return false;
  char* end = nullptr;
  const double v = std::strtod(t.c_str(), &end);
  return end == t.c_str() + t.size() && std::isfinite(v);
}

/// Group codes whose values are real numbers or integers (DXF reference, "Group code value types").
bool real_code(unsigned c) { return (c >= 10 && c <= 59) || (c >= 110 && c <= 149) || (c >= 210 && c <= 239) || (c >= 1010 && c <= 1059); }
bool int_code(unsigned c) {
  return (c >= 60 && c <= 99) || (c >= 160 && c <= 179) || (c >= 270 && c <= 289) || (c >= 370 && c <= 389) || (c >= 1060 && c <= 1071);
}

/// Checks what libdxflib relies on before it reads the text: not binary, lines short enough for its fixed
/// buffer, every group code line an integer 0..1071. Returns the number of group pairs.
std::size_t check_group_structure(const std::string& text, const std::string& file) {
  if (text.compare(0, 18, "AutoCAD Binary DXF") == 0)
    throw InputError(file, "", "binary DXF is not supported; save the drawing as ASCII DXF");
  std::size_t line = 0, pos = 0, pairs = 0;
  while (pos < text.size()) {
    std::size_t eol = text.find('\n', pos);
    if (eol == std::string::npos) eol = text.size();
    ++line;
    const std::string content = text.substr(pos, eol - pos);
    if (content.size() > kMaxLine)
      throw InputError(file, "line " + std::to_string(line),
                       "line of " + std::to_string(content.size()) + " characters; DXF lines are at most " +
                           std::to_string(kMaxLine) + " characters here");
    if (line % 2 == 1) {
      long code = 0;
      const bool last_blank = eol >= text.size() - 1 && trim(content).empty();
      if (!last_blank && (!parse_long(content, code) || code < 0 || code > 1071))
        throw InputError(file, "line " + std::to_string(line),
                         "expected a group code (an integer 0..1071), got \"" + trim(content).substr(0, 40) + "\"");
      if (!last_blank) ++pairs;
    }
    pos = eol + 1;
  }
  return pairs;
}

struct Vertex {
  double x, y, z, bulge;
};

/// One entity of the ENTITIES section: what the scan saw and what libdxflib delivered.
struct RawEntity {
  std::string type, handle, layer = "0";
  std::size_t line = 0;  // line of its group 0
  // group counts from the scan (checked against the counts libdxflib sizes its arrays with)
  long n10 = 0, n11 = 0, n40 = 0, n41 = 0;
  long g72 = -1, g73 = -1, g74 = -1, g90 = -1;
  // geometry from libdxflib callbacks
  bool delivered = false;
  std::array<double, 9> v{};  // LINE x1 y1 z1 x2 y2 z2; ARC cx cy cz r a1 a2; CIRCLE cx cy cz r; ELLIPSE c M ratio t0 t1
  std::array<double, 3> extrusion{{0, 0, 1}};
  int flags = 0, degree = 0;
  std::vector<Vertex> vertices;
  std::vector<double> knots;
  std::vector<std::array<double, 4>> control;  // x y z w

  std::string label() const { return type + " " + (handle.empty() ? "(no handle, line " + std::to_string(line) + ")" : handle); }
};

class Collector : public DL_CreationAdapter {
 public:
  Collector(std::string file, std::size_t pairs) : file_(std::move(file)), pairs_(pairs) {}

  std::vector<RawEntity> entities;
  bool has_insunits = false;
  int insunits = 0;

  void processCodeValuePair(unsigned int code, const std::string& value) override {
    ++pair_;
    const std::size_t line = 2 * pair_ - 1;
    if (code == 0) {
      entity_type_ = trim(value);
      return entity_start(entity_type_, line);
    }
    // (In ENTITIES count_value checks them too, naming the entity by its handle.)
    if (section_ != "ENTITIES" && sizes_an_array(entity_type_, code)) bounded_count(code, value, line);
    if (code == 2 && expect_section_name_) {
      section_ = trim(value);
      expect_section_name_ = false;
      return;
    }
    if (section_ == "HEADER") {
      if (code == 9) header_variable_ = trim(value);
      if (header_variable_ == "$INSUNITS" && code == 70) {
        long u = 0;
        if (!parse_long(value, u)) throw InputError(file_, "line " + std::to_string(line + 1), "$INSUNITS \"" + value + "\" is not an integer");
      }
      return;
    }
    if (section_ != "ENTITIES" || current_ < 0) return;
    RawEntity& e = entities[static_cast<std::size_t>(current_)];
    if ((real_code(code) && !parse_real(value)) || (int_code(code) && !parse_long(value, dummy_)))
      throw InputError(file_, "line " + std::to_string(line + 1),
                       e.label() + ": group " + std::to_string(code) + " value \"" + trim(value).substr(0, 40) + "\" is not " +
                           (real_code(code) ? "a finite number" : "an integer"));
    if (in_sequence_) return;  // VERTEX, ATTRIB, SEQEND of a POLYLINE or INSERT: libdxflib reports them
    // libdxflib stores an LWPOLYLINE's vertices and bulges in an array sized by group 90 and indexed from the
    // last group 10: a vertex before the count, or a bulge before the first vertex, would be written outside it.
    if (e.type == "LWPOLYLINE" && (code == 10 || code == 42) && (e.g90 < 0 || (code == 42 && e.n10 == 0)))
      throw InputError(file_, "line " + std::to_string(line), e.label() + ": group " + std::to_string(code) +
                                                                  (code == 10 ? " (vertex) before the vertex count (group 90)"
                                                                              : " (bulge) before the first vertex (group 10)"));
    switch (code) {
      case 5: e.handle = trim(value); break;
      case 8: e.layer = trim(value); break;
      case 10: ++e.n10; break;
      case 11: ++e.n11; break;
      case 40: ++e.n40; break;
      case 41: ++e.n41; break;
      case 72: e.g72 = count_value(e, code, value, line); break;
      case 73: e.g73 = count_value(e, code, value, line); break;
      case 74: e.g74 = count_value(e, code, value, line); break;
      case 90: e.g90 = count_value(e, code, value, line); break;
      case 76: if (e.type == "LEADER") count_value(e, code, value, line); break;  // libdxflib: new double[3 n]
      default: break;
    }
  }

  void setVariableInt(const std::string& key, int value, int) override {
    if (key == "$INSUNITS") {
      has_insunits = true;
      insunits = value;
    }
  }

  void addLine(const DL_LineData& d) override {
    if (RawEntity* e = target()) e->v = {d.x1, d.y1, d.z1, d.x2, d.y2, d.z2, 0, 0, 0};
  }
  void addArc(const DL_ArcData& d) override {
    if (RawEntity* e = target()) e->v = {d.cx, d.cy, d.cz, d.radius, d.angle1, d.angle2, 0, 0, 0};
  }
  void addCircle(const DL_CircleData& d) override {
    if (RawEntity* e = target()) e->v = {d.cx, d.cy, d.cz, d.radius, 0, 0, 0, 0, 0};
  }
  void addEllipse(const DL_EllipseData& d) override {
    if (RawEntity* e = target()) e->v = {d.cx, d.cy, d.cz, d.mx, d.my, d.mz, d.ratio, d.angle1, d.angle2};
  }
  void addPolyline(const DL_PolylineData& d) override {
    if (RawEntity* e = target()) e->flags = d.flags;
  }
  void addVertex(const DL_VertexData& d) override {
    if (RawEntity* e = target()) e->vertices.push_back({d.x, d.y, d.z, d.bulge});
  }
  void addSpline(const DL_SplineData& d) override {
    if (RawEntity* e = target()) {
      e->degree = static_cast<int>(d.degree);
      e->flags = d.flags;
    }
  }
  void addControlPoint(const DL_ControlPointData& d) override {
    if (RawEntity* e = target()) e->control.push_back({d.x, d.y, d.z, d.w});
  }
  void addKnot(const DL_KnotData& d) override {
    if (RawEntity* e = target()) e->knots.push_back(d.k);
  }

 private:
  /// The entity a callback belongs to: the one whose end (the next group 0) libdxflib is processing, when it
  /// lies in the ENTITIES section; records that its geometry arrived and the extrusion libdxflib set for it.
  RawEntity* target() {
    if (target_ < 0) return nullptr;
    RawEntity& e = entities[static_cast<std::size_t>(target_)];
    e.delivered = true;
    const double* dir = getExtrusion()->getDirection();
    e.extrusion = {dir[0], dir[1], dir[2]};
    return &e;
  }

  /// Groups from which libdxflib sizes an array (new double[k * count]) for the entity it is reading, in any
  /// section: ENTITIES, BLOCKS or one it does not know (fuzz_dxf: a SPLINE in a misspelt section with
  /// 1056964608 fit points overflowed the size).
  static bool sizes_an_array(const std::string& type, unsigned code) {
    return (type == "LWPOLYLINE" && code == 90) || (type == "SPLINE" && (code == 72 || code == 73 || code == 74)) ||
           (type == "LEADER" && code == 76);
  }

  /// Such a count must be an integer between 0 and the number of groups in the file.
  void bounded_count(unsigned code, const std::string& value, std::size_t line) const {
    long n = 0;
    if (!parse_long(value, n) || n < 0 || static_cast<std::size_t>(n) > pairs_)
      throw InputError(file_, "line " + std::to_string(line + 1),
                       entity_type_ + ": group " + std::to_string(code) + " count \"" + trim(value).substr(0, 40) +
                           "\" is impossible (not an integer from 0 to the file's " + std::to_string(pairs_) + " groups)");
  }

  long count_value(const RawEntity& e, unsigned code, const std::string& value, std::size_t line) {
    long n = 0;
    parse_long(value, n);
    if (n < 0 || static_cast<std::size_t>(n) > pairs_)
      throw InputError(file_, "line " + std::to_string(line + 1),
                       e.label() + ": group " + std::to_string(code) + " count " + std::to_string(n) +
                           " is impossible (negative or more than the file's " + std::to_string(pairs_) + " groups)");
    return n;
  }

  void entity_start(const std::string& type, std::size_t line) {
    target_ = -1;
    if (section_ == "ENTITIES" && current_ >= 0) {
      const RawEntity& e = entities[static_cast<std::size_t>(current_)];
      const bool owner = e.type == "POLYLINE" || e.type == "INSERT";
      if (owner && (type == "VERTEX" || type == "ATTRIB" || type == "SEQEND")) {
        target_ = current_;  // libdxflib completes the POLYLINE or the previous VERTEX now
        in_sequence_ = true;
        return;
      }
      check_counts(e);
      target_ = current_;
      current_ = -1;
      in_sequence_ = false;
    }
    if (type == "SECTION") {
      expect_section_name_ = true;
      section_.clear();
    } else if (type == "ENDSEC") {
      section_.clear();
    } else if (section_ == "ENTITIES") {
      RawEntity e;
      e.type = type;
      e.line = line;
      entities.push_back(e);
      current_ = static_cast<long>(entities.size()) - 1;
    }
  }

  /// The counts libdxflib sizes its arrays with must match the groups that follow (it keeps a missing count
  /// from the previous entity and drops or zero-fills the difference).
  void check_counts(const RawEntity& e) const {
    auto fail = [&](const std::string& what) { throw InputError(file_, "line " + std::to_string(e.line), e.label() + ": " + what); };
    auto declared = [](long g) { return g < 0 ? std::string("no count") : "a count of " + std::to_string(g); };
    if (e.type == "LWPOLYLINE" && e.g90 != e.n10)
      fail("group 90 gives " + declared(e.g90) + " vertices but " + std::to_string(e.n10) + " vertices (group 10) follow");
    if (e.type == "SPLINE") {
      if (e.g72 != e.n40) fail("group 72 gives " + declared(e.g72) + " knots but " + std::to_string(e.n40) + " knots (group 40) follow");
      if (e.g73 != e.n10 && !(e.g73 < 0 && e.n10 == 0))
        fail("group 73 gives " + declared(e.g73) + " control points but " + std::to_string(e.n10) + " (group 10) follow");
      if (e.n41 != 0 && e.n41 != e.n10)
        fail(std::to_string(e.n41) + " weights (group 41) for " + std::to_string(e.n10) + " control points; give one per point or none");
      if (e.g74 >= 0 && e.g74 != e.n11)
        fail("group 74 gives " + declared(e.g74) + " fit points but " + std::to_string(e.n11) + " (group 11) follow");
    }
  }

  std::string file_;
  std::size_t pairs_, pair_ = 0;
  std::string section_, header_variable_, entity_type_;  // entity_type_: of the last group 0, any section
  bool expect_section_name_ = false, in_sequence_ = false;
  long current_ = -1, target_ = -1, dummy_ = 0;
};

// ---- conversion of one entity ------------------------------------------------------------------------------

struct Piece {
  std::string label;
  std::vector<Segment> segments;
  bool closed = false;  // closed on its own (CIRCLE, full ELLIPSE, closed polyline or SPLINE)
};

Segment reversed(Segment s) {
  std::reverse(s.points.begin(), s.points.end());
  std::reverse(s.weights.begin(), s.weights.end());
  return s;
}

/// The unit circle arc from t0 to t1 (radians), exact rational quadratics, mapped by p -> c + p.x M + p.y m.
std::vector<Segment> affine_arc(double t0, double t1, const V& c, const V& M, const V& m) {
  std::vector<Segment> segs = BezierPath<double>::circle_arc(V(0, 0), 1.0, t0, t1).segments();
  for (Segment& s : segs)
    for (V& p : s.points) p = c + p.x() * M + p.y() * m;
  return segs;
}

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

class Converter {
 public:
  explicit Converter(std::string file) : file_(std::move(file)) {}

  Piece convert(const RawEntity& e) const {
    Piece piece;
    piece.label = e.label();
    check_extrusion(e);
    if (e.type == "LINE") line(e, piece);
    else if (e.type == "ARC" || e.type == "CIRCLE") arc(e, piece);
    else if (e.type == "ELLIPSE") ellipse(e, piece);
    else if (e.type == "LWPOLYLINE" || e.type == "POLYLINE") polyline(e, piece);
    else if (e.type == "SPLINE") spline(e, piece);
    if (piece.segments.empty()) fail(e, "has no extent (zero length)");
    return piece;
  }

 private:
  [[noreturn]] void fail(const RawEntity& e, const std::string& what) const {
    throw InputError(file_, "line " + std::to_string(e.line), e.label() + " " + what);
  }

  bool mirrored(const RawEntity& e) const { return e.extrusion[2] < 0; }

  void check_extrusion(const RawEntity& e) const {
    const auto& n = e.extrusion;
    if (!(n[0] == 0 && n[1] == 0 && std::abs(n[2]) == 1))
      fail(e, "has extrusion direction (" + number(n[0]) + ", " + number(n[1]) + ", " + number(n[2]) +
                  "): only drawings in the XY plane, extrusion (0, 0, 1) or (0, 0, -1), are read");
  }

  /// OCS to WCS for extrusion (0, 0, -1): the arbitrary axis algorithm gives Ax = (-1, 0, 0), Ay = (0, 1, 0).
  V ocs(const RawEntity& e, double x, double y) const { return mirrored(e) ? V(-x, y) : V(x, y); }

  void line(const RawEntity& e, Piece& piece) const {
    if (e.v[2] != e.v[5]) fail(e, "is not parallel to the XY plane (z " + number(e.v[2]) + " and " + number(e.v[5]) + ")");
    const V a(e.v[0], e.v[1]), b(e.v[3], e.v[4]);
    if (a == b) fail(e, "has zero length");
    piece.segments.push_back({{a, b}, {}});
  }

  void arc(const RawEntity& e, Piece& piece) const {
    const double r = e.v[3];
    if (!(r > 0)) fail(e, "has radius " + number(r) + "; it must be positive");
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
    if (e.v[5] != 0) fail(e, "has a major axis out of the XY plane (z component " + number(e.v[5]) + ")");
    if (!(M.norm() > 0)) fail(e, "has a zero major axis");
    if (!(ratio > 0 && ratio <= 1)) fail(e, "has axis ratio " + number(ratio) + "; it must be in (0, 1]");
    // Minor axis: ratio (N x M), N the extrusion (0, 0, +-1).
    const V m = mirrored(e) ? V(ratio * M.y(), -ratio * M.x()) : V(-ratio * M.y(), ratio * M.x());
    const double t0 = std::fmod(e.v[7], 2 * M_PI);
    const double sweep = ccw_sweep(e.v[7], e.v[8], 2 * M_PI);
    piece.segments = affine_arc(t0, t0 + (full_turn(sweep) ? 2 * M_PI : sweep), c, M, m);
    piece.closed = full_turn(sweep);
  }

  /// Bulge b from a to b_: arc of included angle 4 atan(b) (counter-clockwise for b > 0), centre on the chord's
  /// perpendicular bisector at (1 - b^2) / (4 b) chord lengths to its left.
  std::vector<Segment> bulge_arc(const V& a, const V& b_, double bulge) const {
    const double angle = 4 * std::atan(bulge);
    const V center = (a + b_) / 2 + perp(V(b_ - a)) * ((1 - bulge * bulge) / (4 * bulge));
    const double r = (a - center).norm(), t0 = std::atan2(a.y() - center.y(), a.x() - center.x());
    if (!std::isfinite(r) || !std::isfinite(center.x()) || !std::isfinite(center.y()))
      throw std::range_error("bulge " + number(bulge) + " gives no finite arc");
    std::vector<Segment> segs = affine_arc(t0, t0 + angle, center, V(r, 0), V(0, r));
    segs.front().points.front() = a;  // the vertices are the data: keep them exact
    segs.back().points.back() = b_;
    return segs;
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
    for (std::size_t i = 0; i < pieces; ++i) {
      const Vertex& v = vs[i];
      const Vertex& w = vs[(i + 1) % n];
      const V a = three_d ? V(v.x, v.y) : ocs(e, v.x, v.y), b = three_d ? V(w.x, w.y) : ocs(e, w.x, w.y);
      // Mirroring the OCS x axis reverses the sense of rotation, hence the bulge's sign.
      const double bulge = three_d ? 0.0 : (mirrored(e) ? -v.bulge : v.bulge);
      if (!std::isfinite(bulge)) fail(e, "has a bulge that is not finite at vertex " + std::to_string(i));
      if (bulge == 0) {
        piece.segments.push_back({{a, b}, {}});
      } else {
        std::vector<Segment> arc;
        try {
          arc = bulge_arc(a, b, bulge);
        } catch (const std::range_error& ex) {
          fail(e, std::string("at vertex ") + std::to_string(i) + ": " + ex.what());
        }
        for (Segment& s : arc) piece.segments.push_back(std::move(s));
      }
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
    try {
      piece.segments = nurbs_to_bezier(c).segments;
    } catch (const std::invalid_argument& ex) {
      fail(e, std::string("is not a valid NURBS curve: ") + ex.what());
    }
    piece.closed = (e.flags & 1) != 0;
  }

  std::string file_;
};

// ---- chaining ------------------------------------------------------------------------------------------------

struct Chain {
  std::vector<Segment> segments;
  std::vector<std::size_t> owner;  // piece index of each segment
  bool closed = false;
};

class Chainer {
 public:
  Chainer(std::string file, const std::vector<Piece>& pieces) : file_(std::move(file)), pieces_(pieces) {
    V lo = pieces[0].segments[0].points[0], hi = lo;
    for (const Piece& p : pieces)
      for (const Segment& s : p.segments)
        for (const V& q : s.points) {
          lo = lo.cwiseMin(q);
          hi = hi.cwiseMax(q);
        }
    size_ = (hi - lo).norm();
    tol_ = kDxfJoinTolerance * size_;
    for (const Piece& p : pieces)
      for (const Segment& s : p.segments) {
        double reach = 0;
        for (const V& q : s.points) reach = std::max(reach, (q - s.points.front()).norm());
        if (!(reach > tol_))
          fail(p.label + " has a piece at " + point_text(s.points.front()) + " no longer than the join tolerance (" +
               tolerance_text() + "): nearly repeated vertices or a vanishing arc");
      }
  }

  double size() const { return size_; }

  Chain chain() {
    Chain c;
    for (std::size_t k = 0; k < pieces_.size(); ++k) {
      const Piece& p = pieces_[k];
      if (p.closed && pieces_.size() > 1)
        fail(p.label + " is closed on its own but is not the only entity selected (" + std::to_string(pieces_.size()) +
             " are); a contour is one chain: select it alone (by handle) or move the others to another layer");
      const V s = p.segments.front().points.front(), e = p.segments.back().points.back();
      if (k == 0) {
        append(c, k, false);
        joints_.push_back({s, "the chain's start (the start of " + p.label + ")"});
      } else {
        const V end = c.segments.back().points.back();
        if (c.closed) leftover(c, k);
        if ((s - end).norm() <= tol_) append(c, k, false);
        else if ((e - end).norm() <= tol_) append(c, k, true);
        else not_at_end(c, k, end);
      }
      const V end = c.segments.back().points.back();
      const V start = c.segments.front().points.front();
      if ((end - start).norm() <= tol_) {
        c.segments.back().points.back() = start;
        c.closed = true;
      }
    }
    if (pieces_.size() == 1 && pieces_[0].closed && !c.closed)
      fail(pieces_[0].label + " is flagged closed but ends at " + point_text(c.segments.back().points.back()) +
           ", not at its start " + point_text(c.segments.front().points.front()) +
           " (for a periodic SPLINE, rollkin needs the wrapped control points)");
    return c;
  }

 private:
  struct Joint {
    V point;
    std::string what;
  };

  [[noreturn]] void fail(const std::string& message) const { throw InputError(file_, "", message); }

  std::string tolerance_text() const {
    return "tolerance " + number(tol_) + " = " + number(kDxfJoinTolerance) + " x drawing size " + number(size_);
  }

  void append(Chain& c, std::size_t k, bool reverse) {
    const Piece& p = pieces_[k];
    const std::size_t first = c.segments.size();
    if (!reverse) {
      for (const Segment& s : p.segments) c.segments.push_back(s);
    } else {
      for (auto it = p.segments.rbegin(); it != p.segments.rend(); ++it) c.segments.push_back(reversed(*it));
    }
    c.owner.resize(c.segments.size(), k);
    if (first > 0) {
      c.segments[first].points.front() = c.segments[first - 1].points.back();  // snap the joint
      joints_.push_back({c.segments[first].points.front(), "where " + pieces_[c.owner[first - 1]].label + " and " + p.label + " meet"});
    }
  }

  /// Entity k meets neither end... of the chain's end: a branch if it touches the chain elsewhere, else a gap.
  [[noreturn]] void not_at_end(const Chain& c, std::size_t k, const V& end) const {
    const Piece& p = pieces_[k];
    const V s = p.segments.front().points.front(), e = p.segments.back().points.back();
    for (const Joint& j : joints_)
      for (const V& q : {s, e})
        if ((q - j.point).norm() <= tol_)
          fail(p.label + " meets the chain at " + point_text(q) + ", " + j.what + ", not at the chain's end " + point_text(end) +
               " (the end of " + pieces_[c.owner.back()].label + "): a branch or an entity out of order; a contour is one "
               "chain, its entities listed in order along it");
    const bool start_nearer = (s - end).norm() <= (e - end).norm();
    const V near = start_nearer ? s : e;
    fail("gap of " + number((near - end).norm()) + " between the end of " + pieces_[c.owner.back()].label + " at " +
         point_text(end) + " and " + p.label + " (its nearer end at " + point_text(near) + "); " + tolerance_text() +
         "; entities are chained end to end in file order");
  }

  [[noreturn]] void leftover(const Chain& c, std::size_t k) const {
    const Piece& p = pieces_[k];
    fail("the chain closed at " + point_text(c.segments.front().points.front()) + " with " + pieces_[c.owner.back()].label +
         ", but " + p.label + " follows (a branch, or a second contour on the layer); a contour is one chain");
  }

  std::string file_;
  const std::vector<Piece>& pieces_;
  std::vector<Joint> joints_;
  double size_ = 0, tol_ = 0;
};

// ---- units and selection -------------------------------------------------------------------------------------

void set_units(DxfContour& out, const Collector& collector, const std::string& file) {
  out.insunits = collector.has_insunits ? collector.insunits : 0;
  switch (out.insunits) {
    case 0: out.unit = ""; out.metres_per_unit = 0; break;
    case 1: out.unit = "in"; out.metres_per_unit = 0.0254; break;
    case 2: out.unit = "ft"; out.metres_per_unit = 0.3048; break;
    case 4: out.unit = "mm"; out.metres_per_unit = 0.001; break;
    case 5: out.unit = "cm"; out.metres_per_unit = 0.01; break;
    case 6: out.unit = "m"; out.metres_per_unit = 1; break;
    default:
      throw InputError(file, "$INSUNITS",
                       "drawing unit code " + std::to_string(out.insunits) +
                           " is not supported; use 0 (unitless), 1 (in), 2 (ft), 4 (mm), 5 (cm) or 6 (m)");
  }
}

const char* kSupported = "LINE, ARC, CIRCLE, ELLIPSE, LWPOLYLINE, POLYLINE, SPLINE";

bool supported(const std::string& type) {
  for (const char* t : {"LINE", "ARC", "CIRCLE", "ELLIPSE", "LWPOLYLINE", "POLYLINE", "SPLINE"})
    if (type == t) return true;
  return false;
}

std::vector<const RawEntity*> select(const std::vector<RawEntity>& all, const DxfSelection& sel, const std::string& file) {
  if (sel.layer.empty() == sel.handle.empty())
    throw InputError(file, "", "select the contour by a layer name or by an entity handle (exactly one of the two)");
  std::vector<const RawEntity*> chosen;
  for (const RawEntity& e : all)
    if (sel.layer.empty() ? upper(e.handle) == upper(sel.handle) : upper(e.layer) == upper(sel.layer)) chosen.push_back(&e);
  if (chosen.empty()) {
    std::vector<std::string> layers;
    for (const RawEntity& e : all)
      if (std::find(layers.begin(), layers.end(), e.layer) == layers.end()) layers.push_back(e.layer);
    std::string known;
    for (std::size_t i = 0; i < layers.size() && i < 20; ++i) known += (i ? ", \"" : "\"") + layers[i] + "\"";
    throw InputError(file, "",
                     sel.layer.empty() ? "no entity with handle " + sel.handle + " in the ENTITIES section"
                                       : "no entity on layer \"" + sel.layer + "\" in the ENTITIES section (layers with entities: " +
                                             (known.empty() ? "none" : known) + ")");
  }
  std::string unsupported;
  for (const RawEntity* e : chosen)
    if (!supported(e->type) || !e->delivered)
      unsupported += (unsupported.empty() ? "" : ", ") + e->label() + " (line " + std::to_string(e->line) + ")";
  if (!unsupported.empty())
    throw InputError(file, sel.layer.empty() ? "handle " + sel.handle : "layer \"" + sel.layer + "\"",
                     "unsupported entities: " + unsupported + "; a contour is made of " + kSupported +
                         " (explode blocks, and move text, hatches and dimensions to another layer)");
  return chosen;
}

std::string describe(const DxfContour& out, const DxfSelection& sel, const std::string& file) {
  std::ostringstream os;
  os << "DXF " << (file.empty() ? std::string("<text>") : file) << " "
     << (sel.layer.empty() ? "handle " + sel.handle : "layer \"" + sel.layer + "\"") << ": " << out.entities.size()
     << (out.entities.size() == 1 ? " entity (" : " entities (");
  for (std::size_t i = 0; i < out.entities.size() && i < 4; ++i) os << (i ? ", " : "") << out.entities[i];
  if (out.entities.size() > 4) os << ", ...";
  os << "), " << out.segments.size() << " segments, " << (out.closed ? "closed" : "open") << ", " << out.corners.size()
     << (out.corners.size() == 1 ? " corner, " : " corners, ")
     << (out.unit.empty() ? std::string("unitless") : "unit " + out.unit + " (" + number(out.metres_per_unit) + " m)");
  return os.str();
}

}  // namespace

namespace {

/// A private temporary copy of a text, removed when it goes out of scope.
class TempFile {
 public:
  explicit TempFile(const std::string& text) {
    std::string pattern = (std::filesystem::temp_directory_path() / "rollkin-dxf-XXXXXX").string();
    const int fd = mkstemp(pattern.data());
    if (fd < 0) throw std::runtime_error("cannot create a temporary file for the DXF text in " + pattern);
    path_ = pattern;
    std::size_t done = 0;
    while (done < text.size()) {
      const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
      if (n <= 0) break;
      done += static_cast<std::size_t>(n);
    }
    ::close(fd);
    if (done != text.size()) {
      std::remove(path_.c_str());
      throw std::runtime_error("cannot write the temporary copy " + path_ + " of the DXF text");
    }
  }
  ~TempFile() { std::remove(path_.c_str()); }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

/// Runs the collector's checks over the group pairs of `text` as libdxflib will deliver them (a code line and
/// a value line per group, up to group 0 "EOF"), before libdxflib reads it. The checks must not fire while
/// libdxflib reads: an exception thrown through DL_Dxf::in leaves its FILE open (fuzz_dxf ran out of file
/// descriptors after some 10^5 rejected inputs), so every input error is found here first.
void check_groups_before_reading(const std::string& text, Collector& dry) {
  std::size_t pos = 0;
  auto next_line = [&](std::string& line) {
    if (pos >= text.size()) return false;
    std::size_t eol = text.find('\n', pos);
    if (eol == std::string::npos) eol = text.size();
    line = text.substr(pos, eol - pos);
    pos = eol + 1;
    return true;
  };
  std::string code_line, value;
  while (next_line(code_line) && next_line(value)) {
    long code = 0;
    if (!parse_long(code_line, code)) return;  // only a trailing blank line (check_group_structure)
    dry.processCodeValuePair(static_cast<unsigned>(code), value);
    if (code == 0 && trim(value) == "EOF") return;
  }
}

/// `text` is the content of the file at `disk_path`, which libdxflib reads (its FILE* reader is the one that
/// calls processCodeValuePair; its istream reader, in libdxflib 3.26, does not).
DxfContour contour_from(const std::string& text, const std::string& disk_path, const DxfSelection& selection,
                        const std::string& file) {
  const std::size_t pairs = check_group_structure(text, file);
  {
    Collector dry(file, pairs);
    check_groups_before_reading(text, dry);
  }
  Collector collector(file, pairs);
  {
    DL_Dxf reader;
    if (!reader.in(disk_path, &collector)) throw InputError(file, "", "libdxflib could not open the DXF file");
  }
  DxfContour out;
  set_units(out, collector, file);
  const std::vector<const RawEntity*> chosen = select(collector.entities, selection, file);

  const Converter converter(file);
  std::vector<Piece> pieces;
  for (const RawEntity* e : chosen) pieces.push_back(converter.convert(*e));
  Chainer chainer(file, pieces);
  Chain chain = chainer.chain();
  out.segments = std::move(chain.segments);
  out.closed = chain.closed;
  for (std::size_t i = 0; i < chain.owner.size(); ++i)
    if (i == 0 || chain.owner[i] != chain.owner[i - 1]) out.entities.push_back(pieces[chain.owner[i]].label);

  const std::size_t n = out.segments.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t before = chain.owner[(i + n - 1) % n], after = chain.owner[i];
    out.joint_entities.push_back(before == after ? pieces[after].label : pieces[before].label + " / " + pieces[after].label);
  }
  const BezierPathOptions<double> options;
  for (const PathCorner<double>& k : path_corners(out.segments, out.closed, options.joint_tolerance * chainer.size(), options.corner_tolerance))
    out.corners.push_back({out.joint_entities[k.piece], k.piece, k.point, rad_to_deg(k.turn)});
  out.description = describe(out, selection, file);
  return out;
}

}  // namespace

DxfContour parse_dxf_contour(const std::string& dxf, const DxfSelection& selection, const std::string& file) {
  const TempFile copy(dxf);
  return contour_from(dxf, copy.path(), selection, file);
}

DxfContour read_dxf_contour(const std::string& path, const DxfSelection& selection) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open the DXF file");
  std::ostringstream text;
  text << in.rdbuf();
  return contour_from(text.str(), path, selection, path);
}

}  // namespace rollkin
