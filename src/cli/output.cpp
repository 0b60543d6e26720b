// The output files of a solved sweep other than the plot (plot.cpp): the CSV text, the centrode files and the
// drawing of the mechanism; and the rank check of an assembly (output.hpp).
#include "output.hpp"

#include "rollkin/io/csv.hpp"
#include "rollkin/io/dxf_writer.hpp"
#include "rollkin/io/svg.hpp"

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace rollkin::cli {

std::string strip_header(const std::string& svg) {
  const std::size_t at = svg.find("<svg");
  return at == std::string::npos ? svg : svg.substr(at);
}

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
      const Vec2<double>& x = in_a ? c.in_a : c.in_b;
      if (!c.finite) close_run(false);
      else if (run.empty() || !same_centre(run.back(), x, m.length_scale)) run.push_back(x);
    }
    close_run(run.size() == centres.size());
  }
  return io::dxf_text(splines, ctx.scene.length_unit);
}

std::string centrode_single_point(const OutputContext& ctx, const std::vector<InstantCentre<double>>& centres, int a,
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
std::vector<std::size_t> poses_to_draw(const io::SweepRows& result, std::size_t count) {
  std::vector<std::size_t> solved;
  for (std::size_t i = 0; i < result.size(); ++i)
    if (result.has_pose(i)) solved.push_back(i);
  std::sort(solved.begin(), solved.end(), [&](auto a, auto b) { return result.input(a) < result.input(b); });
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
  io::RowReader rows(ctx.result);
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
    evaluate_pairs<double>(m, rows.q(pick[k]), nullptr, 2, kin);
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
    const SolveStatus status = ctx.result.status(pick[k]);
    io::SvgDrawing d(w, h, 24);
    d.set_title(base_name(scene.file) + ": " + m.variables[input].name + " = " + io::format_double(input_column(ctx, pick[k])) +
                (input_column_unit(ctx).empty() ? "" : " " + input_column_unit(ctx)) +
                (status == SolveStatus::Converged ? "" : " (" + std::string(to_string(status)) + ")"));
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
