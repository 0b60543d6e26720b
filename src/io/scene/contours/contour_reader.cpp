// Checks shared by the contour readers (see contour_reader.hpp).
#include "contour_reader.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>

namespace rollkin::io {

namespace fs = std::filesystem;

void ContourContext::keys(const json& c, const std::string& path, std::vector<std::string> extra) const {
  static const std::vector<std::string> common = {"name", "type", "at", "material"};
  extra.insert(extra.begin(), common.begin(), common.end());
  js.object(c, path, extra);
}

std::string ContourContext::contour_file(const json& v, const std::string& path) const {
  const std::string rel = js.string(v, path, "a file name relative to the scene file");
  if (rel.empty()) js.fail(path, "expected a file name, got an empty string");
  const fs::path p = fs::path(rel).is_absolute() ? fs::path(rel) : dir_ / rel;
  files_read_.push_back(p.string());
  return p.string();
}

bool ContourContext::material(const json& c, const std::string& path, std::optional<bool> natural_inside,
                              const std::string& def) const {
  std::string side = def;
  if (const json* s = js.get(c, "material")) side = js.string(*s, child(path, "material"), "the material side");
  const std::vector<std::string> allowed = natural_inside ? std::vector<std::string>{"left", "right", "inside", "outside"}
                                                          : std::vector<std::string>{"left", "right"};
  bool known = false;
  for (const auto& a : allowed) known = known || a == side;
  if (!known)
    js.fail(child(path, "material"), "material \"" + side + "\" is not allowed for this contour; expected one of " +
                                         quoted_list(allowed) +
                                         (natural_inside ? "" : " (\"inside\"/\"outside\" need a closed contour, a disk or a parabola)"));
  if (side == "left") return false;
  if (side == "right") return true;
  const bool inside = side == "inside";
  return inside != *natural_inside;
}

ArcLengthMethod ContourContext::arc_length_method(const json& v, const std::string& path) const {
  js.object(v, path, {"method", "order", "panels"});
  ArcLengthMethod am;
  const std::string method = js.get(v, "method") ? js.string(v["method"], child(path, "method"), "an arc-length method") : "closed_form";
  if (method == "closed_form") {
    if (js.get(v, "order") || js.get(v, "panels")) js.fail(path, "\"order\" and \"panels\" apply to gauss_legendre and newton_cotes only");
    return am;
  }
  am.closed_form = false;
  if (method == "gauss_legendre") {
    am.rule.kind = Quadrature::GaussLegendre;
    am.rule.order = 8;
  } else if (method == "newton_cotes") {
    am.rule.kind = Quadrature::NewtonCotes;
    am.rule.order = 2;
  } else {
    js.fail(child(path, "method"), "unknown arc-length method \"" + method +
                                       "\"; expected \"closed_form\", \"gauss_legendre\" or \"newton_cotes\"");
  }
  if (const json* o = js.get(v, "order")) {
    const double n = js.number(*o, child(path, "order"), "the rule's order");
    const bool gl = am.rule.kind == Quadrature::GaussLegendre;
    if (n != std::floor(n) || (gl && (n < 1 || n > 64)) || (!gl && n != 2 && n != 4))
      js.fail(child(path, "order"), gl ? "expected a Gauss-Legendre order: an integer from 1 to 64, got " + format_number(n)
                                       : "expected a Newton-Cotes degree: 2 (Simpson) or 4 (Boole), got " + format_number(n));
    am.rule.order = static_cast<int>(n);
  }
  if (const json* p = js.get(v, "panels")) {
    const double n = js.number(*p, child(path, "panels"), "the number of panels");
    if (n != std::floor(n) || n < 1 || n > 100000)
      js.fail(child(path, "panels"), "expected an integer number of panels from 1 to 100000, got " + format_number(n));
    am.rule.panels = static_cast<int>(n);
  }
  return am;
}

ProfileShape<double> ContourContext::parameterised(ProfileShape<double> shape, const json& c, const std::string& path) const {
  const json* p = js.get(c, "parameter");
  if (p == nullptr) return shape;
  const std::string v = js.string(*p, child(path, "parameter"), "the contour parameter");
  static const std::vector<std::string> allowed = {"native", "arc_length"};
  if (v != "native" && v != "arc_length")
    js.fail(child(path, "parameter"), "unknown contour parameter \"" + v + "\"; expected one of " + quoted_list(allowed));
  if (v == "native") return shape;
  if (const auto* sp = std::get_if<SampledProfile<double>>(&shape)) return ArcLengthProfile<double>(*sp);
  return ArcLengthProfile<double>(std::get<BezierPath<double>>(shape));
}

double ContourContext::scale(const json& c, const std::string& path) const {
  const double s = js.number_or(c, path, "scale", 1.0, "a scale factor");
  if (!(s > 0) || !std::isfinite(s)) js.fail(child(path, "scale"), "expected a positive finite scale factor, got " + format_number(s));
  return s;
}

double ContourContext::unit_factor(double file_metres_per_unit) const {
  if (!(file_metres_per_unit > 0) || length_unit_ == LengthUnit::Unitless) return 1;
  return file_metres_per_unit / metres_per(length_unit_);
}

std::vector<Vec2<double>> control_polygon(const std::vector<BezierSegment<double>>& segments) {
  std::vector<Vec2<double>> polygon;
  for (std::size_t i = 0; i < segments.size(); ++i)
    for (std::size_t k = (i == 0 ? 0 : 1); k < segments[i].points.size(); ++k) polygon.push_back(segments[i].points[k]);
  return polygon;
}

double signed_area(const std::vector<Vec2<double>>& pts) {
  double a = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) a += cross2<double>(pts[i], pts[(i + 1) % pts.size()]);
  return a / 2;
}

namespace {

using V2 = Vec2<double>;

bool line_piece(const BezierSegment<double>& s) { return s.degree() == 1 && !s.rational(); }

/// Round-off of points: 16 eps of their largest coordinate.
double round_off(std::initializer_list<V2> points) {
  double m = 0;
  for (const V2& p : points) m = std::max(m, p.cwiseAbs().maxCoeff());
  return 16 * std::numeric_limits<double>::epsilon() * m;
}

/// Distance from p to the line through a and c.
double off_line(const V2& a, const V2& c, const V2& p) { return std::abs(cross2(V2(c - a), V2(p - a))) / (c - a).norm(); }

/// Whether b -> c continues a -> b straight on: b within round-off of the line a c, c ahead of b.
bool continues_straight(const V2& a, const V2& b, const V2& c) {
  return (b - a).dot(c - b) > 0 && off_line(a, c, b) <= round_off({a, b, c});
}

}  // namespace

std::vector<std::size_t> join_straight_runs(std::vector<BezierSegment<double>>& segments) {
  std::vector<BezierSegment<double>> joined;
  std::vector<std::size_t> first;
  const std::size_t n = segments.size();
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i;  // the run is pieces i .. j
    if (line_piece(segments[i]))
      while (j + 1 < n && line_piece(segments[j + 1]) &&
             continues_straight(segments[j].points[0], segments[j].points[1], segments[j + 1].points[1]))
        ++j;
    // Each joint was checked against its neighbours; the run's joints must also lie on its chord (no drift).
    const V2 a = segments[i].points.front(), c = segments[j].points.back();
    bool straight = true;
    for (std::size_t k = i + 1; k <= j && straight; ++k) straight = off_line(a, c, segments[k].points[0]) <= round_off({a, c});
    if (j > i && straight) {
      joined.push_back({{a, c}, {}});
      first.push_back(i);
    } else {  // a drift off the chord: the pieces as drawn
      for (std::size_t k = i; k <= j; ++k) {
        joined.push_back(segments[k]);
        first.push_back(k);
      }
    }
    i = j + 1;  // each piece is looked at once or twice: linear in the pieces
  }
  segments = std::move(joined);
  return first;
}

std::vector<std::string> describe_joints(const BezierPath<double>& path, const JointDescriber& describe,
                                         const std::string& what, const ContourContext& ctx) {
  std::vector<std::string> labels;
  const std::size_t n = path.segments().size();
  std::vector<bool> corner_at(n, false);  // by piece: one pass, not a search of corners() per joint
  for (const PathCorner<double>& c : path.corners()) {
    corner_at[c.piece] = true;
    labels.push_back(describe(c.piece) + ", turning " + format_number(rad_to_deg(c.turn)) + " deg");
    ctx.note(what + ": corner " + labels.back() + " at (" + format_number(c.point.x()) + ", " + format_number(c.point.y()) +
             "): a contact stops there (status corner)");
  }
  // Tangent joints (not corners) where the signed curvature kappa = (p' x p'') / |p'|^3 jumps.
  const std::size_t joints = path.domain().closed ? n : n - 1;
  const double extent = path.total_length();
  for (std::size_t j = 0; j < joints; ++j) {
    const std::size_t next = (j + 1) % n;
    if (corner_at[next]) continue;
    const double kl = contour_point(path.segment_jet(j, 1.0, 2), 2).curvature();
    const double kr = contour_point(path.segment_jet(next, 0.0, 2), 2).curvature();
    if (!std::isfinite(kl) || !std::isfinite(kr)) continue;  // a stationary end: no curvature there
    if (std::abs(kl - kr) * extent > 1e-9 * (1 + (std::abs(kl) + std::abs(kr)) * extent))
      ctx.note(what + ": curvature jumps from " + format_number(kl) + " to " + format_number(kr) + " (1/length) at " + describe(next) +
               " (tangent continuous: a contact rolls through)");
  }
  return labels;
}

}  // namespace rollkin::io
