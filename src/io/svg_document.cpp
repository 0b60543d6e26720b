// SVG documents: the shapes an element (or the whole document) draws, with <use>, <symbol> and <switch>
// expanded; their transforms, the root viewport and units; the choice of one subpath (see io/svg_reader.hpp).
#include "rollkin/io/svg_reader.hpp"
#include "rollkin/io/input_file.hpp"
#include "rollkin/io/text_position.hpp"
#include "rollkin/io/units.hpp"
#include "rollkin/io/format.hpp"

#include "segment_geometry.hpp"
#include "svg_detail.hpp"

#include <pugixml.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>

#include <Eigen/Core>

namespace rollkin::io {
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

/// The shapes rollkin reads as contours.
bool is_shape(const std::string& kind) {
  static const char* shapes[] = {"path", "circle", "ellipse", "rect", "line", "polyline", "polygon"};
  return std::any_of(std::begin(shapes), std::end(shapes), [&](const char* s) { return kind == s; });
}

/// Elements whose content is drawn only where something references it (SVG 1.1, 5.3, 5.5, 14.3, 14.4, 11.6, 13.3).
bool is_referenced_only(const std::string& kind) {
  return kind == "defs" || kind == "symbol" || kind == "clipPath" || kind == "mask" || kind == "marker" ||
         kind == "pattern";
}

/// Line numbers of byte offsets without rescanning the text for every element.
class LineIndex {
 public:
  explicit LineIndex(const std::string& text) {
    for (std::size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') newlines_.push_back(i);
  }
  std::size_t line(std::ptrdiff_t offset) const {
    const std::size_t o = static_cast<std::size_t>(std::max<std::ptrdiff_t>(offset, 0));
    return static_cast<std::size_t>(std::lower_bound(newlines_.begin(), newlines_.end(), o) - newlines_.begin()) + 1;
  }

 private:
  std::vector<std::size_t> newlines_;
};

/// The parsed document with what every step needs: its text, file label, ids and line numbers.
struct Document {
  const std::string& text;
  const std::string& file;
  pugi::xml_node root;
  LineIndex lines;
  std::map<std::string, std::vector<pugi::xml_node>> ids;  // every element of each id, in document order

  Document(const std::string& t, const std::string& f, pugi::xml_node r) : text(t), file(f), root(r), lines(t) {
    for_each_element(root, [&](const pugi::xml_node& n) {
      if (n.attribute("id")) ids[n.attribute("id").value()].push_back(n);
    });
  }
  std::string location(const pugi::xml_node& n) const {
    const std::string id = n.attribute("id").value();
    return "line " + std::to_string(lines.line(n.offset_debug())) + ", " +
           (id.empty() ? "<" + local_name(n) + ">" : local_name(n) + " \"" + id + "\"");
  }
  Where where(const pugi::xml_node& n) const { return Where{file, location(n)}; }
};

/// An XML entity reference left in the element content of a structural element (pugixml does not read the
/// DOCTYPE's entity declarations): what it stands for is missing from the drawing.
std::string unexpanded_entity(const Document& doc, const pugi::xml_node& container) {
  for (const pugi::xml_node c : container.children()) {
    if (c.type() != pugi::node_pcdata) continue;
    const std::string t = c.value();
    const std::size_t amp = t.find('&');
    if (amp == std::string::npos) continue;
    const std::size_t semi = t.find(';', amp);
    const std::string ref = t.substr(amp, semi == std::string::npos ? 20 : semi - amp + 1);
    return "the XML entity reference " + ref + " in " + doc.location(container) +
           " is not expanded: XML entities are not read; write the element into the file";
  }
  return "";
}

/// One value of transform-origin: a length in user units (CSS Transforms 1, 6.1; the reference box is the
/// view box, whose origin is the user coordinate system's, CSS Transforms 1, 7.1).
double origin_value(const std::string& word, const std::string& text, const Where& where) {
  const Length l = parse_length(word, "transform-origin", where);
  if (l.unit == "%")
    where.fail("transform-origin=\"" + text + "\": a percentage is relative to a reference box rollkin does not "
               "resolve; give the origin in user units, e.g. transform-origin=\"10 20\"");
  return l.unit.empty() ? l.value : l.value * *metres_per(l.unit) / *metres_per("px");
}

/// The point transform-origin names: "x y" or "x y 0", lengths in user units; keywords are refused.
P transform_origin(const std::string& text, const Where& where) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  for (const std::string& w : words)
    if (!w.empty() && std::isalpha(static_cast<unsigned char>(w.front())))
      where.fail("transform-origin=\"" + text + "\": the keyword \"" + w + "\" is relative to a reference box "
                 "rollkin does not resolve; give the origin in user units, e.g. transform-origin=\"10 20\"");
  if (words.size() < 2 || words.size() > 3)
    where.fail("transform-origin=\"" + text + "\" is not \"x y\" (two lengths in user units); give both, e.g. "
               "transform-origin=\"10 20\"");
  if (words.size() == 3 && origin_value(words[2], text, where) != 0)
    where.fail("transform-origin=\"" + text + "\" has a non-zero z, which has no meaning in a 2D drawing");
  return P(origin_value(words[0], text, where), origin_value(words[1], text, where));
}

/// The element's own transform: its transform attribute about its transform-origin (CSS Transforms 1, 6.1:
/// translate(origin) transform translate(-origin)). CSS transforms and other transform boxes are errors.
Affine own_transform(const pugi::xml_node& n, const Document& doc, std::size_t& count) {
  const auto where = [&] { return doc.where(n); };
  if (const std::string p = css_transform_property(n.attribute("style").value()); !p.empty())
    where().fail("has a CSS transform (" + p + ") in style=\"" + std::string(n.attribute("style").value()) +
                 "\", which rollkin does not apply; use the transform attribute instead");
  if (const pugi::xml_attribute box = n.attribute("transform-box"); box && trimmed(box.value()) != "view-box")
    where().fail("has transform-box=\"" + std::string(box.value()) +
                 "\", which rollkin does not apply; remove it (the default, view-box, is what rollkin applies)");
  const pugi::xml_attribute t = n.attribute("transform");
  if (!t) return Affine{};
  if (n == doc.root) where().fail("the root <svg> has a transform attribute, which rollkin does not apply; move it to a <g>");
  const Where w = where();
  Affine m = parse_transform(t.value(), w);
  if (const pugi::xml_attribute o = n.attribute("transform-origin")) {
    const P origin = transform_origin(o.value(), w);
    m = Affine::translate(origin.x(), origin.y()) * m * Affine::translate(-origin.x(), -origin.y());
  }
  ++count;
  return m;
}

/// The child a <switch> draws: its first direct child that renders and whose conditions hold (SVG 1.1, 5.8.2;
/// requiredExtensions: rollkin supports none, so any value fails; requiredFeatures always holds, as in SVG 2;
/// systemLanguage depends on the viewer and is an error). Null when none does.
pugi::xml_node switch_choice(const pugi::xml_node& sw, const Document& doc) {
  static const char* rendering[] = {"g", "a", "use", "switch", "svg", "path", "circle", "ellipse", "rect", "line",
                                    "polyline", "polygon", "text", "image", "foreignObject"};
  for (const pugi::xml_node c : sw.children()) {
    if (c.type() != pugi::node_element) continue;
    const std::string kind = local_name(c);
    if (std::none_of(std::begin(rendering), std::end(rendering), [&](const char* r) { return kind == r; })) continue;
    if (c.attribute("requiredExtensions")) continue;
    if (const pugi::xml_attribute lang = c.attribute("systemLanguage"))
      doc.where(c).fail("which child of the <switch> (" + doc.location(sw) + ") is drawn depends on the viewer's "
                        "language (systemLanguage=\"" + std::string(lang.value()) + "\"); take the element you mean "
                        "out of the <switch>");
    if (kind == "foreignObject")
      doc.where(c).fail("the <switch> (" + doc.location(sw) + ") draws a <foreignObject>, which has no contour. "
                        "Illustrator writes such a switch with \"Preserve Illustrator Editing Capabilities\": save "
                        "the SVG with that option turned off");
    return c;
  }
  return pugi::xml_node{};
}

/// One shape element as drawn: once in place, once more for every <use> that clones it.
struct Drawn {
  pugi::xml_node element;
  Affine to_root;                      // the element's user coordinates -> the root's user coordinates
  std::size_t transforms = 0;          // transform attributes applied (for --verbose)
  std::string via;                     // " (drawn by line 20, use "u1")" for a clone, else ""
  std::size_t owner = 0;               // its innermost owner in Owners (below)
};

/// What draws each shape in the document tree (the element itself, its groups, the outermost <use> of a clone
/// and that <use>'s groups): a list of (element, index of the next owner outwards), shared by all shapes.
struct Owners {
  static constexpr std::size_t none = static_cast<std::size_t>(-1);
  std::vector<std::pair<pugi::xml_node, std::size_t>> links;

  std::size_t add(const pugi::xml_node& n, std::size_t outer) {
    links.emplace_back(n, outer);
    return links.size() - 1;
  }
};

/// Shapes drawn and their owners.
struct DrawnSet {
  std::vector<Drawn> drawn;
  Owners owners;
};

/// Bounds of the walk: <use> nesting (clones of clones multiply), the count of drawn shapes, and the nesting of
/// elements below the selected one (the walk recurses: 256 levels keep it far inside the stack also under
/// AddressSanitizer, whose frames are several times larger; at 2000 its 8 MB overflowed).
constexpr std::size_t kMaxUseDepth = 32;
constexpr std::size_t kMaxDrawn = 100000;
constexpr std::size_t kMaxNesting = 256;

/// Walks the rendering tree below an element, expanding <use> and <switch> (SVG 1.1, 5.6, 5.8.2).
class DrawnCollector {
 public:
  explicit DrawnCollector(const Document& doc) : doc_(doc) {}

  /// The element drawn with `parent` mapping its parent's coordinates to the root's. `owner`: its innermost
  /// ancestor in the document tree that draws it (in set.owners), when it is drawn in place.
  void element(const pugi::xml_node& n, const Affine& parent, std::size_t transforms, std::size_t owner,
               std::size_t depth = 0) {
    const std::string kind = local_name(n);
    if (depth > kMaxNesting)
      doc_.where(n).fail("is nested more than " + std::to_string(kMaxNesting) + " elements deep below the selected "
                         "element, which rollkin does not walk; select an element further in, or ungroup in the editor");
    if (kind == "svg" && n != doc_.root)
      doc_.where(n).fail("is a nested <svg> viewport, which rollkin does not apply; ungroup it in the editor");
    const bool container = kind == "g" || kind == "a" || kind == "switch" || kind == "svg";
    if (!container && !is_shape(kind) && kind != "use") return;  // not drawn, or nothing with a contour
    const std::size_t mine = uses_.empty() ? set.owners.add(n, owner) : owner;
    const Affine m = parent * own_transform(n, doc_, transforms);
    if (is_shape(kind)) {
      if (set.drawn.size() >= kMaxDrawn)
        doc_.where(n).fail("draws more than " + std::to_string(kMaxDrawn) + " shapes (through nested <use>); "
                           "select one group or clone by its id");
      set.drawn.push_back({n, m, transforms, via_, uses_.empty() ? mine : use_owner_});
      return;
    }
    if (kind == "use") return use(n, m, transforms, mine, depth);
    if (const std::string e = unexpanded_entity(doc_, n); !e.empty()) doc_.where(n).fail(e);
    if (kind == "switch") {
      if (const pugi::xml_node c = switch_choice(n, doc_)) element(c, m, transforms, mine, depth + 1);
      return;
    }
    for (const pugi::xml_node c : n.children())
      if (c.type() == pugi::node_element) element(c, m, transforms, mine, depth + 1);
  }

  DrawnSet set;

 private:
  /// <use>: its transform, then translate(x, y) (SVG 2, 5.6), then the referenced element, or a <symbol>'s
  /// children through its viewBox (SVG 1.1, 5.5 and 7.8).
  void use(const pugi::xml_node& n, Affine m, std::size_t transforms, std::size_t owner, std::size_t depth) {
    const Where where = doc_.where(n);
    const std::string href = href_of(n);
    if (href.empty()) where.fail("has no href; expected href=\"#id\" of the element it clones");
    if (href.front() != '#')
      where.fail("references \"" + href + "\", outside this file; rollkin follows references within the file "
                 "(href=\"#id\")");
    const auto target = doc_.ids.find(href.substr(1));
    if (target == doc_.ids.end()) where.fail("references \"" + href + "\", which is not in the file");
    if (target->second.size() > 1)
      where.fail("references \"" + href + "\", an id used by " + std::to_string(target->second.size()) +
                 " elements (ids must be unique); rename the others in the editor");
    if (std::find(uses_.begin(), uses_.end(), n) != uses_.end()) {
      std::string cycle;
      for (const pugi::xml_node& u : uses_) cycle += doc_.location(u) + " -> ";
      where.fail("is part of a <use> cycle (" + cycle + doc_.location(n) + "): the clone contains itself; break "
                 "the cycle in the editor");
    }
    if (uses_.size() >= kMaxUseDepth)
      where.fail("nests <use> clones more than " + std::to_string(kMaxUseDepth) + " deep; unlink some clones "
                 "in the editor (Edit > Clone > Unlink Clone)");
    m = m * Affine::translate(user_length(n, "x", where, 0.0), user_length(n, "y", where, 0.0));
    const pugi::xml_node t = target->second.front();
    const std::string saved_via = via_;
    if (uses_.empty()) use_owner_ = owner;
    via_ = " (drawn by " + doc_.location(n) + ")" + via_;
    uses_.push_back(n);
    if (local_name(t) == "symbol") {
      m = m * own_transform(t, doc_, transforms) * symbol_viewbox(n, t);
      if (const std::string e = unexpanded_entity(doc_, t); !e.empty()) doc_.where(t).fail(e);
      for (const pugi::xml_node c : t.children())
        if (c.type() == pugi::node_element) element(c, m, transforms, owner, depth + 1);
    } else {
      element(t, m, transforms, owner, depth + 1);
    }
    uses_.pop_back();
    via_ = saved_via;
  }

  /// A <symbol>'s viewBox mapped onto the <use>'s width and height (SVG 1.1, 5.6 and 7.8); identity without a
  /// viewBox (the symbol's content is then drawn in the <use>'s coordinates).
  Affine symbol_viewbox(const pugi::xml_node& use, const pugi::xml_node& symbol) const {
    const Where where = doc_.where(symbol);
    for (const char* a : {"x", "y"})
      if (symbol.attribute(a) && user_length(symbol, a, where, 0.0) != 0)
        where.fail(std::string("has ") + a + "=\"" + symbol.attribute(a).value() + "\", which rollkin does not "
                   "apply; position the symbol with the <use>'s x and y instead");
    const pugi::xml_attribute vb_attr = symbol.attribute("viewBox");
    if (!vb_attr) return Affine{};
    const std::vector<double> vb = number_list(vb_attr.value(), "viewBox", where);
    if (vb.size() != 4 || !(vb[2] > 0) || !(vb[3] > 0))
      where.fail(std::string("viewBox=\"") + vb_attr.value() +
                 "\" is not \"min-x min-y width height\" with a positive width and height");
    const Where use_where = doc_.where(use);
    double size[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
      const char* name = k == 0 ? "width" : "height";
      const pugi::xml_node from = use.attribute(name) ? use : symbol;
      if (!from.attribute(name))
        use_where.fail(std::string("clones the <symbol> ") + doc_.location(symbol) + ", which has a viewBox, "
                       "without " + name + ": the symbol would fill 100% of the viewport, which rollkin does not "
                       "resolve; give the <use> width and height in user units");
      size[k] = user_length(from, name, from == use ? use_where : where, std::nullopt);
      if (!(size[k] > 0)) (from == use ? use_where : where).fail(std::string(name) + " must be positive");
    }
    return viewbox_map(vb, size[0], size[1], symbol.attribute("preserveAspectRatio").value(), where);
  }

  const Document& doc_;
  std::vector<pugi::xml_node> uses_;        // the <use> elements being expanded, outermost first
  std::size_t use_owner_ = Owners::none;    // the outermost <use> being expanded, in set.owners
  std::string via_;
};

/// The <use> elements that reference `n` or one of its ancestors, for the message about an element that is
/// drawn only through them.
std::string uses_of(const Document& doc, const pugi::xml_node& n) {
  std::vector<std::string> hrefs;
  for (pugi::xml_node a = n; a && a != doc.root; a = a.parent())
    if (a.attribute("id")) hrefs.push_back("#" + std::string(a.attribute("id").value()));
  std::string list;
  std::size_t count = 0;
  for_each_element(doc.root, [&](const pugi::xml_node& u) {
    if (local_name(u) != "use" || std::find(hrefs.begin(), hrefs.end(), href_of(u)) == hrefs.end()) return;
    if (++count <= 10) list += (list.empty() ? "" : ", ") + doc.location(u);
  });
  return list.empty() ? "no <use> references it" : "select the clone by its <use>'s id instead: " + list;
}

/// The shapes the element `selected` draws where it stands in the document: its ancestors' transforms
/// (innermost first, SVG 1.1, 7.5) applied, checked to draw it at all.
DrawnSet drawn_by(const Document& doc, const pugi::xml_node& selected) {
  Affine m;
  std::size_t transforms = 0;
  std::vector<pugi::xml_node> ancestors;
  for (pugi::xml_node child = selected, n = selected.parent(); n && n != doc.root; child = n, n = n.parent()) {
    const std::string kind = local_name(n);
    if (is_referenced_only(kind))
      doc.where(selected).fail("the element is inside <" + kind + "> (" + doc.location(n) + "): it is drawn only "
                               "where a <use> clones it; " + uses_of(doc, selected));
    if (kind == "switch" && switch_choice(n, doc) != child)
      doc.where(selected).fail("the element is not drawn: the <switch> (" + doc.location(n) + ") draws only its "
                               "first child that renders, which is " +
                               (switch_choice(n, doc) ? doc.location(switch_choice(n, doc)) : std::string("none")) +
                               "; select an element of that child or take this one out of the <switch>");
    if (kind == "svg")
      doc.where(selected).fail("the element is inside a nested <svg> viewport (" + doc.location(n) +
                               "), which rollkin does not apply; ungroup it in the editor");
    if (kind == "use" || is_shape(kind)) return {};  // content of a shape or of a <use> is not drawn
    try {
      m = own_transform(n, doc, transforms) * m;
    } catch (const InputError& e) {
      throw InputError(doc.file, doc.location(selected) + " (its ancestor " + doc.location(n) + ")", e.message());
    }
    ancestors.push_back(n);
  }
  if (doc.root.attribute("transform")) own_transform(doc.root, doc, transforms);
  DrawnCollector collect(doc);
  std::size_t owner = Owners::none;
  for (auto a = ancestors.rbegin(); a != ancestors.rend(); ++a) owner = collect.set.owners.add(*a, owner);
  collect.element(selected, m, transforms, owner);
  return std::move(collect.set);
}

/// Everything the document draws.
DrawnSet drawn_in_document(const Document& doc) {
  std::size_t transforms = 0;
  own_transform(doc.root, doc, transforms);
  DrawnCollector collect(doc);
  if (const std::string e = unexpanded_entity(doc, doc.root); !e.empty()) doc.where(doc.root).fail(e);
  for (const pugi::xml_node c : doc.root.children())
    if (c.type() == pugi::node_element) collect.element(c, Affine{}, 0, Owners::none);
  return std::move(collect.set);
}

/// The document's <style> sheets must not set CSS transforms (they could apply to any element).
void check_style_sheets(const Document& doc) {
  for_each_element(doc.root, [&](const pugi::xml_node& n) {
    if (local_name(n) == "style" && !css_transform_property(n.text().get()).empty())
      doc.where(n).fail("the document's <style> sheet sets a CSS transform (" + css_transform_property(n.text().get()) +
                        "), which rollkin does not apply; use transform attributes instead");
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
  // One zero radius: the path equivalent's corner arcs have a zero radius, which SVG draws as straight lines
  // (SVG 1.1, F.6.2) along the sides: the rect has square corners.
  if (rx == 0 || ry == 0) rx = ry = 0;
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
  if (v.size() < 4)
    where.fail("points=\"" + trimmed(n.attribute("points").value()) + "\" has " + std::to_string(v.size() / 2) +
               " point(s); a " + kind + " needs at least 2 points (one edge): add the missing points or delete the element");
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

std::vector<SvgSubpath> path_geometry(const pugi::xml_node& n, const std::string& file, const Where& where) {
  if (!n.attribute("d")) where.fail("has no d attribute; expected the path data d=\"M ...\"");
  std::vector<SvgSubpath> subs = svg_detail::parse_path_data(n.attribute("d").value(), file, where.location);
  if (subs.empty()) where.fail("the path data draws nothing (no segment of non-zero length)");
  return subs;
}

/// The element's subpaths in its own user coordinates (a <path> may have several; the other shapes one).
std::vector<SvgSubpath> element_geometry(const pugi::xml_node& n, const std::string& kind, const std::string& file,
                                         const Where& where) {
  auto positive = [&](double r, const char* name) {
    if (!(r > 0)) where.fail(std::string(name) + " must be positive, got " + fmt(r));
    return r;
  };
  if (kind == "path") return path_geometry(n, file, where);
  if (kind == "circle") {
    const double r = positive(user_length(n, "r", where, std::nullopt), "r");
    return {ellipse_geometry(user_length(n, "cx", where, 0.0), user_length(n, "cy", where, 0.0), r, r, kind)};
  }
  if (kind == "ellipse") {
    const bool has_rx = n.attribute("rx") && trimmed(n.attribute("rx").value()) != "auto";
    const bool has_ry = n.attribute("ry") && trimmed(n.attribute("ry").value()) != "auto";
    if (!has_rx && !has_ry) where.fail("has neither rx nor ry; expected the radii rx=\"...\" ry=\"...\"");
    const double rx = positive(user_length(n, has_rx ? "rx" : "ry", where, std::nullopt), "rx");
    const double ry = positive(user_length(n, has_ry ? "ry" : "rx", where, std::nullopt), "ry");
    return {ellipse_geometry(user_length(n, "cx", where, 0.0), user_length(n, "cy", where, 0.0), rx, ry, kind)};
  }
  if (kind == "rect") return {rect_geometry(n, where)};
  if (kind == "line") {
    const P a(user_length(n, "x1", where, 0.0), user_length(n, "y1", where, 0.0));
    const P b(user_length(n, "x2", where, 0.0), user_length(n, "y2", where, 0.0));
    if (a == b) where.fail("has zero length (x1, y1 = x2, y2); a contour needs a non-zero extent");
    SvgSubpath g;
    g.segments = {Segment{{a, b}, {}}};
    g.origins = {"the line"};
    return {g};
  }
  if (kind == "polyline" || kind == "polygon") return {poly_geometry(n, kind == "polygon", kind, where)};
  where.fail("is a <" + kind + ">, which rollkin does not read as a contour; expected path, circle, ellipse, rect, "
             "line, polyline or polygon (convert it to a path in the editor: Path > Object to Path)");
}

// ---- finding the element --------------------------------------------------------------------------------

/// Every unexpanded entity reference in the document's structure, for the message about a missing id.
std::string entity_note(const Document& doc) {
  std::string note;
  for_each_element(doc.root, [&](const pugi::xml_node& n) {
    if (note.empty()) note = unexpanded_entity(doc, n);
  });
  return note.empty() ? "" : "; " + note;
}

pugi::xml_node find_by_id(const Document& doc, const std::string& id) {
  const auto hit = doc.ids.find(id);
  if (hit != doc.ids.end() && hit->second.size() > 1)
    throw InputError(doc.file, doc.location(hit->second[1]),
                     "the id \"" + id + "\" is used by " + std::to_string(hit->second.size()) +
                         " elements (ids must be unique); rename the others in the editor");
  if (hit == doc.ids.end()) {
    std::vector<std::string> known;
    for_each_element(doc.root, [&](const pugi::xml_node& n) {
      if (n.attribute("id") && is_shape(local_name(n)) && known.size() < 20) known.push_back(n.attribute("id").value());
    });
    std::string list;
    for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
    throw InputError(doc.file, "", "no element with id=\"" + id + "\"" +
                                       (list.empty() ? " (the file has no path or shape element with an id)"
                                                     : "; ids of path and shape elements: " + list) +
                                       entity_note(doc));
  }
  return hit->second.front();
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

// ---- from drawn elements to shapes in scene units -------------------------------------------------------

/// Every subpath of every drawn element, mapped by steps 1-5, with the selector that picks it (its nearest
/// owner with a unique id and its index among what that owner draws).
std::vector<SvgShape> drawn_shapes(const Document& doc, const DrawnSet& set, const SvgReadOptions& options) {
  const Viewport vp = root_viewport(doc.root, doc.where(doc.root));
  double unit_factor = 1;
  if (vp.metres && options.metres_per_scene_unit) unit_factor = *vp.metres / *options.metres_per_scene_unit;
  const double k = unit_factor * options.scale;
  std::vector<SvgShape> out;
  std::vector<const Drawn*> from;
  for (const Drawn& d : set.drawn) {
    const std::string element_at = doc.location(d.element);
    const Where where{doc.file, element_at + d.via};
    const std::string kind = local_name(d.element);
    std::vector<SvgSubpath> subs = element_geometry(d.element, kind, doc.file, where);
    const Affine total = Affine::scale(k, options.flip_y ? -k : k) * vp.map * d.to_root;
    if (total.degenerate())
      where.fail("the combined transform (element, groups, clones, viewBox, scale) is degenerate; expected an "
                 "invertible map");
    for (std::size_t i = 0; i < subs.size(); ++i) {
      SvgSubpath& g = subs[i];
      SvgShape shape;
      shape.file = doc.file;
      shape.id = d.element.attribute("id").value();
      shape.element = kind;
      shape.subpath = i + 1;
      shape.subpaths = subs.size();
      shape.location = element_at + (subs.size() > 1 ? ", subpath " + std::to_string(i + 1) : "") + d.via;
      const Where at{doc.file, shape.location};
      if (!all_finite(g.segments))
        at.fail("the shape's control points overflow (a coordinate or radius near the largest double); expected "
                "coordinates of a drawing");
      for (Segment& s : g.segments)
        for (P& p : s.points) p = total(p);
      if (!all_finite(g.segments))
        at.fail("the transforms, viewBox and scale map the shape beyond the largest double (overflow); expected "
                "the transforms of a drawing");
      // In the coordinates BezierPath gets (a non-uniform transform changes which pieces are short), e.g. a
      // polygon whose last point repeats the first to round-off.
      svg_detail::merge_short_segments(g);
      if (g.segments.empty()) at.fail("draws nothing (every segment has zero length)");
      shape.segments = std::move(g.segments);
      shape.origins = std::move(g.origins);
      shape.closed = g.closed;
      shape.metres_per_file_unit = vp.metres;
      shape.file_unit = vp.unit;
      shape.unit_factor = unit_factor;
      shape.corners = find_corners(shape, options.corner_tolerance);
      shape.conversion = conversion_line(shape, d.transforms, vp, options);
      out.push_back(std::move(shape));
      from.push_back(&d);
    }
  }
  // Selectors: an owner with a unique id draws the shapes listing it, in this order (drawn_by walks alike).
  // Counted per owner link (each link is one element of the document tree, drawing the shapes below it).
  const auto& links = set.owners.links;
  std::vector<std::size_t> drawn_count(links.size(), 0), seen(links.size(), 0);
  for (const Drawn* d : from)
    for (std::size_t o = d->owner; o != Owners::none; o = links[o].second) ++drawn_count[o];
  for (std::size_t s = 0; s < out.size(); ++s) {
    for (std::size_t o = from[s]->owner; o != Owners::none; o = links[o].second) ++seen[o];
    for (std::size_t o = from[s]->owner; o != Owners::none; o = links[o].second) {
      const pugi::xml_node& n = links[o].first;
      const auto ids = doc.ids.find(n.attribute("id").value());
      if (!n.attribute("id") || ids == doc.ids.end() || ids->second.size() != 1) continue;
      out[s].selector_id = n.attribute("id").value();
      out[s].selector_subpath = drawn_count[o] > 1 ? seen[o] : 0;
      break;
    }
  }
  return out;
}

std::string point_text(const P& p) { return "(" + fmt(p.x() + 0.0) + ", " + fmt(p.y() + 0.0) + ")"; }  // no "-0"

/// "1: line 3, path "a", subpath 1 (closed, from (0, 0)); 2: ..." (at most 20).
std::string candidate_list(const std::vector<SvgShape>& all) {
  std::string list;
  for (std::size_t k = 0; k < all.size() && k < 20; ++k)
    list += (k ? "; " : "") + std::to_string(k + 1) + ": " + all[k].location + " (" + (all[k].closed ? "closed" : "open") +
            ", from " + point_text(all[k].segments.front().points.front()) + ")";
  if (all.size() > 20) list += "; ...";
  return list;
}

/// The one subpath the options select among those `what` draws (docs/scene_format.md, "SVG contours").
SvgShape select_shape(std::vector<SvgShape> all, const SvgReadOptions& o, const std::string& file,
                      const std::string& location, const std::string& what) {
  const auto fail = [&](const std::string& m) -> void { throw InputError(file, location, m); };
  if (all.empty()) fail(what + " draws no shape (path, circle, ellipse, rect, line, polyline or polygon)");
  if (o.subpath && o.near) fail("give \"subpath\" or \"near\", not both");
  const std::string count = what + " draws " + std::to_string(all.size()) + " subpath(s): " + candidate_list(all);
  if (o.subpath) {
    if (*o.subpath < 1 || *o.subpath > all.size())
      fail("subpath " + std::to_string(*o.subpath) + " does not exist (subpaths count from 1): " + count);
    return std::move(all[*o.subpath - 1]);
  }
  if (o.near) {
    std::vector<std::pair<double, std::size_t>> d;
    double extent = 0;
    for (std::size_t k = 0; k < all.size(); ++k) {
      d.emplace_back(io::distance_to_segments(all[k].segments, *o.near), k);
      extent = std::max(extent, svg_detail::control_extent(all[k].segments));
    }
    std::sort(d.begin(), d.end());
    if (d.size() > 1 && d[1].first - d[0].first <= svg_detail::kNearTie * d[0].first + 1e-9 * extent)
      fail("near " + point_text(*o.near) + " is about equally near " + all[d[0].second].location + " (distance " +
           fmt(d[0].first) + ") and " + all[d[1].second].location + " (distance " + fmt(d[1].first) +
           "); give a point closer to the one you mean, or select it by id and \"subpath\"");
    return std::move(all[d[0].second]);
  }
  if (all.size() > 1)
    fail(count + "; select one with \"subpath\": k (1 to " + std::to_string(all.size()) + ") or \"near\": [x, y]");
  return std::move(all.front());
}

}  // namespace

namespace {

/// Every subpath the element `id` draws (the document for ""), and the element's location for messages.
std::vector<SvgShape> shapes_of(const std::string& text, const std::string& id, const SvgReadOptions& options,
                                const std::string& file, std::string& location) {
  if (!(options.scale > 0) || !std::isfinite(options.scale))
    throw InputError(file, "", "the scale factor must be positive and finite, got " + fmt(options.scale));
  if (options.metres_per_scene_unit && !(*options.metres_per_scene_unit > 0))
    throw InputError(file, "", "the scene's length unit must be a positive number of metres");
  pugi::xml_document xml;
  const Document doc(text, file, parse_document(xml, text, file));
  check_style_sheets(doc);
  if (id.empty()) return drawn_shapes(doc, drawn_in_document(doc), options);
  const pugi::xml_node selected = find_by_id(doc, id);
  location = doc.location(selected);
  if (selected == doc.root) return drawn_shapes(doc, drawn_in_document(doc), options);
  const std::string kind = local_name(selected);
  if (!is_shape(kind) && kind != "g" && kind != "a" && kind != "use" && kind != "switch")
    doc.where(selected).fail("is a <" + kind + ">, which rollkin does not read as a contour; expected path, circle, "
                             "ellipse, rect, line, polyline or polygon, or a group or <use> that draws them (convert "
                             "it to a path in the editor: Path > Object to Path)");
  return drawn_shapes(doc, drawn_by(doc, selected), options);
}

}  // namespace

std::vector<SvgShape> read_svg_shapes_from_text(const std::string& text, const std::string& id,
                                                const SvgReadOptions& options, const std::string& file) {
  std::string location;
  return shapes_of(text, id, options, file, location);
}

std::vector<SvgShape> read_svg_shapes(const std::string& svg_file, const std::string& id, const SvgReadOptions& options) {
  return read_svg_shapes_from_text(io::read_input_file(svg_file, "the SVG file"), id, options, svg_file);
}

SvgShape read_svg_shape_from_text(const std::string& text, const std::string& id, const SvgReadOptions& options,
                                  const std::string& file) {
  if (id.empty() && !options.near && !options.subpath)
    throw InputError(file, "", "no element id given; give the id of the element, or \"near\": [x, y] (or \"subpath\": "
                               "k) to take the subpath of the drawing passing nearest to a point (or its k-th)");
  std::string location;
  std::vector<SvgShape> all = shapes_of(text, id, options, file, location);
  return select_shape(std::move(all), options, file, location, id.empty() ? "the document" : "the element");
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

}  // namespace rollkin::io
