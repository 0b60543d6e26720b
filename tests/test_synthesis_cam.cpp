// Disk cam synthesis (include/rollkin/synthesis/cam.hpp) against closed forms and by round trip:
//  - an eccentric circular cam (radius R, centre at distance eps from the pivot) with an in-line roller
//    follower: the law s = eps cos(theta) + sqrt((R + r)^2 - eps^2 sin^2(theta)) - (R + eps + r) synthesises the
//    circle back, every profile point at distance R from the circle's centre to 1e-10 relative; with a flat
//    face, s = eps (cos(theta) - 1) gives the circle again;
//  - a textbook cam (cycloidal rise, dwell, cycloidal return, dwell; roller follower, in-line and offset,
//    both rotations): the profile points against the closed form (pitch curve R(-alpha) (e, y0 + s) offset by
//    r along its normal) to 1e-9 of the cam's size; the round trip (scene written, read back, swept at 997
//    poses between the samples) reproduces the law to 1e-9 of the stroke and the pressure angle to 1e-6 deg
//    against atan(|s' - w e| / (y0 + s)) (w = +1 ccw, -1 cw: the common normal passes through the relative
//    instant centre (w s', 0) and the roller's centre);
//  - an undercut: the folds of a roller larger than the pitch curve's radius of curvature are reported;
//  - "contact": {"contour"}: the roller, the flat face and the oscillating roller given as contours give the same
//    profiles (1e-12); a mushroom follower by round trip; a bad contour reported at contact.contour.
#define BOOST_TEST_MODULE synthesis_cam
#include <boost/test/unit_test.hpp>

#include "rollkin/synthesis/cam.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>

using namespace rollkin;
using namespace rollkin::synthesis;

namespace {

const double kPi = M_PI;
const double kDeg = kPi / 180;
using V = Vec2<double>;
V perp(const V& x) { return V(-x.y(), x.x()); }
V rot(double a, const V& x) { return V(std::cos(a) * x.x() - std::sin(a) * x.y(), std::sin(a) * x.x() + std::cos(a) * x.y()); }

CamSpec translating_roller(double Rb, double r, double e, int rotation, MotionLaw<double> law) {
  CamSpec spec;
  spec.file = "test";
  spec.length_label = "mm";
  spec.base_radius = Rb;
  spec.rotation = rotation;
  spec.motion = FollowerMotion::Translating;
  spec.offset = e;
  spec.contact = FollowerContact::Roller;
  spec.roller_radius = r;
  spec.law = std::move(law);
  spec.stroke = spec.law->stroke();
  spec.tolerance = 1e-9 * spec.stroke;
  return spec;
}

MotionLaw<double> cycloidal_law(double h) {
  return MotionLaw<double>::from_segments({{0, 90 * kDeg, h, RiseKind::Cycloidal},
                                           {90 * kDeg, 180 * kDeg, 0, RiseKind::Dwell},
                                           {180 * kDeg, 270 * kDeg, -h, RiseKind::Cycloidal},
                                           {270 * kDeg, 360 * kDeg, 0, RiseKind::Dwell}});
}

/// Writes the profile and the scene under build/synthesis_cam_test/NAME.* and runs the round trip.
CamRoundTrip round_trip(const CamSpec& spec, const CamProfile& profile, const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(ROLLKIN_BINARY_DIR) / "synthesis_cam_test";
  std::filesystem::create_directories(dir);
  {
    std::ofstream points(dir / (name + ".txt"));
    points << std::setprecision(17);
    for (const auto& p : profile.points) points << p.x() << " " << p.y() << "\n";
    std::ofstream scene(dir / (name + ".json"));
    scene << cam_scene(spec, profile, name + ".txt").dump(2);
  }
  return cam_round_trip(spec, (dir / (name + ".json")).string());
}

}  // namespace

BOOST_AUTO_TEST_CASE(eccentric_circle_comes_back_with_a_roller) {
  const double R = 30, eps = 6, r = 8;
  const MotionLaw<double> law = MotionLaw<double>::from_function([=](const double& t) {
    const double c = std::cos(t), s = std::sin(t), q = (R + r) * (R + r) - eps * eps * s * s;
    const double root = std::sqrt(q);
    const double dq = -2 * eps * eps * s * c, ddq = -2 * eps * eps * (c * c - s * s), dddq = 8 * eps * eps * s * c;
    const double droot = dq / (2 * root);
    const double ddroot = ddq / (2 * root) - dq * dq / (4 * q * root);
    const double dddroot = dddq / (2 * root) - ddq * dq / (4 * q * root) - (2 * dq * ddq) / (4 * q * root) +
                           dq * dq * dq * 3 / (8 * q * q * root);
    return LawValue<double>{eps * c + root - (R + eps + r), -eps * s + droot, -eps * c + ddroot, eps * s + dddroot};
  });
  const CamSpec spec = translating_roller(R + eps, r, 0, 1, law);
  const CamProfile profile = synthesise_cam(spec);
  BOOST_TEST(profile.envelope.defects.empty());
  double worst = 0;
  for (const auto& p : profile.points) worst = std::max(worst, std::abs((p - V(0, eps)).norm() - R));
  BOOST_TEST(worst < 1e-10 * R);
}

BOOST_AUTO_TEST_CASE(eccentric_circle_comes_back_with_a_flat_face) {
  const double R = 30, eps = 6;
  CamSpec spec = translating_roller(R + eps, 1, 0, 1, MotionLaw<double>::from_function([=](const double& t) {
    return LawValue<double>{eps * (std::cos(t) - 1), -eps * std::sin(t), -eps * std::cos(t), eps * std::sin(t)};
  }));
  spec.contact = FollowerContact::Flat;
  spec.roller_radius = 0;
  const CamProfile profile = synthesise_cam(spec);
  BOOST_TEST(profile.envelope.defects.empty());
  double worst = 0;
  for (const auto& p : profile.points) worst = std::max(worst, std::abs((p - V(0, eps)).norm() - R));
  BOOST_TEST(worst < 1e-10 * R);
  const CamRoundTrip rt = round_trip(spec, profile, "flat_circle");
  BOOST_TEST(rt.solved == rt.poses);
  BOOST_TEST(rt.worst_deviation <= spec.tolerance);
  BOOST_TEST(std::abs(rt.min_radius_of_curvature - R) < 1e-5 * R);  // the circle, as the fitted spline bends
}

BOOST_AUTO_TEST_CASE(cycloidal_cam_against_the_closed_form_and_by_round_trip) {
  const double Rb = 40, r = 10, h = 15;
  const MotionLaw<double> law = cycloidal_law(h);
  for (double e : {0.0, 12.0}) {
    for (int w : {1, -1}) {
      const CamSpec spec = translating_roller(Rb, r, e, w, law);
      const CamProfile profile = synthesise_cam(spec);
      BOOST_TEST_REQUIRE(profile.envelope.defects.empty());
      const double y0 = std::sqrt((Rb + r) * (Rb + r) - e * e);
      double worst = 0;
      for (const auto& s : profile.envelope.samples) {
        const LawValue<double> l = law(s.t);
        const double a = w * s.t;
        const V v(e, y0 + l.s), dv(0, l.v);
        const V c = rot(-a, v), dc = rot(-a, V(dv - w * perp(v)));
        // Offset towards the cam centre: the side of the pitch curve the origin lies on.
        V n = perp(dc) / dc.norm();
        if (n.dot(c) > 0) n = -n;
        worst = std::max(worst, (s.point - (c + r * n)).norm());
      }
      BOOST_TEST_INFO("offset " << e << " rotation " << w);
      BOOST_TEST(worst < 1e-9 * (Rb + h));
      const CamRoundTrip rt = round_trip(spec, profile, "cycloidal_" + std::to_string(int(e)) + (w > 0 ? "_ccw" : "_cw"));
      BOOST_TEST(rt.solved == rt.poses);
      BOOST_TEST(rt.poses == 998u);
      BOOST_TEST(rt.worst_deviation <= 1e-9 * h);
      double worst_angle = 0;
      std::size_t compared = 0;
      for (const auto& p : rt.solved_poses) {
        if (!std::isfinite(p.pressure_angle)) continue;
        const LawValue<double> l = law(p.theta);
        const double closed = std::atan(std::abs(l.v - w * e) / (y0 + l.s));
        worst_angle = std::max(worst_angle, std::abs(p.pressure_angle - closed));
        ++compared;
      }
      BOOST_TEST(compared > 400u);
      BOOST_TEST(worst_angle < 1e-6 * kDeg);
    }
  }
}

BOOST_AUTO_TEST_CASE(an_undercut_profile_is_reported) {
  const MotionLaw<double> law = MotionLaw<double>::from_segments({{0, 30 * kDeg, 30, RiseKind::Cycloidal},
                                                                  {30 * kDeg, 180 * kDeg, 0, RiseKind::Dwell},
                                                                  {180 * kDeg, 210 * kDeg, -30, RiseKind::Cycloidal},
                                                                  {210 * kDeg, 360 * kDeg, 0, RiseKind::Dwell}});
  const CamProfile small = synthesise_cam(translating_roller(20, 5, 0, 1, law));
  BOOST_TEST(small.envelope.defects.empty());
  const CamProfile large = synthesise_cam(translating_roller(20, 15, 0, 1, law));
  BOOST_TEST(large.envelope.defects.size() == 4u);  // two folds in the rise, two in the return
}

namespace {

CamSpec spec_from_text(const std::string& text) {
  return cam_spec_from_document(nlohmann::ordered_json::parse(text), "spec.json", ROLLKIN_BINARY_DIR);
}

const char* kLaw = R"("law": [{"to": 90, "lift": 15, "kind": "cycloidal"}, {"to": 180, "kind": "dwell"},
                             {"to": 270, "lift": -15, "kind": "cycloidal"}, {"to": 360, "kind": "dwell"}])";

/// Largest distance between two profiles' points (the same sampling when the same envelope is computed).
double largest_difference(const CamProfile& a, const CamProfile& b) {
  if (a.points.size() != b.points.size()) return std::numeric_limits<double>::infinity();
  double worst = 0;
  for (std::size_t k = 0; k < a.points.size(); ++k) worst = std::max(worst, (a.points[k] - b.points[k]).norm());
  return worst;
}

}  // namespace

// "contact": {"contour": ...} is any contour of the scene format: given as the circle of the roller, the line of
// the flat face and the circle on the oscillating arm, it gives the dedicated kinds' profiles (the same sampling,
// points to 1e-12), so the general path is checked against the two closed-form-tested ones.
BOOST_AUTO_TEST_CASE(any_contour_agrees_with_the_roller_and_the_flat_face) {
  const std::string head = R"({"units": {"length": "mm", "angle": "deg"}, "base_radius": 40, )";
  const std::string translating = R"("follower": {"motion": "translating"}, )";
  const std::string oscillating = R"("follower": {"motion": "oscillating", "pivot": [80, 50], "arm": 80, "start_angle": 180}, )";
  struct Case {
    std::string follower, dedicated, contour;
  };
  const Case cases[] = {
      {translating, R"("contact": {"roller_radius": 10}, )", R"("contact": {"contour": {"type": "circle", "radius": 10, "at": {"y": 10}}}, )"},
      {translating, R"("contact": {"flat": true}, )", R"("contact": {"contour": {"type": "line", "from": -40, "to": 40}}, )"},
      {oscillating, R"("contact": {"roller_radius": 10}, )", R"("contact": {"contour": {"type": "circle", "radius": 10, "at": {"x": 80}}}, )"}};
  for (const Case& c : cases) {
    const CamProfile a = synthesise_cam(spec_from_text(head + c.follower + c.dedicated + kLaw + "}"));
    const CamSpec spec = spec_from_text(head + c.follower + c.contour + kLaw + "}");
    BOOST_TEST((spec.contact == FollowerContact::Contour));
    const CamProfile b = synthesise_cam(spec);
    BOOST_TEST_INFO(c.contour);
    BOOST_TEST(largest_difference(a, b) < 1e-12 * 60);
  }
}

BOOST_AUTO_TEST_CASE(a_mushroom_follower_by_round_trip) {
  // A convex circular face (radius 60, an arc of 60 degrees) on a translating follower: no closed form, the
  // analysis of the written scene is the proof.
  const CamSpec spec = spec_from_text(
      R"({"units": {"length": "mm", "angle": "deg"}, "base_radius": 40, "follower": {"motion": "translating"},
          "contact": {"contour": {"type": "circle", "radius": 60, "arc": [240, 300], "at": {"y": 60}}},
          "law": [{"to": 100, "lift": 12, "kind": "poly345"}, {"to": 160, "kind": "dwell"},
                  {"to": 260, "lift": -12, "kind": "poly345"}, {"to": 360, "kind": "dwell"}]})");
  const CamProfile profile = synthesise_cam(spec);
  BOOST_TEST(profile.envelope.defects.empty());
  const CamRoundTrip rt = round_trip(spec, profile, "mushroom");
  BOOST_TEST(rt.solved == rt.poses);
  BOOST_TEST(rt.worst_deviation <= 1e-9 * 12);
}

BOOST_AUTO_TEST_CASE(a_bad_follower_contour_is_reported_at_its_path) {
  try {
    spec_from_text(std::string(R"({"base_radius": 40, "follower": {"motion": "translating"},
                                   "contact": {"contour": {"type": "circel", "radius": 10}}, )") + kLaw + "}");
    BOOST_FAIL("no error");
  } catch (const io::InputError& e) {
    BOOST_TEST(e.location() == "contact.contour.type");
  }
}
