// rollkin_bench, the savings the design makes (ratios measured in the same run) and the memory rows
// (bench/main.cpp, docs/benchmark.md).
#include "profile_bench.hpp"

#include "rollkin/io/point_file.hpp"

#include <unistd.h>

#include <cstdio>

namespace rollkin::bench::profiles {
namespace {

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

}  // namespace

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

  // 3. Interference checks (opt-in, analysis/interference.hpp): the sweep alone vs sweep + check_interference.
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
    const std::vector<Vec2d> q = io::read_point_file(path, 2);
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

}  // namespace rollkin::bench::profiles
