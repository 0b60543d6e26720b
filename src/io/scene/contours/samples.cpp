// "samples" contours: points from a point file or inline, fitted by a spline (docs/scene_format.md); and the
// listing of a point file (io/contour_formats.hpp): the one chain the reader would fit.
#include "contour_reader.hpp"

#include "../../segment_geometry.hpp"
#include "rollkin/geometry/validation.hpp"
#include "rollkin/io/contour_listing.hpp"
#include "rollkin/io/point_file.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>

namespace rollkin::io {

namespace {

constexpr std::size_t kMinSplineSamples = 4;
constexpr double kValidationTolerance = 1e-9;

/// The spline through the samples as a "samples" contour fits it: the polyline checked (geometry::
/// validate_polyline with the material on the side its drawing turns, the closing repeat of a closed one
/// dropped), then fitted. Throws std::runtime_error saying which step refused it.
SampledProfile<double> fitted_samples(std::vector<Vec2<double>> pts, const std::vector<std::size_t>& lines, bool closed,
                                      double smoothing, const std::string& source) {
  const double area = closed ? signed_area(pts) : 0.0;
  const geometry::MaterialSide as_drawn = area >= 0 ? geometry::MaterialSide::Left : geometry::MaterialSide::Right;
  try {
    const auto report = geometry::validate_polyline(pts, closed, as_drawn, kValidationTolerance);
    geometry::throw_if_invalid(report, source, lines);
    if (report.dropped_closing_repeat) pts.pop_back();  // closed: the first point repeated at the end
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(std::string("invalid sampled contour: ") + e.what());
  }
  SplineOptions<double> opt;
  opt.closed = closed;
  opt.smoothing_tolerance = smoothing;
  try {
    return SampledProfile<double>(pts, opt);
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot fit the sampled contour (" + source + "): " + e.what());
  }
}

/// The spline's cubic spans as Bezier segments (exact: end points and tangents scaled by a third of the span).
std::vector<BezierSegment<double>> spline_segments(const SampledProfile<double>& spline) {
  std::vector<BezierSegment<double>> out;
  for (std::size_t k = 0; k + 1 < spline.knots().size(); ++k) {
    const double a = spline.knot(k), b = spline.knot(k + 1), third = (b - a) / 3;
    const Jet<double> ja = spline.jet(a, 1), jb = spline.jet(b, 1);
    out.push_back({{ja.p, ja.p + third * ja.d1, jb.p - third * jb.d1, jb.p}, {}});
  }
  return out;
}

}  // namespace

std::vector<ListedChain> list_point_file_contours(const std::string& path) {
  PointSamples read = read_point_samples(path, kMinSplineSamples);
  const bool closed = read.points.front() == read.points.back();  // a closed file repeats its first point
  std::optional<SampledProfile<double>> spline;
  try {
    spline.emplace(fitted_samples(read.points, read.lines, closed, 0.0, path));
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(path, "", e.what());
  }
  ListedChain c;
  c.group = std::filesystem::path(path).filename().string();
  c.entities = {std::to_string(read.points.size()) + " points"};
  c.closed = closed;
  c.length = spline->total_length();
  c.segments = spline_segments(*spline);
  segments_box(c.segments, c.min, c.max);
  nlohmann::ordered_json j;
  j["type"] = "samples";
  j["file"] = path;
  j["closed"] = closed;
  c.selector = j.dump();
  return {c};
}

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
  std::optional<SampledProfile<double>> spline;
  try {
    spline.emplace(fitted_samples(std::move(pts), lines, closed, smoothing, source));
  } catch (const std::exception& e) {
    js.fail(path, e.what());
  }
  const bool reversed = closed ? ctx.material(c, path, area > 0, "inside") : ctx.material(c, path, std::nullopt, "left");
  return {ctx.parameterised(std::move(*spline), c, path), reversed};
}

}  // namespace rollkin::io
