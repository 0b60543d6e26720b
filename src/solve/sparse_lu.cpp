// The sparse LU of the unknowns and the search for independent rows (include/rollkin/solve/sparse_lu.hpp):
// the only translation unit that compiles Eigen's SparseLU and calls KLU (SparseQR: independent_rows.cpp).
#include "rollkin/solve/sparse_lu.hpp"

#include "rollkin/kinematics.hpp"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#if ROLLKIN_HAVE_KLU
#include <klu.h>
#endif

namespace rollkin {

/// The matrix, its value map and the factors of one setup; destroying it frees KLU's memory.
struct SparseUnknownsLU::State {
  struct Entry {
    int entry;     // index in the pattern
    int slot;      // index in matrix's values
    double scale;  // row weight x column scale
  };

  Factorisation backend = Factorisation::EigenSparseLU;
  int n = 0;
  std::vector<int> selected;
  std::vector<Entry> entries;
  Eigen::SparseMatrix<double> matrix;
  VectorX<double> rhs, row_sum;
  std::vector<char> visited;
  double largest = 0, smallest = 0;
  int sign = 0;
  bool factored = false;
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> eigen_lu;
#if ROLLKIN_HAVE_KLU
  klu_common common{};
  klu_symbolic* symbolic = nullptr;
  klu_numeric* numeric = nullptr;
  double fresh_ratio = 0;
#endif

  State() = default;
  State(const State&) = delete;
  State& operator=(const State&) = delete;
  ~State() {
#if ROLLKIN_HAVE_KLU
    if (numeric) klu_free_numeric(&numeric, &common);
    if (symbolic) klu_free_symbolic(&symbolic, &common);
#endif
  }

  /// rhs = A^-1 rhs.
  void solve_in_place() {
#if ROLLKIN_HAVE_KLU
    if (backend == Factorisation::Klu) {
      klu_solve(symbolic, numeric, n, 1, rhs.data(), &common);
      return;
    }
#endif
    rhs = eigen_lu.solve(rhs).eval();
  }

  bool factor_eigen() {
    eigen_lu.factorize(matrix);
    factored = eigen_lu.info() == Eigen::Success;
    if (!factored) return false;
    // The diagonal of U sits in the supernodes of L (as in SparseLU::signDeterminant).
    const auto& l = eigen_lu.matrixL().m_mapL;
    largest = 0;
    smallest = std::numeric_limits<double>::infinity();
    for (Eigen::Index j = 0; j < n; ++j)
      for (typename std::decay_t<decltype(l)>::InnerIterator it(l, j); it; ++it)
        if (it.index() == j) {
          largest = std::max(largest, std::abs(it.value()));
          smallest = std::min(smallest, std::abs(it.value()));
          break;
        }
    sign = static_cast<int>(eigen_lu.signDeterminant());
    return smallest > 0;
  }

#if ROLLKIN_HAVE_KLU
  /// Refactors with the previous pivot order (no search: cheapest), and factors afresh (partial pivoting)
  /// the first time, after a breakdown, or when the pivot ratio fell by 100 against the last fresh factors
  /// (the old pivots may have become poor ones).
  bool factor_klu() {
    if (numeric && klu_refactor(matrix.outerIndexPtr(), matrix.innerIndexPtr(), matrix.valuePtr(), symbolic, numeric,
                                &common) &&
        pivots_klu() && smallest / largest >= fresh_ratio / 100)
      return true;
    if (numeric) klu_free_numeric(&numeric, &common);
    numeric = klu_factor(matrix.outerIndexPtr(), matrix.innerIndexPtr(), matrix.valuePtr(), symbolic, &common);
    if (!numeric || !pivots_klu()) return false;
    fresh_ratio = smallest / largest;
    return true;
  }

  /// Pivot extremes and det sign of P R^-1 A Q = L U: sign(P) sign(Q) prod sign(u_ii) (R > 0 scales rows).
  bool pivots_klu() {
    const double* u = static_cast<const double*>(numeric->Udiag);
    largest = 0;
    smallest = std::numeric_limits<double>::infinity();
    int s = 1;
    for (int i = 0; i < n; ++i) {
      largest = std::max(largest, std::abs(u[i]));
      smallest = std::min(smallest, std::abs(u[i]));
      if (u[i] < 0) s = -s;
    }
    sign = s * permutation_sign(numeric->Pnum) * permutation_sign(symbolic->Q);
    return smallest > 0 && smallest == smallest;
  }
#endif

  /// (-1)^(n - cycles) of a permutation of 0..n-1.
  int permutation_sign(const int* p) {
    std::fill(visited.begin(), visited.end(), 0);
    int cycles = 0;
    for (int i = 0; i < n; ++i) {
      if (visited[static_cast<std::size_t>(i)]) continue;
      ++cycles;
      for (int j = i; !visited[static_cast<std::size_t>(j)]; j = p[j]) visited[static_cast<std::size_t>(j)] = 1;
    }
    return (n - cycles) % 2 ? -1 : 1;
  }
};

SparseUnknownsLU::SparseUnknownsLU() = default;
SparseUnknownsLU::SparseUnknownsLU(const SparseUnknownsLU&) {}
SparseUnknownsLU& SparseUnknownsLU::operator=(const SparseUnknownsLU& other) {
  if (this != &other) state_.reset();
  return *this;
}
SparseUnknownsLU::SparseUnknownsLU(SparseUnknownsLU&&) noexcept = default;
SparseUnknownsLU& SparseUnknownsLU::operator=(SparseUnknownsLU&&) noexcept = default;
SparseUnknownsLU::~SparseUnknownsLU() = default;

void SparseUnknownsLU::setup(const JacobianPattern& pattern, const std::vector<int>& unknown_of_variable,
                             const std::vector<int>& selected, const VectorX<double>& row_weight,
                             const VectorX<double>& col_scale, Factorisation backend) {
  state_ = std::make_unique<State>();
  State& s = *state_;
  s.backend = backend;
  s.n = static_cast<int>(selected.size());
  s.selected = selected;
  std::vector<int> local_row(static_cast<std::size_t>(row_weight.size()), -1);
  for (int i = 0; i < s.n; ++i) local_row[static_cast<std::size_t>(selected[static_cast<std::size_t>(i)])] = i;
  std::vector<Eigen::Triplet<double>> triplets;
  for (int e = 0; e < pattern.size(); ++e) {
    const int r = local_row[static_cast<std::size_t>(pattern.row[e])];
    const int c = unknown_of_variable[static_cast<std::size_t>(pattern.column[e])];
    if (r < 0 || c < 0) continue;
    triplets.emplace_back(r, c, 1.0);
    s.entries.push_back(State::Entry{e, 0, row_weight(pattern.row[e]) * col_scale(c)});
  }
  s.matrix.resize(s.n, s.n);
  s.matrix.setFromTriplets(triplets.begin(), triplets.end());
  s.matrix.makeCompressed();
  for (std::size_t k = 0; k < s.entries.size(); ++k) {  // slot of (r, c): binary search in column c
    const int r = triplets[k].row(), c = triplets[k].col();
    const int* begin = s.matrix.innerIndexPtr() + s.matrix.outerIndexPtr()[c];
    const int* end = s.matrix.innerIndexPtr() + s.matrix.outerIndexPtr()[c + 1];
    s.entries[k].slot = static_cast<int>(std::lower_bound(begin, end, r) - s.matrix.innerIndexPtr());
  }
  s.rhs.resize(s.n);
  s.row_sum.resize(s.n);
  s.visited.assign(static_cast<std::size_t>(s.n), 0);
#if ROLLKIN_HAVE_KLU
  if (s.backend == Factorisation::Klu) {
    klu_defaults(&s.common);
    s.symbolic = klu_analyze(s.n, s.matrix.outerIndexPtr(), s.matrix.innerIndexPtr(), &s.common);
    return;
  }
#endif
  s.backend = Factorisation::EigenSparseLU;
  s.eigen_lu.analyzePattern(s.matrix);
}

bool SparseUnknownsLU::ready() const { return state_ && state_->n > 0; }

const std::vector<int>& SparseUnknownsLU::selected_rows() const {
  static const std::vector<int> none;
  return state_ ? state_->selected : none;
}

bool SparseUnknownsLU::factor(const VectorX<double>& values) {
  State& s = *state_;
  double* v = s.matrix.valuePtr();
  std::fill(v, v + s.matrix.nonZeros(), 0.0);
  for (const State::Entry& e : s.entries) v[e.slot] += values(e.entry) * e.scale;
#if ROLLKIN_HAVE_KLU
  if (s.backend == Factorisation::Klu) return s.factor_klu();
#endif
  return s.factor_eigen();
}

void SparseUnknownsLU::solve(const Eigen::Ref<const VectorX<double>>& b, VectorX<double>& x) {
  State& s = *state_;
  for (int i = 0; i < s.n; ++i) s.rhs(i) = b(s.selected[static_cast<std::size_t>(i)]);
  s.solve_in_place();
  x = s.rhs;
}

double SparseUnknownsLU::largest_pivot() const { return state_ ? state_->largest : 0.0; }
double SparseUnknownsLU::smallest_pivot() const { return state_ ? state_->smallest : 0.0; }
int SparseUnknownsLU::determinant_sign() const { return state_ ? state_->sign : 0; }

double SparseUnknownsLU::condition_estimate() {
  State& s = *state_;
  s.row_sum.setZero();
  const double* v = s.matrix.valuePtr();
  const int* row = s.matrix.innerIndexPtr();
  for (Eigen::Index k = 0; k < s.matrix.nonZeros(); ++k) s.row_sum(row[k]) += std::abs(v[k]);
  std::uint32_t state = 0x9e3779b9u;
  for (int i = 0; i < s.n; ++i) {
    state = state * 1664525u + 1013904223u;  // linear congruential signs: fixed, so reproducible
    s.rhs(i) = (state >> 31) ? 1.0 : -1.0;
  }
  s.solve_in_place();
  return s.row_sum.maxCoeff() * s.rhs.cwiseAbs().maxCoeff();
}

std::size_t SparseUnknownsLU::bytes() const {
  if (!state_) return 0;
  const State& s = *state_;
  std::size_t b = static_cast<std::size_t>(s.matrix.nonZeros()) * (sizeof(double) + sizeof(int)) +
                  static_cast<std::size_t>(s.n + 1) * sizeof(int) + s.entries.size() * sizeof(State::Entry);
#if ROLLKIN_HAVE_KLU
  if (s.backend == Factorisation::Klu) return b + s.common.memusage;
#endif
  if (s.n > 0 && s.factored)
    b += static_cast<std::size_t>(s.eigen_lu.nnzL() + s.eigen_lu.nnzU()) * (sizeof(double) + sizeof(int));
  return b;
}

}  // namespace rollkin
