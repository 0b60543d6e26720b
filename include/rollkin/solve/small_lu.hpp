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
  using Matrix = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;
  using Vector = Eigen::Matrix<S, Eigen::Dynamic, 1>;

  explicit SmallLU(Eigen::Index n = 0) : lu_(n, n), perm_(static_cast<std::size_t>(n)) {}

  /// Factors P A = L U. Returns false if a pivot is exactly zero (then solve() must not be used).
  template <class M> bool compute(const M& a) {
    using std::abs;
    lu_ = a;
    const Eigen::Index n = lu_.rows();
    for (Eigen::Index i = 0; i < n; ++i) perm_[i] = i;
    for (Eigen::Index k = 0; k < n; ++k) {
      Eigen::Index p = k;
      S best = abs(lu_(k, k));
      for (Eigen::Index i = k + 1; i < n; ++i)
        if (abs(lu_(i, k)) > best) {
          best = abs(lu_(i, k));
          p = i;
        }
      if (best == S(0)) return false;
      if (p != k) {
        lu_.row(p).swap(lu_.row(k));
        std::swap(perm_[p], perm_[k]);
      }
      const S inv = S(1) / lu_(k, k);
      for (Eigen::Index i = k + 1; i < n; ++i) {
        const S f = lu_(i, k) * inv;
        lu_(i, k) = f;
        for (Eigen::Index j = k + 1; j < n; ++j) lu_(i, j) -= f * lu_(k, j);
      }
    }
    return true;
  }

  /// Solves A x = b (forward substitution with the unit lower factor, back substitution with U).
  template <class B> void solve(const B& b, Vector& x) const {
    const Eigen::Index n = lu_.rows();
    x.resize(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      S sum = b(perm_[i]);
      for (Eigen::Index j = 0; j < i; ++j) sum -= lu_(i, j) * x(j);
      x(i) = sum;
    }
    for (Eigen::Index i = n - 1; i >= 0; --i) {
      S sum = x(i);
      for (Eigen::Index j = i + 1; j < n; ++j) sum -= lu_(i, j) * x(j);
      x(i) = sum / lu_(i, i);
    }
  }

  /// The combined factors: strictly lower part L (unit diagonal implied), upper part U.
  const Matrix& matrixLU() const { return lu_; }

 private:
  Matrix lu_;
  std::vector<Eigen::Index> perm_;
};

}  // namespace rollkin
