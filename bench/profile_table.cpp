// rollkin_bench, the accuracy and speed table (bench/main.cpp, docs/benchmark.md): link angles against an
// MPFR (50 digits) solution of the exact analytic mechanism, the timed sweep, a profile's bytes, and the runner
// that makes one row per case.
#include "profile_bench.hpp"

#include <iostream>
#include <variant>

namespace rollkin::bench::profiles {

std::size_t g_sink = 0;

namespace {

// ---- link angles and the MPFR reference ---------------------------------------------------------------

template <class S> std::vector<S> link_angles(const Mechanism<S>& m, const VectorX<S>& q) {
  KinematicsData<S> kin(m);
  evaluate_pairs<S>(m, q, nullptr, 2, kin);
  std::vector<S> a;
  for (const SE2<S>& p : link_poses(m, kin)) a.push_back(p.angle());
  return a;
}

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

}  // namespace

SweepTiming time_sweep(const testing::Fixture<double>& f, const std::vector<double>& inputs, int repeats,
                       const ContinuationSettings<double>& cfg) {
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

namespace {

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

}  // namespace

Bench::Bench(Options o) : opt_(std::move(o)) {
  repeats_ = opt_.repeats > 0 ? opt_.repeats : (opt_.quick ? 7 : 31);
}

const std::vector<double>& Bench::inputs(const std::string& scene) {
  auto it = inputs_.find(scene);
  if (it != inputs_.end()) return it->second;
  std::vector<double> v;
  if (scene == "paper") v = testing::degrees<double>(-50, 100);
  else if (scene == "gears" || scene == "noncircular") v = testing::degrees<double>(0, 360);
  else v = testing::degrees<double>(5, 175);  // cam pairs, between the singular vertex poses
  return inputs_[scene] = v;
}

const Reference& Bench::reference(const std::string& scene) {
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
    r = sweep_reference(testing::elliptical_gears<M>(M(2), M(1) / M(2), false, {}, deg_to_rad(M(30))), in);
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

Row Bench::run(const Case& c) {
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

void Bench::print_header() {
  std::printf("%-36s %8s %9s %7s %7s %9s %6s %10s %8s  %s\n", "case", "points", "prep_ms", "B/pt", "RSS/pt",
              "us/pose", "evals", "max_err", "solved", "target");
}
void Bench::print_row(const Row& r) {
  std::printf("%-36s %8s %9s %7s %7s %9s %6s %10s %8s  %s\n", r.name.c_str(),
              r.points ? fmt("%.0f", static_cast<double>(r.points)).c_str() : "-", fmt("%.3f", r.prep_ms).c_str(),
              fmt("%.1f", r.bytes_per_point).c_str(), fmt("%.1f", r.rss_per_point).c_str(), fmt("%.3f", r.us_pose).c_str(),
              fmt("%.2f", r.evals_pose).c_str(), fmt("%.2e", r.max_err).c_str(),
              r.total ? (std::to_string(r.solved) + "/" + std::to_string(r.total)).c_str() : "-", r.verdict.c_str());
  if (!r.note.empty()) std::printf("    note: %s\n", r.note.c_str());
  std::fflush(stdout);
}

}  // namespace rollkin::bench::profiles
