// Singular poses met by the continuation (docs/reliability.md, "Numbers": every pose carries a status): a scene with
// nothing to solve, a bifurcation where two branches meet (crossed four-bar), and a cam pair stepped exactly through
// a singular pose. Every value is checked against a closed form derived here from the geometry, not from the solver.
#define BOOST_TEST_MODULE solve_singular
#include <boost/test/unit_test.hpp>

#include "rollkin/samples/mechanisms.hpp"

#include <array>
#include <cmath>

using namespace rollkin;
using namespace rollkin::testing;

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180;

std::vector<double> grid_degrees(double from, double to, double step) {
  std::vector<double> v;
  const int n = static_cast<int>(std::floor((to - from) / step + 1e-9));
  for (int k = 0; k <= n; ++k) v.push_back((from + step * k) * kDeg);
  return v;
}

/// Both solutions theta4 of the anti-parallelogram at crank angle theta2, from the intersection of the circle
/// of radius 4 (coupler) about the crank pin A = 2 (cos(theta2 + 90), sin(theta2 + 90)) with the circle of
/// radius 2 (follower) about O4 = (4, 0): theta4 is the direction of the follower's pin B - O4.
std::array<double, 2> fourbar_theta4(double theta2) {
  const double ax = 2 * std::cos(theta2 + 90 * kDeg), ay = 2 * std::sin(theta2 + 90 * kDeg);
  const double dx = 4 - ax, dy = -ay, d = std::hypot(dx, dy);  // from A to O4
  const double r_a = 4, r_o = 2;
  const double along = (r_a * r_a - r_o * r_o + d * d) / (2 * d);  // from A toward O4
  const double across = std::sqrt(std::max(0.0, r_a * r_a - along * along));
  const double px = ax + along * dx / d, py = ay + along * dy / d;
  std::array<double, 2> out;
  for (int s = 0; s < 2; ++s) {
    const double sign = s == 0 ? 1 : -1;
    const double bx = px - sign * across * dy / d, by = py + sign * across * dx / d;
    out[s] = std::atan2(by, bx - 4);
  }
  return out;
}

/// The crossed branch: of the two solutions, the one that is not the parallelogram's. Opposite sides equal
/// and parallel: the follower then points where the crank's pin does, theta4 = theta2 + 90 deg.
struct Branches {
  double crossed, parallelogram;
};
Branches fourbar_branches(double theta2) {
  const auto both = fourbar_theta4(theta2);
  const double parallel = theta2 + 90 * kDeg;
  const bool first_is_parallel = std::abs(wrap_angle(both[0] - parallel)) < std::abs(wrap_angle(both[1] - parallel));
  return {first_is_parallel ? both[1] : both[0], parallel};
}

/// Checks a sweep of the anti-parallelogram against the crossed branch; returns the singular rows.
int check_crossed_branch(const SweepResult<double>& res) {
  int singular = 0;
  for (const auto& p : res.poses) {
    const double theta2_deg = p.input / kDeg;
    BOOST_TEST_REQUIRE(p.report.has_pose(), "theta2 " << theta2_deg << ": " << p.report.status << " " << p.report.detail);
    const Branches b = fourbar_branches(p.input);
    const double error_deg = std::abs(wrap_angle(p.q(3) - b.crossed)) / kDeg;
    const double separation_deg = std::abs(wrap_angle(b.crossed - b.parallelogram)) / kDeg;
    if (p.report.status == SolveStatus::Singular) {
      ++singular;
      // Only where the branches meet; the values still follow the branch (interpolated between regular poses).
      BOOST_TEST(separation_deg < 1e-6, "singular at theta2 " << theta2_deg);
      BOOST_TEST(error_deg < 1e-6, "theta2 " << theta2_deg);
    } else {
      BOOST_TEST(p.report.ok(), "theta2 " << theta2_deg << ": " << p.report.status);
      BOOST_TEST(error_deg < 1e-9, "theta2 " << theta2_deg << " theta4 " << p.q(3) / kDeg << " crossed "
                                              << b.crossed / kDeg << " parallelogram " << b.parallelogram / kDeg);
    }
  }
  return singular;
}

}  // namespace

BOOST_AUTO_TEST_CASE(zero_unknowns_solve_as_forward_kinematics) {
  auto f = driven_open_chain<double>(3.0);
  SolveReport<double> rep;
  const auto res = assemble_and_sweep(f, grid_degrees(-90, 270, 30), &rep);
  BOOST_TEST(rep.ok());
  BOOST_TEST(rep.unknowns == 0);
  BOOST_TEST(rep.equations == 0);
  BOOST_TEST_REQUIRE(res.all_solved());
  KinematicsData<double> kin(f.mech);
  for (const auto& p : res.poses) {
    BOOST_TEST(p.report.residual == 0.0);
    BOOST_TEST(p.q(0) == p.input);
    evaluate_pairs<double>(f.mech, p.q, nullptr, 1, kin);
    const auto poses = link_poses(f.mech, kin);
    // The slider sits 2 x scale along the crank.
    BOOST_TEST((poses[2].translation() - 6.0 * Vec2<double>(std::cos(p.input), std::sin(p.input))).norm() < 1e-14);
  }
}

BOOST_AUTO_TEST_CASE(anti_parallelogram_keeps_the_crossed_branch_through_both_change_points) {
  auto f = antiparallelogram<double>();
  SolveReport<double> rep;
  const auto res = assemble_and_sweep(f, grid_degrees(0, 360, 1), &rep);
  BOOST_TEST_REQUIRE(rep.ok());
  BOOST_TEST(std::abs(f.guess(3) - fourbar_branches(0).crossed) < 1 * kDeg);  // assembled on the crossed branch
  const int singular = check_crossed_branch(res);
  BOOST_TEST(singular <= 2);  // at most the two change points, theta2 = 90 and 270
  BOOST_TEST(res.limits.empty());
}

BOOST_AUTO_TEST_CASE(anti_parallelogram_crossed_between_grid_values) {
  auto f = antiparallelogram<double>();
  const auto res = assemble_and_sweep(f, grid_degrees(0, 360, 0.7));
  BOOST_TEST(check_crossed_branch(res) == 0);  // no grid value on a change point: every row regular
  BOOST_TEST(res.all_solved());
}

BOOST_AUTO_TEST_CASE(anti_parallelogram_backward_through_the_change_point) {
  // Downward from the assembly input: through theta2 = -90 (= 270), landing on it exactly.
  auto f = antiparallelogram<double>();
  const auto res = assemble_and_sweep(f, grid_degrees(-180, 0, 1));
  BOOST_TEST(check_crossed_branch(res) <= 1);
}

BOOST_AUTO_TEST_CASE(cam_gears_stepped_exactly_through_the_singular_vertex_pose) {
  // Twin elliptical gears as a cam pair: at phi1 = 180 deg the contact normal passes through both pivots and
  // the cam Jacobian is singular. tan(phi2/2) = ((1 - e)/(1 + e)) tan(phi1/2) (method.md section 5).
  const double a = 2, e = 0.5;
  auto f = elliptical_gears<double>(a, e, false, {}, 40 * kDeg);
  const auto res = assemble_and_sweep(f, grid_degrees(40, 320, 5));
  int singular = 0;
  for (const auto& p : res.poses) {
    BOOST_TEST_REQUIRE(p.report.has_pose(), p.input / kDeg << ": " << p.report.status << " " << p.report.detail);
    const double expected = -2 * std::atan((1 - e) / (1 + e) * std::tan(p.input / 2));
    const double error_deg = std::abs(wrap_angle(p.q(3) - expected)) / kDeg;
    if (p.report.status == SolveStatus::Singular) {
      ++singular;
      BOOST_TEST(std::abs(p.input / kDeg - 180) < 1e-9);
      BOOST_TEST(error_deg < 1e-6);
    } else {
      BOOST_TEST(p.report.ok());
      BOOST_TEST(error_deg < 1e-9, "phi1 " << p.input / kDeg << " phi2 " << p.q(3) / kDeg << " expected " << expected / kDeg);
    }
  }
  BOOST_TEST(singular <= 1);
}

BOOST_AUTO_TEST_CASE(determinant_sign_follows_row_swaps_and_pivots) {
  // det [[0, 1], [1, 0]] = -1 (one swap), det [[2, 0], [0, -3]] = -6, det [[1, 2], [3, 4]] = -2.
  SmallLU<double> lu(2);
  Eigen::Matrix2d m;
  m << 0, 1, 1, 0;
  BOOST_TEST_REQUIRE(lu.compute(m));
  BOOST_TEST(lu.determinant_sign() == -1);
  m << 2, 0, 0, -3;
  BOOST_TEST_REQUIRE(lu.compute(m));
  BOOST_TEST(lu.determinant_sign() == -1);
  m << 1, 2, 3, 4;
  BOOST_TEST_REQUIRE(lu.compute(m));
  BOOST_TEST(lu.determinant_sign() == -1);
  m << 4, 3, 2, 1;  // det -2 with the pivot already on top
  BOOST_TEST_REQUIRE(lu.compute(m));
  BOOST_TEST(lu.determinant_sign() == -1);
  m << 3, 4, 1, 2;  // det 2
  BOOST_TEST_REQUIRE(lu.compute(m));
  BOOST_TEST(lu.determinant_sign() == 1);
}

BOOST_AUTO_TEST_CASE(redundant_mechanism_passes_a_change_point_landed_on_exactly) {
  // Two rolling disks (radii 1 and 1.5: phi_1 = -phi_0 / 1.5; the centre distance row is redundant, 7 equations
  // and 6 unknowns) whose second disk drives a parallelogram (rollkin/samples/mechanisms.hpp,
  // gear_train_with_parallelogram): on its branch the rocker turns with disk 1, theta = phi_1, and at
  // phi_1 = -90 deg (phi_0 = 135 deg, a grid value) the crossed branch meets it. A change point is no motion
  // limit: the sweep must go on past it on the same branch, as it does for the square anti-parallelogram.
  const auto f = gear_train_with_parallelogram<double>(1);
  SolveReport<double> rep;
  const auto res = assemble_and_sweep(f, grid_degrees(0, 360, 1), &rep);
  BOOST_TEST_REQUIRE(rep.ok());
  BOOST_TEST_REQUIRE(rep.redundant() == 1);
  BOOST_TEST(res.limits.empty(), (res.limits.empty() ? "" : res.limits[0].detail));
  const int rocker = f.mech.find_variable("O.theta");
  BOOST_TEST_REQUIRE(rocker >= 0);
  int singular = 0, off_branch = 0, missing = 0;
  for (const auto& p : res.poses) {
    if (!p.report.has_pose()) {
      ++missing;
      continue;
    }
    const double phi1 = -p.input / 1.5;
    const double error_deg =
        std::max(std::abs(wrap_angle(p.q(1) - phi1)), std::abs(wrap_angle(p.q(rocker) - phi1))) / kDeg;
    if (p.report.status == SolveStatus::Singular) {
      ++singular;
      if (std::abs(p.input / kDeg - 135) > 1e-9 || !(error_deg < 1e-6)) ++off_branch;
    } else if (!p.report.ok() || !(error_deg < 1e-9)) {
      ++off_branch;
    }
  }
  BOOST_TEST(missing == 0, missing << " of " << res.poses.size() << " poses not reached");
  BOOST_TEST(off_branch == 0);
  BOOST_TEST(singular <= 1);
}
