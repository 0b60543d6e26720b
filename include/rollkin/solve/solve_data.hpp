// The solve workspace of one mechanism: Newton's settings and SolveData, the buffers and the factorisation
// (dense LU, LU of independent rows, complete orthogonal decomposition, or the sparse path) of the scaled
// Jacobian of the unknowns, sized once so that a solve allocates nothing per Newton step. position.hpp
// evaluates, factors and solves with it.
#pragma once

#include "rollkin/kinematics.hpp"
#include "rollkin/solve/report.hpp"
#include "rollkin/solve/small_lu.hpp"
#include "rollkin/solve/sparse_lu.hpp"

#include <Eigen/QR>

namespace rollkin {

template <class S> struct NewtonSettings {
  int max_iterations = 30;
  /// Converged when the scaled residual is below residual_tolerance...
  S residual_tolerance = epsilon<S>() * S(64);
  /// ...or when a step is below step_tolerance and the residual below consistency_tolerance (round-off).
  S step_tolerance = tolerance<S>(S(3) / S(4));
  /// Least-squares residual above this at convergence means inconsistent constraints. Redundant constraints
  /// between sampled contours agree only to the contours' interpolation error: SolveData raises it to that.
  S consistency_tolerance = tolerance<S>(S(1) / S(2));
};

/// The sparse factors SolveData<S> holds: SparseUnknownsLU for double, nothing for other scalars (MPFR).
struct NoSparseFactors {};
template <class S>
using SparseFactors = std::conditional_t<sparse_factorisation_available<S>, SparseUnknownsLU, NoSparseFactors>;

/// Solve workspace: buffers sized once per mechanism; a solve does not allocate per Newton step.
///
/// Factorisation (chosen once per mechanism, `method`): small mechanisms take the dense path: a square
/// system whose LU is well conditioned is solved by partial-pivot LU (SmallLU, many times cheaper than QR at
/// the sizes of planar mechanisms); a system with redundant constraints by the same LU on independent rows,
/// chosen once by a rank-revealing QR and again only where they fail (factor_selected_rows); a rank-deficient
/// or numerically singular system by the rank-revealing complete orthogonal decomposition, whose solve is the
/// minimum-norm least-squares step. From sparse_threshold unknowns (double) the sparse path (sparse_lu.hpp)
/// factors the independent rows, found once, by a sparse LU whose symbolic analysis is done once; its
/// condition is the larger of its pivot ratio and a one-solve estimate; a pose where that LU is singular
/// or ill-conditioned takes the dense decomposition instead (same statuses, rank and condition as the dense
/// path), and the independent rows are chosen again at the next pose if the system had rank n there.
template <class S> struct SolveData {
  Factorisation method;                  // Dense, EigenSparseLU or Klu (Automatic resolved)
  KinematicsData<S> kin;
  VectorX<S> row_scale, col_scale;       // residual and variable scales
  VectorX<S> row_weight;                 // 1 / row_scale: the hot path multiplies instead of dividing
  MatrixX<S> ju;                         // scaled Jacobian of the unknowns (filled for the COD only)
  std::vector<int> unknowns;             // the unknowns' columns in kin.jacobian
  VectorX<S> rhs, step;                  // scaled
  SmallLU<S> lu;
  Eigen::CompleteOrthogonalDecomposition<MatrixX<S>> cod;
  SparseFactors<S> sparse_lu;
  NewtonSettings<S> settings;
  // State of the current factorisation.
  bool lu_active = false;
  bool sparse_active = false;
  int rank = 0;
  S condition = S(0);

  explicit SolveData(const Mechanism<S>& m, Factorisation how = Factorisation::Automatic);

  /// The factorisation `how` asks for, with Automatic and the sparse back ends resolved for this mechanism
  /// and scalar (a sparse request for a scalar other than double gives Dense; Klu without KLU, Eigen's).
  static Factorisation resolve(const Mechanism<S>& m, Factorisation how);
  bool sparse() const { return method != Factorisation::Dense; }

  /// Entry (r, c) of the scaled Jacobian of the unknowns R^-1 J_u C: row r divided by its residual scale,
  /// column c (variable unknowns[c]) multiplied by its variable scale. Dense Jacobian only.
  S scaled_jacobian(Eigen::Index r, Eigen::Index c) const {
    return kin.jacobian(r, unknowns[static_cast<std::size_t>(c)]) * row_weight(r) * col_scale(c);
  }

  /// Factors the first `rows` rows of the scaled Jacobian of the unknowns (kin's Jacobian evaluated),
  /// choosing LU, sparse LU or COD as described above. The LU reads the scaled entries straight from
  /// kin.jacobian; ju is filled only for the COD. The condition estimate is the pivot ratio of the
  /// triangular factor (max |u_ii| / min |u_ii| for the LUs, |r_11| / |r_nn| for the column-pivoted QR inside
  /// COD): cheap, and it grows like 1/sigma_min toward a singular pose.
  void factor(int rows);
  /// x = J^-1 b (LU; of the independent rows of a redundant system) or the minimum-norm least-squares
  /// solution (COD), in the scaled variables.
  template <class B> void solve(const B& b, VectorX<S>& x) {
    if (lu_on_selected_rows_) {
      for (std::size_t i = 0; i < selected_rows_.size(); ++i) selected_rhs_(static_cast<Eigen::Index>(i)) = b(selected_rows_[i]);
      lu.solve(selected_rhs_, x);
    } else if (lu_active) lu.solve(b, x);
    else if (unknowns.empty()) x.resize(0);
    else if (sparse_active) {
      if constexpr (sparse_factorisation_available<S>) sparse_lu.solve(b, x);
    } else x.noalias() = cod.solve(b);
  }
  /// Sign of det of the scaled Jacobian of the unknowns when an LU is active (square, regular), else 0
  /// (unknown). The column and row scales are positive, so it is the sign of det J_u itself (with redundant
  /// constraints, of the independent rows the sparse path factors).
  int determinant_sign() const;

  /// The bound on the error of the unknowns at the pose just factored: the condition times the scaled
  /// residual of the square system the LU solves (`residual`, all rows, when `rows` is the number of
  /// unknowns; square_residual(), at least eps, with redundant rows: the few rows an LU solves can come out
  /// exactly zero at a change point, where the unknowns are anything but exact).
  S error_bound(const S& residual, int rows) const;

  /// The scaled residual (max-norm) of the square system the active LU factors: all rows of a square
  /// system, the independent rows of a redundant one (dense or sparse). Its condition times this bounds the
  /// error of the unknowns, which the least-squares floor of redundant rows that disagree (sampled contours)
  /// would blur. Infinite when no LU is active (the COD: rank-deficient or singular here).
  S square_residual() const;

  /// Bytes of the solve buffers and factors (the mechanism itself not counted).
  std::size_t bytes() const;

 private:
  std::vector<int> unknown_of_variable_;  // a variable's column among the unknowns, -1 for a driver
  int selected_for_rows_ = -1;            // the row count the sparse LU's independent rows were chosen for
  // Dense redundant systems: the independent rows the LU factors, the row count they were chosen for, the
  // pivot ratio of their LU when chosen, and the right-hand side gathered on them.
  std::vector<Eigen::Index> selected_rows_;
  int selected_dense_for_ = -1;
  S selected_condition_ = S(0);
  int selected_sign_offset_ = 1;      // relates the sign of det of the rows chosen now to the first choice's
  std::vector<Eigen::Index> kept_rows_;  // the previous choice, while a new one is tried
  VectorX<S> selected_rhs_;
  bool lu_on_selected_rows_ = false;  // the active LU is that of selected_rows_

  /// The LU just computed is used when its pivots are nonzero and not below n eps of the largest.
  bool accept_lu(bool nonzero_pivots);

  /// A dense system with more rows than unknowns (redundant constraints): the LU of n independent rows among
  /// the first `rows`, chosen by a column-pivoted QR of the transposed Jacobian (its first n pivots) at the
  /// first pose. Where their pivot ratio has grown 16-fold since they were chosen (rows that were independent
  /// may become a poor choice while others stay well conditioned), rows are chosen again and kept if they do
  /// better; the sign of det of the new rows is related to the old ones' at this pose, where both are
  /// regular, so determinant_sign() keeps its meaning for the continuation. Where their LU is singular, false:
  /// the COD takes the pose (and factor() asks for new rows if the system has rank n there).
  bool factor_selected_rows(int rows);

  /// The LU of the selected rows; true (and active) if regular.
  bool lu_of_selected_rows();

  /// The first n column pivots of the column-pivoted QR of the transposed scaled Jacobian (first `rows`
  /// rows), in increasing order; false if its rank is below n.
  bool choose_selected_rows(int rows);

  /// Sparse LU of the independent rows among the first `rows` (chosen at the first pose, again after a
  /// pose where their LU failed while the system had rank n, see factor()). False when the dense decomposition must do
  /// this pose, and always for a scalar without a sparse back end (NoSparseFactors: resolve() never gives
  /// it a sparse method, and the body is compiled for double only).
  bool factor_sparse(int rows);

  /// The first `rows` rows of the scaled Jacobian of the unknowns as a sparse matrix (from kin's nonzeros).
  Eigen::SparseMatrix<S> scaled_sparse_jacobian(int rows) const;

  /// ju from kin's nonzeros, for the COD at a pose the sparse LU cannot take (allocated at the first).
  void fill_ju_from_sparse();
};

/// Max-norm of a vector whose entries are multiplied by weight (the inverse of their scales).
template <class S, class A, class B> S weighted_max_norm(const A& v, const B& weight) {
  using std::abs;
  using std::max;
  S n(0);
  for (Eigen::Index i = 0; i < v.size(); ++i) n = max(n, S(abs(v(i)) * weight(i)));
  return n;
}

// SolveData for one scalar S, after KEYWORD (`extern template` or `template`), as the entry-point lists of
// solve/position.hpp. The members' bodies are in solve/solve_data.hxx.
#define ROLLKIN_SOLVE_DATA_INSTANCES(KEYWORD, S) KEYWORD struct SolveData<S>;

// Compiled once for double, in src/solve/instantiate_double.cpp.
ROLLKIN_SOLVE_DATA_INSTANCES(extern template, double)

}  // namespace rollkin
