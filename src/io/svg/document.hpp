// Internal to src/io (not installed): the parsed SVG document and what the parts of the document reader
// (io/svg/reader.hpp) share. svg/document_map.cpp maps the document (lengths and units, transform attributes,
// the root viewport), svg/clones.cpp walks what an element draws (<use>, <symbol>, <switch>),
// svg/selection.cpp chooses one subpath ("subpath", "near"), svg/reader.cpp turns drawn elements into shapes
// in scene units and holds the entry points; svg/names.hpp is the table of element names they dispatch on.
#pragma once

#include "rollkin/io/format.hpp"
#include "rollkin/io/input_error.hpp"
#include "rollkin/io/svg/reader.hpp"
#include "rollkin/io/units.hpp"
#include "rollkin/scalar.hpp"

#include "names.hpp"

#include <pugixml.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rollkin::io::svg_detail {

using P = Vec2<double>;

/// Numbers in messages and notes: 12 significant digits.
inline std::string fmt(double x) { return format_number(x, 12); }

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

std::pair<std::size_t, std::size_t> line_column(const std::string& text, std::ptrdiff_t offset);
std::string local_name(const pugi::xml_node& n);
/// "line L, <kind> "id"" of an element, from the text (for the root before a Document exists).
std::string element_location(const std::string& text, const pugi::xml_node& n);

/// s without leading and trailing white space.
std::string trimmed(const std::string& s);

/// A geometry attribute (cx, r, width, ...) in user units: absolute units are converted as CSS does (1 user
/// unit = 1px); a percentage (relative to the viewport) is an error. `fallback` when absent, if given.
double user_length(const pugi::xml_node& n, const char* name, const Where& where, std::optional<double> fallback);

/// A list of numbers separated by white space and/or commas (points, viewBox).
std::vector<double> number_list(const std::string& s, const std::string& what, const Where& where);

// ---- the root viewport (SVG 1.1, 7.7-7.8) ----------------------------------------------------------------

struct Viewport {
  Affine map;                       // root user units -> viewport units
  std::optional<double> metres;     // metres per viewport unit, when declared
  std::string unit = "user unit";   // name of the viewport unit
  std::string description;          // for the conversion line
};

/// The viewBox-to-viewport map for a viewport of size (w, h) (SVG 1.1, 7.8, preserveAspectRatio).
Affine viewbox_map(const std::vector<double>& vb, double w, double h, const std::string& par_text, const Where& where);

/// The root <svg>'s viewBox, width, height and preserveAspectRatio as a map to viewport units.
Viewport root_viewport(const pugi::xml_node& root, const Where& where);

// ---- the document --------------------------------------------------------------------------------------

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

/// The first transform-related CSS property a style sets, or "".
std::string css_transform_property(const std::string& style);

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
std::string unexpanded_entity(const Document& doc, const pugi::xml_node& container);

/// The element's own transform: its transform attribute about its transform-origin (CSS Transforms 1, 6.1:
/// translate(origin) transform translate(-origin)). CSS transforms and other transform boxes are errors.
Affine own_transform(const pugi::xml_node& n, const Document& doc, std::size_t& count);

// ---- what an element draws (svg/clones.cpp) ----------------------------------------------------------

/// One shape element as drawn: once in place, once more for every <use> that clones it.
struct Drawn {
  pugi::xml_node element;
  Affine to_root;                      // the element's user coordinates -> the root's user coordinates
  std::size_t transforms = 0;          // transform attributes applied (for --verbose)
  std::string via;                     // " (drawn by line 20, use "u1")" for a clone, else ""
  std::size_t owner = 0;               // its innermost owner in Owners (below)
  std::string hidden;                  // why it is not drawn (Hiding::why), or "" when it is
  std::size_t hider = static_cast<std::size_t>(-1);  // Hiding::hider(): the link of what hides it
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

// ---- what is drawn: display and visibility (visibility.cpp) -----------------------------------------

/// What an element's own display and visibility properties say (SVG 1.1, 11.5; the style attribute's
/// declaration over the presentation attribute, CSS 2, 6.4.4). display is not inherited, but display="none"
/// takes the element's whole content out of the drawing; visibility is inherited and a descendant may set it
/// back to visible. Any visibility other than visible, hidden, collapse or inherit is an error naming it.
struct OwnRendering {
  bool display_none = false;
  std::optional<bool> visible;  // its own visibility, when it sets one (not inherit)
  std::string display_why, visibility_why;  // "display=\"none\" on line 4, g \"layer2\""
};
OwnRendering own_rendering(const pugi::xml_node& n, const Document& doc);

/// The document's <style> sheets must not hide or show elements (display: none, a visibility: they could
/// apply to any element, by selectors rollkin does not match): the first such declaration, or "".
std::string css_rendering_property(const std::string& sheet);

/// Whether the shapes below a point of the walk are drawn: the innermost display="none" and the innermost
/// visibility declaration above them, each with the owner link of its element (Owners), or `inside` for an
/// element inside a <use>'s clone (no link of its own: deeper than every link). Rule (docs/reliability.md, "CAD
/// readers (issue 37)"): a hidden shape is no candidate of "near", "subpath" or the only-one choice; only the id
/// of the shape or of an element on the way out to the one that hides it (inclusive) selects it (the selected
/// element's own display and visibility, and its ancestors', are not applied: the user named it).
struct Hiding {
  static constexpr std::size_t none = static_cast<std::size_t>(-1), inside = static_cast<std::size_t>(-2);
  std::size_t display = none, visibility = none;
  bool visibility_hidden = false;
  std::string display_why, visibility_why;

  /// The state below an element with these properties and owner link `link`.
  Hiding below(const OwnRendering& r, std::size_t link) const {
    Hiding h = *this;
    if (r.display_none) h.display = link, h.display_why = r.display_why;
    if (r.visible) h.visibility = link, h.visibility_hidden = !*r.visible, h.visibility_why = r.visibility_why;
    return h;
  }
  bool hidden() const { return display != none || visibility_hidden; }
  /// The innermost element that hides (its link, or `inside`), or none.
  std::size_t hider() const {
    const std::size_t v = visibility_hidden ? visibility : none;
    if (display == none) return v;
    if (v == none) return display;
    return std::max(display, v);  // links deeper in the walk come later; inside is deepest
  }
  std::string why() const {
    if (!hidden()) return "";
    return display != none && (!visibility_hidden || display == hider()) ? display_why : visibility_why;
  }
};

/// Shapes drawn and their owners.
struct DrawnSet {
  std::vector<Drawn> drawn;
  Owners owners;
};

/// The shapes the element `selected` draws where it stands in the document: its ancestors' transforms
/// (innermost first, SVG 1.1, 7.5) applied, checked to draw it at all.
DrawnSet drawn_by(const Document& doc, const pugi::xml_node& selected);

/// Everything the document draws.
DrawnSet drawn_in_document(const Document& doc);

/// The document's <style> sheets must not set CSS transforms (they could apply to any element).
void check_style_sheets(const Document& doc);

// ---- the choice of one subpath (svg/selection.cpp) -----------------------------------------------------

/// The one subpath the options select among those `what` draws (docs/scene_format.md, "SVG contours").
SvgShape select_shape(std::vector<SvgShape> all, const SvgReadOptions& o, const std::string& file,
                      const std::string& location, const std::string& what);

}  // namespace rollkin::io::svg_detail
