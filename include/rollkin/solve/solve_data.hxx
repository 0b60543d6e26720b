// The bodies of SolveData's members (declared in solve/solve_data.hpp), for the translation units that compile
// them (solve/position.hxx).
#pragma once

#include "rollkin/solve/solve_data.hpp"

namespace rollkin {

template <class S>
SolveData<S>::SolveData(const Mechanism<S>& m, Factorisation how)
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

template <class S> Factorisation SolveData<S>::resolve(const Mechanism<S>& m, Factorisation how) {
  if (!sparse_factorisation_available<S> || m.unknowns.empty()) return Factorisation::Dense;
  if (how == Factorisation::Automatic)
    return static_cast<int>(m.unknowns.size()) >= sparse_threshold ? default_sparse_factorisation()
                                                                    : Factorisation::Dense;
  if (how == Factorisation::Klu && !klu_available) return Factorisation::EigenSparseLU;
  return how;
}

template <class S> void SolveData<S>::factor(int rows) {
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

template <class S> int SolveData<S>::determinant_sign() const {
  if (lu_active) return lu.determinant_sign() * (lu_on_selected_rows_ ? selected_sign_offset_ : 1);
  if constexpr (sparse_factorisation_available<S>)
    if (sparse_active) return sparse_lu.determinant_sign();
  return 0;
}

template <class S> S SolveData<S>::error_bound(const S& residual, int rows) const {
  using std::max;
  const bool square = rows == static_cast<int>(unknowns.size());
  return condition * (square ? residual : max(square_residual(), epsilon<S>()));
}

template <class S> S SolveData<S>::square_residual() const {
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

template <class S> std::size_t SolveData<S>::bytes() const {
  const auto count = [](const auto& v) { return static_cast<std::size_t>(v.size()) * sizeof(S); };
  std::size_t b = count(kin.residual) + count(kin.jacobian) + count(kin.jacobian_values) + count(kin.bias) +
                  count(kin.reference) + kin.pattern.row.size() * 2 * sizeof(int) +
                  kin.pairs.size() * sizeof(PairState<S>) + kin.spatial.size() * sizeof(Twist<S>) +
                  count(row_scale) * 2 + count(col_scale) + count(ju) + count(rhs) + count(step) +
                  static_cast<std::size_t>(lu.size() * lu.size() + cod.rows() * cod.cols()) * sizeof(S);
  if constexpr (sparse_factorisation_available<S>) b += sparse_lu.bytes();
  return b;
}

template <class S> bool SolveData<S>::accept_lu(bool nonzero_pivots) {
  const auto n = static_cast<int>(unknowns.size());
  const S& largest = lu.largest_pivot();
  const S& smallest = lu.smallest_pivot();
  if (!nonzero_pivots || !(smallest > largest * epsilon<S>() * S(n))) return false;
  lu_active = true;
  rank = n;
  condition = largest / smallest;
  return true;
}

template <class S> bool SolveData<S>::factor_selected_rows(int rows) {
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

template <class S> bool SolveData<S>::lu_of_selected_rows() {
  lu_on_selected_rows_ = accept_lu(lu.compute([this](Eigen::Index r, Eigen::Index c) {
    return scaled_jacobian(selected_rows_[static_cast<std::size_t>(r)], c);
  }));
  return lu_on_selected_rows_;
}

template <class S> bool SolveData<S>::choose_selected_rows(int rows) {
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

template <class S> bool SolveData<S>::factor_sparse(int rows) {
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

template <class S> Eigen::SparseMatrix<S> SolveData<S>::scaled_sparse_jacobian(int rows) const {
  std::vector<Eigen::Triplet<S>> t;
  for (int e = 0; e < kin.pattern.size(); ++e) {
    const int r = kin.pattern.row[e], c = unknown_of_variable_[static_cast<std::size_t>(kin.pattern.column[e])];
    if (r < rows && c >= 0) t.emplace_back(r, c, kin.jacobian_values(e) * row_weight(r) * col_scale(c));
  }
  Eigen::SparseMatrix<S> a(rows, static_cast<Eigen::Index>(unknowns.size()));
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

template <class S> void SolveData<S>::fill_ju_from_sparse() {
  ju.setZero(row_scale.size(), static_cast<Eigen::Index>(unknowns.size()));
  for (int e = 0; e < kin.pattern.size(); ++e) {
    const int r = kin.pattern.row[e], c = unknown_of_variable_[static_cast<std::size_t>(kin.pattern.column[e])];
    if (c >= 0) ju(r, c) += kin.jacobian_values(e) * row_weight(r) * col_scale(c);
  }
}

}  // namespace rollkin
