// Partial-pivot LU for the small square systems of planar mechanisms (a handful of unknowns per loop).
// Eigen's general PartialPivLU is blocked for large matrices; at n = 5 its bookkeeping costs several times
// the arithmetic, and the Newton loop factors once per iteration. This is the textbook Doolittle
// elimination with row pivoting, in place, allocation-free after construction, for any scalar S.
#pragma once

#include "rollkin/scalar.hpp"

#include <Eigen/Core>

#include <vector>

namespace rollkin {

template <class S> class SmallLU {
 public:
  using Vector = Eigen::Matrix<S, Eigen::Dynamic, 1>;

  explicit SmallLU(Eigen::Index n = 0) : n_(n), lu_(static_cast<std::size_t>(n * n)), row_(static_cast<std::size_t>(n)) {}

  /// Factors P A = L U in a row-major buffer; pivoting permutes row indices, not the data.
  /// Returns false if a pivot is exactly zero (then solve() must not be used).
  template <class M> bool compute(const M& a) {
    using std::abs;
    const Eigen::Index n = n_;
    for (Eigen::Index i = 0; i < n; ++i) {
      row_[i] = i;
      for (Eigen::Index j = 0; j < n; ++j) at(i, j) = a(i, j);
    }
    for (Eigen::Index k = 0; k < n; ++k) {
      Eigen::Index p = k;
      S best = abs(at(row_[k], k));
      for (Eigen::Index i = k + 1; i < n; ++i) {
        const S candidate = abs(at(row_[i], k));
        if (candidate > best) {
          best = candidate;
          p = i;
        }
      }
      if (best == S(0)) return false;
      std::swap(row_[p], row_[k]);
      S* pivot_row = &at(row_[k], 0);
      const S inv = S(1) / pivot_row[k];
      for (Eigen::Index i = k + 1; i < n; ++i) {
        S* r = &at(row_[i], 0);
        const S f = r[k] * inv;
        r[k] = f;
        for (Eigen::Index j = k + 1; j < n; ++j) r[j] -= f * pivot_row[j];
      }
    }
    return true;
  }

  /// Solves A x = b (forward substitution with the unit lower factor, back substitution with U).
  template <class B> void solve(const B& b, Vector& x) const {
    const Eigen::Index n = n_;
    x.resize(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const S* r = &at(row_[i], 0);
      S sum = b(row_[i]);
      for (Eigen::Index j = 0; j < i; ++j) sum -= r[j] * x(j);
      x(i) = sum;
    }
    for (Eigen::Index i = n - 1; i >= 0; --i) {
      const S* r = &at(row_[i], 0);
      S sum = x(i);
      for (Eigen::Index j = i + 1; j < n; ++j) sum -= r[j] * x(j);
      x(i) = sum / r[i];
    }
  }

  /// |u_ii|, the pivots of the upper factor (for the pivot-ratio condition estimate).
  S pivot(Eigen::Index i) const {
    using std::abs;
    return abs(at(row_[i], i));
  }
  Eigen::Index size() const { return n_; }

 private:
  S& at(Eigen::Index i, Eigen::Index j) { return lu_[static_cast<std::size_t>(i * n_ + j)]; }
  const S& at(Eigen::Index i, Eigen::Index j) const { return lu_[static_cast<std::size_t>(i * n_ + j)]; }

  Eigen::Index n_;
  std::vector<S> lu_;                 // row-major n x n: L below the diagonal (unit diagonal implied), U on and above
  std::vector<Eigen::Index> row_;     // row_[k]: the stored row that is the k-th row of P A
};

}  // namespace rollkin
