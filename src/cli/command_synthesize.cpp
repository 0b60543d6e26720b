// `rollkin synthesize cam SPEC.json --out PREFIX`: the disk cam that gives a follower a motion law, written as
// a point file, a DXF SPLINE, an SVG drawing and the scene that analyses it, then proved by that analysis
// (docs/synthesis.md); likewise `synthesize gears` and `synthesize envelope`. The files are built by
// output/synthesis_files.hpp, which Python's synthesize_cam and synthesize_gears call too.
#include "commands.hpp"

#include "rollkin/io/point_file.hpp"
#include "rollkin/output/synthesis_files.hpp"
#include "rollkin/synthesis/scene_envelope.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>

namespace rollkin::cli {
namespace {

struct SynthesizeCamOptions {
  std::string spec;
  std::string out;  // PREFIX of PREFIX.txt, .dxf, .svg, .json
};

int run_synthesize_cam(const SynthesizeCamOptions& o);
int run_synthesize_gears(const SynthesizeCamOptions& o);

struct SynthesizeEnvelopeOptions {
  SweepRequest sweep;
  std::vector<std::string> links;  // A B
  std::string contour;             // B.name
  std::string out;
  std::optional<double> tolerance, start;
};
int run_synthesize_envelope(const SynthesizeEnvelopeOptions& o);

}  // namespace

Command synthesize_command(CLI::App& rollkin) {
  auto o = std::make_shared<SynthesizeCamOptions>();
  CLI::App* app = rollkin.add_subcommand("synthesize", "the contour that gives a prescribed motion (cams), proved by analysing it");
  app->require_subcommand(0, 1);  // none: a UsageError naming the three (run below)
  CLI::App* cam = app->add_subcommand("cam", "a disk cam from a motion law and a follower (docs/synthesis.md)");
  cam->add_option("SPEC", o->spec, "the cam spec (JSON: base_radius, rotation, follower, contact, law, tolerance)")
      ->required()
      ->type_name("SPEC.json");
  add_prefix(*cam, "--out", o->out, "prefix of PREFIX.txt (profile points), PREFIX.dxf, PREFIX.svg and PREFIX.json (scene)")
      ->required()
      ->type_name("PREFIX");
  cam->footer(
      "Computes the cam profile as the envelope of the follower's contour (roller or flat face) under its motion\n"
      "relative to the turning cam, sampled so that the fitted spline is within a sixteenth of the tolerance of\n"
      "the true profile. Writes PREFIX.txt (closed point file, the cam's frame), PREFIX.dxf (one SPLINE),\n"
      "PREFIX.svg (cam and follower at the law's start) and PREFIX.json (the scene: revolute 'cam' theta,\n"
      "follower pair 'follower' s or phi, cam pair 'contact'), all or nothing: before any is committed it reads\n"
      "PREFIX.json back (with the point file it names), solves one turn and prints the worst deviation of the analysed follower motion from the law, the largest\n"
      "pressure angle and the smallest radius of curvature of the profile at the contacts.\n"
      "Exit status: 0 the analysed motion matches the law to the spec's tolerance (default 1e-9 of the stroke);\n"
      "1 it does not, or the profile is undercut (the cam angles where it folds on stderr; nothing written);\n"
      "2 bad input (spec, law file, an output that would overwrite an input); 3 out of memory; 4 internal error (a\n"
      "file it wrote that its own reader refuses; nothing written).");
  auto g = std::make_shared<SynthesizeCamOptions>();
  CLI::App* gears = app->add_subcommand("gears", "a non-circular gear pair from its transmission function (docs/synthesis.md)");
  gears->add_option("SPEC", g->spec, "the gear spec (JSON: centre_distance, transmission, tolerance)")->required()->type_name("SPEC.json");
  add_prefix(*gears, "--out", g->out, "prefix of PREFIX.1.txt, PREFIX.2.txt (pitch curves), PREFIX.dxf, PREFIX.svg and PREFIX.json (scene)")
      ->required()
      ->type_name("PREFIX");
  gears->footer(
      "Samples both pitch curves (r1 = E f'/(1 + f'), r2 = E/(1 + f')) until their fitted splines are within a\n"
      "sixteenth of the tolerance (times E) of the true curves at every mid-angle, reports whether the pair closes\n"
      "(f(phi + 360) = f(phi) + 360) and the smallest curvature of each curve (convex or not), writes the curves,\n"
      "their DXF, a picture of the pair at its start (PREFIX.svg) and the scene rolling them (revolutes gear1,\n"
      "gear2, rolling pair mesh), all or nothing, then solves that scene over one turn and prints the worst\n"
      "deviation of gear2.phi from -f(gear1.phi).\n"
      "Exit status: 0 within the tolerance (default 1e-9 of a turn); 1 not, or the pair does not close (nothing\n"
      "written); 2 bad input; 3 out of memory; 4 internal error (nothing written).");
  auto e = std::make_shared<SynthesizeEnvelopeOptions>();
  CLI::App* env = app->add_subcommand("envelope", "the conjugate on link A of a contour of link B under the scene's sweep");
  add_sweep_options(*env, e->sweep);
  env->add_option("--links", e->links, "the links A (carries the envelope) and B (carries the contour)")->expected(2)->required()->type_name("A B");
  env->add_option("--contour", e->contour, "B's contour, as the scene's pairs name it (B.name)")->required()->type_name("B.NAME");
  add_prefix(*env, "--out", e->out, "prefix of PREFIX.txt (the envelope in A's frame) and PREFIX.dxf")->required()->type_name("PREFIX");
  // Checked by the library's rule that Python's envelope() shares (synthesis/scene_envelope.hpp).
  add_checked_number(*env, "--tolerance", e->tolerance, synthesis::envelope_tolerance_problem,
                     "largest mid-pose distance of the fitted spline from the envelope (scene length units; default 1e-9 of the scene's size)");
  add_checked_number(*env, "--start", e->start, synthesis::envelope_start_problem,
                     "B's contour parameter near the contact at the sweep's first pose (internal units: radians for angles; default: the root nearest the instant centre)");
  env->footer(
      "Solves the sweep, interpolates B's pose relative to A (cubic Hermite in the input, from poses and rates)\n"
      "and computes the envelope of B's contour from the equation of meshing n . v_rel = 0, sampled until the\n"
      "spline through the points is within the tolerance at every mid-pose (docs/synthesis.md). Writes PREFIX.txt\n"
      "(a point file, closed when the relative motion is periodic) and PREFIX.dxf (one SPLINE), all or nothing.\n"
      "Exit status: 0 written; 1 the envelope folds (undercut, cusp) or does not exist somewhere (the inputs on\n"
      "stderr; the points found are still written, the DXF not); 2 bad input; 3 out of memory.");
  return {app, [o, cam, g, gears, e, env] {
            if (cam->parsed()) return run_synthesize_cam(*o);
            if (gears->parsed()) return run_synthesize_gears(*g);
            if (env->parsed()) return run_synthesize_envelope(*e);
            throw UsageError("synthesize: expected what to synthesize: cam, gears or envelope");
          }};
}

namespace {

/// The law's unit for messages: the length unit, or the angle unit of an oscillating follower.
std::string law_value(const synthesis::CamSpec& spec, double v) {
  if (spec.motion == synthesis::FollowerMotion::Oscillating)
    return io::format_number(io::from_radians(v, spec.angle_unit), 6) + " " + io::unit_label(spec.angle_unit);
  return io::format_number(v, 6) + (spec.length_label.empty() ? "" : " " + spec.length_label);
}

std::string angle_value(const synthesis::CamSpec& spec, double rad) {
  return io::format_number(io::from_radians(rad, spec.angle_unit), 10) + " " + io::unit_label(spec.angle_unit);
}

int run_synthesize_cam(const SynthesizeCamOptions& o) {
  g_doing = "reading the cam spec";
  const synthesis::CamSpec spec = synthesis::read_cam_spec(o.spec);
  io::OutputSet outputs(spec.files_read);
  const std::string txt = o.out + ".txt", dxf = o.out + ".dxf", svg = o.out + ".svg", scene_file = o.out + ".json";
  const std::size_t i_txt = outputs.add("--out (profile)", txt), i_dxf = outputs.add("--out (DXF)", dxf),
                    i_svg = outputs.add("--out (SVG)", svg), i_scene = outputs.add("--out (scene)", scene_file);

  for (const auto& j : spec.law->check_continuity()) {
    const char* what[] = {"the displacement jumps (no motion can follow it)", "the velocity jumps (infinite acceleration)",
                          "the acceleration jumps (infinite jerk)"};
    std::cerr << o.spec << ": law: at cam angle " << angle_value(spec, j.theta) << " " << what[j.order] << ": from "
              << io::format_number(j.left) << " to " << io::format_number(j.right) << "\n";
  }

  // The library's messages of the synthesis named no key: each step says here which input governs it.
  const StepInput sizes{o.spec, "base_radius, follower, contact, law, tolerance",
                        "the cam is sampled until its spline is within \"tolerance\" (default 1e-9 of the stroke) of the "
                        "true profile; give a larger \"tolerance\", or sizes (base_radius, roller, offset, lift) that differ by "
                        "fewer orders of magnitude"};
  g_doing = "computing the cam profile";
  const synthesis::CamProfile profile = from_input(sizes, [&] { return synthesis::synthesise_cam(spec); });
  if (!profile.envelope.defects.empty()) {
    for (const auto& d : profile.envelope.defects)
      std::cerr << o.spec << ": undercut: at cam angle " << angle_value(spec, d.t) << " " << d.what
                << (std::isfinite(d.point.x()) ? " (profile point " + io::format_number(d.point.x(), 10) + ", " + io::format_number(d.point.y(), 10) + ")" : "")
                << "\n";
    std::cerr << o.spec << ": the profile is undercut (a smaller roller or a larger base circle avoids it); nothing written\n";
    return 1;
  }

  g_doing = "building the output files";
  output::CamFiles files = from_input(sizes, [&] { return output::cam_files(spec, profile, std::filesystem::path(txt).filename().string()); });
  outputs.set(i_txt, std::move(files.profile));
  outputs.set(i_dxf, std::move(files.dxf));
  outputs.set(i_svg, std::move(files.svg));
  outputs.set(i_scene, std::move(files.scene));
  // The round trip reads the files before they are committed (io::OutputSet::commit(check)): when it fails,
  // nothing is written, and a file of this run that rollkin's reader refuses is an internal error (exit 4).
  synthesis::CamRoundTrip rt;
  outputs.commit([&] {
    g_doing = "analysing the cam (round trip)";
    rt = synthesis::cam_round_trip(spec, scene_file);
    g_doing = "writing the output files";
  });
  std::cout << o.spec << ": profile of " << profile.points.size() << " points (spline within "
            << io::format_number(profile.profile_tolerance, 3) << " of the envelope at every mid-point) written to " << txt << ", "
            << dxf << ", " << svg << ", " << scene_file << "\n";
  std::cout << "round trip (" << scene_file << ", " << rt.solved << "/" << rt.poses << " poses solved):\n";
  std::cout << "  worst deviation of the follower from the law: " << law_value(spec, rt.worst_deviation) << " at cam angle "
            << angle_value(spec, rt.worst_deviation_at) << " (tolerance " << law_value(spec, spec.tolerance) << ")\n";
  std::cout << "  largest pressure angle: " << io::format_number(rad_to_deg(rt.max_pressure_angle), 10) << " deg at cam angle "
            << angle_value(spec, rt.max_pressure_angle_at) << "\n";
  std::cout << "  smallest radius of curvature of the profile: " << io::format_number(rt.min_radius_of_curvature, 10)
            << (rt.min_radius_of_curvature < 0 ? " (concave)" : "") << " at cam angle " << angle_value(spec, rt.min_radius_at) << "\n";
  for (const auto& p : rt.problems) std::cerr << scene_file << ": " << p << "\n";
  const bool ok = rt.problems.empty() && rt.solved == rt.poses && rt.worst_deviation <= spec.tolerance;
  if (!ok && rt.worst_deviation > spec.tolerance)
    std::cerr << o.spec << ": the analysed motion deviates from the law by more than the tolerance\n";
  return ok ? 0 : 1;
}

int run_synthesize_gears(const SynthesizeCamOptions& o) {
  g_doing = "reading the gear spec";
  const synthesis::GearSpec spec = synthesis::read_gear_spec(o.spec);
  io::OutputSet outputs(spec.files_read);
  const std::string f1 = o.out + ".1.txt", f2 = o.out + ".2.txt", dxf = o.out + ".dxf", svg = o.out + ".svg",
                    scene_file = o.out + ".json";
  const std::size_t i1 = outputs.add("--out (gear 1)", f1), i2 = outputs.add("--out (gear 2)", f2),
                    i_dxf = outputs.add("--out (DXF)", dxf), i_svg = outputs.add("--out (SVG)", svg),
                    i_scene = outputs.add("--out (scene)", scene_file);
  const std::string deg = io::unit_label(spec.angle_unit);
  if (std::abs(spec.closure_error) > spec.tolerance) {
    std::cerr << o.spec << ": the pair does not close: f(phi + " << io::format_number(io::from_radians(2 * pi<double>(), spec.angle_unit))
              << ") - f(phi) = " << io::format_number(io::from_radians(2 * pi<double>() + spec.closure_error, spec.angle_unit), 12) << " " << deg
              << ", not one turn (gear 2 would not come back to its start after a turn of gear 1); nothing written\n";
    return 1;
  }
  const StepInput curves{o.spec, "transmission, centre_distance, tolerance",
                         "the pitch curves are sampled until their splines are within \"tolerance\" (default 1e-9 of a turn) "
                         "times centre_distance of the true curves, and gear 2 must turn as long as gear 1 does (f' > 0 at "
                         "every angle); give a larger \"tolerance\" or a transmission whose speed ratio varies less"};
  g_doing = "computing the pitch curves";
  const synthesis::GearDesign d = from_input(curves, [&] { return synthesis::synthesise_gears(spec); });
  output::GearFiles files = from_input(curves, [&] {
    return output::gear_files(spec, d, std::filesystem::path(f1).filename().string(), std::filesystem::path(f2).filename().string());
  });
  outputs.set(i1, std::move(files.gear1));
  outputs.set(i2, std::move(files.gear2));
  outputs.set(i_dxf, std::move(files.dxf));
  outputs.set(i_svg, std::move(files.svg));
  outputs.set(i_scene, std::move(files.scene));
  synthesis::GearRoundTrip rt;  // read back before anything is committed, as the cam's
  outputs.commit([&] {
    g_doing = "analysing the gears (round trip)";
    rt = synthesis::gear_round_trip(spec, scene_file);
    g_doing = "writing the output files";
  });
  std::cout << o.spec << ": the pair closes; " << d.pair.gear1.size() << " points per pitch curve (splines within "
            << io::format_number(d.profile_tolerance, 3) << " at every mid-angle) written to " << f1 << ", " << f2 << ", " << dxf << ", "
            << svg << ", " << scene_file << "\n";
  for (int gear = 1; gear <= 2; ++gear) {
    const double kappa = gear == 1 ? d.min_curvature1 : d.min_curvature2, at = gear == 1 ? d.min_curvature1_at : d.min_curvature2_at;
    std::cout << "  gear " << gear << ": " << (kappa > 0 ? "convex" : "NOT convex (teeth cut on it would undercut)")
              << ", smallest curvature " << io::format_number(kappa, 8) << " at polar angle " << io::format_number(io::from_radians(at, spec.angle_unit), 8)
              << " " << deg << "\n";
  }
  std::cout << "round trip (" << scene_file << ", " << rt.solved << "/" << rt.poses << " poses solved):\n"
            << "  worst deviation of gear2.phi from -f(gear1.phi): " << io::format_number(io::from_radians(rt.worst_deviation, spec.angle_unit)) << " "
            << deg << " at gear1.phi = " << io::format_number(io::from_radians(rt.worst_deviation_at, spec.angle_unit), 10) << " " << deg
            << " (tolerance " << io::format_number(io::from_radians(spec.tolerance, spec.angle_unit)) << " " << deg << ")\n";
  for (const auto& p : rt.problems) std::cerr << scene_file << ": " << p << "\n";
  return rt.problems.empty() && rt.worst_deviation <= spec.tolerance ? 0 : 1;
}

int run_synthesize_envelope(const SynthesizeEnvelopeOptions& o) {
  if (o.links[0] == o.links[1]) throw UsageError("--links: give two different links, got \"" + o.links[0] + "\" twice");
  const std::string txt = o.out + ".txt", dxf = o.out + ".dxf";
  output::SweepRun run = start_run(o.sweep, {{"--out (points)", txt, ""}, {"--out (DXF)", dxf, ""}});
  const io::Scene& scene = run.scene();
  const Sweep& sw = run.sweep();
  const Mechanism<double>& m = scene.mechanism;
  const int a = m.find_link(o.links[0]), b = m.find_link(o.links[1]);
  if (a < 0 || b < 0) throw UsageError("--links: no link \"" + (a < 0 ? o.links[0] : o.links[1]) + "\" in the scene");
  const int contour = m.find_contour(o.contour);
  if (contour < 0 || m.contours[contour].link() != b)
    throw UsageError("--contour: no contour \"" + o.contour + "\" on link \"" + o.links[1] + "\" (give it as " + o.links[1] + ".NAME)");
  SolveData<double> sd(m);
  VectorX<double> q;
  g_doing = "assembling the mechanism";
  const SolveReport<double> assembly = run.assemble(sd, q);
  g_doing = "solving the sweep";
  const SweepResult<double> result = run.solve(sd, q, assembly);
  const SweepSummary<double> found = summarise(result);
  for (const auto& p : sweep_problems(scene, sw, found, run.inputs())) std::cerr << scene.file << ": " << p << "\n";
  g_doing = "computing the envelope";
  const double tol = o.tolerance ? *o.tolerance : 1e-9 * m.length_scale;
  const StepInput motion_input{scene.file, "sweep",
                               "the envelope needs B's motion at every pose of the sweep and a spline within --tolerance (default "
                               "1e-9 of the scene's size) of it; give --from/--to within the poses that solve (limits above), "
                               "--start near the contact, or a larger --tolerance"};
  const synthesis::Envelope<double> env = from_input(motion_input, [&] {
    const synthesis::SweepMotion motion(m, result, a, b);
    const synthesis::EnvelopeProblem<double> pr = synthesis::scene_envelope_problem(m, motion, contour, o.start);
    return synthesis::envelope(pr, synthesis::EnvelopeOptions{tol, 256, 400000});
  });
  const std::vector<Vec2<double>> pts = env.points();
  run.set_output("--out (points)", [&] {
    return io::point_file_text("envelope of " + o.contour + " in the frame of link " + o.links[0] +
                                   ", written by rollkin synthesize envelope from " + scene.file + (env.closed ? " (closed)" : " (open)"),
                               pts);
  });
  const bool drawable = env.defects.empty() && pts.size() >= 4;
  if (drawable) {
    // Fitted now, before anything is written: a failure of the fit names the input (from_input).
    std::string dxf_text = from_input(motion_input, [&] { return output::envelope_dxf(pts, env.closed, scene.length_unit); });
    run.set_output("--out (DXF)", [text = std::move(dxf_text)] { return text; });
  } else {
    run.omit_output("--out (DXF)");
  }
  g_doing = "writing the output files";
  run.commit();
  std::cout << scene.file << ": envelope of " << o.contour << " relative to link " << o.links[0] << ": " << pts.size() << " points"
            << (env.closed ? " (closed)" : " (open)") << ", spline within " << io::format_number(env.max_midpoint_deviation, 3)
            << " at every mid-pose (tolerance " << io::format_number(tol, 3) << "), written to " << txt << (drawable ? " and " + dxf : "") << "\n";
  for (const auto& d : env.defects)
    std::cerr << scene.file << ": at " << input_text(scene, sw, d.t) << ": " << d.what << "\n";
  return std::max(sweep_status(found, run.inputs().size()), env.defects.empty() ? 0 : 1);
}

}  // namespace
}  // namespace rollkin::cli
