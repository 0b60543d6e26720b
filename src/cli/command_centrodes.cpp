// `rollkin centrodes`: the instant centre of two links' relative motion over the sweep, as point files (and
// DXF splines).
#include "commands.hpp"
#include "rollkin/analysis/centrodes.hpp"

#include <algorithm>
#include <iostream>
#include <memory>

namespace rollkin::cli {
namespace {

// ---- rollkin centrodes -----------------------------------------------------------------------------------

struct CentrodesOptions {
  SweepRequest sweep;
  std::vector<std::string> links;  // A B
  std::string out;                 // prefix of PREFIX.A.txt and PREFIX.B.txt
  std::string dxf;                 // both centrodes as SPLINE entities (optional)
};

int run_centrodes(const CentrodesOptions& o);

}  // namespace

Command centrodes_command(CLI::App& rollkin) {
  auto o = std::make_shared<CentrodesOptions>();
  CLI::App* app = rollkin.add_subcommand("centrodes", "loci of the instant centre of two links' relative motion, as point files");
  add_sweep_options(*app, o->sweep);
  app->add_option("--links", o->links, "the two links A and B (names in the scene)")->expected(2)->required()->type_name("A B");
  add_prefix(*app, "--out", o->out, "prefix of the files PREFIX.A.txt (centrode in A's frame) and PREFIX.B.txt")
      ->required()
      ->type_name("PREFIX");
  add_output(*app, "--dxf", o->dxf, "both centrodes as DXF SPLINE entities for CAD, on layers named after A and B");
  app->footer(
      "Sweeps the scene like 'solve' and writes, for every input value in sweep order, the instant centre of\n"
      "the motion of link B relative to link A (from the velocity solution) in A's frame (PREFIX.A.txt: the\n"
      "fixed centrode when A is the ground) and in B's frame (PREFIX.B.txt), in the point-file format a\n"
      "\"samples\" contour reads: rolled on each other as a rolling pair they reproduce the relative motion.\n"
      "A value where the centre is at infinity (pure relative translation) or that was not solved is a comment\n"
      "line in both files and a line on stderr (exit status 1).\n"
      "--dxf: each run of consecutive centres as the cubic spline through them (exact NURBS form of the\n"
      "spline a \"samples\" contour fits to the points; closed when the sweep ends where it starts). A centrode\n"
      "that is one point (links joined by a revolute) is said to be one; its point files are written, the\n"
      "DXF is not (a line on stderr says why).\n" +
      std::string(kExitStatus));
  return {app, [o] { return run_centrodes(*o); }};
}

namespace {

/// A link of the scene named on the command line (--links).
int named_link(const Mechanism<double>& m, const std::string& name) {
  const int i = m.find_link(name);
  if (i >= 0) return i;
  std::string names;
  for (const Link& l : m.links) names += (names.empty() ? "\"" : ", \"") + l.name + "\"";
  throw UsageError("--links: no link \"" + name + "\" in the scene; its links are " + names);
}

/// `rollkin centrodes`: the sweep, then the instant centre at every pose, written as two point files.
int run_centrodes(const CentrodesOptions& o) {
  if (o.links[0] == o.links[1]) throw UsageError("--links: give two different links, got \"" + o.links[0] + "\" twice");
  const std::string file_a = o.out + "." + o.links[0] + ".txt", file_b = o.out + "." + o.links[1] + ".txt";
  output::SweepRun run = start_run(o.sweep, {{"--out (link A)", file_a, ""}, {"--out (link B)", file_b, ""}, {"--dxf", o.dxf, ""}});
  const io::Scene& scene = run.scene();
  const Sweep& sw = run.sweep();
  const Mechanism<double>& m = scene.mechanism;
  const int a = named_link(m, o.links[0]), b = named_link(m, o.links[1]);

  SolveData<double> sd(m);
  VectorX<double> q;
  g_doing = "assembling the mechanism";
  const SolveReport<double> assembly = run.assemble(sd, q);
  g_doing = "solving the sweep";
  const SweepResult<double> result = run.solve(sd, q, assembly);
  g_doing = "computing the instant centres";
  const std::vector<InstantCentre<double>> centres = centrodes(m, sd.kin, result, a, b);

  g_doing = "building the output files";
  const io::SweepOutput ctx = run.output(result);
  run.set_output("--out (link A)", [&] { return output::centrode_text(ctx, centres, a, b, true); });
  run.set_output("--out (link B)", [&] { return output::centrode_text(ctx, centres, a, b, false); });
  // A centrode that is one point (two links joined by a revolute) has no curve to draw: its point files are
  // written, the DXF is not (docs/reliability.md, "Outputs").
  const std::string single_point = output::centrode_single_point(ctx, centres, a, b);
  if (single_point.empty()) run.set_output("--dxf", [&] { return output::centrode_dxf(ctx, centres, a, b); });
  else run.omit_output("--dxf");
  g_doing = "writing the output files";
  run.commit();

  std::size_t finite = 0;
  const SweepSummary<double> found = summarise(result);
  std::vector<std::string> problems = sweep_problems(scene, sw, found, run.inputs());  // as solve reports them
  for (std::size_t k = 0; k < centres.size(); ++k) {
    if (centres[k].finite) {
      ++finite;
    } else if (result.poses[k].report.has_pose()) {
      problems.push_back("centre at infinity at " + input_text(scene, sw, run.inputs()[k]) +
                         ": link '" + o.links[1] + "' translates relative to link '" + o.links[0] +
                         "' (no point written; a comment line marks the place in both files)");
    }
  }
  std::cout << fs::path(scene.file).filename().string() << ": " << finite << "/" << centres.size()
            << " instant centres of '" << o.links[1] << "' relative to '" << o.links[0] << "' written to " << file_a
            << " and " << file_b << "\n";
  if (!single_point.empty()) {
    std::cout << fs::path(scene.file).filename().string() << ": " << single_point << "\n";
    if (!o.dxf.empty()) std::cerr << scene.file << ": --dxf '" << o.dxf << "' not written: a centrode that is one point has no curve to draw as a spline\n";
  }
  for (const auto& p : problems) std::cerr << scene.file << ": " << p << "\n";
  return std::max(sweep_status(found, run.inputs().size()), finite == centres.size() ? 0 : 1);
}

}  // namespace
}  // namespace rollkin::cli
