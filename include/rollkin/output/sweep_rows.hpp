// The rows of a solved sweep as the outputs read them, wherever the poses are kept: a SweepResult in memory
// (the Python module, --interference, --verbose) or a SweepFile (`rollkin solve`'s files: memory that does not
// grow with the number of poses). Statuses and inputs are at hand for every row; values are read through a
// RowReader, which holds one block of rows at a time (a view into the SweepResult when in memory).
//
//   io::RowReader rows(out.result);
//   for (std::size_t r = 0; r < out.result.size(); ++r)
//     if (out.result.has_pose(r)) use(rows.q(r), rows.qdot(r));  // views valid until the next call
#pragma once

#include "rollkin/output/sweep_file.hpp"
#include "rollkin/solve/sweep_result.hpp"

#include <cstddef>

namespace rollkin::io {

class SweepRows {
 public:
  SweepRows(const SweepResult<double>& r) : memory_(&r) {}  // NOLINT: implicit, as the outputs took a result
  SweepRows(const SweepFile& f) : file_(&f) {}              // NOLINT

  std::size_t size() const { return memory_ ? memory_->size() : file_->size(); }
  double input(std::size_t k) const { return memory_ ? memory_->input(k) : file_->input(k); }
  SolveStatus status(std::size_t k) const { return memory_ ? memory_->status(k) : file_->status[k]; }
  /// Values are kept for the solved and the singular poses.
  bool has_pose(std::size_t k) const { return status(k) == SolveStatus::Converged || status(k) == SolveStatus::Singular; }
  /// The result when the rows are in memory, else nullptr.
  const SweepResult<double>* in_memory() const { return memory_; }
  const SweepFile* file() const { return file_; }

 private:
  const SweepResult<double>* memory_ = nullptr;
  const SweepFile* file_ = nullptr;
};

/// Reads rows' values: in memory, views of the result; from a file, a block of `block_rows` rows at a time
/// around the row asked for (reading in row order reads the file once). Views are valid until the next call.
/// One reader per thread.
class RowReader {
 public:
  explicit RowReader(const SweepRows& rows, std::size_t block_rows = 1024) : rows_(rows), block_rows_(block_rows) {}

  PoseColumn<double> q(std::size_t r) { return block(r).q(r - first_); }
  PoseColumn<double> qdot(std::size_t r) { return block(r).qdot(r - first_); }
  double residual(std::size_t r) { return block(r).residual(r - first_); }
  /// Row r's link poses and angles when the result keeps them (in memory, ContinuationSettings::link_poses),
  /// else nullptr.
  const SE2<double>* link_poses(std::size_t r) { return block(r).link_poses(r - first_); }
  const double* link_angles(std::size_t r) { return block(r).link_angles(r - first_); }

 private:
  const SweepResult<double>& block(std::size_t r) {
    if (const SweepResult<double>* all = rows_.in_memory()) return *all;
    if (r < first_ || r >= first_ + block_.size()) {
      first_ = r / block_rows_ * block_rows_;
      rows_.file()->read(first_, block_rows_, block_);
    }
    return block_;
  }

  SweepRows rows_;
  std::size_t block_rows_, first_ = 0;  // in memory first_ stays 0: row r is the result's pose r
  SweepResult<double> block_;
};

}  // namespace rollkin::io
