// Arc length (eq. 4) of a piecewise profile (sampled spline, Bezier path) through a cumulative table.
//
// The table holds s_k = arc length from the first knot to knot k, built once at construction by quadrature
// of each piece. Then
//   s(u)            = s_i + integral_{u_i}^{u} |p'| du         (u in piece i: one small quadrature),
//   arc_length(a,b) = s(b) - s(a)    (one quadrature only when a and b lie in the same piece; s(u) is the
//                                     profile's arc-length primitive),
//   u(s)            = bisection of the table for the piece, then safeguarded Newton inside it.
// Closed profiles add whole turns: s(u + period) = s(u) + total length.
//
// The piecewise profile supplies (as a `Pieces` object):
//   std::size_t piece_count() const;
//   std::size_t piece_of(const S& u) const;                   // piece holding u (clamped to the ends)
//   S knot(std::size_t k) const;                              // k = 0 .. piece_count()
//   S piece_length(std::size_t i, const S& a, const S& b) const;  // signed integral of |p'| inside piece i
//   S speed(std::size_t i, const S& u) const;                 // |p'(u)| evaluated with piece i's formula
#pragma once

#include "rollkin/profile/jet.hpp"

#include <algorithm>
#include <vector>

namespace rollkin {

template <class S> class PiecewiseArcLength {
 public:
  PiecewiseArcLength() = default;

  template <class Pieces> explicit PiecewiseArcLength(const Pieces& pieces) {
    const std::size_t n = pieces.piece_count();
    cumulative_.resize(n + 1);
    cumulative_[0] = S(0);
    for (std::size_t i = 0; i < n; ++i)
      cumulative_[i + 1] = cumulative_[i] + pieces.piece_length(i, pieces.knot(i), pieces.knot(i + 1));
  }

  S total() const { return cumulative_.back(); }
  const std::vector<S>& cumulative() const { return cumulative_; }

  /// Signed arc length from u0 to u1 (one quadrature inside one piece, else the primitive's difference,
  /// with each end wrapped and looked up once).
  template <class Pieces>
  S between(const Pieces& pieces, const Domain<S>& domain, const S& u0, const S& u1) const {
    const S t0 = domain.turns(u0), t1 = domain.turns(u1);
    const S w0 = domain.wrap(u0), w1 = domain.wrap(u1);
    const std::size_t i0 = pieces.piece_of(w0), i1 = pieces.piece_of(w1);
    if (t0 == t1 && i0 == i1) return pieces.piece_length(i0, w0, w1);
    return (t1 - t0) * total() + from_start(pieces, i1, w1) - from_start(pieces, i0, w0);
  }

  /// s(u): arc length from the first knot, whole turns included (closed profiles).
  template <class Pieces> S primitive(const Pieces& pieces, const Domain<S>& domain, const S& u) const {
    const S w = domain.wrap(u);
    return domain.turns(u) * total() + from_start(pieces, pieces.piece_of(w), w);
  }

  /// u such that between(u0, u) = ds.
  template <class Pieces>
  S param_at(const Pieces& pieces, const Domain<S>& domain, const S& u0, const S& ds) const {
    using std::floor;
    const S w0 = domain.wrap(u0);
    S target = from_start(pieces, pieces.piece_of(w0), w0) + ds;
    S turns(0);
    if (domain.closed) {
      turns = floor(target / total());
      target -= turns * total();
    }
    const std::size_t i = piece_at_length(target);
    return (u0 - w0) + turns * domain.period() + solve_in_piece(pieces, i, target - cumulative_[i]);
  }

 private:
  template <class Pieces> S from_start(const Pieces& pieces, std::size_t i, const S& u) const {
    return cumulative_[i] + pieces.piece_length(i, pieces.knot(i), u);
  }

  /// Piece k with s_k <= s < s_{k+1} by binary search; lengths outside [0, total] go to the end pieces.
  std::size_t piece_at_length(const S& s) const {
    const std::size_t n = cumulative_.size() - 1;
    const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), s);
    const std::size_t k = it == cumulative_.begin() ? 0 : static_cast<std::size_t>(it - cumulative_.begin()) - 1;
    return std::min(k, n - 1);
  }

  /// Solves integral_{knot_i}^{u} |p'| = r by Newton (derivative |p'(u)|), bisecting inside the piece's
  /// bracket whenever a step leaves it. Outside [0, piece length] (open ends) the piece is extrapolated.
  template <class Pieces> S solve_in_piece(const Pieces& pieces, std::size_t i, const S& r) const {
    using std::abs;
    const S a = pieces.knot(i), b = pieces.knot(i + 1);
    const S len = cumulative_[i + 1] - cumulative_[i];
    const bool bracketed = r >= S(0) && r <= len;
    S lo = a, hi = b;
    S u = a + (b - a) * (r / len);
    const S tol = epsilon<S>() * S(8) * (abs(a) + abs(b) + (b - a));
    for (int it = 0; it < 100; ++it) {
      const S f = pieces.piece_length(i, a, u) - r;
      if (f < S(0)) lo = u; else hi = u;
      S next = u - f / pieces.speed(i, u);
      if (bracketed && !(next >= lo && next <= hi)) next = (lo + hi) / S(2);
      const S step = abs(next - u);
      u = next;
      if (step <= tol) break;
    }
    return u;
  }

  std::vector<S> cumulative_;
};

}  // namespace rollkin
