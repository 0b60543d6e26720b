// rollkin_bench_cli: the path a user runs (docs/benchmark.md, "The CLI path"). All in
// one run, on the paper example over theta2 = -50 .. 100 degrees by 0.001 (150,001 poses):
//   - hand: the hand-specialised limit (bench/hand_paper.hpp: 2 unknowns, closed-form Jacobian and arc
//     lengths), in process;
//   - library: rollkin::sweep() on the scene as `rollkin solve` reads it, in process (assembly excluded);
//   - cli: `rollkin solve examples/paper_fourbar.json --from -50 --to 100 --step 0.001` as a child process,
//     without output and with --csv FILE (its rows formatted on all cores, the default, and with --jobs 1)
//     (wall time from spawn to exit, everything included: start-up,
//     scene, assembly, sweep, output), and the child's peak resident memory (wait4's ru_maxrss), children
//     spawned by a small process forked at start-up (Spawner);
//   - jobs: eight copies of the scene in one `rollkin solve s1.json ... s8.json --step 0.001` run with --jobs 1
//     and with --jobs <cores> (wall time; the speed-up against the target >= 0.8 x cores);
//   - scipy: bench/scipy_paper.py (fsolve with quad arc lengths) with /usr/bin/python3, fewer poses (it takes
//     about a millisecond each), per pose;
//   - outputs: `rollkin solve` over the same range with 10^4, 10^5 and 10^6 poses, --plot --animate and
//     --csv --plot --animate: the size of each file and the child's peak resident memory (targets: chart
//     < 2 MB and animation < 5 MB at any number of poses, < 60 MB of memory at 10^6 poses with all three).
// Medians over --repeats runs (alternating the cases, so that the machine's load drifts evenly). Prints a
// table with the targets: cli <= 1.0x hand per pose, cli --csv <= 2.5x, peak memory < 40 MB.
//
//   rollkin_bench_cli [--rollkin build/rollkin] [--repeats 7] [--scipy-poses 1501] [--no-scipy]
//                     [--only timing|outputs]
#include "hand_paper.hpp"

#include "rollkin/io/scene/reader.hpp"
#include "rollkin/solve/continuation.hpp"

#include <CLI/CLI.hpp>

#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <thread>
#include <string>
#include <vector>

extern char** environ;

namespace {

using Clock = std::chrono::steady_clock;
constexpr long kPoses = 150001;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

struct Child {
  double seconds = 0;
  double max_rss_mb = 0;
  int status = -1;
};

/// Runs argv with stdout and stderr to /dev/null; wall time and peak RSS of the child (wait4).
Child run_child(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
  Child c;
  const Clock::time_point t0 = Clock::now();
  pid_t pid = 0;
  if (posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), environ) != 0) {
    posix_spawn_file_actions_destroy(&fa);
    return c;
  }
  int status = 0;
  struct rusage ru {};
  wait4(pid, &status, 0, &ru);
  c.seconds = seconds_since(t0);
  c.max_rss_mb = static_cast<double>(ru.ru_maxrss) / 1024.0;  // kilobytes on Linux
  c.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  posix_spawn_file_actions_destroy(&fa);
  return c;
}

bool write_all(int fd, const void* data, std::size_t n) {
  const char* p = static_cast<const char*>(data);
  while (n > 0) {
    const ssize_t w = write(fd, p, n);
    if (w <= 0) return false;
    p += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}
bool read_all(int fd, void* data, std::size_t n) {
  char* p = static_cast<char*>(data);
  while (n > 0) {
    const ssize_t r = read(fd, p, n);
    if (r <= 0) return false;
    p += r;
    n -= static_cast<std::size_t>(r);
  }
  return true;
}

/// Runs the timed children from a small process forked at start-up. Linux carries a process's peak memory
/// over exec, and a spawned child starts with its parent's (ru_maxrss): spawned from this benchmark, whose
/// library sweep has held 20 MB and more, every child would read at least that.
class Spawner {
 public:
  Spawner() {
    int request[2], reply[2];
    if (pipe(request) != 0 || pipe(reply) != 0) return;
    pid_ = fork();
    if (pid_ == 0) {
      close(request[1]);
      close(reply[0]);
      serve(request[0], reply[1]);
      _exit(0);
    }
    close(request[0]);
    close(reply[1]);
    to_ = request[1];
    from_ = reply[0];
  }
  ~Spawner() {
    close(to_);
    close(from_);
    if (pid_ > 0) waitpid(pid_, nullptr, 0);
  }
  Spawner(const Spawner&) = delete;
  Spawner& operator=(const Spawner&) = delete;

  /// run_child(args) in the small process.
  Child run(const std::vector<std::string>& args) const {
    std::string message;
    for (const auto& a : args) message.append(a).push_back('\0');
    const std::uint64_t n = message.size();
    Child c;
    if (pid_ <= 0 || !write_all(to_, &n, sizeof n) || !write_all(to_, message.data(), n) || !read_all(from_, &c, sizeof c))
      c.status = -1;
    return c;
  }

 private:
  static void serve(int in, int out) {
    std::uint64_t n = 0;
    while (read_all(in, &n, sizeof n)) {
      std::string message(n, '\0');
      if (!read_all(in, message.data(), n)) return;
      std::vector<std::string> args;
      for (std::size_t begin = 0, end; begin < message.size(); begin = end + 1) {
        end = message.find('\0', begin);
        args.push_back(message.substr(begin, end - begin));
      }
      const Child c = run_child(args);
      if (!write_all(out, &c, sizeof c)) return;
    }
  }
  pid_t pid_ = -1;
  int to_ = -1, from_ = -1;
};

/// The SciPy baseline's us per pose (its own median over its repeats), or a negative number on failure.
double scipy_us_per_pose(const std::string& script, int poses, std::string& check) {
  const std::string cmd = "/usr/bin/python3 " + script + " --poses " + std::to_string(poses) + " --step " +
                          std::to_string(150.0 / (poses - 1)) + " --repeat 3 2>/dev/null";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return -1;
  double us = -1, lo = 0, hi = 0, phi = 0;
  char line[256];
  while (std::fgets(line, sizeof line, p)) {
    if (std::sscanf(line, "us_per_pose %lf %lf %lf", &us, &lo, &hi) == 3) continue;
    if (std::sscanf(line, "phi_first_deg %lf", &phi) == 1) check = std::to_string(phi);
  }
  pclose(p);
  return us;
}

double file_mb(const std::string& path) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  return ec ? -1 : static_cast<double>(size) / 1e6;
}

/// The outputs' sizes and peak memory of `rollkin solve` with `poses` poses over theta2 -50..100.
void output_rows(const Spawner& spawner, const std::string& rollkin, const std::string& scene_file) {
  const std::string base = "/tmp/rollkin_bench_out." + std::to_string(getpid());
  const std::string plot = base + ".svg", page = base + ".html", table = base + ".csv";
  std::printf("\nOutputs at any size: paper example, theta2 -50..100 deg, one run per case (file sizes in MB, "
              "peak RSS of the child)\n");
  std::printf("| poses | outputs | --plot MB | --animate MB | --csv MB | peak RSS MB | s | target |\n"
              "|---:|---|---:|---:|---:|---:|---:|---|\n");
  for (const long poses : {10000L, 100000L, 1000000L}) {
    char step[32];
    std::snprintf(step, sizeof step, "%.17g", 150.0 / static_cast<double>(poses - 1));
    for (const bool csv : {false, true}) {
      std::vector<std::string> args{rollkin, "solve", scene_file, "--from", "-50", "--to", "100", "--step", step,
                                    "--plot", plot, "--animate", page};
      if (csv) args.insert(args.end(), {"--csv", table});
      for (const std::string& f : {plot, page, table}) std::remove(f.c_str());
      const Child c = spawner.run(args);
      const double plot_mb = file_mb(plot), page_mb = file_mb(page), csv_mb = csv ? file_mb(table) : 0;
      const bool sizes_ok = plot_mb >= 0 && plot_mb < 2 && page_mb >= 0 && page_mb < 5;
      std::string target = std::string(sizes_ok ? "PASS" : "MISS") + " sizes (< 2 MB, < 5 MB)";
      if (csv && poses == 1000000) target += std::string(", ") + (c.max_rss_mb < 60 ? "PASS" : "MISS") + " memory (< 60 MB)";
      if (c.status != 0) target += ", exit " + std::to_string(c.status);
      std::printf("| %ld | %s | %.3f | %.3f | %s | %.1f | %.2f | %s |\n", poses,
                  csv ? "--csv --plot --animate" : "--plot --animate", plot_mb, page_mb,
                  csv ? std::to_string(csv_mb).substr(0, 6).c_str() : "", c.max_rss_mb, c.seconds, target.c_str());
      std::fflush(stdout);
    }
  }
  for (const std::string& f : {plot, page, table}) std::remove(f.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  std::string rollkin = "rollkin", source = ROLLKIN_SOURCE_DIR;
  int repeats = 7, scipy_poses = 1501;
  bool no_scipy = false;
  std::string only;
  CLI::App app("the CLI path against the hand-coded limit and SciPy (bench/cli_path.cpp)");
  app.add_option("--rollkin", rollkin, "the rollkin executable (default: next to this one)")->type_name("FILE");
  app.add_option("--repeats", repeats, "runs per case (median)")->check(CLI::Range(1, 1000));
  app.add_option("--scipy-poses", scipy_poses, "poses of the SciPy sweep over the same range")->check(CLI::Range(2, 150001));
  app.add_flag("--no-scipy", no_scipy, "skip the SciPy baseline");
  app.add_option("--only", only, "run one part: timing (the CLI path against the hand-coded limit) or outputs "
                 "(output sizes and peak memory at 10^4 to 10^6 poses)")->check(CLI::IsMember({"timing", "outputs"}));
  CLI11_PARSE(app, argc, argv);
  const Spawner spawner;  // before anything large is allocated here
  if (rollkin == "rollkin") rollkin = (std::string(argv[0]).find('/') == std::string::npos ? std::string(".")
                                        : std::string(argv[0]).substr(0, std::string(argv[0]).rfind('/'))) + "/rollkin";
  const std::string scene_file = source + "/examples/paper_fourbar.json";
  if (only == "outputs") {
    output_rows(spawner, rollkin, scene_file);
    return 0;
  }
  const std::string csv = "/tmp/rollkin_bench_cli." + std::to_string(getpid()) + ".csv";
  const std::vector<std::string> plain{rollkin, "solve", scene_file, "--from", "-50", "--to", "100", "--step", "0.001"};
  std::vector<std::string> with_csv = plain;
  with_csv.push_back("--csv");
  with_csv.push_back(csv);
  std::vector<std::string> csv_one_thread = with_csv;  // the rows formatted by one thread (--jobs 1)
  csv_one_thread.push_back("--jobs");
  csv_one_thread.push_back("1");

  // The library on the scene as the CLI reads it.
  using namespace rollkin;
  const io::Scene scene = io::load_scene(scene_file);
  Sweep sw = *scene.sweep;
  sw.from = -50;
  sw.to = 100;
  sw.step = 0.001;
  const std::vector<double> inputs = sweep_inputs(sw);
  if (static_cast<long>(inputs.size()) != kPoses) {
    std::cerr << "rollkin_bench_cli: expected " << kPoses << " inputs, got " << inputs.size() << "\n";
    return 2;
  }

  std::vector<double> hand, lib, cli, cli_csv, cli_csv1, rss, rss_csv, rss_csv1;
  std::vector<hand_paper::Unknowns> hand_out;
  long hand_iterations = 0;
  double worst_phi = 0;
  int bad_status = 0;
  for (int r = 0; r < repeats; ++r) {
    Clock::time_point t0 = Clock::now();
    hand_iterations = hand_paper::sweep(-50, 0.001, kPoses, hand_out);
    hand.push_back(seconds_since(t0) / kPoses * 1e6);

    SolveData<double> sd(scene.mechanism);
    VectorX<double> q = scene.guess;
    const SolveReport<double> assembly = assemble(scene.mechanism, q, sd, scene.held);
    t0 = Clock::now();
    const SweepResult<double> res = sweep(scene.mechanism, sd, q, assembly, sw.driver, inputs);
    lib.push_back(seconds_since(t0) / kPoses * 1e6);
    if (r == 0) {  // the hand-coded values against the library's (theta5 = O_B's variable, index 5)
      for (long k = 0; k < kPoses; ++k)
        worst_phi = std::max(worst_phi, std::abs(hand_out[static_cast<std::size_t>(k)].phi - res.q(static_cast<std::size_t>(k))(5)));
    }

    const Child a = spawner.run(plain);
    const Child b = spawner.run(with_csv);
    const Child c = spawner.run(csv_one_thread);
    bad_status += (a.status != 0) + (b.status != 0) + (c.status != 0);
    cli.push_back(a.seconds / kPoses * 1e6);
    rss.push_back(a.max_rss_mb);
    cli_csv.push_back(b.seconds / kPoses * 1e6);
    rss_csv.push_back(b.max_rss_mb);
    cli_csv1.push_back(c.seconds / kPoses * 1e6);
    rss_csv1.push_back(c.max_rss_mb);
  }
  std::remove(csv.c_str());

  // Several scenes at once: eight copies of the scene (temporary files), one job against all cores. Each is
  // swept by 0.001 degree, so that the sweeps, not the start-up and the scene loading, take the time (by
  // 0.005 degree, since the summary interpolates, eight sweeps took 0.09 s on one core).
  namespace fs = std::filesystem;
  const fs::path copies = fs::temp_directory_path() / ("rollkin_bench_cli." + std::to_string(getpid()));
  fs::create_directories(copies);
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<std::string> one_job{rollkin, "solve"};
  for (int i = 1; i <= 8; ++i) {
    const fs::path copy = copies / ("s" + std::to_string(i) + ".json");
    fs::copy_file(scene_file, copy, fs::copy_options::overwrite_existing);
    one_job.push_back(copy.string());
  }
  for (const char* a : {"--from", "-50", "--to", "100", "--step", "0.001", "--jobs"}) one_job.push_back(a);
  std::vector<std::string> all_jobs = one_job;
  one_job.push_back("1");
  all_jobs.push_back(std::to_string(cores));
  std::vector<double> jobs1, jobs_all;
  for (int r = 0; r < repeats; ++r) {
    const Child a = spawner.run(one_job), b = spawner.run(all_jobs);
    bad_status += (a.status != 0) + (b.status != 0);
    jobs1.push_back(a.seconds);
    jobs_all.push_back(b.seconds);
  }
  fs::remove_all(copies);

  double scipy = -1;
  std::string scipy_check;
  if (!no_scipy) scipy = scipy_us_per_pose(source + "/bench/scipy_paper.py", scipy_poses, scipy_check);

  const double h = median(hand);
  auto verdict = [](bool ok) { return ok ? "PASS" : "MISS"; };
  std::printf("The CLI path: paper example, theta2 -50..100 by 0.001 deg (%ld poses), medians of %d runs\n", kPoses, repeats);
  std::printf("hand-coded: %.2f Newton iterations/pose; largest |phi_hand - theta5_library| %.2e rad\n",
              static_cast<double>(hand_iterations) / kPoses, worst_phi);
  std::printf("| case | us/pose (min-max) | x hand | peak RSS MB | target |\n|---|---:|---:|---:|---|\n");
  auto row = [&](const char* name, const std::vector<double>& t, const std::vector<double>* m, const std::string& target) {
    std::printf("| %s | %.3f (%.3f-%.3f) | %.2f | %s | %s |\n", name, median(t), *std::min_element(t.begin(), t.end()),
                *std::max_element(t.begin(), t.end()), median(t) / h, m ? std::to_string(median(*m)).substr(0, 5).c_str() : "",
                target.c_str());
  };
  row("hand-coded limit (bench/hand_paper.hpp)", hand, nullptr, "");
  row("library sweep()", lib, nullptr, "");
  row("rollkin solve, no output", cli, &rss,
      std::string(verdict(median(cli) <= 1.0 * h)) + " time (<= 1.0x), " + verdict(median(rss) < 40) + " memory (< 40 MB)");
  row("rollkin solve --csv (rows formatted on all cores)", cli_csv, &rss_csv,
      std::string(verdict(median(cli_csv) <= 2.5 * h)) + " time (<= 2.5x), " + verdict(median(rss_csv) < 40) + " memory (< 40 MB)");
  row("rollkin solve --csv --jobs 1", cli_csv1, &rss_csv1, verdict(median(rss_csv1) < 40) + std::string(" memory (< 40 MB)"));
  if (scipy > 0)
    std::printf("| SciPy fsolve + quad (%d poses, phi(-50) = %s deg) | %.1f | %.0f | | |\n", scipy_poses, scipy_check.c_str(),
                scipy, scipy / h);
  const double speedup = median(jobs1) / median(jobs_all);
  std::printf("\nSeveral scenes at once: 8 copies, 150001 poses each, wall time (min-max)\n");
  std::printf("| --jobs | s | speed-up | target |\n|---:|---:|---:|---|\n");
  std::printf("| 1 | %.3f (%.3f-%.3f) | 1.00 | |\n", median(jobs1), *std::min_element(jobs1.begin(), jobs1.end()),
              *std::max_element(jobs1.begin(), jobs1.end()));
  std::printf("| %d (cores) | %.3f (%.3f-%.3f) | %.2f = %.2f x cores | %s (>= 0.8 x cores) |\n", cores, median(jobs_all),
              *std::min_element(jobs_all.begin(), jobs_all.end()), *std::max_element(jobs_all.begin(), jobs_all.end()),
              speedup, speedup / cores, verdict(speedup >= 0.8 * cores));
  if (bad_status) std::printf("WARNING: %d rollkin runs did not exit 0\n", bad_status);
  if (only.empty()) output_rows(spawner, rollkin, scene_file);
  return 0;
}
