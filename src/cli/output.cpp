#include "output.hpp"

#include "rollkin/analysis.hpp"
#include "rollkin/io/csv.hpp"
#include "rollkin/io/dxf_writer.hpp"
#include "rollkin/io/svg.hpp"
#include "rollkin/io/units.hpp"

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>

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

std::string strip_header(const std::string& svg) {
  const std::size_t at = svg.find("<svg");
  return at == std::string::npos ? svg : svg.substr(at);
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

std::string base_name(const std::string& file) { return std::filesystem::path(file).filename().string(); }

std::string csv_text(const OutputContext& ctx, bool rates) { return io::sweep_table(ctx, rates).csv(); }

std::string centrode_text(const OutputContext& ctx, const std::vector<InstantCentre<double>>& centres, int a, int b,
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
    const SweepPose<double>& p = ctx.result.poses[k];
    if (c.finite) {
      const Vec2<double>& x = in_a ? c.in_a : c.in_b;
      text += io::format_double(x.x()) + " " + io::format_double(x.y()) + "\n";
    } else if (!p.report.has_pose()) {
      text += "# " + input(k) + ": not solved (" + to_string(p.report.status) + ")\n";
    } else {
      text += "# " + input(k) + ": centre at infinity (pure relative translation, direction (" +
              io::format_double(c.direction.x()) + ", " + io::format_double(c.direction.y()) + ") in the world frame)\n";
    }
  }
  return text;
}

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

namespace {

/// A DXF layer name from a link name: the characters DXF forbids in names (< > / \ " : ; ? * | = `) as '_'.
std::string layer_name(const std::string& link) {
  std::string name = link;
  for (char& c : name)
    if (std::strchr("<>/\\\":;?*|=`", c) != nullptr || static_cast<unsigned char>(c) < 0x20) c = '_';
  return name;
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

std::string centrode_dxf(const OutputContext& ctx, const std::vector<InstantCentre<double>>& centres, int a, int b) {
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
      if (c.finite) run.push_back(in_a ? c.in_a : c.in_b);
      else close_run(false);
    }
    close_run(run.size() == centres.size());
  }
  return io::dxf_text(splines, ctx.scene.length_unit);
}

std::vector<LinkSketch> link_sketches(const Mechanism<double>& m) {
  std::vector<LinkSketch> s(m.links.size());
  for (std::size_t l = 0; l < s.size(); ++l)
    s[l].color = static_cast<int>(l) == m.ground ? "#000000" : io::palette_color(l);
  for (const auto& c : m.contours) {
    LinkSketch& k = s[static_cast<std::size_t>(c.link())];
    const Domain<double> dom = c.domain();
    const int n = 200;
    std::vector<Eigen::Vector2d> pts;
    for (int i = 0; i < n; ++i) pts.push_back(c.jet(dom.sample(i, n), 0).p);
    k.contours.push_back(std::move(pts));
    k.closed.push_back(dom.closed);
  }
  // Bodies: the joints and contour origins of each moving link.
  for (std::size_t l = 0; l < s.size(); ++l) {
    if (static_cast<int>(l) == m.ground) continue;
    std::vector<Eigen::Vector2d> anchors;
    for (const auto& p : m.pairs) {
      if (is_contact(p.kind)) continue;
      if (p.link_a == static_cast<int>(l)) anchors.push_back(p.frame_a.translation());
      if (p.link_b == static_cast<int>(l)) anchors.push_back(p.frame_b.translation());
    }
    for (const auto& c : m.contours)
      if (c.link() == static_cast<int>(l)) anchors.push_back(c.placement().translation());
    if (anchors.size() >= 2) s[l].body = std::move(anchors);
  }
  for (const auto& p : m.pairs) {
    if (is_contact(p.kind)) continue;
    if (p.link_a != m.ground && p.link_b != m.ground) {
      s[static_cast<std::size_t>(p.link_a)].joints.push_back(p.frame_a.translation());
    } else {
      LinkSketch& g = s[static_cast<std::size_t>(m.ground)];
      g.pivots.push_back(p.link_a == m.ground ? p.frame_a.translation() : p.frame_b.translation());
      g.pivot_names.push_back(p.name);
    }
  }
  return s;
}

std::vector<Eigen::Vector2d> contact_points(const Mechanism<double>& m, const KinematicsData<double>& kin,
                                            const std::vector<SE2<double>>& lp) {
  std::vector<Eigen::Vector2d> out;
  for (int p : contact_pairs(m)) out.push_back(lp[m.pairs[p].link_a].act(kin.pairs[p].contact[0].p));
  return out;
}

namespace {

/// Documents side by side in rows of `columns` (nested <svg> elements), each `w` x `h` pixels.
std::string tile_documents(const std::vector<std::string>& svgs, int w, int h, int columns) {
  const int n = static_cast<int>(svgs.size()), rows = (n + columns - 1) / columns, cols = std::min(n, columns);
  const int width = w * std::max(cols, 1), height = h * std::max(rows, 1);
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
                    "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + std::to_string(width) +
                    "\" height=\"" + std::to_string(height) + "\" viewBox=\"0 0 " + std::to_string(width) + " " +
                    std::to_string(height) + "\">\n";
  for (int k = 0; k < n; ++k) {
    std::string body = strip_header(svgs[static_cast<std::size_t>(k)]);
    body.insert(4, " x=\"" + std::to_string(w * (k % columns)) + "\" y=\"" + std::to_string(h * (k / columns)) + "\"");
    out += body;
  }
  return out + "</svg>\n";
}

/// The solved poses the drawing shows: up to `count`, spread evenly over the solved ones in input order.
std::vector<std::size_t> poses_to_draw(const SweepResult<double>& result, std::size_t count) {
  std::vector<std::size_t> solved;
  for (std::size_t i = 0; i < result.poses.size(); ++i)
    if (result.poses[i].report.has_pose()) solved.push_back(i);
  std::sort(solved.begin(), solved.end(), [&](auto a, auto b) { return result.poses[a].input < result.poses[b].input; });
  std::vector<std::size_t> pick;
  count = std::min(count, solved.size());
  for (std::size_t k = 0; k < count; ++k)
    pick.push_back(solved[count == 1 ? 0 : (k * (solved.size() - 1) + (count - 1) / 2) / (count - 1)]);
  return pick;
}

}  // namespace

std::string draw_svg(const OutputContext& ctx) {
  const io::Scene& scene = ctx.scene;
  const Mechanism<double>& m = scene.mechanism;
  // Small multiples: one panel per pose, all at the same scale, so that no two poses overlap and the labels
  // (ground pivots, the input value in each panel's title) stand alone.
  const std::vector<std::size_t> pick = poses_to_draw(ctx.result, 4);
  const std::vector<LinkSketch> sketches = link_sketches(m);
  KinematicsData<double> kin(m);
  struct Placed {
    std::vector<std::vector<Eigen::Vector2d>> lines;  // contours and bodies, world
    std::vector<bool> closed, body;
    std::vector<std::string> colors;
    std::vector<Eigen::Vector2d> contacts, joints;
  };
  std::vector<Placed> placed(pick.size());
  Eigen::Vector4d box(1e300, 1e300, -1e300, -1e300);
  auto extend = [&](const Eigen::Vector2d& p) {
    box << std::min(box(0), p.x()), std::min(box(1), p.y()), std::max(box(2), p.x()), std::max(box(3), p.y());
  };
  for (std::size_t k = 0; k < pick.size(); ++k) {
    evaluate_pairs<double>(m, ctx.result.poses[pick[k]].q, nullptr, 2, kin);
    const std::vector<SE2<double>> lp = link_poses(m, kin);
    Placed& pl = placed[k];
    for (std::size_t l = 0; l < sketches.size(); ++l) {
      auto add = [&](const std::vector<Eigen::Vector2d>& pts, bool closed, bool body) {
        std::vector<Eigen::Vector2d> world;
        for (const auto& p : pts) {
          world.push_back(lp[l].act(p));
          extend(world.back());
        }
        pl.lines.push_back(std::move(world));
        pl.closed.push_back(closed);
        pl.body.push_back(body);
        pl.colors.push_back(sketches[l].color);
      };
      for (std::size_t c = 0; c < sketches[l].contours.size(); ++c) add(sketches[l].contours[c], sketches[l].closed[c], false);
      if (!sketches[l].body.empty()) add(sketches[l].body, false, true);
      for (const auto& p : sketches[l].joints) pl.joints.push_back(lp[l].act(p));
    }
    pl.contacts = contact_points(m, kin, lp);
  }
  const int w = 450, h = 360;
  const int input = ctx.sweep.variable;
  std::vector<std::string> panels;
  for (std::size_t k = 0; k < pick.size(); ++k) {
    const SweepPose<double>& pose = ctx.result.poses[pick[k]];
    io::SvgDrawing d(w, h, 24);
    d.set_title(base_name(scene.file) + ": " + m.variables[input].name + " = " + io::format_double(input_column(ctx, pick[k])) +
                (input_column_unit(ctx).empty() ? "" : " " + input_column_unit(ctx)) +
                (pose.report.ok() ? "" : " (" + std::string(to_string(pose.report.status)) + ")"));
    d.set_world_box(box(0), box(1), box(2), box(3));
    const Placed& pl = placed[k];
    for (std::size_t i = 0; i < pl.lines.size(); ++i) {
      io::Stroke st;
      st.color = pl.colors[i];
      st.width = pl.body[i] ? 2.4 : 1.6;
      d.add_polyline(pl.lines[i], st, pl.closed[i]);
    }
    for (const Eigen::Vector2d& p : pl.contacts) d.add_point(p, "#d62728", 3.5, io::Marker::Dot);
    for (const Eigen::Vector2d& p : pl.joints) d.add_point(p, "#333333", 3.5, io::Marker::Circle);
    // Ground pivots (the ground's frame is the world frame).
    const LinkSketch& ground = sketches[static_cast<std::size_t>(m.ground)];
    for (std::size_t j = 0; j < ground.pivots.size(); ++j) {
      d.add_point(ground.pivots[j], "#000000", 5, io::Marker::Square);
      d.add_text(ground.pivots[j], ground.pivot_names[j], 12, "#000000", 6, 14);
    }
    panels.push_back(d.to_svg());
  }
  if (panels.empty()) {
    io::SvgDrawing d(w, h, 24);
    d.set_title(base_name(scene.file) + ": no solved pose to draw");
    d.add_text(Eigen::Vector2d(0, 0), "no solved pose to draw", 14, "#d62728", 0, 0);
    return d.to_svg();
  }
  return tile_documents(panels, w, h, 2);
}

AssemblyRank full_rank(const Mechanism<double>& m, const SolveData<double>& sd) {
  MatrixX<double> j = sd.kin.dense_jacobian();  // either store (the sparse path keeps only the nonzeros)
  for (int c = 0; c < m.variable_count(); ++c) j.col(c) = j.col(c).cwiseQuotient(sd.row_scale) * m.variable_scale(c);
  Eigen::CompleteOrthogonalDecomposition<MatrixX<double>> cod(j);
  AssemblyRank r;
  r.rank = static_cast<int>(cod.rank());
  r.redundant = m.equation_count() - r.rank;
  r.mobility = m.variable_count() - r.rank;
  return r;
}

}  // namespace rollkin::cli
