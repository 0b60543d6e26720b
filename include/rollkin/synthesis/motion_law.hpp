// A follower's motion law over one turn of the cam: the follower displacement s (a length, or an angle for an
// oscillating follower) as a function of the cam angle theta, with its first three derivatives
// (docs/synthesis.md, "Motion laws").
//
// A law is a list of segments covering [0, 2 pi). Segment k runs from theta_k to theta_{k+1}, its duration
// is beta = theta_{k+1} - theta_k and its lift h (the change of s over the segment; negative for a return).
// With x = (theta - theta_k) / beta in [0, 1] and y(x) one of the normalised rise curves (y(0) = 0, y(1) = 1):
//   s = s_k + h y(x),   s' = h y'(x) / beta,   s'' = h y''(x) / beta^2,   s''' = h y'''(x) / beta^3.
// Normalised rises (Norton, "Cam Design and Manufacturing Handbook", ch. 3):
//   dwell           y = 0 (h = 0)
//   cycloidal       y = x - sin(2 pi x) / (2 pi)                          peak y' = 2,      peak y'' = 2 pi
//   harmonic        y = (1 - cos(pi x)) / 2                               peak y' = pi / 2, peak y'' = pi^2 / 2
//   poly345         y = 10 x^3 - 15 x^4 + 6 x^5                           peak y' = 1.875,  peak y'' = 5.7735
//   poly4567        y = 35 x^4 - 84 x^5 + 70 x^6 - 20 x^7                 peak y' = 2.1875, peak y'' = 7.5132
//   modified trapezoid and modified sine: y'' is made of pieces c0 + c1 sin(w t + phase) (t from the piece's
//   start), integrated in closed form piece by piece and scaled so that y(1) = 1:
//     modified trapezoid  y'' = C [sin(4 pi x) on [0, 1/8], 1 on [1/8, 3/8], cos(4 pi t) on [3/8, 5/8],
//                                  -1 on [5/8, 7/8], -cos(4 pi t) on [7/8, 1]]     peak y' = 2, y'' = 4.888
//     modified sine       y'' = C [sin(4 pi x) on [0, 1/8], cos(4 pi t / 3) on [1/8, 7/8],
//                                  -cos(4 pi t) on [7/8, 1]]                      peak y' = 1.76, y'' = 5.528
// A law may also be given as a function of theta (MotionLaw::from_function), e.g. in closed form.
// A table of points (theta_i, s_i) over one turn, starting anywhere, is the periodic C4 quintic spline through
// them (synthesis/periodic_spline.hpp).
//
// Continuity (check_continuity): at every join (and at 2 pi = 0) the one-sided values of s, s' and s'' are
// compared; a jump in s is no motion at all, in s' an infinite acceleration, in s'' an infinite jerk.
#pragma once

#include "rollkin/scalar.hpp"
#include "rollkin/synthesis/periodic_spline.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rollkin::synthesis {

/// s and its first three derivatives with respect to the cam angle.
template <class S> struct LawValue {
  S s, v, a, j;
};

enum class RiseKind { Dwell, Cycloidal, Harmonic, ModifiedTrapezoid, ModifiedSine, Poly345, Poly4567 };

/// The spelling of each kind in a spec ("kind": ...) and messages.
inline const std::array<std::pair<RiseKind, const char*>, 7>& rise_kind_names() {
  static const std::array<std::pair<RiseKind, const char*>, 7> names{{{RiseKind::Dwell, "dwell"},
                                                                       {RiseKind::Cycloidal, "cycloidal"},
                                                                       {RiseKind::Harmonic, "harmonic"},
                                                                       {RiseKind::ModifiedTrapezoid, "modified_trapezoid"},
                                                                       {RiseKind::ModifiedSine, "modified_sine"},
                                                                       {RiseKind::Poly345, "poly345"},
                                                                       {RiseKind::Poly4567, "poly4567"}}};
  return names;
}

namespace detail {

/// One piece of a piecewise-sinusoidal acceleration: y'' = c0 + c1 sin(w t + phase), t = x - x0.
template <class S> struct AccelPiece {
  S x0, c0, c1, w, phase;
  S y0 = S(0), v0 = S(0);  // y and y' at x0 (filled by integrate)
};

/// Closed-form integrals of one piece at t: {y, y', y'', y'''}.
template <class S> std::array<S, 4> piece_value(const AccelPiece<S>& p, const S& t) {
  using std::cos;
  using std::sin;
  const S arg = p.w * t + p.phase;
  const S acc = p.c0 + p.c1 * sin(arg);
  const S vel = p.v0 + p.c0 * t - p.c1 / p.w * (cos(arg) - cos(p.phase));
  const S pos = p.y0 + p.v0 * t + p.c0 * t * t / S(2) -
                p.c1 / p.w * ((sin(arg) - sin(p.phase)) / p.w - t * cos(p.phase));
  return {pos, vel, acc, p.c1 * p.w * cos(arg)};
}

/// Sets each piece's starting y and y' by integrating the pieces before it from y(0) = y'(0) = 0, then scales
/// the accelerations so that y(1) = 1.
template <class S> std::vector<AccelPiece<S>> normalised(std::vector<AccelPiece<S>> pieces) {
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t k = 1; k < pieces.size(); ++k) {
      const auto end = piece_value(pieces[k - 1], S(pieces[k].x0 - pieces[k - 1].x0));
      pieces[k].y0 = end[0];
      pieces[k].v0 = end[1];
    }
    if (pass == 1) break;
    const auto last = piece_value(pieces.back(), S(S(1) - pieces.back().x0));
    for (auto& p : pieces) {
      p.c0 /= last[0];
      p.c1 /= last[0];
    }
  }
  return pieces;
}

template <class S> const std::vector<AccelPiece<S>>& modified_trapezoid_pieces() {
  static const std::vector<AccelPiece<S>> pieces = [] {
    const S w = S(4) * pi<S>(), half = pi<S>() / S(2);
    return normalised<S>({{S(0), S(0), S(1), w, S(0)},
                          {S(1) / S(8), S(1), S(0), w, S(0)},
                          {S(3) / S(8), S(0), S(1), w, half},
                          {S(5) / S(8), S(-1), S(0), w, S(0)},
                          {S(7) / S(8), S(0), S(1), w, -half}});
  }();
  return pieces;
}

template <class S> const std::vector<AccelPiece<S>>& modified_sine_pieces() {
  static const std::vector<AccelPiece<S>> pieces = [] {
    const S w = S(4) * pi<S>(), half = pi<S>() / S(2);
    return normalised<S>({{S(0), S(0), S(1), w, S(0)},
                          {S(1) / S(8), S(0), S(1), w / S(3), half},
                          {S(7) / S(8), S(0), S(1), w, -half}});
  }();
  return pieces;
}

template <class S> std::array<S, 4> piecewise_rise(const std::vector<AccelPiece<S>>& pieces, const S& x) {
  std::size_t k = pieces.size() - 1;
  while (k > 0 && x < pieces[k].x0) --k;
  return piece_value(pieces[k], S(x - pieces[k].x0));
}

}  // namespace detail

/// The normalised rise y(x) and its derivatives y', y'', y''' at x in [0, 1] (file comment).
template <class S> std::array<S, 4> normalised_rise(RiseKind kind, const S& x) {
  using std::cos;
  using std::sin;
  const S tau = S(2) * pi<S>(), p = pi<S>();
  switch (kind) {
    case RiseKind::Dwell: return {S(0), S(0), S(0), S(0)};
    case RiseKind::Cycloidal:
      return {S(x - sin(tau * x) / tau), S(S(1) - cos(tau * x)), S(tau * sin(tau * x)), S(tau * tau * cos(tau * x))};
    case RiseKind::Harmonic:
      return {S((S(1) - cos(p * x)) / S(2)), S(p / S(2) * sin(p * x)), S(p * p / S(2) * cos(p * x)),
              S(-p * p * p / S(2) * sin(p * x))};
    case RiseKind::Poly345: {
      const S x2 = x * x;
      return {S(x2 * x * (S(10) - S(15) * x + S(6) * x2)), S(x2 * (S(30) - S(60) * x + S(30) * x2)),
              S(x * (S(60) - S(180) * x + S(120) * x2)), S(S(60) - S(360) * x + S(360) * x2)};
    }
    case RiseKind::Poly4567: {
      const S x2 = x * x, x3 = x2 * x;
      return {S(x2 * x2 * (S(35) - S(84) * x + S(70) * x2 - S(20) * x3)),
              S(x3 * (S(140) - S(420) * x + S(420) * x2 - S(140) * x3)),
              S(x2 * (S(420) - S(1680) * x + S(2100) * x2 - S(840) * x3)),
              S(x * (S(840) - S(5040) * x + S(8400) * x2 - S(4200) * x3))};
    }
    case RiseKind::ModifiedTrapezoid: return detail::piecewise_rise(detail::modified_trapezoid_pieces<S>(), x);
    case RiseKind::ModifiedSine: return detail::piecewise_rise(detail::modified_sine_pieces<S>(), x);
  }
  throw std::logic_error("normalised_rise: unknown kind");
}

/// One segment of a law: from `start` to `end` (cam angle, radians), lift h.
template <class S> struct LawSegment {
  S start, end, lift;
  RiseKind kind;
};

/// A jump at a join of the law: where, in which derivative (0 = s, 1 = s', 2 = s''), and by how much.
template <class S> struct LawJump {
  S theta;
  int order;
  S left, right;
};

/// The motion law over one turn: segments, or a periodic C2 spline through a table of points.
template <class S> class MotionLaw {
 public:
  /// Segments in order, the first starting at 0 and each at the end of the one before, the last ending at
  /// 2 pi, with a net lift of zero (the follower comes back). Throws std::invalid_argument naming the segment.
  static MotionLaw from_segments(std::vector<LawSegment<S>> segments) {
    using std::abs;
    if (segments.empty()) throw std::invalid_argument("the law has no segments");
    const S two_pi = S(2) * pi<S>(), round_off = S(64) * epsilon<S>() * two_pi;
    MotionLaw law;
    S s = S(0), lift_scale = S(0);
    for (std::size_t k = 0; k < segments.size(); ++k) {
      const LawSegment<S>& g = segments[k];
      const S expected_start = k == 0 ? S(0) : segments[k - 1].end;
      if (abs(g.start - expected_start) > round_off)
        throw std::invalid_argument("segment " + std::to_string(k) + " does not start where the one before ends");
      if (!(g.end > g.start))
        throw std::invalid_argument("segment " + std::to_string(k) + " ends before it starts (its \"to\" must increase)");
      if (g.kind == RiseKind::Dwell && g.lift != S(0))
        throw std::invalid_argument("segment " + std::to_string(k) + " is a dwell with a lift; a dwell has none");
      if (g.kind != RiseKind::Dwell && g.lift == S(0))
        throw std::invalid_argument("segment " + std::to_string(k) + " has no lift; use \"kind\": \"dwell\"");
      law.start_s_.push_back(s);
      s += g.lift;
      lift_scale = std::max(lift_scale, S(abs(s)));
    }
    if (abs(segments.back().end - two_pi) > round_off)
      throw std::invalid_argument("the law ends at " + std::to_string(static_cast<double>(segments.back().end)) +
                                  " rad, not after one turn (2 pi)");
    if (abs(s) > S(64) * epsilon<S>() * lift_scale)
      throw std::invalid_argument("the lifts add up to " + std::to_string(static_cast<double>(s)) +
                                  ", not 0: the follower would not come back after one turn");
    segments.back().end = two_pi;
    for (const auto& g : segments) law.ends_.push_back(g.end);
    law.segments_ = std::move(segments);
    return law;
  }

  /// The periodic spline through (theta_i, s_i), theta_i increasing over less than one turn from any start
  /// theta_0 (the law repeats every turn wherever its table starts); a last point at theta_0 + 2 pi must
  /// repeat the first value and is dropped.
  static MotionLaw from_table(std::vector<S> theta, std::vector<S> s) {
    using std::abs;
    const S two_pi = S(2) * pi<S>();
    if (theta.size() != s.size()) throw std::invalid_argument("table: as many angles as displacements needed");
    // Round-off of the angles' size (a table may start anywhere, e.g. at 720 degrees).
    const S round_off = S(64) * epsilon<S>() * (two_pi + (theta.empty() ? S(0) : S(abs(theta.front()))));
    if (theta.size() >= 2 && abs(theta.back() - (theta.front() + two_pi)) <= round_off) {
      if (abs(s.back() - s.front()) > S(1e-12) * (S(1) + abs(s.front())))
        throw std::invalid_argument("table: the point one turn after the first (" + std::to_string(static_cast<double>(s.back())) +
                                    ") does not repeat the first (" + std::to_string(static_cast<double>(s.front())) + ")");
      theta.pop_back();
      s.pop_back();
    }
    if (theta.size() < 4) throw std::invalid_argument("table: at least 4 points over the turn needed");
    for (std::size_t k = 1; k < theta.size(); ++k)
      if (!(theta[k] > theta[k - 1]))
        throw std::invalid_argument("table: the angles must increase (row " + std::to_string(k + 1) + ")");
    if (!(theta.back() < theta.front() + two_pi))
      throw std::invalid_argument("table: the angles span more than one turn");
    MotionLaw law;
    law.table_ = PeriodicSpline<S>(std::move(theta), std::move(s));
    return law;
  }

  /// A law given by a function of theta (returning s and its three derivatives), 2 pi-periodic; for a law in
  /// closed form that is neither a list of segments nor a table (library use and tests).
  static MotionLaw from_function(std::function<LawValue<S>(const S&)> f) {
    MotionLaw law;
    law.function_ = std::move(f);
    return law;
  }

  bool is_table() const { return !table_.empty(); }
  const std::vector<LawSegment<S>>& segments() const { return segments_; }

  /// s, s', s'', s''' at cam angle theta (any real: the law repeats every turn).
  LawValue<S> operator()(const S& theta) const { return is_table() ? table_value(theta, false) : evaluate(wrap_to_turn(theta), false); }

  /// The one-sided value just before theta (the previous segment's or span's end) at a join.
  LawValue<S> left_of(const S& theta) const { return is_table() ? table_value(theta, true) : evaluate(wrap_to_turn(theta), true); }

  /// Largest |s - s(0)|: the stroke.
  S stroke(int samples = 3600) const {
    using std::abs;
    S lo = (*this)(S(0)).s, hi = lo;
    for (int k = 1; k < samples; ++k) {
      const S v = (*this)(S(2) * pi<S>() * S(k) / S(samples)).s;
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    return hi - lo;
  }

  /// The joins where s, s' or s'' jump (by more than round-off of the law's size): the lowest order per join.
  std::vector<LawJump<S>> check_continuity() const {
    using std::abs;
    std::vector<LawJump<S>> jumps;
    const S scale = std::max(stroke(360), S(1));
    for (const S& theta : joins()) {
      const LawValue<S> l = left_of(theta), r = (*this)(theta);
      const std::array<S, 3> left{l.s, l.v, l.a}, right{r.s, r.v, r.a};
      for (int order = 0; order < 3; ++order) {
        if (abs(left[order] - right[order]) > tolerance<S>(S(3) / S(4)) * scale) {
          jumps.push_back({theta, order, left[order], right[order]});
          break;
        }
      }
    }
    return jumps;
  }

  /// Segment starts (or table points): where the law's pieces meet, in [0, 2 pi).
  std::vector<S> joins() const {
    std::vector<S> out;
    if (is_table()) return table_.knots();
    for (const auto& g : segments_) out.push_back(g.start);
    return out;
  }

 private:
  /// A table's spline at theta (any real: periodic_spline.hpp takes it to the table's turn).
  LawValue<S> table_value(const S& theta, bool left) const {
    const std::array<S, 4> v = table_(theta, left);
    return {v[0], v[1], v[2], v[3]};
  }

  /// theta in [0, 2 pi); `left`: at a join take the piece that ends there (theta = 0 is the turn's end).
  LawValue<S> evaluate(const S& theta, bool left) const {
    if (function_) return function_(left && theta == S(0) ? S(S(2) * pi<S>()) : theta);
    // The segment that holds theta (left: the one ending there), by binary search over the ends: O(log n).
    const auto end = left ? std::lower_bound(ends_.begin(), ends_.end(), theta) : std::upper_bound(ends_.begin(), ends_.end(), theta);
    std::size_t k = std::min(static_cast<std::size_t>(end - ends_.begin()), segments_.size() - 1);
    S t = theta;
    if (left && theta == S(0)) {
      k = segments_.size() - 1;
      t = S(2) * pi<S>();
    }
    const LawSegment<S>& g = segments_[k];
    const S beta = g.end - g.start;
    const auto y = normalised_rise(g.kind, S((t - g.start) / beta));
    return {start_s_[k] + g.lift * y[0], g.lift * y[1] / beta, g.lift * y[2] / (beta * beta),
            g.lift * y[3] / (beta * beta * beta)};
  }

  std::vector<LawSegment<S>> segments_;
  std::vector<S> start_s_, ends_;  // each segment's s at its start and its end angle (sorted: binary search)
  PeriodicSpline<S> table_;  // a table's spline (periodic_spline.hpp)
  std::function<LawValue<S>(const S&)> function_;
};

/// The kind named `name` (rise_kind_names), or throws std::invalid_argument listing the names.
inline RiseKind rise_kind(const std::string& name) {
  std::string names;
  for (const auto& [kind, spelling] : rise_kind_names()) {
    if (name == spelling) return kind;
    names += (names.empty() ? "\"" : ", \"") + std::string(spelling) + "\"";
  }
  throw std::invalid_argument("unknown kind \"" + name + "\"; expected one of " + names);
}

}  // namespace rollkin::synthesis
