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

  explicit SolveData(const Mechanism<S>& m, Factorisation how = Factorisation::Automatic)
      : method(resolve(m, how)),
        kin(m, method != Factorisation::Dense),
        row_scale(m.equation_count()),
        col_scale(m.unknowns.size()),
        row_weight(m.equation_count()),
        ju(sparse() ? 0 : m.equation_count(), sparse() ? 0 : m.unknowns.size()),
        unknowns(m.unknowns),
        rhs(m.equation_count()),
        step(m.unknowns.size()),
        lu(sparse() ? 0 : m.unknowns.size()),
        cod(sparse() ? 0 : m.equation_count(), sparse() ? 0 : m.unknowns.size()),
        unknown_of_variable_(static_cast<std::size_t>(m.variable_count()), -1) {
    int row = 0;
    for (std::size_t l = 0; l < m.loops.size(); ++l, row += 3) {
      row_scale(row) = m.length_scale;
      row_scale(row + 1) = m.length_scale;
      row_scale(row + 2) = S(1);
    }
    for (; row < m.equation_count(); ++row) row_scale(row) = m.length_scale;
    row_weight = row_scale.cwiseInverse();
    for (std::size_t c = 0; c < m.unknowns.size(); ++c) {
      col_scale(c) = m.variable_scale(m.unknowns[c]);
      unknown_of_variable_[static_cast<std::size_t>(m.unknowns[c])] = static_cast<int>(c);
    }
    using std::max;
    settings.consistency_tolerance =
        max(settings.consistency_tolerance, S(S(16) * m.representation_error / m.length_scale));
  }

  /// The factorisation `how` asks for, with Automatic and the sparse back ends resolved for this mechanism
  /// and scalar (a sparse request for a scalar other than double gives Dense; Klu without KLU, Eigen's).
  static Factorisation resolve(const Mechanism<S>& m, Factorisation how) {
    if (!sparse_factorisation_available<S> || m.unknowns.empty()) return Factorisation::Dense;
    if (how == Factorisation::Automatic)
      return static_cast<int>(m.unknowns.size()) >= sparse_threshold ? default_sparse_factorisation()
                                                                      : Factorisation::Dense;
    if (how == Factorisation::Klu && !klu_available) return Factorisation::EigenSparseLU;
    return how;
  }
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
  void factor(int rows) {
    using std::abs;
    const auto n = static_cast<Eigen::Index>(unknowns.size());
    lu_active = sparse_active = lu_on_selected_rows_ = false;
    if (n == 0) {  // nothing to solve (every pair variable is an input): forward kinematics only
      rank = 0;
      condition = S(1);
      return;
    }
    if (sparse()) {
      if constexpr (sparse_factorisation_available<S>) {
        if (factor_sparse(rows)) return;
      }
      fill_ju_from_sparse();
    } else if (rows == n) {
      if (accept_lu(lu.compute([this](Eigen::Index r, Eigen::Index c) { return scaled_jacobian(r, c); }))) return;
    } else if (factor_selected_rows(rows)) {
      return;
    }
    if (!sparse())
      for (Eigen::Index c = 0; c < n; ++c)
        for (Eigen::Index r = 0; r < ju.rows(); ++r) ju(r, c) = scaled_jacobian(r, c);
    if (rows == ju.rows()) cod.compute(ju);
    else cod.compute(ju.topRows(rows));
    rank = static_cast<int>(cod.rank());
    condition = rank < n || rank == 0 ? std::numeric_limits<S>::infinity()
                                      : S(abs(cod.matrixQTZ()(0, 0)) / abs(cod.matrixQTZ()(n - 1, n - 1)));
    // The system has rank n here although the LU of the chosen independent rows failed: they were a poor
    // choice, so choose again at the next pose. Where the system itself is singular (a change point) the
    // rows are kept, and with them the meaning of the determinant's sign the continuation tracks.
    if (rank == n) selected_for_rows_ = selected_dense_for_ = -1;
  }
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
  int determinant_sign() const {
    if (lu_active) return lu.determinant_sign() * (lu_on_selected_rows_ ? selected_sign_offset_ : 1);
    if constexpr (sparse_factorisation_available<S>)
      if (sparse_active) return sparse_lu.determinant_sign();
    return 0;
  }

  /// The bound on the error of the unknowns at the pose just factored: the condition times the scaled
  /// residual of the square system the LU solves (`residual`, all rows, when `rows` is the number of
  /// unknowns; square_residual(), at least eps, with redundant rows: the few rows an LU solves can come out
  /// exactly zero at a change point, where the unknowns are anything but exact).
  S error_bound(const S& residual, int rows) const {
    using std::max;
    const bool square = rows == static_cast<int>(unknowns.size());
    return condition * (square ? residual : max(square_residual(), epsilon<S>()));
  }

  /// The scaled residual (max-norm) of the square system the active LU factors: all rows of a square
  /// system, the independent rows of a redundant one (dense or sparse). Its condition times this bounds the
  /// error of the unknowns, which the least-squares floor of redundant rows that disagree (sampled contours)
  /// would blur. Infinite when no LU is active (the COD: rank-deficient or singular here).
  S square_residual() const {
    using std::abs;
    using std::max;
    S worst(0);
    const auto row = [&](Eigen::Index r) { worst = max(worst, S(abs(kin.residual(r)) * row_weight(r))); };
    if (lu_on_selected_rows_) {
      for (Eigen::Index r : selected_rows_) row(r);
    } else if (lu_active) {
      for (Eigen::Index r = 0; r < static_cast<Eigen::Index>(unknowns.size()); ++r) row(r);
    } else if constexpr (sparse_factorisation_available<S>) {
      if (!sparse_active) return std::numeric_limits<S>::infinity();
      for (int r : sparse_lu.selected_rows()) row(r);
    } else {
      return std::numeric_limits<S>::infinity();
    }
    return worst;
  }

  /// Bytes of the solve buffers and factors (the mechanism itself not counted).
  std::size_t bytes() const {
    const auto count = [](const auto& v) { return static_cast<std::size_t>(v.size()) * sizeof(S); };
    std::size_t b = count(kin.residual) + count(kin.jacobian) + count(kin.jacobian_values) + count(kin.bias) +
                    count(kin.reference) + kin.pattern.row.size() * 2 * sizeof(int) +
                    kin.pairs.size() * sizeof(PairState<S>) + kin.spatial.size() * sizeof(Twist<S>) +
                    count(row_scale) * 2 + count(col_scale) + count(ju) + count(rhs) + count(step) +
                    static_cast<std::size_t>(lu.size() * lu.size() + cod.rows() * cod.cols()) * sizeof(S);
    if constexpr (sparse_factorisation_available<S>) b += sparse_lu.bytes();
    return b;
  }

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
  bool accept_lu(bool nonzero_pivots) {
    const auto n = static_cast<int>(unknowns.size());
    const S& largest = lu.largest_pivot();
    const S& smallest = lu.smallest_pivot();
    if (!nonzero_pivots || !(smallest > largest * epsilon<S>() * S(n))) return false;
    lu_active = true;
    rank = n;
    condition = largest / smallest;
    return true;
  }

  /// A dense system with more rows than unknowns (redundant constraints): the LU of n independent rows among
  /// the first `rows`, chosen by a column-pivoted QR of the transposed Jacobian (its first n pivots) at the
  /// first pose. Where their pivot ratio has grown 16-fold since they were chosen (rows that were independent
  /// may become a poor choice while others stay well conditioned), rows are chosen again and kept if they do
  /// better; the sign of det of the new rows is related to the old ones' at this pose, where both are
  /// regular, so determinant_sign() keeps its meaning for the continuation. Where their LU is singular, false:
  /// the COD takes the pose (and factor() asks for new rows if the system has rank n there).
  bool factor_selected_rows(int rows) {
    const auto n = static_cast<Eigen::Index>(unknowns.size());
    if (rows < n) return false;
    if (selected_dense_for_ != rows) {
      if (choose_selected_rows(rows) && lu_of_selected_rows()) {
        selected_condition_ = condition;
        return true;
      }
      selected_dense_for_ = -1;
      return false;
    }
    if (!lu_of_selected_rows()) return false;
    if (!(condition > S(16) * selected_condition_)) return true;
    const int old_sign = lu.determinant_sign();
    const S old_condition = condition;
    kept_rows_ = selected_rows_;
    if (choose_selected_rows(rows) && lu_of_selected_rows() && condition < old_condition) {
      selected_sign_offset_ *= old_sign * lu.determinant_sign();
      selected_condition_ = condition;
      return true;
    }
    selected_rows_.swap(kept_rows_);  // no better rows here: the old ones, factored again
    selected_dense_for_ = rows;
    selected_condition_ = old_condition;  // not asked again before a further 16-fold growth
    return lu_of_selected_rows();
  }

  /// The LU of the selected rows; true (and active) if regular.
  bool lu_of_selected_rows() {
    lu_on_selected_rows_ = accept_lu(lu.compute([this](Eigen::Index r, Eigen::Index c) {
      return scaled_jacobian(selected_rows_[static_cast<std::size_t>(r)], c);
    }));
    return lu_on_selected_rows_;
  }

  /// The first n column pivots of the column-pivoted QR of the transposed scaled Jacobian (first `rows`
  /// rows), in increasing order; false if its rank is below n.
  bool choose_selected_rows(int rows) {
    const auto n = static_cast<Eigen::Index>(unknowns.size());
    MatrixX<S> transposed(n, rows);
    for (Eigen::Index r = 0; r < rows; ++r)
      for (Eigen::Index c = 0; c < n; ++c) transposed(c, r) = scaled_jacobian(r, c);
    const Eigen::ColPivHouseholderQR<MatrixX<S>> qr(transposed);
    if (qr.rank() < n) return false;
    selected_rows_.resize(static_cast<std::size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i) selected_rows_[static_cast<std::size_t>(i)] = qr.colsPermutation().indices()(i);
    std::sort(selected_rows_.begin(), selected_rows_.end());
    selected_rhs_.resize(n);
    selected_dense_for_ = rows;
    return true;
  }

  /// Sparse LU of the independent rows among the first `rows` (chosen at the first pose, again after a
  /// pose where their LU failed while the system had rank n, see factor()). False when the dense decomposition must do
  /// this pose, and always for a scalar without a sparse back end (NoSparseFactors: resolve() never gives
  /// it a sparse method, and the body below is compiled for double only).
  bool factor_sparse(int rows) {
    if constexpr (!sparse_factorisation_available<S>) {
      static_cast<void>(rows);
      return false;
    } else {
      const auto n = static_cast<int>(unknowns.size());
      if (rows < n) return false;
      if (!sparse_lu.ready() || selected_for_rows_ != rows) {
        std::vector<int> selected(static_cast<std::size_t>(rows));
        for (int r = 0; r < rows; ++r) selected[static_cast<std::size_t>(r)] = r;
        if (rows > n) selected = independent_rows(scaled_sparse_jacobian(rows));
        // Rank deficient here: the COD's minimum-norm step.
        if (static_cast<int>(selected.size()) < n) return false;
        sparse_lu.setup(kin.pattern, unknown_of_variable_, selected, row_weight, col_scale, method);
        selected_for_rows_ = rows;
      }
      const bool ok = sparse_lu.factor(kin.jacobian_values);
      const double largest = sparse_lu.largest_pivot(), smallest = sparse_lu.smallest_pivot();
      const double singular_condition = 1 / (epsilon<double>() * n);
      const double estimate = ok ? std::max(largest / smallest, sparse_lu.condition_estimate()) : 0.0;
      if (!ok || !(estimate < singular_condition)) {
        return false;  // singular here: the COD takes this pose (factor() chooses the rows again if it has rank n)
      }
      sparse_active = true;
      rank = n;
      condition = estimate;
      return true;
    }
  }

  /// The first `rows` rows of the scaled Jacobian of the unknowns as a sparse matrix (from kin's nonzeros).
  Eigen::SparseMatrix<S> scaled_sparse_jacobian(int rows) const {
    std::vector<Eigen::Triplet<S>> t;
    for (int e = 0; e < kin.pattern.size(); ++e) {
      const int r = kin.pattern.row[e], c = unknown_of_variable_[static_cast<std::size_t>(kin.pattern.column[e])];
      if (r < rows && c >= 0) t.emplace_back(r, c, kin.jacobian_values(e) * row_weight(r) * col_scale(c));
    }
    Eigen::SparseMatrix<S> a(rows, static_cast<Eigen::Index>(unknowns.size()));
    a.setFromTriplets(t.begin(), t.end());
    return a;
  }

  /// ju from kin's nonzeros, for the COD at a pose the sparse LU cannot take (allocated at the first).
  void fill_ju_from_sparse() {
    ju.setZero(row_scale.size(), static_cast<Eigen::Index>(unknowns.size()));
    for (int e = 0; e < kin.pattern.size(); ++e) {
      const int r = kin.pattern.row[e], c = unknown_of_variable_[static_cast<std::size_t>(kin.pattern.column[e])];
      if (c >= 0) ju(r, c) += kin.jacobian_values(e) * row_weight(r) * col_scale(c);
    }
  }
};

/// Max-norm of a vector whose entries are multiplied by weight (the inverse of their scales).
template <class S, class A, class B> S weighted_max_norm(const A& v, const B& weight) {
  using std::abs;
  using std::max;
  S n(0);
  for (Eigen::Index i = 0; i < v.size(); ++i) n = max(n, S(abs(v(i)) * weight(i)));
  return n;
}

}  // namespace rollkin
