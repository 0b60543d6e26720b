// Non-circular gear pairs: pitch curves sampled to a tolerance, the scene that rolls them, the round trip
// (include/rollkin/synthesis/gears.hpp; docs/synthesis.md, "Non-circular gears").
#include "rollkin/io/format.hpp"
#include "rollkin/synthesis/gears.hpp"

#include "rollkin/io/scene/reader.hpp"
#include "rollkin/profile/spline.hpp"
#include "rollkin/synthesis/round_trip.hpp"

#include "../io/json/access.hpp"

#include <cmath>
#include <limits>

namespace rollkin::synthesis {
namespace {

using V = Vec2<double>;
using io::json;

/// Largest distance of the closed spline through `pts` (sample j at body angle 2 pi j / n) from the true curve
/// at the mid-angles (`truth(angle)`), each found by Newton on the spline's parameter within its span.
template <class Truth> double midpoint_deviation(const std::vector<V>& pts, Truth truth) {
  SplineOptions<double> o;
  o.closed = true;
  const SampledProfile<double> spline(pts, o);
  const std::size_t n = pts.size();
  double worst = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const V x = truth(2 * pi<double>() * (k + 0.5) / double(n));
    const double lo = spline.knots()[k], hi = spline.knots()[k + 1];
    double u = (lo + hi) / 2;
    for (int it = 0; it < 20; ++it) {
      const Jet<double> j = spline.jet(u, 2);
      const V r = j.p - x;
      u = std::min(hi, std::max(lo, u - j.d1.dot(r) / (j.d2.dot(r) + j.d1.dot(j.d1))));
    }
    worst = std::max(worst, (spline.jet(u, 0).p - x).norm());
  }
  return worst;
}

/// Smallest signed curvature of the closed spline through `pts` (at 8 points per span) and its polar angle.
std::pair<double, double> min_curvature(const std::vector<V>& pts) {
  SplineOptions<double> o;
  o.closed = true;
  const SampledProfile<double> spline(pts, o);
  double best = std::numeric_limits<double>::infinity(), at = 0;
  for (std::size_t k = 0; k < spline.span_count(); ++k)
    for (int i = 0; i < 8; ++i) {
      const double u = spline.knots()[k] + (spline.knots()[k + 1] - spline.knots()[k]) * i / 8.0;
      const Jet<double> j = spline.jet(u, 2);
      const double kappa = cross2(j.d1, j.d2) / std::pow(j.d1.norm(), 3);
      if (kappa < best) {
        best = kappa;
        at = std::atan2(j.p.y(), j.p.x());
      }
    }
  return {best, at};
}

}  // namespace

TransmissionFunction<double> transmission(const GearSpec& spec) {
  if (spec.kind == "sinusoidal") return TransmissionFunction<double>::sinusoidal(spec.parameter);
  if (spec.kind == "elliptical") {
    const double k = (1 + spec.parameter) / (1 - spec.parameter);
    return {[k](const double& p) {
              const double s = std::sin(p / 2), c = std::cos(p / 2);
              return p + 2 * std::atan((k - 1) * s * c / (c * c + k * s * s));
            },
            [k](const double& p) {
              const double s = std::sin(p / 2), c = std::cos(p / 2);
              return k / (c * c + k * k * s * s);
            }};
  }
  const MotionLaw<double> g = *spec.table_excess;
  return {[g](const double& p) { return p + g(p).s; },
          [g](const double& p) { return 1 + g(p).v; }};
}

GearDesign synthesise_gears(const GearSpec& spec) {
  const TransmissionFunction<double> t = transmission(spec);
  const double E = spec.centre_distance;
  GearDesign d;
  d.profile_tolerance = spec.tolerance * E / 16;
  auto gear1 = [&](double theta) {
    const double r1 = pitch_radii(t, E, -theta).r1;
    return V(r1 * std::cos(theta), r1 * std::sin(theta));
  };
  auto gear2 = [&](double psi) {
    const double r2 = pitch_radii(t, E, t.inverse(psi - pi<double>(), 2 * pi<double>())).r2;
    return V(r2 * std::cos(psi), r2 * std::sin(psi));
  };
  std::size_t n = 64;
  double reached = 0;  // the larger mid-angle deviation of the last sampling, for the message
  for (;; n *= 2) {
    if (n > (std::size_t(1) << 20))
      throw std::runtime_error("gear synthesis: the pitch curves need more than 2^20 samples each to be within " +
                               io::format_number(d.profile_tolerance, 3) + " of the true curves (with 2^20 their splines are " +
                               io::format_number(reached, 3) + " off at a mid-angle)");
    d.pair = synthesise_gear_pair(t, E, n, n);
    const double dev1 = midpoint_deviation(d.pair.gear1, gear1), dev2 = midpoint_deviation(d.pair.gear2, gear2);
    reached = std::max(dev1, dev2);
    if (dev1 <= d.profile_tolerance && dev2 <= d.profile_tolerance) break;
  }
  std::tie(d.min_curvature1, d.min_curvature1_at) = min_curvature(d.pair.gear1);
  std::tie(d.min_curvature2, d.min_curvature2_at) = min_curvature(d.pair.gear2);
  return d;
}

json gear_scene(const GearSpec& spec, const GearDesign& d, const std::string& file1, const std::string& file2) {
  const TransmissionFunction<double> t = transmission(spec);
  auto angle_out = [&](double rad) { return io::from_radians(rad, spec.angle_unit); };
  json scene = json::object();
  scene["description"] = "Written by rollkin synthesize gears from " + spec.file +
                         ": the pitch curves of the non-circular gear pair roll on each other (pair 'mesh'); gear 2 "
                         "turns by -f(gear1.phi).";
  json units = json::object();
  if (!spec.length_label.empty()) units["length"] = spec.length_label;
  units["angle"] = spec.angle_unit == io::AngleUnit::Degree ? "deg" : "rad";
  scene["units"] = units;
  scene["links"] = json::array(
      {{{"name", "frame"}, {"ground", true}},
       {{"name", "gear1"}, {"contours", json::array({{{"name", "pitch"}, {"type", "samples"}, {"file", file1}, {"closed", true}}})}},
       {{"name", "gear2"}, {"contours", json::array({{{"name", "pitch"}, {"type", "samples"}, {"file", file2}, {"closed", true}}})}}});
  // Gear 2's contact at phi1 = 0 is its body point at polar angle pi + f(0): the chord length to the nearest
  // sample is the guess (the assembly solves it; gear 1's contact, its first sample, is held).
  const double psi = std::remainder(pi<double>() + t.f(0), 2 * pi<double>());
  const std::size_t n2 = d.pair.gear2.size();
  std::size_t nearest = static_cast<std::size_t>(std::lround((psi < 0 ? psi + 2 * pi<double>() : psi) / (2 * pi<double>()) * n2)) % n2;
  double chord = 0;
  for (std::size_t j = 0; j < nearest; ++j) chord += (d.pair.gear2[j + 1] - d.pair.gear2[j]).norm();
  scene["pairs"] = json::array(
      {{{"name", "gear1"}, {"type", "revolute"}, {"links", {"frame", "gear1"}}, {"variable", "phi"}, {"value", 0}},
       {{"name", "gear2"}, {"type", "revolute"}, {"links", {"frame", "gear2"}},
        {"at", json::array({{{"x", spec.centre_distance}}, json::object()})}, {"variable", "phi"}, {"value", angle_out(-t.f(0))}},
       {{"name", "mesh"}, {"type", "rolling"}, {"contours", {"gear1.pitch", "gear2.pitch"}}, {"variables", {"u1", "u2"}},
        {"values", {0, chord}}, {"hold", {true, false}}}});
  scene["inputs"] = json::array({"gear1.phi"});
  scene["sweep"] = {{"input", "gear1.phi"}, {"from", 0}, {"to", angle_out(2 * pi<double>())}, {"step", angle_out(deg_to_rad(1.0))}};
  return scene;
}

GearRoundTrip gear_round_trip(const GearSpec& spec, const std::string& scene_file) {
  return gear_round_trip(spec, io::load_scene(scene_file), {});
}

GearRoundTrip gear_round_trip(const GearSpec& spec, const io::Scene& scene, const std::vector<double>& inputs) {
  const TransmissionFunction<double> t = transmission(spec);
  GearRoundTrip rt;
  const Mechanism<double>& m = scene.mechanism;
  const int var = m.find_variable("gear2.phi");
  if (var < 0) throw std::logic_error("gear_round_trip: the scene has no gear2.phi");
  // Solved as `rollkin solve` solves them (round_trip.hpp): a pose counts when its status is ok.
  const RoundTripInput phi1{"gear1.phi", [&](double input) { return io::format_number(io::from_radians(input, spec.angle_unit)); },
                            std::string(" ") + io::unit_label(spec.angle_unit)};
  const RoundTripSweep swept = round_trip_sweep(scene, inputs.empty() ? round_trip_inputs(997) : inputs, phi1);
  const SweepResult<double>& result = swept.result;
  rt.problems = swept.problems;
  rt.poses = result.size();
  rt.statuses.reserve(result.size());
  for (std::size_t k = 0; k < result.size(); ++k) {
    rt.statuses.push_back(result.status(k));
    if (!result.ok(k)) continue;
    ++rt.solved;
    const double phi1 = result.input(k);
    const double deviation = std::abs(std::remainder(result.q(k)[var] + t.f(phi1), 2 * pi<double>()));
    if (deviation > rt.worst_deviation) {
      rt.worst_deviation = deviation;
      rt.worst_deviation_at = phi1;
    }
  }
  return rt;
}

}  // namespace rollkin::synthesis
