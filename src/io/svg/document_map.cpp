// SVG documents, the map from an element's coordinates to the root's viewport (io/svg/reader.hpp, steps 1-2):
// lengths and units, transform attributes with their transform-origin, the root viewport (viewBox, width,
// height, preserveAspectRatio), and what must not be silently ignored (CSS transforms, entity references).
#include "document.hpp"

#include "rollkin/io/text_position.hpp"
#include "rollkin/io/units.hpp"

#include "detail.hpp"

#include <cctype>
#include <cstring>
#include <sstream>

namespace rollkin::io::svg_detail {
namespace {

/// Metres per unit of the absolute CSS units (CSS Values 3, 5.2: 1in = 2.54cm = 96px = 72pt = 6pc), from the
/// units table (io/units.hpp); none for any other spelling.
std::optional<double> metres_per(const std::string& unit) {
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

}  // namespace

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

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r\n"), last = s.find_last_not_of(" \t\r\n");
  return first == std::string::npos ? "" : s.substr(first, last - first + 1);
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

namespace {

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

}  // namespace

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

namespace {

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

}  // namespace

/// The first transform-related CSS property a style sets, or "".
std::string css_transform_property(const std::string& style) {
  for (const char* name : {"transform", "transform-origin", "transform-box", "rotate", "scale", "translate"})
    if (has_css_property(style, name)) return name;
  return "";
}

/// The shapes rollkin reads as contours.
bool is_shape(const std::string& kind) {
  static const char* shapes[] = {"path", "circle", "ellipse", "rect", "line", "polyline", "polygon"};
  return std::any_of(std::begin(shapes), std::end(shapes), [&](const char* s) { return kind == s; });
}

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

namespace {

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

}  // namespace

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

}  // namespace rollkin::io::svg_detail
