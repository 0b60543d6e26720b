// build/rollkin_bench_cli_scaling: the command line's cost per pose against the library's, as the mechanism
// grows (docs/benchmark.md, "The command line at the library's cost"). A train of N + 1 pivoted rolling disks
// (the scene of samples' disk_train(N): radii 1, 1.5, 0.75, 1.25 repeating, pivots on the x-axis, each mesh a
// rolling pair), swept 0 .. 360 deg by --step, at N = 2, 8, 64:
//   - cli: `rollkin solve s1.json ... sK.json --jobs 1` without output (K copies of the scene in one process,
//     so that start-up is shared), the child's CPU time per pose (everything: start-up, reading, assembly,
//     sweep, summary);
//   - library: rollkin::sweep_summary() on the scene as load_scene reads it, in process, CPU time per pose;
//     and the whole library path (load_scene, SolveData, assemble, sweep_summary) per pose.
// CPU times (user + system), so that the other processes of a shared machine do not count.
// Medians over --repeats runs, the cases alternated so that the machine's load drifts evenly. Prints the
// ratio cli / library (target <= 1.2 at every N) and cost(64) / cost(8) through the CLI (target <= 10).
//
//   rollkin_bench_cli_scaling [--rollkin build/rollkin] [--repeats 5] [--step 0.1] [--sizes 2,8,64]
#include "measure.hpp"

#include "rollkin/io/scene/reader.hpp"
#include "rollkin/solve/continuation.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <fcntl.h>

#include <cmath>
#include <ctime>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

extern char** environ;

namespace {

using namespace rollkin;
using namespace rollkin::bench;
namespace fs = std::filesystem;

/// The radius of disk k (samples' disk_train_radius): 1, 1.5, 0.75, 1.25 repeating.
double disk_radius(int k) {
  const int pattern[4] = {4, 6, 3, 5};
  return pattern[k % 4] / 4.0;
}

/// The scene of a train of n + 1 pivoted disks, neighbours rolling on each other, input pivot0.phi swept
/// from 0 to 360 deg by `step`; assembled with every contact on the x-axis (u = 0, v = 180 deg: exact).
nlohmann::ordered_json disk_train_scene(int n, double step) {
  nlohmann::ordered_json links = nlohmann::ordered_json::array(), pairs = nlohmann::ordered_json::array();
  links.push_back({{"name", "ground"}, {"ground", true}});
  double x = 0;
  for (int k = 0; k <= n; ++k) {
    if (k > 0) x += disk_radius(k - 1) + disk_radius(k);
    const std::string disk = "disk" + std::to_string(k);
    links.push_back({{"name", disk}, {"contours", {{{"name", "rim"}, {"type", "circle"}, {"radius", disk_radius(k)}}}}});
    pairs.push_back({{"name", "pivot" + std::to_string(k)}, {"type", "revolute"}, {"links", {"ground", disk}},
                     {"at", {{{"x", x}}, nlohmann::ordered_json::object()}}, {"variable", "phi"}, {"value", 0}});
  }
  for (int k = 0; k < n; ++k)
    pairs.push_back({{"name", "mesh" + std::to_string(k)}, {"type", "rolling"},
                     {"contours", {"disk" + std::to_string(k) + ".rim", "disk" + std::to_string(k + 1) + ".rim"}},
                     {"variables", {"u", "v"}}, {"values", {0, 180}}});
  return {{"description", "train of " + std::to_string(n + 1) + " pivoted rolling disks (rollkin_bench_cli_scaling)"},
          {"units", {{"length", "m"}, {"angle", "deg"}}},
          {"links", links},
          {"pairs", pairs},
          {"inputs", {"pivot0.phi"}},
          {"sweep", {{"from", 0}, {"to", 360}, {"step", step}}}};
}

/// CPU seconds (user + system) of this process so far.
double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// Runs argv with stdout and stderr to /dev/null; its CPU seconds (user + system, from wait4), or NAN when it
/// did not exit 0. CPU time, not wall time: on a shared machine it does not count the other processes' turns.
double run_child(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  double seconds = NAN;
  if (posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), environ) == 0) {
    int status = 0;
    rusage ru{};
    wait4(pid, &status, 0, &ru);
    const auto cpu = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) seconds = cpu(ru.ru_utime) + cpu(ru.ru_stime);
  }
  posix_spawn_file_actions_destroy(&fa);
  return seconds;
}

struct LibraryTimes {
  double summary = 0, whole = 0;  // CPU seconds: sweep_summary alone; load_scene to summary
  bool ok = true;
};

/// The library's path on every scene file: load_scene, SolveData, assemble, sweep_summary.
LibraryTimes run_library(const std::vector<std::string>& files) {
  LibraryTimes t;
  const double t0 = process_cpu_seconds();
  for (const std::string& file : files) {
    const io::Scene scene = io::load_scene(file);
    const Sweep& sw = *scene.sweep;
    const std::vector<double> inputs = sweep_inputs(sw);
    SolveData<double> sd(scene.mechanism);
    VectorX<double> q = scene.guess;
    const SolveReport<double> assembly = assemble(scene.mechanism, q, sd, scene.held);
    const double ts = process_cpu_seconds();
    const SweepSummary<double> s = sweep_summary(scene.mechanism, sd, q, assembly, sw.driver, inputs);
    t.summary += process_cpu_seconds() - ts;
    t.ok = t.ok && s.solved() == inputs.size();
  }
  t.whole = process_cpu_seconds() - t0;
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"rollkin_bench_cli_scaling: the command line's cost per pose against the library's"};
  std::string rollkin = "rollkin";
  int repeats = 5;
  double step = 0.1;
  std::vector<int> sizes = {2, 8, 64};
  app.add_option("--rollkin", rollkin, "the rollkin executable (default: next to this one)")->type_name("FILE");
  app.add_option("--repeats", repeats, "timed runs per case (median)");
  app.add_option("--step", step, "sweep step in degrees (0 .. 360)");
  app.add_option("--sizes", sizes, "numbers of meshes N")->delimiter(',');
  CLI11_PARSE(app, argc, argv);
  if (rollkin == "rollkin") {
    const std::string self = argv[0];
    rollkin = (self.find('/') == std::string::npos ? std::string(".") : self.substr(0, self.rfind('/'))) + "/rollkin";
  }
  const fs::path dir = fs::temp_directory_path() / ("rollkin_bench_cli_scaling_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const double poses = std::floor(360 / step + 1e-9) + 1;

  std::printf("# rollkin_bench_cli_scaling: %s, %ld cpus, load %s, %s\n", cpu_model().c_str(), cpu_count(),
              load_average().c_str(), compiler().c_str());
  std::printf("# disk train of N + 1 pivoted disks, 0 .. 360 deg by %g (%.0f poses), K copies per run, %d repeats\n",
              step, poses, repeats);
  std::printf("%4s %5s %3s %12s %14s %14s %11s\n", "N", "unkn", "K", "cli us/pose", "library us/pose",
              "lib whole us", "cli/library");
  std::vector<double> cli_cost, lib_cost;
  for (int n : sizes) {
    // K copies so that a run sweeps about 64 * 2 meshes' worth of poses: start-up shared, runs short.
    const int copies = std::max(2, std::min(64, 128 / std::max(n, 1)));
    std::vector<std::string> files;
    for (int k = 0; k < copies; ++k) {
      const fs::path file = dir / ("train" + std::to_string(n) + "_" + std::to_string(k) + ".json");
      std::ofstream(file) << disk_train_scene(n, step).dump(1) << "\n";
      files.push_back(file.string());
    }
    std::vector<std::string> args = {rollkin, "solve"};
    args.insert(args.end(), files.begin(), files.end());
    args.insert(args.end(), {"--jobs", "1"});
    std::vector<double> cli, lib, whole;
    bool ok = true;
    for (int r = 0; r < repeats; ++r) {
      const double c = run_child(args);
      const LibraryTimes l = run_library(files);
      ok = ok && std::isfinite(c) && l.ok;
      cli.push_back(c / (copies * poses) * 1e6);
      lib.push_back(l.summary / (copies * poses) * 1e6);
      whole.push_back(l.whole / (copies * poses) * 1e6);
    }
    const double c = median(cli), l = median(lib);
    cli_cost.push_back(c);
    lib_cost.push_back(l);
    std::printf("%4d %5d %3d %12.3f %14.3f %14.3f %11.2f%s\n", n, 3 * n, copies, c, l, median(whole), c / l,
                ok ? "" : "  (a run failed)");
  }
  const auto at = [&](const std::vector<double>& cost, int n) -> double {
    for (std::size_t k = 0; k < sizes.size(); ++k)
      if (sizes[k] == n) return cost[k];
    return NAN;
  };
  std::printf("cost(64)/cost(8): cli %.1f (target <= 10), library %.1f\n", at(cli_cost, 64) / at(cli_cost, 8),
              at(lib_cost, 64) / at(lib_cost, 8));
  fs::remove_all(dir);
  return 0;
}
