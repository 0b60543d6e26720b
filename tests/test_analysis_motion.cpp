// The contact analysis of a solved pose (analysis/motion.hpp) against independent truth:
//  - pressure angle of an eccentric circular cam (radius R, centre e from its pivot) driving a translating
//    follower on a line through the pivot: with a roller of radius r, |phi| = asin(e |cos theta| / (R + r)),
//    theta the cam's eccentricity angle measured from the perpendicular to the follower's line; with a flat
//    face tilted by beta from the perpendicular to the stroke, phi = |beta| (0 for a perpendicular face);
//  - sliding and rolling speed of that cam against a numeric derivation from positions alone (central
//    differences of the arc-length positions R u and r v of the contact on the two circles);
//  - the same against differences of the closed-form arc length for an elliptic cam under a flat face;
//  - the paper's example (examples/paper_fourbar.json): sliding zero to round-off at both rolling pairs;
//  - curvatures against closed forms: parabola 2a / (1 + 4 a^2 x^2)^(3/2), circles 1/r, a ring -1/R,
//    ellipse AB / (A^2 sin^2 t + B^2 cos^2 t)^(3/2) (t the eccentric anomaly);
//  - angular accelerations against central differences of the angular velocities along a sweep;
//  - jerk: the follower's third derivative s''' against the closed forms of the eccentric cam's followers
//    (roller: s = e sin theta + sqrt((R + r)^2 - e^2 cos^2 theta); flat face: s = R + e sin theta); the paper
//    example's angular jerks and pair variables' third derivatives against central differences of the
//    analytic accelerations;
//  - the same analysis in MPFR (50 digits) against double.
#define BOOST_TEST_MODULE analysis
#include <boost/test/unit_test.hpp>

#include "rollkin/samples/mechanisms.hpp"
#include "rollkin/builder.hpp"
#include "rollkin/analysis/motion.hpp"
#include "rollkin/io/scene/reader.hpp"
#include "rollkin/scalar_mpfr.hpp"
#include "rollkin/solve/mpfr50_instances.hpp"

#include <algorithm>
#include <cmath>

using namespace rollkin;
using namespace rollkin::testing;

namespace {

const double kDeg = M_PI / 180;

/// Inputs from `from` to `to` degrees in steps of `step` degrees, each with its central-difference neighbours
/// at -h and +h (radians): pose 3k + 1 is the value, poses 3k and 3k + 2 its neighbours.
std::vector<double> with_neighbours(int from, int to, int step, double h) {
  std::vector<double> inputs;
  for (int d = from; d <= to; d += step)
    for (int j = -1; j <= 1; ++j) inputs.push_back(d * kDeg + j * h);
  return inputs;
}

/// Analysis of every solved pose of a sweep (nothing for unsolved ones).
std::vector<PoseAnalysis<double>> analyse_sweep(const Mechanism<double>& m, const SweepResult<double>& res) {
  AnalysisData<double> data(m);
  std::vector<PoseAnalysis<double>> out;
  for (const auto& p : res.poses) out.push_back(p.report.ok() ? analyse_pose(m, p.q, p.qdot, data) : PoseAnalysis<double>{});
  return out;
}

/// The paper example solved and analysed from -40 to 90 degrees every 10, each value with its
/// central-difference neighbours at +-h (with_neighbours).
struct PaperWithNeighbours {
  Fixture<double> f;
  std::vector<double> inputs;
  SweepResult<double> res;
  std::vector<PoseAnalysis<double>> an;
  explicit PaperWithNeighbours(double h)
      : f(paper_fourbar<double>()), inputs(with_neighbours(-40, 90, 10, h)), res(assemble_and_sweep(f, inputs)) {
    BOOST_TEST_REQUIRE(res.all_solved());
    an = analyse_sweep(f.mech, res);
  }
};

double ellipse_curvature(double A, double B, double t) {
  const double s = std::sin(t), c = std::cos(t);
  return A * B / std::pow(A * A * s * s + B * B * c * c, 1.5);
}

}  // namespace

BOOST_AUTO_TEST_CASE(roller_follower_pressure_angle_closed_form_over_a_turn) {
  const double R = 3, e = 1, r = 1;
  const auto f = eccentric_cam<double>(R, e, true, r);
  const auto res = assemble_and_sweep(f, degrees<double>(-180, 180, 3));
  BOOST_TEST_REQUIRE(res.all_solved());
  const auto an = analyse_sweep(f.mech, res);
  double worst = 0;
  int undefined = 0;
  for (std::size_t k = 0; k < res.poses.size(); ++k) {
    const double theta = res.poses[k].input;
    const ContactAnalysis<double>& c = an[k].contacts.at(0);
    if (std::abs(std::cos(theta)) < 1e-12) {
      // theta = +-90 deg: the follower is at the top or bottom of its stroke and stands still.
      BOOST_TEST(std::isnan(c.pressure_angle), "theta " << theta / kDeg);
      ++undefined;
      continue;
    }
    const double expected = std::asin(e * std::abs(std::cos(theta)) / (R + r));
    worst = std::max(worst, std::abs(c.pressure_angle - expected));
    // The contact holds: the two material points' relative velocity is tangential.
    BOOST_TEST(std::abs((c.velocity_b - c.velocity_a).dot(c.normal)) < 1e-13 * R);
  }
  BOOST_TEST_MESSAGE("roller follower: worst pressure-angle error vs asin(e|cos theta|/(R+r)) " << worst << " rad over "
                                                                                                  << res.poses.size() << " poses");
  BOOST_TEST(worst < 1e-13);
  BOOST_TEST(undefined == 2);
}

BOOST_AUTO_TEST_CASE(flat_faced_follower_pressure_angle_is_the_face_tilt) {
  const double R = 3, e = 1;
  for (double beta_deg : {0.0, 20.0, -35.0}) {
    const double beta = beta_deg * kDeg;
    const auto f = eccentric_cam<double>(R, e, false, 0.0, beta);
    const auto res = assemble_and_sweep(f, degrees<double>(-180, 180, 3));
    BOOST_TEST_REQUIRE(res.all_solved());
    const auto an = analyse_sweep(f.mech, res);
    double worst = 0;
    for (std::size_t k = 0; k < res.poses.size(); ++k) {
      const double pa = an[k].contacts.at(0).pressure_angle;
      // The follower stands still where s' = e cos(theta - beta) / cos(beta) = 0.
      if (std::abs(std::cos(res.poses[k].input - beta)) < 1e-12) {
        BOOST_TEST(std::isnan(pa));
        continue;
      }
      worst = std::max(worst, std::abs(pa - std::abs(beta)));
    }
    BOOST_TEST_MESSAGE("flat face tilted " << beta_deg << " deg: worst pressure-angle error " << worst << " rad");
    BOOST_TEST(worst < 1e-13);
  }
}

BOOST_AUTO_TEST_CASE(cam_sliding_and_rolling_speed_against_differences_of_positions) {
  // The contact's arc-length positions on the two circles are R u and r v; the contact point travels along
  // the cam at R u' (along t) and along the roller at r v' (along -t): sliding = R u' + r v',
  // rolling speed = (R u' - r v') / 2, here from central differences of the solved positions.
  const double R = 3, e = 1, r = 1, h = 1e-4;
  const auto f = eccentric_cam<double>(R, e, true, r);
  const std::vector<double> inputs = with_neighbours(-170, 170, 20, h);
  const auto res = assemble_and_sweep(f, inputs);
  BOOST_TEST_REQUIRE(res.all_solved());
  const auto an = analyse_sweep(f.mech, res);
  double worst_sliding = 0, worst_ratio = 0;
  for (std::size_t k = 1; k < inputs.size(); k += 3) {
    const VectorX<double> dq = (res.poses[k + 1].q - res.poses[k - 1].q) / (2 * h);
    const double sliding = R * dq(2) + r * dq(3), rolling = (R * dq(2) - r * dq(3)) / 2;
    const ContactAnalysis<double>& c = an[k].contacts.at(0);
    worst_sliding = std::max(worst_sliding, std::abs(c.sliding - sliding) / R);
    worst_ratio = std::max(worst_ratio, std::abs(c.slide_to_roll - sliding / rolling) / std::abs(sliding / rolling));
    BOOST_TEST(std::abs(c.rolling_speed - rolling) < 1e-7 * R);
  }
  BOOST_TEST_MESSAGE("cam pair: sliding vs differences of positions, worst " << worst_sliding
                                                                              << " (relative to R); slide-to-roll relative " << worst_ratio);
  BOOST_TEST(worst_sliding < 1e-7);
  BOOST_TEST(worst_ratio < 1e-6);
}

BOOST_AUTO_TEST_CASE(elliptic_cam_sliding_against_differences_of_arc_lengths) {
  // A non-circular cam: an ellipse (A = 3, B = 2) turning about its centre under a flat face perpendicular
  // to the stroke. The contact's arc-length positions are s_A(u) on the ellipse (elliptic integral, closed
  // form) and v on the face; sliding = s_A' + v', rolling speed = (s_A' - v') / 2, by central differences.
  const double A = 3, B = 2, h = 1e-4;
  MechanismBuilder<double> b;
  const int ground = b.link("ground", true), cam = b.link("cam"), follower = b.link("follower");
  const int disk = b.contour(cam, "ellipse", Ellipse<double>(A, B));
  const int face = b.contour(follower, "face", Line<double>(-10, 10), SE2<double>(-M_PI / 2, Vec2<double>(0, 0)));
  const int pivot = b.revolute("pivot", ground, cam, SE2<double>(), SE2<double>(), "theta");
  b.prismatic("guide", ground, follower, SE2<double>(M_PI / 2, Vec2<double>(0, 0)), SE2<double>(), "s");
  b.contact("contact", false, disk, face, "u", "v");
  b.driver(pivot);
  Fixture<double> f{b.build(), VectorX<double>(4), {}};
  f.guess << 0, B, M_PI / 2, 0;  // the ellipse's top vertex (0, B) under the face
  const std::vector<double> inputs = with_neighbours(-175, 175, 10, h);
  const auto res = assemble_and_sweep(f, inputs);
  BOOST_TEST_REQUIRE(res.all_solved());
  const auto an = analyse_sweep(f.mech, res);
  const Contour<double>& ellipse = f.mech.contours[disk];
  double worst_sliding = 0, worst_ratio = 0, worst_angle = 0, worst_kappa = 0;
  for (std::size_t k = 1; k < inputs.size(); k += 3) {
    const double sa = (ellipse.arc_length(res.poses[k].q(2), res.poses[k + 1].q(2)) -
                       ellipse.arc_length(res.poses[k].q(2), res.poses[k - 1].q(2))) / (2 * h);
    const double sb = (res.poses[k + 1].q(3) - res.poses[k - 1].q(3)) / (2 * h);
    const ContactAnalysis<double>& c = an[k].contacts.at(0);
    const double sliding = sa + sb, rolling = (sa - sb) / 2;
    worst_sliding = std::max(worst_sliding, std::abs(c.sliding - sliding) / A);
    worst_ratio = std::max(worst_ratio, std::abs(c.slide_to_roll - sliding / rolling) / std::abs(sliding / rolling));
    if (!std::isnan(c.pressure_angle)) worst_angle = std::max(worst_angle, c.pressure_angle);
    worst_kappa = std::max(worst_kappa, std::abs(c.kappa1 / ellipse_curvature(A, B, res.poses[k].q(2)) - 1));
    BOOST_TEST(c.kappa2 == 0.0);
  }
  BOOST_TEST_MESSAGE("elliptic cam, flat face: sliding vs differences of arc lengths " << worst_sliding << " (relative to A), slide-to-roll "
                     << worst_ratio << " relative, pressure angle up to " << worst_angle << " rad, curvature " << worst_kappa);
  BOOST_TEST(worst_sliding < 1e-7);
  BOOST_TEST(worst_ratio < 1e-6);
  BOOST_TEST(worst_angle < 1e-13);
  BOOST_TEST(worst_kappa < 1e-14);
}

BOOST_AUTO_TEST_CASE(paper_example_rolls_without_sliding_and_curvatures_match_closed_forms) {
  const io::Scene scene = io::load_scene(std::string(ROLLKIN_SOURCE_DIR) + "/examples/paper_fourbar.json");
  const Mechanism<double>& m = scene.mechanism;
  SolveData<double> sd(m);
  VectorX<double> q = scene.guess;
  const auto assembly = assemble(m, q, sd, scene.held);
  BOOST_TEST_REQUIRE(assembly.ok());
  const auto res = sweep(m, sd, q, assembly, scene.sweep->driver, sweep_inputs(*scene.sweep));
  BOOST_TEST_REQUIRE(res.all_solved());
  const auto an = analyse_sweep(m, res);
  const int pair_a = m.find_pair("A"), pair_b = m.find_pair("B"), x = m.find_variable("A.x");
  BOOST_TEST_REQUIRE(an[0].contacts.size() == 2u);
  const double a = 0.5;
  double worst_sliding = 0, worst_kappa = 0, largest_speed = 0;
  for (std::size_t k = 0; k < res.poses.size(); ++k) {
    const ContactAnalysis<double>& A = an[k].contacts[0];
    const ContactAnalysis<double>& B = an[k].contacts[1];
    BOOST_TEST(A.pair == pair_a);
    BOOST_TEST(B.pair == pair_b);
    for (const auto* c : {&A, &B}) {
      worst_sliding = std::max(worst_sliding, std::abs(c->sliding));
      largest_speed = std::max({largest_speed, c->velocity_a.norm(), c->velocity_b.norm()});
      if (!std::isnan(c->slide_to_roll)) BOOST_TEST(std::abs(c->slide_to_roll) < 1e-12);
    }
    // Parabola y = a x^2 with its material on the convex-region side faces disk 3 convexly.
    const double xx = res.poses[k].q(x);
    const double parabola = 2 * a / std::pow(1 + 4 * a * a * xx * xx, 1.5);
    worst_kappa = std::max({worst_kappa, std::abs(A.kappa1 - parabola) / parabola, std::abs(A.kappa2 - 1.0),
                            std::abs(B.kappa1 - 1.0), std::abs(B.kappa2 - 0.25) / 0.25,
                            std::abs(A.relative_curvature - (parabola + 1)) / (parabola + 1)});
  }
  BOOST_TEST_MESSAGE("paper example: worst |sliding| " << worst_sliding << " per rad (contact speeds up to "
                                                       << largest_speed << "), worst relative curvature error " << worst_kappa);
  BOOST_TEST(worst_sliding < 1e-13 * largest_speed);
  BOOST_TEST(worst_kappa < 1e-14);
}

BOOST_AUTO_TEST_CASE(curvatures_of_ellipses_and_of_a_ring) {
  const double A = 2, ecc = 0.5, B = A * std::sqrt(1 - ecc * ecc);
  const auto gears = elliptical_gears<double>(A, ecc, true);
  const auto res = assemble_and_sweep(gears, degrees<double>(-180, 180, 10));
  BOOST_TEST_REQUIRE(res.all_solved());
  const auto an = analyse_sweep(gears.mech, res);
  double worst = 0, worst_sliding = 0;
  for (std::size_t k = 0; k < res.poses.size(); ++k) {
    const ContactAnalysis<double>& c = an[k].contacts.at(0);
    const double k1 = ellipse_curvature(A, B, res.poses[k].q(1)), k2 = ellipse_curvature(A, B, res.poses[k].q(2));
    worst = std::max({worst, std::abs(c.kappa1 - k1) / k1, std::abs(c.kappa2 - k2) / k2,
                      std::abs(c.relative_curvature - (k1 + k2)) / (k1 + k2)});
    worst_sliding = std::max(worst_sliding, std::abs(c.sliding) / A);
  }
  BOOST_TEST_MESSAGE("elliptical gears: worst relative curvature error " << worst << ", worst |sliding|/A " << worst_sliding);
  BOOST_TEST(worst < 1e-14);
  BOOST_TEST(worst_sliding < 1e-13);

  // A planet disk (r = 1) inside a fixed ring (R = 4): the ring is concave toward the planet.
  const auto planet = planet_on_arm<double>(4.0, 1.0, false);
  const auto pres = assemble_and_sweep(planet, degrees<double>(0, 90, 30));
  BOOST_TEST_REQUIRE(pres.all_solved());
  for (const auto& pa : analyse_sweep(planet.mech, pres)) {
    const ContactAnalysis<double>& c = pa.contacts.at(0);
    BOOST_TEST(std::abs(c.kappa1 + 0.25) < 1e-15);
    BOOST_TEST(std::abs(c.kappa2 - 1.0) < 1e-15);
    BOOST_TEST(std::abs(c.relative_curvature - 0.75) < 1e-15);
    // The ring (second contour's partner) is the ground: the planet's contact point is the instant centre,
    // and the ring's contour is the first one; the driven point (on the planet) stands still.
    BOOST_TEST(std::isnan(c.pressure_angle));
  }
}

BOOST_AUTO_TEST_CASE(angular_accelerations_match_differences_of_angular_velocities) {
  const double h = 1e-4;
  const PaperWithNeighbours p(h);
  const auto& [f, inputs, res, an] = p;
  double worst = 0;
  for (std::size_t k = 1; k < inputs.size(); k += 3)
    for (std::size_t l = 0; l < f.mech.links.size(); ++l) {
      const double fd = (an[k + 1].link_velocity[l].z() - an[k - 1].link_velocity[l].z()) / (2 * h);
      const double alpha = an[k].angular_acceleration[l];
      const double size = std::max(std::abs(alpha), std::abs(an[k].link_velocity[l].z()));
      if (size == 0) {
        BOOST_TEST(fd == 0.0);
        continue;
      }
      worst = std::max(worst, std::abs(alpha - fd) / size);
      // The angular velocity itself against differences of the link's world angle.
      const double angle_rate = wrap_angle(an[k + 1].link_pose[l].angle() - an[k - 1].link_pose[l].angle()) / (2 * h);
      BOOST_TEST(std::abs(angle_rate - an[k].link_velocity[l].z()) < 1e-6 * size);
    }
  // Every pair variable's second derivative against differences of the sweep's rates (SweepPose::qdot).
  double worst_q = 0;
  for (std::size_t k = 1; k < inputs.size(); k += 3)
    for (int i = 0; i < f.mech.variable_count(); ++i) {
      const double fd = (res.poses[k + 1].qdot(i) - res.poses[k - 1].qdot(i)) / (2 * h);
      const double size = std::max({1.0, std::abs(an[k].qddot(i)), std::abs(res.poses[k].qdot(i))});
      worst_q = std::max(worst_q, std::abs(an[k].qddot(i) - fd) / size);
    }
  BOOST_TEST_MESSAGE("paper example: angular accelerations vs central differences, worst relative error " << worst
                     << "; pair variables' second derivatives vs differences of the rates " << worst_q);
  BOOST_TEST(worst < 1e-6);
  BOOST_TEST(worst_q < 1e-6);
}

/// Third derivative of the roller follower's height s = e sin t + f, f = sqrt(w), w = (R + r)^2 - e^2 cos^2 t:
/// from f^2 = w, 2 f f' = w', f'' = (w'' - 2 f'^2) / (2 f), f''' = (w''' - 6 f' f'') / (2 f).
double roller_follower_jerk(double R, double e, double r, double t) {
  const double w = (R + r) * (R + r) - e * e * std::cos(t) * std::cos(t);
  const double w1 = e * e * std::sin(2 * t), w2 = 2 * e * e * std::cos(2 * t), w3 = -4 * e * e * std::sin(2 * t);
  const double f = std::sqrt(w), f1 = w1 / (2 * f), f2 = (w2 - 2 * f1 * f1) / (2 * f);
  return -e * std::cos(t) + (w3 - 6 * f1 * f2) / (2 * f);
}

BOOST_AUTO_TEST_CASE(follower_jerk_matches_the_closed_forms_of_the_eccentric_cam) {
  const double R = 3, e = 1, r = 1;
  for (const bool roller : {true, false}) {
    const auto f = eccentric_cam<double>(R, e, roller, r);
    const auto res = assemble_and_sweep(f, degrees<double>(-180, 180, 5));
    BOOST_TEST_REQUIRE(res.all_solved());
    const auto an = analyse_sweep(f.mech, res);
    const int s = f.mech.find_variable("guide.s");
    BOOST_TEST_REQUIRE(s >= 0);
    double worst = 0;
    for (std::size_t k = 0; k < res.poses.size(); ++k) {
      const double t = res.poses[k].input;
      const double expected = roller ? roller_follower_jerk(R, e, r, t) : -e * std::cos(t);
      worst = std::max(worst, std::abs(an[k].qdddot(s) - expected));
      // The follower translates: no angular jerk; the cam turns at a constant rate: none either.
      BOOST_TEST(std::abs(an[k].angular_jerk[f.mech.find_link("follower")]) < 1e-9);
      BOOST_TEST(std::abs(an[k].angular_jerk[f.mech.find_link("cam")]) < 1e-9);
    }
    BOOST_TEST_MESSAGE((roller ? "roller" : "flat-faced") << " follower: worst error of s''' against the closed form "
                                                          << worst << " (e = " << e << ") over " << res.poses.size() << " poses");
    BOOST_TEST(worst < 1e-9 * e);
  }
}

BOOST_AUTO_TEST_CASE(jerks_match_differences_of_the_analytic_accelerations) {
  const double h = 1e-4;
  const PaperWithNeighbours p(h);
  const auto& [f, inputs, res, an] = p;
  double worst = 0, worst_q = 0;
  for (std::size_t k = 1; k < inputs.size(); k += 3) {
    for (std::size_t l = 0; l < f.mech.links.size(); ++l) {
      const double fd = (an[k + 1].angular_acceleration[l] - an[k - 1].angular_acceleration[l]) / (2 * h);
      const double size = std::max({1.0, std::abs(an[k].angular_jerk[l]), std::abs(an[k].angular_acceleration[l])});
      worst = std::max(worst, std::abs(an[k].angular_jerk[l] - fd) / size);
    }
    for (int i = 0; i < f.mech.variable_count(); ++i) {
      const double fd = (an[k + 1].qddot(i) - an[k - 1].qddot(i)) / (2 * h);
      const double size = std::max({1.0, std::abs(an[k].qdddot(i)), std::abs(an[k].qddot(i))});
      worst_q = std::max(worst_q, std::abs(an[k].qdddot(i) - fd) / size);
    }
  }
  BOOST_TEST_MESSAGE("paper example: angular jerks vs central differences of the accelerations, worst relative error "
                     << worst << "; pair variables' third derivatives " << worst_q);
  BOOST_TEST(worst < 1e-6);
  BOOST_TEST(worst_q < 1e-6);
}

BOOST_AUTO_TEST_CASE(mpfr_analysis_agrees_with_double) {
  using M = mpfr50;
  const auto fd = paper_fourbar<double>();
  const Fixture<M> fm{fd.mech.cast<M>(), fd.guess.cast<M>(), fd.held};
  const double input = 37 * kDeg;
  const auto rd = assemble_and_sweep(fd, {input});
  SolveData<M> sd(fm.mech);
  VectorX<M> q;
  const auto assembly = assemble_fixture(fm, q, sd);
  BOOST_TEST_REQUIRE(assembly.ok());
  const auto rm = sweep(fm.mech, sd, q, assembly, 0, std::vector<M>{M(input)});
  BOOST_TEST_REQUIRE(rd.all_solved());
  BOOST_TEST_REQUIRE(rm.all_solved());
  AnalysisData<double> dd(fd.mech);
  AnalysisData<M> dm(fm.mech);
  const auto ad = analyse_pose(fd.mech, rd.poses[0].q, rd.poses[0].qdot, dd);
  const auto am = analyse_pose(fm.mech, rm.poses[0].q, rm.poses[0].qdot, dm);
  double worst = 0;
  auto compare = [&](double d, const M& m, double scale) { worst = std::max(worst, std::abs(d - to_double(m)) / scale); };
  for (std::size_t i = 0; i < ad.contacts.size(); ++i) {
    const auto& c = ad.contacts[i];
    const auto& cm = am.contacts[i];
    compare(c.pressure_angle, cm.pressure_angle, 1);
    compare(c.sliding, cm.sliding, 1);
    compare(c.rolling_speed, cm.rolling_speed, std::abs(c.rolling_speed));
    compare(c.kappa1, cm.kappa1, std::abs(c.kappa1));
    compare(c.kappa2, cm.kappa2, std::abs(c.kappa2));
    compare(c.relative_curvature, cm.relative_curvature, std::abs(c.relative_curvature));
  }
  for (std::size_t l = 0; l < ad.angular_acceleration.size(); ++l)
    compare(ad.angular_acceleration[l], am.angular_acceleration[l], std::max(1.0, std::abs(ad.angular_acceleration[l])));
  BOOST_TEST_MESSAGE("paper example at 37 deg: double vs MPFR50 analysis, worst relative difference " << worst);
  BOOST_TEST(worst < 1e-12);
  // The jerk's differences in MPFR take h = eps^(1/5) ~ 1e-10 (truncation ~ 1e-40): the double jerk's own
  // error (truncation and round-off) is measured against it.
  double worst_jerk = 0;
  for (std::size_t l = 0; l < ad.angular_jerk.size(); ++l)
    worst_jerk = std::max(worst_jerk, std::abs(ad.angular_jerk[l] - to_double(am.angular_jerk[l])) /
                                          std::max(1.0, std::abs(ad.angular_jerk[l])));
  for (int i = 0; i < fd.mech.variable_count(); ++i)
    worst_jerk = std::max(worst_jerk, std::abs(ad.qdddot(i) - to_double(am.qdddot(i))) / std::max(1.0, std::abs(ad.qdddot(i))));
  BOOST_TEST_MESSAGE("paper example at 37 deg: double vs MPFR50 jerks, worst relative difference " << worst_jerk);
  BOOST_TEST(worst_jerk < 1e-9);
  // MPFR is not merely double in disguise: its sliding at the rolling pairs is zero to its own precision.
  for (const auto& cm : am.contacts) BOOST_TEST(abs(cm.sliding) < M("1e-40"));
}
