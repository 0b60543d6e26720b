// Banded linear systems for spline fitting, O(n w^2) time and O(n w) memory for half-bandwidth w.
//
// Cyclic systems (periodic splines) are made banded by the zig-zag ordering 0, n-1, 1, n-2, 2, ...: nodes
// that are neighbours on the cycle (distance d, wrapping) are then at most 2d rows apart, so a cyclic
// tridiagonal matrix becomes a band of half-width 2 and a cyclic pentadiagonal one of half-width 4.
// Elimination is Gaussian without pivoting, which is stable for the symmetric positive definite and the
// diagonally dominant matrices the splines produce.
#pragma once

#include "rollkin/scalar.hpp"

#include <vector>

namespace rollkin {

template <class S> class BandedSystem {
 public:
  /// n unknowns indexed by node 0..n-1; `cyclic` selects the zig-zag row order; `node_half_width` is the
  /// largest |i - j| (cyclic distance if cyclic) of a non-zero entry between nodes i and j.
  BandedSystem(std::size_t n, std::size_t node_half_width, bool cyclic)
      : n_(n), cyclic_(cyclic), w_(cyclic ? 2 * node_half_width : node_half_width), band_(n * (2 * w_ + 1), S(0)) {}

  std::size_t size() const { return n_; }

  /// A(i, j) += v for nodes i, j.
  void add(std::size_t i, std::size_t j, const S& v) { entry(row_of(i), row_of(j)) += v; }

  /// Solves A x = rhs (one right-hand side per node, x and y together) and returns x by node. Destroys A.
  std::vector<Vec2<S>> solve(const std::vector<Vec2<S>>& rhs_by_node) {
    std::vector<Vec2<S>> b(n_);
    for (std::size_t i = 0; i < n_; ++i) b[row_of(i)] = rhs_by_node[i];
    eliminate_forward(b);
    substitute_back(b);
    std::vector<Vec2<S>> x(n_);
    for (std::size_t i = 0; i < n_; ++i) x[i] = b[row_of(i)];
    return x;
  }

 private:
  /// Zig-zag position of node i: nodes 0, 1, 2, ... go to rows 0, 2, 4, ...; nodes n-1, n-2, ... to rows 1, 3, ...
  std::size_t row_of(std::size_t i) const {
    if (!cyclic_) return i;
    return i < (n_ + 1) / 2 ? 2 * i : 2 * (n_ - 1 - i) + 1;
  }
  S& entry(std::size_t r, std::size_t c) { return band_[r * (2 * w_ + 1) + (c + w_ - r)]; }

  void eliminate_forward(std::vector<Vec2<S>>& b) {
    for (std::size_t k = 0; k < n_; ++k) {
      const S pivot = entry(k, k);
      const std::size_t last = std::min(n_ - 1, k + w_);
      for (std::size_t r = k + 1; r <= last; ++r) {
        const S factor = entry(r, k) / pivot;
        if (factor == S(0)) continue;
        for (std::size_t c = k + 1; c <= last; ++c) entry(r, c) -= factor * entry(k, c);
        b[r] -= factor * b[k];
      }
    }
  }
  void substitute_back(std::vector<Vec2<S>>& b) {
    for (std::size_t k = n_; k-- > 0;) {
      const std::size_t last = std::min(n_ - 1, k + w_);
      for (std::size_t c = k + 1; c <= last; ++c) b[k] -= entry(k, c) * b[c];
      b[k] /= entry(k, k);
    }
  }

  std::size_t n_;
  bool cyclic_;
  std::size_t w_;
  std::vector<S> band_;
};

}  // namespace rollkin
