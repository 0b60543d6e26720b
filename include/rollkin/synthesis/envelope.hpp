// The envelope (conjugate contour) on link A of a contour on link B under the motion of B relative to A
// (docs/synthesis.md, "The envelope"; Litvin & Fuentes, "Gear Geometry and Applied Theory", ch. 6).
//
// B's contour p(u) (B's frame) and B's pose in A at the motion parameter t: rotation R(phi(t)), origin d(t).
// A point of B's contour sits in A at
//   x(u, t) = R(phi) p(u) + d.
// The envelope is the set of points where the contour touches its neighbours in the family: the relative
// velocity of the contact point is tangent to the contour (the equation of meshing, n . v_rel = 0). In B's
// frame, with J the rotation by +90 degrees and w = R^T d',
//   v_rel = R^T dx/dt = phi' J p + w,      n = J p',
//   f(u, t) = (J p') . (phi' J p + w) = phi' p' . p + (J p') . w = 0.                          (meshing)
// At each t the contact parameter u(t) is the root of f(., t) found by Newton's method inside a bracket (a
// sign change of f searched outward from the previous contact), with
//   f_u = phi' (p'' . p + |p'|^2) + (J p'') . w,
//   f_t = phi'' p' . p + (J p') . w_t,    w_t = R^T d'' - phi' J w.
// The envelope point is X(t) = x(u(t), t); it moves along the contour's tangent T = R p'/|p'| with speed
//   sigma = dX/dt . T = |p'| u' + p' . (phi' J p + w) / |p'|,     u' = -f_t / f_u.                (speed)
// Where sigma changes sign the envelope folds back on itself (a cusp; for a cam, the profile is undercut);
// where f_u = 0 the contact is not a simple root and the envelope does not exist as a smooth curve there
// (the family's members osculate). Both are reported, located by bisection on t to 1e-9 of the t range.
//
// Sampling: the envelope is sampled at poses t_k (an even grid refined by halving), fitted by the chord-length
// C2 spline a `samples` contour uses (profile/spline.hpp), and each interval is checked at its mid-pose: the
// distance from X(t_mid) to the spline (found by Newton on the spline's parameter) must not exceed the
// tolerance, or the mid-pose is added and the fit checked again. The refined samples are checked for folds
// once more (a fold narrower than the first grid's step shows only between them).
#pragma once

#include "rollkin/profile/jet.hpp"
#include "rollkin/profile/spline.hpp"
#include "rollkin/scalar.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace rollkin::synthesis {

/// B's pose in A at the motion parameter t with its first two derivatives: angle phi, origin d.
template <class S> struct MotionJet {
  S phi, dphi, ddphi;
  Vec2<S> d, dd, ddd;
};

/// The pose of a follower that moves in the world (angle psi, origin v) seen from a cam that turns by alpha
/// about the world origin, each with two derivatives: angle psi - alpha, origin R(-alpha) v, and
///   origin'  = R(-alpha) (v' - alpha' J v),
///   origin'' = R(-alpha) (v'' - alpha'' J v - 2 alpha' J v' - alpha'^2 v).
template <class S>
MotionJet<S> relative_to_turning_frame(const S& alpha, const S& dalpha, const S& ddalpha, const S& psi, const S& dpsi,
                                       const S& ddpsi, const Vec2<S>& v, const Vec2<S>& dv, const Vec2<S>& ddv) {
  using std::cos;
  using std::sin;
  const S c = cos(alpha), s = sin(alpha);
  auto back = [&](const Vec2<S>& x) { return Vec2<S>(c * x.x() + s * x.y(), -s * x.x() + c * x.y()); };
  auto perp = [](const Vec2<S>& x) { return Vec2<S>(-x.y(), x.x()); };
  MotionJet<S> m;
  m.phi = psi - alpha;
  m.dphi = dpsi - dalpha;
  m.ddphi = ddpsi - ddalpha;
  m.d = back(v);
  m.dd = back(Vec2<S>(dv - dalpha * perp(v)));
  m.ddd = back(Vec2<S>(ddv - ddalpha * perp(v) - S(2) * dalpha * perp(dv) - dalpha * dalpha * v));
  return m;
}

/// What the engine needs: B's contour (p, p', p'' in B's frame), B's motion in A, the range of t and where
/// to start looking for the contact.
template <class S> struct EnvelopeProblem {
  std::function<Jet<S>(const S&)> contour;       // u -> p, p', p'' (Jet::d1, d2)
  std::function<MotionJet<S>(const S&)> motion;  // t -> pose of B in A and its derivatives
  S t_begin, t_end;
  bool periodic = false;        // the motion repeats after t_end - t_begin: the envelope is closed
  S u_guess;                    // contact parameter near which the contact at t_begin lies
  S u_scale = S(1);             // typical size of the contour's parameter range (first bracket step / 1000)
  std::optional<S> u_lo, u_hi;  // the contour's parameter domain (none: unbounded or periodic)
};

/// A place where the envelope folds (sigma changes sign) or does not exist (f_u = 0 or no contact found).
template <class S> struct EnvelopeDefect {
  S t;            // located to 1e-9 of the t range
  Vec2<S> point;  // envelope point there (A's frame); NaN where no contact was found
  std::string what;
};

template <class S> struct EnvelopeSample {
  S t, u;         // pose and contact parameter on B's contour
  Vec2<S> point;  // envelope point in A's frame
  S speed;        // sigma (see the file comment)
};

template <class S> struct Envelope {
  std::vector<EnvelopeSample<S>> samples;  // in increasing t (a periodic envelope does not repeat t_begin)
  std::vector<EnvelopeDefect<S>> defects;  // folds and gaps, in increasing t
  S max_midpoint_deviation = S(0);         // largest mid-pose distance to the fitted spline (the last check)
  bool closed = false;

  std::vector<Vec2<S>> points() const {
    std::vector<Vec2<S>> out;
    for (const auto& s : samples) out.push_back(s.point);
    return out;
  }
};

/// The meshing function and its partial derivatives at (u, t).
template <class S> struct Meshing {
  S f, f_u, f_t, speed;
  Vec2<S> point;
};

template <class S> Meshing<S> meshing(const EnvelopeProblem<S>& pr, const S& u, const MotionJet<S>& m) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const Jet<S> j = pr.contour(u);
  const S c = cos(m.phi), s = sin(m.phi);
  auto back = [&](const Vec2<S>& x) { return Vec2<S>(c * x.x() + s * x.y(), -s * x.x() + c * x.y()); };
  auto perp = [](const Vec2<S>& x) { return Vec2<S>(-x.y(), x.x()); };
  const Vec2<S> w = back(m.dd);
  const Vec2<S> w_t = back(m.ddd) - m.dphi * perp(w);
  Meshing<S> r;
  r.f = m.dphi * j.d1.dot(j.p) + perp(j.d1).dot(w);
  r.f_u = m.dphi * (j.d2.dot(j.p) + j.d1.dot(j.d1)) + perp(j.d2).dot(w);
  r.f_t = m.ddphi * j.d1.dot(j.p) + perp(j.d1).dot(w_t);
  const S len = sqrt(j.d1.dot(j.d1));
  const Vec2<S> v_rel = m.dphi * perp(j.p) + w;
  const S du = -r.f_t / r.f_u;
  r.speed = len * du + j.d1.dot(v_rel) / len;
  r.point = Vec2<S>(c * j.p.x() - s * j.p.y(), s * j.p.x() + c * j.p.y()) + m.d;
  return r;
}

namespace detail {
/// A number for a message, three significant digits ("1e-12", "3.2e-09"): std::to_string printed 0.000000.
inline std::string short_number(double v) {
  std::ostringstream s;
  s << std::setprecision(3) << v;
  return s.str();
}
}  // namespace detail

namespace detail {

/// The root of f(., t) nearest `from`: a sign change bracketed by steps that double outward on both sides
/// (within the domain), then Newton's method kept inside the bracket (bisection when a step leaves it).
/// nullopt when no sign change is found within the domain or 60 doublings.
template <class S>
std::optional<S> contact_parameter(const EnvelopeProblem<S>& pr, const MotionJet<S>& m, const S& from) {
  using std::abs;
  auto f = [&](const S& u) { return meshing(pr, u, m).f; };
  auto inside = [&](const S& u) { return (!pr.u_lo || u >= *pr.u_lo) && (!pr.u_hi || u <= *pr.u_hi); };
  const S f0 = f(from);
  if (f0 == S(0)) return from;
  S lo = from, hi = from, flo = f0, fhi = f0;
  bool found = false;
  S step = pr.u_scale / S(1000);
  for (int k = 0; k < 60 && !found; ++k, step *= S(2)) {
    for (int side : {1, -1}) {
      S a = from + S(side) * step;
      if (!inside(a)) a = side > 0 ? *pr.u_hi : *pr.u_lo;
      const S fa = f(a);
      const S prev = side > 0 ? hi : lo, fprev = side > 0 ? fhi : flo;
      if ((fa < S(0)) != (fprev < S(0)) || fa == S(0)) {
        lo = side > 0 ? prev : a;
        hi = side > 0 ? a : prev;
        flo = side > 0 ? fprev : fa;
        fhi = side > 0 ? fa : fprev;
        found = true;
        break;
      }
      if (side > 0) { hi = a; fhi = fa; } else { lo = a; flo = fa; }
    }
    if (!inside(from + step) && !inside(from - step)) break;
  }
  if (!found) return std::nullopt;
  if (flo == S(0)) return lo;
  if (fhi == S(0)) return hi;
  S u = (lo + hi) / S(2);
  for (int it = 0; it < 200; ++it) {
    const Meshing<S> r = meshing(pr, u, m);
    if (r.f == S(0)) return u;
    if ((r.f < S(0)) == (flo < S(0))) lo = u; else hi = u;
    S next = u - r.f / r.f_u;
    if (!(next > lo && next < hi)) next = (lo + hi) / S(2);
    const S change = abs(next - u);
    u = next;
    if (change <= S(4) * epsilon<S>() * (abs(u) + pr.u_scale)) break;
  }
  return u;
}

}  // namespace detail

/// The contact and envelope point at pose t, starting the search at u_from; nullopt where there is none.
template <class S>
std::optional<EnvelopeSample<S>> envelope_point(const EnvelopeProblem<S>& pr, const S& t, const S& u_from) {
  const MotionJet<S> m = pr.motion(t);
  const std::optional<S> u = detail::contact_parameter(pr, m, u_from);
  if (!u) return std::nullopt;
  const Meshing<S> r = meshing(pr, *u, m);
  return EnvelopeSample<S>{t, *u, r.point, r.speed};
}

struct EnvelopeOptions {
  double tolerance;                 // largest mid-pose distance of the fitted spline from the envelope (A's units)
  std::size_t initial_intervals = 64;
  std::size_t max_samples = 200000;
};

namespace detail {

/// Distance from x to the spline near its span [knots[k], knots[k+1]] (Newton on |P(u) - x|^2, kept in the span).
template <class S> S distance_to_span(const SampledProfile<S>& spline, std::size_t k, const Vec2<S>& x) {
  using std::abs;
  const auto& knots = spline.knots();
  const S lo = knots[k], hi = knots[k + 1];
  S u = (lo + hi) / S(2);
  for (int it = 0; it < 20; ++it) {
    const Jet<S> j = spline.jet(u, 2);
    const Vec2<S> r = j.p - x;
    const S g = j.d1.dot(r), dg = j.d2.dot(r) + j.d1.dot(j.d1);
    S next = u - g / dg;
    next = std::min(hi, std::max(lo, next));
    const S change = abs(next - u);
    u = next;
    if (change <= S(8) * epsilon<S>() * (abs(u) + hi - lo)) break;
  }
  return (spline.jet(u, 0).p - x).norm();
}

/// Bisection on t in (a, b) for the zero of a sample's `value`, from the contacts found at a and b.
template <class S, class Value>
EnvelopeSample<S> bisect(const EnvelopeProblem<S>& pr, EnvelopeSample<S> a, EnvelopeSample<S> b, Value value) {
  using std::abs;
  const S resolution = (pr.t_end - pr.t_begin) * S(1e-10);
  const bool a_negative = value(a) < S(0);
  while (abs(b.t - a.t) > resolution) {
    const S mid = (a.t + b.t) / S(2);
    const auto s = envelope_point(pr, mid, a.u);
    if (!s) break;
    if ((value(*s) < S(0)) == a_negative) a = *s; else b = *s;
  }
  return abs(value(a)) <= abs(value(b)) ? a : b;
}

}  // namespace detail

/// The envelope sampled to the tolerance (file comment), with its folds and gaps. Throws std::invalid_argument
/// for an empty t range and std::runtime_error when the tolerance needs more than options.max_samples.
template <class S> Envelope<S> envelope(const EnvelopeProblem<S>& pr, const EnvelopeOptions& options) {
  using std::abs;
  if (!(pr.t_end > pr.t_begin)) throw std::invalid_argument("envelope: the motion's range is empty");
  Envelope<S> env;
  env.closed = pr.periodic;
  const std::size_t n0 = std::max<std::size_t>(options.initial_intervals, 8);
  std::vector<S> ts;
  for (std::size_t k = 0; k <= n0; ++k) {
    if (k == n0 && pr.periodic) break;
    ts.push_back(pr.t_begin + (pr.t_end - pr.t_begin) * S(static_cast<long>(k)) / S(static_cast<long>(n0)));
  }
  auto solve_all = [&](const std::vector<S>& times) {
    std::vector<EnvelopeSample<S>> out;
    std::vector<EnvelopeDefect<S>> gaps;
    S u = pr.u_guess;
    for (const S& t : times) {
      const auto s = envelope_point(pr, t, u);
      if (!s) {
        const S nan = std::numeric_limits<S>::quiet_NaN();
        gaps.push_back({t, Vec2<S>(nan, nan), "no contact: the meshing equation has no root near the last contact"});
        continue;
      }
      u = s->u;
      out.push_back(*s);
    }
    return std::make_pair(out, gaps);
  };
  auto [samples, gaps] = solve_all(ts);
  env.defects = gaps;
  // Folds: sign changes of the envelope's speed between consecutive samples (and across the seam).
  auto find_folds = [&](const std::vector<EnvelopeSample<S>>& list) {
    const std::size_t count = list.size();
    for (std::size_t k = 0; k + 1 < count + (pr.periodic ? 1 : 0) && count > 1; ++k) {
      EnvelopeSample<S> a = list[k], b = list[(k + 1) % count];
      if (k + 1 == count) b.t += pr.t_end - pr.t_begin;
      if ((a.speed < S(0)) != (b.speed < S(0))) {
        const EnvelopeSample<S> at = detail::bisect(pr, a, b, [](const EnvelopeSample<S>& s) { return s.speed; });
        env.defects.push_back({at.t, at.point,
                               std::string("the envelope folds back (cusp): its speed along the contour changes sign") +
                                   (a.speed > S(0) ? " from + to -" : " from - to +")});
      }
    }
    std::sort(env.defects.begin(), env.defects.end(), [](const auto& x, const auto& y) { return x.t < y.t; });
  };
  find_folds(samples);
  const std::size_t n = samples.size();
  if (!env.defects.empty() || n < 4) {
    env.samples = samples;
    return env;
  }
  // Refinement: add the mid-pose of every interval whose mid-point lies farther than the tolerance from the
  // spline through the samples, until none does.
  SplineOptions<S> spline_options;
  spline_options.closed = pr.periodic;
  const S tol = S(options.tolerance);
  for (;;) {
    std::vector<Vec2<S>> pts;
    for (const auto& s : samples) pts.push_back(s.point);
    const SampledProfile<S> spline(pts, spline_options);
    const std::size_t spans = spline.span_count();
    std::vector<EnvelopeSample<S>> refined;
    S worst = S(0);
    for (std::size_t k = 0; k < samples.size(); ++k) {
      refined.push_back(samples[k]);
      if (k >= spans) continue;
      const EnvelopeSample<S>& a = samples[k];
      const S t_next = k + 1 < samples.size() ? samples[k + 1].t : pr.t_end;
      const auto mid = envelope_point(pr, S((a.t + t_next) / S(2)), a.u);
      if (!mid) throw std::runtime_error("envelope: the contact was lost between two samples while refining");
      const S dev = detail::distance_to_span(spline, k, mid->point);
      worst = std::max(worst, dev);
      if (dev > tol) refined.push_back(*mid);
    }
    env.max_midpoint_deviation = worst;
    if (refined.size() == samples.size()) break;
    if (refined.size() > options.max_samples)
      throw std::runtime_error("envelope: more than " + std::to_string(options.max_samples) + " samples needed for the tolerance " +
                               detail::short_number(static_cast<double>(options.tolerance)) + " (the spline through " +
                               std::to_string(samples.size()) + " is " + detail::short_number(static_cast<double>(worst)) +
                               " off at a mid-point)");
    samples = std::move(refined);
  }
  find_folds(samples);  // a fold narrower than the first grid shows between the refined samples
  env.samples = samples;
  return env;
}

}  // namespace rollkin::synthesis
