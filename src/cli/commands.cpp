// What the commands of build/rollkin share (declared and documented in commands.hpp): the option helpers,
// the start of every sweeping command (start_run: the scene read, then output::SweepRun), the messages of a
// sweep's problems and the exit status of an error.
#include "commands.hpp"

#include "rollkin/io/work_bound.hpp"

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>

namespace rollkin::cli {

thread_local const char* g_doing = "starting";  // per thread: several scenes may be solved at once (--jobs)

const char* kExitStatus =
    "Exit status: 0 all requested poses solved; 1 some not (limits or singular poses on stderr, solved rows\n"
    "still written); 2 bad input or command line, or a request above --max-steps (nothing written);\n"
    "3 out of memory (nothing written); 4 internal error: a defect of rollkin, such as a file it wrote that its\n"
    "own reader refuses (nothing written).";

// ---- option values: fully parsed, checked before anything is read ------------------------------------------

std::optional<double> finite_number(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v)) return std::nullopt;
  return v;
}

CLI::Validator number(const std::string& expected, std::function<bool(double)> accept) {
  return CLI::Validator(
      [expected, accept](std::string& text) -> std::string {
        const std::optional<double> v = finite_number(text);
        if (v && (!accept || accept(*v))) return {};
        return "expects " + expected + ", got \"" + text + "\"";
      },
      "", "");
}

namespace {

/// A check of an output file name: not empty, and not an option (CLI11 gives the next argument to an option
/// that needs a value, so "--csv --rates" would otherwise write a file named "--rates").
const CLI::Validator kFileName(
    [](std::string& text) -> std::string {
      if (text.empty()) return "expects a file name, got an empty string";
      if (text.rfind("--", 0) == 0)
        return "expects a file name, got the option \"" + text + "\" (for a file of that name write ./" + text + ")";
      return {};
    },
    "", "");

/// A check of an output prefix (PREFIX of PREFIX.txt, PREFIX.dxf, ...): a file name must follow its last '/',
/// or the outputs would be hidden files ".txt", ".dxf" in that directory.
const CLI::Validator kPrefix(
    [](std::string& text) -> std::string {
      const std::size_t slash = text.find_last_of('/');
      const std::string name = slash == std::string::npos ? text : text.substr(slash + 1);
      if (name.empty() || name == "." || name == "..")
        return "expects a prefix that ends in a file name (e.g. \"" + (slash == std::string::npos ? std::string() : text.substr(0, slash + 1)) +
               "cam\" for cam.txt, cam.dxf, ...), got \"" + text + "\", which would write hidden files such as \".txt\"";
      return {};
    },
    "", "");

}  // namespace

CLI::Option* add_number(CLI::App& app, const std::string& name, std::optional<double>& slot, std::string& text,
                        const std::string& help) {
  return app.add_option_function<std::string>(name, [&slot, &text](const std::string& v) {
              text = v;
              slot = finite_number(v);  // the check below accepted it
            }, help)
      ->type_name("V")
      ->check(number("a number"));
}

namespace {

/// `text` read by strtod, all of it (nan and inf included); nullopt for text that is not a number.
std::optional<double> any_number(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0') return std::nullopt;
  return v;
}

}  // namespace

CLI::Option* add_checked_number(CLI::App& app, const std::string& name, std::optional<double>& slot,
                                std::string (*problem)(double), const std::string& help) {
  return app.add_option_function<std::string>(name, [&slot](const std::string& v) { slot = any_number(v); }, help)
      ->type_name("V")
      ->check(CLI::Validator(
          [problem](std::string& text) -> std::string {
            const std::optional<double> v = any_number(text);
            if (!v) return "expects a number, got \"" + text + "\"";
            return problem(*v);
          },
          "", ""));
}

CLI::Option* add_output(CLI::App& app, const std::string& name, std::string& slot, const std::string& help) {
  return app.add_option(name, slot, help)->type_name("FILE")->check(kFileName);
}

CLI::Option* add_prefix(CLI::App& app, const std::string& name, std::string& slot, const std::string& help) {
  return add_output(app, name, slot, help)->type_name("PREFIX")->check(kPrefix);
}

// ---- what every sweeping command shares: scene, sweep overrides, bounded work, outputs --------------------

void add_sweep_options(CLI::App& app, SweepRequest& r, std::vector<std::string>* scenes) {
  if (scenes)
    app.add_option("SCENE", *scenes, "the scene(s): JSON files (docs/scene_format.md)")->required()->type_name("");
  else
    app.add_option("SCENE", r.scene, "the scene: a JSON file (docs/scene_format.md)")->required()->type_name("");
  add_number(app, "--from", r.from, r.from_text, "first input value (overrides the scene's \"sweep\"; angles in the scene's unit)");
  add_number(app, "--to", r.to, r.to_text, "last input value (overrides the scene's \"sweep\")");
  add_number(app, "--step", r.step, r.step_text, "step between input values, with the sign of --to minus --from (negative for a decreasing sweep: --from 100 --to 0 --step -1)");
  app.add_option("--max-steps", r.max_steps,
                 "refuse (exit 2) a sweep estimated to need more than N continuation sub-steps, or of more than N "
                 "values (default 1e7)")
      ->type_name("N")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {  // the rule of rollkin/io/work_bound.hpp, shared with Python
            char* end = nullptr;
            const double v = std::strtod(text.c_str(), &end);
            if (text.empty() || *end != '\0') return "expects a number of continuation sub-steps, got \"" + text + "\"";
            return io::max_steps_problem(v);
          },
          "", ""));
}

namespace {

/// The command line's options in the library's messages about a request.
const output::RequestNames kOptionNames{"--from/--to/--step", "--from, --to and --step", "--max-steps"};

}  // namespace

output::SweepRun start_run(const SweepRequest& r, const std::vector<output::OutputRequest>& outputs,
                           std::optional<io::Scene> loaded) {
  auto scene = std::make_shared<const io::Scene>(loaded ? std::move(*loaded) : read_scene(r.scene));
  std::vector<io::InputFile> inputs{{scene->file, ""}};  // "the input file '<path>' read by this run"
  for (const std::string& f : scene->files_read) inputs.push_back({f, ""});
  g_doing = "checking the output files";
  try {
    return output::SweepRun(std::move(scene), std::move(inputs), outputs, r, kOptionNames);
  } catch (const output::SweepRequestError& e) {
    throw UsageError(e.what());
  } catch (const io::WorkLimitError& e) {  // bounded work (rollkin/io/work_bound.hpp): exit 2
    throw UsageError(e.what());
  }
}

io::Scene read_scene(const std::string& file) {
  g_doing = "reading the scene";
  return io::load_scene(file);
}

void check_run_outputs(const std::vector<PlannedScene>& run) {
  std::vector<io::InputFile> inputs;
  for (const PlannedScene& p : run) {
    inputs.push_back(io::InputFile{p.file, "the scene file '" + p.file + "'"});
    if (p.scene)
      for (const std::string& f : p.scene->files_read)
        inputs.push_back(io::InputFile{f, "the contour file '" + f + "' read by scene '" + p.file + "'"});
  }
  io::OutputSet whole(std::move(inputs));
  for (const PlannedScene& p : run)
    for (const auto& [option, path] : p.outputs)
      if (!path.empty()) whole.add(p.file + "'s " + option, path);
}

std::string with_scene_name(const std::string& pattern, const std::string& stem) {
  static const std::string kToken = "{scene}";
  std::string out;
  std::size_t from = 0;
  for (std::size_t at; (at = pattern.find(kToken, from)) != std::string::npos; from = at + kToken.size())
    out += pattern.substr(from, at - from) + stem;
  return out + pattern.substr(from);
}

// ---- messages and reports ---------------------------------------------------------------------------------

std::string input_text(const io::Scene& scene, const Sweep& sw, double internal) {
  const std::string unit = scene.unit_label(sw.variable);
  return sw.input + " = " + io::format_number(internal / sw.unit, 8) + (unit.empty() ? "" : " " + unit);
}

std::string limit_line(const io::Scene& scene, const Sweep& sw, const SolveReport<double>& r) {
  const Mechanism<double>& m = scene.mechanism;
  const std::string where = input_text(scene, sw, r.limit_input);
  switch (r.status) {
    case SolveStatus::DeadPoint:
      return "dead_point: dead point (motion limit) at " + where + ": the mechanism cannot move past it (Jacobian " +
             "singular there, condition " + io::format_number(r.condition, 3) + ")";
    case SolveStatus::DomainExit: {
      std::string what = "a contact leaves its contour";
      if (r.pair >= 0 && r.contour >= 0)
        what = "the contact of pair '" + m.pairs[r.pair].name + "' leaves the end of contour '" + m.contours[r.contour].name() + "'";
      return "domain_exit: " + what + " at " + where;
    }
    case SolveStatus::Corner: {
      const ContourCorner<double>& k = m.contours[r.contour].corners()[static_cast<std::size_t>(r.corner)];
      return "corner: the contact of pair '" + m.pairs[r.pair].name + "' reaches a corner of contour '" +
             m.contours[r.contour].name() + "' (" + k.label + "; (" + io::format_number(k.point.x(), 10) + ", " +
             io::format_number(k.point.y(), 10) + ") in the contour's frame) at " + where +
             ": a contact cannot pass a corner";
    }
    case SolveStatus::NoConvergence: return "no_convergence: Newton-Raphson does not converge beyond " + where;
    default: return std::string(to_string(r.status)) + ": " + r.detail + " (at " + where + ")";
  }
}

std::vector<std::string> sweep_problems(const io::Scene& scene, const Sweep& sw, const SweepSummary<double>& summary,
                                        const std::vector<double>& inputs) {
  std::vector<std::string> problems;
  const SolveReport<double>& assembly = summary.assembly;
  if (!assembly.ok())
    problems.push_back(std::string(to_string(assembly.status)) + ": assembly failed: " +
                       (assembly.detail.empty() ? "the mechanism cannot be assembled" : assembly.detail) +
                       " (rank " + std::to_string(assembly.rank) + " of " + std::to_string(assembly.unknowns) +
                       " unknowns, condition " + io::format_number(assembly.condition, 3) + ")");
  for (const auto& l : summary.limits) problems.push_back(limit_line(scene, sw, l));
  for (const auto& p : summary.singular)
    problems.push_back("singular: singular pose at " + input_text(scene, sw, inputs[p.index]) +
                       ": the branches meet / Jacobian singular; values follow the branch (interpolated between"
                       " the regular poses on both sides, condition " + io::format_number(p.report.condition, 3) + ")");
  return problems;
}

io::InputError input_error_of_step(const StepInput& input, const std::string& message) {
  // The library's own prefix ("envelope: ", "gear synthesis: ", "SampledProfile: ") names code, not input.
  std::string what = message;
  const std::size_t colon = what.find(": ");
  if (colon != std::string::npos && colon <= 24 && std::count(what.begin(), what.begin() + static_cast<long>(colon), ' ') <= 1)
    what.erase(0, colon + 2);
  return io::InputError(input.file, input.location, what + " (while " + g_doing + ")" + (input.advice.empty() ? "" : "; " + input.advice));
}

int sweep_status(const SweepSummary<double>& summary, std::size_t requested) {
  return summary.assembly.ok() && summary.solved() == requested ? 0 : 1;
}

int error_status(std::ostream& err) {
  try {
    throw;
  } catch (const std::bad_alloc&) {
    err << "rollkin: out of memory while " << g_doing
        << "; nothing was written (a smaller sweep, fewer samples or more memory may help)\n";
    return 3;
  } catch (const io::InputError& e) {
    err << e.what() << "\n";
    return 2;
  } catch (const io::InternalError& e) {
    err << "rollkin: internal error: " << e.what() << "\n";
    return 4;
  } catch (const std::exception& e) {
    err << "rollkin: error: " << e.what() << "\n";
    return 2;
  } catch (...) {
    err << "rollkin: unexpected error\n";
    return 2;
  }
}

AssemblyRank full_rank(const Mechanism<double>& m, const SolveData<double>& sd) {
  MatrixX<double> j = sd.kin.dense_jacobian();  // either store (the sparse path keeps only the nonzeros)
  for (int c = 0; c < m.variable_count(); ++c) j.col(c) = j.col(c).cwiseQuotient(sd.row_scale) * m.variable_scale(c);
  Eigen::CompleteOrthogonalDecomposition<MatrixX<double>> cod(j);
  AssemblyRank r;
  r.rank = static_cast<int>(cod.rank());
  r.redundant = m.equation_count() - r.rank;
  r.mobility = m.variable_count() - r.rank;
  return r;
}

}  // namespace rollkin::cli
