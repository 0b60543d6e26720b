// The SVG element names the reader knows, in one table (as usvg keeps svgtree/names.rs), with what each is to
// rollkin. Every dispatch of the reader on an element's name (svg/clones.cpp, svg/document_map.cpp,
// svg/reader.cpp) asks this table; an element it does not list is neither drawn nor walked.
#pragma once

#include <algorithm>
#include <array>
#include <string>
#include <string_view>

namespace rollkin::io::svg_detail {

/// What an element is to the reader.
enum class ElementRole {
  Shape,           // drawn and read as a contour (SVG 2, 9 "Basic shapes"; 8 "Paths")
  Container,       // drawn, its children walked (SVG 1.1, 5.2 <g>, 5.1 <svg>, 5.8 <switch>; 17.1 <a>)
  Clone,           // draws the element it references (SVG 1.1, 5.6 <use>)
  DrawnNoContour,  // drawn but without a contour (text, raster image, foreign content)
  ReferencedOnly,  // its content is drawn only where something references it (SVG 1.1, 5.3, 5.5, 14.3, 14.4, 11.6, 13.3)
  Other,           // not drawn (title, desc, style, metadata, ...): every name not in the table
};

/// The names the dispatches compare with (the table below gives their roles).
namespace element {
inline constexpr std::string_view path = "path", circle = "circle", ellipse = "ellipse", rect = "rect", line = "line",
                                  polyline = "polyline", polygon = "polygon";
inline constexpr std::string_view g = "g", a = "a", switch_ = "switch", svg = "svg", use = "use";
inline constexpr std::string_view symbol = "symbol", style = "style", foreign_object = "foreignObject";
}  // namespace element

struct ElementName {
  std::string_view name;
  ElementRole role;
};

/// The table. The shapes come first, in the order messages list them.
inline constexpr std::array<ElementName, 22> kElementNames{{
    {element::path, ElementRole::Shape},
    {element::circle, ElementRole::Shape},
    {element::ellipse, ElementRole::Shape},
    {element::rect, ElementRole::Shape},
    {element::line, ElementRole::Shape},
    {element::polyline, ElementRole::Shape},
    {element::polygon, ElementRole::Shape},
    {element::g, ElementRole::Container},
    {element::a, ElementRole::Container},
    {element::switch_, ElementRole::Container},
    {element::svg, ElementRole::Container},
    {element::use, ElementRole::Clone},
    {"text", ElementRole::DrawnNoContour},
    {"image", ElementRole::DrawnNoContour},
    {element::foreign_object, ElementRole::DrawnNoContour},
    {"defs", ElementRole::ReferencedOnly},
    {element::symbol, ElementRole::ReferencedOnly},
    {"clipPath", ElementRole::ReferencedOnly},
    {"mask", ElementRole::ReferencedOnly},
    {"marker", ElementRole::ReferencedOnly},
    {"pattern", ElementRole::ReferencedOnly},
    {element::style, ElementRole::Other},
}};

inline ElementRole element_role(std::string_view name) {
  const auto hit = std::find_if(kElementNames.begin(), kElementNames.end(), [&](const ElementName& e) { return e.name == name; });
  return hit == kElementNames.end() ? ElementRole::Other : hit->role;
}

/// The shapes rollkin reads as contours.
inline bool is_shape(std::string_view name) { return element_role(name) == ElementRole::Shape; }
/// The elements whose children the walk visits (a nested <svg> among them is refused where it is met).
inline bool is_container(std::string_view name) { return element_role(name) == ElementRole::Container; }
/// The elements a viewer renders where they stand: the candidates of a <switch> (SVG 1.1, 5.8.2).
inline bool renders(std::string_view name) {
  const ElementRole r = element_role(name);
  return r == ElementRole::Shape || r == ElementRole::Container || r == ElementRole::Clone || r == ElementRole::DrawnNoContour;
}
inline bool is_referenced_only(std::string_view name) { return element_role(name) == ElementRole::ReferencedOnly; }

/// The shapes for messages: "path, circle, ellipse, rect, line, polyline or polygon".
inline std::string shape_names() {
  std::string out;
  std::string_view last;
  for (const ElementName& e : kElementNames) {
    if (e.role != ElementRole::Shape) continue;
    if (!last.empty()) out += (out.empty() ? "" : ", ") + std::string(last);
    last = e.name;
  }
  return out + " or " + std::string(last);
}

}  // namespace rollkin::io::svg_detail
