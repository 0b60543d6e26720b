// The drawing of a solved sweep's mechanism (rollkin/output/drawing.hpp) and the parts of it the animation
// shares: each link's sketch in its own frame and the contact points.
#include "rollkin/output/drawing.hpp"

#include "rollkin/io/csv.hpp"
#include "rollkin/output/svg_drawing.hpp"
#include "rollkin/io/svg/markup.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace rollkin::output {

std::string strip_header(const std::string& svg) {
  const std::size_t at = svg.find("<svg");
  return at == std::string::npos ? svg : svg.substr(at);
}

std::string base_name(const std::string& file) { return std::filesystem::path(file).filename().string(); }

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

std::string draw_svg(const SweepOutput& ctx) {
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

}  // namespace rollkin::output
