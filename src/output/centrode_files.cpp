// The centrode files of `rollkin centrodes` and Python's Scene.centrodes (rollkin/output/centrode_files.hpp).
#include "rollkin/output/centrode_files.hpp"

#include "rollkin/io/csv.hpp"
#include "rollkin/io/dxf/writer.hpp"

#include <cstring>

namespace rollkin::output {

std::string centrode_text(const SweepOutput& ctx, const std::vector<InstantCentre<double>>& centres, int a, int b,
                          bool in_a) {
  const Mechanism<double>& m = ctx.scene.mechanism;
  const std::string& frame = m.links[in_a ? a : b].name;
  const std::string unit = ctx.scene.unit_label(ctx.sweep.variable);
  auto input = [&](std::size_t k) { return ctx.sweep.input + " = " + io::format_double(ctx.inputs[k]) + (unit.empty() ? "" : " " + unit); };
  std::string text = "# rollkin centrodes: instant centre of link '" + m.links[b].name + "' relative to link '" +
                     m.links[a].name + "', in link '" + frame + "''s frame (" + ctx.scene.length_unit + ")\n" +
                     "# scene " + base_name(ctx.scene.file) + "; " + ctx.sweep.input + " from " + io::format_double(ctx.sweep.from) +
                     " to " + io::format_double(ctx.sweep.to) + " step " + io::format_double(ctx.sweep.step) +
                     "; one point per input value, in sweep order\nx y\n";
  for (std::size_t k = 0; k < centres.size(); ++k) {
    const InstantCentre<double>& c = centres[k];
    const SolveStatus status = ctx.result.status(k);
    if (c.finite) {
      const Vec2<double>& x = in_a ? c.in_a : c.in_b;
      text += io::format_double(x.x()) + " " + io::format_double(x.y()) + "\n";
    } else if (!ctx.result.has_pose(k)) {
      text += "# " + input(k) + ": not solved (" + to_string(status) + ")\n";
    } else {
      text += "# " + input(k) + ": centre at infinity (pure relative translation, direction (" +
              io::format_double(c.direction.x()) + ", " + io::format_double(c.direction.y()) + ") in the world frame)\n";
    }
  }
  return text;
}
namespace {

/// A DXF layer name from a link name: the characters DXF forbids in names (< > / \ " : ; ? * | = `) as '_'.
std::string layer_name(const std::string& link) {
  std::string name = link;
  for (char& c : name)
    if (std::strchr("<>/\\\":;?*|=`", c) != nullptr || static_cast<unsigned char>(c) < 0x20) c = '_';
  return name;
}

/// Two centres closer than this are one point: round-off of the velocity solution, relative to the
/// mechanism's size and the centres' distance from the origin.
bool same_centre(const Vec2<double>& p, const Vec2<double>& q, double length_scale) {
  return (p - q).norm() <= 1e-9 * (length_scale + p.norm());
}

/// The SPLINE of one run of centre points (see centrode_dxf).
io::DxfSpline centrode_spline(const std::vector<Vec2<double>>& run, bool whole_sweep, const std::string& layer) {
  if (run.size() < 4) return io::polyline_spline(run, layer);
  double size = 0;
  for (const Vec2<double>& x : run) size = std::max(size, (x - run.front()).norm());
  SplineOptions<double> options;
  options.closed = whole_sweep && (run.back() - run.front()).norm() <= 1e-9 * size;
  if (!options.closed) return io::spline_of(SampledProfile<double>(run, options), layer);
  // A full period: the last centre repeats the first (to round-off); the closed spline returns to it.
  return io::spline_of(SampledProfile<double>(std::vector<Vec2<double>>(run.begin(), run.end() - 1), options), layer);
}

}  // namespace

std::string centrode_dxf(const SweepOutput& ctx, const std::vector<InstantCentre<double>>& centres, int a, int b) {
  const Mechanism<double>& m = ctx.scene.mechanism;
  std::vector<io::DxfSpline> splines;
  for (const bool in_a : {true, false}) {
    const std::string layer = layer_name(m.links[in_a ? a : b].name);
    std::vector<Vec2<double>> run;
    auto close_run = [&](bool whole_sweep) {
      if (run.size() >= 2) splines.push_back(centrode_spline(run, whole_sweep, layer));
      run.clear();
    };
    for (const InstantCentre<double>& c : centres) {
      const Vec2<double>& x = in_a ? c.in_a : c.in_b;
      if (!c.finite) close_run(false);
      else if (run.empty() || !same_centre(run.back(), x, m.length_scale)) run.push_back(x);
    }
    close_run(run.size() == centres.size());
  }
  return io::dxf_text(splines, ctx.scene.length_unit);
}

std::string centrode_single_point(const SweepOutput& ctx, const std::vector<InstantCentre<double>>& centres, int a,
                                  int b) {
  const Mechanism<double>& m = ctx.scene.mechanism;
  const InstantCentre<double>* first = nullptr;
  for (const InstantCentre<double>& c : centres) {
    if (!c.finite) continue;
    if (!first) first = &c;
    if (!same_centre(first->in_a, c.in_a, m.length_scale) || !same_centre(first->in_b, c.in_b, m.length_scale)) return "";
  }
  if (!first) return "";
  std::string joint = "link '" + m.links[b].name + "' turns about one point of link '" + m.links[a].name + "'";
  for (const Pair<double>& p : m.pairs)
    if (p.kind == PairKind::Revolute && ((p.link_a == a && p.link_b == b) || (p.link_a == b && p.link_b == a)))
      joint = "the links are joined by the revolute '" + p.name + "'";
  auto point = [&](const Vec2<double>& x, int link) {  // a coordinate within round-off of zero is shown as 0
    auto coordinate = [&](double v) { return io::format_double(same_centre(x, x - Vec2<double>(v, 0), m.length_scale) ? 0.0 : v); };
    return "(" + coordinate(x.x()) + ", " + coordinate(x.y()) + ") in link '" + m.links[link].name + "''s frame";
  };
  return "the centrode of '" + m.links[b].name + "' relative to '" + m.links[a].name + "' is one point, " +
         point(first->in_a, a) + " and " + point(first->in_b, b) + ": " + joint;
}

}  // namespace rollkin::output
