// `rollkin reference`: the same assembly and sweep as `solve` in MPFR, written as decimal strings.
#include "commands.hpp"
#include "rollkin/reference.hpp"

#include <iostream>
#include <memory>

namespace rollkin::cli {
namespace {

// ---- rollkin reference -----------------------------------------------------------------------------------

struct ReferenceOptions {
  SweepRequest sweep;
  int digits = 50;  // MPFR precision in decimal digits: 30, 50 or 100
  std::string csv;
};

int run_reference(const ReferenceOptions& o);

}  // namespace

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

namespace {

/// `rollkin reference`: the same assembly and sweep in MPFR, written as decimal strings (rollkin/reference.hpp).
int run_reference(const ReferenceOptions& o) {
  output::SweepRun run = start_run(o.sweep, {{"--csv", o.csv, ""}});
  const io::Scene& scene = run.scene();
  const Sweep& sw = run.sweep();
  const Mechanism<double>& m = scene.mechanism;
  g_doing = "computing the reference sweep in MPFR";
  const ReferenceSweep ref = io::scene_reference(scene, sw, o.digits);
  g_doing = "writing the output file";
  run.set_output("--csv", [&] { return reference_csv_text(ref, m); });
  run.commit();
  std::size_t solved = 0;
  for (const auto& p : ref.poses) solved += p.status == SolveStatus::Converged ? 1 : 0;
  std::cout << fs::path(scene.file).filename().string() << ": " << solved << "/" << ref.poses.size()
            << " poses solved at " << o.digits << " digits, written to " << o.csv << "\n";
  return solved == ref.poses.size() ? 0 : 1;
}

}  // namespace
}  // namespace rollkin::cli
