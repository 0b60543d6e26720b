// "dxf" contours: the entities of one layer (or one entity by handle) of a DXF drawing, chained by
// read_dxf_contour (io/dxf.hpp), converted to scene units and made a BezierPath (docs/scene_format.md, "dxf").
#include "contour_reader.hpp"

#include "rollkin/io/dxf.hpp"

namespace rollkin::io {

namespace {

/// "layer" or "handle", exactly one.
DxfSelection dxf_selection(const json& c, const std::string& path, const JsonAccess& js) {
  const json* layer = js.get(c, "layer");
  const json* handle = js.get(c, "handle");
  if (layer && handle) js.fail(child(path, "handle"), "give either \"layer\" or \"handle\", not both");
  if (!layer && !handle) js.fail(path, "missing key \"layer\" or \"handle\": expected the DXF layer name or the entity handle");
  DxfSelection sel;
  const std::string key = layer ? "layer" : "handle";
  std::string& value = layer ? sel.layer : sel.handle;
  value = js.string(layer ? *layer : *handle, child(path, key), layer ? "a layer name" : "an entity handle (hexadecimal)");
  if (value.empty()) js.fail(child(path, key), "expected a non-empty " + key);
  return sel;
}

/// Every point multiplied by `factor` (an affine map: rational weights stay as they are).
void scale_segments(std::vector<BezierSegment<double>>& segments, double factor) {
  for (BezierSegment<double>& s : segments)
    for (Vec2<double>& p : s.points) p *= factor;
}

}  // namespace

ContourShape read_dxf_contour(const json& c, const std::string& path, const ContourContext& ctx) {
  const JsonAccess& js = ctx.js;
  ctx.keys(c, path, {"file", "layer", "handle", "scale", "parameter"});
  const std::string file = ctx.contour_file(js.require(c, path, "file", "the DXF file"), child(path, "file"));
  const DxfSelection sel = dxf_selection(c, path, js);
  const double scale = ctx.scale(c, path);
  DxfContour dxf;
  try {
    dxf = read_dxf_contour(file, sel);
  } catch (const InputError& e) {
    js.fail(child(path, "file"), e.what());
  }
  const std::string what = sel.layer.empty() ? "entity " + sel.handle : "layer \"" + sel.layer + "\"";
  const std::string drawing_unit = dxf.unit.empty() ? "drawing units" : dxf.unit;
  std::vector<Vec2<double>> joint_points;  // in drawing units, for messages
  for (const BezierSegment<double>& s : dxf.segments) joint_points.push_back(s.points.front());
  const double unit = ctx.unit_factor(dxf.metres_per_unit);
  const double factor = unit * scale;
  scale_segments(dxf.segments, factor);
  const std::string conversion =
      dxf.unit.empty() ? "no drawing unit ($INSUNITS 0 or absent): numbers as they are"
      : ctx.length_unit() == LengthUnit::Unitless
          ? "the scene has no units.length: numbers as they are"
          : "converted " + dxf.unit + " -> " + unit_label(ctx.length_unit()) + " (x " + format_number(unit) + ")";
  ctx.note(dxf.description + "; " + conversion + ", then scale " + format_number(scale) + ": coordinates x " + format_number(factor));
  const std::vector<std::size_t> first = join_straight_runs(dxf.segments);
  std::optional<BezierPath<double>> bezier;
  try {
    bezier.emplace(dxf.segments, dxf.closed);
  } catch (const std::exception& e) {
    js.fail(child(path, "file"), file + ": " + what + " is not a usable contour: " + e.what());
  }
  const bool reversed = dxf.closed ? ctx.material(c, path, signed_area(control_polygon(dxf.segments)) > 0, "inside")
                                   : ctx.material(c, path, std::nullopt, "left");
  std::vector<std::string> corners = describe_joints(*bezier, [&](std::size_t piece) {
    const Vec2<double>& p = joint_points[first[piece]];
    return "entity " + dxf.joint_entities[first[piece]] + " at (" + format_number(p.x()) + ", " + format_number(p.y()) + ") " + drawing_unit + " in " + file;
  }, "dxf " + what, ctx);
  return {ctx.parameterised(std::move(*bezier), c, path), reversed, std::move(corners)};
}

}  // namespace rollkin::io
