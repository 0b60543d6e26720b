// Closed forms of docs/method.md section 5, solved as mechanisms: hypocycloid and epicycloid (overconstrained:
// redundant but consistent), twin elliptical gears as a rolling pair and as a cam pair, a disk rolling on a
// line (cycloid), and an assembly that cannot close.
#define BOOST_TEST_MODULE solve_closed_forms
#include <boost/test/unit_test.hpp>

#include "rollkin/samples/mechanisms.hpp"
#include "rollkin/builder.hpp"

using namespace rollkin;
using namespace rollkin::testing;

namespace {

}  // namespace

BOOST_AUTO_TEST_CASE(hypocycloid_planet_turns_minus_r_minus_r_over_r) {
  for (auto [R, r] : {std::pair{4.0, 1.0}, std::pair{2.0, 1.0}, std::pair{5.0, 1.5}}) {
    auto f = planet_on_arm<double>(R, r, false);
    SolveReport<double> rep;
    const auto res = assemble_and_sweep(f, degrees<double>(-360, 360, 15), &rep);
    BOOST_TEST_REQUIRE(res.all_solved());
    BOOST_TEST(rep.equations == 4);
    BOOST_TEST(rep.rank == 3);
    BOOST_TEST(rep.redundant() == 1);  // overconstrained, consistent
    for (const auto& p : res.poses) {
      const double planet = p.q(0) + p.q(1);  // absolute angle of the planet
      BOOST_TEST(std::abs(planet - (-(R - r) / r * p.input)) < 1e-10, "R " << R << " arm " << p.input);
    }
  }
}

BOOST_AUTO_TEST_CASE(hypocycloid_with_ring_twice_planet_traces_a_straight_line) {
  auto f = planet_on_arm<double>(2.0, 1.0, false);
  const auto res = assemble_and_sweep(f, degrees<double>(0, 360, 10));
  BOOST_TEST_REQUIRE(res.all_solved());
  for (const auto& p : res.poses) {
    // The planet rim point that touched the ring at the start: (r cos v0, r sin v0) in the planet frame.
    const double planet = p.q(0) + p.q(1);
    const Vec2<double> centre(std::cos(p.q(0)), std::sin(p.q(0)));
    const Vec2<double> point = centre + Vec2<double>(std::cos(planet), std::sin(planet));
    BOOST_TEST(std::abs(point.y()) < 1e-10);  // R = 2r: a diameter of the ring
  }
}

BOOST_AUTO_TEST_CASE(epicycloid_planet_turns_plus_r_plus_r_over_r) {
  const double R = 3, r = 1;
  auto f = planet_on_arm<double>(R, r, true);
  const auto res = assemble_and_sweep(f, degrees<double>(-180, 360, 20));
  BOOST_TEST_REQUIRE(res.all_solved());
  for (const auto& p : res.poses) BOOST_TEST(std::abs(p.q(0) + p.q(1) - (R + r) / r * p.input) < 1e-10);
}

BOOST_AUTO_TEST_CASE(twin_elliptical_gears_follow_the_transmission_function) {
  const double a = 2, e = 0.5;
  for (bool rolling : {true, false}) {
    // The cam pair is singular at the vertex poses (phi1 = 0, 180): assemble it at 40 and stay between.
    auto f = elliptical_gears<double>(a, e, rolling, {}, rolling ? 0.0 : 40 * pi<double>() / 180);
    SolveReport<double> rep;
    const auto res = assemble_and_sweep(f, rolling ? degrees<double>(-170, 170, 10) : degrees<double>(5, 175, 10), &rep);
    BOOST_TEST_REQUIRE(res.all_solved());
    BOOST_TEST(rep.redundant() == (rolling ? 1 : 0));
    for (const auto& p : res.poses) {
      // tan(phi2/2) = ((1 - e)/(1 + e)) tan(phi1/2); gear 2 turns the other way.
      const double expected = -2 * std::atan((1 - e) / (1 + e) * std::tan(p.input / 2));
      BOOST_TEST(std::abs(wrap_angle(p.q(3) - expected)) < 1e-10, (rolling ? "rolling " : "cam ") << p.input);
    }
    // As a cam pair the gears still roll without slip: equal and opposite arc lengths (eq. 3).
    const Ellipse<double> pitch(a, a * std::sqrt(1 - e * e));
    const double u0 = f.guess(1), v0 = f.guess(2);
    for (const auto& p : res.poses)
      BOOST_TEST(std::abs(pitch.arc_length(u0, p.q(1)) + pitch.arc_length(v0, p.q(2))) < 1e-10);
  }
}

BOOST_AUTO_TEST_CASE(full_revolutions_of_elliptical_gears_wrap_the_closed_contours) {
  auto f = elliptical_gears<double>(2, 0.3, true);
  std::vector<double> inputs;
  for (int k = 0; k <= 12; ++k) inputs.push_back(k * pi<double>() / 2);  // three turns
  const auto res = assemble_and_sweep(f, inputs);
  BOOST_TEST_REQUIRE(res.all_solved());
  // After every whole turn of gear 1, gear 2 has made exactly one whole turn back.
  for (int k = 4; k <= 12; k += 4)
    BOOST_TEST(std::abs(res.poses[k].q(3) + res.poses[k].input) < 1e-10);
}

BOOST_AUTO_TEST_CASE(disk_on_line_traces_a_cycloid) {
  const double r = 0.75;
  auto f = disk_on_line<double>(r);
  std::vector<double> xs;
  for (int k = -8; k <= 16; ++k) xs.push_back(k * 0.3);
  SolveReport<double> rep;
  const auto res = assemble_and_sweep(f, xs, &rep);
  BOOST_TEST_REQUIRE(res.all_solved());
  BOOST_TEST(rep.redundant() == 1);  // slider height fixed at r: loop rows and rolling row overlap
  for (const auto& p : res.poses) {
    const double t = p.input / r;
    BOOST_TEST(std::abs(p.q(1) + t) < 1e-12);  // rolls clockwise
    // The rim point that started at the contact: (r cos v0, r sin v0) with v0 = -pi/2.
    const Vec2<double> point = Vec2<double>(p.input, r) + r * Vec2<double>(std::cos(p.q(1) - pi<double>() / 2), std::sin(p.q(1) - pi<double>() / 2));
    BOOST_TEST((point - Vec2<double>(r * (t - std::sin(t)), r * (1 - std::cos(t)))).norm() < 1e-12);
  }
}

BOOST_AUTO_TEST_CASE(assembly_that_cannot_close_is_reported) {
  // Disk of radius 1 whose axle rides 1.5 above the floor: it can never touch it.
  MechanismBuilder<double> b;
  const int ground = b.link("ground", true), slider = b.link("slider"), disk = b.link("disk");
  const int line = b.contour(ground, "floor", Line<double>(-10, 10), SE2<double>(), true);
  const int rim = b.contour(disk, "rim", Circle<double>(1.0));
  const int drive = b.prismatic("slide", ground, slider, SE2<double>(0, Vec2<double>(0, 1.5)));
  b.revolute("axle", slider, disk);
  b.contact("tread", true, line, rim);
  b.driver(drive);
  const auto m = b.build();
  SolveData<double> sd(m);
  VectorX<double> q(4);
  q << 0, 0, 0, -pi<double>() / 2;
  const auto rep = assemble(m, q, sd);
  BOOST_TEST(rep.status == SolveStatus::CannotAssemble);
  BOOST_TEST(rep.detail.find("cannot") != std::string::npos);
}
