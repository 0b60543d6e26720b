// SVG documents (io/svg/reader.hpp): the element selected by id (or the whole document), the shapes it draws
// (svg/clones.cpp) as exact Bezier segments in their own user coordinates, mapped to scene units (steps 1-5:
// svg/document_map.cpp), with their corners; one of them chosen (svg/selection.cpp). The entry points.
#include "rollkin/io/svg/reader.hpp"

#include "rollkin/io/input_file.hpp"
#include "rollkin/io/text_position.hpp"

#include "detail.hpp"
#include "document.hpp"

#include <sstream>

namespace rollkin::io {
namespace {

using namespace svg_detail;
using Segment = BezierSegment<double>;

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
  if (kind == element::path) return path_geometry(n, file, where);
  if (kind == element::circle) {
    const double r = positive(user_length(n, "r", where, std::nullopt), "r");
    return {ellipse_geometry(user_length(n, "cx", where, 0.0), user_length(n, "cy", where, 0.0), r, r, kind)};
  }
  if (kind == element::ellipse) {
    const bool has_rx = n.attribute("rx") && trimmed(n.attribute("rx").value()) != "auto";
    const bool has_ry = n.attribute("ry") && trimmed(n.attribute("ry").value()) != "auto";
    if (!has_rx && !has_ry) where.fail("has neither rx nor ry; expected the radii rx=\"...\" ry=\"...\"");
    const double rx = positive(user_length(n, has_rx ? "rx" : "ry", where, std::nullopt), "rx");
    const double ry = positive(user_length(n, has_ry ? "ry" : "rx", where, std::nullopt), "ry");
    return {ellipse_geometry(user_length(n, "cx", where, 0.0), user_length(n, "cy", where, 0.0), rx, ry, kind)};
  }
  if (kind == element::rect) return {rect_geometry(n, where)};
  if (kind == element::line) {
    const P a(user_length(n, "x1", where, 0.0), user_length(n, "y1", where, 0.0));
    const P b(user_length(n, "x2", where, 0.0), user_length(n, "y2", where, 0.0));
    if (a == b) where.fail("has zero length (x1, y1 = x2, y2); a contour needs a non-zero extent");
    SvgSubpath g;
    g.segments = {Segment{{a, b}, {}}};
    g.origins = {"the line"};
    return {g};
  }
  if (kind == element::polyline || kind == element::polygon) return {poly_geometry(n, kind == element::polygon, kind, where)};
  where.fail("is a <" + kind + ">, which rollkin does not read as a contour; expected " + shape_names() +
             " (convert it to a path in the editor: Path > Object to Path)");
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
  if (local_name(root) != element::svg)
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
      shape.hidden = d.hidden;
      out.push_back(std::move(shape));
      from.push_back(&d);
    }
  }
  // Selectors: an owner with a unique id draws the shapes listing it, in this order (drawn_by walks alike).
  // Counted per owner link (each link is one element of the document tree, drawing the shapes below it), among
  // the shapes its own walk draws: its own display and visibility and its ancestors' are not applied there, so
  // it draws a shape unless what hides the shape lies strictly inside it (document.hpp, Hiding): owners
  // from the shape out to its hider draw it, owners beyond do not, none draws a shape hidden inside a clone.
  const auto& links = set.owners.links;
  const auto shown_from = [&](const Drawn& d, auto&& visit) {  // visit(o, shown) for each owner outwards
    bool passed = d.hider == Hiding::inside;
    for (std::size_t o = d.owner; o != Owners::none; o = links[o].second) {
      if (!visit(o, d.hider == Hiding::none || !passed)) return;
      if (o == d.hider) passed = true;
    }
  };
  std::vector<std::size_t> drawn_count(links.size(), 0), seen(links.size(), 0);
  for (const Drawn* d : from)
    shown_from(*d, [&](std::size_t o, bool shown) { return drawn_count[o] += shown, true; });
  for (std::size_t s = 0; s < out.size(); ++s) {
    shown_from(*from[s], [&](std::size_t o, bool shown) { return seen[o] += shown, true; });
    shown_from(*from[s], [&](std::size_t o, bool shown) {
      const pugi::xml_node& n = links[o].first;
      const auto ids = doc.ids.find(n.attribute("id").value());
      if (!shown || !n.attribute("id") || ids == doc.ids.end() || ids->second.size() != 1) return true;
      out[s].selector_id = n.attribute("id").value();
      out[s].selector_subpath = drawn_count[o] > 1 ? seen[o] : 0;
      return false;
    });
  }
  return out;
}

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
  const bool draws_shapes = is_shape(kind) || kind == element::use || (is_container(kind) && kind != element::svg);
  if (!draws_shapes)
    doc.where(selected).fail("is a <" + kind + ">, which rollkin does not read as a contour; expected " + shape_names() +
                             ", or a group or <use> that draws them (convert it to a path in the editor: Path > "
                             "Object to Path)");
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
