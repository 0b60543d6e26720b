// Centrodes (include/rollkin/analysis/centrodes.hpp) and the link velocities they come from (kinematics.hpp,
// link_twists), against independent truth:
//  - link twists: the velocity of every link's origin and its angular rate against central differences of
//    the link poses along the paper example's sweep;
//  - the anti-parallelogram (frame 4, coupler 4, cranks 2): the relative centrodes of its two cranks are
//    congruent ellipses with foci at each crank's two joints and major axis 4 (sum of focal distances);
//  - round trip: the two centrodes, sampled at every half degree and rolled on each other as a rolling pair
//    of spline contours between the same two pivots, reproduce the four-bar's output angle over a full turn
//    (through both change points at 90 and 270 deg) to 1e-6 deg;
//  - the same round trip for a crank-rocker (frame 4, crank 1, coupler 4, rocker 3), whose centrodes have no
//    closed form: rolled back, the rocker's angle over a full turn of the crank to 1e-6 deg;
//  - a pure relative translation (the parallel links of a parallelogram) has its centre at infinity.
#define BOOST_TEST_MODULE centrodes
#include <boost/test/unit_test.hpp>

#include "rollkin/samples/mechanisms.hpp"
#include "rollkin/builder.hpp"

#include "rollkin/analysis/centrodes.hpp"

#include <cmath>

using namespace rollkin;
using namespace rollkin::testing;

namespace {

const double kDeg = M_PI / 180;

/// Inputs from `from` to `to` degrees in steps of `step` degrees (exact multiples of the step).
std::vector<double> inputs_deg(double from, double to, double step) {
  std::vector<double> v;
  const int n = static_cast<int>(std::lround((to - from) / step));
  for (int k = 0; k <= n; ++k) v.push_back((from + k * step) * kDeg);
  return v;
}

/// The parallelogram (frame 4, cranks 2, coupler 4 between the crank pins): its coupler keeps its
/// orientation, a pure translation relative to the frame. Assembled at theta2 = 0.3 rad.
Fixture<double> parallelogram() {
  Fixture<double> f = four_bar<double>(Vec2<double>(2, 0), Vec2<double>(4, 0), Vec2<double>(2, 0), 4, "rocker");
  f.guess << 0.3, -0.3, 0.3, 0.3;
  return f;
}

}  // namespace

BOOST_AUTO_TEST_CASE(link_twists_match_central_differences_of_the_link_poses) {
  const Fixture<double> f = paper_fourbar<double>();
  const SweepResult<double> r = assemble_and_sweep(f, inputs_deg(-40, 90, 10));
  BOOST_REQUIRE(r.all_solved());
  KinematicsData<double> d(f.mech);
  const double h = 1e-5;
  double worst = 0;
  for (const SweepPose<double>& p : r.poses) {
    evaluate_pairs<double>(f.mech, p.q, nullptr, 1, d);
    const std::vector<SE2<double>> pose = link_poses(f.mech, d);
    const std::vector<Twist<double>> twist = link_twists<double>(f.mech, d, pose, p.qdot);
    // Poses at q +- h qdot: first order along the motion, so the central difference is O(h^2) accurate.
    std::vector<SE2<double>> ahead, behind;
    for (double sign : {1.0, -1.0}) {
      evaluate_pairs(f.mech, VectorX<double>(p.q + sign * h * p.qdot), nullptr, 1, d);
      (sign > 0 ? ahead : behind) = link_poses(f.mech, d);
    }
    for (std::size_t i = 0; i < pose.size(); ++i) {
      const Vec2<double> o = pose[i].translation();
      const Vec2<double> v_origin = Vec2<double>(twist[i].x(), twist[i].y()) + twist[i].z() * Vec2<double>(-o.y(), o.x());
      const Vec2<double> fd = (ahead[i].translation() - behind[i].translation()) / (2 * h);
      const double omega_fd = std::remainder(ahead[i].angle() - behind[i].angle(), 2 * M_PI) / (2 * h);
      worst = std::max({worst, (v_origin - fd).norm(), std::abs(twist[i].z() - omega_fd)});
    }
  }
  BOOST_TEST_MESSAGE("link twists vs central differences: worst " << worst);
  BOOST_TEST(worst < 1e-8);
}

/// Round trip: the centrodes of the links "crank" and "follower" of a four-bar with pivots O2 = (0, 0) and
/// O4 = (4, 0), one point per input of `linkage` (closed curves: the last input repeats the first point),
/// rolled on each other as a rolling pair of spline contours between the same pivots. Returns the worst
/// difference of the follower's angle (variable 3) from the linkage's, in radians.
double rolled_back_error(const Fixture<double>& f, const SweepResult<double>& linkage, const std::vector<double>& inputs) {
  const int crank = f.mech.find_link("crank"), follower = f.mech.find_link("follower");
  KinematicsData<double> d(f.mech);
  const std::vector<InstantCentre<double>> c = centrodes(f.mech, d, linkage, crank, follower);
  std::vector<Vec2<double>> on_crank, on_follower;
  for (std::size_t k = 0; k + 1 < c.size(); ++k) {
    BOOST_REQUIRE_MESSAGE(c[k].finite, "centre at pose " << k);
    on_crank.push_back(c[k].in_a);
    on_follower.push_back(c[k].in_b);
  }
  MechanismBuilder<double> b;
  const int frame = b.link("frame", true), g1 = b.link("crank"), g2 = b.link("follower");
  SplineOptions<double> closed;
  closed.closed = true;
  // The crank's body on the side of its pivot (its frame's origin) at the first contact, as a gear around its
  // shaft: the profile runs reversed when the pivot lies right of the sample order there. Rolling, the contact
  // point moves along both centrodes in the same world direction, so their sample orders agree there and
  // exactly one of the two profiles runs reversed (eq. 1: opposite tangents at the contact).
  const bool crank_reversed = cross2(Vec2<double>(on_crank[1] - on_crank[0]), Vec2<double>(-on_crank[0])) < 0;
  const int c1 = b.contour(g1, "centrode", SampledProfile<double>(on_crank, closed), SE2<double>(), crank_reversed);
  const int c2 = b.contour(g2, "centrode", SampledProfile<double>(on_follower, closed), SE2<double>(), !crank_reversed);
  const int drive = b.revolute("O2", frame, g1, SE2<double>(), SE2<double>(), "theta2");
  b.contact("roll", true, c1, c2, "u", "v");
  b.revolute("O4", frame, g2, SE2<double>(0, Vec2<double>(4, 0)), SE2<double>(), "theta4");
  b.driver(drive);
  Fixture<double> g{b.build(), VectorX<double>(4), {1}};  // u held: the contact starts at the first samples
  g.guess << inputs.front(), 0, 0, linkage.poses.front().q(3);
  const SweepResult<double> rolled = assemble_and_sweep(g, inputs);
  BOOST_TEST_MESSAGE("rolled assembly " << to_string(rolled.assembly.status) << " " << rolled.assembly.detail);
  BOOST_REQUIRE(rolled.all_solved());
  double angle = 0;
  for (std::size_t k = 0; k < inputs.size(); ++k)
    angle = std::max(angle, std::abs(std::remainder(rolled.poses[k].q(3) - linkage.poses[k].q(3), 2 * M_PI)));
  return angle;
}

/// Crank-rocker: frame 4 (O2 = (0, 0), O4 = (4, 0)), crank 1 (pin A at (0, 1) in its frame), coupler 4
/// (pin B at (4, 0) in its frame), rocker 3 (B at (3, 0) in its frame), open branch. The coupler's angle stays
/// between 29 and 60 deg over a turn, so the coupler line always meets the frame line: the centre of the
/// rocker's motion relative to the crank is finite. Variables as antiparallelogram(): theta2, theta3, theta_b,
/// theta4. Assembled at theta2 = 0 (B at (3.489, 2.956)).
Fixture<double> crank_rocker() {
  Fixture<double> f = four_bar<double>(Vec2<double>(0, 1), Vec2<double>(4, 0), Vec2<double>(3, 0), 4);
  f.guess << 0, 29.28 * kDeg, 70.53 * kDeg, 99.81 * kDeg;
  return f;
}

BOOST_AUTO_TEST_CASE(crank_rocker_centrodes_without_closed_form_roll_back_into_the_linkage) {
  const Fixture<double> f = crank_rocker();
  const std::vector<double> inputs = inputs_deg(0, 360, 0.5);
  const SweepResult<double> r = assemble_and_sweep(f, inputs);
  BOOST_REQUIRE(r.all_solved());
  const double angle = rolled_back_error(f, r, inputs);
  BOOST_TEST_MESSAGE("crank-rocker: rolled centrodes vs four-bar, worst output angle difference " << angle / kDeg << " deg");
  BOOST_TEST(angle < 1e-6 * kDeg);
}

BOOST_AUTO_TEST_CASE(antiparallelogram_crank_centrodes_are_ellipses_and_roll_back_into_the_linkage) {
  const Fixture<double> f = antiparallelogram<double>();
  const std::vector<double> inputs = inputs_deg(0, 360, 0.5);
  const SweepResult<double> r = assemble_and_sweep(f, inputs);
  const int crank = f.mech.find_link("crank"), follower = f.mech.find_link("follower");
  KinematicsData<double> d(f.mech);
  const std::vector<InstantCentre<double>> c = centrodes(f.mech, d, r, crank, follower);
  // Foci: the crank's joints O2 (0, 0) and A (0, 2) in its frame; the follower's O4 (0, 0) and B (2, 0).
  // At the change points (90 and 270 deg, status singular) the rates are those of the cubic Hermite
  // interpolant between the regular poses on both sides (solve/continuation.hpp), O(h^3) accurate.
  double worst = 0, worst_singular = 0;
  for (std::size_t k = 0; k < c.size(); ++k) {
    BOOST_REQUIRE_MESSAGE(r.poses[k].report.has_pose() && c[k].finite, "pose " << k);
    const double e = std::max(std::abs(c[k].in_a.norm() + (c[k].in_a - Vec2<double>(0, 2)).norm() - 4),
                              std::abs(c[k].in_b.norm() + (c[k].in_b - Vec2<double>(2, 0)).norm() - 4));
    (r.poses[k].report.ok() ? worst : worst_singular) = std::max(r.poses[k].report.ok() ? worst : worst_singular, e);
  }
  BOOST_TEST_MESSAGE("anti-parallelogram centrodes: worst |PF1 + PF2 - 4| = " << worst << " (regular poses), "
                                                                           << worst_singular << " (change points)");
  BOOST_TEST(worst < 1e-10);  // 2e-11 next to the change points, where the Jacobian is ill-conditioned
  BOOST_TEST(worst_singular < 1e-8);

  // Round trip: the sampled centrodes as a rolling pair between the four-bar's pivots.
  const double angle = rolled_back_error(f, r, inputs);
  BOOST_TEST_MESSAGE("rolled centrodes vs four-bar: worst output angle difference " << angle / kDeg << " deg");
  BOOST_TEST(angle < 1e-6 * kDeg);
}

BOOST_AUTO_TEST_CASE(a_pure_relative_translation_has_its_centre_at_infinity) {
  const Fixture<double> f = parallelogram();
  const SweepResult<double> r = assemble_and_sweep(f, inputs_deg(10, 50, 20));
  BOOST_REQUIRE(r.all_solved());
  KinematicsData<double> d(f.mech);
  const int frame = f.mech.find_link("frame"), coupler = f.mech.find_link("coupler"), crank = f.mech.find_link("crank");
  for (std::size_t k = 0; k < r.poses.size(); ++k) {
    const InstantCentre<double> ic = centrodes(f.mech, d, r, frame, coupler)[k];
    BOOST_TEST(!ic.finite);
    // The coupler translates on a circle of radius 2: its velocity is normal to the crank, (-sin, cos).
    const double t = r.poses[k].input;
    BOOST_TEST(std::abs(std::abs(ic.direction.dot(Vec2<double>(-std::sin(t), std::cos(t)))) - 1) < 1e-12);
    // The crank relative to the frame turns about O2.
    const InstantCentre<double> pivot = centrodes(f.mech, d, r, frame, crank)[k];
    BOOST_TEST(pivot.finite);
    BOOST_TEST(pivot.world.norm() < 1e-14);
  }
}
