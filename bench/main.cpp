// rollkin_bench: accuracy and speed of the position solver over the profile representations
// (docs/benchmark.md). A separate executable, not a unit test: it measures and prints, it never asserts.
//
//   rollkin_bench [--quick] [--csv FILE] [--svg FILE] [--repeats N] [--only TEXT] [--no-reference]
//
// Every case sweeps its input in 1-degree steps with rollkin::sweep (one thread, steady_clock). Reported per
// case: median over N sweeps of (sweep time / poses), evaluations per pose (the sum of the poses'
// SolveReport::evaluations: residual and Jacobian evaluations, each with a factorisation, over all
// sub-steps), profile preparation time and memory, and the largest error of
// any link's world angle (which includes every revolute angle) against an MPFR (50 digits) solution of the
// exact analytic mechanism at the same inputs. See docs/benchmark.md.
//
// This file is the driver (options, the order of the sections); the table, the cases, the savings and memory
// rows and the output files are the files profile_bench.hpp lists.
#include "profile_bench.hpp"

#include <CLI/CLI.hpp>

#include <malloc.h>

#include <cerrno>
#include <cstdlib>
#include <iostream>
#include <optional>

using namespace rollkin;
using namespace rollkin::bench;
using namespace rollkin::bench::profiles;

namespace {

/// --repeats: a whole number of timed sweeps, all of the text parsed (CLI11 names the option in front).
const CLI::Validator kRepeats(
    [](std::string& text) -> std::string {
      char* end = nullptr;
      errno = 0;
      const long v = std::strtol(text.c_str(), &end, 10);
      if (!text.empty() && *end == '\0' && errno == 0 && v >= 1 && v <= 1000000) return {};
      return "expects a whole number of timed sweeps from 1 to 1000000, got \"" + text + "\"";
    },
    "", "");

/// The command line, parsed by CLI11 into `opt`. Returns the exit status when the program should stop now:
/// 0 after --help, 2 (with the message on stderr) for an unknown option or a bad value.
std::optional<int> parse_options(int argc, char** argv, Options& opt) {
  CLI::App app("rollkin_bench: accuracy and speed of the position solver over the profile representations "
               "(bench/README.md, docs/benchmark.md)",
               "rollkin_bench");
  app.add_flag("--quick", opt.quick, "CI smoke run: no 1e5/1e6 sweeps, 7 repeats");
  app.add_option("--csv", opt.csv, "write the results table as CSV")->type_name("FILE");
  app.add_option("--svg", opt.svg, "write the chart of time per pose against error")->type_name("FILE");
  app.add_option("--repeats", opt.repeats, "timed sweeps per case (default 31, 7 with --quick)")
      ->type_name("N")
      ->check(kRepeats);
  app.add_option("--only", opt.only, "only the cases whose name contains TEXT (skips load, memory and savings)")
      ->type_name("TEXT");
  app.add_flag_callback("--no-reference", [&opt] { opt.reference = false; },
                        "skip the MPFR reference (no errors reported; for profilers)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);  // --help
    std::cerr << "rollkin_bench: " << e.what() << "\n(rollkin_bench --help lists the options)\n";
    return 2;
  }
  return std::nullopt;
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  if (const std::optional<int> stop = parse_options(argc, argv, opt)) return *stop;
  // Fixed mmap threshold: large blocks are mapped and returned to the system when freed, so the resident
  // memory deltas of one build are not hidden by the allocator keeping earlier blocks.
  mallopt(M_MMAP_THRESHOLD, 64 * 1024);
  Eigen::setNbThreads(1);

  Bench bench(opt);
  std::printf("rollkin_bench%s: %ld CPUs, %s; %s; %d timed sweeps per case (median), 1 thread; load average %s\n",
              opt.quick ? " --quick" : "", cpu_count(), cpu_model().c_str(), compiler().c_str(), bench.repeats(),
              load_average().c_str());
  Bench::print_header();
  std::vector<Row> rows;
  for (const Case& c : make_cases(opt.quick)) {
    if (!opt.only.empty() && c.name.find(opt.only) == std::string::npos) continue;
    rows.push_back(bench.run(c));
  }
  if (opt.only.empty()) {
    rows.push_back(load_and_prepare(1000000));
    Bench::print_row(rows.back());
    rows.push_back(memory_linearity(rows));
    Bench::print_row(rows.back());
  }
  std::vector<Saving> savings;
  if (opt.only.empty()) {
    std::printf("\nSavings (same run): %-21s %-26s %10s  %-30s %10s  %s %8s\n", "", "baseline", "value", "alternative",
                "value", "unit", "ratio");
    savings = measure_savings(bench, rows);
  }
  if (!opt.csv.empty()) write_csv(opt.csv, rows, savings);
  if (!opt.svg.empty())
    write_svg(opt.svg, rows, std::string(opt.quick ? "--quick, " : "") + cpu_model() + ", " + std::to_string(cpu_count()) + " CPUs");
  std::printf("\n%s%s%s\n", opt.csv.empty() ? "" : ("wrote " + opt.csv + "\n").c_str(),
              opt.svg.empty() ? "" : ("wrote " + opt.svg + "\n").c_str(), g_sink ? "" : " ");
  return 0;
}
