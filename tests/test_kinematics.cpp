// Constraint equations (eq. 6 loops, eq. 3 rolling rows): analytic Jacobian against central finite
// differences of the residual, the acceleration bias against the directional derivative of J qdot, the
// loops found from the graph, and link poses from the spanning tree (link_poses_near against a fresh
// evaluation, over the example scenes: every pair kind).
#define BOOST_TEST_MODULE kinematics
#include <boost/test/unit_test.hpp>

#include "test_support.hpp"

#include "rollkin/io/scene/reader.hpp"
#include "rollkin/samples/mechanisms.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

using namespace rollkin;
using namespace rollkin::testing;

namespace {

VectorX<double> residual_at(const Mechanism<double>& m, KinematicsData<double>& d, const VectorX<double>& q) {
  evaluate_pairs<double>(m, q, nullptr, 2, d);
  compute_constraints(m, q, d);
  return d.residual;
}

double pose_difference(const std::vector<SE2<double>>& a, const std::vector<SE2<double>>& b, double length) {
  return link_pose_difference(a.data(), b.data(), a.size(), length);
}

/// The largest difference of the angles summed down the tree from the angles of the rotations (atan2), and
/// whether every summed angle lies in [-pi, pi], next to a half turn on atan2's side.
double angle_difference(const std::vector<double>& summed, const std::vector<SE2<double>>& b, bool& in_range) {
  double worst = 0;
  in_range = true;
  for (std::size_t i = 0; i < b.size(); ++i) {
    worst = std::max(worst, angle_gap(summed[i], b[i].angle()));
    in_range = in_range && summed[i] >= -pi<double>() && summed[i] <= pi<double>() &&
               (std::abs(summed[i]) < 3 || std::signbit(summed[i]) == std::signbit(b[i].angle()));  // atan2's side
  }
  return worst;
}

bool bitwise_equal(const std::vector<SE2<double>>& a, const std::vector<SE2<double>>& b) {
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].cos_angle() != b[i].cos_angle() || a[i].sin_angle() != b[i].sin_angle() || a[i].translation() != b[i].translation())
      return false;
  return true;
}

}  // namespace

BOOST_AUTO_TEST_CASE(paper_loop_is_found_from_the_graph) {
  const auto f = paper_fourbar<double>();
  BOOST_TEST(f.mech.loops.size() == 1u);
  BOOST_TEST(f.mech.loops[0].size() == 4u);  // O_A, A, B, O_B
  BOOST_TEST(f.mech.equation_count() == 5);  // 3 loop rows + 2 rolling rows (eqs. 6, 7a, 7b)
  BOOST_TEST(f.mech.unknowns.size() == 5u);
}

BOOST_AUTO_TEST_CASE(jacobian_matches_finite_differences_away_from_closure) {
  for (const auto& f : {paper_fourbar<double>(), elliptical_gears<double>(2, 0.5, true), planet_on_arm<double>(4, 1, false)}) {
    KinematicsData<double> d(f.mech);
    d.reference = f.guess;
    VectorX<double> q = f.guess;
    for (int i = 0; i < q.size(); ++i) q(i) += 0.05 * std::sin(3.0 * i + 1);  // not closed: T != I
    residual_at(f.mech, d, q);
    const MatrixX<double> jac = d.jacobian;
    const double h = 1e-6;
    for (int j = 0; j < q.size(); ++j) {
      VectorX<double> qp = q, qm = q;
      qp(j) += h;
      qm(j) -= h;
      const VectorX<double> fd = (residual_at(f.mech, d, qp) - residual_at(f.mech, d, qm)) / (2 * h);
      BOOST_TEST((fd - jac.col(j)).cwiseAbs().maxCoeff() < 1e-8, "column " << j);
    }
  }
}

BOOST_AUTO_TEST_CASE(acceleration_bias_is_directional_derivative_of_j_qdot) {
  auto f = paper_fourbar<double>();
  SolveData<double> sd(f.mech);
  VectorX<double> q;
  BOOST_TEST_REQUIRE(assemble_fixture(f, q, sd).ok());
  q(0) = 0.4;  // move the input and re-close
  BOOST_TEST_REQUIRE(solve_position(f.mech, q, sd).ok());
  VectorX<double> rate(1);
  rate << 1.0;
  const VectorX<double> qdot = solve_velocity(f.mech, sd, rate);
  evaluate_pairs<double>(f.mech, q, &qdot, 3, sd.kin);
  compute_bias(f.mech, qdot, sd.kin);
  const VectorX<double> gamma = sd.kin.bias;
  const double h = 1e-6;
  KinematicsData<double> d(f.mech);
  d.reference = sd.kin.reference;
  residual_at(f.mech, d, q + h * qdot);
  const VectorX<double> jp = d.jacobian * qdot;
  residual_at(f.mech, d, q - h * qdot);
  const VectorX<double> jm = d.jacobian * qdot;
  BOOST_TEST(((jp - jm) / (2 * h) - gamma).cwiseAbs().maxCoeff() < 1e-7);
}

BOOST_AUTO_TEST_CASE(link_poses_close_every_loop) {
  auto f = paper_fourbar<double>();
  SolveData<double> sd(f.mech);
  VectorX<double> q;
  BOOST_TEST_REQUIRE(assemble_fixture(f, q, sd).ok());
  const auto pose = link_poses(f.mech, sd.kin);
  // The chord O_B (ground -> link4) was not used by the tree; it must agree with link 4's tree pose.
  const SE2<double> via_chord = pose[0] * sd.kin.pairs[3].transform;
  BOOST_TEST((via_chord.translation() - pose[3].translation()).norm() < 1e-13);
  BOOST_TEST(std::abs(wrap_angle(via_chord.angle() - pose[3].angle())) < 1e-13);
  // Disk 3's centre is at (3, 0) at assembly (contact at the vertex, docs/method.md section 4).
  BOOST_TEST((pose[2].translation() - Vec2<double>(3, 0)).norm() < 1e-13);
  // Disk 4's centre: the upper point 5 from (3, 0) and 2 from O_B = (7, -2): about (7.99303, -0.26394).
  const Vec2<double> c4 = pose[3].act(Vec2<double>(2, 0));
  BOOST_TEST((c4 - Vec2<double>(3, 0)).norm() == 5.0, boost::test_tools::tolerance(1e-13));
  BOOST_TEST((c4 - Vec2<double>(7, -2)).norm() == 2.0, boost::test_tools::tolerance(1e-13));
  BOOST_TEST(c4.x() == 7.99303, boost::test_tools::tolerance(1e-6));
  BOOST_TEST(c4.y() == -0.26394, boost::test_tools::tolerance(1e-4));
}

BOOST_AUTO_TEST_CASE(rolling_rows_follow_a_changed_reference) {
  // The rolling rows keep each origin's arc-length primitive between evaluations; when the reference (the
  // arc-length origin, eq. 3) changes, the rows must follow it. Truth: the contours' own arc_length from the
  // reference, which integrates or differences the closed form per call.
  const auto f = paper_fourbar<double>();
  const Mechanism<double>& m = f.mech;
  KinematicsData<double> d(m);
  VectorX<double> q = f.guess;
  for (int i = 0; i < q.size(); ++i) q(i) += 0.1 * std::cos(2.0 * i + 0.5);
  for (double shift : {0.0, 0.3, -0.2, 0.0}) {
    d.reference = f.guess;
    for (int i = 0; i < d.reference.size(); ++i) d.reference(i) += shift * (i % 2 ? 1 : -1);
    residual_at(m, d, q);
    int row = 3 * static_cast<int>(m.loops.size());
    for (int k : m.rolling_pairs) {
      const Pair<double>& p = m.pairs[k];
      const int i = p.first_variable;
      const double expected = m.contours[p.contour_a].arc_length(d.reference(i), q(i)) +
                              m.contours[p.contour_b].arc_length(d.reference(i + 1), q(i + 1));
      BOOST_TEST(std::abs(d.residual(row) - expected) < 1e-14, "pair " << p.name << ", shift " << shift);
      ++row;
    }
  }
}

// link_poses_near (a sweep's kept link poses) against link_poses_at (the tree's pairs evaluated at q), on every
// example scene (revolute, prismatic, rolling and cam pairs; analytic, spline, Bezier and DXF contours), the
// pairs evaluated at the scene's guess q0: at q0 itself the same numbers; at q0 moved by 1e-12 of each
// variable's scale (a closing step's size) the first-order move agrees to round-off, where the transforms
// of q0 unmoved are 1e-12 off; at 1e-6 (beyond the first order's reach) each pair is evaluated afresh. The
// angles summed down the tree agree with the rotations' (atan2) to round-off, in [-pi, pi], also after
// several turns of every variable.
BOOST_AUTO_TEST_CASE(link_poses_near_an_evaluation_equal_a_fresh_evaluation_on_every_example) {
  int scenes = 0;
  for (const auto& file : std::filesystem::directory_iterator(std::string(ROLLKIN_SOURCE_DIR) + "/examples")) {
    if (file.path().extension() != ".json") continue;
    BOOST_TEST_CONTEXT(file.path().filename().string()) {
      const io::Scene s = io::load_scene(file.path().string());
      const Mechanism<double>& m = s.mechanism;
      SolveData<double> sd(m);
      const VectorX<double> q0 = s.guess;  // the tree's poses need no closed loop
      evaluate_pairs<double>(m, q0, nullptr, 1, sd.kin);
      const std::size_t links = m.links.size();
      std::vector<SE2<double>> near(links), fresh(links);
      std::vector<double> angle(links);
      bool in_range = false;
      const auto moved = [&](double by) {
        VectorX<double> q = q0;
        for (int i = 0; i < m.variable_count(); ++i) q(i) += (i % 2 ? -by : by) * m.variable_scale(i);
        return q;
      };
      link_poses_near(m, sd.kin, q0, near.data(), angle.data());
      link_poses_at(m, q0, fresh);
      BOOST_TEST(bitwise_equal(near, fresh));
      const double eps = std::numeric_limits<double>::epsilon();
      BOOST_TEST(angle_difference(angle, fresh, in_range) <= 16 * eps);
      BOOST_TEST(in_range);

      const VectorX<double> q1 = moved(1e-12);
      link_poses_near(m, sd.kin, q1, near.data());
      link_poses_at(m, q1, fresh);
      BOOST_TEST(pose_difference(near, fresh, m.length_scale) <= 16 * eps);
      BOOST_TEST(pose_difference(link_poses(m, sd.kin), fresh, m.length_scale) > 1e-13);  // not moved: off

      const VectorX<double> q2 = moved(1e-6);
      link_poses_near(m, sd.kin, q2, near.data());
      link_poses_at(m, q2, fresh);
      BOOST_TEST(bitwise_equal(near, fresh));

      VectorX<double> turned = q0;  // every angle variable 3.25 turns on
      for (int i = 0; i < m.variable_count(); ++i)
        if (m.variables[i].kind == ParamKind::Angle) turned(i) += 6.5 * pi<double>();
      evaluate_pairs<double>(m, turned, nullptr, 1, sd.kin);
      link_poses_near(m, sd.kin, turned, near.data(), angle.data());
      link_poses_at(m, turned, fresh);
      BOOST_TEST(angle_difference(angle, fresh, in_range) <= 64 * eps);
      BOOST_TEST(in_range);
      ++scenes;
    }
  }
  BOOST_TEST(scenes >= 8);
}
