// rollkin_bench: accuracy and speed of the position solver over the profile representations (issue
// "Accuracy and speed"). A separate executable, not a unit test: it measures and prints, it never asserts.
//
//   rollkin_bench [--quick] [--csv FILE] [--svg FILE] [--repeats N] [--only TEXT] [--no-reference]
//
// Every case sweeps its input in 1-degree steps with rollkin::sweep (one thread, steady_clock). Reported per
// case: median over N sweeps of (sweep time / poses), evaluations per pose (the sum of the poses'
// SolveReport::evaluations: residual and Jacobian evaluations, each with a factorisation, over all
// sub-steps), profile preparation time and memory, and the largest error of
// any link's world angle (which includes every revolute angle) against an MPFR (50 digits) solution of the
// exact analytic mechanism at the same inputs. See docs/benchmark.md.
#include "measure.hpp"
#include "scenes.hpp"

#include "rollkin/io/atomic_file.hpp"
#include "rollkin/io/csv.hpp"
#include "rollkin/io/point_file.hpp"
#include "rollkin/io/svg_chart.hpp"
#include "rollkin/io/svg_markup.hpp"
#include "rollkin/scalar_mpfr.hpp"
#include "rollkin/solve/interference.hpp"

#include <CLI/CLI.hpp>

#include <malloc.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <regex>
#include <sstream>

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
    r.angles.push_back(p.report.ok() ? link_angles<M>(f.mech, p.q) : std::vector<M>{});
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
    const std::vector<double> a = link_angles<double>(m, res.poses[i].q);
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
      evals += p.report.evaluations;
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
         retained_bytes = kNaN, rss_per_point = kNaN;
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
  if (std::isnan(r.us_pose) || r.solved < r.total) return "MISS (not all solved)";
  if (std::isnan(r.max_err)) return "time only (no reference)";
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
      row.rss_per_point = mem.retained / (static_cast<double>(c.points) * sampled);
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
    std::printf("%-36s %8s %9s %7s %7s %9s %6s %10s %8s  %s\n", "case", "points", "prep_ms", "B/pt", "RSS/pt",
                "us/pose", "evals", "max_err", "solved", "target");
  }
  static void print_row(const Row& r) {
    std::printf("%-36s %8s %9s %7s %7s %9s %6s %10s %8s  %s\n", r.name.c_str(),
                r.points ? fmt("%.0f", static_cast<double>(r.points)).c_str() : "-", fmt("%.3f", r.prep_ms).c_str(),
                fmt("%.1f", r.bytes_per_point).c_str(), fmt("%.1f", r.rss_per_point).c_str(), fmt("%.3f", r.us_pose).c_str(),
                fmt("%.2f", r.evals_pose).c_str(), fmt("%.2e", r.max_err).c_str(),
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
    c.tag = "P" + count_tag(n);
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
    c.tag = rolling ? "EG analytic" : "EC analytic";
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
      d.tag = (rolling ? "EG" : "EC") + count_tag(n);
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
      c.tag = (rolling ? "NG" : "NC") + count_tag(n);
      c.scene = rolling ? "noncircular" : "noncircular_cam";
      c.points = n;
      c.samples = [n] {
        const GearPair<double> g = NonCircularGears{}.pitch_curves(static_cast<std::size_t>(n));
        return Samples{g.gear1, g.gear2};
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

// ---- the savings the design makes (ratios measured in the same run) -----------------------------------------

struct Saving {
  std::string what, base_name, alt_name, unit, note;
  double base = kNaN, alt = kNaN;
  double ratio() const { return alt / base; }
};

void print_saving(const Saving& s) {
  std::printf("%-40s %-26s %10s  %-30s %10s  %s %8s\n", s.what.c_str(), s.base_name.c_str(), fmt("%.3f", s.base).c_str(),
              s.alt_name.c_str(), fmt("%.3f", s.alt).c_str(), s.unit.c_str(), fmt("%.2f", s.ratio()).c_str());
  if (!s.note.empty()) std::printf("    note: %s\n", s.note.c_str());
  std::fflush(stdout);
}

/// A plain continuation loop written here (tangent predictor q + qdot h, Newton, velocity), optionally with
/// the acceleration at every pose: the same work with and without accelerations.
struct LoopTiming {
  double us_pose = kNaN, evals_pose = kNaN;
};

LoopTiming time_manual_loop(const testing::Fixture<double>& f, const std::vector<double>& inputs, int repeats,
                            bool accelerations) {
  const Mechanism<double>& m = f.mech;
  SolveData<double> sd(m);
  VectorX<double> q0;
  const SolveReport<double> rep = testing::assemble_fixture(f, q0, sd);
  LoopTiming out;
  if (!rep.ok()) return out;
  const int var = m.drivers[0];
  std::vector<double> up, down;
  for (double x : inputs) (x >= q0(var) ? up : down).push_back(x);
  std::sort(up.begin(), up.end());
  std::sort(down.begin(), down.end(), std::greater<>());
  const VectorX<double> rate = VectorX<double>::Ones(1), zero = VectorX<double>::Zero(1);
  VectorX<double> q, v, acc;
  double sink = 0;
  long evals = 0;
  auto once = [&] {
    evals = 0;
    for (const auto* side : {&up, &down}) {
      q = q0;
      solve_position(m, q, sd);
      solve_velocity(m, sd, rate, v);
      for (double t : *side) {
        const double h = t - q(var);
        q += v * h;
        q(var) = t;
        evals += solve_position(m, q, sd).evaluations;
        solve_velocity(m, sd, rate, v);
        if (accelerations) {
          acc = solve_acceleration(m, q, sd, v, zero);
          sink += acc(m.unknowns[0]);
        }
      }
    }
  };
  once();
  std::vector<double> per_pose;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = Clock::now();
    once();
    per_pose.push_back(seconds_since(t0) / static_cast<double>(inputs.size()));
  }
  g_sink += sink != 0;
  out.us_pose = 1e6 * median(per_pose);
  out.evals_pose = static_cast<double>(evals) / static_cast<double>(inputs.size());
  return out;
}

const Row* find_row(const std::vector<Row>& rows, const std::string& name) {
  for (const Row& r : rows)
    if (r.name == name) return &r;
  return nullptr;
}

std::vector<Saving> measure_savings(Bench& bench, const std::vector<Row>& rows) {
  std::vector<Saving> out;
  auto emit = [&](Saving s) {
    print_saving(s);
    out.push_back(std::move(s));
  };
  const int repeats = bench.repeats();
  const testing::Fixture<double> paper = testing::paper_fourbar<double>();
  const std::vector<double>& in = bench.inputs("paper");

  // 1. Closed-form arc length vs quadrature (and vs the exact Bezier and the sampled spline).
  if (const Row* base = find_row(rows, "paper: parabola closed form"))
    for (const Row& r : rows)
      if (r.scene == "paper" && &r != base && !std::isnan(r.us_pose) &&
          (r.group.find("analytic") == 0 || r.group.find("Bezier") == 0))
        emit({"closed form vs " + r.tag, "closed form", r.name.substr(7), "us/pose",
              "max error " + fmt("%.1e", base->max_err) + " vs " + fmt("%.1e", r.max_err) + " rad", base->us_pose,
              r.us_pose});
  if (const Row* e = find_row(rows, "elliptical gears: analytic"))
    if (const Row* s = find_row(rows, "elliptical gears: sampled 1e4"))
      emit({"ellipse closed form (ellint_2) vs spline", "analytic ellipse", "sampled 1e4", "us/pose",
            "Boost.Math incomplete elliptic integral per arc-length evaluation", e->us_pose, s->us_pose});

  // 2. Accelerations only when asked: the same loop with and without solve_acceleration per pose.
  {
    const LoopTiming without = time_manual_loop(paper, in, repeats, false);
    const LoopTiming with = time_manual_loop(paper, in, repeats, true);
    emit({"acceleration only when asked", "positions+velocities", "+ solve_acceleration", "us/pose",
          "paper, analytic; tangent-predictor loop written in bench/, " + fmt("%.2f", without.evals_pose) + " evals/pose",
          without.us_pose, with.us_pose});
  }

  // 3. Interference checks (opt-in, solve/interference.hpp): the sweep alone vs sweep + check_interference.
  {
    SolveData<double> sd(paper.mech);
    VectorX<double> q0;
    const SolveReport<double> rep = testing::assemble_fixture(paper, q0, sd);
    for (int samples : {1024, 256}) {
      InterferenceCheck opt;
      opt.samples_per_contour = samples;
      std::vector<double> plain, checked;
      std::size_t findings = 0;
      for (int r = 0; r < std::max(3, repeats / 4); ++r) {
        const auto t0 = Clock::now();
        const SweepResult<double> res = sweep(paper.mech, sd, q0, rep, 0, in);
        const auto t1 = Clock::now();
        const SweepInterference inter = check_interference(paper.mech, res, opt);
        const auto t2 = Clock::now();
        plain.push_back(std::chrono::duration<double>(t1 - t0).count() / static_cast<double>(in.size()));
        checked.push_back(std::chrono::duration<double>(t2 - t0).count() / static_cast<double>(in.size()));
        findings = 0;
        for (const auto& p : inter.poses) findings += p.findings.size();
      }
      emit({"interference checks only when asked", "sweep", "sweep + check_interference", "us/pose",
            "paper, analytic, " + std::to_string(samples) + " samples/contour, " + std::to_string(findings) +
                " findings",
            1e6 * median(plain), 1e6 * median(checked)});
    }
  }

  // 4. Predictors (ContinuationSettings::predictor): Hermite (default) vs tangent vs zero order.
  for (const char* scene : {"paper", "cam"}) {
    const testing::Fixture<double> f =
        std::string(scene) == "paper" ? paper
                                      : testing::elliptical_gears<double>(2, 0.5, false, {}, 30 * pi<double>() / 180);
    const std::vector<double>& inputs = bench.inputs(scene);
    ContinuationSettings<double> cfg;
    std::map<Predictor, SweepTiming> t;
    for (Predictor p : {Predictor::Hermite, Predictor::Tangent, Predictor::Previous}) {
      cfg.predictor = p;
      t[p] = time_sweep(f, inputs, repeats, cfg);
    }
    const std::string where = std::string(scene) == "paper" ? "paper" : "ellipse cam";
    auto note = [&](Predictor a, Predictor b) {
      return "evals/pose " + fmt("%.2f", t[a].evals_pose) + " vs " + fmt("%.2f", t[b].evals_pose) + "; solved " +
             std::to_string(t[a].solved) + " vs " + std::to_string(t[b].solved);
    };
    emit({"predictor (" + where + ")", "Hermite (default)", "tangent q + qdot h", "us/pose",
          note(Predictor::Hermite, Predictor::Tangent), t[Predictor::Hermite].us_pose, t[Predictor::Tangent].us_pose});
    emit({"predictor (" + where + ")", "Hermite (default)", "zero order (previous pose)", "us/pose",
          note(Predictor::Hermite, Predictor::Previous), t[Predictor::Hermite].us_pose, t[Predictor::Previous].us_pose});
  }

  // 5. Arc-length table built once vs rebuilt: table build time against the time per pose.
  for (const Row& r : rows)
    if (r.group == "sampled parabola (spline)" && !std::isnan(r.table_ms))
      emit({"arc-length table once vs per pose (" + r.tag + ")", "us/pose (table kept)", "table build", "us",
            "ratio = poses one rebuild costs", r.us_pose, 1e3 * r.table_ms});
  return out;
}

/// Loading a 10^6-point contour from a point file and preparing it.
Row load_and_prepare(long n) {
  Row row;
  row.name = "load+prepare " + count_tag(n) + "-point file";
  row.group = "load";
  row.tag = count_tag(n);
  row.scene = "-";
  row.points = n;
  row.target = "load1e6";
  const std::string path = "/tmp/rollkin_bench_" + std::to_string(::getpid()) + ".txt";
  {
    std::FILE* f = std::fopen(path.c_str(), "w");
    if (!f) {
      row.note = "cannot write " + path;
      return row;
    }
    std::fprintf(f, "# y = 0.5 x^2, %ld points\n", n);
    for (const Vec2d& p : parabola_samples(0.5, -2, 2, static_cast<std::size_t>(n)))
      std::fprintf(f, "%.17g %.17g\n", p.x(), p.y());
    std::fclose(f);
  }
  std::vector<double> load, prep;
  for (int k = 0; k < 3; ++k) {
    const auto t0 = Clock::now();
    const std::vector<Vec2d> q = read_point_file(path, 2);
    const auto t1 = Clock::now();
    const SampledProfile<double> p(q);
    load.push_back(std::chrono::duration<double>(t1 - t0).count());
    prep.push_back(seconds_since(t1));
    g_sink += p.span_count();
  }
  std::remove(path.c_str());
  row.prep_ms = 1e3 * (median(load) + median(prep));
  row.note = "read_point_file " + fmt("%.1f", 1e3 * median(load)) + " ms + SampledProfile " +
             fmt("%.1f", 1e3 * median(prep)) + " ms (median of 3)";
  row.verdict = row.prep_ms < 1000 ? "PASS (< 1 s, " + fmt("%.2f", row.prep_ms / 1000) + " s)"
                                   : "MISS (< 1 s: x" + fmt("%.2f", row.prep_ms / 1000) + ")";
  return row;
}

/// Memory linear in the points: bytes per point of the sampled parabola over its sizes.
Row memory_linearity(const std::vector<Row>& rows) {
  Row row;
  row.name = "memory per point (sampled parabola)";
  row.group = "memory";
  row.scene = "-";
  row.target = "linear";
  double lo = INFINITY, hi = 0;
  std::string list;
  for (const Row& r : rows)
    if (r.group == "sampled parabola (spline)" && r.points >= 10000) {
      list += (list.empty() ? "" : ", ") + r.tag + ": " + fmt("%.1f", r.bytes_per_point) + " B/pt data, " +
              fmt("%.1f", r.rss_per_point) + " B/pt RSS retained, " + fmt("%.1f", r.peak_bytes / r.points) + " B/pt peak";
      lo = std::min(lo, r.rss_per_point);
      hi = std::max(hi, r.rss_per_point);
    }
  row.note = list;
  if (hi > 0) row.verdict = (hi <= 1.5 * lo ? "PASS" : "MISS") + std::string(" (RSS/pt spread x") + fmt("%.2f", hi / lo) + ")";
  return row;
}

// ---- output files -------------------------------------------------------------------------------------------

void write_csv(const std::string& path, const std::vector<Row>& rows, const std::vector<Saving>& savings) {
  std::ostringstream o;
  o << "section,case,group,tag,scene,points,prep_ms,table_ms,profile_bytes,bytes_per_point,rss_bytes_per_point,"
       "peak_rss_bytes,us_per_pose,evals_per_pose,max_err_rad,solved,total,target,verdict,note,baseline,baseline_value,"
       "value,unit,ratio\n";
  auto d = [](double v) { return io::format_double(v); };
  for (const Row& r : rows)
    o << "case," << io::csv_field(r.name) << ',' << io::csv_field(r.group) << ',' << io::csv_field(r.tag) << ','
      << r.scene << ',' << r.points << ',' << d(r.prep_ms) << ',' << d(r.table_ms) << ',' << d(r.bytes) << ','
      << d(r.bytes_per_point) << ',' << d(r.rss_per_point) << ',' << d(r.peak_bytes) << ',' << d(r.us_pose) << ','
      << d(r.evals_pose) << ',' << d(r.max_err) << ',' << r.solved << ',' << r.total << ',' << r.target << ','
      << io::csv_field(r.verdict) << ',' << io::csv_field(r.note) << ",,,,,\n";
  for (const Saving& s : savings)
    o << "saving," << io::csv_field(s.what) << ",," << io::csv_field(s.alt_name) << std::string(16, ',')
      << io::csv_field(s.note) << ','
      << io::csv_field(s.base_name) << ',' << d(s.base) << ',' << d(s.alt) << ',' << io::csv_field(s.unit) << ','
      << d(s.ratio()) << '\n';
  io::write_file_atomic(path, o.str());
}

/// log10(time per pose) against log10(max error), one series per group; every marker labelled with its case
/// tag (the chart draws the markers, the labels are added at the markers' pixel positions).
void write_svg(const std::string& path, const std::vector<Row>& rows, const std::string& subtitle) {
  io::SvgChart chart(1100, 640);
  chart.set_title("rollkin: time per pose against max angle error (" + subtitle + ")")
      .set_x_label("log10(time per pose / us)")
      .set_y_label("log10(max link-angle error / rad), vs MPFR 50 digits")
      .set_legend(io::LegendPosition::Outside);
  std::vector<std::string> groups;
  std::map<std::string, std::vector<const Row*>> by_group;
  for (const Row& r : rows) {
    if (std::isnan(r.us_pose) || std::isnan(r.max_err) || r.solved < r.total || r.total == 0) continue;
    if (!by_group.count(r.group)) groups.push_back(r.group);
    by_group[r.group].push_back(&r);
  }
  std::vector<std::vector<std::string>> labels;
  for (const std::string& g : groups) {
    io::ChartSeries s;
    s.name = g;
    s.markers = true;
    s.stroke_width = 1.4;
    std::vector<std::string> tags;
    for (const Row* r : by_group[g]) {
      s.x.push_back(std::log10(r->us_pose));
      s.y.push_back(std::log10(std::max(r->max_err, 1e-17)));
      tags.push_back(r->tag);
    }
    if (g.find("sampled") == std::string::npos) s.dash = "2 4";  // unrelated variants: no curve implied
    chart.add_series(s);
    labels.push_back(tags);
  }
  std::string svg = chart.to_svg();
  // Label the markers: the k-th series <g> holds its markers in order.
  std::string out;
  std::size_t pos = 0, series = 0;
  const std::regex marker("<circle class=\"marker\" cx=\"([-0-9.]+)\" cy=\"([-0-9.]+)\"");
  std::string labels_svg = "<g class=\"labels\" font-size=\"10\" fill=\"#333333\">\n";
  while (true) {
    const std::size_t g = svg.find("<g class=\"series\"", pos);
    if (g == std::string::npos || series >= labels.size()) break;
    const std::size_t end = svg.find("</g>", g);
    const std::string block = svg.substr(g, end - g);
    std::size_t k = 0;
    for (auto it = std::sregex_iterator(block.begin(), block.end(), marker); it != std::sregex_iterator() && k < labels[series].size();
         ++it, ++k)
      labels_svg += "<text x=\"" + fmt("%.2f", std::stod((*it)[1]) + 5) + "\" y=\"" + fmt("%.2f", std::stod((*it)[2]) - 4) +
                    "\">" + io::xml_escape(labels[series][k]) + "</text>\n";
    pos = end;
    ++series;
  }
  labels_svg += "</g>\n";
  const std::size_t close = svg.rfind("</svg>");
  svg.insert(close, labels_svg);
  io::write_file_atomic(path, svg);
}

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
