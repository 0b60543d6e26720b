// Disk cam synthesis on the envelope engine, the scene that analyses the cam, and the round trip
// (include/rollkin/synthesis/cam.hpp; docs/synthesis.md, "Disk cams").
#include "rollkin/synthesis/cam.hpp"

#include "rollkin/analysis/motion.hpp"
#include "rollkin/io/format.hpp"
#include "rollkin/io/scene/reader.hpp"
#include "rollkin/synthesis/round_trip.hpp"

#include "../io/json/access.hpp"

#include <cmath>
#include <limits>

namespace rollkin::synthesis {
namespace {

using V = Vec2<double>;
using io::json;

V unit(double a) { return V(std::cos(a), std::sin(a)); }
V perp(const V& x) { return V(-x.y(), x.x()); }

/// The follower contour's frame in the world at cam angle theta: origin, velocity and acceleration (per unit
/// theta), the frame staying parallel to the world axes (file comment of cam.hpp).
struct FollowerPlace {
  V v, dv, ddv;
};

FollowerPlace follower_place(const CamSpec& spec, double theta) {
  const LawValue<double> l = (*spec.law)(theta);
  if (spec.motion == FollowerMotion::Oscillating) {
    const double psi = spec.start_angle + l.s;
    const V u = unit(psi), n = perp(u);
    return {spec.pivot + spec.arm * u, spec.arm * l.v * n, spec.arm * (l.a * n - l.v * l.v * u)};
  }
  const double y0 = spec.contact == FollowerContact::Roller
                        ? std::sqrt(std::pow(spec.base_radius + spec.roller_radius, 2) - spec.offset * spec.offset)
                        : spec.base_radius;  // a flat face or a contour: the follower's frame at (e, Rb)
  return {V(spec.offset, y0 + l.s), V(0, l.v), V(0, l.a)};
}

double signed_area(const std::vector<V>& p) {
  double a = 0;
  for (std::size_t k = 0; k < p.size(); ++k) a += cross2(p[k], p[(k + 1) % p.size()]);
  return a / 2;
}


/// A follower given as any contour: its jets, its domain, and the contact at theta = 0 as the root of the meshing
/// equation nearest the cam centre among 2000 points of the domain (a closed contour has two or more).
void contour_follower(const CamSpec& spec, EnvelopeProblem<double>& pr) {
  const auto shape = spec.follower_shape;
  const Contour<double>& c = shape->mechanism.contours[0];
  pr.contour = [shape, &c](const double& u) { return c.jet(u, 2); };
  const Domain<double>& dom = c.domain();
  pr.u_scale = dom.hi - dom.lo;
  if (!dom.closed) {
    pr.u_lo = dom.lo;
    pr.u_hi = dom.hi;
  }
  pr.u_guess = (dom.lo + dom.hi) / 2;
  const MotionJet<double> m0 = pr.motion(0.0);
  const int n = 2000;
  double best = std::numeric_limits<double>::infinity();
  double prev_u = dom.lo, prev_f = meshing(pr, dom.lo, m0).f;
  for (int i = 1; i <= n; ++i) {
    const double u = dom.lo + (dom.hi - dom.lo) * i / n;
    const Meshing<double> r = meshing(pr, u, m0);
    if ((r.f < 0) != (prev_f < 0)) {
      const double dist = meshing(pr, (prev_u + u) / 2, m0).point.norm();
      if (dist < best) {
        best = dist;
        pr.u_guess = (prev_u + u) / 2;
      }
    }
    prev_u = u;
    prev_f = r.f;
  }
}

}  // namespace

EnvelopeProblem<double> cam_envelope_problem(const CamSpec& spec) {
  EnvelopeProblem<double> pr;
  const double rotation = spec.rotation;
  if (spec.contact == FollowerContact::Contour && spec.motion == FollowerMotion::Oscillating) {
    // The contour turns with the arm: its frame at the pivot, at the angle psi = a0 + s.
    pr.motion = [spec, rotation](const double& theta) {
      const LawValue<double> l = (*spec.law)(theta);
      const V zero = V::Zero();
      return relative_to_turning_frame<double>(rotation * theta, rotation, 0, spec.start_angle + l.s, l.v, l.a, spec.pivot, zero, zero);
    };
  } else {
    pr.motion = [spec, rotation](const double& theta) {
      const FollowerPlace f = follower_place(spec, theta);
      return relative_to_turning_frame<double>(rotation * theta, rotation, 0, 0, 0, 0, f.v, f.dv, f.ddv);
    };
  }
  pr.t_begin = 0;
  pr.t_end = 2 * pi<double>();
  pr.periodic = true;
  const V start = follower_place(spec, 0).v;
  if (spec.contact == FollowerContact::Contour) {
    contour_follower(spec, pr);
  } else if (spec.contact == FollowerContact::Roller) {
    const double r = spec.roller_radius;
    pr.contour = [r](const double& u) {
      Jet<double> j;
      j.p = r * unit(u);
      j.d1 = r * perp(unit(u));
      j.d2 = -j.p;
      return j;
    };
    pr.u_guess = std::atan2(-start.y(), -start.x());  // the roller's point facing the cam centre
    pr.u_scale = 2 * pi<double>();
  } else {
    pr.contour = [](const double& u) {
      Jet<double> j;
      j.p = V(u, 0);
      j.d1 = V(1, 0);
      return j;
    };
    pr.u_guess = -spec.offset;  // below the cam centre
    pr.u_scale = spec.base_radius;
  }
  return pr;
}

CamProfile synthesise_cam(const CamSpec& spec) {
  CamProfile out;
  const double length_tolerance = spec.motion == FollowerMotion::Oscillating ? spec.tolerance * spec.arm : spec.tolerance;
  // A sixteenth of the tolerance: the follower responds to the profile error about one to one, and the contact
  // normal (pressure angle) and curvature, derivatives of the fitted spline, need the finer sampling to stay
  // within 1e-6 deg and 1e-5 relative (docs/synthesis.md, "Tolerances").
  out.profile_tolerance = length_tolerance / 16;
  EnvelopeOptions options{out.profile_tolerance, 360, 400000};
  out.envelope = envelope(cam_envelope_problem(spec), options);
  std::vector<V> pts = out.envelope.points();
  if (signed_area(pts) < 0) std::reverse(pts.begin() + 1, pts.end());  // counter-clockwise, first point kept
  out.points = pts;
  out.follower_origin = spec.contact == FollowerContact::Contour && spec.motion == FollowerMotion::Oscillating
                            ? spec.pivot
                            : follower_place(spec, 0).v;
  out.contact = out.envelope.samples.empty() ? out.follower_origin : out.envelope.samples.front().point;
  double reach = 0;
  for (const auto& s : out.envelope.samples) reach = std::max(reach, std::abs(s.u));
  out.face_half_length = 1.1 * reach + 0.1 * spec.base_radius;
  return out;
}

json cam_scene(const CamSpec& spec, const CamProfile& profile, const std::string& profile_file) {
  const bool deg = spec.angle_unit == io::AngleUnit::Degree;
  auto angle_out = [&](double rad) { return io::from_radians(rad, spec.angle_unit); };
  json scene = json::object();
  scene["description"] = "Written by rollkin synthesize cam from " + spec.file +
                         ": the cam turns on the revolute 'cam' (theta), the follower moves on the pair 'follower' "
                         "(the law's displacement s itself) and touches the profile through the cam pair 'contact'.";
  json units = json::object();
  if (!spec.length_label.empty()) units["length"] = spec.length_label;
  units["angle"] = deg ? "deg" : "rad";
  scene["units"] = units;

  json follower_contour = json::object();
  const V origin = profile.follower_origin, c = profile.contact;
  double follower_value = 0;  // the follower contour's parameter at the contact, theta = 0
  // The follower's frame: the world's axes at its origin for a translating follower (the prismatic pair's frame
  // on the follower is turned back by its 90 degrees), the arm's frame at the pivot for an oscillating one.
  // The follower's variable is the law's displacement s itself (zero on the base circle, where the spec places
  // the follower), so it starts at s(0) (docs/synthesis.md, "`rollkin synthesize cam SPEC.json --out PREFIX`"): the round trip compares it with s.
  const double s0 = (*spec.law)(0.0).s;
  const double frame_angle = spec.motion == FollowerMotion::Translating ? 0.0 : spec.start_angle + s0;
  std::string follower_contour_name;
  if (spec.contact == FollowerContact::Contour) {
    follower_contour = spec.follower_contour;
    follower_contour_name = follower_contour["name"].get<std::string>();
    const Contour<double>& shape = spec.follower_shape->mechanism.contours[0];
    const double u0 = profile.envelope.samples.empty() ? 0.0 : profile.envelope.samples.front().u;
    follower_value = shape.parameter_kind() == ParamKind::Angle ? angle_out(u0) : u0;
  } else if (spec.contact == FollowerContact::Roller) {
    follower_contour_name = "roller";
    follower_contour = {{"name", "roller"}, {"type", "circle"}, {"radius", spec.roller_radius}};
    if (spec.motion == FollowerMotion::Oscillating) follower_contour["at"] = {{"x", spec.arm}};
    const V d = c - origin;
    follower_value = angle_out(std::atan2(d.y(), d.x()) - frame_angle);
  } else {
    follower_contour_name = "face";
    follower_contour = {{"name", "face"},        {"type", "line"}, {"from", -profile.face_half_length},
                        {"to", profile.face_half_length}, {"at", {{"angle", angle_out(pi<double>())}}},
                        {"material", "right"}};
    follower_value = -(c.x() - origin.x());  // the face's x axis is the world's -x
  }

  json links = json::array();
  links.push_back({{"name", "frame"}, {"ground", true}});
  links.push_back({{"name", "cam"},
                   {"contours", json::array({{{"name", "profile"}, {"type", "samples"}, {"file", profile_file}, {"closed", true}}})}});
  links.push_back({{"name", "follower"}, {"contours", json::array({follower_contour})}});
  scene["links"] = links;

  json pairs = json::array();
  pairs.push_back({{"name", "cam"}, {"type", "revolute"}, {"links", {"frame", "cam"}}, {"variable", "theta"}, {"value", 0}});
  if (spec.motion == FollowerMotion::Translating) {
    const V at = spec.contact == FollowerContact::Roller ? V(origin - V(0, s0)) : V(spec.offset, spec.base_radius);
    const double quarter = angle_out(pi<double>() / 2);
    pairs.push_back({{"name", "follower"}, {"type", "prismatic"}, {"links", {"frame", "follower"}},
                     {"at", json::array({{{"x", at.x()}, {"y", at.y()}, {"angle", quarter}}, {{"angle", quarter}}})},
                     {"variable", "s"}, {"value", s0}});
  } else {
    pairs.push_back({{"name", "follower"}, {"type", "revolute"}, {"links", {"frame", "follower"}},
                     {"at", json::array({{{"x", spec.pivot.x()}, {"y", spec.pivot.y()}, {"angle", angle_out(spec.start_angle)}},
                                         json::object()})},
                     {"variable", "phi"}, {"value", angle_out(s0)}});
  }
  pairs.push_back({{"name", "contact"}, {"type", "cam"},
                   {"contours", {"cam.profile", "follower." + follower_contour_name}},
                   {"variables", {"u", "v"}}, {"values", {0, follower_value}}});
  scene["pairs"] = pairs;
  scene["inputs"] = json::array({"cam.theta"});
  const double turn = deg ? 360 : 2 * pi<double>(), step = deg ? 1 : deg_to_rad(1.0);
  scene["sweep"] = {{"input", "cam.theta"}, {"from", 0}, {"to", spec.rotation * turn}, {"step", spec.rotation * step}};
  return scene;
}

CamRoundTrip cam_round_trip(const CamSpec& spec, const std::string& scene_file, std::size_t poses) {
  return cam_round_trip(spec, io::load_scene(scene_file), poses);
}

CamRoundTrip cam_round_trip(const CamSpec& spec, const io::Scene& scene, std::size_t poses) {
  CamRoundTrip rt;
  const Mechanism<double>& m = scene.mechanism;
  const std::string follower_variable = spec.motion == FollowerMotion::Translating ? "follower.s" : "follower.phi";
  const int var = m.find_variable(follower_variable);
  if (var < 0) throw std::logic_error("cam_round_trip: the scene has no " + follower_variable);
  // Poses at cam angles that are not those of the samples (the grid of the samples halves 1/360 of a turn):
  // the analysis runs between the samples too, where the fitted spline is farthest from the envelope. Solved
  // as `rollkin solve` solves them (round_trip.hpp): a pose counts when its status is ok.
  const RoundTripInput cam_angle{"cam angle", [&](double input) { return io::format_number(io::from_radians(spec.rotation * input, spec.angle_unit)); },
                                 std::string(" ") + io::unit_label(spec.angle_unit)};
  const RoundTripSweep swept = round_trip_sweep(scene, round_trip_inputs(poses, spec.rotation), cam_angle);
  const SweepResult<double>& result = swept.result;
  rt.problems = swept.problems;
  AnalysisData<double> data(m);
  rt.poses = result.size();
  rt.min_radius_of_curvature = std::numeric_limits<double>::infinity();
  double smallest_abs_radius = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < result.size(); ++k) {
    const double theta = spec.rotation * result.input(k);
    if (!result.ok(k)) continue;  // its status is among the problems
    ++rt.solved;
    const double prescribed = (*spec.law)(theta).s;
    const double deviation = std::abs(result.q(k)[var] - prescribed);
    if (deviation > rt.worst_deviation) {
      rt.worst_deviation = deviation;
      rt.worst_deviation_at = theta;
    }
    const PoseAnalysis<double> a = analyse_pose(m, result.q(k), result.qdot(k), data);
    if (a.contacts.empty()) continue;
    const ContactAnalysis<double>& c = a.contacts.front();
    if (std::isfinite(c.pressure_angle) && c.pressure_angle > rt.max_pressure_angle) {
      rt.max_pressure_angle = c.pressure_angle;
      rt.max_pressure_angle_at = theta;
    }
    const double radius = 1 / c.kappa1;
    rt.solved_poses.push_back({theta, result.q(k)[var], prescribed, c.pressure_angle, radius});
    if (std::abs(radius) < smallest_abs_radius) {
      smallest_abs_radius = std::abs(radius);
      rt.min_radius_of_curvature = radius;
      rt.min_radius_at = theta;
    }
  }
  return rt;
}

}  // namespace rollkin::synthesis
