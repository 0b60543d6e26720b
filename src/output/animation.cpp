#include "rollkin/output/animation.hpp"

#include "animation_assets.hpp"  // generated: animation.css and animation.js as string literals

#include "rollkin/analysis/centrodes.hpp"
#include "rollkin/io/csv.hpp"
#include "rollkin/output/decimate.hpp"
#include "rollkin/io/format.hpp"
#include "rollkin/io/svg/markup.hpp"
#include "rollkin/io/units.hpp"

#include <algorithm>
#include <cstdlib>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include <nlohmann/json.hpp>

namespace rollkin::output {
namespace {

/// A coordinate of the page's drawing: 7 significant digits.
std::string coordinate(double v) { return io::format_number(v, 7); }

const int kWidth = 900, kHeight = 640;  // px of the drawing
const double kMargin = 30;              // px around the mechanism's extent

/// SVG path data through the points ("M x y x y ...": coordinates after a moveto are linetos; "Z" when
/// closed); a non-finite point breaks the path, the next finite one starts a new piece.
std::string path_data(const std::vector<Eigen::Vector2d>& pts, bool closed) {
  std::string d;
  bool drawing = false, broken = false;
  for (const Eigen::Vector2d& p : pts) {
    if (!p.allFinite()) {
      drawing = false;
      broken = true;
      continue;
    }
    d += (d.empty() ? "" : " ") + std::string(drawing ? "" : "M") + coordinate(p.x()) + " " + coordinate(p.y());
    drawing = true;
  }
  if (closed && !broken && !d.empty()) d += " Z";
  return d;
}

/// Whether the finite points spread over more than `size` in x or y (a centrode that stays within one pixel,
/// such as that of a link turning about a ground pivot, is not drawn).
bool spans(const std::vector<Eigen::Vector2d>& pts, double size) {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Eigen::Vector2d& p : pts)
    if (p.allFinite()) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  return (hi - lo).maxCoeff() > size;
}

/// A link pose as the CSV's <link>.x, <link>.y, <link>.angle columns give it (angle in degrees).
Eigen::Vector3d pose_columns(const SE2<double>& p) {
  return {p.translation().x(), p.translation().y(), io::from_radians(p.angle(), io::AngleUnit::Degree)};
}

/// "translate(x y) rotate(angle)" of a link pose: a point p of the link's frame at R p + t, angle in degrees.
std::string transform_of(const SE2<double>& pose) {
  const Eigen::Vector3d c = pose_columns(pose);
  return "translate(" + coordinate(c.x()) + " " + coordinate(c.y()) + ") rotate(" + coordinate(c.z()) + ")";
}

/// The frames of the page (io::pick_frames: every pose of a sweep of up to io::kAnimationFrames, else as many
/// evenly spaced plus the poses where the status changes) and everything that moves at each frame whose pose
/// has values (has_pose()): link poses and contact points.
struct Frames {
  std::vector<std::size_t> pose;                       // per frame: the pose (CSV row) it shows
  std::vector<bool> has;                               // per frame
  std::vector<std::vector<SE2<double>>> links;         // per frame, per link: world pose
  std::vector<std::vector<Eigen::Vector2d>> contacts;  // per frame, per contact pair: world point
};

Frames frames_of(const SweepOutput& ctx) {
  const Mechanism<double>& m = ctx.scene.mechanism;
  const io::SweepRows& result = ctx.result;
  io::RowReader rows(result);
  KinematicsData<double> kin(m);
  Frames f;
  f.pose = io::pick_frames(result.size(), [&](std::size_t k) { return static_cast<int>(result.status(k)); });
  for (const std::size_t k : f.pose) {
    f.has.push_back(result.has_pose(k));
    f.links.emplace_back();
    f.contacts.emplace_back();
    if (!f.has.back()) continue;
    evaluate_pairs<double>(m, rows.q(k), nullptr, 1, kin);  // as csv_text: the same link poses
    f.links.back() = link_poses(m, kin);
    f.contacts.back() = contact_points(m, kin, f.links.back());
  }
  return f;
}

/// World box (xmin, ymin, xmax, ymax) of the links' drawings and the contact points over all frames with
/// values, and of the ground's drawing (in the world frame: link_poses()) also when no pose has values.
Eigen::Vector4d extent(const std::vector<LinkSketch>& sketches, const Frames& f, int ground) {
  const double inf = std::numeric_limits<double>::infinity();
  Eigen::Vector4d box(inf, inf, -inf, -inf);
  auto add = [&](const Eigen::Vector2d& p) {
    if (!p.allFinite()) return;
    box << std::min(box(0), p.x()), std::min(box(1), p.y()), std::max(box(2), p.x()), std::max(box(3), p.y());
  };
  auto add_link = [&](const LinkSketch& k, const SE2<double>& at) {
    for (const auto& c : k.contours)
      for (const auto& p : c) add(at.act(p));
    for (const auto& p : k.body) add(at.act(p));
    for (const auto& p : k.pivots) add(at.act(p));
  };
  add_link(sketches[static_cast<std::size_t>(ground)], SE2<double>());
  for (std::size_t k = 0; k < f.has.size(); ++k) {
    if (!f.has[k]) continue;
    for (std::size_t l = 0; l < sketches.size(); ++l) add_link(sketches[l], f.links[k][l]);
    for (const auto& p : f.contacts[k]) add(p);
  }
  if (!(box(0) <= box(2))) box << -1, -1, 1, 1;  // nothing drawn
  return box;
}

/// The centrodes of every moving link relative to the ground (analysis/centrodes.hpp): per link its moving centrode
/// (in its own frame) and its fixed centrode (in the ground's frame). Only the part whose world point lies
/// within `view` (xmin, ymin, xmax, ymax) is kept: where two links turn at nearly the same rate the centre runs
/// off far away, and a path thousands of pictures long would only cost drawing time.
struct LinkCentrodes {
  std::vector<std::vector<Eigen::Vector2d>> fixed, moving;  // per link (empty for the ground)
};

LinkCentrodes centrodes_of(const SweepOutput& ctx, const Frames& f, const Eigen::Vector4d& view) {
  const Mechanism<double>& m = ctx.scene.mechanism;
  KinematicsData<double> kin(m);
  LinkCentrodes out;
  out.fixed.resize(m.links.size());
  out.moving.resize(m.links.size());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Eigen::Vector2d none(nan, nan);
  // At the frames' poses (as centrodes() computes them at every pose of a sweep).
  io::RowReader rows(ctx.result);
  for (std::size_t k = 0; k < f.pose.size(); ++k) {
    std::vector<Twist<double>> twists;
    if (f.has[k]) {
      evaluate_pairs<double>(m, rows.q(f.pose[k]), nullptr, 1, kin);
      twists = link_twists<double>(m, kin, f.links[k], rows.qdot(f.pose[k]));
    }
    for (std::size_t l = 0; l < m.links.size(); ++l) {
      if (static_cast<int>(l) == m.ground) continue;
      const InstantCentre<double> c = f.has[k] ? instant_centre(f.links[k], twists, m.ground, static_cast<int>(l), m.length_scale)
                                               : InstantCentre<double>();
      const bool shown = c.finite && c.world.x() >= view(0) && c.world.y() >= view(1) && c.world.x() <= view(2) &&
                         c.world.y() <= view(3);
      out.fixed[l].push_back(shown ? Eigen::Vector2d(c.in_a) : none);
      out.moving[l].push_back(shown ? Eigen::Vector2d(c.in_b) : none);
    }
  }
  return out;
}

/// v rounded to 7 significant digits (the page's compact tables), NaN (JSON null) when not finite.
double seven_digits(double v) {
  if (!std::isfinite(v)) return std::numeric_limits<double>::quiet_NaN();
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.7g", v);
  return std::strtod(buf, nullptr);
}

/// Text of the status of one kind on the page, and the class that colours it.
std::pair<std::string, std::string> status_text(SolveStatus s) {
  const std::string name = to_string(s);
  if (s == SolveStatus::Converged) return {name, "ok"};
  if (s == SolveStatus::Singular)
    return {name + ": the values follow the branch (interpolated between the regular poses on both sides)", "warn"};
  return {name + ": not solved, the moving links are hidden", "bad"};
}

/// The data of the script (nlohmann-json), per frame: the pose (CSV row, from 0), the input column (full
/// precision, as in the CSV), a status index and the flat tables of link poses and contact points (7
/// significant digits; null for a pose without values). Only numbers and the fixed status texts: nothing in
/// it can end the script or its CDATA section.
std::string page_data(const SweepOutput& ctx, const Frames& f, std::size_t start) {
  using nlohmann::json;
  const Mechanism<double>& m = ctx.scene.mechanism;
  json texts = json::array(), kinds = json::array(), rows = json::array(), inputs = json::array(),
       status = json::array(), poses = json::array(), contacts = json::array();
  std::map<SolveStatus, std::size_t> index;
  for (std::size_t k = 0; k < f.has.size(); ++k) {
    const SolveStatus s = ctx.result.status(f.pose[k]);
    if (!index.count(s)) {
      index[s] = texts.size();
      const auto [text, kind] = status_text(s);
      texts.push_back(text);
      kinds.push_back(kind);
    }
    rows.push_back(f.pose[k]);
    inputs.push_back(input_column(ctx, f.pose[k]));
    status.push_back(index[s]);
    json row = json::array(), points = json::array();
    for (const auto& p : f.links[k]) {
      const Eigen::Vector3d c = pose_columns(p);
      for (double v : {c.x(), c.y(), c.z()}) row.push_back(seven_digits(v));
    }
    for (const auto& p : f.contacts[k]) {
      points.push_back(seven_digits(p.x()));
      points.push_back(seven_digits(p.y()));
    }
    poses.push_back(f.has[k] ? row : json(nullptr));
    contacts.push_back(f.has[k] ? points : json(nullptr));
  }
  const json data{{"links", m.links.size()},    {"contacts", contact_pairs(m).size()}, {"ground", m.ground},
                  {"start", start},             {"status_texts", texts},               {"status_kinds", kinds},
                  {"rows", rows},               {"inputs", inputs},                    {"status", status},
                  {"poses", poses},             {"contact_points", contacts}};
  return data.dump(-1, ' ', /*ensure_ascii=*/true);
}


std::string fixed2(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

/// What the page is made of: the links' drawings, the frames, the pose shown first and the view.
struct Page {
  const SweepOutput& ctx;
  const Mechanism<double>& m;
  std::vector<LinkSketch> sketches;
  Frames f;
  std::vector<int> contacts;  // the contact pairs, in the order of the contact points
  std::size_t start = 0;      // the frame shown first: the first with values
  bool shown = false;         // ... and it has values
  double scale = 1, ox = 0, oy = 0;  // world to pixels (y up): pixel = (ox + scale x, oy - scale y)
  double px = 1;                     // one pixel in world units (marker sizes)
  Eigen::Vector4d around;            // the picture and as much again around it (world)

  explicit Page(const SweepOutput& c)
      : ctx(c), m(c.scene.mechanism), sketches(link_sketches(m)), f(frames_of(c)), contacts(contact_pairs(m)) {
    const std::size_t n = f.has.size();
    while (start + 1 < n && !f.has[start]) ++start;
    shown = n > 0 && f.has[start];
    // The extent centred with a margin.
    const Eigen::Vector4d box = extent(sketches, f, m.ground);
    const double w = std::max(box(2) - box(0), 1e-12 * m.length_scale), h = std::max(box(3) - box(1), 1e-12 * m.length_scale);
    scale = std::min((kWidth - 2 * kMargin) / w, (kHeight - 2 * kMargin) / h);
    ox = kWidth / 2.0 - scale * (box(0) + box(2)) / 2;
    oy = kHeight / 2.0 + scale * (box(1) + box(3)) / 2;
    px = 1 / scale;
    around << box(0) - w, box(1) - h, box(2) + w, box(3) + h;
  }
};

/// The page's head, title and controls: play/pause, the slider over the frames, the input value, the pose
/// (CSV row) shown, the status, the toggles.
std::string head_and_controls(const Page& p) {
  const std::size_t n = p.f.has.size(), poses = p.ctx.result.size();
  const std::string name = io::xml_escape(base_name(p.ctx.scene.file));
  const std::string unit = io::xml_escape(input_column_unit(p.ctx));
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n<title>" + name +
         ": animation (rollkin)</title>\n<style>" + assets::kAnimationStyle + "</style>\n</head>\n<body>\n<h1>" + name + ": " +
         std::to_string(poses) + " poses of the sweep of " + io::xml_escape(p.ctx.sweep.input) +
         (n < poses ? ", " + std::to_string(n) + " of them shown (evenly spaced, and both sides of every status change)" : "") +
         "</h1>\n" +
         "<div id=\"controls\">\n<button id=\"play\" type=\"button\" aria-pressed=\"false\">Play</button>\n" +
         "<input id=\"pose\" type=\"range\" min=\"0\" max=\"" + std::to_string(n ? n - 1 : 0) + "\" step=\"1\" value=\"" +
         std::to_string(p.start) + "\" aria-label=\"pose\"/>\n<span><span id=\"input-name\">" +
         io::xml_escape(p.m.variables[p.ctx.sweep.variable].name) + "</span> = <output id=\"input-value\">" +
         (n ? io::format_double(input_column(p.ctx, p.f.pose[p.start])) : "") + "</output>" + (unit.empty() ? "" : " " + unit) +
         "</span>\n<span>pose <output id=\"pose-index\">" + (n ? std::to_string(p.f.pose[p.start] + 1) : "0") + "</output>/" +
         std::to_string(poses) +
         "</span>\n<output id=\"status\"></output>\n" +
         (p.contacts.empty() ? "" : "<label><input id=\"show-traces\" type=\"checkbox\" checked=\"checked\"/> contact paths</label>\n") +
         "<label><input id=\"show-centrodes\" type=\"checkbox\"/> centrodes</label>\n</div>\n";
}

/// The paths of the contact points over the sweep (world frame), drawn once.
std::string contact_paths(const Page& p) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::string svg;
  for (std::size_t slot = 0; slot < p.contacts.size(); ++slot) {
    std::vector<Eigen::Vector2d> path;
    for (std::size_t k = 0; k < p.f.has.size(); ++k) path.push_back(p.f.has[k] ? p.f.contacts[k][slot] : Eigen::Vector2d(nan, nan));
    svg += "<path class=\"trace\" stroke=\"#d62728\" stroke-width=\"1\" stroke-dasharray=\"4 3\" stroke-opacity=\"0.7\" d=\"" +
           path_data(path, false) + "\"><title>path of the contact point of " +
           io::xml_escape(p.m.pairs[p.contacts[slot]].name) + "</title></path>\n";
  }
  return svg;
}

/// A centrode as a path of the given dash pattern, or nothing when it stays within a pixel.
std::string centrode_path(const Page& p, const std::vector<Eigen::Vector2d>& pts, std::size_t link, const std::string& dash,
                          const std::string& what) {
  if (!spans(pts, p.px)) return "";
  return "<path class=\"centrode\" stroke=\"" + p.sketches[link].color + "\" stroke-width=\"1.2\" stroke-dasharray=\"" + dash +
         "\" d=\"" + path_data(pts, false) + "\"><title>" + what + " centrode of " + io::xml_escape(p.m.links[link].name) +
         "</title></path>\n";
}

/// Link l drawn once in its own frame, in a group moved by its transform (that of the first pose shown):
/// its centrodes, contours, body, joints and (the ground) pivots with their names.
std::string link_group(const Page& p, const LinkCentrodes& centrodes, std::size_t l) {
  const LinkSketch& k = p.sketches[l];
  const bool ground = static_cast<int>(l) == p.m.ground;
  std::string svg = "<g id=\"link-" + std::to_string(l) + "\" class=\"link\" transform=\"" +
                    (p.shown ? transform_of(p.f.links[p.start][l]) : std::string("translate(0 0) rotate(0)")) + "\"" +
                    (p.shown || ground ? "" : " visibility=\"hidden\"") + ">\n<title>" + io::xml_escape(p.m.links[l].name) +
                    "</title>\n";
  if (ground)
    for (std::size_t o = 0; o < p.sketches.size(); ++o) svg += centrode_path(p, centrodes.fixed[o], o, "2 3", "fixed");
  svg += centrode_path(p, centrodes.moving[l], l, "6 3", "moving");
  for (std::size_t c = 0; c < k.contours.size(); ++c)
    svg += "<path class=\"contour\" stroke=\"" + k.color + "\" stroke-width=\"1.6\" d=\"" + path_data(k.contours[c], k.closed[c]) + "\"/>\n";
  if (!k.body.empty())
    svg += "<path class=\"body\" stroke=\"" + k.color + "\" stroke-width=\"2.4\" d=\"" + path_data(k.body, false) + "\"/>\n";
  for (const auto& j : k.joints)
    svg += "<circle class=\"joint\" cx=\"" + coordinate(j.x()) + "\" cy=\"" + coordinate(j.y()) + "\" r=\"" + coordinate(3.5 * p.px) +
           "\" fill=\"#ffffff\" stroke=\"#333333\" stroke-width=\"1.2\"/>\n";
  for (std::size_t j = 0; j < k.pivots.size(); ++j) {
    const Eigen::Vector2d& at = k.pivots[j];
    // The name upright in pixels: the text's own frame undoes the world's scale and y flip.
    svg += "<rect x=\"" + coordinate(at.x() - 5 * p.px) + "\" y=\"" + coordinate(at.y() - 5 * p.px) + "\" width=\"" + coordinate(10 * p.px) +
           "\" height=\"" + coordinate(10 * p.px) + "\" fill=\"#000000\"/>\n<text transform=\"translate(" + coordinate(at.x()) + " " +
           coordinate(at.y()) + ") scale(" + coordinate(p.px) + " " + coordinate(-p.px) + ")\" x=\"7\" y=\"16\" font-size=\"12\">" +
           io::xml_escape(k.pivot_names[j]) + "</text>\n";
  }
  return svg + "</g>\n";
}

/// The contact points, each moved by its transform (that of the first pose shown).
std::string contact_markers(const Page& p) {
  std::string svg;
  for (std::size_t slot = 0; slot < p.contacts.size(); ++slot) {
    const Eigen::Vector2d at = p.shown ? p.f.contacts[p.start][slot] : Eigen::Vector2d::Zero();
    svg += "<circle id=\"contact-" + std::to_string(slot) + "\" class=\"contact\" r=\"" + coordinate(3.5 * p.px) +
           "\" fill=\"#d62728\" transform=\"translate(" + coordinate(at.x()) + " " + coordinate(at.y()) + ")\"" +
           (p.shown ? "" : " visibility=\"hidden\"") + "><title>contact " + io::xml_escape(p.m.pairs[p.contacts[slot]].name) +
           "</title></circle>\n";
  }
  return svg;
}

/// The inline SVG: one world group (y up) holding the contact paths, the link groups and the contact points.
std::string drawing(const Page& p) {
  const LinkCentrodes centrodes = centrodes_of(p.ctx, p.f, p.around);
  const std::string w = std::to_string(kWidth), h = std::to_string(kHeight);
  std::string svg = "<svg id=\"mechanism\" class=\"no-centrodes\" width=\"" + w + "\" height=\"" + h + "\" viewBox=\"0 0 " + w +
                    " " + h + "\">\n<rect width=\"" + w + "\" height=\"" + h + "\" fill=\"#ffffff\"/>\n<g transform=\"matrix(" +
                    coordinate(p.scale) + " 0 0 " + coordinate(-p.scale) + " " + fixed2(p.ox) + " " + fixed2(p.oy) + ")\">\n";
  svg += contact_paths(p);
  for (std::size_t l = 0; l < p.sketches.size(); ++l) svg += link_group(p, centrodes, l);
  svg += contact_markers(p);
  return svg + "</g>\n</svg>\n";
}

}  // namespace

std::string animation_html(const SweepOutput& ctx) {
  const Page p(ctx);
  return head_and_controls(p) + drawing(p) + "<script>//<![CDATA[\nvar rollkinData = " + page_data(ctx, p.f, p.start) +
         ";\n" + assets::kAnimationScript + "//]]>\n</script>\n</body>\n</html>\n";
}

}  // namespace rollkin::output
