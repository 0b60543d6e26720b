#include "animation.hpp"

#include "rollkin/centrodes.hpp"
#include "rollkin/io/csv.hpp"
#include "rollkin/io/decimate.hpp"
#include "rollkin/io/svg.hpp"
#include "rollkin/io/units.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

namespace rollkin::cli {
namespace {

const int kWidth = 900, kHeight = 640;  // px of the drawing
const double kMargin = 30;              // px around the mechanism's extent

/// A number with 7 significant digits (the compact table of the page), "null" when not finite (JSON).
std::string num(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.7g", v);
  return buf;
}

/// A JavaScript string literal of text with every character but letters, digits and " _.,:;()-" written as
/// \u00XX: nothing in it can end the string, the script or the CDATA section.
std::string js_string(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (std::isalnum(u) || std::string(" _.,:;()-").find(c) != std::string::npos) {
      out += c;
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(u));
      out += buf;
    }
  }
  return out + "\"";
}

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
    d += (d.empty() ? "" : " ") + std::string(drawing ? "" : "M") + num(p.x()) + " " + num(p.y());
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
  return "translate(" + num(c.x()) + " " + num(c.y()) + ") rotate(" + num(c.z()) + ")";
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

Frames frames_of(const OutputContext& ctx) {
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

/// The centrodes of every moving link relative to the ground (centrodes.hpp): per link its moving centrode
/// (in its own frame) and its fixed centrode (in the ground's frame). Only the part whose world point lies
/// within `view` (xmin, ymin, xmax, ymax) is kept: where two links turn at nearly the same rate the centre runs
/// off far away, and a path thousands of pictures long would only cost drawing time.
struct LinkCentrodes {
  std::vector<std::vector<Eigen::Vector2d>> fixed, moving;  // per link (empty for the ground)
};

LinkCentrodes centrodes_of(const OutputContext& ctx, const Frames& f, const Eigen::Vector4d& view) {
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

/// A JSON array of the numbers, 7 significant digits.
std::string json_numbers(const std::vector<double>& v) {
  std::string out = "[";
  for (std::size_t i = 0; i < v.size(); ++i) out += (i ? "," : "") + num(v[i]);
  return out + "]";
}

/// The data of the script, per frame: the pose (CSV row, from 0), the input column (full precision, as in
/// the CSV), a status index and the flat tables of link poses and contact points (null for a pose without
/// values).
std::string page_data(const OutputContext& ctx, const Frames& f, std::size_t start) {
  const Mechanism<double>& m = ctx.scene.mechanism;
  std::vector<std::string> texts, kinds;
  std::map<SolveStatus, std::size_t> index;
  std::string rows, inputs, status, poses, contacts;
  for (std::size_t k = 0; k < f.has.size(); ++k) {
    const SolveStatus s = ctx.result.status(f.pose[k]);
    if (!index.count(s)) {
      index[s] = texts.size();
      const std::string name = to_string(s);
      if (s == SolveStatus::Converged) {
        texts.push_back(name);
        kinds.push_back("ok");
      } else if (s == SolveStatus::Singular) {
        texts.push_back(name + ": the values follow the branch (interpolated between the regular poses on both sides)");
        kinds.push_back("warn");
      } else {
        texts.push_back(name + ": not solved, the moving links are hidden");
        kinds.push_back("bad");
      }
    }
    const std::string sep = k ? "," : "";
    rows += sep + std::to_string(f.pose[k]);
    inputs += sep + io::format_double(input_column(ctx, f.pose[k]));
    status += sep + std::to_string(index[s]);
    std::vector<double> row, points;
    for (const auto& p : f.links[k]) {
      const Eigen::Vector3d c = pose_columns(p);
      row.insert(row.end(), {c.x(), c.y(), c.z()});
    }
    for (const auto& p : f.contacts[k]) points.insert(points.end(), {p.x(), p.y()});
    poses += sep + (f.has[k] ? json_numbers(row) : "null");
    contacts += sep + (f.has[k] ? json_numbers(points) : "null");
  }
  auto strings = [](const std::vector<std::string>& v) {
    std::string out = "[";
    for (std::size_t i = 0; i < v.size(); ++i) out += (i ? "," : "") + js_string(v[i]);
    return out + "]";
  };
  return "{\"links\":" + std::to_string(m.links.size()) + ",\"contacts\":" + std::to_string(contact_pairs(m).size()) +
         ",\"ground\":" + std::to_string(m.ground) + ",\"start\":" + std::to_string(start) + ",\n\"status_texts\":" +
         strings(texts) + ",\"status_kinds\":" + strings(kinds) + ",\n\"rows\":[" + rows + "],\n\"inputs\":[" + inputs +
         "],\n\"status\":[" +
         status + "],\n\"poses\":[" + poses + "],\n\"contact_points\":[" + contacts + "]}";
}

// The page's style and script (fixed text). A frame sets one `transform` per link and per contact point from
// tables of strings built once from the data; nothing else of the document changes.
const char* const kStyle = R"CSS(
body { font: 14px sans-serif; margin: 12px; color: #222; }
h1 { font-size: 16px; margin: 0 0 8px 0; }
#controls { display: flex; flex-wrap: wrap; gap: 14px; align-items: center; margin-bottom: 6px; }
#pose { width: 280px; }
#play { width: 64px; }
#status.ok { color: #2a7d2a; }
#status.warn { color: #b8860b; font-weight: bold; }
#status.bad { color: #d62728; font-weight: bold; }
svg path { fill: none; vector-effect: non-scaling-stroke; stroke-linejoin: round; }
svg .joint { vector-effect: non-scaling-stroke; }
svg.no-traces .trace, svg.no-centrodes .centrode { display: none; }
)CSS";

const char* const kScript = R"JS(
(function () {
  "use strict";
  var d = rollkinData, n = d.inputs.length;
  var svg = document.getElementById("mechanism");
  var slider = document.getElementById("pose"), button = document.getElementById("play");
  var valueOut = document.getElementById("input-value"), indexOut = document.getElementById("pose-index");
  var statusOut = document.getElementById("status");
  var links = [], contacts = [], l, c, k;
  for (l = 0; l < d.links; ++l) links.push(document.getElementById("link-" + l));
  for (c = 0; c < d.contacts; ++c) contacts.push(document.getElementById("contact-" + c));
  // Per pose, the transform of every link and contact point (null: the pose has no values).
  var linkT = [], contactT = [];
  for (k = 0; k < n; ++k) {
    var p = d.poses[k], q = d.contact_points[k], t = null, u = null;
    if (p !== null) {
      t = [];
      for (l = 0; l < d.links; ++l) t.push("translate(" + p[3 * l] + " " + p[3 * l + 1] + ") rotate(" + p[3 * l + 2] + ")");
      u = [];
      for (c = 0; c < d.contacts; ++c) u.push("translate(" + q[2 * c] + " " + q[2 * c + 1] + ")");
    }
    linkT.push(t);
    contactT.push(u);
  }
  var shown = -1, hidden = false;
  function setHidden(h) {
    if (h === hidden) return;
    hidden = h;
    for (l = 0; l < links.length; ++l) if (l !== d.ground) links[l].setAttribute("visibility", h ? "hidden" : "visible");
    for (c = 0; c < contacts.length; ++c) contacts[c].setAttribute("visibility", h ? "hidden" : "visible");
  }
  function show(i) {
    if (i === shown) return;
    shown = i;
    var t = linkT[i], u = contactT[i];
    if (t !== null) {
      for (l = 0; l < links.length; ++l) links[l].setAttribute("transform", t[l]);
      for (c = 0; c < contacts.length; ++c) contacts[c].setAttribute("transform", u[c]);
    }
    setHidden(t === null);
    valueOut.textContent = String(d.inputs[i]);
    indexOut.textContent = String(d.rows[i] + 1);
    statusOut.textContent = d.status_texts[d.status[i]];
    statusOut.className = d.status_kinds[d.status[i]];
    slider.value = String(i);
  }
  // Playing: about six seconds per sweep (10 to 60 poses per second), from the pose shown, looping.
  var rate = Math.min(60, Math.max(10, n / 6)), playing = false, t0 = null, from = 0;
  function tick(now) {
    if (!playing) return;
    if (t0 === null) t0 = now;
    show((from + Math.floor((now - t0) * rate / 1000)) % n);
    window.requestAnimationFrame(tick);
  }
  function setPlaying(on) {
    playing = on;
    button.textContent = on ? "Pause" : "Play";
    button.setAttribute("aria-pressed", on ? "true" : "false");
    if (on) {
      t0 = null;
      from = shown === n - 1 ? 0 : shown;
      window.requestAnimationFrame(tick);
    }
  }
  button.addEventListener("click", function () { setPlaying(!playing); });
  slider.addEventListener("input", function () { show(Number(slider.value)); t0 = null; from = shown; });
  var traces = document.getElementById("show-traces");  // (none without contact pairs)
  if (traces !== null) traces.addEventListener("change", function (e) { svg.classList.toggle("no-traces", !e.target.checked); });
  document.getElementById("show-centrodes").addEventListener("change", function (e) {
    svg.classList.toggle("no-centrodes", !e.target.checked);
  });
  show(d.start);
})();
)JS";

std::string fixed2(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

/// What the page is made of: the links' drawings, the frames, the pose shown first and the view.
struct Page {
  const OutputContext& ctx;
  const Mechanism<double>& m;
  std::vector<LinkSketch> sketches;
  Frames f;
  std::vector<int> contacts;  // the contact pairs, in the order of the contact points
  std::size_t start = 0;      // the frame shown first: the first with values
  bool shown = false;         // ... and it has values
  double scale = 1, ox = 0, oy = 0;  // world to pixels (y up): pixel = (ox + scale x, oy - scale y)
  double px = 1;                     // one pixel in world units (marker sizes)
  Eigen::Vector4d around;            // the picture and as much again around it (world)

  explicit Page(const OutputContext& c)
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
         ": animation (rollkin)</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n<h1>" + name + ": " +
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
    svg += "<circle class=\"joint\" cx=\"" + num(j.x()) + "\" cy=\"" + num(j.y()) + "\" r=\"" + num(3.5 * p.px) +
           "\" fill=\"#ffffff\" stroke=\"#333333\" stroke-width=\"1.2\"/>\n";
  for (std::size_t j = 0; j < k.pivots.size(); ++j) {
    const Eigen::Vector2d& at = k.pivots[j];
    // The name upright in pixels: the text's own frame undoes the world's scale and y flip.
    svg += "<rect x=\"" + num(at.x() - 5 * p.px) + "\" y=\"" + num(at.y() - 5 * p.px) + "\" width=\"" + num(10 * p.px) +
           "\" height=\"" + num(10 * p.px) + "\" fill=\"#000000\"/>\n<text transform=\"translate(" + num(at.x()) + " " +
           num(at.y()) + ") scale(" + num(p.px) + " " + num(-p.px) + ")\" x=\"7\" y=\"16\" font-size=\"12\">" +
           io::xml_escape(k.pivot_names[j]) + "</text>\n";
  }
  return svg + "</g>\n";
}

/// The contact points, each moved by its transform (that of the first pose shown).
std::string contact_markers(const Page& p) {
  std::string svg;
  for (std::size_t slot = 0; slot < p.contacts.size(); ++slot) {
    const Eigen::Vector2d at = p.shown ? p.f.contacts[p.start][slot] : Eigen::Vector2d::Zero();
    svg += "<circle id=\"contact-" + std::to_string(slot) + "\" class=\"contact\" r=\"" + num(3.5 * p.px) +
           "\" fill=\"#d62728\" transform=\"translate(" + num(at.x()) + " " + num(at.y()) + ")\"" +
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
                    num(p.scale) + " 0 0 " + num(-p.scale) + " " + fixed2(p.ox) + " " + fixed2(p.oy) + ")\">\n";
  svg += contact_paths(p);
  for (std::size_t l = 0; l < p.sketches.size(); ++l) svg += link_group(p, centrodes, l);
  svg += contact_markers(p);
  return svg + "</g>\n</svg>\n";
}

}  // namespace

std::string animation_html(const OutputContext& ctx) {
  const Page p(ctx);
  return head_and_controls(p) + drawing(p) + "<script>//<![CDATA[\nvar rollkinData = " + page_data(ctx, p.f, p.start) +
         ";\n" + kScript + "//]]>\n</script>\n</body>\n</html>\n";
}

}  // namespace rollkin::cli
