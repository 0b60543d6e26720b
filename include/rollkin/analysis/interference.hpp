// Interference along a sweep: do contours of different links cross, or touch somewhere besides the contact
// the mechanism models? Opt-in: nothing here runs unless the caller asks (sweep() does not include it).
//
// Every contour is sampled once (samples_per_contour points, equally spaced in its parameter, in its link
// frame) into a hierarchy of bounding circles (geometry::SegmentHierarchy). For every solved pose of a
// SweepResult the link poses are computed (evaluate_pairs, link_poses) and each contour pair is handed with
// its two link poses to geometry::check_interference (the CGAL boundary; geometry/contact.hpp), which moves
// only the circles it visits: pairs of contours far apart cost one circle test, and near ones the segments
// near each other (exact crossing predicate). Of the zones where two polylines
// come within the touch tolerance, the one at a contact pair's own contact point is the modelled contact
// and is not reported; any other zone is a finding: Penetration if the polylines cross there, SecondTouch
// otherwise. Optionally each contact pair's curvatures are checked too: with both contours material-on-left
// the bodies stay apart near the contact only if kappa_A + kappa_B >= 0 (docs/method.md section 5); below
// -curvature_tolerance that is a CurvatureInterference finding (local overlap that sampled polylines of a
// nearly conformal contact cannot resolve).
//
// Limits (documented, not hidden): the polylines are chords, within the sagitta (about L^2 kappa / 8 for a
// chord of length L) of the curves, so touches closer than that are found only when touch_tolerance exceeds
// the sagittas of both contours; a second touching region that merges with the own contact zone (gap below
// the tolerance all the way between them) is reported as part of the own contact; crossings inside the own
// contact zone (chords of a conformal internal contact cross by up to the sagittas) are not reported.
#pragma once

#include "rollkin/geometry/contact.hpp"
#include "rollkin/solve/continuation.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace rollkin {

struct InterferenceCheck {
  /// Contour index pairs to check; empty: every pair of contours on different links.
  std::vector<std::pair<int, int>> contour_pairs;
  int samples_per_contour = 1024;
  /// Polylines within this distance (world units) touch; <= 0: relative_touch times the mechanism's
  /// length scale.
  double touch_tolerance = 0;
  double relative_touch = 1e-4;
  /// Also check kappa_A + kappa_B >= -curvature_tolerance at every contact pair (1/length units).
  bool check_contact_curvature = true;
  double curvature_tolerance = 1e-9;
};

enum class InterferenceKind { Penetration, SecondTouch, CurvatureInterference };

inline const char* to_string(InterferenceKind k) {
  switch (k) {
    case InterferenceKind::Penetration: return "penetration";
    case InterferenceKind::SecondTouch: return "second_touch";
    case InterferenceKind::CurvatureInterference: return "curvature_interference";
  }
  return "?";
}

struct InterferenceFinding {
  InterferenceKind kind;
  int contour_a = -1, contour_b = -1;
  int pair = -1;  // the contact pair between these contours (-1 if none); CurvatureInterference: that pair
  Vec2<double> point_a = Vec2<double>::Zero(), point_b = Vec2<double>::Zero();  // world, closest pair of the zone
  double distance = 0;   // zone's closest distance (0 when crossing); curvature: kappa_A + kappa_B
};

struct PoseInterference {
  double input = 0;
  bool checked = false;  // false: the pose was not solved
  std::vector<InterferenceFinding> findings;
  bool clear() const { return findings.empty(); }
  bool has(InterferenceKind k) const {
    for (const auto& f : findings)
      if (f.kind == k) return true;
    return false;
  }
};

struct SweepInterference {
  double touch_tolerance = 0;                 // the tolerance actually used
  /// Per contour (0 for one not checked): the largest distance of the curve from its chords, measured at the
  /// quarter points of every chord (the sagitta; exact at the midpoint for a circle's chords). Findings and
  /// touches are decided on the chords, so they are exact to within this of the curves.
  std::vector<double> chord_error;
  double max_chord_error() const {
    double e = 0;
    for (double c : chord_error) e = std::max(e, c);
    return e;
  }
  std::vector<std::pair<int, int>> contour_pairs;  // the pairs actually checked
  std::vector<PoseInterference> poses;        // one per pose of the sweep, same order
  bool any() const {
    for (const auto& p : poses)
      if (!p.clear()) return true;
    return false;
  }
};

namespace detail {

/// samples_per_contour points of a contour in its link frame, equally spaced in the parameter (open: both
/// ends included; closed: the period, first point not repeated).
template <class S> std::vector<Vec2<double>> contour_samples(const Contour<S>& c, int n) {
  const Domain<S> d = c.domain();
  std::vector<Vec2<double>> pts;
  pts.reserve(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    const Vec2<S> p = c.jet(d.sample(k, n), 0).p;
    pts.emplace_back(to_double(p.x()), to_double(p.y()));
  }
  return pts;
}

/// The largest distance of contour c from the chords of its samples (contour_samples), measured at the
/// quarter points of each chord's parameter interval.
template <class S> double chord_error(const Contour<S>& c, const std::vector<Vec2<double>>& pts) {
  const Domain<S> d = c.domain();
  const std::size_t n = pts.size(), segments = d.closed ? n : n - 1;
  const double lo = to_double(d.lo), span = to_double(d.hi - d.lo) / static_cast<double>(d.closed ? n : n - 1);
  double worst = 0;
  for (std::size_t k = 0; k < segments; ++k) {
    const Vec2<double>& p = pts[k];
    const Vec2<double> chord = pts[(k + 1) % n] - p;
    for (double f : {0.25, 0.5, 0.75}) {
      const Vec2<S> q = c.jet(S(lo + (static_cast<double>(k) + f) * span), 0).p;
      const Vec2<double> v = Vec2<double>(to_double(q.x()), to_double(q.y())) - p;
      const double len = chord.norm();
      worst = std::max(worst, len > 0 ? std::abs(v.x() * chord.y() - v.y() * chord.x()) / len : v.norm());
    }
  }
  return worst;
}

/// Segment of the sampled polyline of contour c holding parameter u.
template <class S> std::size_t segment_of(const Contour<S>& c, const S& u, int n) {
  const Domain<S> d = c.domain();
  const double span = to_double(d.hi - d.lo);
  const double segments = d.closed ? n : n - 1;
  double t = (to_double(d.wrap(u)) - to_double(d.lo)) / span * segments;
  if (t < 0) t = 0;
  const std::size_t k = static_cast<std::size_t>(t);
  return std::min(k, static_cast<std::size_t>(segments) - 1);
}

inline bool near_segment(const std::vector<std::size_t>& sorted, std::size_t k, std::size_t count, bool closed) {
  for (std::size_t s : sorted) {
    const std::size_t diff = s > k ? s - k : k - s;
    if (diff <= 1 || (closed && count - diff <= 1)) return true;
  }
  return false;
}

}  // namespace detail

/// Findings at one pose q of m (all variables, as solved).
template <class S> std::vector<InterferenceFinding> check_pose_interference(
    const Mechanism<S>& m, const VectorX<S>& q, const InterferenceCheck& opt,
    const std::vector<std::pair<int, int>>& contour_pairs, const std::vector<std::optional<geometry::SegmentHierarchy>>& local,
    double touch_tol, KinematicsData<S>& d) {
  evaluate_pairs<S>(m, q, nullptr, 2, d);
  const std::vector<SE2<S>> pose = link_poses(m, d);
  std::vector<SE2<double>> world(pose.size());
  for (std::size_t i = 0; i < pose.size(); ++i) world[i] = pose[i].template cast<double>();
  std::vector<InterferenceFinding> out;
  const int n = opt.samples_per_contour;
  for (const auto& [ca, cb] : contour_pairs) {
    const geometry::SegmentHierarchy &ha = *local[ca], &hb = *local[cb];
    const bool a_closed = ha.closed(), b_closed = hb.closed();
    const geometry::InterferenceReport rep = geometry::check_interference(
        ha, world[m.contours[ca].link()], hb, world[m.contours[cb].link()], touch_tol);
    // Own contacts: segments of the contact points of every contact pair between these two contours.
    std::vector<std::pair<std::size_t, std::size_t>> own;  // (segment on ca, segment on cb)
    int own_pair = -1;
    for (std::size_t k = 0; k < m.pairs.size(); ++k) {
      const Pair<S>& p = m.pairs[k];
      if (!is_contact(p.kind)) continue;
      const S& u = q(p.first_variable);
      const S& v = q(p.first_variable + 1);
      if (p.contour_a == ca && p.contour_b == cb)
        own.emplace_back(detail::segment_of(m.contours[ca], u, n), detail::segment_of(m.contours[cb], v, n));
      else if (p.contour_a == cb && p.contour_b == ca)
        own.emplace_back(detail::segment_of(m.contours[ca], v, n), detail::segment_of(m.contours[cb], u, n));
      else continue;
      own_pair = static_cast<int>(k);
    }
    const std::size_t na = ha.points().size(), nb = hb.points().size();
    for (const geometry::ContactZone& z : rep.zones) {
      bool is_own = false;
      for (const auto& [sa, sb] : own)
        is_own = is_own || detail::near_segment(z.a_segments, sa, na, a_closed) ||
                 detail::near_segment(z.b_segments, sb, nb, b_closed);
      if (is_own) continue;
      InterferenceFinding f;
      f.kind = z.penetrating ? InterferenceKind::Penetration : InterferenceKind::SecondTouch;
      f.contour_a = ca;
      f.contour_b = cb;
      f.pair = own_pair;
      f.point_a = z.on_a.point;
      f.point_b = z.on_b.point;
      f.distance = z.distance;
      out.push_back(f);
    }
  }
  if (opt.check_contact_curvature) {
    for (std::size_t k = 0; k < m.pairs.size(); ++k) {
      const Pair<S>& p = m.pairs[k];
      if (!is_contact(p.kind)) continue;
      const PairState<S>& st = d.pairs[k];
      const double sum = to_double(S(st.contact[0].curvature() + st.contact[1].curvature()));
      if (sum >= -opt.curvature_tolerance) continue;
      InterferenceFinding f;
      f.kind = InterferenceKind::CurvatureInterference;
      f.contour_a = p.contour_a;
      f.contour_b = p.contour_b;
      f.pair = static_cast<int>(k);
      const Vec2<S> pa = pose[p.link_a].act(st.contact[0].p);
      f.point_a = f.point_b = Vec2<double>(to_double(pa.x()), to_double(pa.y()));
      f.distance = sum;
      out.push_back(f);
    }
  }
  return out;
}

/// Interference at every solved pose of a sweep (unsolved poses: checked = false). Throws
/// std::invalid_argument for a bad contour index, a pair of contours on one link, or fewer than 3 samples.
template <class S> SweepInterference check_interference(const Mechanism<S>& m, const SweepResult<S>& sweep,
                                                        const InterferenceCheck& opt = {}) {
  if (opt.samples_per_contour < 3) throw std::invalid_argument("interference check: at least 3 samples per contour");
  SweepInterference out;
  out.touch_tolerance = opt.touch_tolerance > 0 ? opt.touch_tolerance : opt.relative_touch * to_double(m.length_scale);
  const int nc = static_cast<int>(m.contours.size());
  if (opt.contour_pairs.empty()) {
    for (int i = 0; i < nc; ++i)
      for (int j = i + 1; j < nc; ++j)
        if (m.contours[i].link() != m.contours[j].link()) out.contour_pairs.emplace_back(i, j);
  } else {
    for (const auto& [a, b] : opt.contour_pairs) {
      if (a < 0 || b < 0 || a >= nc || b >= nc) throw std::invalid_argument("interference check: no such contour");
      if (m.contours[a].link() == m.contours[b].link())
        throw std::invalid_argument("interference check: contours '" + m.contours[a].name() + "' and '" +
                                    m.contours[b].name() + "' are on the same link");
      out.contour_pairs.emplace_back(a, b);
    }
  }
  std::vector<std::optional<geometry::SegmentHierarchy>> local(m.contours.size());
  out.chord_error.assign(m.contours.size(), 0.0);
  for (const auto& [a, b] : out.contour_pairs)
    for (int c : {a, b}) {
      if (local[c]) continue;
      std::vector<Vec2<double>> pts = detail::contour_samples(m.contours[c], opt.samples_per_contour);
      out.chord_error[c] = detail::chord_error(m.contours[c], pts);
      local[c].emplace(std::move(pts), m.contours[c].domain().closed);
    }
  KinematicsData<S> d(m);
  out.poses.resize(sweep.poses.size());
  for (std::size_t i = 0; i < sweep.poses.size(); ++i) {
    const SweepPose<S>& p = sweep.poses[i];
    out.poses[i].input = to_double(p.input);
    if (!p.report.has_pose()) continue;
    out.poses[i].checked = true;
    out.poses[i].findings = check_pose_interference<S>(m, p.q, opt, out.contour_pairs, local, out.touch_tolerance, d);
  }
  return out;
}

// The interference check for one scalar S, after KEYWORD (`extern template` or `template`;
// ROLLKIN_POSITION_INSTANCES, docs/benchmark.md, "Build times").
#define ROLLKIN_INTERFERENCE_INSTANCES(KEYWORD, S) \
  KEYWORD SweepInterference check_interference(const Mechanism<S>&, const SweepResult<S>&, const InterferenceCheck&);

// Compiled once for double, in src/analysis/instantiate_double.cpp.
ROLLKIN_INTERFERENCE_INSTANCES(extern template, double)

}  // namespace rollkin
