// Partial-pivot LU for the small square systems of planar mechanisms (a handful of unknowns per loop).
// Eigen's general PartialPivLU is blocked for large matrices; at n = 5 its bookkeeping costs several times
// the arithmetic, and the Newton loop factors once per iteration. This is the textbook Doolittle
// elimination with row pivoting, in place, allocation-free after construction, for any scalar S.
#pragma once

#include "rollkin/scalar.hpp"

#include <Eigen/Core>

#include <vector>

// Full unrolling of the fixed-size kernels (GCC and Clang both read this pragma; others ignore it).
#if defined(__GNUC__) || defined(__clang__)
#define ROLLKIN_UNROLL _Pragma("GCC unroll 8")
#else
#define ROLLKIN_UNROLL
#endif

namespace rollkin {

template <class S> class SmallLU {
 public:
  using Vector = Eigen::Matrix<S, Eigen::Dynamic, 1>;

  explicit SmallLU(Eigen::Index n = 0)
      : n_(n), lu_(static_cast<std::size_t>(n * n)), inverse_pivot_(static_cast<std::size_t>(n)), row_(static_cast<std::size_t>(n)) {}

  /// Factors P A = L U in a row-major buffer; pivoting permutes row indices, not the data.
  /// Returns false if a pivot is exactly zero (then solve() must not be used). `a` is anything with a(i, j):
  /// a matrix, or a function computing the entries (read once each).
  /// Sizes 1 to 8 run a kernel whose size is a compile-time constant (fully unrolled loops, no
  /// bounds bookkeeping); the arithmetic and its order are the same for every size.
  template <class M> bool compute(const M& a) {
    switch (n_) {
      case 1: return compute_n<1>(a);
      case 2: return compute_n<2>(a);
      case 3: return compute_n<3>(a);
      case 4: return compute_n<4>(a);
      case 5: return compute_n<5>(a);
      case 6: return compute_n<6>(a);
      case 7: return compute_n<7>(a);
      case 8: return compute_n<8>(a);
      default: return compute_n<kDynamic>(a);
    }
  }

  /// Solves A x = b (forward substitution with the unit lower factor, back substitution with U).
  template <class B> void solve(const B& b, Vector& x) const {
    x.resize(n_);
    switch (n_) {
      case 1: return solve_n<1>(b, x);
      case 2: return solve_n<2>(b, x);
      case 3: return solve_n<3>(b, x);
      case 4: return solve_n<4>(b, x);
      case 5: return solve_n<5>(b, x);
      case 6: return solve_n<6>(b, x);
      case 7: return solve_n<7>(b, x);
      case 8: return solve_n<8>(b, x);
      default: return solve_n<kDynamic>(b, x);
    }
  }

  /// max_i |u_ii| and min_i |u_ii| of the last successful compute().
  const S& largest_pivot() const { return largest_pivot_; }
  const S& smallest_pivot() const { return smallest_pivot_; }
  /// Sign of det A of the last successful compute(): det A = (-1)^(row swaps) prod u_kk. A sign change
  /// between two poses of a continuation means a singular Jacobian in between (continuation.hpp).
  int determinant_sign() const {
    int sign = odd_swaps_ ? -1 : 1;
    for (Eigen::Index k = 0; k < n_; ++k)
      if (lu_[static_cast<std::size_t>(row_[static_cast<std::size_t>(k)] * n_ + k)] < S(0)) sign = -sign;
    return sign;
  }
  Eigen::Index size() const { return n_; }

 private:
  static constexpr int kDynamic = 0;  // kernel size 0: the run-time size n_

  template <int N> Eigen::Index dim() const { return N == kDynamic ? n_ : Eigen::Index(N); }

  /// Doolittle elimination with row pivoting (Golub & Van Loan, Algorithm 3.4.1) on the row-major copy.
  template <int N, class M> bool compute_n(const M& a) {
    using std::abs;
    using std::max;
    using std::min;
    const Eigen::Index n = dim<N>();
    S* lu = lu_.data();
    Eigen::Index* row = row_.data();
    odd_swaps_ = false;
    ROLLKIN_UNROLL
    for (Eigen::Index i = 0; i < n; ++i) {
      row[i] = i;
      ROLLKIN_UNROLL
      for (Eigen::Index j = 0; j < n; ++j) lu[i * n + j] = a(i, j);
    }
    ROLLKIN_UNROLL
    for (Eigen::Index k = 0; k < n; ++k) {
      Eigen::Index p = k;
      S best = abs(lu[row[k] * n + k]);
      ROLLKIN_UNROLL
      for (Eigen::Index i = k + 1; i < n; ++i) {
        const S candidate = abs(lu[row[i] * n + k]);
        if (candidate > best) {
          best = candidate;
          p = i;
        }
      }
      // best = |u_kk|: the pivot ratio for the condition estimate comes for free.
      largest_pivot_ = k == 0 ? best : max(largest_pivot_, best);
      smallest_pivot_ = k == 0 ? best : min(smallest_pivot_, best);
      if (best == S(0)) return false;
      odd_swaps_ ^= p != k;
      std::swap(row[p], row[k]);
      const S* pivot_row = lu + row[k] * n;
      const S inv = S(1) / pivot_row[k];
      inverse_pivot_[static_cast<std::size_t>(k)] = inv;
      ROLLKIN_UNROLL
      for (Eigen::Index i = k + 1; i < n; ++i) {
        S* r = lu + row[i] * n;
        const S f = r[k] * inv;
        r[k] = f;
        ROLLKIN_UNROLL
        for (Eigen::Index j = k + 1; j < n; ++j) r[j] -= f * pivot_row[j];
      }
    }
    return true;
  }

  /// L y = P b by forward substitution, then U x = y by back substitution (Golub & Van Loan, 3.1), multiplying
  /// by the pivots' reciprocals kept from compute(): a chain of dependent divisions was most of a solve.
  template <int N, class B> void solve_n(const B& b, Vector& x) const {
    const Eigen::Index n = dim<N>();
    const S* lu = lu_.data();
    const Eigen::Index* row = row_.data();
    const S* inverse_pivot = inverse_pivot_.data();
    S* xs = x.data();
    ROLLKIN_UNROLL
    for (Eigen::Index i = 0; i < n; ++i) {
      const S* r = lu + row[i] * n;
      S sum = b(row[i]);
      ROLLKIN_UNROLL
      for (Eigen::Index j = 0; j < i; ++j) sum -= r[j] * xs[j];
      xs[i] = sum;
    }
    ROLLKIN_UNROLL
    for (Eigen::Index i = n - 1; i >= 0; --i) {
      const S* r = lu + row[i] * n;
      S sum = xs[i];
      ROLLKIN_UNROLL
      for (Eigen::Index j = i + 1; j < n; ++j) sum -= r[j] * xs[j];
      xs[i] = sum * inverse_pivot[i];
    }
  }

  Eigen::Index n_;
  std::vector<S> lu_;                 // row-major n x n: L below the diagonal (unit diagonal implied), U on and above
  std::vector<S> inverse_pivot_;      // 1 / u_kk
  std::vector<Eigen::Index> row_;     // row_[k]: the stored row that is the k-th row of P A
  S largest_pivot_ = S(0), smallest_pivot_ = S(0);
  bool odd_swaps_ = false;            // parity of the row permutation P
};

}  // namespace rollkin
