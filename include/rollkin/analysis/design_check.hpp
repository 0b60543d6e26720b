// The undercut and conformity check of a solved sweep (docs/analysis.md "Design check"): for every cam or
// rolling pair, what its contours' curvatures allow.
//
// Signs as in analysis.hpp: kappa1, kappa2 are the signed curvatures of the pair's first and second contour at
// the contact, positive where a contour is convex toward the other body. Near the contact the bodies stay
// apart only while kappa1 + kappa2 >= 0 (docs/method.md section 5); below zero they interpenetrate: the design
// is impossible there.
//
// A circular contour of radius r (a roller) touching a contour of curvature kappa: the roller centre runs on
// the offset of that contour at distance r, c(u) = p(u) + r n(u), whose speed is sigma (1 + r kappa) (n the
// outward normal, n' = kappa sigma t). Where the contour is concave with radius rho = -1/kappa < r the factor
// 1 + r kappa is negative: the roller is too large to enter, the offset runs backwards (undercut), and it has a
// cusp where 1 + r kappa = 0. This is the same sign as kappa + 1/r, the relative curvature, so for a roller the
// undercut region is where the relative curvature is negative, and its ends are the offset's cusps.
//
// What is reported, per contact pair, over the touched part of each contour:
//  - the sharpest convex and the sharpest concave point touched (largest and smallest kappa), hence the
//    smallest radius of curvature touched, each with its parameter, point and the input at which it is touched;
//  - the smallest relative curvature kappa1 + kappa2 over the contacts made, and where, with the verdict of an
//    exact sign test (geometry/curvature_sign.hpp): conforming, osculating (zero within a relative band) or
//    interpenetrating;
//  - for a pair with a circular contour (roller) that interpenetrates: the ends of the undercut region on the
//    other contour, the cusps of the roller-centre path, where 1 + r kappa = 0.
// "Touched" covers the motion between the solved poses too: between two consecutive solved poses each contact
// parameter follows the cubic Hermite interpolant of its values and rates there (linear where a pose is singular
// and its rates are meaningless), sampled samples_per_step times, and the extreme samples are refined on that
// path (the zero of its slope, else Brent's minimisation). So a concave point passed between two poses is
// still found.
#pragma once

#include "rollkin/geometry/curvature_sign.hpp"
#include "rollkin/solve/continuation.hpp"

#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <variant>
#include <vector>

namespace rollkin {

struct DesignCheckOptions {
  int samples_per_step = 8;         // curvature samples on the contact path between two solved poses
  double osculation_band = 1e-9;    // relative zero band of the sign test (geometry/curvature_sign.hpp)
  int cusp_search_steps = 1024;     // steps over the contour's domain when walking to the undercut's ends
};

/// A point of a contour touched along the sweep.
template <class S> struct TouchedPoint {
  bool found = false;
  S u = S(0);                       // the contour's parameter (the pair variable's value, internal units)
  Vec2<S> point = Vec2<S>::Zero();  // in the contour's own frame (the profile's coordinates)
  S kappa = S(0);                   // signed curvature there (1/length)
  S input = S(0);                   // the swept input at which it is touched (interpolated between poses)
};

template <class S> struct ContourCurvatureCheck {
  int contour = -1;
  bool circle = false;              // a circle or circular arc (a roller when convex)
  S radius = S(0);                  // its radius, for a circle
  TouchedPoint<S> sharpest_convex;  // largest kappa > 0 touched: the smallest convex radius, 1 / kappa
  TouchedPoint<S> sharpest_concave; // smallest kappa < 0 touched: the smallest concave radius, -1 / kappa
  /// The smallest radius of curvature touched on either side; infinity where only straight parts were.
  S min_radius() const {
    using std::min;
    S r = std::numeric_limits<S>::infinity();
    if (sharpest_convex.found) r = S(1) / sharpest_convex.kappa;
    if (sharpest_concave.found) r = min(r, S(S(-1) / sharpest_concave.kappa));
    return r;
  }
};

enum class Conformity { Conforming, Osculating, Interpenetrating };

inline const char* to_string(Conformity c) {
  switch (c) {
    case Conformity::Conforming: return "conforming";
    case Conformity::Osculating: return "osculating";
    case Conformity::Interpenetrating: return "interpenetrating";
  }
  return "?";
}

template <class S> struct PairDesignCheck {
  int pair = -1;                                    // index in Mechanism::pairs
  bool touched = false;                             // at least one solved pose
  std::array<ContourCurvatureCheck<S>, 2> contours; // the pair's first and second contour
  int roller = -1;                                  // 0 or 1: the side whose contour is a convex circle; -1 none
  S worst_relative = S(0);                          // smallest kappa1 + kappa2 over the contacts made
  std::array<TouchedPoint<S>, 2> worst;             // the contact points where it occurs
  Conformity conformity = Conformity::Conforming;   // exact sign test at that contact
  /// For a roller that interpenetrates: the ends of the undercut region on the other contour (the roller
  /// centre path's cusps, 1 + r kappa = 0), before and after `worst` in its parameter; not found where the
  /// region reaches the end of an open contour or covers a closed one.
  std::array<TouchedPoint<S>, 2> cusps;
};

template <class S> struct DesignCheck {
  std::vector<PairDesignCheck<S>> pairs;  // one per cam or rolling pair, in pair order
  bool impossible() const {
    for (const auto& p : pairs)
      if (p.conformity == Conformity::Interpenetrating) return true;
    return false;
  }
};

namespace detail {

/// The contact parameters of one pair between two consecutive solved poses, as functions of t in [0, 1]
/// (input = in0 + (in1 - in0) t): cubic Hermite interpolants of the values and the rates scaled to t.
template <class S> struct ContactPath {
  S in0, in1;
  std::array<std::array<S, 4>, 2> coeff;  // per side: u(t) = ((c3 t + c2) t + c1) t + c0

  S input(const S& t) const { return in0 + (in1 - in0) * t; }
  S param(int side, const S& t) const {
    const auto& c = coeff[static_cast<std::size_t>(side)];
    return ((c[3] * t + c[2]) * t + c[1]) * t + c[0];
  }
  S rate(int side, const S& t) const {  // du/dt
    const auto& c = coeff[static_cast<std::size_t>(side)];
    return (S(3) * c[3] * t + S(2) * c[2]) * t + c[1];
  }
};

/// Hermite coefficients from u(0) = u0, u(1) = u1, u'(0) = m0, u'(1) = m1.
template <class S> std::array<S, 4> hermite(const S& u0, const S& u1, const S& m0, const S& m1) {
  return {u0, m0, S(S(3) * (u1 - u0) - S(2) * m0 - m1), S(S(2) * (u0 - u1) + m0 + m1)};
}

/// The contact paths of pair p: one per consecutive pair of solved poses, and a constant one for a solved
/// pose with no solved neighbour after it and none before it.
template <class S> std::vector<ContactPath<S>> contact_paths(const Pair<S>& p, const SweepResult<S>& sweep) {
  std::vector<ContactPath<S>> paths;
  const auto& poses = sweep.poses;
  for (std::size_t k = 0; k < poses.size(); ++k) {
    const SweepPose<S>& a = poses[k];
    if (!a.report.has_pose()) continue;
    const bool next = k + 1 < poses.size() && poses[k + 1].report.has_pose();
    const bool previous = k > 0 && poses[k - 1].report.has_pose();
    if (!next && previous) continue;  // already the end of the previous path
    const SweepPose<S>& b = next ? poses[k + 1] : a;
    ContactPath<S> path{a.input, b.input, {}};
    const S h = b.input - a.input;
    const bool rates = a.report.ok() && b.report.ok();  // a singular pose's rates mean nothing
    for (int side = 0; side < 2; ++side) {
      const int v = p.first_variable + side;
      const S u0 = a.q(v), u1 = b.q(v);
      const S m0 = rates ? S(h * a.qdot(v)) : S(u1 - u0), m1 = rates ? S(h * b.qdot(v)) : S(u1 - u0);
      path.coeff[static_cast<std::size_t>(side)] = hermite(u0, u1, m0, m1);
    }
    paths.push_back(path);
  }
  return paths;
}

template <class S> S curvature_at(const Contour<S>& c, const S& u) { return contour_point(c.jet(u, 2), 2).curvature(); }

/// d kappa / du = (d(kappa sigma)/du - kappa d sigma/du) / sigma (profile/jet.hpp: turn_accel, speed_rate).
template <class S> S curvature_slope(const Contour<S>& c, const S& u) {
  const ContourPoint<S> p = contour_point(c.jet(u, 3), 3);
  return (p.turn_accel - p.curvature() * p.speed_rate) / p.speed;
}

/// The touched point of contour c at parameter u, reached at `input`.
template <class S> TouchedPoint<S> touched_point(const Contour<S>& c, const S& u, const S& input) {
  const Jet<S> j = c.jet(u, 2);
  TouchedPoint<S> t;
  t.found = true;
  t.u = u;
  t.point = c.placement().inverse().act(j.p);
  t.kappa = contour_point(j, 2).curvature();
  t.input = input;
  return t;
}

/// What is minimised over the contact paths: -kappa of a side (its sharpest convex point), kappa of a side
/// (its sharpest concave point), or kappa1 + kappa2.
enum class Objective : std::uint8_t { NegKappa0, Kappa0, NegKappa1, Kappa1, Relative };
constexpr int kObjectives = 5;

template <class S> struct Extreme {
  S value = std::numeric_limits<S>::infinity();
  std::size_t path = 0;
  S t = S(0);
};

template <class S> S objective(Objective o, const S& k0, const S& k1) {
  switch (o) {
    case Objective::NegKappa0: return -k0;
    case Objective::Kappa0: return k0;
    case Objective::NegKappa1: return -k1;
    case Objective::Kappa1: return k1;
    case Objective::Relative: return k0 + k1;
  }
  return k0 + k1;
}

/// The root of f in [lo, hi] where f changes sign (TOMS 748 to the scalar's precision).
template <class S, class F> S bracketed_root(const F& f, const S& lo, const S& hi) {
  boost::math::tools::eps_tolerance<S> tol(std::numeric_limits<S>::digits - 3);
  std::uintmax_t iterations = 200;
  const auto bracket = boost::math::tools::toms748_solve(f, lo, hi, tol, iterations);
  return (bracket.first + bracket.second) / S(2);
}

/// The undercut's end on contour c starting from u0 (where 1 + r kappa < 0) in direction dir (+1 or -1): the
/// first zero of 1 + r kappa, walked in steps of the domain's length / steps and then bracketed (TOMS 748).
template <class S> std::optional<S> undercut_end(const Contour<S>& c, const S& r, const S& u0, int dir, int steps) {
  const Domain<S> d = c.domain();
  const S h = (d.hi - d.lo) / S(steps) * S(dir);
  auto margin = [&](const S& u) { return S(S(1) + r * curvature_at(c, u)); };
  S a = u0;
  for (int k = 0; k < steps; ++k) {
    S b = a + h;
    const bool at_end = !d.closed && (b <= d.lo || b >= d.hi);
    if (at_end) b = dir > 0 ? d.hi : d.lo;
    if (margin(b) >= S(0)) return bracketed_root(margin, dir > 0 ? a : b, dir > 0 ? b : a);
    if (at_end) return std::nullopt;  // the region reaches the contour's end
    a = b;
  }
  return std::nullopt;  // a closed contour undercut all round
}

template <class S> ContourCurvatureCheck<S> contour_check(const Contour<S>& c, int index) {
  ContourCurvatureCheck<S> out;
  out.contour = index;
  if (const auto* circle = std::get_if<Circle<S>>(&c.shape())) {
    out.circle = true;
    out.radius = circle->radius();
  }
  return out;
}

/// The exact sign test at a contact: contour jets (circles exactly, geometry::circle_derivatives).
template <class S> Conformity conformity_at(const std::array<const Contour<S>*, 2>& c,
                                            const std::array<ContourCurvatureCheck<S>, 2>& info,
                                            const std::array<TouchedPoint<S>, 2>& at, double band) {
  std::array<std::array<Vec2<double>, 2>, 2> d;
  for (std::size_t s = 0; s < 2; ++s) {
    if (info[s].circle) {
      d[s] = geometry::circle_derivatives(to_double(info[s].radius), at[s].kappa > S(0));
    } else {
      const Jet<S> j = c[s]->jet(at[s].u, 2);
      d[s] = {Vec2<double>(to_double(j.d1.x()), to_double(j.d1.y())), Vec2<double>(to_double(j.d2.x()), to_double(j.d2.y()))};
    }
  }
  const int sign = geometry::relative_curvature_sign(d[0][0], d[0][1], d[1][0], d[1][1], band);
  return sign > 0 ? Conformity::Conforming : (sign == 0 ? Conformity::Osculating : Conformity::Interpenetrating);
}

/// The extremes of every objective over the contact paths of a pair with contours c, sampled at t = j / steps.
template <class S> std::array<Extreme<S>, kObjectives> scan_extremes(const std::array<const Contour<S>*, 2>& c,
                                                                     const std::vector<ContactPath<S>>& paths, int steps) {
  std::array<Extreme<S>, kObjectives> best;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const bool moving = paths[i].in1 != paths[i].in0;
    for (int j = 0; j <= (moving ? steps : 0); ++j) {
      const S t = S(j) / S(steps);
      const S k0 = curvature_at(*c[0], paths[i].param(0, t)), k1 = curvature_at(*c[1], paths[i].param(1, t));
      for (int o = 0; o < kObjectives; ++o) {
        const S v = objective(static_cast<Objective>(o), k0, k1);
        if (v < best[static_cast<std::size_t>(o)].value) best[static_cast<std::size_t>(o)] = {v, i, t};
      }
    }
  }
  return best;
}

/// Refines the extreme e of objective o on its path within a sample step on either side: the zero of the
/// objective's slope where the slope changes sign there (to full precision), else Brent's minimisation (half
/// the digits). The objective is linear in the curvatures, so its slope is the objective of their slopes.
template <class S> void refine_extreme(const std::array<const Contour<S>*, 2>& c, const std::vector<ContactPath<S>>& paths,
                                       int steps, Objective o, Extreme<S>& e) {
  using std::max;
  using std::min;
  const ContactPath<S>& path = paths[e.path];
  if (path.in1 == path.in0) return;
  const S lo = max(S(0), S(e.t - S(1) / S(steps))), hi = min(S(1), S(e.t + S(1) / S(steps)));
  const auto f = [&](const S& t) {
    return objective(o, curvature_at(*c[0], path.param(0, t)), curvature_at(*c[1], path.param(1, t)));
  };
  const auto slope = [&](const S& t) {
    return objective(o, S(curvature_slope(*c[0], path.param(0, t)) * path.rate(0, t)),
                     S(curvature_slope(*c[1], path.param(1, t)) * path.rate(1, t)));
  };
  const S t = slope(lo) < S(0) && slope(hi) > S(0)
                  ? bracketed_root(slope, lo, hi)
                  : S(boost::math::tools::brent_find_minima(f, lo, hi, std::numeric_limits<S>::digits / 2).first);
  const S v = f(t);
  if (v < e.value) e = {v, e.path, t};
}

/// The roller of a pair: the side whose contour is a circle convex at the contact (the smaller when both are).
template <class S> int roller_side(const PairDesignCheck<S>& d) {
  int roller = -1;
  for (int side = 0; side < 2; ++side) {
    const ContourCurvatureCheck<S>& info = d.contours[static_cast<std::size_t>(side)];
    if (!info.circle || !(d.worst[static_cast<std::size_t>(side)].kappa > S(0))) continue;
    if (roller < 0 || info.radius < d.contours[static_cast<std::size_t>(roller)].radius) roller = side;
  }
  return roller;
}

/// The check of contact pair k over the sweep (see the top of this file).
template <class S> PairDesignCheck<S> check_pair(const Mechanism<S>& m, int k, const SweepResult<S>& sweep,
                                                 const DesignCheckOptions& opt) {
  const Pair<S>& p = m.pairs[static_cast<std::size_t>(k)];
  const std::array<const Contour<S>*, 2> c{&m.contours[static_cast<std::size_t>(p.contour_a)],
                                           &m.contours[static_cast<std::size_t>(p.contour_b)]};
  PairDesignCheck<S> out;
  out.pair = k;
  out.contours = {contour_check(*c[0], p.contour_a), contour_check(*c[1], p.contour_b)};
  const std::vector<ContactPath<S>> paths = contact_paths(p, sweep);
  if (paths.empty()) return out;
  out.touched = true;

  const int steps = opt.samples_per_step < 1 ? 1 : opt.samples_per_step;
  std::array<Extreme<S>, kObjectives> best = scan_extremes(c, paths, steps);
  for (int o = 0; o < kObjectives; ++o) refine_extreme(c, paths, steps, static_cast<Objective>(o), best[static_cast<std::size_t>(o)]);
  auto point = [&](int side, Objective o) {
    const Extreme<S>& e = best[static_cast<std::size_t>(o)];
    return touched_point(*c[static_cast<std::size_t>(side)], paths[e.path].param(side, e.t), paths[e.path].input(e.t));
  };
  for (int side = 0; side < 2; ++side) {
    const Objective convex = side == 0 ? Objective::NegKappa0 : Objective::NegKappa1;
    const Objective concave = side == 0 ? Objective::Kappa0 : Objective::Kappa1;
    ContourCurvatureCheck<S>& info = out.contours[static_cast<std::size_t>(side)];
    if (best[static_cast<std::size_t>(convex)].value < S(0)) info.sharpest_convex = point(side, convex);
    if (best[static_cast<std::size_t>(concave)].value < S(0)) info.sharpest_concave = point(side, concave);
  }
  out.worst = {point(0, Objective::Relative), point(1, Objective::Relative)};
  out.worst_relative = out.worst[0].kappa + out.worst[1].kappa;
  out.conformity = conformity_at(c, out.contours, out.worst, opt.osculation_band);
  out.roller = roller_side(out);
  if (out.roller < 0 || out.conformity != Conformity::Interpenetrating) return out;
  // The undercut region of the roller on the other contour: its ends on either side of the worst point.
  const std::size_t other = out.roller == 0 ? 1 : 0;
  const S r = out.contours[static_cast<std::size_t>(out.roller)].radius;
  for (int dir = -1; dir <= 1; dir += 2) {
    const std::optional<S> u = undercut_end(*c[other], r, out.worst[other].u, dir, opt.cusp_search_steps);
    if (!u) continue;
    TouchedPoint<S>& cusp = out.cusps[dir < 0 ? 0 : 1];
    cusp = touched_point(*c[other], *u, S(0));
    cusp.input = std::numeric_limits<S>::quiet_NaN();  // a point of the contour, not necessarily touched
  }
  return out;
}

}  // namespace detail

/// The design check of every cam and rolling pair over a solved sweep of m (see the top of this file).
template <class S> DesignCheck<S> check_design(const Mechanism<S>& m, const SweepResult<S>& sweep,
                                               const DesignCheckOptions& opt = {}) {
  DesignCheck<S> out;
  for (std::size_t k = 0; k < m.pairs.size(); ++k)
    if (is_contact(m.pairs[k].kind)) out.pairs.push_back(detail::check_pair(m, static_cast<int>(k), sweep, opt));
  return out;
}

// The design check for one scalar S, after KEYWORD (`extern template` or `template`; ROLLKIN_POSITION_INSTANCES
// in solve/position.hpp, docs/benchmark.md, "Build times").
#define ROLLKIN_DESIGN_CHECK_INSTANCES(KEYWORD, S) \
  KEYWORD DesignCheck<S> check_design(const Mechanism<S>&, const SweepResult<S>&, const DesignCheckOptions&);

// Compiled once for double, in src/analysis/instantiate_double.cpp.
ROLLKIN_DESIGN_CHECK_INSTANCES(extern template, double)

}  // namespace rollkin
