// build/rollkin_bench_scaling: cost per pose against the number of loops N (docs/benchmark.md, "Scaling with
// the mechanism"). Families of rollkin/samples/mechanisms.hpp: disk_train(N) (N + 1 pivoted rolling disks, redundant
// constraints), four_bar_chain(N) and cam_gear_train(N) (the gear train with a cam and translating follower on
// each driven disk: rolling, cam, revolute and prismatic pairs, 2N loops); N = 2 .. 256; factorisations Dense (SmallLU / COD), Eigen SparseLU and
// KLU (solve/sparse_lu.hpp), and Automatic (what SolveData picks). Per case: us per pose (median over
// repeats of a path of poses, each an Euler predictor from the previous pose's velocity and Newton),
// Newton iterations per pose, one factorisation's time, the bytes of the solve data, the assembly's time (once
// per mechanism: it includes the sparse path's choice of independent rows); then the exponent of
// cost against N fitted by least squares on log-log, and the ratios. Not a test; see docs/benchmark.md.
#include "measure.hpp"
#include "rollkin/samples/mechanisms.hpp"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <string>
#include <vector>

using namespace rollkin;
using namespace rollkin::bench;
using testing::Fixture;

namespace {

const double kDeg = deg_to_rad(1.0);

struct Family {
  std::string name;
  std::function<Fixture<double>(int)> make;
  double step_deg;  // input step between poses (the path starts at the assembly pose, 0)
};

struct Result {
  double us_per_pose = NAN, iterations = NAN, factor_us = NAN, bytes = NAN, assemble_ms = NAN;
};

const char* method_name(Factorisation f) {
  switch (f) {
    case Factorisation::Automatic: return "automatic";
    case Factorisation::Dense: return "dense";
    case Factorisation::EigenSparseLU: return "eigen_sparselu";
    case Factorisation::Klu: return "klu";
  }
  return "?";
}

/// Times `poses` poses along the input from the assembly pose (median over `repeats` runs of the path).
Result measure(const Fixture<double>& f, Factorisation how, int poses, double step, int repeats) {
  SolveData<double> sd(f.mech, how);
  VectorX<double> q0 = f.guess;
  const auto t_assemble = Clock::now();
  if (!assemble(f.mech, q0, sd, f.held).ok()) return {};
  const double assemble_ms = seconds_since(t_assemble) * 1e3;
  const int driver = f.mech.drivers[0];
  const VectorX<double> unit_rate = VectorX<double>::Ones(1);
  VectorX<double> q, rates;
  Result r;
  r.assemble_ms = assemble_ms;
  std::vector<double> times;
  long iterations = 0;
  for (int rep = 0; rep < repeats; ++rep) {
    q = q0;
    iterations = 0;
    const auto t0 = Clock::now();
    for (int k = 1; k <= poses; ++k) {
      solve_velocity(f.mech, sd, unit_rate, rates);
      q += rates * step;  // Euler predictor (the continuation's first guess)
      q(driver) = q0(driver) + k * step;
      const SolveReport<double> s = solve_position(f.mech, q, sd);
      if (!s.ok()) return {};
      iterations += s.iterations;
    }
    times.push_back(seconds_since(t0) / poses * 1e6);
  }
  r.us_per_pose = median(times);
  r.iterations = static_cast<double>(iterations) / poses;
  // One factorisation at the last pose (the Jacobian evaluated once; factor() alone timed).
  evaluate_and_factor(f.mech, q, sd, f.mech.equation_count());
  std::vector<double> ft;
  const int inner = std::max(1, 20000 / (f.mech.equation_count() + 1));
  for (int rep = 0; rep < 7; ++rep) {
    const auto t0 = Clock::now();
    for (int i = 0; i < inner; ++i) sd.factor(f.mech.equation_count());
    ft.push_back(seconds_since(t0) / inner * 1e6);
  }
  r.factor_us = median(ft);
  r.bytes = static_cast<double>(sd.bytes());
  return r;
}

/// Least-squares slope of log(y) against log(x) over the finite points.
double fitted_exponent(const std::vector<int>& x, const std::vector<double>& y, int from = 0) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    if (x[k] < from || !std::isfinite(y[k])) continue;
    const double lx = std::log(x[k]), ly = std::log(y[k]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly, ++n;
  }
  if (n < 2) return NAN;
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"rollkin_bench_scaling: cost per pose against the number of loops"};
  int repeats = 9, poses = 40, dense_max = 64;
  std::string csv;
  bool quick = false;
  std::string only;
  app.add_option("--repeats", repeats, "timed paths per case (median)");
  app.add_option("--poses", poses, "poses per path");
  app.add_option("--dense-max", dense_max, "largest N for the dense factorisation (its cost grows as N^3)");
  app.add_option("--csv", csv, "write the table as CSV")->type_name("FILE");
  app.add_flag("--quick", quick, "N up to 32, 3 repeats");
  app.add_option("--family", only, "only this family (gear_train, four_bar_chain, cam_gear_train)");
  CLI11_PARSE(app, argc, argv);
  if (quick) repeats = 3;

  std::printf("# rollkin_bench_scaling: %s, %ld cpus, load %s, %s; KLU %s\n", cpu_model().c_str(), cpu_count(),
              load_average().c_str(), compiler().c_str(), klu_available ? "yes" : "no (Eigen SparseLU in its place)");
  std::printf("# Automatic: dense below %d unknowns, else %s\n", sparse_threshold,
              method_name(default_sparse_factorisation()));

  // The paper example (docs/method.md section 4) through the same per-pose loop: the small-mechanism row.
  {
    const Fixture<double> paper = testing::paper_fourbar<double>();
    const Result r = measure(paper, Factorisation::Automatic, 100, 1 * kDeg, repeats);
    std::printf("paper example (automatic = dense): %.3f us/pose, %.2f iterations/pose, factor %.3f us, %.0f bytes\n",
                r.us_per_pose, r.iterations, r.factor_us, r.bytes);
  }

  const std::vector<Family> families = {
      {"gear_train", [](int n) { return testing::disk_train<double>(n); }, 0.5},
      {"four_bar_chain", [](int n) { return testing::four_bar_chain<double>(n); }, 0.1},
      {"cam_gear_train", [](int n) { return testing::cam_gear_train<double>(n); }, 0.5},
  };
  const std::vector<Factorisation> methods = {Factorisation::Dense, Factorisation::EigenSparseLU, Factorisation::Klu,
                                              Factorisation::Automatic};
  std::vector<int> sizes = {2, 4, 8, 16, 32, 64, 128, 256};
  if (quick) sizes = {2, 4, 8, 16, 32};
  std::ofstream out;
  if (!csv.empty()) {
    out.open(csv);
    out << "family,N,unknowns,equations,method,us_per_pose,iterations_per_pose,factor_us,bytes,assemble_ms\n";
  }
  for (const Family& fam : families) {
    if (!only.empty() && fam.name != only) continue;
    std::printf("\n%-15s %4s %5s %5s  %-15s %11s %8s %10s %10s %12s\n", "family", "N", "unkn", "eqns", "factorisation",
                "us/pose", "it/pose", "factor us", "bytes", "assemble ms");
    std::map<Factorisation, std::vector<double>> cost;
    for (int n : sizes) {
      const Fixture<double> f = fam.make(n);
      for (Factorisation how : methods) {
        Result r;
        if (how != Factorisation::Dense || n <= dense_max) r = measure(f, how, poses, fam.step_deg * kDeg, repeats);
        cost[how].push_back(r.us_per_pose);
        std::printf("%-15s %4d %5zu %5d  %-15s %11.3f %8.2f %10.3f %10.0f %12.3f\n", fam.name.c_str(), n,
                    f.mech.unknowns.size(), f.mech.equation_count(), method_name(how), r.us_per_pose, r.iterations,
                    r.factor_us, r.bytes, r.assemble_ms);
        if (out)
          out << fam.name << ',' << n << ',' << f.mech.unknowns.size() << ',' << f.mech.equation_count() << ','
              << method_name(how) << ',' << r.us_per_pose << ',' << r.iterations << ',' << r.factor_us << ','
              << r.bytes << ',' << r.assemble_ms << '\n';
      }
    }
    std::printf("fitted exponent of us/pose against N (least squares on log-log), %s:\n", fam.name.c_str());
    for (Factorisation how : methods)
      std::printf("  %-15s all N: %.2f   N >= 8: %.2f\n", method_name(how), fitted_exponent(sizes, cost[how]),
                  fitted_exponent(sizes, cost[how], 8));
    const auto at = [&](Factorisation how, int n) -> double {
      for (std::size_t k = 0; k < sizes.size(); ++k)
        if (sizes[k] == n) return cost[how][k];
      return NAN;
    };
    const double c2 = at(Factorisation::Automatic, 2), c8 = at(Factorisation::Automatic, 8),
                 c64 = at(Factorisation::Automatic, 64);
    std::printf("automatic: cost(64)/cost(2) = %.1f (target <= 100), cost(64)/cost(8) = %.1f (target <= 12)\n",
                c64 / c2, c64 / c8);
  }
  return 0;
}
