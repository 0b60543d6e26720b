// `rollkin solve`: one scene or several (--jobs), assembly, sweep, the outputs (CSV, plot, drawing,
// animation), the summary, the assembly report (--verbose) and the interference check (--interference).
#include "commands.hpp"

#include "rollkin/output/sweep_file.hpp"
#include "rollkin/analysis/forces.hpp"
#include "rollkin/output/sweep_forces.hpp"
#include "rollkin/solve/batch.hpp"
#include "rollkin/analysis/interference.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

namespace rollkin::cli {
namespace {

void print_assembly(std::ostream& out, const io::Scene& scene, const SolveReport<double>& rep, const AssemblyRank& ar) {
  const Mechanism<double>& m = scene.mechanism;
  for (const std::string& n : scene.notes) out << "contour " << n << "\n";
  out << "assembly: " << to_string(rep.status) << " after " << rep.iterations << " iteration(s), residual "
            << io::format_number(rep.residual, 3) << "\n"
            << "  variables " << m.variable_count() << " (inputs " << m.drivers.size() << ", unknowns " << m.unknowns.size()
            << "), equations " << m.equation_count() << " (" << m.loops.size() << " loop(s) x 3 + "
            << m.rolling_pairs.size() << " rolling)\n"
            << "  rank of the unknowns' Jacobian " << rep.rank << ", condition " << io::format_number(rep.condition, 3) << "\n"
            << "  rank of the full Jacobian " << ar.rank << ": redundant constraints " << ar.redundant
            << ", mobility (DOF = variables - rank) " << ar.mobility << "\n";
  if (!rep.detail.empty()) out << "  " << rep.detail << "\n";
  if (m.unknowns.empty())
    out << "  nothing to solve: every pair variable is an input, so each pose follows from the inputs alone"
                 " (forward kinematics)\n";
  else if (ar.mobility == 0)
    out << "  the mechanism has zero degrees of freedom: it is a rigid structure, its inputs cannot move\n";
}

/// Contact pairs whose signed curvatures cancel at q (osculation): their contact Jacobian is singular
/// (docs/method.md section 5), which the solver reports only as a rank loss.
std::vector<std::string> osculating_contacts(const Mechanism<double>& m, const VectorX<double>& q) {
  std::vector<std::string> out;
  KinematicsData<double> kin(m);
  evaluate_pairs<double>(m, q, nullptr, 2, kin);
  for (std::size_t k = 0; k < m.pairs.size(); ++k) {
    if (!m.pairs[k].traits().has_contours) continue;
    const double ka = kin.pairs[k].contact[0].curvature(), kb = kin.pairs[k].contact[1].curvature();
    const double size = std::max(std::abs(ka), std::abs(kb));
    if (size > 0 && std::abs(ka + kb) <= 1e-6 * size)
      out.push_back("osculation: at the assembly pose the contours of pair '" + m.pairs[k].name +
                    "' osculate (signed curvatures " + io::format_number(ka) + " and " + io::format_number(kb) +
                    " cancel), so the contact Jacobian is singular there; choose another assembly pose or geometry");
  }
  return out;
}

/// --interference: contours sampled once in their links' frames and checked at every solved pose
/// (analysis/interference.hpp); one line per run of consecutive poses with the same finding, inputs in the
/// file's units, with the chords' distance from the curves and the touch tolerance.
std::vector<std::string> interference_lines(const io::Scene& scene, const Sweep& sw, const SweepResult<double>& result) {
  const Mechanism<double>& m = scene.mechanism;
  const SweepInterference si = check_interference(m, result);
  struct Run {
    InterferenceKind kind;
    int a, b;
    double from, to;
    bool open;
  };
  std::vector<Run> runs;
  for (const auto& pose : si.poses) {
    for (auto& r : runs) r.open = r.open && pose.checked && !pose.clear();
    for (const auto& f : pose.findings) {
      Run* run = nullptr;
      for (auto& r : runs)
        if (r.open && r.kind == f.kind && r.a == f.contour_a && r.b == f.contour_b) run = &r;
      if (run) run->to = pose.input;
      else runs.push_back(Run{f.kind, f.contour_a, f.contour_b, pose.input, pose.input, true});
    }
  }
  std::vector<std::string> lines;
  const std::string unit = scene.unit_label(sw.variable);
  for (const auto& r : runs)
    lines.push_back(std::string("interference: ") + to_string(r.kind) + " between '" + m.contours[r.a].name() +
                    "' and '" + m.contours[r.b].name() + "' for " + sw.input + " from " + io::format_number(r.from / sw.unit, 8) +
                    " to " + io::format_number(r.to / sw.unit, 8) + (unit.empty() ? "" : " " + unit) + " (decided on chords within " +
                    io::format_number(std::max(si.chord_error[r.a], si.chord_error[r.b]), 2) + " " + scene.length_unit +
                    " of the contours, touch tolerance " + io::format_number(si.touch_tolerance, 2) + " " + scene.length_unit + ")");
  return lines;
}

// ---- rollkin solve ---------------------------------------------------------------------------------------

constexpr int kMaxJobs = 4096;  // --jobs: threads at once (a run never starts more workers than scenes)

struct SolveOptions {
  SweepRequest sweep;
  std::vector<std::string> scenes;  // the scene files given; sweep.scene is each in turn
  std::vector<std::pair<std::string, std::string>> files;  // (format, path) per output::sweep_formats(), "" not given
  bool rates = false, analysis = false, verbose = false, interference = false, forces = false;
  std::string speed;  // --speed as written ("" : the scene's)
  int jobs = 0;  // scenes solved at once, or with one scene the threads that format its CSV (0: one per core)
};

int run_solve(const SolveOptions& o);

}  // namespace

Command solve_command(CLI::App& rollkin) {
  auto o = std::make_shared<SolveOptions>();
  CLI::App* app = rollkin.add_subcommand("solve", "assemble the mechanism and sweep its input (double precision)");
  add_sweep_options(*app, o->sweep, &o->scenes);
  for (const output::SweepFormat& f : output::sweep_formats()) o->files.emplace_back(f.name, "");
  for (auto& [format, path] : o->files) add_output(*app, "--" + format, path, output::sweep_format(format).help);
  app->add_flag("--rates", o->rates, "add the rate columns d(var)/d(input) to the CSV");
  app->add_flag("--analysis", o->analysis,
                "add the contact analysis columns to the CSV and charts to the plot: pressure angle, sliding, "
                "curvatures, link accelerations and jerks (docs/analysis.md)");
  app->add_flag("--forces", o->forces,
                "add the force columns to the CSV and the force summary: pair reactions, contact normal and friction "
                "forces, contact stress, drive effort and power at the scene's \"dynamics\" speed; statuses separation "
                "and slip (exit 1) (docs/forces.md)");
  app->add_option("--speed", o->speed,
                  "with --forces: the input speed instead of the scene's, a number and a unit: 500rpm, 52rad/s, 300deg/s, "
                  "or for a length input 20mm/s (no unit: the scene's speed unit)")
      ->type_name("V[UNIT]");
  app->add_flag("-v,--verbose", o->verbose,
                "print the assembly report, how imported contours were converted and the design check (as 'rollkin check')");
  app->add_flag("--interference", o->interference,
                "check every solved pose for contours that penetrate or touch twice (findings make exit 1)");
  // Read as text and checked by rollkin (CLI11's own conversion to int said only "Could not convert" for 1e9).
  app->add_option_function<std::string>("-j,--jobs", [o](const std::string& v) { o->jobs = static_cast<int>(*finite_number(v)); },
                                         "with several scenes: how many are solved at once; with one: how many threads "
                                         "format its --csv (default 0: one per core; at most " + std::to_string(kMaxJobs) + ")")
      ->type_name("N")
      ->check(number("a whole number of scenes or threads at once from 0 (one per core) to " + std::to_string(kMaxJobs),
                     [](double v) { return v >= 0 && v <= kMaxJobs && v == std::floor(v); }));
  app->footer(
      "Loads the scene, assembles the mechanism and sweeps its input over the scene's \"sweep\" (--from/--to/\n"
      "--step override it), following one branch in both directions from the assembly pose.\n"
      "CSV columns: angles in degrees, lengths in scene units. Without output options a one-line summary is\n"
      "printed (on a grid finer than the solver needs, the poses between its steps are interpolated, each one\n"
      "checked by evaluating its constraints).\n"
      "Status column: ok; singular (branches meet there, the Jacobian is singular: the values follow the branch,\n"
      "interpolated between regular poses on both sides; a line on stderr, exit status 1); dead_point,\n"
      "domain_exit, corner, no_convergence (a limit met: one line on stderr); not_reached (beyond a limit).\n"
      "--max-steps: the estimate is the input's travel over the largest sub-step (5 deg for angles) plus the\n"
      "number of values.\n"
      "Several scenes (rollkin solve A.json B.json ... --jobs N): each is solved as if alone, N at a time, with\n"
      "the same options; every output name must contain {scene}, each replaced by the scene file's name\n"
      "without its extension (--csv 'out/{scene}.csv'). All scenes are read first; an output that is a file\n"
      "any scene reads, or another output, is exit 2 before anything is solved. Reports come in the order the\n"
      "scenes were given; a scene that fails does not stop the others; the exit status is the worst of the\n"
      "scenes'.\n" +
      std::string(kExitStatus));
  return {app, [o] { return run_solve(*o); }};
}

namespace {

/// The outputs `rollkin solve` may write: (option, path), path "" for one not given.
std::vector<std::pair<std::string, std::string>> output_files(const SolveOptions& o) {
  std::vector<std::pair<std::string, std::string>> files;
  for (const auto& [format, path] : o.files) files.emplace_back("--" + format, path);
  return files;
}

/// The input speed of --forces (internal units per second): --speed, else the scene's "dynamics" speed.
/// Exit 2 (ForcesUnavailable, UsageError) for a scene without dynamics or a speed that is not one.
double forces_speed(const SolveOptions& o, const io::Scene& scene, const Sweep& sw) {
  if (!scene.dynamics)
    throw output::ForcesUnavailable(scene.file + ": --forces needs the scene's \"dynamics\" object (at least its \"speed\"; "
                                    "docs/forces.md)");
  try {
    ForceLayout{scene.mechanism};  // refuses an input whose effort is not a joint's torque or force
  } catch (const std::invalid_argument& e) {
    throw output::ForcesUnavailable(scene.file + ": --forces: " + e.what());
  }
  if (o.speed.empty()) return scene.dynamics->speed;
  const bool angular = scene.mechanism.variables[static_cast<std::size_t>(sw.variable)].kind != ParamKind::Length;
  io::SpeedUnit unit;
  try {
    return io::parse_speed(o.speed, angular, scene.length, scene.speed_unit, unit) * unit.per_second;
  } catch (const std::invalid_argument& e) {
    throw UsageError("--speed: " + std::string(e.what()));
  }
}

/// `rollkin solve` on one scene (o.sweep.scene, or `loaded` when already read): assembly, sweep, outputs,
/// summary on `out`, one line per problem on `err`.
int solve_scene(const SolveOptions& o, std::optional<io::Scene> loaded, std::ostream& out, std::ostream& err) {
  std::vector<output::OutputRequest> files;
  for (const auto& [format, path] : o.files) files.push_back({"--" + format, path, format});
  output::SweepRun run = start_run(o.sweep, files, std::move(loaded));
  const io::Scene& scene = run.scene();
  const Sweep& sw = run.sweep();
  const std::vector<double>& inputs = run.inputs();
  const Mechanism<double>& m = scene.mechanism;
  if (!o.speed.empty() && !o.forces) throw UsageError("--speed sets the input speed of --forces; add --forces");
  const double speed = o.forces ? forces_speed(o, scene, sw) : 0.0;

  SolveData<double> sd(m);
  VectorX<double> q;
  g_doing = "assembling the mechanism";
  const SolveReport<double> assembly = run.assemble(sd, q);
  if (o.verbose) print_assembly(out, scene, assembly, full_rank(m, sd));
  g_doing = "solving the sweep";
  // Only the poses' values feed the outputs, the interference check and the design check: without them the
  // sweep keeps its summary alone (sweep_summary.hpp), no values, and on a fine grid interpolates the poses
  // between its sub-steps, each checked by its residual (dense output, solve/continuation.hpp).
  const bool values_needed = run.writes_files() || o.interference || o.verbose || o.forces;
  std::optional<SweepResult<double>> result;
  std::optional<io::SweepFile> file;
  SweepSummary<double> found;
  std::optional<output::SweepForceReport> forces;
  if (values_needed) {
    // The files alone read the poses in row order: kept in a temporary file, memory stays that of a summary
    // (output/sweep_file.hpp). The interference and design checks take the whole result in memory.
    std::optional<io::SweepRows> rows;
    if (o.interference || o.verbose) {
      result = run.solve(sd, q, assembly);
      found = summarise(*result);
      rows.emplace(*result);
    } else {
      file.emplace(assembly, inputs, m.variable_count());
      run.solve_into(sd, q, assembly, *file);
      found = *file;
      rows.emplace(*file);
    }
    if (o.forces && assembly.ok()) {
      g_doing = "computing the forces";
      forces = output::sweep_forces(scene, sw, *rows, sd.kin.reference, speed);
    }
    // Everything is computed before anything is written, and then written all or nothing.
    g_doing = "writing the output files";
    io::SweepOutput table = run.output(*rows, o.analysis);
    if (forces) table.forces = &forces->table;
    if (run.writes_files()) run.write(table, output::WriteOptions{o.rates, o.jobs});
  } else {
    found = run.summary(sd, q, assembly);
  }
  g_doing = "reporting";

  const std::size_t solved = found.solved();
  std::vector<std::string> problems = sweep_problems(scene, sw, found, inputs);
  const std::vector<std::string> clashes = o.interference ? interference_lines(scene, sw, *result) : std::vector<std::string>{};
  problems.insert(problems.end(), clashes.begin(), clashes.end());
  if (!assembly.ok())
    for (const auto& note : osculating_contacts(m, q)) problems.push_back(note);

  const std::string unit = scene.unit_label(sw.variable);
  std::ostringstream summary;
  summary << fs::path(scene.file).filename().string() << ": " << solved << "/" << inputs.size() << " poses solved, "
          << sw.input << " from " << io::format_number(sw.from) << " to " << io::format_number(sw.to) << (unit.empty() ? "" : " " + unit)
          << ", max residual " << io::format_number(found.max_residual, 2) << ", ";
  if (!assembly.ok()) {
    summary << "assembly failed (" << to_string(assembly.status) << ")";
  } else if (found.limits.empty()) {
    summary << "no limits met";
  } else {
    summary << found.limits.size() << " limit(s) met:";
    for (std::size_t i = 0; i < found.limits.size(); ++i)
      summary << (i ? "," : "") << " " << to_string(found.limits[i].status) << " at "
              << io::format_number(found.limits[i].limit_input / sw.unit, 8) << (unit.empty() ? "" : " " + unit);
  }
  if (!found.singular.empty()) summary << ", " << found.singular.size() << " singular pose(s)";
  out << summary.str() << "\n";
  if (forces) {
    for (const auto& l : forces->summary) out << "  " << l << "\n";
    problems.insert(problems.end(), forces->problems.begin(), forces->problems.end());
  }
  if (o.verbose) {
    const DesignReport design = design_report(scene, sw, *result);
    for (const auto& l : design.section) out << l << "\n";
    for (const auto& f : design.findings) out << "  " << f << "\n";
  }
  for (const auto& p : problems) err << scene.file << ": " << p << "\n";
  const bool forces_ok = !forces || !forces->separation_or_slip;
  return std::max({sweep_status(found, inputs.size()), clashes.empty() ? 0 : 1, forces_ok ? 0 : 1});
}

/// The options of each of several scenes: every {scene} in every output name replaced by the scene file's
/// stem. UsageError for an output name without {scene}; collisions are checked once the scenes are read
/// (check_run_outputs).
std::vector<SolveOptions> per_scene_options(const SolveOptions& o) {
  std::vector<SolveOptions> each;
  for (const std::string& file : o.scenes) {
    SolveOptions one = o;
    one.jobs = 1;  // the scenes share the threads: each formats its own CSV on the thread that solved it
    one.scenes = {file};
    one.sweep.scene = file;
    for (auto& [format, path] : one.files) {
      if (path.empty()) continue;
      if (path.find("{scene}") == std::string::npos)
        throw UsageError("--" + format + " '" + path + "': with several scenes each needs its own file; put " +
                         "{scene} in the name, e.g. 'out/{scene}.csv'");
      path = with_scene_name(path, fs::path(file).stem().string());
    }
    each.push_back(std::move(one));
  }
  return each;
}

/// What one scene of several reports: its summary and its problems, kept to be printed in the order given.
struct SceneReport {
  std::ostringstream out, err;
  int status = 0;
};

/// Runs `step` on the scene of report `r`, turning its error into the report the command line would print
/// for that scene alone.
template <class Step> void report_errors(const SolveOptions& one, SceneReport& r, Step&& step) {
  try {
    step();
  } catch (const UsageError& e) {
    r.err << "rollkin: " << one.sweep.scene << ": " << e.what() << "\n";
    r.status = 2;
  } catch (...) {
    r.status = error_status(r.err);
  }
}

/// Several scenes: all read first (on up to o.jobs threads), then every output of every scene checked against
/// every file any scene reads and against each other (check_run_outputs: a collision is exit 2, nothing
/// solved, nothing written); then each solved as alone (solve_scene), its report kept and printed in the order
/// given. A scene's own error is reported as the command line would report it alone and does not stop the
/// others. The exit status is the worst of the scenes'.
int solve_scenes(const SolveOptions& o) {
  const std::vector<SolveOptions> each = per_scene_options(o);
  std::vector<SceneReport> reports(each.size());
  std::vector<std::optional<io::Scene>> scenes(each.size());
  run_batch(each.size(), o.jobs, [&](std::size_t k, const std::atomic<bool>&) {
    report_errors(each[k], reports[k], [&] { scenes[k] = read_scene(each[k].sweep.scene); });
  });
  std::vector<PlannedScene> plan;
  for (std::size_t k = 0; k < each.size(); ++k)
    plan.push_back(PlannedScene{each[k].sweep.scene, scenes[k] ? &*scenes[k] : nullptr, output_files(each[k])});
  g_doing = "checking the output files";
  try {
    check_run_outputs(plan);
  } catch (...) {  // exit 2 before anything is solved; the scenes that could not be read are named too
    for (const SceneReport& r : reports) std::cerr << r.err.str();
    throw;
  }
  run_batch(each.size(), o.jobs, [&](std::size_t k, const std::atomic<bool>&) {
    if (!scenes[k]) return;  // its reading failed: reported
    SceneReport& r = reports[k];
    report_errors(each[k], r, [&] { r.status = solve_scene(each[k], std::move(scenes[k]), r.out, r.err); });
  });
  int status = 0;
  for (const SceneReport& r : reports) {
    std::cout << r.out.str();
    std::cerr << r.err.str();
    status = std::max(status, r.status);
  }
  return status;
}

/// `rollkin solve`: one scene, or several (solve_scenes).
int run_solve(const SolveOptions& o) {
  if (o.scenes.size() > 1) return solve_scenes(o);
  SolveOptions one = o;
  one.sweep.scene = o.scenes.front();
  return solve_scene(one, std::nullopt, std::cout, std::cerr);
}

}  // namespace
}  // namespace rollkin::cli
