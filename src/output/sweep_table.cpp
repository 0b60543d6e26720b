// The result table of a solved sweep (rollkin/output/sweep_table.hpp): the CLI's --csv and the Python module's
// columns.
#include "rollkin/output/sweep_table.hpp"

#include "rollkin/analysis/motion.hpp"
#include "rollkin/io/csv.hpp"
#include "rollkin/solve/batch.hpp"

#include <algorithm>
#include <future>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

namespace rollkin::io {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

const char* const kContactColumns[] = {"pressure_angle", "sliding", "slide_to_roll", "kappa1", "kappa2", "relative_curvature"};
const std::size_t kContactColumnCount = sizeof(kContactColumns) / sizeof(kContactColumns[0]);

std::size_t analysis_column_count(const Mechanism<double>& m) {
  return contact_pairs(m).size() * kContactColumnCount + 2 * (m.links.size() - 1) + 2 * m.unknowns.size();
}

/// Analysis columns (docs/analysis.md): per contact pair P the P.<quantity> columns, per moving link
/// <link>.accel and <link>.jerk, per unknown v d2(v)/d(input)2 and d3(v)/d(input)3.
void analysis_columns(const Mechanism<double>& m, int input, std::vector<std::string>& cols) {
  for (int k : contact_pairs(m))
    for (const char* q : kContactColumns) cols.push_back(m.pairs[k].name + "." + q);
  for (const char* q : {".accel", ".jerk"})
    for (std::size_t l = 0; l < m.links.size(); ++l)
      if (static_cast<int>(l) != m.ground) cols.push_back(m.links[l].name + q);
  for (const char* order : {"2", "3"})
    for (int i : m.unknowns)
      cols.push_back(std::string("d") + order + "(" + m.variables[i].name + ")/d(" + m.variables[input].name + ")" + order);
}

/// The analysis of one pose in output units: pressure angle in degrees, sliding per unit of the input's
/// output unit (per degree for an angle input, like the rate columns), curvatures in 1/scene unit, angular
/// accelerations in degrees per input unit squared, jerks per input unit cubed.
template <class Row>
void analysis_values(const Mechanism<double>& m, const PoseAnalysis<double>& a, double in_scale, Row& row) {
  const double degrees = from_radians(1.0, kOutputAngle);
  for (const ContactAnalysis<double>& c : a.contacts) {
    row.push_back(c.pressure_angle * degrees);
    row.push_back(c.sliding / in_scale);
    row.push_back(c.slide_to_roll);
    row.push_back(c.kappa1);
    row.push_back(c.kappa2);
    row.push_back(c.relative_curvature);
  }
  for (std::size_t l = 0; l < m.links.size(); ++l)
    if (static_cast<int>(l) != m.ground) row.push_back(a.angular_acceleration[l] * degrees / (in_scale * in_scale));
  for (std::size_t l = 0; l < m.links.size(); ++l)
    if (static_cast<int>(l) != m.ground) row.push_back(a.angular_jerk[l] * degrees / (in_scale * in_scale * in_scale));
  for (int i : m.unknowns) row.push_back(a.qddot(i) * output_scale(m, i) / (in_scale * in_scale));
  for (int i : m.unknowns) row.push_back(a.qdddot(i) * output_scale(m, i) / (in_scale * in_scale * in_scale));
}

/// The column names, in output order (see sweep_table).
std::vector<std::string> column_names(const SweepOutput& out, bool rates, std::vector<int>& others) {
  const Mechanism<double>& m = out.scene.mechanism;
  const int input = out.sweep.variable;
  std::vector<std::string> cols{m.variables[input].name};
  for (int i = 0; i < m.variable_count(); ++i)
    if (i != input) {
      others.push_back(i);
      cols.push_back(m.variables[i].name);
    }
  if (rates)
    for (int i : m.unknowns) cols.push_back("d(" + m.variables[i].name + ")/d(" + m.variables[input].name + ")");
  for (const auto& l : m.links) {
    cols.push_back(l.name + ".x");
    cols.push_back(l.name + ".y");
    cols.push_back(l.name + ".angle");
  }
  if (out.analysis) analysis_columns(m, input, cols);
  cols.push_back("residual");
  return cols;
}

/// What a row is computed with, made once per table (per thread): each column's scale to output units, the
/// links' poses, the analysis' workspace (with the analysis columns), the row's values.
struct RowWork {
  RowWork(const SweepOutput& out, const std::vector<int>& others)
      : rows(out.result), link_pose(out.scene.mechanism.links.size()), link_angle(link_pose.size()) {
    const Mechanism<double>& m = out.scene.mechanism;
    in_scale = output_scale(m, out.sweep.variable);
    for (int i : others) other_scale.push_back(output_scale(m, i));
    for (int i : m.unknowns) unknown_scale.push_back(output_scale(m, i));
    if (out.analysis) analysis_data.emplace(m);
  }
  RowReader rows;
  double in_scale;
  std::vector<double> other_scale, unknown_scale;  // output_scale of each of `others`, of each unknown
  VectorX<double> q;
  std::vector<SE2<double>> link_pose;  // of a row whose result keeps none
  std::vector<double> link_angle;
  std::optional<AnalysisData<double>> analysis_data;
  std::vector<double> row;  // a row of the CSV
};

/// A row of a table held by column (SweepColumns): value k of the row at at[k * stride], at most `columns`.
struct StridedRow {
  double* at;
  std::size_t stride, columns, n = 0;
  void push_back(double v) {
    if (n == columns) throw std::logic_error("sweep_columns: a row has more values than columns");
    at[n++ * stride] = v;
  }
  std::size_t size() const { return n; }
};

/// The numeric values of row r appended to `row` (a std::vector<double> or a StridedRow), in the order of
/// column_names.
template <class Row>
void row_values(const SweepOutput& out, bool rates, const std::vector<int>& others, std::size_t r, RowWork& w, Row& row) {
  const Mechanism<double>& m = out.scene.mechanism;
  const double in_scale = w.in_scale;
  const SweepRows& res = out.result;
  row.push_back(input_column(out, r));
  const bool ok = res.has_pose(r);  // values also for singular poses
  const auto q = w.rows.q(r);
  for (std::size_t k = 0; k < others.size(); ++k) row.push_back(ok ? q(others[k]) * w.other_scale[k] : kNaN);
  if (rates) {
    const auto qdot = w.rows.qdot(r);
    for (std::size_t k = 0; k < m.unknowns.size(); ++k)
      row.push_back(ok ? qdot(m.unknowns[k]) * w.unknown_scale[k] / in_scale : kNaN);
  }
  // The link poses the sweep kept (ContinuationSettings::link_poses), else the spanning tree's pairs alone
  // evaluated at q, positions only.
  const SE2<double>* pose = ok ? w.rows.link_poses(r) : nullptr;
  const double* angle = ok ? w.rows.link_angles(r) : nullptr;
  if (ok && pose == nullptr) {
    w.q = q;
    link_poses_at(m, w.q, w.link_pose);
    for (std::size_t i = 0; i < w.link_pose.size(); ++i) w.link_angle[i] = w.link_pose[i].angle();
    pose = w.link_pose.data();
    angle = w.link_angle.data();
  }
  for (std::size_t i = 0; i < w.link_pose.size(); ++i) {
    row.push_back(ok ? pose[i].translation().x() : kNaN);
    row.push_back(ok ? pose[i].translation().y() : kNaN);
    row.push_back(ok ? from_radians(angle[i], kOutputAngle) : kNaN);
  }
  if (out.analysis) {
    if (ok) analysis_values(m, analyse_pose(m, q, w.rows.qdot(r), *w.analysis_data), in_scale, row);
    else
      for (std::size_t k = analysis_column_count(m); k > 0; --k) row.push_back(kNaN);
  }
  row.push_back(ok ? w.rows.residual(r) : kNaN);
}

/// What the rows of one CSV table share.
struct CsvRows {
  const SweepOutput& out;
  bool rates;
  const std::vector<int>& others;
  std::size_t columns;
};

/// Rows are formatted in blocks of this many (about a quarter of a megabyte of text) when several threads
/// share the work (write_sweep_csv).
constexpr std::size_t kRowsPerBlock = 1024;

/// Row r of the table as a CSV line appended to `text`.
void append_table_row(const CsvRows& t, std::size_t r, RowWork& w, std::string& text) {
  w.row.clear();
  row_values(t.out, t.rates, t.others, r, w, w.row);
  if (w.row.size() != t.columns) throw std::logic_error("write_sweep_csv: a row's values do not match its columns");
  const std::string status = to_string(t.out.result.status(r));
  append_csv_row(text, w.row.data(), w.row.size(), &status);
}

}  // namespace

double output_scale(const Mechanism<double>& m, int var) {
  return m.variables[var].kind == ParamKind::Angle ? from_radians(1.0, kOutputAngle) : 1.0;
}

std::vector<int> contact_pairs(const Mechanism<double>& m) {
  std::vector<int> k;
  for (std::size_t p = 0; p < m.pairs.size(); ++p)
    if (is_contact(m.pairs[p].kind)) k.push_back(static_cast<int>(p));
  return k;
}

std::string input_column_unit(const SweepOutput& out) {
  switch (out.scene.mechanism.variables[out.sweep.variable].kind) {
    case ParamKind::Angle: return unit_label(kOutputAngle);
    case ParamKind::Length: return out.scene.length_unit;
    case ParamKind::Unitless: return "";
  }
  return "";
}

double input_column(const SweepOutput& out, std::size_t r) {
  // From the requested values in file units (exact grid values for a "deg" file).
  const bool radians_file_angle = out.scene.angle_unit != kOutputAngle &&
                                  out.scene.mechanism.variables[out.sweep.variable].kind == ParamKind::Angle;
  return radians_file_angle ? from_radians(out.inputs[r], kOutputAngle) : out.inputs[r];
}

SweepColumns sweep_columns(const SweepOutput& out, bool rates) {
  SweepColumns t;
  std::vector<int> others;
  t.names = column_names(out, rates, others);
  const std::size_t rows = out.result.size(), columns = t.names.size();
  t.values.reset(new double[columns * rows]);  // every value written below: no fill first
  t.status.resize(rows);
  RowWork w(out, others);
  double* const values = t.values.get();
  for (std::size_t r = 0; r < rows; ++r) {
    StridedRow row{values + r, rows, columns};
    row_values(out, rates, others, r, w, row);
    if (row.size() != columns) throw std::logic_error("sweep_columns: a row's values do not match its columns");
    t.status[r] = out.result.status(r);
  }
  return t;
}

SweepTable sweep_table(const SweepOutput& out, bool rates) {
  const SweepColumns c = sweep_columns(out, rates);
  SweepTable t;
  t.names = c.names;
  for (std::size_t k = 0; k < c.names.size(); ++k) t.columns.emplace_back(c.column(k), c.column(k) + c.rows());
  t.status.reserve(c.rows());
  for (SolveStatus s : c.status) t.status.push_back(to_string(s));
  return t;
}

void write_sweep_csv(const SweepOutput& out, bool rates, OutputSink& sink, int threads) {
  std::vector<int> others;
  const std::vector<std::string> names = column_names(out, rates, others);
  append_csv_header(sink.buffer(), names, SweepTable().status_name);
  const CsvRows table{out, rates, others, names.size()};
  const std::size_t rows = out.result.size();
  const std::size_t workers = batch_workers((rows + kRowsPerBlock - 1) / kRowsPerBlock, threads);
  if (workers <= 1) {
    RowWork w(out, others);
    for (std::size_t r = 0; r < rows; ++r) {
      append_table_row(table, r, w, sink.buffer());
      sink.flush_full();
    }
    return;
  }
  // Each round, `workers` threads format one block of rows each while this thread writes the previous
  // round's blocks in row order: two rounds of text are held, whatever the table's size. Each thread's row
  // buffers and text sit on cache lines of their own (appending to neighbouring strings would share them).
  struct alignas(64) Worker {
    Worker(const SweepOutput& out, const std::vector<int>& others) : work(out, others) {}
    RowWork work;
    std::string text;
  };
  const std::size_t per_round = workers * kRowsPerBlock;
  std::vector<Worker> worker;
  worker.reserve(workers);
  for (std::size_t b = 0; b < workers; ++b) worker.emplace_back(out, others);
  std::vector<std::string> ready(workers);
  std::vector<std::future<void>> running;  // declared last: destroyed (waited for) before what it uses
  const auto start_round = [&](std::size_t first) {
    running.clear();
    for (std::size_t b = 0; b < workers; ++b) {
      const std::size_t lo = std::min(rows, first + b * kRowsPerBlock), hi = std::min(rows, lo + kRowsPerBlock);
      running.push_back(std::async(std::launch::async, [&table, &w = worker[b], lo, hi] {
        w.text.clear();
        for (std::size_t r = lo; r < hi; ++r) append_table_row(table, r, w.work, w.text);
      }));
    }
  };
  start_round(0);
  for (std::size_t first = 0; first < rows; first += per_round) {
    for (auto& f : running) f.get();  // a worker's exception is thrown here
    for (std::size_t b = 0; b < workers; ++b) ready[b].swap(worker[b].text);
    if (first + per_round < rows) start_round(first + per_round);
    for (const std::string& block : ready) {
      sink.buffer() += block;
      sink.flush_full();
    }
  }
}

std::string SweepTable::csv() const {
  std::string out;
  append_csv_header(out, names, status_name);
  std::vector<double> row(names.size());
  for (std::size_t r = 0; r < rows(); ++r) {
    for (std::size_t c = 0; c < names.size(); ++c) row[c] = columns[c][r];
    append_csv_row(out, row.data(), row.size(), &status[r]);
  }
  return out;
}

}  // namespace rollkin::io
