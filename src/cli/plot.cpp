// The --plot chart (plot_svg, output.hpp): the pair variables against the input and, with --analysis, the
// contact analysis charts, stacked in one SVG document.
#include "output.hpp"

#include "rollkin/analysis.hpp"
#include "rollkin/io/svg.hpp"
#include "rollkin/io/units.hpp"

#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace rollkin::cli {
namespace {
const double kNaN = std::numeric_limits<double>::quiet_NaN();
using io::kOutputAngle;
double out_scale(const Mechanism<double>& m, int var) { return io::output_scale(m, var); }

std::string axis_label(const OutputContext& ctx, int var) {
  const Mechanism<double>& m = ctx.scene.mechanism;
  switch (m.variables[var].kind) {
    case ParamKind::Angle: return m.variables[var].name + " [" + io::unit_label(kOutputAngle) + "]";
    case ParamKind::Length: return m.variables[var].name + " [" + ctx.scene.length_unit + "]";
    case ParamKind::Unitless: return m.variables[var].name;
  }
  return m.variables[var].name;
}

/// Charts stacked top to bottom in one SVG document (nested <svg> elements); a single chart as it is.
std::string stack_charts(const std::vector<io::SvgChart>& charts) {
  if (charts.size() == 1) return charts.front().to_svg();
  int w = 0, h = 0;
  for (const io::SvgChart& c : charts) {
    w = std::max(w, c.width());
    h += c.height();
  }
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
                    "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + std::to_string(w) +
                    "\" height=\"" + std::to_string(h) + "\" viewBox=\"0 0 " + std::to_string(w) + " " + std::to_string(h) + "\">\n";
  int y = 0;
  for (const io::SvgChart& c : charts) {
    std::string body = strip_header(c.to_svg());
    body.insert(4, " x=\"0\" y=\"" + std::to_string(y) + "\"");
    out += body;
    y += c.height();
  }
  return out + "</svg>\n";
}

/// One chart against the input with a series per (name, value of an analysed pose) pair.
struct ChartSpec {
  std::string title, y_label;
  std::vector<std::string> names;
  std::function<double(const PoseAnalysis<double>&, std::size_t series)> value;
  std::vector<int> link;  // per series, the link it charts (angular accelerations and jerks); else empty
};

/// y[c][k]: the values of series k of chart c, one per pose (NaN where not solved), in one pass over the
/// poses: each is analysed once and not kept. turns[l]: link l's angular acceleration is not zero at some
/// pose.
void chart_values(const OutputContext& ctx, const std::vector<ChartSpec>& specs,
                  std::vector<std::vector<std::vector<double>>>& y, std::vector<bool>& turns) {
  const Mechanism<double>& m = ctx.scene.mechanism;
  const std::size_t poses = ctx.result.size();
  y.assign(specs.size(), {});
  for (std::size_t c = 0; c < specs.size(); ++c) y[c].assign(specs[c].names.size(), std::vector<double>(poses, kNaN));
  turns.assign(m.links.size(), false);
  AnalysisData<double> data(m);
  for (std::size_t r = 0; r < poses; ++r) {
    if (!ctx.result.has_pose(r)) continue;
    const PoseAnalysis<double> a = analyse_pose(m, ctx.result.q(r), ctx.result.qdot(r), data);
    for (std::size_t c = 0; c < specs.size(); ++c)
      for (std::size_t k = 0; k < specs[c].names.size(); ++k) y[c][k][r] = specs[c].value(a, k);
    for (std::size_t l = 0; l < m.links.size(); ++l) turns[l] = turns[l] || a.angular_acceleration[l] != 0.0;
  }
}

/// The charts of specs with their values; a link's series only where the link turns (chart_values), a chart
/// with no series left out.
std::vector<io::SvgChart> charts_from_specs(const OutputContext& ctx, const std::vector<double>& x,
                                            const std::vector<ChartSpec>& specs) {
  std::vector<std::vector<std::vector<double>>> y;
  std::vector<bool> turns;
  chart_values(ctx, specs, y, turns);
  std::vector<io::SvgChart> charts;
  for (std::size_t c = 0; c < specs.size(); ++c) {
    const ChartSpec& spec = specs[c];
    io::SvgChart chart(760, 360);
    chart.set_title(base_name(ctx.scene.file) + ": " + spec.title).set_x_label(axis_label(ctx, ctx.sweep.variable))
        .set_y_label(spec.y_label).set_legend(io::LegendPosition::Outside);
    std::size_t shown = 0;
    for (std::size_t k = 0; k < spec.names.size(); ++k) {
      if (!spec.link.empty() && !turns[static_cast<std::size_t>(spec.link[k])]) continue;
      io::ChartSeries s;
      s.name = spec.names[k];
      s.x = x;
      s.y = std::move(y[c][k]);
      s.color = io::palette_color(shown++);
      chart.add_series(std::move(s));
    }
    if (shown > 0) charts.push_back(std::move(chart));
  }
  return charts;
}

/// The --analysis charts (docs/analysis.md), in the CSV's output units.
std::vector<io::SvgChart> analysis_charts(const OutputContext& ctx, const std::vector<double>& x) {
  const Mechanism<double>& m = ctx.scene.mechanism;
  const double degrees = io::from_radians(1.0, kOutputAngle);
  const double in_scale = out_scale(m, ctx.sweep.variable);
  const std::string per_input = ctx.scene.unit_label(ctx.sweep.variable);
  const std::string& len = ctx.scene.length_unit;
  // Sliding is zero by construction at rolling pairs (docs/analysis.md): charted for cam pairs only.
  std::vector<std::string> pairs, cams, curvatures, links;
  std::vector<std::size_t> cam_contact;
  std::vector<int> moving;
  for (int k : contact_pairs(m)) {
    if (m.pairs[k].kind == PairKind::Cam) {
      cams.push_back(m.pairs[k].name);
      cam_contact.push_back(pairs.size());
    }
    pairs.push_back(m.pairs[k].name);
    curvatures.push_back(m.pairs[k].name + ".kappa1");
    curvatures.push_back(m.pairs[k].name + ".kappa2");
  }
  // The moving links, charted where their turning accelerates somewhere in the sweep (not a translating
  // follower, nor a crank driven at the input's constant rate: charts_from_specs), and the unknowns of
  // prismatic pairs: a follower's stroke, whose acceleration and jerk a cam designer reads.
  for (std::size_t l = 0; l < m.links.size(); ++l)
    if (static_cast<int>(l) != m.ground) {
      links.push_back(m.links[l].name);
      moving.push_back(static_cast<int>(l));
    }
  std::vector<std::string> strokes;
  std::vector<int> stroke_variable;
  for (int i : m.unknowns)
    for (const Pair<double>& p : m.pairs)
      if (p.kind == PairKind::Prismatic && p.first_variable == i) {
        strokes.push_back(m.variables[i].name);
        stroke_variable.push_back(i);
      }
  std::vector<ChartSpec> specs;
  if (!pairs.empty())
    specs.push_back({"pressure angle at the contact pairs", std::string("pressure angle [") + io::unit_label(kOutputAngle) + "]",
                     pairs, [=](const PoseAnalysis<double>& a, std::size_t k) { return a.contacts[k].pressure_angle * degrees; }});
  if (!cams.empty()) {
    specs.push_back({"sliding velocity at the cam pairs (second contour minus first)", "sliding [" + len + " / " + per_input + "]",
                     cams, [=](const PoseAnalysis<double>& a, std::size_t k) { return a.contacts[cam_contact[k]].sliding / in_scale; }});
    specs.push_back({"slide-to-roll ratio at the cam pairs", "slide-to-roll", cams,
                     [=](const PoseAnalysis<double>& a, std::size_t k) { return a.contacts[cam_contact[k]].slide_to_roll; }});
  }
  if (!pairs.empty())
    specs.push_back({"curvature of the contours at the contact", "curvature [1/" + len + "]", curvatures,
                     [](const PoseAnalysis<double>& a, std::size_t k) {
                       const ContactAnalysis<double>& c = a.contacts[k / 2];
                       return k % 2 == 0 ? c.kappa1 : c.kappa2;
                     }});
  if (!links.empty())
    specs.push_back({"angular acceleration of the links",
                     std::string("angular acceleration [") + io::unit_label(kOutputAngle) + " / " + per_input + "^2]", links,
                     [=](const PoseAnalysis<double>& a, std::size_t k) {
                       return a.angular_acceleration[moving[k]] * degrees / (in_scale * in_scale);
                     },
                     moving});
  if (!links.empty())
    specs.push_back({"angular jerk of the links",
                     std::string("angular jerk [") + io::unit_label(kOutputAngle) + " / " + per_input + "^3]", links,
                     [=](const PoseAnalysis<double>& a, std::size_t k) {
                       return a.angular_jerk[moving[k]] * degrees / (in_scale * in_scale * in_scale);
                     },
                     moving});
  if (!strokes.empty()) {
    specs.push_back({"acceleration of the sliding pairs", "acceleration [" + len + " / " + per_input + "^2]", strokes,
                     [=](const PoseAnalysis<double>& a, std::size_t k) { return a.qddot(stroke_variable[k]) / (in_scale * in_scale); }});
    specs.push_back({"jerk of the sliding pairs", "jerk [" + len + " / " + per_input + "^3]", strokes,
                     [=](const PoseAnalysis<double>& a, std::size_t k) {
                       return a.qdddot(stroke_variable[k]) / (in_scale * in_scale * in_scale);
                     }});
  }
  return charts_from_specs(ctx, x, specs);
}

}  // namespace

std::string plot_svg(const OutputContext& ctx) {
  const Mechanism<double>& m = ctx.scene.mechanism;
  const int input = ctx.sweep.variable;
  const double in_scale = out_scale(m, input);
  std::vector<double> x;
  for (const auto& p : ctx.result.poses) x.push_back(p.input * in_scale);
  (void)ctx.inputs;
  const std::string name = base_name(ctx.scene.file);

  io::SvgChart angles(760, 460), lengths(760, 460);
  angles.set_title(name + ": pair angles against " + m.variables[input].name).set_x_label(axis_label(ctx, input))
      .set_y_label(std::string("angle [") + io::unit_label(kOutputAngle) + "]").set_legend(io::LegendPosition::Outside);
  lengths.set_title(name + ": contact parameters against " + m.variables[input].name).set_x_label(axis_label(ctx, input))
      .set_y_label("length [" + ctx.scene.length_unit + "] or parameter").set_legend(io::LegendPosition::Outside);
  std::size_t n_angles = 0, n_lengths = 0;
  for (int i = 0; i < m.variable_count(); ++i) {
    if (i == input) continue;
    std::vector<double> y;
    for (const auto& p : ctx.result.poses) y.push_back(p.report.has_pose() ? p.q(i) * out_scale(m, i) : kNaN);
    const bool is_angle = m.variables[i].kind == ParamKind::Angle;
    const std::size_t k = is_angle ? n_angles++ : n_lengths++;
    io::ChartSeries s;
    s.name = m.variables[i].name;
    s.x = x;
    s.y = std::move(y);
    s.color = io::palette_color(static_cast<std::size_t>(i));
    if (k >= 10) s.dash = "6 3";
    (is_angle ? angles : lengths).add_series(std::move(s));
  }
  std::vector<io::SvgChart> charts;
  if (n_angles > 0) charts.push_back(std::move(angles));
  if (n_lengths > 0) charts.push_back(std::move(lengths));
  if (ctx.analysis)
    for (io::SvgChart& c : analysis_charts(ctx, x)) charts.push_back(std::move(c));
  if (charts.empty()) charts.push_back(std::move(angles));  // a scene whose only variable is the input
  return stack_charts(charts);
}

}  // namespace rollkin::cli
