// SVG documents: one element by id, its transforms, the root viewport and units (see io/svg_path.hpp).
#include "rollkin/io/svg_path.hpp"
#include "rollkin/io/input_file.hpp"
#include "rollkin/io/text_position.hpp"
#include "rollkin/io/units.hpp"
#include "rollkin/io/format.hpp"

#include "svg_detail.hpp"

#include <pugixml.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <map>
#include <sstream>

namespace rollkin {
namespace {

using P = Vec2<double>;
using Segment = BezierSegment<double>;

/// Numbers in messages and notes: 12 significant digits.
std::string fmt(double x) { return io::format_number(x, 12); }

// ---- affine maps ----------------------------------------------------------------------------------------

/// x' = a x + c y + e, y' = b x + d y + f: the matrix(a b c d e f) of SVG 1.1, 7.4.
struct Affine {
  double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;

  P operator()(const P& p) const { return P(a * p.x() + c * p.y() + e, b * p.x() + d * p.y() + f); }
  /// (*this) o m: m first.
  Affine operator*(const Affine& m) const {
    return {a * m.a + c * m.b, b * m.a + d * m.b, a * m.c + c * m.d, b * m.c + d * m.d, a * m.e + c * m.f + e,
            b * m.e + d * m.f + f};
  }
  double det() const { return a * d - b * c; }
  bool finite() const {
    for (double v : {a, b, c, d, e, f})
      if (!std::isfinite(v)) return false;
    return true;
  }
  /// Singular to round-off: the ratio of the singular values is below sqrt(eps), or a value is not finite.
  bool degenerate() const {
    const double frob2 = a * a + b * b + c * c + d * d;
    return !finite() || !(std::abs(det()) > tolerance<double>(0.5) * frob2);
  }
  static Affine translate(double tx, double ty) { return {1, 0, 0, 1, tx, ty}; }
  static Affine scale(double sx, double sy) { return {sx, 0, 0, sy, 0, 0}; }
  static Affine rotate_deg(double deg) {
    const double t = deg_to_rad(deg);
    return {std::cos(t), std::sin(t), -std::sin(t), std::cos(t), 0, 0};
  }
};

// ---- messages -------------------------------------------------------------------------------------------

/// Where a message points: the file and "line L, <kind> "id"" of the element.
struct Where {
  const std::string& file;
  std::string location;

  [[noreturn]] void fail(const std::string& message) const { throw InputError(file, location, message); }
};

std::pair<std::size_t, std::size_t> line_column(const std::string& text, std::ptrdiff_t offset) {
  return line_column_at(text, static_cast<std::size_t>(std::max<std::ptrdiff_t>(offset, 0)));
}

std::string local_name(const pugi::xml_node& n) {
  const std::string name = n.name();
  const std::size_t colon = name.rfind(':');
  return colon == std::string::npos ? name : name.substr(colon + 1);
}

std::string element_location(const std::string& text, const pugi::xml_node& n) {
  std::string id = n.attribute("id").value();
  const std::string line = "line " + std::to_string(line_column(text, n.offset_debug()).first) + ", ";
  return line + (id.empty() ? "<" + local_name(n) + ">" : local_name(n) + " \"" + id + "\"");
}

// ---- numbers, lengths and units -------------------------------------------------------------------------

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r\n"), last = s.find_last_not_of(" \t\r\n");
  return first == std::string::npos ? "" : s.substr(first, last - first + 1);
}

/// Metres per unit of the absolute CSS units (CSS Values 3, 5.2: 1in = 2.54cm = 96px = 72pt = 6pc), from the
/// units table (io/units.hpp); none for any other spelling.
std::optional<double> metres_per(const std::string& unit) {
  using io::LengthUnit;
  for (LengthUnit u : {LengthUnit::Millimetre, LengthUnit::Centimetre, LengthUnit::Inch, LengthUnit::Point,
                       LengthUnit::Pica, LengthUnit::Pixel})
    if (unit == io::unit_label(u)) return io::metres_per(u);
  return std::nullopt;
}

struct Length {
  double value = 0;
  std::string unit;  // "", "px", "mm", ... or "%"
};

/// An SVG length "number unit?"; `what` names the attribute in messages.
Length parse_length(const std::string& raw, const std::string& what, const Where& where) {
  const std::string s = trimmed(raw);
  Length out;
  std::size_t pos = 0;
  const auto scan = svg_detail::scan_number(s, pos, out.value);
  if (scan == svg_detail::NumberScan::out_of_range)
    where.fail(what + "=\"" + raw + "\" is out of range (not a finite number)");
  if (scan == svg_detail::NumberScan::none)
    where.fail(what + "=\"" + raw + "\" is not a number; expected a number with an optional unit, e.g. \"12.5\"");
  out.unit = s.substr(pos);
  if (!out.unit.empty() && out.unit != "%" && !metres_per(out.unit))
    where.fail(what + "=\"" + raw + "\" has the unit \"" + out.unit +
               "\", which rollkin does not read; expected no unit or one of px, mm, cm, in, pt, pc");
  return out;
}

/// A geometry attribute (cx, r, width, ...) in user units: absolute units are converted as CSS does (1 user
/// unit = 1px); a percentage (relative to the viewport) is an error. `fallback` when absent, if given.
double user_length(const pugi::xml_node& n, const char* name, const Where& where, std::optional<double> fallback) {
  const pugi::xml_attribute a = n.attribute(name);
  if (!a) {
    if (fallback) return *fallback;
    where.fail("has no " + std::string(name) + " attribute; expected " + name + "=\"number\"");
  }
  const Length l = parse_length(a.value(), name, where);
  if (l.unit == "%")
    where.fail(std::string(name) + "=\"" + a.value() +
               "\" is a percentage of the viewport, which rollkin does not resolve; give it in user units");
  return l.unit.empty() ? l.value : l.value * *metres_per(l.unit) / *metres_per("px");
}

/// A list of numbers separated by white space and/or commas (points, viewBox).
std::vector<double> number_list(const std::string& s, const std::string& what, const Where& where) {
  std::vector<double> out;
  std::size_t pos = 0;
  while (true) {
    while (pos < s.size() && svg_detail::is_separator(s[pos])) ++pos;
    if (pos >= s.size()) return out;
    double v = 0;
    const std::size_t start = pos;
    const auto scan = svg_detail::scan_number(s, pos, v);
    if (scan != svg_detail::NumberScan::ok)
      where.fail(what + ": number " + std::to_string(out.size() + 1) + " (offset " + std::to_string(start) + ", \"" +
                 s.substr(start, 20) + "\") is " + (scan == svg_detail::NumberScan::none ? "malformed" : "out of range") +
                 "; expected numbers separated by spaces or commas");
    out.push_back(v);
  }
}

// ---- transform attribute (SVG 1.1, 7.6) ----------------------------------------------------------------

Affine transform_function(const std::string& name, const std::vector<double>& v, const std::string& text,
                          const Where& where) {
  auto need = [&](std::initializer_list<std::size_t> counts) {
    for (std::size_t c : counts)
      if (v.size() == c) return;
    std::string allowed;
    for (std::size_t c : counts) allowed += (allowed.empty() ? "" : " or ") + std::to_string(c);
    where.fail("transform=\"" + text + "\": " + name + "() takes " + allowed + " numbers, got " +
               std::to_string(v.size()));
  };
  if (name == "matrix") {
    need({6});
    return {v[0], v[1], v[2], v[3], v[4], v[5]};
  }
  if (name == "translate") {
    need({1, 2});
    return Affine::translate(v[0], v.size() == 2 ? v[1] : 0);
  }
  if (name == "scale") {
    need({1, 2});
    return Affine::scale(v[0], v.size() == 2 ? v[1] : v[0]);
  }
  if (name == "rotate") {
    need({1, 3});
    const Affine r = Affine::rotate_deg(v[0]);
    return v.size() == 1 ? r : Affine::translate(v[1], v[2]) * r * Affine::translate(-v[1], -v[2]);
  }
  if (name == "skewX" || name == "skewY") {
    need({1});
    const double t = std::tan(deg_to_rad(v[0]));
    return name == "skewX" ? Affine{1, 0, t, 1, 0, 0} : Affine{1, t, 0, 1, 0, 0};
  }
  where.fail("transform=\"" + text + "\": unknown transform function \"" + name +
             "\"; expected matrix, translate, scale, rotate, skewX or skewY");
}

/// The product of a transform list, left to right (the rightmost function applies first).
Affine parse_transform(const std::string& text, const Where& where) {
  Affine total;
  std::size_t pos = 0;
  auto skip = [&] {
    while (pos < text.size() && svg_detail::is_separator(text[pos])) ++pos;
  };
  while (true) {
    skip();
    if (pos >= text.size()) break;
    const std::size_t start = pos;
    while (pos < text.size() && std::isalpha(static_cast<unsigned char>(text[pos]))) ++pos;
    const std::string name = text.substr(start, pos - start);
    while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos]))) ++pos;
    if (name.empty() || pos >= text.size() || text[pos] != '(')
      where.fail("transform=\"" + text + "\" is not understood at offset " + std::to_string(start) +
                 "; expected a list of functions such as translate(10, 20) rotate(30)");
    const std::size_t close = text.find(')', pos);
    if (close == std::string::npos)
      where.fail("transform=\"" + text + "\": " + name + "( has no closing parenthesis");
    const std::vector<double> args = number_list(text.substr(pos + 1, close - pos - 1), "transform=\"" + text + "\", " + name + "()", where);
    const Affine m = transform_function(name, args, text, where);
    if (m.degenerate())
      where.fail("transform=\"" + text + "\": " + name + "() is degenerate (not invertible: it flattens the drawing); "
                 "expected an invertible transform");
    total = total * m;
    pos = close + 1;
  }
  return total;
}

// ---- the root viewport (SVG 1.1, 7.7-7.8) ----------------------------------------------------------------

struct Viewport {
  Affine map;                       // root user units -> viewport units
  std::optional<double> metres;     // metres per viewport unit, when declared
  std::string unit = "user unit";   // name of the viewport unit
  std::string description;          // for the conversion line
};

/// The viewBox-to-viewport map for a viewport of size (w, h) (SVG 1.1, 7.8, preserveAspectRatio).
Affine viewbox_map(const std::vector<double>& vb, double w, double h, const std::string& par_text, const Where& where) {
  std::istringstream words(par_text);
  std::string align = "xMidYMid", mode = "meet", word;
  if (words >> word) {
    if (word == "defer") words >> word;
    align = word;
    if (words >> word) mode = word;
  }
  static const char* aligns[] = {"none", "xMinYMin", "xMidYMin", "xMaxYMin", "xMinYMid", "xMidYMid",
                                 "xMaxYMid", "xMinYMax", "xMidYMax", "xMaxYMax"};
  if (std::none_of(std::begin(aligns), std::end(aligns), [&](const char* a) { return align == a; }) ||
      (mode != "meet" && mode != "slice") || (words >> word))
    where.fail("preserveAspectRatio=\"" + par_text +
               "\" is not understood; expected none or xMinYMin..xMaxYMax, optionally followed by meet or slice");
  double sx = w / vb[2], sy = h / vb[3];
  if (align != "none") sx = sy = mode == "meet" ? std::min(sx, sy) : std::max(sx, sy);
  double tx = -vb[0] * sx, ty = -vb[1] * sy;
  const double free_x = w - vb[2] * sx, free_y = h - vb[3] * sy;
  if (align.find("xMid") == 0) tx += free_x / 2;
  if (align.find("xMax") == 0) tx += free_x;
  if (align.find("YMid") != std::string::npos) ty += free_y / 2;
  if (align.find("YMax") != std::string::npos) ty += free_y;
  return {sx, 0, 0, sy, tx, ty};
}

Viewport root_viewport(const pugi::xml_node& root, const Where& where) {
  Viewport v;
  std::optional<Length> width, height;
  for (const char* name : {"width", "height"})
    if (const pugi::xml_attribute a = root.attribute(name)) {
      const Length l = parse_length(a.value(), name, where);
      if (l.unit != "%" && !(l.value > 0)) where.fail(std::string(name) + "=\"" + a.value() + "\" must be positive");
      if (l.unit != "%") (std::strcmp(name, "width") == 0 ? width : height) = l;
    }
  if (width && height && width->unit.empty() != height->unit.empty())
    where.fail("width=\"" + std::string(root.attribute("width").value()) + "\" and height=\"" +
               root.attribute("height").value() + "\" mix a unit and no unit; give both with the same kind");
  const bool declared = (width && !width->unit.empty()) || (height && !height->unit.empty());
  const pugi::xml_attribute vb_attr = root.attribute("viewBox");
  if (!vb_attr || (!width && !height)) {
    // User units are the viewport's px (SVG 1.1, 7.2); without width/height the viewBox only frames.
    if (declared) {
      v.metres = metres_per("px");
      v.unit = "px";
    }
    v.description = declared ? "user units are px (no viewBox)" : "user units as they are (no unit declared)";
    if (vb_attr) number_list(vb_attr.value(), "viewBox", where);  // still a malformed viewBox is an error
    return v;
  }
  const std::vector<double> vb = number_list(vb_attr.value(), "viewBox", where);
  if (vb.size() != 4 || !(vb[2] > 0) || !(vb[3] > 0))
    where.fail(std::string("viewBox=\"") + vb_attr.value() +
               "\" is not \"min-x min-y width height\" with a positive width and height");
  // Viewport size in the unit of width (or of height when only it is given).
  const std::string unit = width ? width->unit : height->unit;
  auto in_unit = [&](const Length& l) { return unit.empty() ? l.value : l.value * *metres_per(l.unit) / *metres_per(unit); };
  double w = width ? in_unit(*width) : in_unit(*height) * vb[2] / vb[3];
  double h = height ? in_unit(*height) : in_unit(*width) * vb[3] / vb[2];
  v.map = viewbox_map(vb, w, h, root.attribute("preserveAspectRatio").value(), where);
  if (!unit.empty()) {
    v.metres = metres_per(unit);
    v.unit = unit;
  }
  v.description = "viewBox \"" + trimmed(vb_attr.value()) + "\" in " + fmt(w) + " x " + fmt(h) + " " +
                  (unit.empty() ? "user units (no unit declared)" : unit);
  return v;
}

// ---- what must not be silently ignored -----------------------------------------------------------------

/// Calls f on every element under (and including) root in document order, without recursion.
template <class F> void for_each_element(const pugi::xml_node& root, F&& f) {
  for (pugi::xml_node n = root; n;) {
    if (n.type() == pugi::node_element) f(n);
    if (n.first_child()) {
      n = n.first_child();
      continue;
    }
    while (n != root && !n.next_sibling()) n = n.parent();
    if (n == root) break;
    n = n.next_sibling();
  }
}

/// Whether a CSS declaration list (a style attribute or sheet) sets the property `name` ("transform").
bool has_css_property(const std::string& style, const std::string& name) {
  std::string s;
  for (char c : style) s += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (std::size_t p = s.find(name); p != std::string::npos; p = s.find(name, p + 1)) {
    std::size_t q = p + name.size();
    while (q < s.size() && std::isspace(static_cast<unsigned char>(s[q]))) ++q;
    const bool word_start = p == 0 || !(std::isalnum(static_cast<unsigned char>(s[p - 1])) || s[p - 1] == '-');
    if (word_start && q < s.size() && s[q] == ':') return true;
  }
  return false;
}

/// The first transform-related CSS property a style sets, or "".
std::string css_transform_property(const std::string& style) {
  for (const char* name : {"transform", "transform-origin", "transform-box", "rotate", "scale", "translate"})
    if (has_css_property(style, name)) return name;
  return "";
}

std::string href_of(const pugi::xml_node& use) {
  for (const char* name : {"href", "xlink:href"})
    if (const pugi::xml_attribute a = use.attribute(name)) return trimmed(a.value());
  return "";
}

/// Refuses what would change the drawn geometry without being applied: <use> of the element or of an
/// ancestor, CSS transforms (style sheets, style attributes), <defs>/<symbol> and nested <svg> ancestors.
void check_nothing_ignored(const pugi::xml_node& root, const pugi::xml_node& element, const std::string& text,
                           const Where& where) {
  std::map<std::string, pugi::xml_node> chain_ids;  // ids of the element and its ancestors below the root
  for (pugi::xml_node n = element; n && n != root; n = n.parent()) {
    const std::string kind = local_name(n);
    if (kind == "defs" || kind == "symbol" || kind == "clipPath" || kind == "mask" || kind == "marker" ||
        kind == "pattern")
      where.fail("the element is inside <" + kind + "> (" + element_location(text, n) +
                 "): it is drawn only where it is referenced (e.g. by <use>), which rollkin does not follow; "
                 "move it out of <" + kind + "> or select a drawn element");
    if (kind == "switch")
      where.fail("the element is inside <switch> (" + element_location(text, n) +
                 "): which child is drawn depends on the viewer; take it out of the <switch>");
    if (kind == "svg")
      where.fail("the element is inside a nested <svg> viewport (" + element_location(text, n) +
                 "), which rollkin does not apply; ungroup it in the editor");
    // Built only for a message: element_location counts lines from the start of the text, so building it for
    // every ancestor would cost depth x file size (quadratic for deeply nested groups).
    const auto who = [&] { return n == element ? std::string("the element") : "its ancestor " + element_location(text, n); };
    if (const std::string p = css_transform_property(n.attribute("style").value()); !p.empty())
      where.fail(who() + " has a CSS transform (" + p + ") in style=\"" + std::string(n.attribute("style").value()) +
                 "\", which rollkin does not apply; use the transform attribute instead");
    for (const char* a : {"transform-origin", "transform-box"})
      if (n.attribute(a))
        where.fail(who() + " has " + a + "=\"" + n.attribute(a).value() +
                   "\", which rollkin does not apply; write the transform about the origin instead");
    if (const std::string id = n.attribute("id").value(); !id.empty()) chain_ids.emplace("#" + id, n);
  }
  for_each_element(root, [&](const pugi::xml_node& n) {
    const std::string kind = local_name(n);
    if (kind == "style" && !css_transform_property(n.text().get()).empty())
      where.fail("the document's <style> sheet (" + element_location(text, n) + ") sets a CSS transform (" +
                 css_transform_property(n.text().get()) + "), which rollkin does not apply; use transform attributes instead");
    if (kind != "use") return;
    const auto used = chain_ids.find(href_of(n));
    if (used == chain_ids.end()) return;
    where.fail((used->second == element ? std::string("the element")
                                        : "its ancestor \"" + std::string(used->second.attribute("id").value()) + "\"") +
               " is referenced by <use> (" + element_location(text, n) +
               "), which draws a copy elsewhere that rollkin does not follow; "
               "unlink the clone in the editor (Edit > Clone > Unlink Clone) and select the copy you mean");
  });
}

// ---- element geometry in its own user coordinates -------------------------------------------------------

/// Quarter arc from c + u to c + v through the corner c + u + v: exact rational quadratic, weight cos(45 deg).
Segment quarter_arc(const P& c, const P& u, const P& v) {
  return Segment{{c + u, c + u + v, c + v}, {1.0, std::sqrt(0.5), 1.0}};
}

SvgSubpath ellipse_geometry(double cx, double cy, double rx, double ry, const std::string& kind) {
  // SVG 2, 10.4-10.5: from (cx + rx, cy) through (cx, cy + ry), (cx - rx, cy), (cx, cy - ry).
  const P c(cx, cy), ex(rx, 0), ey(0, ry);
  SvgSubpath g;
  g.segments = {quarter_arc(c, ex, ey), quarter_arc(c, ey, -ex), quarter_arc(c, -ex, -ey), quarter_arc(c, -ey, ex)};
  for (int k = 1; k <= 4; ++k) g.origins.push_back("quarter " + std::to_string(k) + " of the " + kind);
  g.closed = true;
  return g;
}

SvgSubpath rect_geometry(const pugi::xml_node& n, const Where& where) {
  const double x = user_length(n, "x", where, 0.0), y = user_length(n, "y", where, 0.0);
  const double w = user_length(n, "width", where, std::nullopt), h = user_length(n, "height", where, std::nullopt);
  if (!(w > 0) || !(h > 0)) where.fail("width and height must be positive, got " + fmt(w) + " x " + fmt(h));
  // SVG 2, 10.2: a missing or "auto" radius takes the other; both are clamped to half the side.
  const bool has_rx = n.attribute("rx") && trimmed(n.attribute("rx").value()) != "auto";
  const bool has_ry = n.attribute("ry") && trimmed(n.attribute("ry").value()) != "auto";
  double rx = has_rx ? user_length(n, "rx", where, 0.0) : 0, ry = has_ry ? user_length(n, "ry", where, 0.0) : 0;
  if (rx < 0 || ry < 0) where.fail("rx and ry must not be negative, got " + fmt(rx) + ", " + fmt(ry));
  if (!has_rx) rx = ry;
  if (!has_ry) ry = rx;
  rx = std::min(rx, w / 2);
  ry = std::min(ry, h / 2);
  SvgSubpath g;
  g.closed = true;
  auto line = [&](const P& a, const P& b, const std::string& side) {
    if (a == b) return;
    g.segments.push_back(Segment{{a, b}, {}});
    g.origins.push_back(side + " side of the rect");
  };
  auto corner = [&](const P& c, const P& u, const P& v, const std::string& name) {
    if (rx == 0 || ry == 0) return;
    g.segments.push_back(quarter_arc(c, u, v));
    g.origins.push_back(name + " rounded corner of the rect");
  };
  const P ex(rx, 0), ey(0, ry);
  // SVG 2, 10.2 path equivalent: start at (x + rx, y), clockwise on screen.
  line(P(x + rx, y), P(x + w - rx, y), "top");
  corner(P(x + w - rx, y + ry), -ey, ex, "top-right");
  line(P(x + w, y + ry), P(x + w, y + h - ry), "right");
  corner(P(x + w - rx, y + h - ry), ex, ey, "bottom-right");
  line(P(x + w - rx, y + h), P(x + rx, y + h), "bottom");
  corner(P(x + rx, y + h - ry), ey, -ex, "bottom-left");
  line(P(x, y + h - ry), P(x, y + ry), "left");
  corner(P(x + rx, y + ry), -ex, -ey, "top-left");
  return g;
}

SvgSubpath poly_geometry(const pugi::xml_node& n, bool closed, const std::string& kind, const Where& where) {
  if (!n.attribute("points")) where.fail("has no points attribute; expected points=\"x1,y1 x2,y2 ...\"");
  const std::vector<double> v = number_list(n.attribute("points").value(), "points", where);
  if (v.size() % 2 != 0)
    where.fail("points has an odd count of numbers (" + std::to_string(v.size()) + "); expected x,y pairs");
  if (v.size() < 4) where.fail("points has fewer than 2 points; a contour needs at least one edge");
  SvgSubpath g;
  const std::size_t count = v.size() / 2;
  for (std::size_t k = 0; k < (closed ? count : count - 1); ++k) {
    const std::size_t next = (k + 1) % count;
    const P a(v[2 * k], v[2 * k + 1]), b(v[2 * next], v[2 * next + 1]);
    if (a == b) continue;  // repeated point (also the closing point of a polygon that repeats its first)
    g.segments.push_back(Segment{{a, b}, {}});
    g.origins.push_back("edge from point " + std::to_string(k + 1) + " to point " + std::to_string(next + 1) +
                             " of the " + kind);
  }
  g.closed = closed;
  return g;
}

SvgSubpath path_geometry(const pugi::xml_node& n, const std::string& file, const Where& where) {
  if (!n.attribute("d")) where.fail("has no d attribute; expected the path data d=\"M ...\"");
  std::vector<SvgSubpath> subs = svg_detail::parse_path_data(n.attribute("d").value(), file, where.location);
  if (subs.size() != 1) {
    std::string starts;
    for (const auto& s : subs) starts += (starts.empty() ? "" : ", ") + s.origins.front();
    where.fail(subs.empty() ? "the path data draws nothing (no segment of non-zero length)"
                            : "the path data has " + std::to_string(subs.size()) + " subpaths (starting at " + starts +
                                  "); a contour is one subpath: break the path apart in the editor and select one");
  }
  return std::move(subs.front());
}

SvgSubpath element_geometry(const pugi::xml_node& n, const std::string& kind, const std::string& file, const Where& where) {
  auto positive = [&](double r, const char* name) {
    if (!(r > 0)) where.fail(std::string(name) + " must be positive, got " + fmt(r));
    return r;
  };
  if (kind == "path") return path_geometry(n, file, where);
  if (kind == "circle") {
    const double r = positive(user_length(n, "r", where, std::nullopt), "r");
    return ellipse_geometry(user_length(n, "cx", where, 0.0), user_length(n, "cy", where, 0.0), r, r, kind);
  }
  if (kind == "ellipse") {
    const bool has_rx = n.attribute("rx") && trimmed(n.attribute("rx").value()) != "auto";
    const bool has_ry = n.attribute("ry") && trimmed(n.attribute("ry").value()) != "auto";
    if (!has_rx && !has_ry) where.fail("has neither rx nor ry; expected the radii rx=\"...\" ry=\"...\"");
    const double rx = positive(user_length(n, has_rx ? "rx" : "ry", where, std::nullopt), "rx");
    const double ry = positive(user_length(n, has_ry ? "ry" : "rx", where, std::nullopt), "ry");
    return ellipse_geometry(user_length(n, "cx", where, 0.0), user_length(n, "cy", where, 0.0), rx, ry, kind);
  }
  if (kind == "rect") return rect_geometry(n, where);
  if (kind == "line") {
    const P a(user_length(n, "x1", where, 0.0), user_length(n, "y1", where, 0.0));
    const P b(user_length(n, "x2", where, 0.0), user_length(n, "y2", where, 0.0));
    if (a == b) where.fail("has zero length (x1, y1 = x2, y2); a contour needs a non-zero extent");
    SvgSubpath g;
    g.segments = {Segment{{a, b}, {}}};
    g.origins = {"the line"};
    return g;
  }
  if (kind == "polyline" || kind == "polygon") return poly_geometry(n, kind == "polygon", kind, where);
  where.fail("is a <" + kind + ">, which rollkin does not read as a contour; expected path, circle, ellipse, rect, "
             "line, polyline or polygon (convert it to a path in the editor: Path > Object to Path)");
}

// ---- finding the element --------------------------------------------------------------------------------

pugi::xml_node find_by_id(const pugi::xml_document& doc, const std::string& id, const std::string& text,
                          const std::string& file) {
  std::vector<pugi::xml_node> hits;
  std::vector<std::string> known;
  for_each_element(doc.document_element(), [&](const pugi::xml_node& n) {
    if (!n.attribute("id")) return;
    const std::string this_id = n.attribute("id").value();
    if (this_id == id) hits.push_back(n);
    static const char* shapes[] = {"path", "circle", "ellipse", "rect", "line", "polyline", "polygon"};
    const std::string kind = local_name(n);
    if (std::any_of(std::begin(shapes), std::end(shapes), [&](const char* s) { return kind == s; }) && known.size() < 20)
      known.push_back(this_id);
  });
  if (hits.size() > 1)
    throw InputError(file, element_location(text, hits[1]),
                     "the id \"" + id + "\" is used by " + std::to_string(hits.size()) +
                         " elements (ids must be unique); rename the others in the editor");
  if (hits.empty()) {
    std::string list;
    for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
    throw InputError(file, "", "no element with id=\"" + id + "\"" +
                                   (list.empty() ? " (the file has no path or shape element with an id)"
                                                 : "; ids of path and shape elements: " + list));
  }
  return hits.front();
}

pugi::xml_node parse_document(pugi::xml_document& doc, const std::string& text, const std::string& file) {
  const pugi::xml_parse_result r = doc.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_utf8);
  if (!r) {
    const auto [line, column] = line_column(text, r.offset);
    throw InputError(file, "line " + std::to_string(line) + ":" + std::to_string(column),
                     std::string("malformed XML: ") + r.description() + "; expected a well-formed SVG document");
  }
  const pugi::xml_node root = doc.document_element();
  if (local_name(root) != "svg")
    throw InputError(file, element_location(text, root),
                     "the root element is <" + std::string(root.name()) + ">; expected an SVG document (<svg>)");
  return root;
}

// ---- corners --------------------------------------------------------------------------------------------

std::vector<SvgCorner> find_corners(const SvgShape& s, double corner_tolerance) {
  std::vector<SvgCorner> out;
  const std::size_t n = s.segments.size();
  const double gap = BezierPathOptions<double>{}.joint_tolerance * svg_detail::control_extent(s.segments);
  for (const PathCorner<double>& c : path_corners(s.segments, s.closed, gap, corner_tolerance))
    out.push_back({c.piece, c.point, rad_to_deg(c.turn), "where " + s.origins[(c.piece + n - 1) % n] + " meets " + s.origins[c.piece]});
  std::sort(out.begin(), out.end(), [](const SvgCorner& x, const SvgCorner& y) { return x.segment < y.segment; });
  return out;
}

bool all_finite(const std::vector<Segment>& segments) {
  for (const Segment& s : segments)
    for (const P& p : s.points)
      if (!std::isfinite(p.x()) || !std::isfinite(p.y())) return false;
  return true;
}

/// Step 1: the element's transform, then its ancestors', innermost first (SVG 1.1, 7.5); counts them.
Affine element_to_root(const pugi::xml_node& root, const pugi::xml_node& element, const std::string& text,
                       const Where& where, std::size_t& count) {
  Affine m;
  for (pugi::xml_node n = element; n && n != root; n = n.parent())
    if (const pugi::xml_attribute t = n.attribute("transform")) {
      try {
        m = parse_transform(t.value(), where) * m;
      } catch (const InputError& e) {
        if (n == element) throw;
        throw InputError(where.file, where.location + " (its ancestor " + element_location(text, n) + ")", e.message());
      }
      ++count;
    }
  if (root.attribute("transform"))
    where.fail("the root <svg> has a transform attribute, which rollkin does not apply; move it to a <g>");
  return m;
}

/// The one line for --verbose: what steps 1-5 did.
std::string conversion_line(const SvgShape& shape, std::size_t transforms, const Viewport& vp, const SvgReadOptions& o) {
  std::ostringstream line;
  line << shape.file << " " << shape.location << ": " << transforms << " transform attribute(s) applied; "
       << vp.description << "; ";
  if (vp.metres && o.metres_per_scene_unit)
    line << vp.unit << " -> scene units x " << fmt(shape.unit_factor);
  else if (vp.metres)
    line << "file unit " << vp.unit << " kept (the scene declares no units.length)";
  else
    line << "numbers kept (the file declares no unit)";
  line << (o.flip_y ? "; y flipped" : "; y not flipped") << "; scale " << fmt(o.scale);
  return line.str();
}

}  // namespace

SvgShape read_svg_shape_from_text(const std::string& text, const std::string& id, const SvgReadOptions& options,
                                  const std::string& file) {
  if (!(options.scale > 0) || !std::isfinite(options.scale))
    throw InputError(file, "", "the scale factor must be positive and finite, got " + fmt(options.scale));
  if (options.metres_per_scene_unit && !(*options.metres_per_scene_unit > 0))
    throw InputError(file, "", "the scene's length unit must be a positive number of metres");
  pugi::xml_document doc;
  const pugi::xml_node root = parse_document(doc, text, file);
  const pugi::xml_node element = find_by_id(doc, id, text, file);
  SvgShape shape;
  shape.file = file;
  shape.id = id;
  shape.element = local_name(element);
  shape.location = element_location(text, element);
  const Where where{file, shape.location};
  check_nothing_ignored(root, element, text, where);
  SvgSubpath g = element_geometry(element, shape.element, file, where);
  if (!all_finite(g.segments))
    where.fail("the shape's control points overflow (a coordinate or radius near the largest double); expected "
               "coordinates of a drawing");

  std::size_t transforms = 0;
  const Affine m = element_to_root(root, element, text, where, transforms);
  const Viewport vp = root_viewport(root, Where{file, element_location(text, root)});
  shape.metres_per_file_unit = vp.metres;
  shape.file_unit = vp.unit;
  if (vp.metres && options.metres_per_scene_unit) shape.unit_factor = *vp.metres / *options.metres_per_scene_unit;
  const double k = shape.unit_factor * options.scale;
  const Affine total = Affine::scale(k, options.flip_y ? -k : k) * vp.map * m;
  if (total.degenerate())
    where.fail("the combined transform (element, groups, viewBox, scale) is degenerate; expected an invertible map");
  for (Segment& s : g.segments)
    for (P& p : s.points) p = total(p);
  if (!all_finite(g.segments))
    where.fail("the transforms, viewBox and scale map the shape beyond the largest double (overflow); expected "
               "the transforms of a drawing");
  // In the coordinates BezierPath gets (a non-uniform transform changes which pieces are short), e.g. a polygon
  // whose last point repeats the first to round-off.
  svg_detail::merge_short_segments(g);
  shape.segments = std::move(g.segments);
  shape.origins = std::move(g.origins);
  shape.closed = g.closed;
  if (shape.segments.empty()) where.fail("draws nothing (every segment has zero length)");
  shape.corners = find_corners(shape, options.corner_tolerance);

  shape.conversion = conversion_line(shape, transforms, vp, options);
  return shape;
}

SvgShape read_svg_shape(const std::string& svg_file, const std::string& id, const SvgReadOptions& options) {
  return read_svg_shape_from_text(io::read_input_file(svg_file, "the SVG file"), id, options, svg_file);
}

BezierPath<double> svg_bezier_path(const SvgShape& shape) {
  try {
    return BezierPath<double>(shape.segments, shape.closed);
  } catch (const std::invalid_argument& e) {
    throw InputError(shape.file, shape.location, std::string("not a usable contour: ") + e.what());
  }
}

std::vector<SvgSubpath> read_svg_path(const std::string& svg_file, const std::string& path_id,
                                      const SvgPathOptions& options) {
  SvgReadOptions o;
  o.flip_y = options.flip_y;
  o.scale = options.scale;
  SvgShape s = read_svg_shape(svg_file, path_id, o);
  return {SvgSubpath{std::move(s.segments), s.closed, std::move(s.origins)}};
}

}  // namespace rollkin
