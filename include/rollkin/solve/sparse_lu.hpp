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
//
// The factorisations live in src/solve/sparse_lu.cpp behind SparseUnknownsLU's pointer to its state, so a
// caller of the solver parses neither Eigen's SparseLU and SparseQR nor KLU (they cost about 10 s of parsing
// in every translation unit that included them; docs/benchmark.md, "Build times").
#pragma once

#include "rollkin/kinematics.hpp"

#include <Eigen/SparseCore>

#include <cstddef>
#include <memory>
#include <type_traits>
#include <vector>

#ifndef ROLLKIN_HAVE_KLU
#define ROLLKIN_HAVE_KLU 0
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
std::vector<int> independent_rows(const Eigen::SparseMatrix<double>& a);

/// Square sparse LU of selected rows of the scaled Jacobian of the unknowns (double).
class SparseUnknownsLU {
 public:
  SparseUnknownsLU();
  // A copy holds no factors (they own KLU's memory): it is set up again at its first use (ready() false).
  SparseUnknownsLU(const SparseUnknownsLU&);
  SparseUnknownsLU& operator=(const SparseUnknownsLU& other);
  SparseUnknownsLU(SparseUnknownsLU&&) noexcept;
  SparseUnknownsLU& operator=(SparseUnknownsLU&&) noexcept;
  ~SparseUnknownsLU();

  /// Builds the matrix of the rows `selected` (equation indices, as many as unknowns) and the columns of
  /// the unknowns (unknown_of_variable: a variable's unknown column, -1 for a driver), the map from each
  /// pattern entry to its value slot and the per-entry scale R^-1 .. C, and analyses it symbolically.
  void setup(const JacobianPattern& pattern, const std::vector<int>& unknown_of_variable,
             const std::vector<int>& selected, const VectorX<double>& row_weight, const VectorX<double>& col_scale,
             Factorisation backend);

  bool ready() const;
  const std::vector<int>& selected_rows() const;

  /// Refills the values from the Jacobian's nonzeros (pattern order) and factors; false if the factors
  /// broke down (a zero pivot). Then largest_pivot / smallest_pivot and determinant_sign describe them.
  bool factor(const VectorX<double>& values);

  /// x = A^-1 b(selected rows).
  void solve(const Eigen::Ref<const VectorX<double>>& b, VectorX<double>& x);

  double largest_pivot() const;
  double smallest_pivot() const;

  /// The condition of the factored matrix A as the pivots cannot show it: ||A||_inf ||A^-1 b||_inf for a
  /// vector b of pseudo-random signs (one solve), a lower bound of cond_inf(A) that grows like 1/sigma_min
  /// unless b is orthogonal to the smallest singular direction. KLU's pivots (taken in the order of an
  /// earlier factorisation by klu_refactor, and spread over its block-triangular blocks) can all stay
  /// moderate at a singular matrix: at a parallelogram's change point their ratio read 8.7 where the dense
  /// LU's read 1.5e12.
  double condition_estimate();
  int determinant_sign() const;

  /// Bytes held: the matrix, the map, and the factors (KLU's own count; Eigen: the factors' nonzeros).
  std::size_t bytes() const;

 private:
  struct State;  // src/solve/sparse_lu.cpp
  std::unique_ptr<State> state_;
};

}  // namespace rollkin
