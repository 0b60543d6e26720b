// Pair matrices: the spatial twists lambda_j = (dP/dq_j) P^-1 and their time derivatives against central
// finite differences, and the rolling-contact rate relation of docs/method.md section 5.
#define BOOST_TEST_MODULE pair
#include <boost/test/unit_test.hpp>

#include "rollkin/pair/pair.hpp"

using namespace rollkin;

namespace {

/// (P(q + h e_j) - P(q - h e_j)) / 2h * P(q)^-1 as a twist (omega from the (1,0) entry, v from column 2).
Twist<double> fd_twist(const Pair<double>& p, const std::vector<Contour<double>>& cs, std::array<double, 2> q, int j,
                       double h = 1e-6) {
  auto at = [&](double dq) {
    auto qq = q;
    qq[j] += dq;
    return evaluate_pair(p, cs, qq.data(), nullptr, 2).transform.matrix();
  };
  const Eigen::Matrix3d d = (at(h) - at(-h)) / (2 * h);
  const Eigen::Matrix3d lam = d * evaluate_pair(p, cs, q.data(), nullptr, 2).transform.inverse().matrix();
  return Twist<double>(lam(0, 2), lam(1, 2), lam(1, 0));
}

std::vector<Contour<double>> two_contours() {
  return {Contour<double>("a", 0, Parabola<double>(0.5, -2, 2), SE2<double>(0.4, Vec2<double>(2, 0.3)), false),
          Contour<double>("b", 1, Ellipse<double>(1.5, 0.9), SE2<double>(-0.2, Vec2<double>(0.1, 0.2)), true)};
}

Pair<double> contact_pair(bool rolling) {
  Pair<double> p;
  p.kind = rolling ? PairKind::Rolling : PairKind::Cam;
  p.link_a = 0;
  p.link_b = 1;
  p.contour_a = 0;
  p.contour_b = 1;
  return p;
}

}  // namespace

BOOST_AUTO_TEST_CASE(revolute_and_prismatic_twists) {
  Pair<double> rev;
  rev.kind = PairKind::Revolute;
  rev.frame_a = SE2<double>(0.3, Vec2<double>(1, 2));
  rev.frame_b = SE2<double>(-0.5, Vec2<double>(0.4, -1));
  Pair<double> pri = rev;
  pri.kind = PairKind::Prismatic;
  const std::vector<Contour<double>> none;
  for (const auto& p : {rev, pri}) {
    const std::array<double, 2> q{0.7, 0};
    const auto st = evaluate_pair(p, none, q.data(), nullptr, 2);
    BOOST_TEST((st.twist[0] - fd_twist(p, none, q, 0)).norm() < 1e-8);
  }
}

BOOST_AUTO_TEST_CASE(contact_pair_matrix_puts_contours_tangent_with_opposite_normals) {
  const auto cs = two_contours();
  const std::array<double, 2> q{0.6, 2.1};
  const auto st = evaluate_pair(contact_pair(false), cs, q.data(), nullptr, 2);
  // Link B's frame placed by P: contour B's point coincides with contour A's, normals opposite (eq. 1).
  const ContourPoint<double> a = contour_point(cs[0].jet(q[0], 1), 1), b = contour_point(cs[1].jet(q[1], 1), 1);
  BOOST_TEST((st.transform.act(b.p) - a.p).norm() < 1e-14);
  BOOST_TEST((st.transform.rotate(b.outward_normal()) + a.outward_normal()).norm() < 1e-14);
}

BOOST_AUTO_TEST_CASE(contact_twists_match_finite_differences) {
  const auto cs = two_contours();
  for (auto q : {std::array<double, 2>{0.6, 2.1}, {-1.4, -0.3}, {0.0, 4.0}}) {
    const auto st = evaluate_pair(contact_pair(true), cs, q.data(), nullptr, 2);
    BOOST_TEST((st.twist[0] - fd_twist(contact_pair(true), cs, q, 0)).norm() < 1e-8);
    BOOST_TEST((st.twist[1] - fd_twist(contact_pair(true), cs, q, 1)).norm() < 1e-8);
  }
}

BOOST_AUTO_TEST_CASE(twist_rates_match_finite_differences) {
  const auto cs = two_contours();
  const std::array<double, 2> q{0.6, 2.1}, qdot{0.8, -1.3};
  const auto st = evaluate_pair(contact_pair(true), cs, q.data(), qdot.data(), 3);
  const double h = 1e-6;
  std::array<double, 2> qp{q[0] + h * qdot[0], q[1] + h * qdot[1]}, qm{q[0] - h * qdot[0], q[1] - h * qdot[1]};
  const auto sp = evaluate_pair(contact_pair(true), cs, qp.data(), nullptr, 2);
  const auto sm = evaluate_pair(contact_pair(true), cs, qm.data(), nullptr, 2);
  for (int j = 0; j < 2; ++j) BOOST_TEST(((sp.twist[j] - sm.twist[j]) / (2 * h) - st.twist_rate[j]).norm() < 1e-7);
}

BOOST_AUTO_TEST_CASE(rolling_relative_motion_is_rotation_about_contact_at_curvature_sum_rate) {
  // docs/method.md section 5: relative angular velocity = contact speed x (kappa_A + kappa_B), no slip velocity.
  const auto cs = two_contours();
  const std::array<double, 2> q{0.6, 2.1};
  const auto st = evaluate_pair(contact_pair(true), cs, q.data(), nullptr, 2);
  const auto& a = st.contact[0];
  const auto& b = st.contact[1];
  const double sdot = 0.9, udot = sdot / a.speed, vdot = -sdot / b.speed;  // equal and opposite arc lengths (eq. 3)
  const Twist<double> rel = st.twist[0] * udot + st.twist[1] * vdot;
  BOOST_TEST(rel.z() == sdot * (a.curvature() + b.curvature()), boost::test_tools::tolerance(1e-13));
  // Velocity of the contact point under the relative twist is zero.
  const Vec2<double> v = Vec2<double>(rel.x(), rel.y()) + rel.z() * perp(a.p);
  BOOST_TEST(v.norm() < 1e-13);
}
