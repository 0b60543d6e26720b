// independent_rows (include/rollkin/solve/sparse_lu.hpp): the one translation unit that compiles Eigen's
// SparseQR, apart from the sparse LU so that the two build in parallel.
#include "rollkin/solve/sparse_lu.hpp"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseQR>

#include <algorithm>

namespace rollkin {

std::vector<int> independent_rows(const Eigen::SparseMatrix<double>& a) {
  Eigen::SparseMatrix<double> at = a.transpose();
  at.makeCompressed();
  Eigen::SparseQR<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> qr(at);
  std::vector<int> rows;
  if (qr.info() != Eigen::Success) return rows;
  for (Eigen::Index k = 0; k < qr.rank(); ++k) rows.push_back(qr.colsPermutation().indices()(k));
  std::sort(rows.begin(), rows.end());
  return rows;
}

}  // namespace rollkin
