// Interference along a sweep (analysis/interference.hpp) against closed-form geometry:
//  - the reference example (docs/method.md section 4) is interference-free over theta2 in [-50, 100] degrees;
//  - a disk rolling on a floor that ends in a concave fillet and a vertical wall (one contour): the disk
//    touches the wall at a second point, besides its rolling contact, when its centre reaches x = rho - r;
//  - a planet on an arm inside a ring passing a fixed post (a third body): it touches the post where
//    |centre - post| = r + rho, i.e. cos(phi) = ((R - r)^2 + d^2 - (r + rho)^2) / (2 d (R - r));
//  - a disk inside a ring smaller than itself: curvature interference at the contact (kappa sum < 0).
// Each input is classified from the closed-form gap g (distance between the bodies): no finding for
// g > tau + margin, a second touch for margin < g < tau - margin, penetration for g < -margin, where tau is
// the touch tolerance and the margin covers the chord sagittas of the sampled polylines.
#define BOOST_TEST_MODULE solve_interference
#include <boost/test/unit_test.hpp>

#include "rollkin/samples/mechanisms.hpp"
#include "rollkin/solve/continuation.hpp"
#include "rollkin/builder.hpp"
#include "rollkin/io/units.hpp"
#include "rollkin/analysis/interference.hpp"

using namespace rollkin;
using namespace rollkin::testing;

namespace {

SweepResult<double> solve_sweep(const Fixture<double>& f, const std::vector<double>& inputs) {
  SolveData<double> sd(f.mech);
  VectorX<double> q;
  const auto rep = assemble_fixture(f, q, sd);
  BOOST_TEST_REQUIRE(rep.ok(), rep.detail);
  return sweep(f.mech, sd, q, rep, 0, inputs);
}

enum class Expect { Clear, Touch, Penetrate, Either };

Expect classify(double gap, double tau, double margin) {
  if (gap > tau + margin) return Expect::Clear;
  if (gap > margin && gap < tau - margin) return Expect::Touch;
  if (gap < -margin) return Expect::Penetrate;
  return Expect::Either;  // within the margin of a boundary
}

/// Checks the findings for contours (ca, cb) at every pose against the expectation from the gap.
void check_against_gaps(const Mechanism<double>& m, const SweepInterference& res, int ca, int cb,
                        const std::function<double(double)>& gap, double margin) {
  const double tau = res.touch_tolerance;
  int counts[3] = {0, 0, 0};
  for (const auto& p : res.poses) {
    BOOST_TEST_REQUIRE(p.checked);
    bool touch = false, penetrate = false;
    for (const auto& f : p.findings) {
      BOOST_TEST(((f.contour_a == ca && f.contour_b == cb) || (f.contour_a == cb && f.contour_b == ca)),
                 "unexpected finding between " << m.contours[f.contour_a].name() << " and " << m.contours[f.contour_b].name()
                                               << " at input " << p.input);
      touch = touch || f.kind == InterferenceKind::SecondTouch;
      penetrate = penetrate || f.kind == InterferenceKind::Penetration;
    }
    const double g = gap(p.input);
    switch (classify(g, tau, margin)) {
      case Expect::Clear:
        BOOST_TEST(p.clear(), "input " << p.input << " gap " << g);
        ++counts[0];
        break;
      case Expect::Touch:
        BOOST_TEST((touch && !penetrate), "input " << p.input << " gap " << g);
        ++counts[1];
        break;
      case Expect::Penetrate:
        BOOST_TEST(penetrate, "input " << p.input << " gap " << g);
        ++counts[2];
        break;
      case Expect::Either: break;
    }
  }
  BOOST_TEST_MESSAGE("clear " << counts[0] << ", touching " << counts[1] << ", penetrating " << counts[2] << " poses");
  // The test inputs are chosen to visit all three regimes.
  BOOST_TEST(counts[0] > 0);
  BOOST_TEST(counts[1] > 0);
  BOOST_TEST(counts[2] > 0);
}

}  // namespace

BOOST_AUTO_TEST_CASE(paper_example_has_no_interference) {
  const auto f = paper_fourbar<double>();
  const auto r = solve_sweep(f, degrees<double>(-50, 100));
  BOOST_TEST_REQUIRE(r.all_solved());
  const SweepInterference res = check_interference(f.mech, r);
  BOOST_TEST(res.contour_pairs.size() == 3u);  // parabola-disk3, parabola-disk4, disk3-disk4
  for (const auto& p : res.poses) {
    BOOST_TEST(p.checked);
    BOOST_TEST(p.clear(), "theta2 " << rad_to_deg(p.input) << ": " << p.findings.size() << " findings, first "
                                    << (p.findings.empty() ? "" : to_string(p.findings[0].kind)));
  }
  // The chords' distance from the disks is the sagitta R (1 - cos(pi / n)) of a regular n-gon (closed form).
  const double n = InterferenceCheck{}.samples_per_contour;
  BOOST_TEST(res.chord_error[1] == 1 * (1 - std::cos(pi<double>() / n)), boost::test_tools::tolerance(1e-9));
  BOOST_TEST(res.chord_error[2] == 4 * (1 - std::cos(pi<double>() / n)), boost::test_tools::tolerance(1e-9));
  BOOST_TEST(res.max_chord_error() >= res.chord_error[0]);
  // Asking for nothing checks nothing but curvature.
  InterferenceCheck only_curvature;
  only_curvature.contour_pairs = {{0, 2}};
  BOOST_TEST(!check_interference(f.mech, r, only_curvature).any());
  BOOST_CHECK_THROW(([&] {
                      InterferenceCheck bad;
                      bad.contour_pairs = {{0, 0}};
                      check_interference(f.mech, r, bad);
                    }()),
                    std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(disk_rolling_into_a_wall_touches_it_at_a_second_point) {
  // Floor (ground, material below/right): flat from (-10, 0) to (0, 0), a concave quarter circle of radius
  // rho to (rho, rho), then a wall up to (rho, 3). One contour, three Bezier segments.
  const double r = 1, rho = 0.5, H = 3;
  std::vector<BezierSegment<double>> segs;
  segs.push_back({{Vec2<double>(-10, 0), Vec2<double>(0, 0)}, {}});
  const auto fillet = BezierPath<double>::circle_arc(Vec2<double>(0, rho), rho, -pi<double>() / 2, 0);
  segs.push_back(fillet.segments().at(0));
  segs.push_back({{Vec2<double>(rho, rho), Vec2<double>(rho, H)}, {}});
  const BezierPath<double> floor(segs, false);

  MechanismBuilder<double> b;
  const int ground = b.link("ground", true), slider = b.link("slider"), disk = b.link("disk");
  const int line = b.contour(ground, "floor", floor, SE2<double>(), true);
  const int rim = b.contour(disk, "rim", Circle<double>(r));
  const int drive = b.prismatic("slide", ground, slider, SE2<double>(0, Vec2<double>(0, r)), SE2<double>(), "x");
  b.revolute("axle", slider, disk, SE2<double>(), SE2<double>(), "theta");
  b.contact("tread", true, line, rim, "u", "v");
  b.driver(drive);
  const double x0 = -5;
  Fixture<double> f{b.build(), VectorX<double>(4), {}};
  f.guess << x0, 0, -(x0 + 10) / 10, -pi<double>() / 2;  // reversed contour: parameter -u, flat segment u in [0, 1]

  InterferenceCheck opt;
  opt.touch_tolerance = 1e-3;
  opt.samples_per_contour = 3000;
  const double tau = opt.touch_tolerance;
  // Closed form: the disk (centre (x, r)) is clear of the wall by rho - (x + r); the fillet and the rest of
  // the floor stay farther away than that for x <= 0 (checked by hand: the fillet's nearest points are its
  // ends, 1.118 r from the centre at x = rho - r).
  const double x_touch = rho - r;
  std::vector<double> xs;
  for (double x = -4; x <= 0; x += 0.25) xs.push_back(x);
  for (double g : {2 * tau, 1.2 * tau, 0.8 * tau, 0.5 * tau, 0.2 * tau, -0.2 * tau, -tau, -0.01}) xs.push_back(x_touch - g);
  const auto res_sweep = solve_sweep(f, xs);
  BOOST_TEST_REQUIRE(res_sweep.all_solved());
  const SweepInterference res = check_interference(f.mech, res_sweep, opt);
  // Margin: the rim polyline's sagitta r (1 - cos(pi / n)) plus rounding.
  const double margin = r * (1 - std::cos(pi<double>() / opt.samples_per_contour)) + 1e-9;
  check_against_gaps(f.mech, res, line, rim, [&](double x) { return rho - (x + r); }, margin);
  // Where it touches: at the wall, at the height of the disk's centre.
  for (const auto& p : res.poses)
    for (const auto& fd : p.findings)
      if (fd.kind == InterferenceKind::SecondTouch) {
        const Vec2<double> on_floor = fd.contour_a == line ? fd.point_a : fd.point_b;
        BOOST_TEST(std::abs(on_floor.x() - rho) < 1e-9);
        BOOST_TEST(std::abs(on_floor.y() - r) < 0.05);
      }
}

BOOST_AUTO_TEST_CASE(planet_passing_a_fixed_post_is_detected_at_the_closed_form_angles) {
  const double R = 4, r = 1, rho = 0.5, d = 2;
  Fixture<double> f = planet_on_arm<double>(R, r, false);
  // Add the post: a disk of radius rho on the ground at (d, 0). Rebuild with the same variables.
  MechanismBuilder<double> b;
  const int ground = b.link("ground", true), arm = b.link("arm"), planet = b.link("planet");
  const int ring = b.contour(ground, "ring", Circle<double>(R), SE2<double>(), true);
  const int post = b.contour(ground, "post", Circle<double>(rho), SE2<double>(0, Vec2<double>(d, 0)));
  const int rim = b.contour(planet, "rim", Circle<double>(r));
  const int drive = b.revolute("arm", ground, arm, SE2<double>(), SE2<double>(), "phi");
  b.revolute("planet", arm, planet, SE2<double>(0, Vec2<double>(R - r, 0)), SE2<double>(), "psi");
  b.contact("mesh", true, ring, rim, "u", "v");
  b.driver(drive);
  f.mech = b.build();

  // Gap between planet and post: |c - P| - (r + rho), c = (R - r)(cos phi, sin phi), P = (d, 0).
  const double c = R - r;
  auto gap = [&](double phi) { return std::sqrt(c * c + d * d - 2 * c * d * std::cos(phi)) - (r + rho); };
  auto phi_of_gap = [&](double g) {
    const double D = r + rho + g;
    return std::acos((c * c + d * d - D * D) / (2 * c * d));
  };
  const double phi_touch = phi_of_gap(0);
  BOOST_TEST_MESSAGE("planet touches the post at phi = +-" << rad_to_deg(phi_touch) << " deg");
  InterferenceCheck opt;
  opt.touch_tolerance = 1e-3;
  opt.samples_per_contour = 2048;
  const double tau = opt.touch_tolerance;
  std::vector<double> phis = degrees<double>(-90, 90, 5);
  for (double g : {2 * tau, 0.6 * tau, 0.3 * tau, -0.3 * tau, -2 * tau})
    for (double sign : {-1.0, 1.0}) phis.push_back(sign * phi_of_gap(g));
  const auto res_sweep = solve_sweep(f, phis);
  BOOST_TEST_REQUIRE(res_sweep.all_solved());
  const SweepInterference res = check_interference(f.mech, res_sweep, opt);
  BOOST_TEST(res.contour_pairs.size() == 2u);  // ring-rim (own contact, internal) and post-rim
  const double margin = (r + rho) * (1 - std::cos(pi<double>() / opt.samples_per_contour)) + 1e-9;
  check_against_gaps(f.mech, res, post, rim, gap, margin);
}

BOOST_AUTO_TEST_CASE(disk_inside_a_smaller_ring_is_curvature_interference) {
  // Planet of radius 3 "inside" a ring of radius 2 (centre distance -1): kappa_ring + kappa_planet =
  // -1/2 + 1/3 < 0, the bodies overlap around the contact whatever the pose.
  const auto f = planet_on_arm<double>(2.0, 3.0, false);
  const auto r = solve_sweep(f, degrees<double>(0, 90, 30));
  BOOST_TEST_REQUIRE(r.all_solved());
  const SweepInterference res = check_interference(f.mech, r);
  for (const auto& p : res.poses) {
    BOOST_TEST(p.has(InterferenceKind::CurvatureInterference));
    for (const auto& fd : p.findings)
      if (fd.kind == InterferenceKind::CurvatureInterference) BOOST_TEST(std::abs(fd.distance - (-0.5 + 1.0 / 3)) < 1e-12);
  }
  InterferenceCheck off;
  off.check_contact_curvature = false;
  for (const auto& p : check_interference(f.mech, r, off).poses) BOOST_TEST(!p.has(InterferenceKind::CurvatureInterference));
}
