// A sweep whose poses are kept in a temporary file rather than in memory: what `rollkin solve` writes its
// outputs from, so that its memory does not grow with the number of poses (docs/benchmark.md, "Outputs at
// any size"). The continuation reports into it (sweep_into, continuation.hpp) as into a SweepResult; each
// pose's row (variables, rates and the report's numbers, 16 n + 32 bytes for n variables) is written at its
// place in the requested order, so the file reads back in row order whichever way the sweep ran. What a
// report needs of every pose (its status, the limits, the singular poses, the largest residual) stays in
// memory as the sweep's SweepSummary. The file is unlinked from the start: nothing is left behind, whatever
// ends the run.
//
//   io::SweepFile file(assembly, inputs, m.variable_count());
//   io::sweep_to_file(m, sd, q, assembly, driver, inputs, {}, file);
//   SweepResult<double> block;
//   file.read(first, count, block);  // rows first .. first + count - 1 as a SweepResult of count poses
#pragma once

#include "rollkin/solve/continuation.hpp"
#include "rollkin/solve/sweep_summary.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rollkin::io {

class SweepFile : public SweepSummary<double>, public SweepSink<double> {
 public:
  /// Keeps every pose's values (in the file): the continuation solves each requested input.
  static constexpr bool holds_values = true;

  /// Room for one row per input (`inputs` must outlive the file). Creates the file in $TMPDIR (else /tmp),
  /// unlinked; refuses up front, naming the directory and the bytes needed, when its file system has no room.
  SweepFile(const SolveReport<double>& assembly, const std::vector<double>& inputs, int variables);
  ~SweepFile();
  SweepFile(const SweepFile&) = delete;
  SweepFile& operator=(const SweepFile&) = delete;

  // What the continuation reports (sweep_into, solve/continuation.hpp), as into a SweepResult.
  bool keeps_values() const override { return true; }
  void add_limit(const SolveReport<double>& limit) override { limits.push_back(limit); }
  void set_pose(std::size_t k, const VectorX<double>& q, const VectorX<double>& qdot, const SolveReport<double>& rep) override {
    double* row = writable_row(k);
    for (int i = 0; i < variables_; ++i) row[i] = q(i);
    for (int i = 0; i < variables_; ++i) row[variables_ + i] = qdot(i);
    record_report(k, rep);
  }
  void set_report(std::size_t k, const SolveReport<double>& rep) override;
  void share_report(std::size_t k, std::size_t like) override;
  /// Never called: a sink that keeps values is given solved poses only.
  void set_interpolated_pose(std::size_t k, const VectorX<double>& q, const SolveReport<double>& rep) override;

  /// Writes what is still buffered; read() may be called from any thread after it.
  void finish();

  std::size_t size() const { return status.size(); }
  double input(std::size_t k) const { return (*inputs_)[k]; }
  /// Rows first .. first + count - 1 into `block` as a SweepResult of `count` poses (block pose j is row
  /// first + j; columns of rows without values are zero, as sweep() leaves them).
  void read(std::size_t first, std::size_t count, SweepResult<double>& block) const;
  /// The bytes of one row in the file.
  std::size_t row_bytes() const { return row_bytes_; }

 private:
  /// The numbers of a report kept beside a row's values (a SweepResult's record); `full` indexes the
  /// reports that say more (limits, singular poses), from 1 (0: none).
  struct Record {
    double residual, condition;
    std::int32_t iterations, evaluations, rank, full;
  };
  double* writable_row(std::size_t k);
  void record_report(std::size_t k, const SolveReport<double>& rep);
  void flush();
  Record record_of(std::size_t k) const;
  void read_bytes(char* to, std::size_t bytes, std::size_t at) const;

  const std::vector<double>* inputs_;
  int variables_;
  std::size_t row_bytes_;
  int fd_ = -1;
  std::string dir_;
  // The rows being written: a window of rows [window_, window_ + kWindowRows) of which [dirty_lo_, dirty_hi_)
  // are filled; moved to the next rows in the direction the continuation goes (up or down), so each side of
  // the sweep is written in large sequential blocks.
  static constexpr std::size_t kWindowRows = 4096;
  std::vector<char> buffer_;
  std::size_t window_ = 0, dirty_lo_ = 0, dirty_hi_ = 0, last_ = 0;
  std::vector<SolveReport<double>> full_;  // reports that do not fit a Record
  std::size_t shared_row_ = SIZE_MAX;      // the last row share_report() copied from, and its full index
  std::int32_t shared_full_ = 0;
};

/// sweep_into() (continuation.hpp) for double into a SweepFile, compiled once (src/output/sweep_file.cpp); then
/// finish().
void sweep_to_file(const Mechanism<double>& m, SolveData<double>& sd, const VectorX<double>& q0,
                   const SolveReport<double>& assembly, int driver, const std::vector<double>& inputs,
                   const ContinuationSettings<double>& cfg, SweepFile& out);

}  // namespace rollkin::io
