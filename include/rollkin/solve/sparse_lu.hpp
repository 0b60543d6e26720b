// Sparse LU of the scaled Jacobian of the unknowns, for mechanisms with many loops.
//
// Each loop's three rows touch only its own pairs' variables (and each rolling row two), so the Jacobian of
// a gear train or a chain of four-bars is block-sparse with a few nonzeros per row. Its pattern is fixed per
// mechanism (kinematics.hpp, JacobianPattern): the sparse matrix is built once with a map from each pattern
// entry to its value slot, ordered and analysed symbolically once, and each Newton step only refills the
// values and factors numerically. Two back ends, chosen in SolveData (position.hpp): SuiteSparse KLU (when
// the build found it: ROLLKIN_HAVE_KLU) and Eigen's SparseLU; docs/benchmark.md ("Scaling with the
// mechanism") compares them. Both are double only.
//
// Redundant constraints (more equations than unknowns, e.g. the centre distance of two pivoted rolling disks,
// which the loop's translation rows already fix) are found once by a rank-revealing sparse QR of J^T at the
// first pose (SparseQR pivots out the rows that depend on earlier ones): the LU then factors the square
// system of the independent rows, and the residual of all rows still decides convergence and consistency.
#pragma once

#include "rollkin/kinematics.hpp"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <Eigen/SparseQR>

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#ifndef ROLLKIN_HAVE_KLU
#define ROLLKIN_HAVE_KLU 0
#endif
#if ROLLKIN_HAVE_KLU
#include <klu.h>
#endif

namespace rollkin {

/// How SolveData factors the Jacobian of the unknowns.
enum class Factorisation {
  Automatic,      ///< Dense below sparse_threshold unknowns or for a scalar other than double, else sparse
                  ///< (KLU when built with it, else EigenSparseLU)
  Dense,          ///< SmallLU, or the complete orthogonal decomposition for non-square or singular systems
  EigenSparseLU,  ///< Eigen::SparseLU (COLAMD ordering)
  Klu,            ///< SuiteSparse KLU (BTF + AMD ordering, refactorisation with the previous pivots)
};

/// Unknowns from which Automatic factors sparse: below it the fixed-size dense kernels win (measured by the
/// benchmark's scaling section, docs/benchmark.md).
inline constexpr int sparse_threshold = 12;

/// The sparse back ends work in double; other scalars (MPFR) take the dense path.
template <class S> inline constexpr bool sparse_factorisation_available = std::is_same_v<S, double>;
inline constexpr bool klu_available = ROLLKIN_HAVE_KLU != 0;

/// The sparse back end Automatic picks.
inline Factorisation default_sparse_factorisation() {
  return klu_available ? Factorisation::Klu : Factorisation::EigenSparseLU;
}

/// Rows of `a` (the scaled Jacobian of the unknowns, equations x unknowns) that are linearly independent, in
/// increasing order, by a rank-revealing sparse QR of a^T (SparseQR moves the columns of a^T, the rows of a,
/// whose remaining norm is below its threshold behind the others); their number is the rank of a.
inline std::vector<int> independent_rows(const Eigen::SparseMatrix<double>& a) {
  Eigen::SparseMatrix<double> at = a.transpose();
  at.makeCompressed();
  Eigen::SparseQR<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> qr(at);
  std::vector<int> rows;
  if (qr.info() != Eigen::Success) return rows;
  for (Eigen::Index k = 0; k < qr.rank(); ++k) rows.push_back(qr.colsPermutation().indices()(k));
  std::sort(rows.begin(), rows.end());
  return rows;
}

/// Square sparse LU of selected rows of the scaled Jacobian of the unknowns (double).
class SparseUnknownsLU {
 public:
  SparseUnknownsLU() = default;
  // A copy holds no factors (they own KLU's memory): it is set up again at its first use (ready() false).
  SparseUnknownsLU(const SparseUnknownsLU&) {}
  SparseUnknownsLU& operator=(const SparseUnknownsLU& other) {
    if (this != &other) release();
    return *this;
  }
  ~SparseUnknownsLU() { release(); }

  /// Builds the matrix of the rows `selected` (equation indices, as many as unknowns) and the columns of
  /// the unknowns (unknown_of_variable: a variable's unknown column, -1 for a driver), the map from each
  /// pattern entry to its value slot and the per-entry scale R^-1 .. C, and analyses it symbolically.
  void setup(const JacobianPattern& pattern, const std::vector<int>& unknown_of_variable,
             const std::vector<int>& selected, const VectorX<double>& row_weight, const VectorX<double>& col_scale,
             Factorisation backend) {
    release();
    backend_ = backend;
    n_ = static_cast<int>(selected.size());
    selected_ = selected;
    std::vector<int> local_row(static_cast<std::size_t>(row_weight.size()), -1);
    for (int i = 0; i < n_; ++i) local_row[static_cast<std::size_t>(selected[static_cast<std::size_t>(i)])] = i;
    std::vector<Eigen::Triplet<double>> triplets;
    entry_.clear();
    for (int e = 0; e < pattern.size(); ++e) {
      const int r = local_row[static_cast<std::size_t>(pattern.row[e])];
      const int c = unknown_of_variable[static_cast<std::size_t>(pattern.column[e])];
      if (r < 0 || c < 0) continue;
      triplets.emplace_back(r, c, 1.0);
      entry_.push_back(Entry{e, 0, row_weight(pattern.row[e]) * col_scale(c)});
    }
    matrix_.resize(n_, n_);
    matrix_.setFromTriplets(triplets.begin(), triplets.end());
    matrix_.makeCompressed();
    for (std::size_t k = 0; k < entry_.size(); ++k) {  // slot of (r, c): binary search in column c
      const int r = triplets[k].row(), c = triplets[k].col();
      const int* begin = matrix_.innerIndexPtr() + matrix_.outerIndexPtr()[c];
      const int* end = matrix_.innerIndexPtr() + matrix_.outerIndexPtr()[c + 1];
      entry_[k].slot = static_cast<int>(std::lower_bound(begin, end, r) - matrix_.innerIndexPtr());
    }
    rhs_.resize(n_);
    row_sum_.resize(n_);
    visited_.assign(static_cast<std::size_t>(n_), 0);
#if ROLLKIN_HAVE_KLU
    if (backend_ == Factorisation::Klu) {
      klu_defaults(&common_);
      symbolic_ = klu_analyze(n_, matrix_.outerIndexPtr(), matrix_.innerIndexPtr(), &common_);
      return;
    }
#endif
    backend_ = Factorisation::EigenSparseLU;
    eigen_lu_.analyzePattern(matrix_);
  }

  bool ready() const { return n_ > 0; }
  const std::vector<int>& selected_rows() const { return selected_; }

  /// Refills the values from the Jacobian's nonzeros (pattern order) and factors; false if the factors
  /// broke down (a zero pivot). Then largest_pivot / smallest_pivot and determinant_sign describe them.
  bool factor(const VectorX<double>& values) {
    double* v = matrix_.valuePtr();
    std::fill(v, v + matrix_.nonZeros(), 0.0);
    for (const Entry& e : entry_) v[e.slot] += values(e.entry) * e.scale;
#if ROLLKIN_HAVE_KLU
    if (backend_ == Factorisation::Klu) return factor_klu();
#endif
    return factor_eigen();
  }

  /// x = A^-1 b(selected rows).
  template <class B> void solve(const B& b, VectorX<double>& x) {
    for (int i = 0; i < n_; ++i) rhs_(i) = b(selected_[static_cast<std::size_t>(i)]);
    solve_in_place();
    x = rhs_;
  }

  double largest_pivot() const { return largest_; }
  double smallest_pivot() const { return smallest_; }

  /// The condition of the factored matrix A as the pivots cannot show it: ||A||_inf ||A^-1 b||_inf for a
  /// vector b of pseudo-random signs (one solve), a lower bound of cond_inf(A) that grows like 1/sigma_min
  /// unless b is orthogonal to the smallest singular direction. KLU's pivots (taken in the order of an
  /// earlier factorisation by klu_refactor, and spread over its block-triangular blocks) can all stay
  /// moderate at a singular matrix: at a parallelogram's change point their ratio read 8.7 where the dense
  /// LU's read 1.5e12.
  double condition_estimate() {
    row_sum_.setZero();
    const double* v = matrix_.valuePtr();
    const int* row = matrix_.innerIndexPtr();
    for (Eigen::Index k = 0; k < matrix_.nonZeros(); ++k) row_sum_(row[k]) += std::abs(v[k]);
    std::uint32_t state = 0x9e3779b9u;
    for (int i = 0; i < n_; ++i) {
      state = state * 1664525u + 1013904223u;  // linear congruential signs: fixed, so reproducible
      rhs_(i) = (state >> 31) ? 1.0 : -1.0;
    }
    solve_in_place();
    return row_sum_.maxCoeff() * rhs_.cwiseAbs().maxCoeff();
  }
  int determinant_sign() const { return sign_; }

  /// Bytes held: the matrix, the map, and the factors (KLU's own count; Eigen: the factors' nonzeros).
  std::size_t bytes() const {
    std::size_t b = static_cast<std::size_t>(matrix_.nonZeros()) * (sizeof(double) + sizeof(int)) +
                    static_cast<std::size_t>(n_ + 1) * sizeof(int) + entry_.size() * sizeof(Entry);
#if ROLLKIN_HAVE_KLU
    if (backend_ == Factorisation::Klu) return b + common_.memusage;
#endif
    if (n_ > 0 && factored_)
      b += static_cast<std::size_t>(eigen_lu_.nnzL() + eigen_lu_.nnzU()) * (sizeof(double) + sizeof(int));
    return b;
  }

 private:
  struct Entry {
    int entry;     // index in the pattern
    int slot;      // index in matrix_'s values
    double scale;  // row weight x column scale
  };

  /// rhs_ = A^-1 rhs_.
  void solve_in_place() {
#if ROLLKIN_HAVE_KLU
    if (backend_ == Factorisation::Klu) {
      klu_solve(symbolic_, numeric_, n_, 1, rhs_.data(), &common_);
      return;
    }
#endif
    rhs_ = eigen_lu_.solve(rhs_).eval();
  }

  bool factor_eigen() {
    eigen_lu_.factorize(matrix_);
    factored_ = eigen_lu_.info() == Eigen::Success;
    if (!factored_) return false;
    // The diagonal of U sits in the supernodes of L (as in SparseLU::signDeterminant).
    const auto& l = eigen_lu_.matrixL().m_mapL;
    largest_ = 0;
    smallest_ = std::numeric_limits<double>::infinity();
    for (Eigen::Index j = 0; j < n_; ++j)
      for (typename std::decay_t<decltype(l)>::InnerIterator it(l, j); it; ++it)
        if (it.index() == j) {
          largest_ = std::max(largest_, std::abs(it.value()));
          smallest_ = std::min(smallest_, std::abs(it.value()));
          break;
        }
    sign_ = static_cast<int>(eigen_lu_.signDeterminant());
    return smallest_ > 0;
  }

#if ROLLKIN_HAVE_KLU
  /// Refactors with the previous pivot order (no search: cheapest), and factors afresh (partial pivoting)
  /// the first time, after a breakdown, or when the pivot ratio fell by 100 against the last fresh factors
  /// (the old pivots may have become poor ones).
  bool factor_klu() {
    if (numeric_ && klu_refactor(matrix_.outerIndexPtr(), matrix_.innerIndexPtr(), matrix_.valuePtr(), symbolic_,
                                 numeric_, &common_) &&
        pivots_klu() && smallest_ / largest_ >= fresh_ratio_ / 100)
      return true;
    if (numeric_) klu_free_numeric(&numeric_, &common_);
    numeric_ = klu_factor(matrix_.outerIndexPtr(), matrix_.innerIndexPtr(), matrix_.valuePtr(), symbolic_, &common_);
    if (!numeric_ || !pivots_klu()) return false;
    fresh_ratio_ = smallest_ / largest_;
    return true;
  }

  /// Pivot extremes and det sign of P R^-1 A Q = L U: sign(P) sign(Q) prod sign(u_ii) (R > 0 scales rows).
  bool pivots_klu() {
    const double* u = static_cast<const double*>(numeric_->Udiag);
    largest_ = 0;
    smallest_ = std::numeric_limits<double>::infinity();
    int sign = 1;
    for (int i = 0; i < n_; ++i) {
      largest_ = std::max(largest_, std::abs(u[i]));
      smallest_ = std::min(smallest_, std::abs(u[i]));
      if (u[i] < 0) sign = -sign;
    }
    sign_ = sign * permutation_sign(numeric_->Pnum) * permutation_sign(symbolic_->Q);
    return smallest_ > 0 && smallest_ == smallest_;
  }
#endif

  /// (-1)^(n - cycles) of a permutation of 0..n-1.
  int permutation_sign(const int* p) {
    std::fill(visited_.begin(), visited_.end(), 0);
    int cycles = 0;
    for (int i = 0; i < n_; ++i) {
      if (visited_[static_cast<std::size_t>(i)]) continue;
      ++cycles;
      for (int j = i; !visited_[static_cast<std::size_t>(j)]; j = p[j]) visited_[static_cast<std::size_t>(j)] = 1;
    }
    return (n_ - cycles) % 2 ? -1 : 1;
  }

  void release() {
#if ROLLKIN_HAVE_KLU
    if (numeric_) klu_free_numeric(&numeric_, &common_);
    if (symbolic_) klu_free_symbolic(&symbolic_, &common_);
#endif
    n_ = 0;
    factored_ = false;
  }

  Factorisation backend_ = Factorisation::EigenSparseLU;
  int n_ = 0;
  std::vector<int> selected_;
  std::vector<Entry> entry_;
  Eigen::SparseMatrix<double> matrix_;
  VectorX<double> rhs_, row_sum_;
  std::vector<char> visited_;
  double largest_ = 0, smallest_ = 0;
  int sign_ = 0;
  bool factored_ = false;
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> eigen_lu_;
#if ROLLKIN_HAVE_KLU
  klu_common common_{};
  klu_symbolic* symbolic_ = nullptr;
  klu_numeric* numeric_ = nullptr;
  double fresh_ratio_ = 0;
#endif
};

}  // namespace rollkin
