// rollkin_bench (bench/main.cpp): what its parts share. The accuracy and speed table of the profile
// representations (profile_table.cpp: the MPFR reference, a timed sweep, one row per case), the cases
// (profile_cases.cpp), the savings the design makes and the memory rows (savings.cpp), the CSV and SVG files
// (bench_files.cpp). See docs/benchmark.md.
#pragma once

#include "measure.hpp"
#include "scenes.hpp"

#include "rollkin/scalar_mpfr.hpp"
#include "rollkin/analysis/interference.hpp"

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace rollkin::bench::profiles {

using M = mpfr50;

const double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Options {
  bool quick = false;
  bool reference = true;
  int repeats = 0;  // 0: 31 (full) or 7 (quick)
  std::string csv, svg, only;
};

// ---- the table: reference, timing, rows (profile_table.cpp) ----------------------------------------------

/// World angle of every link at every input (empty where the reference did not solve).
struct Reference {
  std::vector<std::vector<M>> angles;
  double seconds = 0;
  int solved = 0;
  std::string how;
};

struct SweepTiming {
  SolveReport<double> assembly;
  SweepResult<double> result;  // of the first (untimed) sweep
  double us_pose = kNaN, evals_pose = kNaN;
  int solved = 0;
};

extern std::size_t g_sink;  // keeps the timed work observable

/// `repeats` timed sweeps of f over the inputs (after one untimed sweep): median time and evaluations per pose.
SweepTiming time_sweep(const testing::Fixture<double>& f, const std::vector<double>& inputs, int repeats,
                       const ContinuationSettings<double>& cfg = {});

using Samples = std::vector<std::vector<Vec2d>>;

struct Case {
  std::string name, group, tag, scene;  // scene: key of the reference and of the input range
  long points = 0;                      // samples per sampled contour (0: none)
  std::function<Samples()> samples;     // untimed
  std::function<std::vector<Shape>(const Samples&)> profiles;  // timed: preparation
  std::function<testing::Fixture<double>(const std::vector<Shape>&)> mechanism;
  std::string target;  // "analytic", "sampled1e3", "sampled1e5" or empty
  bool sweep = true;   // false: preparation only (e.g. --quick for 1e5 and 1e6 points)
};

struct Row {
  std::string name, group, tag, scene, target, verdict, note;
  long points = 0;
  double prep_ms = kNaN, table_ms = kNaN, bytes = kNaN, bytes_per_point = kNaN, peak_bytes = kNaN,
         retained_bytes = kNaN, rss_per_point = kNaN;
  double us_pose = kNaN, evals_pose = kNaN, max_err = kNaN;
  int solved = 0, total = 0;
};

/// A number with a printf format, "-" for NaN.
inline std::string fmt(const char* f, double v) {
  if (std::isnan(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

/// Runs the cases: preparation (time, memory), a timed sweep, the error against the scene's reference; prints
/// one row per case.
class Bench {
 public:
  explicit Bench(Options o);

  /// The inputs of a scene's sweep (1-degree steps), made once.
  const std::vector<double>& inputs(const std::string& scene);
  /// The scene's reference link angles at its inputs, computed once.
  const Reference& reference(const std::string& scene);
  Row run(const Case& c);

  static void print_header();
  static void print_row(const Row& r);

  int repeats() const { return repeats_; }
  const Options& options() const { return opt_; }

 private:
  Options opt_;
  int repeats_;
  std::map<std::string, std::vector<double>> inputs_;
  std::map<std::string, Reference> refs_;
};

// ---- the cases (profile_cases.cpp) -----------------------------------------------------------------------

/// "1e6" for a power of ten from 1000 on, else the number.
std::string count_tag(long n);
std::vector<Case> make_cases(bool quick);

// ---- savings and memory (savings.cpp) --------------------------------------------------------------------

struct Saving {
  std::string what, base_name, alt_name, unit, note;
  double base = kNaN, alt = kNaN;
  double ratio() const { return alt / base; }
};

/// The savings the design makes, measured in the same run (printed as they are measured).
std::vector<Saving> measure_savings(Bench& bench, const std::vector<Row>& rows);
/// Loading an n-point contour from a point file and preparing it.
Row load_and_prepare(long n);
/// Memory linear in the points: bytes per point of the sampled parabola over its sizes.
Row memory_linearity(const std::vector<Row>& rows);

// ---- output files (bench_files.cpp) ----------------------------------------------------------------------

void write_csv(const std::string& path, const std::vector<Row>& rows, const std::vector<Saving>& savings);
/// log10(time per pose) against log10(max error), one series per group, every marker labelled with its tag.
void write_svg(const std::string& path, const std::vector<Row>& rows, const std::string& subtitle);

}  // namespace rollkin::bench::profiles
