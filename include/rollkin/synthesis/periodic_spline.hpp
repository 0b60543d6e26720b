// The periodic interpolating spline of a table over one turn: a law table (motion_law.hpp) and a gear
// transmission table (gears.hpp). Quintic, C4: s and its first four derivatives are continuous at every
// knot, so s''' (a follower's jerk; a gear's pitch-curve curvature, which depends on f''') has no jumps.
// A cubic spline's s''' jumps at every knot, and a gear pair's pitch curve built from it had a curvature
// that jumped there: the C2 spline fitted through its samples then missed its tangent by O(h) where the
// positions were within the tolerance, and table gears failed their own round trip (issue 37).
//
// Knots x_0 < ... < x_{n-1} < x_0 + 2 pi anywhere on the real line (a table may start at -90 or at 720
// degrees); the spline repeats every turn wherever it starts: every x is first taken to the turn the knots
// cover, [x_0, x_0 + 2 pi) (docs/reliability.md, "Synthesis (issue 37)"), and its span is found by binary
// search, O(log n).
//
// On span k, h = x_{k+1} - x_k, u = (x - x_k) / h, w = 1 - u, with the knot values s_k, the second
// derivatives m_k and the fourth derivatives q_k (linear on the span: a quintic):
//   s = w s_k + u s_{k+1} - h^2 [m_k phi(w) + m_{k+1} phi(u)] + h^4 [q_k psi(w) + q_{k+1} psi(u)],
//   phi(x) = (x - x^3) / 6,   psi(x) = 7 x / 360 - x^3 / 36 + x^5 / 120   (both zero at 0 and 1),
// so that s'' = w m_k + u m_{k+1} + h^2 [q_k (w^3 - w) + q_{k+1} (u^3 - u)] / 6 and s'''' = w q_k + u q_{k+1}.
// Continuity of s' and of s''' at knot i (d_i = (s_{i+1} - s_i) / h_i):
//   h_{i-1}/6 m_{i-1} + (h_{i-1} + h_i)/3 m_i + h_i/6 m_{i+1}
//       - [7 h_{i-1}^3/360 q_{i-1} + (h_{i-1}^3 + h_i^3)/45 q_i + 7 h_i^3/360 q_{i+1}] = d_i - d_{i-1}
//   h_{i-1}/6 q_{i-1} + (h_{i-1} + h_i)/3 q_i + h_i/6 q_{i+1} = (m_{i+1} - m_i)/h_i - (m_i - m_{i-1})/h_{i-1}
// (the second is the cubic spline's moment equation for m with "moments" q). The 2n equations, scaled to
// O(1) by the mean spacing H (rows by 1/H and H, q by H^2), are not diagonally dominant: they are solved by
// Gaussian elimination with partial pivoting on their band (the unknowns m_0, q_0, m_1, q_1, ... in the
// zig-zag order of profile/banded_solver.hpp, which makes the cyclic system a band of half-width 6). Cost O(n).
#pragma once

#include "rollkin/scalar.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace rollkin::synthesis {

/// x taken into one turn, [0, 2 pi): the angle a periodic table or law is evaluated at.
template <class S> S wrap_to_turn(const S& x) {
  using std::floor;
  const S turn = S(2) * pi<S>();
  S w = x - turn * floor(x / turn);
  if (w >= turn) w -= turn;
  return w;
}

namespace detail {

/// A cyclic banded system A x = b over `nodes` unknowns whose non-zeros join nodes at most `node_half_width`
/// apart on the cycle, solved by Gaussian elimination with partial pivoting (rows may swap within the band,
/// so U keeps twice the band above its diagonal). O(nodes w^2).
template <class S> class PivotedCyclicBand {
 public:
  PivotedCyclicBand(std::size_t nodes, std::size_t node_half_width)
      : n_(nodes), w_(2 * node_half_width), band_(nodes * (3 * w_ + 1), S(0)), b_(nodes, S(0)) {}
  void add(std::size_t i, std::size_t j, const S& v) { at(row_of(i), row_of(j)) += v; }
  void set_rhs(std::size_t i, const S& v) { b_[row_of(i)] = v; }

  /// x by node; false when a pivot is zero (a singular system).
  bool solve(std::vector<S>& x) {
    using std::abs;
    for (std::size_t k = 0; k < n_; ++k) {
      const std::size_t last = std::min(n_ - 1, k + w_), right = std::min(n_ - 1, k + 2 * w_);
      std::size_t p = k;
      for (std::size_t r = k + 1; r <= last; ++r)
        if (abs(at(r, k)) > abs(at(p, k))) p = r;
      if (at(p, k) == S(0)) return false;
      if (p != k) {
        for (std::size_t c = k; c <= right; ++c) std::swap(at(k, c), at(p, c));
        std::swap(b_[k], b_[p]);
      }
      for (std::size_t r = k + 1; r <= last; ++r) {
        const S factor = at(r, k) / at(k, k);
        if (factor == S(0)) continue;
        for (std::size_t c = k + 1; c <= right; ++c) at(r, c) -= factor * at(k, c);
        b_[r] -= factor * b_[k];
      }
    }
    for (std::size_t k = n_; k-- > 0;) {
      const std::size_t right = std::min(n_ - 1, k + 2 * w_);
      for (std::size_t c = k + 1; c <= right; ++c) b_[k] -= at(k, c) * b_[c];
      b_[k] /= at(k, k);
    }
    x.resize(n_);
    for (std::size_t i = 0; i < n_; ++i) x[i] = b_[row_of(i)];
    return true;
  }

 private:
  /// Zig-zag position of node i (as BandedSystem): nodes 0, n-1, 1, n-2, ... go to rows 0, 1, 2, 3, ...
  std::size_t row_of(std::size_t i) const { return i < (n_ + 1) / 2 ? 2 * i : 2 * (n_ - 1 - i) + 1; }
  /// Entry (r, c), c - r in [-w, 2 w].
  S& at(std::size_t r, std::size_t c) { return band_[r * (3 * w_ + 1) + (c + w_ - r)]; }

  std::size_t n_, w_;
  std::vector<S> band_, b_;
};

}  // namespace detail

template <class S> class PeriodicSpline {
 public:
  PeriodicSpline() = default;

  /// Through (x_i, s_i), x increasing over less than one turn (at least 4 knots; checked by the caller).
  PeriodicSpline(std::vector<S> x, std::vector<S> s) : x_(std::move(x)), s_(std::move(s)) { fit(); }

  const std::vector<S>& knots() const { return x_; }
  bool empty() const { return x_.empty(); }

  /// {s, s', s'', s'''} at x (any real). `left`: at a knot, the span that ends there.
  std::array<S, 4> operator()(const S& x, bool left = false) const {
    const S turn = S(2) * pi<S>();
    const std::size_t n = x_.size();
    const S first = x_.front();
    S at = x >= first && x < first + turn ? x : S(first + wrap_to_turn(S(x - first)));  // a knot stays exact
    if (left && at == first) at += turn;
    const auto begin = x_.begin();
    // Right: the last knot <= at. Left: the span whose end is the first knot >= at (the closing span if none).
    const std::size_t k = left ? std::min(static_cast<std::size_t>(std::lower_bound(begin + 1, x_.end(), at) - (begin + 1)), n - 1)
                               : static_cast<std::size_t>(std::upper_bound(begin, x_.end(), at) - begin) - 1;
    return on_span(k, S(at - x_[k]));
  }

 private:
  S knot(std::size_t k) const { return k < x_.size() ? x_[k] : S(x_[k - x_.size()] + S(2) * pi<S>()); }
  S h(std::size_t k) const { return knot(k + 1) - knot(k); }

  void fit() {
    const std::size_t n = x_.size();
    const S H = S(2) * pi<S>() / S(n);
    detail::PivotedCyclicBand<S> system(2 * n, 3);
    const auto m = [](std::size_t i) { return 2 * i; };      // unknown of m_i
    const auto q = [](std::size_t i) { return 2 * i + 1; };  // of Q_i = q_i H^2
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t prev = (i + n - 1) % n, next = (i + 1) % n;
      const S hb = h(prev), ha = h(i), hb3 = hb * hb * hb, ha3 = ha * ha * ha, H3 = H * H * H;
      // Continuity of s' (divided by H): the equation of node m(i).
      system.add(m(i), m(prev), hb / (S(6) * H));
      system.add(m(i), m(i), (hb + ha) / (S(3) * H));
      system.add(m(i), m(next), ha / (S(6) * H));
      system.add(m(i), q(prev), -S(7) * hb3 / (S(360) * H3));
      system.add(m(i), q(i), -(hb3 + ha3) / (S(45) * H3));
      system.add(m(i), q(next), -S(7) * ha3 / (S(360) * H3));
      system.set_rhs(m(i), ((s_[next] - s_[i]) / ha - (s_[i] - s_[prev]) / hb) / H);
      // Continuity of s''' (times H): the equation of node q(i).
      system.add(q(i), q(prev), hb / (S(6) * H));
      system.add(q(i), q(i), (hb + ha) / (S(3) * H));
      system.add(q(i), q(next), ha / (S(6) * H));
      system.add(q(i), m(next), -H / ha);
      system.add(q(i), m(i), H / ha + H / hb);
      system.add(q(i), m(prev), -H / hb);
    }
    std::vector<S> x;
    if (!system.solve(x)) throw std::invalid_argument("table: its periodic spline cannot be fitted (the knots are too uneven)");
    m_.resize(n);
    q_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      m_[i] = x[m(i)];
      q_[i] = x[q(i)] / (H * H);
    }
  }

  /// {s, s', s'', s'''} on span k at t = x - x_k (file comment).
  std::array<S, 4> on_span(std::size_t k, const S& t) const {
    const std::size_t n = x_.size(), k1 = (k + 1) % n;
    const S hk = h(k), u = t / hk, w = S(1) - u, h2 = hk * hk;
    const S phi_w = (w - w * w * w) / S(6), phi_u = (u - u * u * u) / S(6);
    const S psi_w = w * (S(7) / S(360) + w * w * (S(-1) / S(36) + w * w / S(120)));
    const S psi_u = u * (S(7) / S(360) + u * u * (S(-1) / S(36) + u * u / S(120)));
    const S dphi_w = (S(1) - S(3) * w * w) / S(6), dphi_u = (S(1) - S(3) * u * u) / S(6);
    const S dpsi_w = S(7) / S(360) + w * w * (S(-1) / S(12) + w * w / S(24));
    const S dpsi_u = S(7) / S(360) + u * u * (S(-1) / S(12) + u * u / S(24));
    const S value = w * s_[k] + u * s_[k1] - h2 * (m_[k] * phi_w + m_[k1] * phi_u) + h2 * h2 * (q_[k] * psi_w + q_[k1] * psi_u);
    const S slope = (s_[k1] - s_[k]) / hk - hk * (m_[k1] * dphi_u - m_[k] * dphi_w) + hk * h2 * (q_[k1] * dpsi_u - q_[k] * dpsi_w);
    const S second = w * m_[k] + u * m_[k1] + h2 * (q_[k] * (w * w * w - w) + q_[k1] * (u * u * u - u)) / S(6);
    const S third = (m_[k1] - m_[k]) / hk + hk * (q_[k1] * (S(3) * u * u - S(1)) - q_[k] * (S(3) * w * w - S(1))) / S(6);
    return {value, slope, second, third};
  }

  std::vector<S> x_, s_, m_, q_;  // knots, values, second and fourth derivatives at the knots
};

}  // namespace rollkin::synthesis
