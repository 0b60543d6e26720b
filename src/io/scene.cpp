// Scene JSON reader (format: docs/scene_format.md). Strict: unknown keys, wrong types and dangling names
// are InputErrors naming the file, the JSON path and what is expected.
#include "rollkin/io/scene.hpp"

#include "rollkin/geometry/contact.hpp"
#include "rollkin/geometry/validation.hpp"
#include "rollkin/io/json_document.hpp"
#include "rollkin/io/point_file.hpp"
#include "rollkin/io/svg_path.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace rollkin::io {
namespace {

using json = nlohmann::ordered_json;
namespace fs = std::filesystem;

constexpr std::size_t kMinSplineSamples = 4;
constexpr double kValidationTolerance = 1e-9;
constexpr int kContactSamples = 2000;

std::string join(const std::vector<std::string>& v, const std::string& sep = ", ") {
  std::string out;
  for (std::size_t i = 0; i < v.size(); ++i) out += (i ? sep : "") + v[i];
  return out;
}

std::string quoted_list(const std::vector<std::string>& v) {
  std::vector<std::string> q;
  for (const auto& s : v) q.push_back("\"" + s + "\"");
  return q.empty() ? "(none)" : join(q);
}

std::string child(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }
std::string index(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }

std::string kind_of(const json& j) {
  switch (j.type()) {
    case json::value_t::null: return "null";
    case json::value_t::object: return "an object";
    case json::value_t::array: return "an array";
    case json::value_t::string: return "a string";
    case json::value_t::boolean: return "a boolean";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float: return "a number";
    default: return "an unsupported value";
  }
}

std::string fmt(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

struct ContactInfo {
  bool has_values = false;
};

class SceneReader {
 public:
  SceneReader(std::string file, const std::string& text) : file_(std::move(file)) {
    dir_ = fs::path(file_).parent_path();
    root_ = parse(text);
  }

  Scene read() {
    Scene scene;
    scene.file = file_;
    object(root_, "", {"units", "description", "links", "pairs", "inputs", "sweep"});
    read_units(scene);
    read_links(scene);
    read_pairs(scene);
    finalize(scene, {});
    read_inputs(scene);
    finalize(scene, scene.mechanism.drivers);
    fill_guess(scene);
    locate_missing_contacts(scene);
    read_sweep(scene);
    return scene;
  }

 private:
  // ---- JSON access ----------------------------------------------------------------------------------
  [[noreturn]] void fail(const std::string& path, const std::string& message) const {
    throw InputError(file_, path, message);
  }

  json parse(const std::string& text) {
    json j = parse_json_document(text, file_);
    if (!j.is_object()) fail("", "the scene must be a JSON object, got " + kind_of(j));
    return j;
  }

  /// Checks that j is an object with only the allowed keys.
  void object(const json& j, const std::string& path, const std::vector<std::string>& allowed) const {
    if (!j.is_object()) fail(path, "expected an object with keys " + quoted_list(allowed) + ", got " + kind_of(j));
    for (auto it = j.begin(); it != j.end(); ++it) {
      bool ok = false;
      for (const auto& a : allowed) ok = ok || a == it.key();
      if (!ok) fail(child(path, it.key()), "unknown key \"" + it.key() + "\"; allowed keys here: " + quoted_list(allowed));
    }
  }

  static const json* get(const json& obj, const std::string& key) {
    auto it = obj.find(key);
    return it == obj.end() ? nullptr : &*it;
  }

  const json& require(const json& obj, const std::string& path, const std::string& key, const std::string& what) const {
    const json* v = get(obj, key);
    if (!v) fail(path, "missing key \"" + key + "\" (" + what + ")");
    return *v;
  }

  double number(const json& v, const std::string& path, const std::string& what) const {
    if (!v.is_number()) fail(path, "expected " + what + " (a number), got " + kind_of(v));
    const double x = v.get<double>();
    if (!std::isfinite(x)) fail(path, "expected " + what + " (a finite number)");
    return x;
  }

  double number_or(const json& obj, const std::string& path, const std::string& key, double def,
                   const std::string& what) const {
    const json* v = get(obj, key);
    return v ? number(*v, child(path, key), what) : def;
  }

  std::string string(const json& v, const std::string& path, const std::string& what) const {
    if (!v.is_string()) fail(path, "expected " + what + " (a string), got " + kind_of(v));
    return v.get<std::string>();
  }

  bool boolean(const json& v, const std::string& path, const std::string& what) const {
    if (!v.is_boolean()) fail(path, "expected " + what + " (true or false), got " + kind_of(v));
    return v.get<bool>();
  }

  const json& array(const json& v, const std::string& path, const std::string& what, std::size_t size = 0) const {
    if (!v.is_array()) fail(path, "expected " + what + " (an array), got " + kind_of(v));
    if (size && v.size() != size)
      fail(path, "expected " + what + ": an array of " + std::to_string(size) + " elements, got " + std::to_string(v.size()));
    return v;
  }

  /// A name: non-empty, without '.' (names are joined with '.' into variable and contour names).
  std::string name(const json& v, const std::string& path, const std::string& what) const {
    const std::string s = string(v, path, what);
    if (s.empty()) fail(path, "expected " + what + ": a non-empty name");
    if (s.find('.') != std::string::npos)
      fail(path, "the " + what + " \"" + s + "\" contains '.'; names are joined with '.' and may not contain it");
    return s;
  }

  double angle(double file_value) const { return scene_degrees_ ? deg_to_rad(file_value) : file_value; }

  /// {"x", "y", "angle"}, all optional.
  SE2<double> frame(const json& v, const std::string& path) const {
    object(v, path, {"x", "y", "angle"});
    const double x = number_or(v, path, "x", 0, "an x coordinate");
    const double y = number_or(v, path, "y", 0, "a y coordinate");
    const double a = number_or(v, path, "angle", 0, std::string("an angle in ") + (scene_degrees_ ? "degrees" : "radians"));
    return SE2<double>(angle(a), Vec2<double>(x, y));
  }

  Vec2<double> point(const json& v, const std::string& path) const {
    array(v, path, "a point [x, y]", 2);
    return Vec2<double>(number(v[0], index(path, 0), "x"), number(v[1], index(path, 1), "y"));
  }

  std::vector<Vec2<double>> points(const json& v, const std::string& path) const {
    array(v, path, "a list of points [[x, y], ...]");
    std::vector<Vec2<double>> out;
    for (std::size_t i = 0; i < v.size(); ++i) out.push_back(point(v[i], index(path, i)));
    return out;
  }

  /// A contour file path, relative to the scene file's directory.
  std::string contour_file(const json& v, const std::string& path, Scene& scene) const {
    const std::string rel = string(v, path, "a file name relative to the scene file");
    if (rel.empty()) fail(path, "expected a file name, got an empty string");
    const fs::path p = fs::path(rel).is_absolute() ? fs::path(rel) : dir_ / rel;
    scene.files_read.push_back(p.string());
    return p.string();
  }

  // ---- sections -------------------------------------------------------------------------------------
  void read_units(Scene& scene) {
    const json* u = get(root_, "units");
    if (!u) return;
    object(*u, "units", {"length", "angle"});
    if (const json* l = get(*u, "length")) scene.length_unit = string(*l, "units.length", "a length unit label such as \"m\" or \"mm\"");
    if (const json* a = get(*u, "angle")) {
      const std::string s = string(*a, "units.angle", "the angle unit \"deg\" or \"rad\"");
      if (s != "deg" && s != "rad") fail("units.angle", "unknown angle unit \"" + s + "\"; expected \"deg\" or \"rad\"");
      scene_degrees_ = s == "deg";
    }
    scene.degrees = scene_degrees_;
  }

  void read_links(Scene& scene) {
    Mechanism<double>& m = scene.mechanism;
    const json& links = array(require(root_, "", "links", "the list of links"), "links", "the list of links");
    if (links.size() < 2) fail("links", "expected at least two links (a ground and a moving link), got " + std::to_string(links.size()));
    int ground = -1;
    for (std::size_t i = 0; i < links.size(); ++i) {
      const std::string path = index("links", i);
      const json& l = links[i];
      object(l, path, {"name", "ground", "contours"});
      const std::string nm = name(require(l, path, "name", "the link's name"), child(path, "name"), "link name");
      if (m.find_link(nm) >= 0) fail(child(path, "name"), "duplicate link name \"" + nm + "\"; link names must be unique");
      m.links.push_back(Link{nm});
      if (const json* g = get(l, "ground"); g && boolean(*g, child(path, "ground"), "whether this is the ground link")) {
        if (ground >= 0)
          fail(child(path, "ground"), "link \"" + nm + "\" is marked ground but \"" + m.links[ground].name +
                                          "\" already is; expected exactly one ground link");
        ground = static_cast<int>(i);
      }
      if (const json* cs = get(l, "contours")) {
        array(*cs, child(path, "contours"), "the link's contours");
        std::set<std::string> names;
        for (std::size_t k = 0; k < cs->size(); ++k) {
          const std::string cpath = index(child(path, "contours"), k);
          read_contour((*cs)[k], cpath, static_cast<int>(i), nm, names, scene);
        }
      }
    }
    if (ground < 0) fail("links", "no ground link; mark exactly one link with \"ground\": true");
    m.ground = ground;
  }

  ArcLengthMethod arc_length_method(const json& v, const std::string& path) const {
    object(v, path, {"method", "order", "panels"});
    ArcLengthMethod am;
    const std::string method = get(v, "method") ? string(v["method"], child(path, "method"), "an arc-length method") : "closed_form";
    if (method == "closed_form") {
      if (get(v, "order") || get(v, "panels")) fail(path, "\"order\" and \"panels\" apply to gauss_legendre and newton_cotes only");
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
      fail(child(path, "method"), "unknown arc-length method \"" + method +
                                      "\"; expected \"closed_form\", \"gauss_legendre\" or \"newton_cotes\"");
    }
    if (const json* o = get(v, "order")) {
      const double n = number(*o, child(path, "order"), "the rule's order");
      const bool gl = am.rule.kind == Quadrature::GaussLegendre;
      if (n != std::floor(n) || (gl && (n < 1 || n > 64)) || (!gl && n != 2 && n != 4))
        fail(child(path, "order"), gl ? "expected a Gauss-Legendre order: an integer from 1 to 64, got " + fmt(n)
                                      : "expected a Newton-Cotes degree: 2 (Simpson) or 4 (Boole), got " + fmt(n));
      am.rule.order = static_cast<int>(n);
    }
    if (const json* p = get(v, "panels")) {
      const double n = number(*p, child(path, "panels"), "the number of panels");
      if (n != std::floor(n) || n < 1 || n > 100000) fail(child(path, "panels"), "expected an integer number of panels from 1 to 100000, got " + fmt(n));
      am.rule.panels = static_cast<int>(n);
    }
    return am;
  }

  /// Signed area of the polygon through pts (shoelace), > 0 counter-clockwise.
  static double signed_area(const std::vector<Vec2<double>>& pts) {
    double a = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) a += cross2<double>(pts[i], pts[(i + 1) % pts.size()]);
    return a / 2;
  }

  /// Material side -> reversed. natural_inside: whether the profile's natural direction has "inside" on the
  /// left (nullopt: "inside"/"outside" are not defined for this contour).
  bool material(const json& c, const std::string& path, std::optional<bool> natural_inside, const std::string& def) const {
    std::string side = def;
    if (const json* s = get(c, "material")) side = string(*s, child(path, "material"), "the material side");
    const std::vector<std::string> allowed = natural_inside ? std::vector<std::string>{"left", "right", "inside", "outside"}
                                                            : std::vector<std::string>{"left", "right"};
    bool known = false;
    for (const auto& a : allowed) known = known || a == side;
    if (!known)
      fail(child(path, "material"), "material \"" + side + "\" is not allowed for this contour; expected one of " + quoted_list(allowed) +
                                        (natural_inside ? "" : " (\"inside\"/\"outside\" need a closed contour, a disk or a parabola)"));
    if (side == "left") return false;
    if (side == "right") return true;
    const bool inside = side == "inside";
    return inside != *natural_inside;
  }

  /// "parameter" of a sampled or Bezier/SVG contour: "native" (default: chord length, segment parameter) or
  /// "arc_length" (the profile re-parameterised by arc length, ArcLengthProfile). Returns true for arc length.
  bool arc_length_parameter(const json& c, const std::string& path) const {
    const json* p = get(c, "parameter");
    if (p == nullptr) return false;
    const std::string v = string(*p, child(path, "parameter"), "the contour parameter");
    static const std::vector<std::string> allowed = {"native", "arc_length"};
    if (v != "native" && v != "arc_length")
      fail(child(path, "parameter"), "unknown contour parameter \"" + v + "\"; expected one of " + quoted_list(allowed));
    return v == "arc_length";
  }

  void read_contour(const json& c, const std::string& path, int link, const std::string& link_name,
                    std::set<std::string>& names, Scene& scene) {
    if (!c.is_object()) fail(path, "expected a contour object, got " + kind_of(c));
    const std::string type = string(require(c, path, "type", "the contour type"), child(path, "type"), "the contour type");
    const std::vector<std::string> common = {"name", "type", "at", "material"};
    auto keys = [&](std::vector<std::string> extra) {
      extra.insert(extra.begin(), common.begin(), common.end());
      object(c, path, extra);
    };
    static const std::vector<std::string> types = {"line", "circle", "parabola", "ellipse", "samples", "bezier", "svg"};
    bool known = false;
    for (const auto& t : types) known = known || t == type;
    if (!known) fail(child(path, "type"), "unknown contour type \"" + type + "\"; expected one of " + quoted_list(types));

    std::optional<ProfileShape<double>> shape;
    bool reversed = false;
    if (type == "line") {
      keys({"from", "to"});
      const double lo = number(require(c, path, "from", "start of the line along the contour frame's x"), child(path, "from"), "a length");
      const double hi = number(require(c, path, "to", "end of the line along the contour frame's x"), child(path, "to"), "a length");
      if (!(hi > lo)) fail(path, "contour too short: the line runs from " + fmt(lo) + " to " + fmt(hi) + "; expected \"to\" > \"from\" (a domain of non-zero length)");
      shape = Line<double>(lo, hi);
      reversed = material(c, path, std::nullopt, "left");
    } else if (type == "circle") {
      keys({"radius", "arc"});
      const double r = number(require(c, path, "radius", "the circle's radius"), child(path, "radius"), "a radius");
      if (!(r > 0)) fail(child(path, "radius"), "non-positive radius " + fmt(r) + "; expected a radius > 0");
      if (const json* a = get(c, "arc")) {
        array(*a, child(path, "arc"), "an arc [from angle, to angle]", 2);
        const double a0 = number((*a)[0], index(child(path, "arc"), 0), "an angle"), a1 = number((*a)[1], index(child(path, "arc"), 1), "an angle");
        if (!(a1 > a0)) fail(child(path, "arc"), "contour too short: the arc [" + fmt(a0) + ", " + fmt(a1) + "] has no length; expected a1 > a0");
        shape = Circle<double>(r, angle(a0), angle(a1));
      } else {
        shape = Circle<double>(r);
      }
      reversed = material(c, path, true, "inside");
    } else if (type == "parabola") {
      keys({"a", "x_range", "arc_length"});
      const double a = number(require(c, path, "a", "the coefficient in y = a x^2"), child(path, "a"), "the coefficient a");
      if (a == 0) fail(child(path, "a"), "a = 0 is a straight line; expected a non-zero coefficient (or use a \"line\" contour)");
      const json& xr = array(require(c, path, "x_range", "the parameter range [x0, x1]"), child(path, "x_range"), "an x range [x0, x1]", 2);
      const double lo = number(xr[0], index(child(path, "x_range"), 0), "x0"), hi = number(xr[1], index(child(path, "x_range"), 1), "x1");
      if (!(hi > lo)) fail(child(path, "x_range"), "contour too short: x_range [" + fmt(lo) + ", " + fmt(hi) + "] has no length; expected x1 > x0");
      ArcLengthMethod am;
      if (const json* al = get(c, "arc_length")) am = arc_length_method(*al, child(path, "arc_length"));
      shape = Parabola<double>(a, lo, hi, am);
      reversed = material(c, path, a > 0, "left");  // left of x increasing is y > a x^2, the focus side iff a > 0
    } else if (type == "ellipse") {
      keys({"semi_axes", "arc_length"});
      const json& sa = array(require(c, path, "semi_axes", "the semi-axes [A, B]"), child(path, "semi_axes"), "semi-axes [A, B]", 2);
      const double A = number(sa[0], index(child(path, "semi_axes"), 0), "semi-axis A"), B = number(sa[1], index(child(path, "semi_axes"), 1), "semi-axis B");
      if (!(A > 0) || !(B > 0)) fail(child(path, "semi_axes"), "non-positive semi-axis; expected A > 0 and B > 0");
      ArcLengthMethod am;
      if (const json* al = get(c, "arc_length")) am = arc_length_method(*al, child(path, "arc_length"));
      shape = Ellipse<double>(A, B, am);
      reversed = material(c, path, true, "inside");
    } else if (type == "samples") {
      keys({"file", "points", "closed", "smoothing", "scale", "parameter"});
      const bool closed = get(c, "closed") ? boolean(c["closed"], child(path, "closed"), "whether the contour is closed") : false;
      const double scale = number_or(c, path, "scale", 1.0, "a scale factor");
      if (!(scale > 0)) fail(child(path, "scale"), "expected a positive scale factor, got " + fmt(scale));
      const double smoothing = number_or(c, path, "smoothing", 0.0, "a smoothing tolerance");
      if (smoothing < 0) fail(child(path, "smoothing"), "expected a smoothing tolerance >= 0, got " + fmt(smoothing));
      const json* f = get(c, "file");
      const json* p = get(c, "points");
      if ((f != nullptr) == (p != nullptr)) fail(path, "expected exactly one of \"file\" (a point file) or \"points\" (inline [[x, y], ...])");
      std::vector<Vec2<double>> pts;
      std::vector<std::size_t> lines;  // of the point file, one per point: messages name them
      std::string source;
      if (f) {
        source = contour_file(*f, child(path, "file"), scene);
        try {
          PointSamples read = read_point_samples(source, kMinSplineSamples, scale);
          pts = std::move(read.points);
          lines = std::move(read.lines);
        } catch (const InputError& e) {
          fail(child(path, "file"), e.what());
        }
      } else {
        source = file_ + ":" + child(path, "points");
        pts = points(*p, child(path, "points"));
        for (auto& q : pts) q *= scale;
        if (pts.size() < kMinSplineSamples)
          fail(child(path, "points"), "contour too short: " + std::to_string(pts.size()) + " samples; expected at least " +
                                          std::to_string(kMinSplineSamples) + " for a spline");
      }
      const double area = closed ? signed_area(pts) : 0.0;
      const geometry::MaterialSide as_drawn = area >= 0 ? geometry::MaterialSide::Left : geometry::MaterialSide::Right;
      try {
        const auto report = geometry::validate_polyline(pts, closed, as_drawn, kValidationTolerance);
        geometry::throw_if_invalid(report, source, lines);
        if (report.dropped_closing_repeat) pts.pop_back();  // closed: the first point repeated at the end
      } catch (const std::runtime_error& e) {
        fail(path, std::string("invalid sampled contour: ") + e.what());
      }
      SplineOptions<double> opt;
      opt.closed = closed;
      opt.smoothing_tolerance = smoothing;
      try {
        shape = SampledProfile<double>(pts, opt);
      } catch (const std::exception& e) {
        fail(path, std::string("cannot fit the sampled contour (") + source + "): " + e.what());
      }
      reversed = closed ? material(c, path, area > 0, "inside") : material(c, path, std::nullopt, "left");
    } else if (type == "bezier") {
      keys({"segments", "closed", "parameter"});
      const bool closed = get(c, "closed") ? boolean(c["closed"], child(path, "closed"), "whether the path is closed") : false;
      const json& segs = array(require(c, path, "segments", "the Bezier segments"), child(path, "segments"), "a list of segments");
      if (segs.empty()) fail(child(path, "segments"), "contour too short: no segments; expected at least one");
      std::vector<BezierSegment<double>> out;
      std::vector<Vec2<double>> polygon;
      for (std::size_t i = 0; i < segs.size(); ++i) {
        const std::string sp = index(child(path, "segments"), i);
        object(segs[i], sp, {"points", "weights"});
        BezierSegment<double> s;
        s.points = points(require(segs[i], sp, "points", "the control points"), child(sp, "points"));
        if (s.points.size() < 2) fail(child(sp, "points"), "expected at least 2 control points, got " + std::to_string(s.points.size()));
        if (const json* w = get(segs[i], "weights")) {
          array(*w, child(sp, "weights"), "one weight per control point", s.points.size());
          for (std::size_t k = 0; k < w->size(); ++k) {
            const double x = number((*w)[k], index(child(sp, "weights"), k), "a weight");
            if (!(x > 0)) fail(index(child(sp, "weights"), k), "expected a positive weight, got " + fmt(x));
            s.weights.push_back(x);
          }
        }
        for (std::size_t k = (i == 0 ? 0 : 1); k < s.points.size(); ++k) polygon.push_back(s.points[k]);
        out.push_back(std::move(s));
      }
      try {
        shape = BezierPath<double>(std::move(out), closed);
      } catch (const std::exception& e) {
        fail(child(path, "segments"), e.what());
      }
      reversed = closed ? material(c, path, signed_area(polygon) > 0, "inside") : material(c, path, std::nullopt, "left");
    } else {  // svg
      keys({"file", "path", "flip_y", "scale", "parameter"});
      const std::string svg = contour_file(require(c, path, "file", "the SVG file"), child(path, "file"), scene);
      const std::string id = string(require(c, path, "path", "the id of the <path> element"), child(path, "path"), "a path id");
      SvgPathOptions opt;
      if (const json* fy = get(c, "flip_y")) opt.flip_y = boolean(*fy, child(path, "flip_y"), "whether to flip y");
      opt.scale = number_or(c, path, "scale", 1.0, "a scale factor");
      if (!(opt.scale > 0)) fail(child(path, "scale"), "expected a positive scale factor, got " + fmt(opt.scale));
      std::vector<SvgSubpath> subs;
      try {
        subs = read_svg_path(svg, id, opt);
      } catch (const InputError& e) {
        fail(child(path, "file"), e.what());
      }
      if (subs.size() != 1)
        fail(child(path, "path"), "the SVG path \"" + id + "\" in " + svg + " has " + std::to_string(subs.size()) +
                                      " subpaths; expected exactly one (one contour per path)");
      std::vector<Vec2<double>> polygon;
      for (std::size_t i = 0; i < subs[0].segments.size(); ++i)
        for (std::size_t k = (i == 0 ? 0 : 1); k < subs[0].segments[i].points.size(); ++k) polygon.push_back(subs[0].segments[i].points[k]);
      const bool closed = subs[0].closed;
      try {
        shape = BezierPath<double>(subs[0].segments, closed);
      } catch (const std::exception& e) {
        fail(path, "the SVG path \"" + id + "\" in " + svg + " is not a usable contour: " + e.what());
      }
      reversed = closed ? material(c, path, signed_area(polygon) > 0, "inside") : material(c, path, std::nullopt, "left");
    }
    if ((type == "samples" || type == "bezier" || type == "svg") && arc_length_parameter(c, path)) {
      if (const auto* sp = std::get_if<SampledProfile<double>>(&*shape)) shape = ArcLengthProfile<double>(*sp);
      else shape = ArcLengthProfile<double>(std::get<BezierPath<double>>(*shape));
    }
    const std::string nm = name(require(c, path, "name", "the contour's name"), child(path, "name"), "contour name");
    if (!names.insert(nm).second) fail(child(path, "name"), "duplicate contour name \"" + nm + "\" on link \"" + link_name + "\"");
    SE2<double> at;
    if (const json* a = get(c, "at")) at = frame(*a, child(path, "at"));
    scene.mechanism.contours.emplace_back(link_name + "." + nm, link, std::move(*shape), at, reversed);
  }

  void read_pairs(Scene& scene) {
    Mechanism<double>& m = scene.mechanism;
    const json& pairs = array(require(root_, "", "pairs", "the list of pairs"), "pairs", "the list of pairs");
    if (pairs.empty()) fail("pairs", "expected at least one pair");
    static const std::vector<std::string> types = {"revolute", "prismatic", "cam", "rolling"};
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      const std::string path = index("pairs", k);
      const json& p = pairs[k];
      if (!p.is_object()) fail(path, "expected a pair object, got " + kind_of(p));
      const std::string type = string(require(p, path, "type", "the pair type"), child(path, "type"), "the pair type");
      Pair<double> pair;
      if (type == "revolute") pair.kind = PairKind::Revolute;
      else if (type == "prismatic") pair.kind = PairKind::Prismatic;
      else if (type == "cam") pair.kind = PairKind::Cam;
      else if (type == "rolling") pair.kind = PairKind::Rolling;
      else fail(child(path, "type"), "unknown pair type \"" + type + "\"; expected one of " + quoted_list(types));
      pair.name = name(require(p, path, "name", "the pair's name"), child(path, "name"), "pair name");
      if (m.find_pair(pair.name) >= 0) fail(child(path, "name"), "duplicate pair name \"" + pair.name + "\"; pair names must be unique");
      PairInput in;
      if (!is_contact(pair.kind)) {
        object(p, path, {"name", "type", "links", "at", "variable", "value"});
        const json& links = array(require(p, path, "links", "the two links [A, B]"), child(path, "links"), "two link names [A, B]", 2);
        int idx[2];
        for (int j = 0; j < 2; ++j) {
          const std::string lp = index(child(path, "links"), j);
          const std::string ln = string(links[j], lp, "a link name");
          idx[j] = m.find_link(ln);
          if (idx[j] < 0) {
            std::vector<std::string> names;
            for (const auto& l : m.links) names.push_back(l.name);
            fail(lp, "unknown link \"" + ln + "\"; existing links: " + quoted_list(names));
          }
        }
        if (idx[0] == idx[1]) fail(child(path, "links"), "a pair must join two different links");
        pair.link_a = idx[0];
        pair.link_b = idx[1];
        if (const json* at = get(p, "at")) {
          array(*at, child(path, "at"), "the joint frames [frame in A, frame in B]", 2);
          pair.frame_a = frame((*at)[0], index(child(path, "at"), 0));
          pair.frame_b = frame((*at)[1], index(child(path, "at"), 1));
        }
        pair.variables = {pair.kind == PairKind::Revolute ? "angle" : "s", ""};
        if (const json* v = get(p, "variable")) pair.variables[0] = name(*v, child(path, "variable"), "variable name");
        in.values[0] = get(p, "value") ? number(p["value"], child(path, "value"), "the variable's value") : 0.0;
        in.has_values = true;
      } else {
        object(p, path, {"name", "type", "contours", "variables", "values", "hold"});
        const json& cs = array(require(p, path, "contours", "the two contours [\"link.contour\", \"link.contour\"]"),
                               child(path, "contours"), "two contour references [\"link.contour\", \"link.contour\"]", 2);
        int idx[2];
        for (int j = 0; j < 2; ++j) {
          const std::string cp = index(child(path, "contours"), j);
          const std::string cn = string(cs[j], cp, "a contour reference \"link.contour\"");
          idx[j] = m.find_contour(cn);
          if (idx[j] < 0) {
            std::vector<std::string> names;
            for (const auto& c : m.contours) names.push_back(c.name());
            fail(cp, "unknown contour \"" + cn + "\"; expected \"link.contour\", existing contours: " + quoted_list(names));
          }
        }
        pair.contour_a = idx[0];
        pair.contour_b = idx[1];
        pair.link_a = m.contours[idx[0]].link();
        pair.link_b = m.contours[idx[1]].link();
        if (pair.link_a == pair.link_b) fail(child(path, "contours"), "both contours are on link \"" + m.links[pair.link_a].name + "\"; a pair must join two different links");
        pair.variables = {"u", "v"};
        if (const json* v = get(p, "variables")) {
          array(*v, child(path, "variables"), "two variable names [u, v]", 2);
          for (int j = 0; j < 2; ++j) pair.variables[j] = name((*v)[j], index(child(path, "variables"), j), "variable name");
          if (pair.variables[0] == pair.variables[1]) fail(child(path, "variables"), "the two variables must have different names");
        }
        if (const json* v = get(p, "values")) {
          array(*v, child(path, "values"), "two values [u0, v0]", 2);
          for (int j = 0; j < 2; ++j) in.values[j] = number((*v)[j], index(child(path, "values"), j), "a contact parameter value");
          in.has_values = true;
        }
        if (const json* h = get(p, "hold")) {
          array(*h, child(path, "hold"), "two flags [hold u, hold v]", 2);
          for (int j = 0; j < 2; ++j) in.hold[j] = boolean((*h)[j], index(child(path, "hold"), j), "whether to hold the variable during assembly");
          if ((in.hold[0] || in.hold[1]) && !in.has_values)
            fail(child(path, "hold"), "\"hold\" needs \"values\": a held variable keeps its given value during "
                                      "assembly; give \"values\": [u0, v0] or drop \"hold\"");
        }
      }
      m.pairs.push_back(pair);
      inputs_.push_back(in);
    }
  }

  void finalize(Scene& scene, std::vector<int> drivers) {
    scene.mechanism.drivers = std::move(drivers);
    try {
      scene.mechanism.finalize();
    } catch (const std::invalid_argument& e) {
      fail("pairs", std::string(e.what()) + "; expected every link to be connected to the ground through pairs");
    }
  }

  std::vector<std::string> variable_names(const Mechanism<double>& m) const {
    std::vector<std::string> names;
    for (const auto& v : m.variables) names.push_back(v.name);
    return names;
  }

  void read_inputs(Scene& scene) {
    Mechanism<double>& m = scene.mechanism;
    const json& in = array(require(root_, "", "inputs", "the list of driver variables, e.g. [\"O_A.theta2\"]"), "inputs",
                           "a list of driver variable names");
    if (in.empty()) fail("inputs", "expected at least one input variable; existing variables: " + quoted_list(variable_names(m)));
    std::vector<int> drivers;
    for (std::size_t i = 0; i < in.size(); ++i) {
      const std::string path = index("inputs", i);
      const std::string v = string(in[i], path, "a variable name \"<pair>.<var>\"");
      const int idx = m.find_variable(v);
      if (idx < 0) fail(path, "unknown variable \"" + v + "\"; existing variables: " + quoted_list(variable_names(m)));
      for (int d : drivers)
        if (d == idx) fail(path, "input \"" + v + "\" is listed twice");
      drivers.push_back(idx);
      scene.inputs.push_back(v);
    }
    m.drivers = drivers;
  }

  void fill_guess(Scene& scene) {
    const Mechanism<double>& m = scene.mechanism;
    scene.guess = VectorX<double>::Zero(m.variable_count());
    for (std::size_t k = 0; k < m.pairs.size(); ++k) {
      const Pair<double>& p = m.pairs[k];
      for (int j = 0; j < p.variable_count(); ++j) {
        const int i = p.first_variable + j;
        scene.guess(i) = inputs_[k].values[j] * scene.unit_of(i);
        if (inputs_[k].hold[j]) {
          bool driver = false;
          for (int d : m.drivers) driver = driver || d == i;
          if (!driver) scene.held.push_back(i);
        }
      }
    }
  }

  /// Contact pairs without "values": closest points of the two contours sampled in world coordinates at
  /// the assembly guess. Needs the poses of both links without this pair: it must not be on the spanning
  /// tree (a chord closing a loop), and the pairs on the tree must have their values.
  void locate_missing_contacts(Scene& scene) {
    const Mechanism<double>& m = scene.mechanism;
    std::vector<int> missing;
    for (std::size_t k = 0; k < m.pairs.size(); ++k)
      if (!inputs_[k].has_values) missing.push_back(static_cast<int>(k));
    if (missing.empty()) return;
    for (int k : missing)
      for (std::size_t l = 0; l < m.links.size(); ++l)
        if (static_cast<int>(l) != m.ground && m.tree[l].edge.pair == k)
          fail(index("pairs", k), "\"values\" required: link \"" + m.links[l].name + "\" is placed through pair \"" +
                                      m.pairs[k].name + "\", so its contact cannot be located from the other pairs; give "
                                      "\"values\": [u0, v0] (contact parameters at the assembly pose)");
    KinematicsData<double> kin(m);
    evaluate_pairs<double>(m, scene.guess, nullptr, 1, kin);
    const std::vector<SE2<double>> pose = link_poses(m, kin);
    for (int k : missing) {
      const Pair<double>& p = m.pairs[k];
      std::vector<double> u[2];
      std::vector<Vec2<double>> pts[2];
      bool closed[2];
      for (int j = 0; j < 2; ++j) {
        const Contour<double>& c = m.contours[j == 0 ? p.contour_a : p.contour_b];
        const Domain<double> d = c.domain();
        closed[j] = d.closed;
        const int n = kContactSamples;
        for (int i = 0; i < n; ++i) {
          const double t = d.sample(i, n);
          u[j].push_back(t);
          pts[j].push_back(pose[c.link()].act(c.jet(t, 0).p));
        }
        if (d.closed) u[j].push_back(d.hi);
      }
      geometry::ContactCandidate cc;
      try {
        cc = geometry::find_contact(pts[0], closed[0], pts[1], closed[1]);
      } catch (const std::exception& e) {
        fail(index("pairs", k), std::string("cannot locate the initial contact: ") + e.what() + "; give \"values\"");
      }
      const geometry::PolylinePoint* on[2] = {&cc.on_a, &cc.on_b};
      for (int j = 0; j < 2; ++j) {
        const std::size_t s = on[j]->segment;
        const double val = u[j][s] + on[j]->fraction * (u[j][s + 1] - u[j][s]);
        scene.guess(p.first_variable + j) = val;
      }
    }
  }

  void read_sweep(Scene& scene) {
    const Mechanism<double>& m = scene.mechanism;
    const json* s = get(root_, "sweep");
    if (!s) return;
    object(*s, "sweep", {"input", "from", "to", "step"});
    Sweep sw;
    sw.input = scene.inputs.front();
    if (const json* in = get(*s, "input")) {
      sw.input = string(*in, "sweep.input", "one of the inputs");
      bool found = false;
      for (const auto& i : scene.inputs) found = found || i == sw.input;
      if (!found) fail("sweep.input", "\"" + sw.input + "\" is not one of the inputs; expected one of " + quoted_list(scene.inputs));
    }
    for (std::size_t d = 0; d < scene.inputs.size(); ++d)
      if (scene.inputs[d] == sw.input) sw.driver = static_cast<int>(d);
    sw.variable = m.drivers[sw.driver];
    sw.unit = scene.unit_of(sw.variable);
    sw.from = number(require(*s, "sweep", "from", "the first input value"), "sweep.from", "the first input value");
    sw.to = number(require(*s, "sweep", "to", "the last input value"), "sweep.to", "the last input value");
    sw.step = number(require(*s, "sweep", "step", "the input step"), "sweep.step", "the input step");
    const std::string bad = check_sweep(sw);
    if (!bad.empty()) fail("sweep.step", bad);
    scene.sweep = sw;
  }

  struct PairInput {
    std::array<double, 2> values{0, 0};
    std::array<bool, 2> hold{false, false};
    bool has_values = false;
  };

  std::string file_;
  fs::path dir_;
  json root_;
  bool scene_degrees_ = true;
  std::vector<PairInput> inputs_;
};

}  // namespace

double Scene::unit_of(int variable) const {
  return degrees && mechanism.variables[variable].kind == ParamKind::Angle ? pi<double>() / 180 : 1.0;
}

std::string Scene::unit_label(int variable) const {
  switch (mechanism.variables[variable].kind) {
    case ParamKind::Angle: return degrees ? "deg" : "rad";
    case ParamKind::Length: return length_unit;
    case ParamKind::Unitless: return "";
  }
  return "";
}

Scene parse_scene(const std::string& text, const std::string& file) { return SceneReader(file, text).read(); }

Scene load_scene(const std::string& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw InputError(path, "", "is a directory; expected a scene file (JSON)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open the scene file (" + std::string(std::strerror(errno)) + ")");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_scene(text.str(), path);
}

std::string check_sweep(const Sweep& s) {
  if (!std::isfinite(s.from) || !std::isfinite(s.to) || !std::isfinite(s.step)) return "from, to and step must be finite numbers";
  if (s.step == 0) return "step must not be zero; expected a step with the sign of to - from";
  const double span = s.to - s.from;
  if (span != 0 && (span > 0) != (s.step > 0))
    return "step " + fmt(s.step) + " has the wrong sign for a sweep from " + fmt(s.from) + " to " + fmt(s.to) +
           "; expected a step with the sign of to - from";
  if (span / s.step > 1e7) return "the sweep from " + fmt(s.from) + " to " + fmt(s.to) + " by " + fmt(s.step) + " has more than 10 million values; expected a larger step";
  return "";
}

std::vector<double> sweep_values(const Sweep& s) {
  const std::string bad = check_sweep(s);
  if (!bad.empty()) throw std::invalid_argument("sweep: " + bad);
  const double n = std::floor((s.to - s.from) / s.step + 1e-9);
  std::vector<double> out;
  for (long k = 0; k <= static_cast<long>(n); ++k) out.push_back(s.from + s.step * static_cast<double>(k));
  return out;
}

std::vector<double> sweep_inputs(const Sweep& s) {
  std::vector<double> out = sweep_values(s);
  for (double& v : out) v *= s.unit;
  return out;
}

}  // namespace rollkin::io
