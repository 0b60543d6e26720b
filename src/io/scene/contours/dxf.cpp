// "dxf" contours: one chain of a DXF drawing (a layer's, the one near a point, or given entities), chained by
// read_dxf_contour (io/dxf/reader.hpp), converted to scene units and made a BezierPath (docs/scene_format.md, "dxf").
#include "contour_reader.hpp"

#include "rollkin/io/dxf/reader.hpp"

namespace rollkin::io {

namespace {

/// The selector (io/dxf/reader.hpp, "Selection"): "layer" (with or without "near"), "near" alone, "handle" alone or
/// "handles" alone.
DxfSelection dxf_selection(const json& c, const std::string& path, const JsonAccess& js) {
  const json* layer = js.get(c, "layer");
  const json* handle = js.get(c, "handle");
  const json* handles = js.get(c, "handles");
  const json* near = js.get(c, "near");
  const int ways = int(handle != nullptr) + int(handles != nullptr) + int(layer != nullptr || near != nullptr);
  if (ways > 1)
    js.fail(child(path, handle ? "handle" : "handles"),
            "give one selector: \"layer\" (optionally with \"near\"), \"near\", \"handle\" or \"handles\"");
  if (ways == 0)
    js.fail(path, "missing key \"layer\", \"near\", \"handle\" or \"handles\": expected the DXF layer name, a point "
                  "[x, y] near the contour (drawing units), an entity handle or a list of handles");
  DxfSelection sel;
  if (layer) {
    sel.layer = js.string(*layer, child(path, "layer"), "a layer name");
    if (sel.layer.empty()) js.fail(child(path, "layer"), "expected a non-empty layer");
  }
  if (near) sel.near = js.point(*near, child(path, "near"));
  if (handle) {
    sel.handle = js.string(*handle, child(path, "handle"), "an entity handle (hexadecimal)");
    if (sel.handle.empty()) js.fail(child(path, "handle"), "expected a non-empty handle");
  }
  if (handles) {
    const json& list = js.array(*handles, child(path, "handles"), "a list of entity handles");
    if (list.empty()) js.fail(child(path, "handles"), "expected at least one handle");
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string where = child(path, "handles") + "[" + std::to_string(i) + "]";
      sel.handles.push_back(js.string(list[i], where, "an entity handle (hexadecimal)"));
      if (sel.handles.back().empty()) js.fail(where, "expected a non-empty handle");
    }
  }
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
  ctx.keys(c, path, {"file", "layer", "handle", "handles", "near", "scale", "parameter"});
  const std::string file = ctx.contour_file(js.require(c, path, "file", "the DXF file"), child(path, "file"));
  const DxfSelection sel = dxf_selection(c, path, js);
  const double scale = ctx.scale(c, path);
  DxfContour dxf;
  try {
    dxf = read_dxf_contour(file, sel);
  } catch (const InputError& e) {
    js.fail(child(path, "file"), e.what());
  }
  const std::string what = selection_text(sel);
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
    js.fail(child(path, "file"), file + ": the contour of " + what + " is not usable: " + e.what());
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
