// The result table of a solved sweep: one column per quantity (the input, every other pair variable, the
// rates, every link's world pose, the contact analysis, the residual) and one status per pose. The CLI's
// --csv writes it (SweepTable::csv()); the Python module (python/) hands the same columns to NumPy
// (sweep_columns), so both give the same names and values by construction.
//
//   const io::SweepOutput out{scene, sweep, result, sweep_values(sweep)};
//   const io::SweepTable table = io::sweep_table(out, /*rates=*/false);
//   std::string text = table.csv();
#pragma once

#include "rollkin/io/output_set.hpp"
#include "rollkin/io/scene/reader.hpp"
#include "rollkin/output/sweep_rows.hpp"
#include "rollkin/io/units.hpp"
#include "rollkin/solve/continuation.hpp"

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace rollkin::io {

/// Outputs give angles in degrees, whatever the scene file's angle unit.
constexpr AngleUnit kOutputAngle = AngleUnit::Degree;

/// Output units per internal unit of variable `var`: degrees per radian for angles, 1 otherwise (lengths stay
/// in scene units).
double output_scale(const Mechanism<double>& m, int var);

/// The contact pairs (cam and rolling) in pair order: the order of the analysis columns.
std::vector<int> contact_pairs(const Mechanism<double>& m);

/// A solved sweep with what the outputs need to present it.
struct SweepOutput {
  const Scene& scene;
  const Sweep& sweep;
  SweepRows result;  // in memory (SweepResult) or in a file (SweepFile)
  const std::vector<double>& inputs;  // requested input values in the file's units (one per pose)
  // Adds the contact analysis columns (docs/analysis.md). Each pose is analysed as its row is built, by the
  // thread that builds it, and not kept (kept, the analyses take about 1 KB per pose: 150 MB for 150,001
  // poses of the paper example).
  bool analysis = false;
};

/// The unit of the input column: degrees for an angle, the scene's length unit for a length, "" otherwise.
std::string input_column_unit(const SweepOutput& out);

/// The value of the input column of row r (output units: degrees for an angle).
double input_column(const SweepOutput& out, std::size_t r);

/// Numeric columns (each one value per pose, in the sweep's requested order) and a status per pose.
struct SweepTable {
  std::vector<std::string> names;            // numeric columns, in output order
  std::vector<std::vector<double>> columns;  // columns[c][r]: column c at pose r; NaN where not solved
  std::string status_name = "status";
  std::vector<std::string> status;           // "ok", "singular", "dead_point", ... (to_string(SolveStatus))

  std::size_t rows() const { return status.size(); }
  /// The table as CSV text (io/csv.hpp): header, then one row per pose, the status last.
  std::string csv() const;
};

/// The same numbers by column, and each row's status as its code: what the Python module hands to NumPy.
/// The columns lie one after the other in one block (column c at pose r: values[c * rows() + r]), made in
/// one allocation and written once (no zero fill): the block becomes the memory of every column's array as
/// it is, without a copy; the statuses become an array of str once, not one string per row.
struct SweepColumns {
  std::vector<std::string> names;    // as SweepTable::names
  std::unique_ptr<double[]> values;  // names.size() columns of rows() values each; NaN where not solved
  std::vector<SolveStatus> status;   // per row

  std::size_t rows() const { return status.size(); }
  const double* column(std::size_t c) const { return values.get() + c * rows(); }
};

/// Columns: the input, every other pair variable, (rates) d(var)/d(input) per unknown, every link's
/// <link>.x, <link>.y, <link>.angle, (out.analysis) per cam or rolling pair P the columns P.pressure_angle,
/// P.sliding, P.slide_to_roll, P.kappa1, P.kappa2, P.relative_curvature, per moving link <link>.accel and
/// <link>.jerk, per unknown v d2(v)/d(input)2 and d3(v)/d(input)3 (docs/analysis.md), residual; then the
/// status. Angles in degrees, lengths in scene units, rates per input unit. A pose without values (not
/// solved) has NaN in every numeric column.
SweepTable sweep_table(const SweepOutput& out, bool rates);

/// The table of sweep_table (the same names and numbers) with the statuses as codes.
SweepColumns sweep_columns(const SweepOutput& out, bool rates);

/// The same table as CSV text (SweepTable::csv(), identical bytes) streamed row by row into `sink` (the
/// CLI's --csv): no column of the table is held in memory. With `threads` other than 1 (0: one per core) the
/// rows are built (poses analysed) and formatted by that many threads, a block of rows each at a time, and
/// written in row order: the same bytes, with at most two blocks per thread of text held.
void write_sweep_csv(const SweepOutput& out, bool rates, OutputSink& sink, int threads = 1);

}  // namespace rollkin::io
