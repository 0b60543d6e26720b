// build/rollkin: the command-line tool.
//
//   rollkin solve SCENE [--from V --to V --step V] [--csv FILE] [--plot FILE.svg] [--draw FILE.svg]
//                       [--rates] [--verbose] [--interference] [--max-steps N]
//   rollkin reference SCENE [--from V --to V --step V] [--digits 30|50|100] --csv FILE
//   rollkin --help | --version
//
// Exit codes: 0 every requested input value solved; 1 some were not (a limit met, assembly failed, a singular
// pose): one line per limit or singular pose on stderr, the solved rows still written; 2 bad input (scene file, contour files, command line,
// an output that would overwrite an input, an output that cannot be written): the message on stderr and no
// output file written; 3 out of memory ("out of memory while ..."), no output file written. Outputs are all
// or nothing (rollkin/io/output_set.hpp).
#include "output.hpp"

#include "rollkin/io/output_set.hpp"
#include "rollkin/io/scene.hpp"
#include "rollkin/reference.hpp"
#include "rollkin/solve/continuation.hpp"
#include "rollkin/solve/interference.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
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

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// What the run is doing, for the message of an allocation failure ("out of memory while ...").
const char* g_doing = "starting";

struct Options {
  std::string command;  // "solve" or "reference"
  int digits = 50;      // reference: MPFR precision (30, 50 or 100 decimal digits)
  std::string scene;
  std::optional<double> from, to, step;
  std::string csv, plot, draw;
  bool rates = false, verbose = false, interference = false;
  bool analysis = false;  // --analysis: contact analysis columns in the CSV (docs/analysis.md)
  double max_steps = 1e7;  // bounded work: largest estimated number of continuation sub-steps
};

const char* kUsage =
    "usage: rollkin solve SCENE [--from V --to V --step V] [--csv FILE] [--plot FILE.svg] [--draw FILE.svg]\n"
    "                           [--rates] [--verbose] [--interference] [--max-steps N]\n"
    "       rollkin reference SCENE [--from V --to V --step V] [--digits 30|50|100] --csv FILE\n"
    "       rollkin --help | --version\n"
    "\n"
    "Kinematic analysis of planar mechanisms with rolling pairs. 'solve' loads the scene (JSON, see\n"
    "docs/scene_format.md), assembles the mechanism and sweeps its input over the scene's \"sweep\"\n"
    "(--from/--to/--step override it, in the scene's angle unit for angle inputs).\n"
    "\n"
    "  --csv FILE       one row per input value: the input, every other pair variable, (with --rates) the rates\n"
    "                   d(var)/d(input), every link's world pose, the residual and the solver status\n"
    "                   (angles in degrees, lengths in scene units)\n"
    "  --plot FILE.svg  the pair variables against the input (angles; lengths in a second chart)\n"
    "  --draw FILE.svg  the mechanism at about five poses across the solved range\n"
    "  --rates          add the rate columns to the CSV\n"
    "  --verbose        print the assembly report (rank, redundant constraints, mobility, condition)\n"
    "                   and how each imported contour (SVG, DXF) was converted to scene units\n"
    "  --interference   check every solved pose for contours that penetrate or touch at a second point\n"
    "                   (findings on stderr; they make the exit status 1)\n"
    "  --max-steps N    refuse (exit 2) a request estimated to need more than N continuation sub-steps\n"
    "                   (default 1e7; the estimate is the input's travel over the largest sub-step, 5 deg\n"
    "                   for angles, plus the number of values)\n"
    "\n"
    "Status column: ok; singular (branches meet there, the Jacobian is singular: the values follow the branch,\n"
    "interpolated between regular poses on both sides; a line on stderr, exit status 1); dead_point,\n"
    "domain_exit, no_convergence (a limit met: one line on stderr); not_reached (beyond a limit).\n"
    "\n"
    "Without output options a one-line summary is printed.\n"
    "\n"
    "'reference' runs the same assembly and sweep in MPFR (30, 50 or 100 decimal digits, default 50) and\n"
    "writes the poses as decimal strings (columns as the solve CSV without link poses): reference data for\n"
    "regression tests and for measuring the double solver's error.\n"
    "Exit status: 0 all requested poses solved; 1 some not (limits or singular poses on stderr, solved rows\n"
    "still written); 2 bad input or command line, or a request above --max-steps (nothing written);\n"
    "3 out of memory (nothing written).\n";

double parse_value(const std::string& opt, const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v))
    throw UsageError(opt + " expects a number, got \"" + text + "\"");
  return v;
}

Options parse_args(const std::vector<std::string>& args) {
  Options o;
  if (args.empty() || (args[0] != "solve" && args[0] != "reference"))
    throw UsageError(args.empty() ? "missing command"
                                  : "unknown command \"" + args[0] + "\"; expected \"solve\" or \"reference\"");
  o.command = args[0];
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
      return args[++i];
    };
    auto set_path = [&](std::string& slot) {
      if (!slot.empty()) throw UsageError(a + " given twice");
      slot = value();
      if (slot.empty()) throw UsageError(a + " needs a file name");
    };
    if (a == "--from") o.from = parse_value(a, value());
    else if (a == "--to") o.to = parse_value(a, value());
    else if (a == "--step") o.step = parse_value(a, value());
    else if (a == "--csv") set_path(o.csv);
    else if (a == "--plot") set_path(o.plot);
    else if (a == "--draw") set_path(o.draw);
    else if (a == "--rates") o.rates = true;
    else if (a == "--analysis" && o.command == "solve") o.analysis = true;
    else if (a == "--interference" && o.command == "solve") o.interference = true;
    else if (a == "--max-steps") {
      o.max_steps = parse_value(a, value());
      if (!(o.max_steps >= 1)) throw UsageError("--max-steps expects a positive number of sub-steps");
    }
    else if (a == "--digits" && o.command == "reference") {
      const double d = parse_value(a, value());
      if (d != 30 && d != 50 && d != 100) throw UsageError("--digits must be 30, 50 or 100");
      o.digits = static_cast<int>(d);
    }
    else if (a == "--verbose" || a == "-v") o.verbose = true;
    else if (!a.empty() && a[0] == '-' && a != "-") throw UsageError("unknown option \"" + a + "\"");
    else if (o.scene.empty()) o.scene = a;
    else throw UsageError("more than one scene file given (\"" + o.scene + "\" and \"" + a + "\")");
  }
  if (o.scene.empty()) throw UsageError("missing scene file");
  if (o.command == "reference" && (o.csv.empty() || !o.plot.empty() || !o.draw.empty() || o.rates))
    throw UsageError("reference writes a CSV only: give --csv FILE (and no --plot, --draw or --rates)");
  return o;
}

/// The sweep to run: the scene's, with the command line's overrides.
io::Sweep requested_sweep(const io::Scene& scene, const Options& o) {
  io::Sweep s;
  if (scene.sweep) {
    s = *scene.sweep;
  } else {
    if (!o.from || !o.to || !o.step)
      throw UsageError(scene.file + " has no \"sweep\"; give --from, --to and --step");
    s.input = scene.inputs.front();
    s.driver = 0;
    s.variable = scene.mechanism.drivers[0];
    s.unit = scene.unit_of(s.variable);
  }
  if (o.from) s.from = *o.from;
  if (o.to) s.to = *o.to;
  if (o.step) s.step = *o.step;
  const std::string bad = io::check_sweep(s);
  if (!bad.empty()) throw UsageError("--from/--to/--step: " + bad);
  return s;
}

/// Bounded work: refuses before solving a request whose estimated continuation sub-steps exceed --max-steps.
void check_work(const io::Scene& scene, const io::Sweep& sw, const std::vector<double>& inputs, const Options& o) {
  const double estimate = estimate_substeps(scene.mechanism, scene.guess, sw.driver, inputs);
  if (estimate <= o.max_steps) return;
  std::ostringstream os;
  os << "the sweep of " << sw.input << " from " << sw.from << " to " << sw.to << " needs an estimated "
     << std::scientific << std::setprecision(2) << estimate << " continuation sub-steps, above the limit "
     << o.max_steps << " (--max-steps); ask for a smaller range (--from/--to), a larger --step (fewer values),"
     << " or raise the limit with --max-steps";
  throw UsageError(os.str());
}

/// The output files of the command line, each checked against the files the run read and against each
/// other before anything is solved; written all or nothing at the end.
struct Outputs {
  io::OutputSet set;
  std::optional<std::size_t> csv, plot, draw;

  Outputs(const io::Scene& scene, const Options& o) : set(files_read(scene)) {
    if (!o.csv.empty()) csv = set.add("--csv", o.csv);
    if (!o.plot.empty()) plot = set.add("--plot", o.plot);
    if (!o.draw.empty()) draw = set.add("--draw", o.draw);
  }

  static std::vector<std::string> files_read(const io::Scene& scene) {
    std::vector<std::string> files{scene.file};
    files.insert(files.end(), scene.files_read.begin(), scene.files_read.end());
    return files;
  }
};

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
    case SolveStatus::NoConvergence: return "no_convergence: Newton-Raphson does not converge beyond " + where;
    default: return std::string(to_string(r.status)) + ": " + r.detail + " (at " + where + ")";
  }
}

void print_assembly(const io::Scene& scene, const SolveReport<double>& rep, const cli::AssemblyRank& ar) {
  const Mechanism<double>& m = scene.mechanism;
  for (const std::string& n : scene.notes) std::cout << "contour " << n << "\n";
  std::cout << "assembly: " << to_string(rep.status) << " after " << rep.iterations << " iteration(s), residual "
            << fmt(rep.residual, 3) << "\n"
            << "  variables " << m.variable_count() << " (inputs " << m.drivers.size() << ", unknowns " << m.unknowns.size()
            << "), equations " << m.equation_count() << " (" << m.loops.size() << " loop(s) x 3 + "
            << m.rolling_pairs.size() << " rolling)\n"
            << "  rank of the unknowns' Jacobian " << rep.rank << ", condition " << fmt(rep.condition, 3) << "\n"
            << "  rank of the full Jacobian " << ar.rank << ": redundant constraints " << ar.redundant
            << ", mobility (DOF = variables - rank) " << ar.mobility << "\n";
  if (!rep.detail.empty()) std::cout << "  " << rep.detail << "\n";
  if (m.unknowns.empty())
    std::cout << "  nothing to solve: every pair variable is an input, so each pose follows from the inputs alone"
                 " (forward kinematics)\n";
  else if (ar.mobility == 0)
    std::cout << "  the mechanism has zero degrees of freedom: it is a rigid structure, its inputs cannot move\n";
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

/// `rollkin reference`: the same assembly and sweep in MPFR, written as decimal strings (rollkin/reference.hpp).
int run_reference(const io::Scene& scene, const io::Sweep& sw, const Options& o, Outputs& out) {
  const Mechanism<double>& m = scene.mechanism;
  const bool decimal = scene.angle_unit == io::AngleUnit::Degree || m.variables[sw.variable].kind != ParamKind::Angle;
  ReferenceSweep ref;
  g_doing = "computing the reference sweep in MPFR";
  if (decimal) {  // the file's decimal input values, exactly (-50 is -50 degrees, not the nearest double)
    std::vector<std::string> values;
    for (double v : io::sweep_values(sw)) values.push_back(fmt(v, 17));
    ref = reference_sweep_decimal(m, scene.guess, scene.held, sw.driver, values, o.digits);
  } else {
    ref = reference_sweep(m, scene.guess, scene.held, sw.driver, io::sweep_inputs(sw), o.digits);
  }
  g_doing = "writing the output file";
  out.set.set(*out.csv, reference_csv_text(ref, m));
  out.set.commit();
  std::size_t solved = 0;
  for (const auto& p : ref.poses) solved += p.status == SolveStatus::Converged ? 1 : 0;
  std::cout << fs::path(scene.file).filename().string() << ": " << solved << "/" << ref.poses.size()
            << " poses solved at " << o.digits << " digits, written to " << o.csv << "\n";
  return solved == ref.poses.size() ? 0 : 1;
}

/// --interference: contours sampled in world coordinates at every solved pose (solve/interference.hpp); one
/// line per run of consecutive poses with the same finding, inputs in the file's units.
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
                    " to " + fmt(r.to / sw.unit, 8) + (unit.empty() ? "" : " " + unit));
  return lines;
}

int run(const Options& o) {
  g_doing = "reading the scene";
  const io::Scene scene = io::load_scene(o.scene);
  g_doing = "checking the output files";
  Outputs out(scene, o);
  if (o.command == "reference") {
    const io::Sweep sw = requested_sweep(scene, o);
    check_work(scene, sw, io::sweep_inputs(sw), o);
    return run_reference(scene, sw, o, out);
  }
  const io::Sweep sw = requested_sweep(scene, o);
  const std::vector<double> inputs = io::sweep_inputs(sw);
  check_work(scene, sw, inputs, o);
  const Mechanism<double>& m = scene.mechanism;

  g_doing = "assembling the mechanism";
  SolveData<double> sd(m);
  VectorX<double> q = scene.guess;
  const SolveReport<double> assembly = assemble(m, q, sd, scene.held);
  const cli::AssemblyRank ar = cli::full_rank(m, sd);
  // Inconsistent constraints at assembly are a problem of the scene (sizes, frames, values), not a motion
  // limit: treated like any other bad input (exit 2, nothing written, no report left on stdout).
  if (assembly.status == SolveStatus::CannotAssemble)
    throw InputError(scene.file, "pairs",
                     "the mechanism cannot be assembled: " + assembly.detail +
                         "; expected pair frames, contour sizes and \"values\" that let every loop close");
  if (o.verbose) print_assembly(scene, assembly, ar);
  g_doing = "solving the sweep";
  const SweepResult<double> result = sweep(m, sd, q, assembly, sw.driver, inputs);

  // Everything is computed before anything is written, and then written all or nothing.
  g_doing = "building the output files";
  const std::vector<double> file_values = io::sweep_values(sw);
  cli::OutputContext ctx{scene, sw, result, file_values};
  if (out.csv) out.set.set(*out.csv, cli::csv_text(ctx, o.rates, o.analysis));
  if (out.plot) out.set.set(*out.plot, cli::plot_svg(ctx));
  if (out.draw) out.set.set(*out.draw, cli::draw_svg(ctx));
  g_doing = "writing the output files";
  out.set.commit();
  g_doing = "reporting";

  std::size_t solved = 0;
  double max_residual = 0;
  for (const auto& p : result.poses)
    if (p.report.ok()) {
      ++solved;
      max_residual = std::max(max_residual, p.report.residual);
    }
  std::vector<std::string> problems;
  if (!assembly.ok())
    problems.push_back(std::string(to_string(assembly.status)) + ": assembly failed: " +
                       (assembly.detail.empty() ? "the mechanism cannot be assembled" : assembly.detail) +
                       " (rank " + std::to_string(assembly.rank) + " of " + std::to_string(assembly.unknowns) +
                       " unknowns, condition " + fmt(assembly.condition, 3) + ")");
  for (const auto& l : result.limits) problems.push_back(limit_line(scene, sw, l));
  std::size_t singular = 0;
  for (const auto& p : result.poses)
    if (p.report.status == SolveStatus::Singular) {
      ++singular;
      problems.push_back("singular: singular pose at " + input_text(scene, sw, p.input) +
                         ": the branches meet / Jacobian singular; values follow the branch (interpolated between"
                         " the regular poses on both sides, condition " + fmt(p.report.condition, 3) + ")");
    }
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
  std::cout << summary.str() << "\n";
  for (const auto& p : problems) std::cerr << scene.file << ": " << p << "\n";
  return solved == inputs.size() && assembly.ok() && clashes.empty() ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  try {
    for (const auto& a : args) {
      if (a == "--help" || a == "-h" || a == "help") {
        std::cout << kUsage;
        return 0;
      }
      if (a == "--version") {
        std::cout << "rollkin " << ROLLKIN_VERSION << "\n";
        return 0;
      }
    }
    return run(parse_args(args));
  } catch (const std::bad_alloc&) {
    std::cerr << "rollkin: out of memory while " << g_doing
              << "; nothing was written (a smaller sweep, fewer samples or more memory may help)\n";
    return 3;
  } catch (const UsageError& e) {
    std::cerr << "rollkin: " << e.what() << "\n(rollkin --help for usage)\n";
    return 2;
  } catch (const InputError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "rollkin: error: " << e.what() << "\n";
    return 2;
  } catch (...) {
    std::cerr << "rollkin: unexpected error\n";
    return 2;
  }
}
