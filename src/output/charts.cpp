// The --plot chart (plot_svg, rollkin/output/charts.hpp): the pair variables against the input and, with --analysis, the
// contact analysis charts, stacked in one SVG document.
#include "rollkin/output/charts.hpp"

#include "rollkin/analysis/motion.hpp"
#include "rollkin/output/decimate.hpp"
#include "rollkin/output/svg_chart.hpp"
#include "rollkin/io/svg/markup.hpp"
#include "rollkin/io/units.hpp"

#include <algorithm>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace rollkin::output {
namespace {
const double kNaN = std::numeric_limits<double>::quiet_NaN();
using io::kOutputAngle;
double out_scale(const Mechanism<double>& m, int var) { return io::output_scale(m, var); }

std::string axis_label(const SweepOutput& ctx, int var) {
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

/// The x axis of every chart: the input column (output units) of each pose, and its range.
struct InputAxis {
  io::SweepRows result;
  double scale, lo, hi;
  InputAxis(const SweepOutput& ctx)
      : result(ctx.result), scale(out_scale(ctx.scene.mechanism, ctx.sweep.variable)),
        lo(std::numeric_limits<double>::infinity()), hi(-lo) {
    for (std::size_t r = 0; r < result.size(); ++r) {
      lo = std::min(lo, at(r));
      hi = std::max(hi, at(r));
    }
  }
  double at(std::size_t r) const { return result.input(r) * scale; }
  /// A series of a chart `width` pixels wide, reduced to its columns as it is read (output/decimate.hpp): the
  /// charts hold a few points per pixel column whatever the number of poses (SvgChart reduces again to its
  /// exact plot area).
  io::SeriesReducer series(int width) const { return io::SeriesReducer(lo, hi, width); }
};

/// A reduced series as a chart series (name and colour set by the caller).
io::ChartSeries chart_series(io::SeriesReducer& reduced) {
  reduced.finish();
  io::ChartSeries s;
  s.x = reduced.x();
  s.y = reduced.y();
  return s;
}

/// series[c][k]: series k of chart c, one point per pose (NaN where not solved) reduced to the chart's
/// columns, in one pass over the poses: each is analysed once and not kept. turns[l]: link l's angular
/// acceleration is not zero at some pose.
void chart_values(const SweepOutput& ctx, const InputAxis& axis, const std::vector<ChartSpec>& specs, int width,
                  std::vector<std::vector<io::SeriesReducer>>& series, std::vector<bool>& turns) {
  const Mechanism<double>& m = ctx.scene.mechanism;
  series.assign(specs.size(), {});
  for (std::size_t c = 0; c < specs.size(); ++c) series[c].assign(specs[c].names.size(), axis.series(width));
  turns.assign(m.links.size(), false);
  AnalysisData<double> data(m);
  io::RowReader rows(ctx.result);
  for (std::size_t r = 0; r < ctx.result.size(); ++r) {
    const double x = axis.at(r);
    if (!ctx.result.has_pose(r)) {
      for (auto& chart : series)
        for (io::SeriesReducer& s : chart) s.add(x, kNaN);
      continue;
    }
    const PoseAnalysis<double> a = analyse_pose(m, rows.q(r), rows.qdot(r), data);
    for (std::size_t c = 0; c < specs.size(); ++c)
      for (std::size_t k = 0; k < specs[c].names.size(); ++k) series[c][k].add(x, specs[c].value(a, k));
    for (std::size_t l = 0; l < m.links.size(); ++l) turns[l] = turns[l] || a.angular_acceleration[l] != 0.0;
  }
}

/// The charts of specs with their values; a link's series only where the link turns (chart_values), a chart
/// with no series left out.
std::vector<io::SvgChart> charts_from_specs(const SweepOutput& ctx, const InputAxis& axis,
                                            const std::vector<ChartSpec>& specs) {
  const int width = 760, height = 360;
  std::vector<std::vector<io::SeriesReducer>> series;
  std::vector<bool> turns;
  chart_values(ctx, axis, specs, width, series, turns);
  std::vector<io::SvgChart> charts;
  for (std::size_t c = 0; c < specs.size(); ++c) {
    const ChartSpec& spec = specs[c];
    io::SvgChart chart(width, height);
    chart.set_title(base_name(ctx.scene.file) + ": " + spec.title).set_x_label(axis_label(ctx, ctx.sweep.variable))
        .set_y_label(spec.y_label).set_legend(io::LegendPosition::Outside);
    std::size_t shown = 0;
    for (std::size_t k = 0; k < spec.names.size(); ++k) {
      if (!spec.link.empty() && !turns[static_cast<std::size_t>(spec.link[k])]) continue;
      io::ChartSeries s = chart_series(series[c][k]);
      s.name = spec.names[k];
      s.color = io::palette_color(shown++);
      chart.add_series(std::move(s));
    }
    if (shown > 0) charts.push_back(std::move(chart));
  }
  return charts;
}

/// The --analysis charts (docs/analysis.md), in the CSV's output units.
std::vector<io::SvgChart> analysis_charts(const SweepOutput& ctx, const InputAxis& axis) {
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
  return charts_from_specs(ctx, axis, specs);
}

}  // namespace

std::string plot_svg(const SweepOutput& ctx) {
  const Mechanism<double>& m = ctx.scene.mechanism;
  const int input = ctx.sweep.variable;
  const InputAxis axis(ctx);
  const std::string name = base_name(ctx.scene.file);

  const int width = 760, height = 460;
  io::SvgChart angles(width, height), lengths(width, height);
  angles.set_title(name + ": pair angles against " + m.variables[input].name).set_x_label(axis_label(ctx, input))
      .set_y_label(std::string("angle [") + io::unit_label(kOutputAngle) + "]").set_legend(io::LegendPosition::Outside);
  lengths.set_title(name + ": contact parameters against " + m.variables[input].name).set_x_label(axis_label(ctx, input))
      .set_y_label("length [" + ctx.scene.length_unit + "] or parameter").set_legend(io::LegendPosition::Outside);
  // Every variable but the input, read in one pass over the poses into its reduced series.
  std::vector<int> charted;
  std::vector<io::SeriesReducer> series;
  for (int i = 0; i < m.variable_count(); ++i)
    if (i != input) {
      charted.push_back(i);
      series.push_back(axis.series(width));
    }
  io::RowReader rows(ctx.result);
  for (std::size_t r = 0; r < ctx.result.size(); ++r) {
    const bool solved = ctx.result.has_pose(r);
    const auto q = rows.q(r);
    for (std::size_t j = 0; j < charted.size(); ++j)
      series[j].add(axis.at(r), solved ? q(charted[j]) * out_scale(m, charted[j]) : kNaN);
  }
  std::size_t n_angles = 0, n_lengths = 0;
  for (std::size_t j = 0; j < charted.size(); ++j) {
    const int i = charted[j];
    const bool is_angle = m.variables[i].kind == ParamKind::Angle;
    const std::size_t k = is_angle ? n_angles++ : n_lengths++;
    io::ChartSeries s = chart_series(series[j]);
    s.name = m.variables[i].name;
    s.color = io::palette_color(static_cast<std::size_t>(i));
    if (k >= 10) s.dash = "6 3";
    (is_angle ? angles : lengths).add_series(std::move(s));
  }
  std::vector<io::SvgChart> charts;
  if (n_angles > 0) charts.push_back(std::move(angles));
  if (n_lengths > 0) charts.push_back(std::move(lengths));
  if (ctx.analysis)
    for (io::SvgChart& c : analysis_charts(ctx, axis)) charts.push_back(std::move(c));
  if (charts.empty()) charts.push_back(std::move(angles));  // a scene whose only variable is the input
  return stack_charts(charts);
}

}  // namespace rollkin::output
