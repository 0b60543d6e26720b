// build/rollkin: the command-line tool.
//
//   rollkin solve SCENE [--from V --to V --step V] [--csv FILE] [--plot FILE.svg] [--draw FILE.svg]
//                       [--animate FILE.html] [--rates] [--analysis] [--verbose] [--interference] [--max-steps N]
//   rollkin reference SCENE [--from V --to V --step V] [--digits 30|50|100] [--max-steps N] --csv FILE
//   rollkin centrodes SCENE --links A B [--from V --to V --step V] [--max-steps N] --out PREFIX
//   rollkin check SCENE [--from V --to V --step V] [--max-steps N]
//   rollkin --help | --version;  rollkin COMMAND --help
//
// Exit codes: 0 every requested input value solved; 1 some were not (a limit met, assembly failed, a singular
// pose): one line per limit or singular pose on stderr, the solved rows still written; 2 bad input (scene file, contour files, command line,
// an output that would overwrite an input, an output that cannot be written): the message on stderr and no
// output file written; 3 out of memory ("out of memory while ..."), no output file written. Outputs are all
// or nothing (rollkin/io/output_set.hpp).
//
// --animate writes one self-contained HTML page (inline SVG and script, no external file) that plays the
// solved poses: a play/pause button, a slider over the poses, the input value and each pose's status
// (src/cli/animation.hpp).
//
// The command line is parsed by CLI11. Each command is one section below: its options struct, the function
// that declares its options (descriptions are the --help text) and the function that runs it; main() lists
// the commands. A new command is one more such section and one line in main().
#include "animation.hpp"
#include "output.hpp"

#include "rollkin/design_check.hpp"
#include "rollkin/io/output_set.hpp"
#include "rollkin/io/scene.hpp"
#include "rollkin/reference.hpp"
#include "rollkin/solve/continuation.hpp"
#include "rollkin/solve/batch.hpp"
#include "rollkin/solve/interference.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <new>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#ifndef ROLLKIN_VERSION
#define ROLLKIN_VERSION "0.1.0"
#endif

namespace {

namespace fs = std::filesystem;
using namespace rollkin;

/// A command line that parses but asks for something that cannot be done (found after reading the scene).
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// What the run is doing, for the message of an allocation failure ("out of memory while ...").
thread_local const char* g_doing = "starting";  // per thread: several scenes may be solved at once (--jobs)

int error_status(std::ostream& err);

const char* kExitStatus =
    "Exit status: 0 all requested poses solved; 1 some not (limits or singular poses on stderr, solved rows\n"
    "still written); 2 bad input or command line, or a request above --max-steps (nothing written);\n"
    "3 out of memory (nothing written).";

/// A command: its CLI11 subcommand (options bound to the values the parse fills in) and the function that runs
/// it with those values.
struct Command {
  CLI::App* app;
  std::function<int()> run;
};

// ---- option values: fully parsed, checked before anything is read ------------------------------------------

/// `text` as a finite number, all of it ("1x", "", "nan", "inf" are not).
std::optional<double> finite_number(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v)) return std::nullopt;
  return v;
}

/// A check of an option's value: a finite number (for which `accept`, when given, is true). CLI11 names the
/// option in front of the message: "--step: expects a number, got \"1x\"".
CLI::Validator number(const std::string& expected, std::function<bool(double)> accept = {}) {
  return CLI::Validator(
      [expected, accept](std::string& text) -> std::string {
        const std::optional<double> v = finite_number(text);
        if (v && (!accept || accept(*v))) return {};
        return "expects " + expected + ", got \"" + text + "\"";
      },
      "", "");
}

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

/// The option `name` storing a number in `slot` when given, and the text it was given as in `text`.
CLI::Option* add_number(CLI::App& app, const std::string& name, std::optional<double>& slot, std::string& text,
                        const std::string& help) {
  return app.add_option_function<std::string>(name, [&slot, &text](const std::string& v) {
              text = v;
              slot = finite_number(v);  // the check below accepted it
            }, help)
      ->type_name("V")
      ->check(number("a number"));
}

/// The option `name` storing an output file name in `slot`.
CLI::Option* add_output(CLI::App& app, const std::string& name, std::string& slot, const std::string& help) {
  return app.add_option(name, slot, help)->type_name("FILE")->check(kFileName);
}

// ---- what every sweeping command shares: scene, sweep overrides, bounded work, outputs --------------------

/// The scene and the part of the sweep the command line may override.
struct SweepRequest {
  std::string scene;
  std::optional<double> from, to, step;
  std::string from_text, to_text, step_text;  // as given: the grid is the decimal one (solve/sweep_grid.hpp)
  double max_steps = 1e7;  // bounded work: largest estimated number of continuation sub-steps
};

/// The sweep options; the positional SCENE goes to r.scene, or, when `scenes` is given, one or more of them.
void add_sweep_options(CLI::App& app, SweepRequest& r, std::vector<std::string>* scenes = nullptr) {
  if (scenes)
    app.add_option("SCENE", *scenes, "the scene(s): JSON files (docs/scene_format.md)")->required()->type_name("");
  else
    app.add_option("SCENE", r.scene, "the scene: a JSON file (docs/scene_format.md)")->required()->type_name("");
  add_number(app, "--from", r.from, r.from_text, "first input value (overrides the scene's \"sweep\"; angles in the scene's unit)");
  add_number(app, "--to", r.to, r.to_text, "last input value (overrides the scene's \"sweep\")");
  add_number(app, "--step", r.step, r.step_text, "step between input values, signed from --from toward --to");
  app.add_option("--max-steps", r.max_steps,
                 "refuse (exit 2) a sweep estimated to need more than N continuation sub-steps (default 1e7)")
      ->type_name("N")
      ->check(number("a positive number of sub-steps (at least 1)", [](double v) { return v >= 1; }));
}

/// The sweep to run: the scene's, with the command line's overrides.
io::Sweep requested_sweep(const io::Scene& scene, const SweepRequest& r) {
  std::optional<io::Sweep> s = io::requested_sweep(scene, r.from, r.to, r.step);
  if (!s) throw UsageError(scene.file + " has no \"sweep\"; give --from, --to and --step");
  if (r.from) s->from_text = r.from_text;
  if (r.to) s->to_text = r.to_text;
  if (r.step) s->step_text = r.step_text;
  const std::string bad = io::check_sweep(*s);
  if (!bad.empty()) throw UsageError("--from/--to/--step: " + bad);
  return *s;
}

/// Bounded work: refuses before solving a request whose estimated continuation sub-steps exceed --max-steps.
void check_work(const io::Scene& scene, const io::Sweep& sw, const std::vector<double>& inputs, double max_steps) {
  const double estimate = estimate_substeps(scene.mechanism, scene.guess, sw.driver, inputs);
  if (estimate <= max_steps) return;
  std::ostringstream os;
  os << "the sweep of " << sw.input << " from " << sw.from << " to " << sw.to << " needs an estimated "
     << std::scientific << std::setprecision(2) << estimate << " continuation sub-steps, above the limit "
     << max_steps << " (--max-steps); ask for a smaller range (--from/--to), a larger --step (fewer values),"
     << " or raise the limit with --max-steps";
  throw UsageError(os.str());
}

/// The start of every sweeping command: the scene read, the output files checked against the files it read
/// (and against each other) before anything is solved, the requested sweep built and its work bounded.
/// Outputs are written all or nothing at the end (`outputs.commit()`).
struct SweepRun {
  io::Scene scene;
  io::OutputSet outputs;
  io::Sweep sweep;
  std::vector<double> inputs;  // the sweep's input values, internal units

  /// `output_files`: (option, path) of every output the command may write; path "" for one not given.
  SweepRun(const SweepRequest& r, const std::vector<std::pair<std::string, std::string>>& output_files)
      : scene(read_scene(r.scene)), outputs(files_read(scene)) {
    g_doing = "checking the output files";
    for (const auto& [option, path] : output_files)
      if (!path.empty()) given_[option] = outputs.add(option, path);
    sweep = requested_sweep(scene, r);
    inputs = io::sweep_inputs(sweep);
    check_work(scene, sweep, inputs, r.max_steps);
  }

  /// Sets the content of the output file named by `option`, if the command line gave one (`make_text` is
  /// called only then).
  void set_output(const std::string& option, const std::function<std::string()>& make_text) {
    const auto it = given_.find(option);
    if (it != given_.end()) outputs.set(it->second, make_text());
  }

  /// The same for an output streamed into its file at commit (io::OutputSet::set_writer).
  void stream_output(const std::string& option, std::function<void(io::OutputSink&)> write) {
    const auto it = given_.find(option);
    if (it != given_.end()) outputs.set_writer(it->second, std::move(write));
  }

 private:
  std::map<std::string, std::size_t> given_;  // option -> index in `outputs`, for the outputs given

  static io::Scene read_scene(const std::string& file) {
    g_doing = "reading the scene";
    return io::load_scene(file);
  }
  static std::vector<std::string> files_read(const io::Scene& scene) {
    std::vector<std::string> files{scene.file};
    files.insert(files.end(), scene.files_read.begin(), scene.files_read.end());
    return files;
  }
};

/// Assembles the scene's mechanism into q (sd ready for sweep()). Inconsistent constraints at assembly are a
/// problem of the scene (sizes, frames, values), not a motion limit: an InputError (exit 2, nothing written).
SolveReport<double> assemble_scene(const io::Scene& scene, SolveData<double>& sd, VectorX<double>& q) {
  g_doing = "assembling the mechanism";
  q = scene.guess;
  const SolveReport<double> assembly = assemble(scene.mechanism, q, sd, scene.held);
  if (assembly.status == SolveStatus::CannotAssemble) throw io::assembly_error(scene, assembly.detail);
  return assembly;
}

// ---- messages and reports ---------------------------------------------------------------------------------

std::string fmt(double v, int digits = 6) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

/// "O_A.theta2 = -57.397 deg" in the file's units.
std::string input_text(const io::Scene& scene, const io::Sweep& sw, double internal) {
  const std::string unit = scene.unit_label(sw.variable);
  return sw.input + " = " + fmt(internal / sw.unit, 8) + (unit.empty() ? "" : " " + unit);
}

/// One line per limit for stderr, the input in the file's units.
std::string limit_line(const io::Scene& scene, const io::Sweep& sw, const SolveReport<double>& r) {
  const Mechanism<double>& m = scene.mechanism;
  const std::string where = input_text(scene, sw, r.limit_input);
  switch (r.status) {
    case SolveStatus::DeadPoint:
      return "dead_point: dead point (motion limit) at " + where + ": the mechanism cannot move past it (Jacobian " +
             "singular there, condition " + fmt(r.condition, 3) + ")";
    case SolveStatus::DomainExit: {
      std::string what = "a contact leaves its contour";
      if (r.pair >= 0 && r.contour >= 0)
        what = "the contact of pair '" + m.pairs[r.pair].name + "' leaves the end of contour '" + m.contours[r.contour].name() + "'";
      return "domain_exit: " + what + " at " + where;
    }
    case SolveStatus::Corner: {
      const ContourCorner<double>& k = m.contours[r.contour].corners()[static_cast<std::size_t>(r.corner)];
      return "corner: the contact of pair '" + m.pairs[r.pair].name + "' reaches a corner of contour '" +
             m.contours[r.contour].name() + "' (" + k.label + "; (" + fmt(k.point.x(), 10) + ", " + fmt(k.point.y(), 10) +
             ") in the contour's frame) at " + where + ": a contact cannot pass a corner";
    }
    case SolveStatus::NoConvergence: return "no_convergence: Newton-Raphson does not converge beyond " + where;
    default: return std::string(to_string(r.status)) + ": " + r.detail + " (at " + where + ")";
  }
}

/// One line per problem of a sweep: a failed assembly, each limit met, each singular pose (counted in
/// `singular`).
std::vector<std::string> sweep_problems(const io::Scene& scene, const io::Sweep& sw, const SolveReport<double>& assembly,
                                        const SweepResult<double>& result, std::size_t& singular) {
  std::vector<std::string> problems;
  if (!assembly.ok())
    problems.push_back(std::string(to_string(assembly.status)) + ": assembly failed: " +
                       (assembly.detail.empty() ? "the mechanism cannot be assembled" : assembly.detail) +
                       " (rank " + std::to_string(assembly.rank) + " of " + std::to_string(assembly.unknowns) +
                       " unknowns, condition " + fmt(assembly.condition, 3) + ")");
  for (const auto& l : result.limits) problems.push_back(limit_line(scene, sw, l));
  singular = 0;
  for (const auto& p : result.poses)
    if (p.report.status == SolveStatus::Singular) {
      ++singular;
      problems.push_back("singular: singular pose at " + input_text(scene, sw, p.input) +
                         ": the branches meet / Jacobian singular; values follow the branch (interpolated between"
                         " the regular poses on both sides, condition " + fmt(p.report.condition, 3) + ")");
    }
  return problems;
}

void print_assembly(std::ostream& out, const io::Scene& scene, const SolveReport<double>& rep, const cli::AssemblyRank& ar) {
  const Mechanism<double>& m = scene.mechanism;
  for (const std::string& n : scene.notes) out << "contour " << n << "\n";
  out << "assembly: " << to_string(rep.status) << " after " << rep.iterations << " iteration(s), residual "
            << fmt(rep.residual, 3) << "\n"
            << "  variables " << m.variable_count() << " (inputs " << m.drivers.size() << ", unknowns " << m.unknowns.size()
            << "), equations " << m.equation_count() << " (" << m.loops.size() << " loop(s) x 3 + "
            << m.rolling_pairs.size() << " rolling)\n"
            << "  rank of the unknowns' Jacobian " << rep.rank << ", condition " << fmt(rep.condition, 3) << "\n"
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
    if (!is_contact(m.pairs[k].kind)) continue;
    const double ka = kin.pairs[k].contact[0].curvature(), kb = kin.pairs[k].contact[1].curvature();
    const double size = std::max(std::abs(ka), std::abs(kb));
    if (size > 0 && std::abs(ka + kb) <= 1e-6 * size)
      out.push_back("osculation: at the assembly pose the contours of pair '" + m.pairs[k].name +
                    "' osculate (signed curvatures " + fmt(ka) + " and " + fmt(kb) +
                    " cancel), so the contact Jacobian is singular there; choose another assembly pose or geometry");
  }
  return out;
}

/// --interference: contours sampled once in their links' frames and checked at every solved pose
/// (solve/interference.hpp); one line per run of consecutive poses with the same finding, inputs in the
/// file's units, with the chords' distance from the curves and the touch tolerance.
std::vector<std::string> interference_lines(const io::Scene& scene, const io::Sweep& sw, const SweepResult<double>& result) {
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
                    "' and '" + m.contours[r.b].name() + "' for " + sw.input + " from " + fmt(r.from / sw.unit, 8) +
                    " to " + fmt(r.to / sw.unit, 8) + (unit.empty() ? "" : " " + unit) + " (decided on chords within " +
                    fmt(std::max(si.chord_error[r.a], si.chord_error[r.b]), 2) + " " + scene.length_unit +
                    " of the contours, touch tolerance " + fmt(si.touch_tolerance, 2) + " " + scene.length_unit + ")");
  return lines;
}

// ---- the design check (rollkin check, solve --verbose) ---------------------------------------------------

/// The design check's text: the report section for stdout and one located line per impossible design
/// (a pair whose contours interpenetrate: a roller too large for a concave part of the other contour).
struct DesignReport {
  std::vector<std::string> section, findings;
};

/// A contour's name as the scene's pairs give it ("link.contour").
std::string contour_name(const Mechanism<double>& m, int contour) { return m.contours[contour].name(); }

/// "u = 12.5 deg (point 3, 0)": a contour point by its parameter (the pair variable's file unit) and its
/// coordinates in the contour's own frame (scene units).
std::string point_text(const io::Scene& scene, int variable, const TouchedPoint<double>& t) {
  const std::string unit = scene.unit_label(variable);
  const Mechanism<double>& m = scene.mechanism;
  return m.variables[variable].name + " = " + fmt(t.u / scene.unit_of(variable), 10) + (unit.empty() ? "" : " " + unit) +
         " (point " + fmt(t.point.x(), 10) + ", " + fmt(t.point.y(), 10) + ")";
}

/// The curvature line(s) of one contour of a pair: its sharpest convex and concave points touched.
std::vector<std::string> curvature_lines(const io::Scene& scene, const io::Sweep& sw, int variable,
                                         const ContourCurvatureCheck<double>& c) {
  const std::string name = contour_name(scene.mechanism, c.contour);
  if (c.circle) {
    const bool convex = c.sharpest_convex.found;
    return {name + ": circle of radius " + fmt(c.radius, 10) + (convex ? " (convex)" : " (concave)")};
  }
  std::vector<std::string> lines;
  if (c.sharpest_convex.found)
    lines.push_back(name + ": smallest convex radius of curvature " + fmt(1 / c.sharpest_convex.kappa, 10) + " at " +
                    point_text(scene, variable, c.sharpest_convex) + ", " + input_text(scene, sw, c.sharpest_convex.input));
  if (c.sharpest_concave.found)
    lines.push_back(name + ": smallest concave radius of curvature " + fmt(-1 / c.sharpest_concave.kappa, 10) + " at " +
                    point_text(scene, variable, c.sharpest_concave) + ", " + input_text(scene, sw, c.sharpest_concave.input));
  if (lines.empty()) lines.push_back(name + ": straight where touched");
  return lines;
}

/// The located message of a pair whose contours interpenetrate.
std::string finding_line(const io::Scene& scene, const io::Sweep& sw, const PairDesignCheck<double>& d) {
  const Mechanism<double>& m = scene.mechanism;
  const Pair<double>& p = m.pairs[d.pair];
  const std::string where = input_text(scene, sw, d.worst[0].input);
  const std::string sum = "kappa1 + kappa2 = " + fmt(d.worst_relative) + " < 0";
  if (d.roller < 0)
    return "interpenetration: the contours '" + contour_name(m, p.contour_a) + "' and '" + contour_name(m, p.contour_b) +
           "' of pair '" + p.name + "' interpenetrate next to their contact at " +
           point_text(scene, p.first_variable, d.worst[0]) + " and " + point_text(scene, p.first_variable + 1, d.worst[1]) +
           ", " + where + " (" + sum + "; curvatures " + fmt(d.worst[0].kappa) + " and " + fmt(d.worst[1].kappa) +
           "): the design is impossible there";
  const int other = 1 - d.roller;
  const int variable = p.first_variable + other;
  const std::string wall = contour_name(m, d.contours[other].contour);
  const double r = d.contours[d.roller].radius;
  std::string line = "undercut: pair '" + p.name + "': the roller '" + contour_name(m, d.contours[d.roller].contour) +
                     "' (radius " + fmt(r, 10) + ") is larger than the concave radius " +
                     fmt(-1 / d.worst[other].kappa, 10) + " of '" + wall + "' it must enter at " +
                     point_text(scene, variable, d.worst[other]) + ", " + where + " (" + sum +
                     ": the contours interpenetrate)";
  std::vector<std::string> ends;
  for (const auto& c : d.cusps)
    if (c.found) ends.push_back(point_text(scene, variable, c));
  if (!ends.empty()) {
    line += "; the roller-centre path (the offset of '" + wall + "' by " + fmt(r, 10) + ") has a cusp at " + ends[0];
    if (ends.size() > 1) line += " and at " + ends[1];
    line += ends.size() > 1 ? ": the roller cannot follow the contour between them" : "";
  }
  return line;
}

/// A roller against the concave parts it must enter: "roller 'f.roller' (radius 1.5) in 'cam.groove': ...".
std::string roller_line(const Mechanism<double>& m, const PairDesignCheck<double>& d) {
  const ContourCurvatureCheck<double>& roller = d.contours[d.roller];
  const ContourCurvatureCheck<double>& other = d.contours[1 - d.roller];
  std::string line = "roller '" + contour_name(m, roller.contour) + "' (radius " + fmt(roller.radius, 10) + ") on '" +
                     contour_name(m, other.contour) + "': ";
  if (!other.sharpest_concave.found) return line + "no concave part touched";
  const double rho = -1 / other.sharpest_concave.kappa;
  if (d.conformity == Conformity::Interpenetrating) return line + "too large for its smallest concave radius " + fmt(rho, 10);
  return line + "fits its smallest concave radius " + fmt(rho, 10) +
         (d.conformity == Conformity::Osculating ? " (equal: osculating)" : "");
}

/// The design check of a solved sweep (rollkin/design_check.hpp) as text.
DesignReport design_report(const io::Scene& scene, const io::Sweep& sw, const SweepResult<double>& result) {
  const Mechanism<double>& m = scene.mechanism;
  const DesignCheck<double> check = check_design(m, result);
  DesignReport out;
  out.section.push_back("design check (radii of curvature where the contours touch, undercut, conformity):");
  if (check.pairs.empty()) out.section.push_back("  no cam or rolling pair");
  for (const auto& d : check.pairs) {
    const Pair<double>& p = m.pairs[d.pair];
    out.section.push_back("  pair '" + p.name + "' (" + to_string(p.kind) + "), '" + contour_name(m, p.contour_a) +
                          "' on '" + contour_name(m, p.contour_b) + "':");
    if (!d.touched) {
      out.section.push_back("    no solved pose: nothing touched");
      continue;
    }
    for (int side = 0; side < 2; ++side)
      for (const auto& l : curvature_lines(scene, sw, p.first_variable + side, d.contours[side]))
        out.section.push_back("    " + l);
    if (d.roller >= 0) out.section.push_back("    " + roller_line(m, d));
    out.section.push_back("    smallest relative curvature kappa1 + kappa2 = " + fmt(d.worst_relative, 10) + " at " +
                          input_text(scene, sw, d.worst[0].input) + ": " + to_string(d.conformity));
    if (d.conformity == Conformity::Interpenetrating) out.findings.push_back(finding_line(scene, sw, d));
  }
  out.section.push_back(out.findings.empty() ? "  no undercut or interpenetration"
                                             : "  " + std::to_string(out.findings.size()) + " pair(s) impossible (stderr)");
  return out;
}

// ---- rollkin solve ---------------------------------------------------------------------------------------

struct SolveOptions {
  SweepRequest sweep;
  std::vector<std::string> scenes;  // the scene files given; sweep.scene is each in turn
  std::string csv, plot, draw, animate;
  bool rates = false, analysis = false, verbose = false, interference = false;
  int jobs = 0;  // scenes solved at once (0: one per core)
};

int run_solve(const SolveOptions& o);

Command solve_command(CLI::App& rollkin) {
  auto o = std::make_shared<SolveOptions>();
  CLI::App* app = rollkin.add_subcommand("solve", "assemble the mechanism and sweep its input (double precision)");
  add_sweep_options(*app, o->sweep, &o->scenes);
  add_output(*app, "--csv", o->csv, "one row per input value: input, pair variables, link poses, residual, status");
  add_output(*app, "--plot", o->plot, "SVG chart of the pair variables against the input");
  add_output(*app, "--draw", o->draw, "SVG drawing of the mechanism at four poses across the solved range, one panel each");
  add_output(*app, "--animate", o->animate,
             "self-contained HTML page animating the mechanism over the solved poses (play/pause, slider)");
  app->add_flag("--rates", o->rates, "add the rate columns d(var)/d(input) to the CSV");
  app->add_flag("--analysis", o->analysis,
                "add the contact analysis columns to the CSV and charts to the plot: pressure angle, sliding, "
                "curvatures, link accelerations and jerks (docs/analysis.md)");
  app->add_flag("-v,--verbose", o->verbose,
                "print the assembly report, how imported contours were converted and the design check (as 'rollkin check')");
  app->add_flag("--interference", o->interference,
                "check every solved pose for contours that penetrate or touch twice (findings make exit 1)");
  app->add_option("-j,--jobs", o->jobs, "with several scenes: how many are solved at once (default 0: one per core)")
      ->type_name("N")
      ->check(number("a number of scenes at once (0: one per core)", [](double v) { return v >= 0 && v == std::floor(v); }));
  app->footer(
      "Loads the scene, assembles the mechanism and sweeps its input over the scene's \"sweep\" (--from/--to/\n"
      "--step override it), following one branch in both directions from the assembly pose.\n"
      "CSV columns: angles in degrees, lengths in scene units. Without output options a one-line summary is\n"
      "printed.\n"
      "Status column: ok; singular (branches meet there, the Jacobian is singular: the values follow the branch,\n"
      "interpolated between regular poses on both sides; a line on stderr, exit status 1); dead_point,\n"
      "domain_exit, corner, no_convergence (a limit met: one line on stderr); not_reached (beyond a limit).\n"
      "--max-steps: the estimate is the input's travel over the largest sub-step (5 deg for angles) plus the\n"
      "number of values.\n"
      "Several scenes (rollkin solve A.json B.json ... --jobs N): each is solved as if alone, N at a time, with\n"
      "the same options; every output name must contain {scene}, replaced by each scene file's name without\n"
      "its extension (--csv 'out/{scene}.csv'). Reports come in the order the scenes were given; a scene that\n"
      "fails does not stop the others; the exit status is the worst of the scenes'.\n" +
      std::string(kExitStatus));
  return {app, [o] { return run_solve(*o); }};
}

/// `rollkin solve` on one scene (o.sweep.scene): assembly, sweep, outputs, summary on `out`, one line per
/// problem on `err`.
int solve_scene(const SolveOptions& o, std::ostream& out, std::ostream& err) {
  SweepRun run(o.sweep, {{"--csv", o.csv}, {"--plot", o.plot}, {"--draw", o.draw}, {"--animate", o.animate}});
  const io::Scene& scene = run.scene;
  const io::Sweep& sw = run.sweep;
  const std::vector<double>& inputs = run.inputs;
  const Mechanism<double>& m = scene.mechanism;

  SolveData<double> sd(m);
  VectorX<double> q;
  const SolveReport<double> assembly = assemble_scene(scene, sd, q);
  if (o.verbose) print_assembly(out, scene, assembly, cli::full_rank(m, sd));
  g_doing = "solving the sweep";
  const SweepResult<double> result = sweep(m, sd, q, assembly, sw.driver, inputs);

  // Everything is computed before anything is written, and then written all or nothing.
  g_doing = "building the output files";
  const std::vector<double> file_values = io::sweep_values(sw);
  const cli::SweepAnalysis analysis = o.analysis ? cli::analyse_sweep(m, result) : cli::SweepAnalysis{};
  const cli::OutputContext ctx{scene, sw, result, file_values, o.analysis ? &analysis : nullptr};
  run.stream_output("--csv", [&](io::OutputSink& sink) { io::write_sweep_csv(ctx, o.rates, sink); });
  run.set_output("--plot", [&] { return cli::plot_svg(ctx); });
  run.set_output("--draw", [&] { return cli::draw_svg(ctx); });
  run.set_output("--animate", [&] { return cli::animation_html(ctx); });
  g_doing = "writing the output files";
  run.outputs.commit();
  g_doing = "reporting";

  std::size_t solved = 0;
  double max_residual = 0;
  for (const auto& p : result.poses)
    if (p.report.ok()) {
      ++solved;
      max_residual = std::max(max_residual, p.report.residual);
    }
  std::size_t singular = 0;
  std::vector<std::string> problems = sweep_problems(scene, sw, assembly, result, singular);
  const std::vector<std::string> clashes = o.interference ? interference_lines(scene, sw, result) : std::vector<std::string>{};
  problems.insert(problems.end(), clashes.begin(), clashes.end());
  if (!assembly.ok())
    for (const auto& note : osculating_contacts(m, q)) problems.push_back(note);

  const std::string unit = scene.unit_label(sw.variable);
  std::ostringstream summary;
  summary << fs::path(scene.file).filename().string() << ": " << solved << "/" << inputs.size() << " poses solved, "
          << sw.input << " from " << fmt(sw.from) << " to " << fmt(sw.to) << (unit.empty() ? "" : " " + unit)
          << ", max residual " << fmt(max_residual, 2) << ", ";
  if (!assembly.ok()) {
    summary << "assembly failed (" << to_string(assembly.status) << ")";
  } else if (result.limits.empty()) {
    summary << "no limits met";
  } else {
    summary << result.limits.size() << " limit(s) met:";
    for (std::size_t i = 0; i < result.limits.size(); ++i)
      summary << (i ? "," : "") << " " << to_string(result.limits[i].status) << " at "
              << fmt(result.limits[i].limit_input / sw.unit, 8) << (unit.empty() ? "" : " " + unit);
  }
  if (singular) summary << ", " << singular << " singular pose(s)";
  out << summary.str() << "\n";
  if (o.verbose) {
    const DesignReport design = design_report(scene, sw, result);
    for (const auto& l : design.section) out << l << "\n";
    for (const auto& f : design.findings) out << "  " << f << "\n";
  }
  for (const auto& p : problems) err << scene.file << ": " << p << "\n";
  return solved == inputs.size() && assembly.ok() && clashes.empty() ? 0 : 1;
}

/// The options of each of several scenes: {scene} in every output name replaced by the scene file's stem.
/// UsageError for an output name without {scene}, two scenes with the same stem, or an output that would
/// be one of the scene files.
std::vector<SolveOptions> per_scene_options(const SolveOptions& o) {
  std::vector<SolveOptions> each;
  std::map<std::string, std::string> stems;  // stem -> scene file
  for (const std::string& file : o.scenes) {
    const std::string stem = fs::path(file).stem().string();
    const auto [at, fresh] = stems.emplace(stem, file);
    if (!fresh)
      throw UsageError("scenes '" + at->second + "' and '" + file + "' have the same name \"" + stem +
                       "\": their output files ({scene}) would be the same; rename one");
    SolveOptions one = o;
    one.scenes = {file};
    one.sweep.scene = file;
    for (auto [option, path] : {std::pair{"--csv", &one.csv}, {"--plot", &one.plot}, {"--draw", &one.draw},
                                {"--animate", &one.animate}}) {
      if (path->empty()) continue;
      const std::size_t at_token = path->find("{scene}");
      if (at_token == std::string::npos)
        throw UsageError(std::string(option) + " '" + *path + "': with several scenes each needs its own file; put " +
                         "{scene} in the name, e.g. 'out/{scene}.csv'");
      path->replace(at_token, 7, stem);
      for (const std::string& input : o.scenes)
        if (std::error_code ec; fs::equivalent(*path, input, ec))
          throw UsageError(std::string(option) + " '" + *path + "' is the scene file '" + input +
                           "'; inputs are never overwritten, choose another name");
    }
    each.push_back(std::move(one));
  }
  return each;
}

/// Several scenes: each solved as alone (solve_scene) on up to o.jobs threads, its report kept and printed in
/// the order given; a scene's error is reported as the command line would report it alone and does not stop
/// the others. The exit status is the worst of the scenes'.
int solve_scenes(const SolveOptions& o) {
  const std::vector<SolveOptions> each = per_scene_options(o);
  struct Report {
    std::ostringstream out, err;
    int status = 0;
  };
  std::vector<Report> reports(each.size());
  run_batch(each.size(), o.jobs, [&](std::size_t k, const std::atomic<bool>&) {
    Report& r = reports[k];
    try {
      r.status = solve_scene(each[k], r.out, r.err);
    } catch (const UsageError& e) {
      r.err << "rollkin: " << each[k].sweep.scene << ": " << e.what() << "\n";
      r.status = 2;
    } catch (...) {
      r.status = error_status(r.err);
    }
  });
  int status = 0;
  for (const Report& r : reports) {
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
  return solve_scene(one, std::cout, std::cerr);
}


// ---- rollkin reference -----------------------------------------------------------------------------------

struct ReferenceOptions {
  SweepRequest sweep;
  int digits = 50;  // MPFR precision in decimal digits: 30, 50 or 100
  std::string csv;
};

int run_reference(const ReferenceOptions& o);

Command reference_command(CLI::App& rollkin) {
  auto o = std::make_shared<ReferenceOptions>();
  CLI::App* app = rollkin.add_subcommand("reference", "the same assembly and sweep in MPFR, written as decimal strings");
  add_sweep_options(*app, o->sweep);
  app->add_option_function<double>(
         "--digits", [o](double d) { o->digits = static_cast<int>(d); },
         "MPFR precision in decimal digits: 30, 50 or 100 (default 50)")
      ->type_name("N")
      ->check(number("30, 50 or 100", [](double d) { return d == 30 || d == 50 || d == 100; }));
  add_output(*app, "--csv", o->csv, "the poses as decimal strings (required: reference writes a CSV only)")->required();
  app->footer(
      "Runs the same assembly and sweep as 'solve' in MPFR and writes the poses as decimal strings (columns as\n"
      "the solve CSV without link poses): reference data for regression tests and for measuring the double\n"
      "solver's error.\n" +
      std::string(kExitStatus));
  return {app, [o] { return run_reference(*o); }};
}

/// `rollkin reference`: the same assembly and sweep in MPFR, written as decimal strings (rollkin/reference.hpp).
int run_reference(const ReferenceOptions& o) {
  SweepRun run(o.sweep, {{"--csv", o.csv}});
  const io::Scene& scene = run.scene;
  const io::Sweep& sw = run.sweep;
  const Mechanism<double>& m = scene.mechanism;
  g_doing = "computing the reference sweep in MPFR";
  const ReferenceSweep ref = io::scene_reference(scene, sw, o.digits);
  g_doing = "writing the output file";
  run.set_output("--csv", [&] { return reference_csv_text(ref, m); });
  run.outputs.commit();
  std::size_t solved = 0;
  for (const auto& p : ref.poses) solved += p.status == SolveStatus::Converged ? 1 : 0;
  std::cout << fs::path(scene.file).filename().string() << ": " << solved << "/" << ref.poses.size()
            << " poses solved at " << o.digits << " digits, written to " << o.csv << "\n";
  return solved == ref.poses.size() ? 0 : 1;
}

// ---- rollkin centrodes -----------------------------------------------------------------------------------

struct CentrodesOptions {
  SweepRequest sweep;
  std::vector<std::string> links;  // A B
  std::string out;                 // prefix of PREFIX.A.txt and PREFIX.B.txt
  std::string dxf;                 // both centrodes as SPLINE entities (optional)
};

int run_centrodes(const CentrodesOptions& o);

Command centrodes_command(CLI::App& rollkin) {
  auto o = std::make_shared<CentrodesOptions>();
  CLI::App* app = rollkin.add_subcommand("centrodes", "loci of the instant centre of two links' relative motion, as point files");
  add_sweep_options(*app, o->sweep);
  app->add_option("--links", o->links, "the two links A and B (names in the scene)")->expected(2)->required()->type_name("A B");
  add_output(*app, "--out", o->out, "prefix of the files PREFIX.A.txt (centrode in A's frame) and PREFIX.B.txt")
      ->required()
      ->type_name("PREFIX");
  add_output(*app, "--dxf", o->dxf, "both centrodes as DXF SPLINE entities for CAD, on layers named after A and B");
  app->footer(
      "Sweeps the scene like 'solve' and writes, for every input value in sweep order, the instant centre of\n"
      "the motion of link B relative to link A (from the velocity solution) in A's frame (PREFIX.A.txt: the\n"
      "fixed centrode when A is the ground) and in B's frame (PREFIX.B.txt), in the point-file format a\n"
      "\"samples\" contour reads: rolled on each other as a rolling pair they reproduce the relative motion.\n"
      "A value where the centre is at infinity (pure relative translation) or that was not solved is a comment\n"
      "line in both files and a line on stderr (exit status 1).\n"
      "--dxf: each run of consecutive centres as the cubic spline through them (exact NURBS form of the\n"
      "spline a \"samples\" contour fits to the points; closed when the sweep ends where it starts).\n" +
      std::string(kExitStatus));
  return {app, [o] { return run_centrodes(*o); }};
}

/// A link of the scene named on the command line (--links).
int named_link(const Mechanism<double>& m, const std::string& name) {
  const int i = m.find_link(name);
  if (i >= 0) return i;
  std::string names;
  for (const Link& l : m.links) names += (names.empty() ? "\"" : ", \"") + l.name + "\"";
  throw UsageError("--links: no link \"" + name + "\" in the scene; its links are " + names);
}

/// `rollkin centrodes`: the sweep, then the instant centre at every pose, written as two point files.
int run_centrodes(const CentrodesOptions& o) {
  if (o.links[0] == o.links[1]) throw UsageError("--links: give two different links, got \"" + o.links[0] + "\" twice");
  const std::string file_a = o.out + "." + o.links[0] + ".txt", file_b = o.out + "." + o.links[1] + ".txt";
  SweepRun run(o.sweep, {{"--out (link A)", file_a}, {"--out (link B)", file_b}, {"--dxf", o.dxf}});
  const io::Scene& scene = run.scene;
  const Mechanism<double>& m = scene.mechanism;
  const int a = named_link(m, o.links[0]), b = named_link(m, o.links[1]);

  SolveData<double> sd(m);
  VectorX<double> q;
  const SolveReport<double> assembly = assemble_scene(scene, sd, q);
  g_doing = "solving the sweep";
  const SweepResult<double> result = sweep(m, sd, q, assembly, run.sweep.driver, run.inputs);
  g_doing = "computing the instant centres";
  const std::vector<InstantCentre<double>> centres = centrodes(m, sd.kin, result, a, b);

  g_doing = "building the output files";
  const std::vector<double> file_values = io::sweep_values(run.sweep);
  const cli::OutputContext ctx{scene, run.sweep, result, file_values};
  run.set_output("--out (link A)", [&] { return cli::centrode_text(ctx, centres, a, b, true); });
  run.set_output("--out (link B)", [&] { return cli::centrode_text(ctx, centres, a, b, false); });
  run.set_output("--dxf", [&] { return cli::centrode_dxf(ctx, centres, a, b); });
  g_doing = "writing the output files";
  run.outputs.commit();

  std::size_t finite = 0;
  std::vector<std::string> problems;
  for (const auto& l : result.limits) problems.push_back(limit_line(scene, run.sweep, l));
  for (std::size_t k = 0; k < centres.size(); ++k) {
    if (centres[k].finite) {
      ++finite;
    } else if (result.poses[k].report.has_pose()) {
      problems.push_back("centre at infinity at " + input_text(scene, run.sweep, run.inputs[k]) +
                         ": link '" + o.links[1] + "' translates relative to link '" + o.links[0] +
                         "' (no point written; a comment line marks the place in both files)");
    }
  }
  std::cout << fs::path(scene.file).filename().string() << ": " << finite << "/" << centres.size()
            << " instant centres of '" << o.links[1] << "' relative to '" << o.links[0] << "' written to " << file_a
            << " and " << file_b << "\n";
  for (const auto& p : problems) std::cerr << scene.file << ": " << p << "\n";
  return finite == centres.size() ? 0 : 1;
}

// ---- rollkin check ---------------------------------------------------------------------------------------

struct CheckOptions {
  SweepRequest sweep;
};

int run_check(const CheckOptions& o);

Command check_command(CLI::App& rollkin) {
  auto o = std::make_shared<CheckOptions>();
  CLI::App* app = rollkin.add_subcommand("check", "undercut and conformity check of the contact pairs over the sweep");
  add_sweep_options(*app, o->sweep);
  app->footer(
      "Sweeps the scene like 'solve' and reports, for every cam and rolling pair, the smallest convex and\n"
      "concave radius of curvature each contour has where it is touched (between the solved poses too), and the\n"
      "smallest relative curvature kappa1 + kappa2 with an exact sign test: below zero the contours interpenetrate\n"
      "next to the contact, e.g. a roller larger than a concave radius it must enter (undercut: its centre's path,\n"
      "the offset of the other contour, has cusps). docs/analysis.md, \"Design check\".\n"
      "Exit status: 0 the design is possible over the solved sweep; 1 a pair interpenetrates (one located line per\n"
      "pair on stderr: pair, contours, contour parameter and point, input, radii), or the sweep met a limit or a\n"
      "singular pose (one line each: the check covers the solved poses only); 2 bad input or command line; 3 out\n"
      "of memory.");
  return {app, [o] { return run_check(*o); }};
}

/// `rollkin check`: assembly, sweep, the design check on stdout, findings and sweep problems on stderr.
int run_check(const CheckOptions& o) {
  SweepRun run(o.sweep, {});
  const io::Scene& scene = run.scene;
  const io::Sweep& sw = run.sweep;
  const Mechanism<double>& m = scene.mechanism;
  SolveData<double> sd(m);
  VectorX<double> q;
  const SolveReport<double> assembly = assemble_scene(scene, sd, q);
  g_doing = "solving the sweep";
  const SweepResult<double> result = sweep(m, sd, q, assembly, sw.driver, run.inputs);
  g_doing = "checking the design";
  const DesignReport design = design_report(scene, sw, result);
  std::size_t singular = 0;
  std::vector<std::string> problems = sweep_problems(scene, sw, assembly, result, singular);
  std::size_t solved = 0;
  for (const auto& p : result.poses) solved += p.report.has_pose() ? 1 : 0;
  const std::string unit = scene.unit_label(sw.variable);
  std::cout << fs::path(scene.file).filename().string() << ": " << solved << "/" << run.inputs.size()
            << " poses solved, " << sw.input << " from " << fmt(sw.from) << " to " << fmt(sw.to)
            << (unit.empty() ? "" : " " + unit) << "\n";
  for (const auto& l : design.section) std::cout << l << "\n";
  for (const auto& f : design.findings) std::cerr << scene.file << ": " << f << "\n";
  for (const auto& p : problems) std::cerr << scene.file << ": " << p << "\n";
  return design.findings.empty() && problems.empty() ? 0 : 1;
}

// ---- main: the commands --------------------------------------------------------------------------------

/// CLI11's "The following argument was not expected: X" in rollkin's words: what X was taken for and what
/// was expected. The arguments are named in command-line order.
std::string unexpected_argument(const CLI::App& rollkin, const CLI::App* command, int argc, char** argv) {
  const std::vector<std::string> extras = rollkin.remaining(true);
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (std::find(extras.begin(), extras.end(), a) == extras.end()) continue;
    if (a.size() > 1 && a[0] == '-' && !finite_number(a)) {
      if (!command) return "unknown option \"" + a + "\"; expected a command first";
      std::string names;
      for (const CLI::Option* opt : command->get_options())
        if (!opt->get_positional() && opt != command->get_help_ptr()) names += (names.empty() ? "" : ", ") + opt->get_name();
      return "unknown option \"" + a + "\" for " + command->get_name() + "; expected one of " + names;
    }
    if (!command) return "unknown command \"" + a + "\"";
    return "unexpected argument \"" + a + "\": " + command->get_name() + " takes one SCENE file";
  }
  return {};
}

/// Inside a catch block: the message for the exception being handled (other than a UsageError) on `err`, and
/// the exit status: 3 out of memory, 2 anything else (bad input, an output that cannot be written).
int error_status(std::ostream& err) {
  try {
    throw;
  } catch (const std::bad_alloc&) {
    err << "rollkin: out of memory while " << g_doing
        << "; nothing was written (a smaller sweep, fewer samples or more memory may help)\n";
    return 3;
  } catch (const InputError& e) {
    err << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    err << "rollkin: error: " << e.what() << "\n";
    return 2;
  } catch (...) {
    err << "rollkin: unexpected error\n";
    return 2;
  }
}

/// "rollkin: <what is wrong>" and where to read what is expected; exit status 2.
int usage_error(const std::string& what, const CLI::App* command, const std::vector<Command>& commands) {
  std::cerr << "rollkin: " << what << "\n";
  if (command) {
    std::cerr << "(rollkin " << command->get_name() << " --help lists its options)\n";
  } else {
    std::string names;
    for (const Command& c : commands) names += (names.empty() ? "" : ", ") + c.app->get_name();
    std::cerr << "(expected a command: " << names << "; rollkin --help for usage)\n";
  }
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App rollkin("rollkin: kinematic analysis of planar mechanisms with rolling pairs", "rollkin");
  rollkin.set_version_flag("--version", "rollkin " ROLLKIN_VERSION);
  rollkin.get_formatter()->column_width(24);
  rollkin.footer("Run 'rollkin COMMAND --help' for the options of a command, e.g. 'rollkin solve --help'.\n" +
                 std::string(kExitStatus));
  const std::vector<Command> commands{solve_command(rollkin), reference_command(rollkin), centrodes_command(rollkin),
                                      check_command(rollkin)};
  const CLI::App* chosen = nullptr;
  try {
    try {
      rollkin.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
      if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return rollkin.exit(e);  // --help, --version
      const std::vector<CLI::App*> given = rollkin.get_subcommands();
      const CLI::App* command = given.empty() ? nullptr : given.front();
      const std::string unexpected = dynamic_cast<const CLI::ExtrasError*>(&e) ? unexpected_argument(rollkin, command, argc, argv) : "";
      return usage_error(unexpected.empty() ? e.what() : unexpected, command, commands);
    }
    for (const Command& c : commands)
      if (c.app->parsed()) {
        chosen = c.app;
        return c.run();
      }
    return usage_error("missing command", nullptr, commands);
  } catch (const UsageError& e) {
    return usage_error(e.what(), chosen, commands);
  } catch (...) {
    return error_status(std::cerr);
  }
}
