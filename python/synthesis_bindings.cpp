// Synthesis in the Python module (docs/synthesis.md, docs/python.md): synthesize_cam, synthesize_gears and
// envelope, returning the contours as the dicts a scene takes and the analysed scenes themselves, so that a
// design study can vary a motion law and read the pressure angles.
#include "bindings.hpp"

#include "rollkin/io/dxf/writer.hpp"
#include "rollkin/io/input_file.hpp"
#include "rollkin/io/json/document.hpp"
#include "rollkin/output/synthesis_files.hpp"
#include "rollkin/solve/continuation.hpp"
#include "rollkin/synthesis/cam.hpp"
#include "rollkin/synthesis/gears.hpp"
#include "rollkin/synthesis/scene_envelope.hpp"

#include <filesystem>
#include <vector>

namespace rollkin::python {
namespace {

using V = Vec2<double>;

/// An (n, 2) float64 array of points.
py::array_t<double> xy_array(const std::vector<V>& pts) {
  py::array_t<double> out({static_cast<py::ssize_t>(pts.size()), py::ssize_t(2)});
  auto a = out.mutable_unchecked<2>();
  for (std::size_t k = 0; k < pts.size(); ++k) {
    a(k, 0) = pts[k].x();
    a(k, 1) = pts[k].y();
  }
  return out;
}

json points_json(const std::vector<V>& pts) {
  json list = json::array();
  for (const V& p : pts) list.push_back({p.x(), p.y()});
  return list;
}

/// The spline a `samples` contour fits through `pts` as the exact `nurbs` contour dict (docs/scene_format.md): the
/// DXF writer's B-spline form of it (io::spline_of: degree 3, the chord-length knots, clamped; closed with equal
/// first and last control points), parameterised by arc length.
json nurbs_json(const std::vector<V>& pts, bool closed, const std::string& name) {
  SplineOptions<double> o;
  o.closed = closed;
  const rollkin::io::DxfSpline s = rollkin::io::spline_of(SampledProfile<double>(pts, o), "");
  // Parameterised by arc length: with the native parameter (piece i on [i, i + 1]) the sweep of a synthesised cam
  // as a NURBS of ~1400 pieces stopped without convergence part way round (docs/synthesis.md, "Python").
  return {{"name", name}, {"type", "nurbs"}, {"degree", s.degree}, {"knots", s.knots}, {"points", points_json(s.control)},
          {"closed", s.closed}, {"parameter", "arc_length"}};
}

/// A spec argument: a dict (read as a spec document named `<dict>`, files relative to base_dir or the working
/// directory) or a path to a spec file. Returns (document, file, dir).
std::tuple<json, std::string, std::string> spec_document(const py::object& spec, const py::object& base_dir) {
  if (py::isinstance<py::dict>(spec)) {
    const std::string dir = base_dir.is_none() ? std::filesystem::current_path().string() : path_argument(base_dir, "base_dir");
    return {to_json(spec, "", "<dict>"), "<dict>", dir};
  }
  const std::string file = path_argument(spec, "spec");
  return {rollkin::io::parse_json_document(rollkin::io::read_input_file(file, "spec"), file), file,
          std::filesystem::path(file).parent_path().string()};
}

/// A scene built from `document` (its contours inline) as a Python Scene.
PyScene scene_of(json document, const std::string& name, const std::string& dir) {
  auto scene = std::make_shared<const rollkin::io::Scene>(rollkin::io::build_scene(document, name, dir));
  return PyScene{std::move(scene), std::make_shared<const json>(std::move(document)), name, dir, ""};
}

py::dict synthesize_cam(const py::object& spec_arg, const py::object& base_dir) {
  auto [document, file, dir] = spec_document(spec_arg, base_dir);
  // Reading the spec (a law table's spline) and the continuity check run without the GIL, Ctrl-C answered.
  using SpecAndJumps = std::pair<synthesis::CamSpec, std::vector<synthesis::LawJump<double>>>;
  const SpecAndJumps read = interruptible<SpecAndJumps>([document = document, file = file, dir = dir](const std::atomic<bool>&) {
    synthesis::CamSpec spec = synthesis::cam_spec_from_document(document, file, dir);
    std::vector<synthesis::LawJump<double>> jumps = spec.law->check_continuity();
    return SpecAndJumps{std::move(spec), std::move(jumps)};
  });
  const synthesis::CamSpec& spec = read.first;
  py::dict out;
  py::list jumps;
  for (const auto& j : read.second)
    jumps.append(py::dict(py::arg("cam_angle") = rollkin::io::from_radians(j.theta, spec.angle_unit), py::arg("order") = j.order,
                          py::arg("left") = j.left, py::arg("right") = j.right));
  out["jumps"] = jumps;
  const synthesis::CamProfile profile = interruptible<synthesis::CamProfile>(
      [spec](const std::atomic<bool>&) { return synthesis::synthesise_cam(spec); });
  py::list folds;
  for (const auto& d : profile.envelope.defects)
    folds.append(py::make_tuple(rollkin::io::from_radians(d.t, spec.angle_unit), d.what));
  out["folds"] = folds;
  out["profile"] = xy_array(profile.points);
  out["profile_tolerance"] = profile.profile_tolerance;
  out["svg"] = rollkin::output::cam_svg(spec, profile);
  json contour = {{"name", "profile"}, {"type", "samples"}, {"points", points_json(profile.points)}, {"closed", true}};
  out["contour"] = to_python(contour);
  if (!profile.envelope.defects.empty()) {  // undercut: no scene, no round trip
    out["scene"] = py::none();
    out["round_trip"] = py::none();
    return out;
  }
  out["nurbs"] = to_python(nurbs_json(profile.points, true, "profile"));
  json scene_doc = synthesis::cam_scene(spec, profile, "profile.txt");
  scene_doc["links"][1]["contours"][0] = contour;
  const PyScene scene = scene_of(scene_doc, "<synthesized cam>", dir);
  const synthesis::CamRoundTrip rt = interruptible<synthesis::CamRoundTrip>(
      [spec, s = scene.scene](const std::atomic<bool>&) { return synthesis::cam_round_trip(spec, *s); });
  const double unit = spec.motion == synthesis::FollowerMotion::Oscillating ? rollkin::io::radians_per<double>(spec.angle_unit) : 1.0;
  py::dict r;
  r["poses"] = rt.poses;
  r["solved"] = rt.solved;
  r["worst_deviation"] = rt.worst_deviation / unit;
  r["tolerance"] = spec.tolerance / unit;
  r["max_pressure_angle_deg"] = rad_to_deg(rt.max_pressure_angle);
  r["min_radius_of_curvature"] = rt.min_radius_of_curvature;
  r["ok"] = rt.problems.empty() && rt.solved == rt.poses && rt.worst_deviation <= spec.tolerance;
  std::vector<double> theta, pressure, analysed, prescribed;
  for (const auto& p : rt.solved_poses) {
    theta.push_back(rollkin::io::from_radians(p.theta, spec.angle_unit));
    pressure.push_back(rad_to_deg(p.pressure_angle));
    analysed.push_back(p.analysed / unit);
    prescribed.push_back(p.prescribed / unit);
  }
  r["cam_angle"] = py::array_t<double>(theta.size(), theta.data());
  r["pressure_angle_deg"] = py::array_t<double>(pressure.size(), pressure.data());
  r["analysed"] = py::array_t<double>(analysed.size(), analysed.data());
  r["prescribed"] = py::array_t<double>(prescribed.size(), prescribed.data());
  out["round_trip"] = r;
  out["scene"] = scene;
  return out;
}

py::dict synthesize_gears(const py::object& spec_arg, const py::object& base_dir) {
  auto [document, file, dir] = spec_document(spec_arg, base_dir);
  const synthesis::GearSpec spec = interruptible<synthesis::GearSpec>([document = document, file = file, dir = dir](const std::atomic<bool>&) {
    return synthesis::gear_spec_from_document(document, file, dir);
  });
  py::dict out;
  const double turn_error = spec.closure_error;
  out["closes"] = std::abs(turn_error) <= spec.tolerance;
  out["closure_error"] = rollkin::io::from_radians(turn_error, spec.angle_unit);
  if (!(std::abs(turn_error) <= spec.tolerance)) return out;
  const synthesis::GearDesign d = interruptible<synthesis::GearDesign>(
      [spec](const std::atomic<bool>&) { return synthesis::synthesise_gears(spec); });
  out["gear1"] = xy_array(d.pair.gear1);
  out["gear2"] = xy_array(d.pair.gear2);
  out["min_curvature"] = py::make_tuple(d.min_curvature1, d.min_curvature2);
  out["svg"] = rollkin::output::gear_svg(spec, d);
  json doc = synthesis::gear_scene(spec, d, "gear1.txt", "gear2.txt");
  json c1 = {{"name", "pitch"}, {"type", "samples"}, {"points", points_json(d.pair.gear1)}, {"closed", true}};
  json c2 = {{"name", "pitch"}, {"type", "samples"}, {"points", points_json(d.pair.gear2)}, {"closed", true}};
  out["contours"] = py::make_tuple(to_python(c1), to_python(c2));
  doc["links"][1]["contours"][0] = c1;
  doc["links"][2]["contours"][0] = c2;
  const PyScene scene = scene_of(doc, "<synthesized gears>", dir);
  const synthesis::GearRoundTrip rt = interruptible<synthesis::GearRoundTrip>(
      [spec, s = scene.scene](const std::atomic<bool>&) { return synthesis::gear_round_trip(spec, *s); });
  out["round_trip"] = py::dict(py::arg("poses") = rt.poses, py::arg("solved") = rt.solved,
                               py::arg("worst_deviation") = rollkin::io::from_radians(rt.worst_deviation, spec.angle_unit),
                               py::arg("ok") = rt.problems.empty() && rt.worst_deviation <= spec.tolerance);
  out["scene"] = scene;
  return out;
}

py::dict envelope(const PyScene& s, const std::string& link_a, const std::string& link_b, const std::string& contour_name,
                  std::optional<double> start, std::optional<double> tolerance) {
  const rollkin::io::Scene& scene = *s.scene;
  const Mechanism<double>& m = scene.mechanism;
  const int a = m.find_link(link_a), b = m.find_link(link_b);
  if (a < 0 || b < 0) throw py::value_error("envelope: no link \"" + (a < 0 ? link_a : link_b) + "\" in the scene");
  const int contour = m.find_contour(contour_name);
  if (contour < 0 || m.contours[contour].link() != b)
    throw py::value_error("envelope: no contour \"" + contour_name + "\" on link \"" + link_b + "\"");
  if (!scene.sweep) throw py::value_error("envelope: the scene has no sweep");
  const double tol = tolerance ? *tolerance : 1e-9 * m.length_scale;
  // The CLI's checks of --start and --tolerance (synthesis/scene_envelope.hpp), before any work.
  if (const std::string bad = synthesis::envelope_tolerance_problem(tol); !bad.empty()) throw py::value_error("envelope: tolerance: " + bad);
  if (start)
    if (const std::string bad = synthesis::envelope_start_problem(*start); !bad.empty()) throw py::value_error("envelope: start: " + bad);
  auto shared = s.scene;
  const synthesis::Envelope<double> env = interruptible<synthesis::Envelope<double>>([shared, a, b, contour, start, tol](const std::atomic<bool>&) {
    const Mechanism<double>& mm = shared->mechanism;
    SolveData<double> sd(mm);
    VectorX<double> q = shared->guess;
    const SolveReport<double> assembly = assemble(mm, q, sd, shared->held);
    if (assembly.status == SolveStatus::CannotAssemble) throw rollkin::io::assembly_error(*shared, assembly.detail);
    const SweepResult<double> result = sweep(mm, sd, q, assembly, shared->sweep->driver, rollkin::sweep_inputs(*shared->sweep));
    const synthesis::SweepMotion motion(mm, result, a, b);
    return synthesis::envelope(synthesis::scene_envelope_problem(mm, motion, contour, start),
                               synthesis::EnvelopeOptions{tol, 256, 400000});
  });
  py::dict out;
  const std::vector<V> pts = env.points();
  out["points"] = xy_array(pts);
  out["closed"] = env.closed;
  out["max_midpoint_deviation"] = env.max_midpoint_deviation;
  py::list defects;
  for (const auto& d : env.defects) defects.append(py::make_tuple(d.t / scene.sweep->unit, d.what));
  out["defects"] = defects;
  out["contour"] = to_python(json{{"name", "envelope"}, {"type", "samples"}, {"points", points_json(pts)}, {"closed", env.closed}});
  out["nurbs"] = env.defects.empty() && pts.size() >= 4 ? to_python(nurbs_json(pts, env.closed, "envelope")) : py::none();
  return out;
}

}  // namespace

void bind_synthesis(py::module_& m) {
  m.def("synthesize_cam", &synthesize_cam, py::arg("spec"), py::kw_only(), py::arg("base_dir") = py::none(),
        "The disk cam of a cam spec (a dict or a spec file; docs/synthesis.md), analysed by the scene made from it.\n"
        "Returns a dict: profile ((n, 2) array, counter-clockwise, the cam's frame), contour (the samples dict a\n"
        "scene takes), nurbs (the same curve as an exact nurbs dict; not when undercut), svg (the picture of the\n"
        "cam and follower at the law's start that `rollkin synthesize cam` writes as PREFIX.svg), folds (cam angle,\n"
        "what: an undercut; then scene and round_trip are None), jumps (the law's\n"
        "discontinuities), scene (a Scene with the profile inline) and round_trip (worst_deviation, tolerance, ok,\n"
        "max_pressure_angle_deg, min_radius_of_curvature, and per pose cam_angle, pressure_angle_deg, analysed,\n"
        "prescribed).\n"
        "    r = rollkin.synthesize_cam({\"base_radius\": 40, \"follower\": {\"motion\": \"translating\"},\n"
        "                                \"contact\": {\"roller_radius\": 10}, \"law\": [...]})");
  m.def("synthesize_gears", &synthesize_gears, py::arg("spec"), py::kw_only(), py::arg("base_dir") = py::none(),
        "A non-circular gear pair from a gear spec (dict or file; docs/synthesis.md). Returns a dict: closes,\n"
        "closure_error (angle unit); when it closes also gear1, gear2 ((n, 2) arrays), contours (two samples dicts),\n"
        "min_curvature (per gear), svg (the picture `rollkin synthesize gears` writes as PREFIX.svg), scene and\n"
        "round_trip (worst_deviation of gear2.phi from -f, ok).");
  m.def("envelope", &envelope, py::arg("scene"), py::arg("link_a"), py::arg("link_b"), py::arg("contour"), py::kw_only(),
        py::arg("start") = py::none(), py::arg("tolerance") = py::none(),
        "The envelope on link_a of link_b's contour (\"B.name\") under the scene's sweep (docs/synthesis.md).\n"
        "Returns a dict: points ((n, 2) array in link_a's frame), closed, contour (a samples dict), nurbs (the same\n"
        "curve as an exact nurbs dict, None where the envelope folds),\n"
        "max_midpoint_deviation, defects (input value, what: folds or gaps).");
}

}  // namespace rollkin::python
