// build/rollkin_bench_forces: the cost of the forces (analysis/forces.hpp, `rollkin solve --forces`) against the
// kinematic sweep alone, per pose (docs/benchmark.md, "Forces"). Cases: the paper example (3 moving links) and
// disk_train(63) (64 pivoted rolling disks: 63 redundant normal forces). Every moving link gets a mass; per case
// the sweep's median time per pose (rollkin::sweep, the poses and their rates), the forces' median time per pose
// (pose_forces at every pose of that sweep: accelerations, the force system, its QR, the null combination) and
// their ratio, against the target of 1.5. Not a test.
#include "measure.hpp"
#include "rollkin/analysis/forces.hpp"
#include "rollkin/samples/mechanisms.hpp"
#include "rollkin/solve/continuation.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <string>
#include <vector>

using namespace rollkin;
using namespace rollkin::bench;
using testing::Fixture;

namespace {

/// Masses on every moving link (centre off the origin), gravity: the full right-hand side.
Dynamics<double> masses(const Mechanism<double>& m) {
  Dynamics<double> d(m.links.size(), m.pairs.size());
  for (std::size_t i = 0; i < m.links.size(); ++i)
    if (static_cast<int>(i) != m.ground) d.links[i] = {1.0, Vec2<double>(0.1, 0.05), 0.2};
  d.gravity = Vec2<double>(0, -9.81);
  d.speed = 10;
  return d;
}

struct Row {
  std::string name;
  int poses = 0, unknowns = 0;
  double sweep_us = 0, forces_us = 0;
};

Row measure(const std::string& name, const Fixture<double>& f, const std::vector<double>& inputs, int repeats) {
  Row row{name, static_cast<int>(inputs.size())};
  SolveData<double> sd(f.mech);
  VectorX<double> q0 = f.guess;
  const SolveReport<double> rep = assemble(f.mech, q0, sd, f.held);
  std::vector<double> sweep_times, force_times;
  SweepResult<double> result;
  for (int k = 0; k < repeats; ++k) {
    SolveData<double> fresh(f.mech);
    VectorX<double> q = q0;
    const SolveReport<double> a = assemble(f.mech, q, fresh, f.held);
    const auto t0 = Clock::now();
    result = sweep(f.mech, fresh, q, a, 0, inputs);
    sweep_times.push_back(seconds_since(t0) / static_cast<double>(inputs.size()));
  }
  const Dynamics<double> dyn = masses(f.mech);
  ForceData<double> data(f.mech);
  row.unknowns = data.layout.size();
  double sink = 0;
  for (int k = 0; k < repeats; ++k) {
    const auto t0 = Clock::now();
    for (const auto& pose : result.poses)
      if (pose.report.has_pose()) sink += pose_forces(f.mech, dyn, pose.q, pose.qdot, data).value(0, dyn.speed);
    force_times.push_back(seconds_since(t0) / static_cast<double>(inputs.size()));
  }
  if (sink == 12345.678) std::printf(" ");  // keeps the forces from being optimised away
  static_cast<void>(rep);
  row.sweep_us = median(sweep_times) * 1e6;
  row.forces_us = median(force_times) * 1e6;
  return row;
}

std::vector<double> degrees(double from, double to, double step) {
  std::vector<double> v;
  for (double d = from; d <= to + 1e-9; d += step) v.push_back(deg_to_rad(d));
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("rollkin_bench_forces: --forces cost against the kinematic sweep per pose (docs/benchmark.md)");
  int repeats = 5;
  app.add_option("--repeats", repeats, "timed runs per case (median)")->check(CLI::Range(1, 1000));
  CLI11_PARSE(app, argc, argv);
  const std::vector<Row> rows = {
      measure("paper example", testing::paper_fourbar<double>(), degrees(-50, 100, 0.1), repeats),
      measure("disk_train(63): 64 disks", testing::disk_train<double>(63), degrees(0, 90, 1), repeats),
  };
  std::printf("%-26s %7s %9s %12s %13s %8s %s\n", "case", "poses", "unknowns", "sweep us/pose", "forces us/pose", "ratio",
              "target <= 1.5");
  for (const Row& r : rows)
    std::printf("%-26s %7d %9d %12.2f %13.2f %8.2f %s\n", r.name.c_str(), r.poses, r.unknowns, r.sweep_us, r.forces_us,
                r.forces_us / r.sweep_us, r.forces_us <= 1.5 * r.sweep_us ? "PASS" : "MISS");
  return 0;
}
