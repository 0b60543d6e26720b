// The parts the commands of build/rollkin share (src/cli/commands.cpp): the command type, the option helpers,
// the start of the sweep every sweeping command runs (SweepRequest, start_run: output::SweepRun), the
// messages of a sweep's problems, the design check's text (src/cli/command_check.cpp) and the exit status of
// an error. Each command is one file src/cli/command_<name>.cpp declaring its options and running it; main.cpp
// lists the commands.
#pragma once
#include "rollkin/output/sweep_table.hpp"
#include "rollkin/output/centrode_files.hpp"
#include "rollkin/output/sweep_files.hpp"
#include "rollkin/output/sweep_run.hpp"

#include "rollkin/analysis/design_check.hpp"
#include "rollkin/io/format.hpp"
#include "rollkin/io/output_set.hpp"
#include "rollkin/io/scene/reader.hpp"
#include "rollkin/solve/continuation.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <functional>
#include <new>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rollkin::cli {

namespace fs = std::filesystem;

/// A command line that parses but asks for something that cannot be done (found after reading the scene).
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// What the run is doing, for the message of an allocation failure ("out of memory while ...").
/// Per thread: several scenes may be solved at once (--jobs).
extern thread_local const char* g_doing;

/// Inside a catch block: the message for the exception being handled (other than a UsageError) on `err`, and
/// the exit status: 3 out of memory, 2 anything else (bad input, an output that cannot be written).
int error_status(std::ostream& err);

/// The input a step of a command depends on, for an error the library raises without naming one.
struct StepInput {
  std::string file;      // the file the user gave (the spec, the scene)
  std::string location;  // the keys or options that govern the step ("tolerance", "--tolerance", "sweep")
  std::string advice;    // what to change
};

/// A message of the library that names no input ("gear synthesis: more than 2^20 samples needed") as an
/// io::InputError naming the input that caused it: "<file>: <location>: <message> (while <doing>); <advice>".
io::InputError input_error_of_step(const StepInput& input, const std::string& message);

/// Runs `step`; an error out of it that names no input (any std::exception but io::InputError, io::OutputError,
/// io::InternalError, UsageError and std::bad_alloc) becomes input_error_of_step (exit 2). The one place where a
/// command's boundary translates the library's messages (docs/reliability.md, "Outputs, signals and messages").
template <class Step> auto from_input(const StepInput& input, Step&& step) -> decltype(step()) {
  try {
    return step();
  } catch (const io::InputError&) {
    throw;
  } catch (const io::OutputError&) {
    throw;
  } catch (const io::InternalError&) {
    throw;
  } catch (const UsageError&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    throw input_error_of_step(input, e.what());
  }
}

/// The exit statuses, as the footer of every command's --help.
extern const char* kExitStatus;

/// A command: its CLI11 subcommand (options bound to the values the parse fills in) and the function that runs
/// it with those values.
struct Command {
  CLI::App* app;
  std::function<int()> run;
};

// The commands (src/cli/command_<name>.cpp): each declares its subcommand on `rollkin` and returns it with the
// function that runs it.
Command solve_command(CLI::App& rollkin);
Command reference_command(CLI::App& rollkin);
Command centrodes_command(CLI::App& rollkin);
Command check_command(CLI::App& rollkin);
Command contours_command(CLI::App& rollkin);
Command synthesize_command(CLI::App& rollkin);

// ---- option values: fully parsed, checked before anything is read ------------------------------------------

/// `text` as a finite number, all of it ("1x", "", "nan", "inf" are not).
std::optional<double> finite_number(const std::string& text);

/// A check of an option's value: a finite number (for which `accept`, when given, is true). CLI11 names the
/// option in front of the message: "--step: expects a number, got \"1x\"".
CLI::Validator number(const std::string& expected, std::function<bool(double)> accept = {});

/// The option `name` storing a number in `slot` when given, and the text it was given as in `text`.
CLI::Option* add_number(CLI::App& app, const std::string& name, std::optional<double>& slot, std::string& text,
                        const std::string& help);

/// The option `name` storing a number in `slot`, read by strtod (nan and inf included) and checked by `problem`, a
/// rule of the library that Python shares ("" when fine, else what is wrong): "--start: expected ..., got nan".
CLI::Option* add_checked_number(CLI::App& app, const std::string& name, std::optional<double>& slot,
                                std::string (*problem)(double), const std::string& help);

/// The option `name` storing an output file name in `slot`.
CLI::Option* add_output(CLI::App& app, const std::string& name, std::string& slot, const std::string& help);

/// The option `name` storing an output prefix in `slot` (PREFIX of PREFIX.txt, PREFIX.dxf, ...): an output file
/// name that must end in a name ("./" and "out/" are refused: they would write hidden files ".txt", ".dxf").
CLI::Option* add_prefix(CLI::App& app, const std::string& name, std::string& slot, const std::string& help);

// ---- what every sweeping command shares: scene, sweep overrides, bounded work, outputs --------------------

/// The scene and the part of the sweep the command line may override (output::SweepRequest: --from, --to,
/// --step as given, --max-steps).
struct SweepRequest : output::SweepRequest {
  std::string scene;
};

/// The sweep options; the positional SCENE goes to r.scene, or, when `scenes` is given, one or more of them.
void add_sweep_options(CLI::App& app, SweepRequest& r, std::vector<std::string>* scenes = nullptr);

/// The start of every sweeping command: the scene read (r.scene, or `loaded` when a run of several scenes has
/// read it already), then the library's checks of the run (output::SweepRun) before anything is solved: the
/// output files (option, path "" for one not given, format for a file of output::sweep_formats()) against the
/// files the scene reads and each other, the requested sweep, and its work. A sweep that cannot be run (no
/// "sweep" and no --from/--to/--step, a bad range, above --max-steps) is a UsageError (exit 2).
output::SweepRun start_run(const SweepRequest& r, const std::vector<output::OutputRequest>& outputs,
                           std::optional<io::Scene> loaded = std::nullopt);

/// Reads a scene file (io::load_scene), g_doing saying so.
io::Scene read_scene(const std::string& file);

/// One scene of a run and the outputs it will write: (option, path) with path "" for one not given. `scene`
/// is null when the file could not be read (its outputs are still checked: the command line names them).
struct PlannedScene {
  std::string file;
  const io::Scene* scene = nullptr;
  std::vector<std::pair<std::string, std::string>> outputs;
};

/// Before anything is solved, every output of a run of several scenes checked in one io::OutputSet against
/// every file any scene reads (its scene file, point files, SVG, DXF) and against every other output
/// (resolved paths; device and inode for files that exist): OutputError naming both.
void check_run_outputs(const std::vector<PlannedScene>& run);

/// `pattern` with every "{scene}" replaced by `stem` (text that `stem` brings in is not searched again).
std::string with_scene_name(const std::string& pattern, const std::string& stem);

// ---- messages and reports ---------------------------------------------------------------------------------

/// "O_A.theta2 = -57.397 deg" in the file's units.
std::string input_text(const io::Scene& scene, const Sweep& sw, double internal);

/// One line per limit for stderr, the input in the file's units.
std::string limit_line(const io::Scene& scene, const Sweep& sw, const SolveReport<double>& r);

/// One line per problem of a sweep: a failed assembly, each limit met, each singular pose (`inputs`: the
/// sweep's requested inputs, internal units).
std::vector<std::string> sweep_problems(const io::Scene& scene, const Sweep& sw, const SweepSummary<double>& summary,
                                        const std::vector<double>& inputs);

/// The one exit status of a sweep's poses, for every command that solves one (solve, check, centrodes, synthesize
/// envelope): 0 when the assembly succeeded and every requested pose is ok, 1 otherwise (a limit, a pose not
/// reached, a singular pose: the lines of sweep_problems). One pose, one status, whichever command solves it.
int sweep_status(const SweepSummary<double>& summary, std::size_t requested);

// ---- the design check (rollkin check, solve --verbose; src/cli/command_check.cpp) --------------------------

/// The design check's text: the report section for stdout and one located line per impossible design
/// (a pair whose contours interpenetrate: a roller too large for a concave part of the other contour).
struct DesignReport {
  std::vector<std::string> section, findings;
};

/// The design check of a solved sweep (rollkin/analysis/design_check.hpp) as text.
DesignReport design_report(const io::Scene& scene, const Sweep& sw, const SweepResult<double>& result);


/// Rank of the full (scaled) constraint Jacobian at the pose sd was last evaluated at (solve --verbose).
struct AssemblyRank {
  int rank = 0;
  int redundant = 0;  // equations - rank
  int mobility = 0;   // variables - rank
};
AssemblyRank full_rank(const Mechanism<double>& m, const SolveData<double>& sd);

}  // namespace rollkin::cli
