// "samples" contours: points from a point file or inline, fitted by a spline (docs/scene_format.md).
#include "contour_reader.hpp"

#include "rollkin/geometry/validation.hpp"
#include "rollkin/io/point_file.hpp"

namespace rollkin::io {

namespace {

constexpr std::size_t kMinSplineSamples = 4;
constexpr double kValidationTolerance = 1e-9;

}  // namespace

ContourShape read_samples_contour(const json& c, const std::string& path, const ContourContext& ctx) {
  const JsonAccess& js = ctx.js;
  ctx.keys(c, path, {"file", "points", "closed", "smoothing", "scale", "parameter"});
  const bool closed = js.get(c, "closed") ? js.boolean(c["closed"], child(path, "closed"), "whether the contour is closed") : false;
  const double scale = ctx.scale(c, path);
  const double smoothing = js.number_or(c, path, "smoothing", 0.0, "a smoothing tolerance");
  if (smoothing < 0) js.fail(child(path, "smoothing"), "expected a smoothing tolerance >= 0, got " + format_number(smoothing));
  const json* f = js.get(c, "file");
  const json* p = js.get(c, "points");
  if ((f != nullptr) == (p != nullptr))
    js.fail(path, "expected exactly one of \"file\" (a point file) or \"points\" (inline [[x, y], ...])");
  std::vector<Vec2<double>> pts;
  std::vector<std::size_t> lines;  // of the point file, one per point: messages name them
  std::string source;
  if (f) {
    source = ctx.contour_file(*f, child(path, "file"));
    try {
      PointSamples read = read_point_samples(source, kMinSplineSamples, scale);
      pts = std::move(read.points);
      lines = std::move(read.lines);
    } catch (const InputError& e) {
      js.fail(child(path, "file"), e.what());
    }
  } else {
    source = js.file() + ":" + child(path, "points");
    pts = js.points(*p, child(path, "points"));
    for (auto& q : pts) q *= scale;
    if (pts.size() < kMinSplineSamples)
      js.fail(child(path, "points"), "contour too short: " + std::to_string(pts.size()) + " samples; expected at least " +
                                         std::to_string(kMinSplineSamples) + " for a spline");
  }
  const double area = closed ? signed_area(pts) : 0.0;
  const geometry::MaterialSide as_drawn = area >= 0 ? geometry::MaterialSide::Left : geometry::MaterialSide::Right;
  try {
    const auto report = geometry::validate_polyline(pts, closed, as_drawn, kValidationTolerance);
    geometry::throw_if_invalid(report, source, lines);
    if (report.dropped_closing_repeat) pts.pop_back();  // closed: the first point repeated at the end
  } catch (const std::runtime_error& e) {
    js.fail(path, std::string("invalid sampled contour: ") + e.what());
  }
  SplineOptions<double> opt;
  opt.closed = closed;
  opt.smoothing_tolerance = smoothing;
  std::optional<SampledProfile<double>> spline;
  try {
    spline.emplace(pts, opt);
  } catch (const std::exception& e) {
    js.fail(path, std::string("cannot fit the sampled contour (") + source + "): " + e.what());
  }
  const bool reversed = closed ? ctx.material(c, path, area > 0, "inside") : ctx.material(c, path, std::nullopt, "left");
  return {ctx.parameterised(std::move(*spline), c, path), reversed};
}

}  // namespace rollkin::io
