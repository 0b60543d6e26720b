// The SVG document reader: the elements of an SVG file as exact Bezier segments in scene units (path data:
// io/svg/path_data.hpp).
//
// Documents (read_svg_shape): parsed with pugixml. An element is selected by id: a shape (<path>, <circle>,
// <ellipse>, <rect> with rx/ry rounded corners, <line>, <polyline>, <polygon>) or something that draws shapes
// (<g>, <a>, <use>, <switch>, the root <svg>). Circles, ellipses and rounded corners are quarter arcs, rational
// quadratics of middle weight cos(45 deg), starting at (cx + r, cy) as SVG 2 (10.3-10.5) draws them; a rect
// with one zero radius has square corners (its corner arcs have a zero radius, drawn as lines, F.6.2).
// What an element draws (read_svg_shapes): its subpaths (a <path> may have several: Combine, holes, compound
// paths) and, for a container, those of every shape inside it, in document order, with
//   - <use>: the referenced element (a shape, a group, another <use>) drawn again with the <use>'s transform,
//     then translate(x, y) (SVG 2, 5.6); a referenced <symbol> draws its children through its viewBox mapped
//     onto the <use>'s width and height (or the symbol's own), with preserveAspectRatio (SVG 1.1, 5.5, 7.8).
//     The referenced element is read as it stands in the document when selected by its own id (an element in
//     <defs> or <symbol> is not drawn there: an error that names the <use> elements to select instead).
//     A <use> cycle, a reference outside the file or to a missing or duplicate id, and nesting deeper than 32
//     <use>, or more than 100000 drawn shapes, are errors;
//   - <switch>: only its first child that renders and whose conditions hold (SVG 1.1, 5.8.2): a child with
//     requiredExtensions fails (rollkin supports no extension), requiredFeatures holds (SVG 2 removed it),
//     systemLanguage is an error (the choice would depend on the viewer's language), a <foreignObject> chosen
//     is an error naming Illustrator's "Preserve Illustrator Editing Capabilities" option;
//   - <defs>, <symbol> (not through <use>), <clipPath>, <mask>, <marker>, <pattern>, text and images: nothing;
//   - an element with display="none" (attribute or style; its whole content), or with visibility="hidden" or
//     "collapse" (inherited, a descendant may set it back to visible), also in a clone: read but marked hidden
//     (SvgShape::hidden), no candidate of the choice below; a <style> sheet that sets display: none or a
//     visibility is an error.
// The choice of one subpath (read_svg_shape) among those drawn (not hidden): SvgReadOptions::subpath k (1-based, in the order
// above), or SvgReadOptions::near (the subpath passing nearest to the point, in the coordinates the contour is
// read in: after steps 1-5; an error naming both when the second nearest is within 1% of the distance, plus
// 1e-9 of the drawing's size), or the only one; several and no choice is an error listing them. Without an id,
// subpath and near choose among everything the document draws.
// The map from the element's coordinates to scene coordinates is, in this order (each an affine map, so
// rational Bezier control points are mapped exactly and the weights kept):
//   1. the element's `transform` (about its transform-origin "x y" in user units, CSS Transforms 1, 6.1), then
//      each ancestor's, innermost first (SVG 1.1, 7.5), through the <use> and <symbol> maps above;
//   2. the root <svg>'s viewBox with width/height and preserveAspectRatio (SVG 1.1, 7.7-7.8), giving
//      viewport coordinates in the unit of `width` (mm, cm, in, pt, pc, px = 1/96 in, or no unit);
//   3. flip_y: (x, y) -> (x, -y), SVG's y-down drawing becoming rollkin's y-up world (this reverses the sense
//      of rotation: a path drawn clockwise on screen is counter-clockwise after the flip);
//   4. unit conversion: when the file declares physical units (width and height with units) and the scene
//      declares units.length, viewport units are converted to scene units; otherwise numbers stay as they are;
//   5. `scale`.
// Without width/height (or with percentages) the viewBox only frames the drawing: user units are kept and
// no unit is declared. Anything that would change the geometry and is not applied is an error naming it:
// a CSS transform (style attribute or <style> sheet), a transform-origin given by keywords or percentages, a
// transform-box other than view-box, a transform function not listed above, a nested <svg> viewport, an
// element of another kind, a malformed or non-finite number, a degenerate transform, a <symbol> with x/y, or
// with a viewBox and no width/height; an XML entity reference where elements stand (pugixml does not expand
// entities: "write the element into the file").
#pragma once

#include "rollkin/io/input_error.hpp"
#include "rollkin/io/svg/path_data.hpp"
#include "rollkin/profile/bezier.hpp"

#include <optional>
#include <string>
#include <vector>

namespace rollkin::io {

struct SvgReadOptions {
  bool flip_y = true;  // step 3 above
  double scale = 1.0;  // step 5 above
  /// The scene's units.length as metres per scene unit; empty when the scene declares no length unit.
  std::optional<double> metres_per_scene_unit;
  /// Tangent turn (radians) above which a joint is reported as a corner; BezierPath's default.
  double corner_tolerance = BezierPathOptions<double>{}.corner_tolerance;
  /// read_svg_shape: the k-th subpath (1-based) of those the element draws.
  std::optional<std::size_t> subpath;
  /// read_svg_shape: the subpath passing nearest to this point, in scene coordinates (after steps 1-5).
  std::optional<Vec2<double>> near;
};

/// A tangent discontinuity at the start of `segment` (for a closed shape, segment 0 is the closing joint).
struct SvgCorner {
  std::size_t segment = 0;
  Vec2<double> point;   // in scene units
  double turn_deg = 0;  // signed tangent turn, in the scene's (flipped) orientation
  std::string where;    // in the user's terms: "where command 3 (L) meets command 4 (C)"
};

/// One element of an SVG document as Bezier segments in scene units.
struct SvgShape {
  std::string file;                                 // the file label given
  std::string id, element;                          // element id and kind ("path", "circle", ...)
  std::string location;                             // "line 12, path \"cam\"": prefix for later messages
  std::vector<BezierSegment<double>> segments;      // in scene units
  std::vector<std::string> origins;                 // per segment, in the user's terms
  bool closed = false;
  std::vector<SvgCorner> corners;                   // tangent discontinuities at joints, in path order
  /// Metres per viewport unit (step 2) when the file declares physical units, otherwise empty.
  std::optional<double> metres_per_file_unit;
  std::string file_unit;                            // "mm", "px", ... or "user unit" when none is declared
  double unit_factor = 1.0;                         // file units -> scene units applied in step 4
  std::string conversion;                           // one line describing steps 1-5, for --verbose
  std::size_t subpath = 1, subpaths = 1;            // which subpath of its element (1-based), of how many
  /// The id that selects it (its own, or that of a group or <use> drawing it; "" when none has a unique id)
  /// and its "subpath" among what that id draws (0 when it is all that id draws).
  std::string selector_id;
  std::size_t selector_subpath = 0;
  /// Why the shape is not drawn ("display=\"none\" on line 4, g \"layer2\"", a visibility), or "" when it is
  /// drawn. A hidden shape is passed over by "subpath", "near" and the only-one choice; only the id of the shape
  /// or of an element on the way out to the one that hides it (inclusive) selects it (read_svg_shape: the
  /// selected element's own display and visibility, and its ancestors', are not applied).
  std::string hidden;
};

/// Every subpath the element `id` draws (the whole document when `id` is empty), mapped into scene units
/// (steps 1-5), in document order; options.subpath and options.near are not used.
std::vector<SvgShape> read_svg_shapes(const std::string& svg_file, const std::string& id,
                                      const SvgReadOptions& options = {});
std::vector<SvgShape> read_svg_shapes_from_text(const std::string& text, const std::string& id,
                                                const SvgReadOptions& options = {}, const std::string& file_label = "");

/// The one subpath the element with the given id draws, or the one options.subpath or options.near choose
/// (id may be empty with either: among all the document draws), mapped into scene units (steps 1-5).
SvgShape read_svg_shape(const std::string& svg_file, const std::string& id, const SvgReadOptions& options = {});

/// The same from the document's text (bytes); `file_label` names the source in messages.
SvgShape read_svg_shape_from_text(const std::string& text, const std::string& id, const SvgReadOptions& options = {},
                                  const std::string& file_label = "");

/// The shape as a contour, split at its corners (BezierPath::corners(); a contact stops there). A defect
/// BezierPath refuses is an InputError naming the file and the element.
BezierPath<double> svg_bezier_path(const SvgShape& shape);

/// Compatibility: read_svg_shape without scene units, as one subpath.
std::vector<SvgSubpath> read_svg_path(const std::string& svg_file, const std::string& path_id,
                                      const SvgPathOptions& options = {});

}  // namespace rollkin::io
