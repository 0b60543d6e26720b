// rollkin_bench: accuracy and speed of the position solver over the profile representations (issue
// "Accuracy and speed"). A separate executable, not a unit test: it measures and prints, it never asserts.
//
//   rollkin_bench [--quick] [--csv FILE] [--svg FILE] [--repeats N] [--only TEXT] [--no-reference]
//
// Every case sweeps its input in 1-degree steps with rollkin::sweep (one thread, steady_clock). Reported per
// case: median over N sweeps of (sweep time / poses), Newton evaluations per pose (the sum of the poses'
// SolveReport::iterations, which the tracer counts as Newton iterations + 1 per sub-step, i.e. residual and
// Jacobian evaluations with a factorisation), profile preparation time and memory, and the largest error of
// any link's world angle (which includes every revolute angle) against an MPFR (50 digits) solution of the
// exact analytic mechanism at the same inputs. See docs/benchmark.md.
#include "measure.hpp"
#include "scenes.hpp"

#include "rollkin/io/atomic_file.hpp"
#include "rollkin/io/csv.hpp"
#include "rollkin/io/point_file.hpp"
#include "rollkin/io/svg.hpp"
#include "rollkin/scalar_mpfr.hpp"

#include <malloc.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <regex>

using namespace rollkin;
using namespace rollkin::bench;
using M = mpfr50;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Options {
  bool quick = false;
  bool reference = true;
  int repeats = 0;  // 0: 31 (full) or 7 (quick)
  std::string csv, svg, only;
};

// ---- link angles and the MPFR reference ---------------------------------------------------------------

template <class S> std::vector<S> link_angles(const Mechanism<S>& m, const VectorX<S>& q) {
  KinematicsData<S> kin(m);
  evaluate_pairs<S>(m, q, nullptr, 2, kin);
  std::vector<S> a;
  for (const SE2<S>& p : link_poses(m, kin)) a.push_back(p.angle());
  return a;
}

/// World angle of every link at every input (empty where the reference did not solve).
struct Reference {
  std::vector<std::vector<M>> angles;
  double seconds = 0;
  int solved = 0;
  std::string how;
};

Reference sweep_reference(const testing::Fixture<M>& f, const std::vector<double>& inputs) {
  const auto t0 = Clock::now();
  Reference r;
  SolveData<M> sd(f.mech);
  VectorX<M> q;
  const SolveReport<M> rep = testing::assemble_fixture(f, q, sd);
  std::vector<M> in;
  for (double x : inputs) in.emplace_back(x);  // exactly the double inputs
  const SweepResult<M> res = sweep(f.mech, sd, q, rep, 0, in);
  for (const auto& p : res.poses) {
    r.angles.push_back(p.report.ok() ? link_angles(f.mech, p.q) : std::vector<M>{});
    r.solved += p.report.ok();
  }
  r.seconds = seconds_since(t0);
  r.how = "analytic mechanism, sweep() in mpfr50";
  return r;
}

/// Largest |wrapped link-angle difference| over the poses both solved.
double max_angle_error(const Mechanism<double>& m, const SweepResult<double>& res, const Reference& ref) {
  double worst = 0;
  bool any = false;
  for (std::size_t i = 0; i < res.poses.size() && i < ref.angles.size(); ++i) {
    if (!res.poses[i].report.ok() || ref.angles[i].empty()) continue;
    const std::vector<double> a = link_angles(m, res.poses[i].q);
    for (std::size_t l = 0; l < a.size(); ++l) {
      const double d = std::remainder(static_cast<double>(M(a[l]) - ref.angles[i][l]), 2 * pi<double>());
      worst = std::max(worst, std::abs(d));
      any = true;
    }
  }
  return any ? worst : kNaN;
}

// ---- timing a sweep ---------------------------------------------------------------------------------------

struct SweepTiming {
  SolveReport<double> assembly;
  SweepResult<double> result;  // of the first (untimed) sweep
  double us_pose = kNaN, evals_pose = kNaN;
  int solved = 0;
};

std::size_t g_sink = 0;  // keeps the timed work observable

SweepTiming time_sweep(const testing::Fixture<double>& f, const std::vector<double>& inputs, int repeats,
                       const ContinuationSettings<double>& cfg = {}) {
  SweepTiming t;
  SolveData<double> sd(f.mech);
  VectorX<double> q0;
  t.assembly = testing::assemble_fixture(f, q0, sd);
  t.result = sweep(f.mech, sd, q0, t.assembly, 0, inputs, cfg);  // warm-up, and the poses compared
  long evals = 0;
  for (const auto& p : t.result.poses)
    if (p.report.ok()) {
      ++t.solved;
      evals += p.report.iterations;
    }
  if (!t.assembly.ok()) return t;
  std::vector<double> per_pose;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = Clock::now();
    const SweepResult<double> res = sweep(f.mech, sd, q0, t.assembly, 0, inputs, cfg);
    per_pose.push_back(seconds_since(t0) / static_cast<double>(inputs.size()));
    g_sink += res.poses.size();
  }
  t.us_pose = 1e6 * median(per_pose);
  t.evals_pose = t.solved ? static_cast<double>(evals) / t.solved : kNaN;
  return t;
}

// ---- profiles -------------------------------------------------------------------------------------------

/// Bytes of a profile's own data (knots, coefficients, tables), from the container sizes.
double profile_bytes(const Shape& shape) {
  return std::visit(
      [](const auto& p) -> double {
        using P = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<P, SampledProfile<double>>) {
          // knots_ (double), values_ and second_ (Vec2) per node, arc-length table (double) per node.
          const double nodes = static_cast<double>(p.knots().size());
          return sizeof(P) + nodes * (sizeof(double) + 2 * sizeof(Vec2d)) + nodes * sizeof(double);
        } else if constexpr (std::is_same_v<P, BezierPath<double>>) {
          double b = sizeof(P);
          for (const auto& s : p.segments()) {
            const double n = static_cast<double>(s.points.size());
            // control points + weights, hodograph (homogeneous points and 3 difference levels), panel count.
            b += n * sizeof(Vec2d) + static_cast<double>(s.weights.size()) * sizeof(double) + 4 * n * 3 * sizeof(double) +
                 sizeof(int);
          }
          return b + (static_cast<double>(p.segments().size()) + 1) * sizeof(double);  // arc-length table
        } else {
          return sizeof(P);
        }
      },
      shape);
}

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
         retained_bytes = kNaN;
  double us_pose = kNaN, evals_pose = kNaN, max_err = kNaN;
  int solved = 0, total = 0;
};

std::string fmt(const char* f, double v) {
  if (std::isnan(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

std::string verdict_for(const Row& r) {
  double us_max = 0, err_max = 0;
  if (r.target == "analytic") us_max = 1.0, err_max = 1e-12;
  else if (r.target == "sampled1e3") us_max = 2.0, err_max = 1e-7;
  else if (r.target == "sampled1e5") us_max = 2.0, err_max = 1e-11;
  else return "";
  if (r.total == 0) return "not measured (no sweep)";
  if (std::isnan(r.us_pose) || std::isnan(r.max_err) || r.solved < r.total) return "MISS (not all solved)";
  const bool t_ok = r.us_pose <= us_max, e_ok = r.max_err <= err_max;
  std::string v = t_ok && e_ok ? "PASS" : "MISS";
  v += " (<= " + fmt("%g", us_max) + " us " + (t_ok ? "ok" : "x" + fmt("%.2f", r.us_pose / us_max)) + ", <= " +
       fmt("%g", err_max) + " rad " + (e_ok ? "ok" : "x" + fmt("%.1f", r.max_err / err_max)) + ")";
  return v;
}

// ---- the runner -------------------------------------------------------------------------------------------

class Bench {
 public:
  explicit Bench(Options o) : opt_(std::move(o)) {
    repeats_ = opt_.repeats > 0 ? opt_.repeats : (opt_.quick ? 7 : 31);
  }

  const std::vector<double>& inputs(const std::string& scene) {
    auto it = inputs_.find(scene);
    if (it != inputs_.end()) return it->second;
    std::vector<double> v;
    if (scene == "paper") v = testing::degrees<double>(-50, 100);
    else if (scene == "gears" || scene == "noncircular") v = testing::degrees<double>(0, 360);
    else v = testing::degrees<double>(5, 175);  // cam pairs, between the singular vertex poses
    return inputs_[scene] = v;
  }

  const Reference& reference(const std::string& scene) {
    auto it = refs_.find(scene);
    if (it != refs_.end()) return it->second;
    Reference r;
    const std::vector<double>& in = inputs(scene);
    if (!opt_.reference) {
      r.how = "skipped (--no-reference)";
    } else if (scene == "paper") {
      r = sweep_reference(testing::paper_fourbar<M>(), in);
    } else if (scene == "gears") {
      r = sweep_reference(testing::elliptical_gears<M>(M(2), M(1) / M(2), true), in);
    } else if (scene == "cam") {
      r = sweep_reference(testing::elliptical_gears<M>(M(2), M(1) / M(2), false, {}, M(30) * pi<M>() / M(180)), in);
    } else if (scene == "noncircular" || scene == "noncircular_cam") {
      // No analytic profile type for these pitch curves: the reference is the transmission function itself,
      // phi2 = -f(phi1), evaluated in mpfr50 (the pose the exact pitch curves give).
      const auto t0 = Clock::now();
      const NonCircularGears g;
      for (double x : in) {
        const M p(x);
        r.angles.push_back({M(0), p, M(-(p + M(g.k) * sin(p)))});
        ++r.solved;
      }
      r.seconds = seconds_since(t0);
      r.how = "transmission function phi2 = -f(phi1) in mpfr50";
    }
    std::cout << "  [reference " << scene << ": " << r.how << ", " << r.solved << "/" << in.size() << " poses, "
              << fmt("%.2f", r.seconds) << " s]\n";
    return refs_[scene] = std::move(r);
  }

  Row run(const Case& c) {
    Row row;
    row.name = c.name;
    row.group = c.group;
    row.tag = c.tag;
    row.scene = c.scene;
    row.points = c.points;
    row.target = c.target;
    const Samples samples = c.samples ? c.samples() : Samples{};
    // Preparation: building the profiles (spline solve + arc-length table), median of a few builds; memory
    // of the first build.
    std::vector<Shape> shapes;
    const MemoryDelta mem = measure_memory([&] { shapes = c.profiles(samples); });
    const int builds = c.points >= 1000000 ? 3 : (c.points >= 100000 ? 5 : 9);
    std::vector<double> prep;
    for (int k = 0; k < builds; ++k) {
      const auto t0 = Clock::now();
      const std::vector<Shape> again = c.profiles(samples);
      prep.push_back(seconds_since(t0));
      g_sink += again.size();
    }
    row.prep_ms = 1e3 * median(prep);
    row.bytes = 0;
    for (const Shape& s : shapes) row.bytes += profile_bytes(s);
    if (c.points > 0) {
      row.peak_bytes = mem.peak;
      row.retained_bytes = mem.retained;
      double sampled = 0, sampled_bytes = 0;  // per sampled profile (both gears may share one sample set)
      for (const Shape& s : shapes)
        if (std::holds_alternative<SampledProfile<double>>(s)) sampled += 1, sampled_bytes += profile_bytes(s);
      row.bytes_per_point = sampled_bytes / (static_cast<double>(c.points) * sampled);
      // Arc-length table alone (rebuilt vs kept): the first sampled profile's table.
      if (const auto* sp = std::get_if<SampledProfile<double>>(&shapes.front())) {
        std::vector<double> t;
        for (int k = 0; k < builds; ++k) {
          const auto t0 = Clock::now();
          const PiecewiseArcLength<double> table(*sp);
          t.push_back(seconds_since(t0));
          g_sink += table.cumulative().size();
        }
        row.table_ms = 1e3 * median(t);
      }
    }
    if (c.sweep) {
      const testing::Fixture<double> f = c.mechanism(shapes);
      const std::vector<double>& in = inputs(c.scene);
      const SweepTiming t = time_sweep(f, in, repeats_);
      row.total = static_cast<int>(in.size());
      row.solved = t.solved;
      row.us_pose = t.us_pose;
      row.evals_pose = t.evals_pose;
      if (!t.assembly.ok()) row.note = "assembly: " + std::string(to_string(t.assembly.status)) + " " + t.assembly.detail;
      else if (t.solved < row.total)
        for (const auto& l : t.result.limits) row.note += (row.note.empty() ? "" : "; ") + l.detail;
      row.max_err = max_angle_error(f.mech, t.result, reference(c.scene));
    } else {
      row.note = "preparation only (--quick)";
    }
    row.verdict = verdict_for(row);
    print_row(row);
    return row;
  }

  static void print_header() {
    std::printf("%-34s %8s %9s %8s %9s %9s %6s %10s %8s  %s\n", "case", "points", "prep_ms", "B/pt", "us/pose",
                "evals/pose", "", "max_err", "solved", "target");
  }
  static void print_row(const Row& r) {
    std::printf("%-34s %8s %9s %8s %9s %9s %6s %10s %8s  %s\n", r.name.c_str(),
                r.points ? fmt("%.0f", static_cast<double>(r.points)).c_str() : "-", fmt("%.3f", r.prep_ms).c_str(),
                fmt("%.1f", r.bytes_per_point).c_str(), fmt("%.3f", r.us_pose).c_str(), fmt("%.2f", r.evals_pose).c_str(),
                "", fmt("%.2e", r.max_err).c_str(),
                r.total ? (std::to_string(r.solved) + "/" + std::to_string(r.total)).c_str() : "-", r.verdict.c_str());
    if (!r.note.empty()) std::printf("    note: %s\n", r.note.c_str());
    std::fflush(stdout);
  }

  int repeats() const { return repeats_; }
  const Options& options() const { return opt_; }

 private:
  Options opt_;
  int repeats_;
  std::map<std::string, std::vector<double>> inputs_;
  std::map<std::string, Reference> refs_;
};

// ---- the cases ----------------------------------------------------------------------------------------------

ArcLengthMethod quadrature(Quadrature kind, int order, int panels) {
  ArcLengthMethod m;
  m.closed_form = false;
  m.rule.kind = kind;
  m.rule.order = order;
  m.rule.panels = panels;
  return m;
}

std::string count_tag(long n) {
  if (n >= 1000 && n % 1000 == 0) {
    int e = 0;
    long m = n;
    while (m % 10 == 0) m /= 10, ++e;
    if (m == 1) return "1e" + std::to_string(e);
  }
  return std::to_string(n);
}

std::vector<Case> make_cases(bool quick) {
  std::vector<Case> cs;
  const double a = 0.5;
  // Reference example, analytic parabola.
  auto analytic_paper = [&](std::string name, std::string group, std::string tag, ArcLengthMethod arc, std::string target) {
    Case c;
    c.name = std::move(name);
    c.group = std::move(group);
    c.tag = std::move(tag);
    c.scene = "paper";
    c.target = std::move(target);
    c.profiles = [arc, a](const Samples&) {
      return std::vector<Shape>{Parabola<double>(a, -2, 2, arc), Circle<double>(1), Circle<double>(4)};
    };
    c.mechanism = [](const std::vector<Shape>& s) { return paper_scene(s[0], s[1], s[2]); };
    cs.push_back(c);
  };
  analytic_paper("paper: parabola closed form", "analytic (closed form)", "closed", {}, "analytic");
  for (auto [order, panels] : {std::pair{4, 1}, {8, 1}, {8, 4}, {16, 1}})
    analytic_paper("paper: parabola Gauss-Legendre " + std::to_string(order) + "x" + std::to_string(panels),
                   "analytic, Gauss-Legendre", "GL" + std::to_string(order) + "x" + std::to_string(panels),
                   quadrature(Quadrature::GaussLegendre, order, panels), "");
  for (int panels : {4, 16, 64, 256})
    analytic_paper("paper: parabola Simpson x" + std::to_string(panels), "analytic, Simpson (paper)",
                   "S" + std::to_string(panels), quadrature(Quadrature::NewtonCotes, 2, panels), "");
  {
    Case c;
    c.name = "paper: Bezier parabola";
    c.group = "Bezier (exact rational)";
    c.tag = "Bz";
    c.scene = "paper";
    c.profiles = [a](const Samples&) {
      return std::vector<Shape>{BezierPath<double>::parabola(a, -2, 2), Circle<double>(1), Circle<double>(4)};
    };
    c.mechanism = [](const std::vector<Shape>& s) { return paper_scene(s[0], s[1], s[2]); };
    cs.push_back(c);
    c.name = "paper: Bezier parabola + circles";
    c.tag = "Bz+circles";
    c.profiles = [a](const Samples&) {
      return std::vector<Shape>{BezierPath<double>::parabola(a, -2, 2), BezierPath<double>::circle(Vec2d(0, 0), 1),
                                BezierPath<double>::circle(Vec2d(0, 0), 4)};
    };
    cs.push_back(c);
  }
  for (long n : {50L, 100L, 1000L, 10000L, 100000L, 1000000L}) {
    Case c;
    c.name = "paper: sampled parabola " + count_tag(n);
    c.group = "sampled parabola (spline)";
    c.tag = count_tag(n);
    c.scene = "paper";
    c.points = n;
    c.target = n == 1000 ? "sampled1e3" : (n == 100000 ? "sampled1e5" : "");
    c.sweep = !(quick && n >= 100000);
    c.samples = [n, a] { return Samples{parabola_samples(a, -2, 2, static_cast<std::size_t>(n))}; };
    c.profiles = [](const Samples& s) {
      return std::vector<Shape>{SampledProfile<double>(s[0]), Circle<double>(1), Circle<double>(4)};
    };
    c.mechanism = [](const std::vector<Shape>& s) { return paper_scene(s[0], s[1], s[2]); };
    cs.push_back(c);
  }

  // Twin elliptical gears (a = 2, e = 0.5), rolling pair over a full turn.
  const double ga = 2, ge = 0.5, gb = ga * std::sqrt(1 - ge * ge);
  for (bool rolling : {true, false}) {
    const std::string scene = rolling ? "gears" : "cam";
    const double start = rolling ? 0 : 30 * pi<double>() / 180;
    const std::string kind = rolling ? "elliptical gears" : "elliptical cam pair";
    Case c;
    c.name = kind + ": analytic";
    c.group = rolling ? "ellipse gears, analytic" : "ellipse cam, analytic";
    c.tag = rolling ? "gears" : "cam";
    c.scene = scene;
    c.profiles = [ga, gb](const Samples&) { return std::vector<Shape>{Ellipse<double>(ga, gb), Ellipse<double>(ga, gb)}; };
    c.mechanism = [=](const std::vector<Shape>& s) { return gear_scene(s[0], s[1], ga, ge, rolling, start); };
    cs.push_back(c);
    std::vector<long> counts = {100, 1000, 10000};
    if (!quick) counts.push_back(100000);
    for (long n : counts) {
      Case d = c;
      d.name = kind + ": sampled " + count_tag(n);
      d.group = rolling ? "ellipse gears, sampled" : "ellipse cam, sampled";
      d.tag = count_tag(n);
      d.points = n;
      d.samples = [=] { return Samples{ellipse_samples(ga, gb, static_cast<std::size_t>(n))}; };
      d.profiles = [](const Samples& s) {
        SplineOptions<double> o;
        o.closed = true;
        const SampledProfile<double> p(s[0], o);
        return std::vector<Shape>{p, p};  // both gears share the pitch curve (two copies, as a scene would)
      };
      cs.push_back(d);
    }
  }

  // Non-circular gear pair synthesised from f(p) = p + 0.3 sin p (sampled pitch curves only).
  for (bool rolling : {true, false}) {
    std::vector<long> counts = {1000, 10000};
    if (!quick) counts.push_back(100000);
    for (long n : counts) {
      Case c;
      const std::string kind = rolling ? "non-circular gears" : "non-circular cam pair";
      c.name = kind + ": sampled " + count_tag(n);
      c.group = rolling ? "non-circular gears, sampled" : "non-circular cam, sampled";
      c.tag = count_tag(n);
      c.scene = rolling ? "noncircular" : "noncircular_cam";
      c.points = n;
      c.samples = [n] {
        const NonCircularGears g;
        return Samples{g.samples1(static_cast<std::size_t>(n)), g.samples2(static_cast<std::size_t>(n))};
      };
      c.profiles = [](const Samples& s) {
        SplineOptions<double> o;
        o.closed = true;
        return std::vector<Shape>{SampledProfile<double>(s[0], o), SampledProfile<double>(s[1], o)};
      };
      const double start = rolling ? 0 : 30 * pi<double>() / 180;
      c.mechanism = [rolling, start](const std::vector<Shape>& s) { return NonCircularGears{}.scene(s[0], s[1], rolling, start); };
      cs.push_back(c);
    }
  }
  return cs;
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::cerr << "rollkin_bench: " << a << " needs a value\n";
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--quick") opt.quick = true;
    else if (a == "--csv") opt.csv = value();
    else if (a == "--svg") opt.svg = value();
    else if (a == "--repeats") opt.repeats = std::stoi(value());
    else if (a == "--only") opt.only = value();
    else if (a == "--no-reference") opt.reference = false;
    else if (a == "-h" || a == "--help") {
      std::cout << "usage: rollkin_bench [--quick] [--csv FILE] [--svg FILE] [--repeats N] [--only TEXT] [--no-reference]\n";
      return 0;
    } else {
      std::cerr << "rollkin_bench: unknown option " << a << "\n";
      return 2;
    }
  }
  // Fixed mmap threshold: large blocks are mapped and returned to the system when freed, so the resident
  // memory deltas of one build are not hidden by the allocator keeping earlier blocks.
  mallopt(M_MMAP_THRESHOLD, 64 * 1024);
  Eigen::setNbThreads(1);

  Bench bench(opt);
  std::printf("rollkin_bench%s: %ld CPUs, %s; %s; %d timed sweeps per case (median), 1 thread\n",
              opt.quick ? " --quick" : "", cpu_count(), cpu_model().c_str(), compiler().c_str(), bench.repeats());
  Bench::print_header();
  std::vector<Row> rows;
  for (const Case& c : make_cases(opt.quick)) {
    if (!opt.only.empty() && c.name.find(opt.only) == std::string::npos) continue;
    rows.push_back(bench.run(c));
  }
  (void)g_sink;
  return 0;
}
