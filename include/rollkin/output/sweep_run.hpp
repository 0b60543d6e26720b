// The run of one sweep, as every front end makes it: the command line (`rollkin solve`, `check`, `centrodes`,
// `reference`, `synthesize envelope`) and the Python module (`Scene.solve`, `write`, `centrodes`, `reference`,
// `solve_many`) all go through SweepRun (src/output/sweep_run.cpp):
//
//   request -> checked inputs -> assemble -> sweep -> write all or nothing
//
// Everything that can be refused is refused when the run is made, before anything is solved: an output that
// is one of the files the run reads or another output (io::OutputSet: "Outputs", docs/reliability.md), a
// sweep the scene does not have or that is not one (SweepRequestError), and more work than the bound
// (io::WorkLimitError, "Bounded work"). The front ends name their own options in these messages
// (RequestNames) and turn the errors into theirs (the command line's exit 2, Python's ValueError).
//
//   output::SweepRun run(scene, inputs, {{"--csv", "out.csv", "csv"}}, request, names);  // checked here
//   SolveData<double> sd(run.mechanism());
//   VectorX<double> q;
//   const SolveReport<double> assembly = run.assemble(sd, q);  // InputError when it cannot assemble
//   const SweepResult<double> result = run.solve(sd, q, assembly);
//   run.write(run.output(result), {});                          // every file or none
#pragma once

#include "rollkin/io/output_set.hpp"
#include "rollkin/io/scene/reader.hpp"
#include "rollkin/output/sweep_table.hpp"
#include "rollkin/io/work_bound.hpp"
#include "rollkin/output/sweep_files.hpp"
#include "rollkin/solve/sweep_summary.hpp"

#include <atomic>
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rollkin {
template <class S> struct SolveData;
}  // namespace rollkin

namespace rollkin::io {
class SweepFile;
}  // namespace rollkin::io

namespace rollkin::output {

/// What the caller asks of the scene's sweep: the overrides of its range (none: the scene's "sweep"; a scene
/// without one needs all three) and the bound on the work (io/work_bound.hpp).
struct SweepRequest {
  std::optional<double> from, to, step;
  // The overrides as the user wrote them ("" : the number's shortest text): the grid is the decimal one
  // (solve/sweep_grid.hpp), so "0.1" stays the decimal 0.1.
  std::string from_text, to_text, step_text;
  double max_steps = io::kDefaultMaxSteps;
};

/// How a front end names the request's parts in its messages: the command line's options
/// ("--from/--to/--step", "--from, --to and --step", "--max-steps") or Python's keywords.
struct RequestNames {
  std::string range;       // the three together, as in "<range>: the step must not be 0"
  std::string range_list;  // as in "a.json has no \"sweep\"; give <range_list>"
  std::string max_steps;   // the bound's option, as in "... above the limit 1e+07 (<max_steps>)"
};

/// A sweep the scene cannot give: none in the scene and not all of from, to and step given, or a range that
/// is not a sweep (check_sweep). The message names the front end's options (RequestNames).
class SweepRequestError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// One output file of a run: `label` names it in messages (the command line's option, Python's keyword),
/// `path` "" when it is not asked for. `format` is a name of sweep_formats() for a file written from the
/// solved sweep by write(); "" for a file the caller fills (set_output, omit_output).
struct OutputRequest {
  std::string label, path, format;
};

class SweepRun {
 public:
  /// The run of `scene`'s sweep as `request` asks, checked in this order before anything is solved:
  /// every output asked for against `inputs` (the files the run reads, never written over) and against the
  /// others (io::OutputError; std::invalid_argument for an unknown format), the sweep (SweepRequestError)
  /// and its work (io::WorkLimitError above request.max_steps).
  SweepRun(std::shared_ptr<const io::Scene> scene, std::vector<io::InputFile> inputs,
           const std::vector<OutputRequest>& outputs, const SweepRequest& request, const RequestNames& names);
  SweepRun(SweepRun&&) = default;

  const io::Scene& scene() const { return *scene_; }
  const std::shared_ptr<const io::Scene>& shared_scene() const { return scene_; }
  const Mechanism<double>& mechanism() const { return scene_->mechanism; }
  /// The requested sweep (the scene's, with the overrides).
  const Sweep& sweep() const { return sweep_; }
  /// Its input values in internal units (radians for an angle), within the bound.
  const std::vector<double>& inputs() const { return inputs_; }
  /// The same values in the file's units (sweep_values: the exact decimal grid for a "deg" scene), made
  /// on the first call: the table's input column.
  const std::vector<double>& values();

  // ---- solving ---------------------------------------------------------------------------------------------

  /// Assembles the mechanism from the scene's guess into q (sd ready for solve()). A scene whose mechanism
  /// cannot be assembled (SolveStatus::CannotAssemble: sizes, frames or values that let no loop close) is a
  /// problem of the input, not a motion limit: io::assembly_error, an InputError.
  SolveReport<double> assemble(SolveData<double>& sd, VectorX<double>& q) const;
  /// The same, the report returned whatever it says (a batch reports a scene that cannot be assembled as a
  /// table of NaN and goes on with the others).
  SolveReport<double> try_assemble(SolveData<double>& sd, VectorX<double>& q) const;
  /// The sweep from the assembly: every pose's values in memory, with every link's pose when `link_poses`
  /// (for a table: ContinuationSettings::link_poses). `cancel`, when given, is polled between poses
  /// (ContinuationSettings::cancel).
  SweepResult<double> solve(SolveData<double>& sd, const VectorX<double>& q, const SolveReport<double>& assembly,
                            const std::atomic<bool>* cancel = nullptr, bool link_poses = false) const;
  /// The same, the poses kept in `file` (made with this run's inputs) rather than in memory: the files'
  /// memory stays that of a summary whatever the number of poses (output/sweep_file.hpp).
  void solve_into(SolveData<double>& sd, const VectorX<double>& q, const SolveReport<double>& assembly,
                  io::SweepFile& file) const;
  /// The sweep's summary alone, no values (sweep_summary.hpp): what a report without files needs.
  SweepSummary<double> summary(SolveData<double>& sd, const VectorX<double>& q, const SolveReport<double>& assembly) const;

  // ---- outputs ---------------------------------------------------------------------------------------------

  /// Whether the run writes any file.
  bool writes_files() const { return !files_.empty() || !given_.empty(); }
  /// The solved rows with what the outputs need to present them (`rows` must outlive it).
  io::SweepOutput output(io::SweepRows rows, bool analysis = false);
  /// Gives every file of a sweep format its writer over `out` and writes every file of the run, all or
  /// nothing (io::OutputSet::commit). `out` must live until this returns.
  void write(const io::SweepOutput& out, const WriteOptions& options);
  /// The content of the file labelled `label` (format ""), if it was asked for (`make_text` is called only then).
  void set_output(const std::string& label, const std::function<std::string()>& make_text);
  /// The file labelled `label`, if asked for, is not written after all (io::OutputSet::omit).
  void omit_output(const std::string& label);
  /// Writes every file of the run, all or nothing (each set or omitted first).
  void commit();

 private:
  std::shared_ptr<const io::Scene> scene_;
  std::unique_ptr<io::OutputSet> outputs_;  // on the heap: `files_` refers to it, and a run is moved
  SweepFiles files_;
  std::map<std::string, std::size_t> given_;  // label -> index in `outputs_`, for the files of format "" asked for
  Sweep sweep_;
  std::vector<double> inputs_;
  std::optional<std::vector<double>> values_;
};

}  // namespace rollkin::output
