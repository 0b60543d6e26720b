// `rollkin check` and the design check's text it prints (also printed by `rollkin solve --verbose`): radii of
// curvature where the contours touch, undercut, conformity.
#include "commands.hpp"

#include <algorithm>
#include <iostream>
#include <memory>

namespace rollkin::cli {
namespace {

// ---- the design check (rollkin check, solve --verbose) ---------------------------------------------------

/// A contour's name as the scene's pairs give it ("link.contour").
std::string contour_name(const Mechanism<double>& m, int contour) { return m.contours[contour].name(); }

/// "u = 12.5 deg (point 3, 0)": a contour point by its parameter (the pair variable's file unit) and its
/// coordinates in the contour's own frame (scene units).
std::string point_text(const io::Scene& scene, int variable, const TouchedPoint<double>& t) {
  const std::string unit = scene.unit_label(variable);
  const Mechanism<double>& m = scene.mechanism;
  return m.variables[variable].name + " = " + io::format_number(t.u / scene.unit_of(variable), 10) + (unit.empty() ? "" : " " + unit) +
         " (point " + io::format_number(t.point.x(), 10) + ", " + io::format_number(t.point.y(), 10) + ")";
}

/// The curvature line(s) of one contour of a pair: its sharpest convex and concave points touched.
std::vector<std::string> curvature_lines(const io::Scene& scene, const Sweep& sw, int variable,
                                         const ContourCurvatureCheck<double>& c) {
  const std::string name = contour_name(scene.mechanism, c.contour);
  if (c.circle) {
    const bool convex = c.sharpest_convex.found;
    return {name + ": circle of radius " + io::format_number(c.radius, 10) + (convex ? " (convex)" : " (concave)")};
  }
  std::vector<std::string> lines;
  if (c.sharpest_convex.found)
    lines.push_back(name + ": smallest convex radius of curvature " + io::format_number(1 / c.sharpest_convex.kappa, 10) + " at " +
                    point_text(scene, variable, c.sharpest_convex) + ", " + input_text(scene, sw, c.sharpest_convex.input));
  if (c.sharpest_concave.found)
    lines.push_back(name + ": smallest concave radius of curvature " + io::format_number(-1 / c.sharpest_concave.kappa, 10) + " at " +
                    point_text(scene, variable, c.sharpest_concave) + ", " + input_text(scene, sw, c.sharpest_concave.input));
  if (lines.empty()) lines.push_back(name + ": straight where touched");
  return lines;
}

/// The located message of a pair whose contours interpenetrate.
std::string finding_line(const io::Scene& scene, const Sweep& sw, const PairDesignCheck<double>& d) {
  const Mechanism<double>& m = scene.mechanism;
  const Pair<double>& p = m.pairs[d.pair];
  const std::string where = input_text(scene, sw, d.worst[0].input);
  const std::string sum = "kappa1 + kappa2 = " + io::format_number(d.worst_relative) + " < 0";
  if (d.roller < 0)
    return "interpenetration: the contours '" + contour_name(m, p.contour_a) + "' and '" + contour_name(m, p.contour_b) +
           "' of pair '" + p.name + "' interpenetrate next to their contact at " +
           point_text(scene, p.first_variable, d.worst[0]) + " and " + point_text(scene, p.first_variable + 1, d.worst[1]) +
           ", " + where + " (" + sum + "; curvatures " + io::format_number(d.worst[0].kappa) + " and " + io::format_number(d.worst[1].kappa) +
           "): the design is impossible there";
  const int other = 1 - d.roller;
  const int variable = p.first_variable + other;
  const std::string wall = contour_name(m, d.contours[other].contour);
  const double r = d.contours[d.roller].radius;
  std::string line = "undercut: pair '" + p.name + "': the roller '" + contour_name(m, d.contours[d.roller].contour) +
                     "' (radius " + io::format_number(r, 10) + ") is larger than the concave radius " +
                     io::format_number(-1 / d.worst[other].kappa, 10) + " of '" + wall + "' it must enter at " +
                     point_text(scene, variable, d.worst[other]) + ", " + where + " (" + sum +
                     ": the contours interpenetrate)";
  std::vector<std::string> ends;
  for (const auto& c : d.cusps)
    if (c.found) ends.push_back(point_text(scene, variable, c));
  if (!ends.empty()) {
    line += "; the roller-centre path (the offset of '" + wall + "' by " + io::format_number(r, 10) + ") has a cusp at " + ends[0];
    if (ends.size() > 1) line += " and at " + ends[1];
    line += ends.size() > 1 ? ": the roller cannot follow the contour between them" : "";
  }
  return line;
}

/// A roller against the concave parts it must enter: "roller 'f.roller' (radius 1.5) in 'cam.groove': ...".
std::string roller_line(const Mechanism<double>& m, const PairDesignCheck<double>& d) {
  const ContourCurvatureCheck<double>& roller = d.contours[d.roller];
  const ContourCurvatureCheck<double>& other = d.contours[1 - d.roller];
  std::string line = "roller '" + contour_name(m, roller.contour) + "' (radius " + io::format_number(roller.radius, 10) + ") on '" +
                     contour_name(m, other.contour) + "': ";
  if (!other.sharpest_concave.found) return line + "no concave part touched";
  const double rho = -1 / other.sharpest_concave.kappa;
  if (d.conformity == Conformity::Interpenetrating) return line + "too large for its smallest concave radius " + io::format_number(rho, 10);
  return line + "fits its smallest concave radius " + io::format_number(rho, 10) +
         (d.conformity == Conformity::Osculating ? " (equal: osculating)" : "");
}

}  // namespace

/// The design check of a solved sweep (rollkin/analysis/design_check.hpp) as text.
DesignReport design_report(const io::Scene& scene, const Sweep& sw, const SweepResult<double>& result) {
  const Mechanism<double>& m = scene.mechanism;
  const DesignCheck<double> check = check_design(m, result);
  DesignReport out;
  out.section.push_back("design check (radii of curvature where the contours touch, undercut, conformity):");
  if (check.pairs.empty()) out.section.push_back("  no cam or rolling pair");
  for (const auto& d : check.pairs) {
    const Pair<double>& p = m.pairs[d.pair];
    out.section.push_back("  pair '" + p.name + "' (" + to_string(p.kind) + "), '" + contour_name(m, p.contour_a) +
                          "' on '" + contour_name(m, p.contour_b) + "':");
    if (!d.touched) {
      out.section.push_back("    no solved pose: nothing touched");
      continue;
    }
    for (int side = 0; side < 2; ++side)
      for (const auto& l : curvature_lines(scene, sw, p.first_variable + side, d.contours[side]))
        out.section.push_back("    " + l);
    if (d.roller >= 0) out.section.push_back("    " + roller_line(m, d));
    out.section.push_back("    smallest relative curvature kappa1 + kappa2 = " + io::format_number(d.worst_relative, 10) + " at " +
                          input_text(scene, sw, d.worst[0].input) + ": " + to_string(d.conformity));
    if (d.conformity == Conformity::Interpenetrating) out.findings.push_back(finding_line(scene, sw, d));
  }
  out.section.push_back(out.findings.empty() ? "  no undercut or interpenetration"
                                             : "  " + std::to_string(out.findings.size()) + " pair(s) impossible (stderr)");
  return out;
}

namespace {

// ---- rollkin check ---------------------------------------------------------------------------------------

struct CheckOptions {
  SweepRequest sweep;
};

int run_check(const CheckOptions& o);

}  // namespace

Command check_command(CLI::App& rollkin) {
  auto o = std::make_shared<CheckOptions>();
  CLI::App* app = rollkin.add_subcommand("check", "undercut and conformity check of the contact pairs over the sweep");
  add_sweep_options(*app, o->sweep);
  app->footer(
      "Sweeps the scene like 'solve' and reports, for every cam and rolling pair, the smallest convex and\n"
      "concave radius of curvature each contour has where it is touched (between the solved poses too), and the\n"
      "smallest relative curvature kappa1 + kappa2 with an exact sign test: below zero the contours interpenetrate\n"
      "next to the contact, e.g. a roller larger than a concave radius it must enter (undercut: its centre's path,\n"
      "the offset of the other contour, has cusps). docs/analysis.md, \"Design check\".\n"
      "Exit status: 0 the design is possible over the solved sweep; 1 a pair interpenetrates (one located line per\n"
      "pair on stderr: pair, contours, contour parameter and point, input, radii), or the sweep met a limit or a\n"
      "singular pose (one line each: the check covers the solved poses only); 2 bad input or command line; 3 out\n"
      "of memory.");
  return {app, [o] { return run_check(*o); }};
}

namespace {

/// `rollkin check`: assembly, sweep, the design check on stdout, findings and sweep problems on stderr.
int run_check(const CheckOptions& o) {
  output::SweepRun run = start_run(o.sweep, {});
  const io::Scene& scene = run.scene();
  const Sweep& sw = run.sweep();
  const std::vector<double>& inputs = run.inputs();
  const Mechanism<double>& m = scene.mechanism;
  SolveData<double> sd(m);
  VectorX<double> q;
  g_doing = "assembling the mechanism";
  const SolveReport<double> assembly = run.assemble(sd, q);
  g_doing = "solving the sweep";
  const SweepResult<double> result = run.solve(sd, q, assembly);
  g_doing = "checking the design";
  const DesignReport design = design_report(scene, sw, result);
  const SweepSummary<double> found = summarise(result);
  std::vector<std::string> problems = sweep_problems(scene, sw, found, inputs);
  const std::size_t solved = found.solved() + found.singular.size();  // every pose with values
  const std::string unit = scene.unit_label(sw.variable);
  std::cout << fs::path(scene.file).filename().string() << ": " << solved << "/" << inputs.size()
            << " poses solved, " << sw.input << " from " << io::format_number(sw.from) << " to " << io::format_number(sw.to)
            << (unit.empty() ? "" : " " + unit) << "\n";
  for (const auto& l : design.section) std::cout << l << "\n";
  for (const auto& f : design.findings) std::cerr << scene.file << ": " << f << "\n";
  for (const auto& p : problems) std::cerr << scene.file << ": " << p << "\n";
  return std::max(sweep_status(found, inputs.size()), design.findings.empty() ? 0 : 1);
}

}  // namespace
}  // namespace rollkin::cli
