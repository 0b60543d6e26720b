// SE(2) in double against the 3x3 homogeneous matrices: composition, inverse, adjoint, Lie bracket and the
// residual rate, on random inputs (fixed seed) and near-degenerate angles (+-pi, tiny, zero).
#define BOOST_TEST_MODULE se2
#include <boost/test/unit_test.hpp>

#include "rollkin/se2.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using rollkin::SE2;
using rollkin::Twist;
using M3 = Eigen::Matrix3d;
using V2 = Eigen::Vector2d;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTol = 1e-12;

M3 hat(const Twist<double>& xi) {
  M3 m = M3::Zero();
  m(0, 1) = -xi.z();
  m(1, 0) = xi.z();
  m(0, 2) = xi.x();
  m(1, 2) = xi.y();
  return m;
}

/// Inverse of hat for matrices of the form [w J v; 0 0] (checks the form too).
Twist<double> vee(const M3& m, double tol = kTol) {
  BOOST_TEST(std::abs(m(0, 0)) < tol);
  BOOST_TEST(std::abs(m(1, 1)) < tol);
  BOOST_TEST(std::abs(m(0, 1) + m(1, 0)) < tol);
  BOOST_TEST(m.row(2).cwiseAbs().maxCoeff() < tol);
  return Twist<double>(m(0, 2), m(1, 2), m(1, 0));
}

template <class A, class B> double maxdiff(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b) {
  return (a - b).cwiseAbs().maxCoeff();
}

/// Angles including the degenerate ones: +-pi and their neighbours, tiny, zero, large.
std::vector<double> test_angles() {
  std::vector<double> a = {0.0,  1e-300, -1e-300, 1e-16,   -1e-16,  1e-8,        -1e-8,
                           kPi,  -kPi,   std::nextafter(kPi, 0.0), std::nextafter(-kPi, 0.0),
                           kPi - 1e-9, -kPi + 1e-9, 0.5 * kPi, -0.5 * kPi, 7.0 * kPi, -100.25};
  std::mt19937 rng(20240517u);
  std::uniform_real_distribution<double> u(-4.0, 4.0);
  for (int i = 0; i < 40; ++i) a.push_back(u(rng));
  return a;
}

struct Sample {
  SE2<double> g;
  Twist<double> xi;
};

std::vector<Sample> samples() {
  std::vector<Sample> out;
  std::mt19937 rng(12345u);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (double a : test_angles()) {
    Sample s{SE2<double>(a, V2(u(rng), u(rng))), Twist<double>(u(rng), u(rng), u(rng))};
    out.push_back(s);
  }
  // Pure rotations, pure translations, the identity and a zero twist.
  out.push_back({SE2<double>::rotation(kPi), Twist<double>(0.0, 0.0, 1.0)});
  out.push_back({SE2<double>::translation(V2(1e-12, -5.0)), Twist<double>(2.0, -1.0, 0.0)});
  out.push_back({SE2<double>(), Twist<double>::Zero()});
  return out;
}

}  // namespace

BOOST_AUTO_TEST_CASE(matrix_is_rigid_and_angle_roundtrips) {
  for (double a : test_angles()) {
    const SE2<double> g(a, V2(0.3, -0.7));
    const M3 m = g.matrix();
    BOOST_TEST_CONTEXT("angle " << a) {
      const Eigen::Matrix2d R = m.topLeftCorner(2, 2);
      BOOST_TEST(maxdiff(R.transpose() * R, Eigen::Matrix2d::Identity()) < kTol);
      BOOST_TEST(std::abs(R.determinant() - 1.0) < kTol);
      BOOST_TEST(m(2, 0) == 0.0);
      BOOST_TEST(m(2, 2) == 1.0);
      // angle() is in [-pi, pi] and equals a modulo 2 pi.
      BOOST_TEST(std::abs(g.angle()) <= kPi);
      BOOST_TEST(std::abs(std::remainder(g.angle() - a, 2.0 * kPi)) < 1e-12 * std::max(1.0, std::abs(a)));
    }
  }
  // Tiny angles keep their full relative precision.
  BOOST_TEST(SE2<double>::rotation(1e-300).angle() == 1e-300);
  BOOST_TEST(SE2<double>::rotation(-1e-16).angle() == -1e-16);
}

BOOST_AUTO_TEST_CASE(small_angle_series_agrees_with_atan2) {
  // angle() switches from atan2 to a series for |tan| <= 0.011: both sides of the switch and the cut
  // itself agree with libm's atan2 to a few ulp (relative), and with the angle the rotation was built from.
  std::mt19937 rng(777u);
  std::uniform_real_distribution<double> u(-0.02, 0.02);
  std::vector<double> angles = {0.011, -0.011, std::atan(0.011), std::nextafter(std::atan(0.011), 1.0), 1e-3, -3e-7};
  for (int i = 0; i < 2000; ++i) angles.push_back(u(rng));
  double worst = 0;
  for (double a : angles) {
    const SE2<double> g(a, V2(0.0, 0.0));
    const double reference = std::atan2(g.sin_angle(), g.cos_angle());
    worst = std::max(worst, std::abs(g.angle() - reference) / std::abs(reference));
    BOOST_TEST(std::abs(g.angle() - a) <= 4e-16 * std::abs(a));
  }
  BOOST_TEST(worst <= 4e-16);
}

BOOST_AUTO_TEST_CASE(composition_matches_matrix_product) {
  const auto s = samples();
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto& a = s[i].g;
    const auto& b = s[(i * 7 + 3) % s.size()].g;
    const auto& c = s[(i * 13 + 5) % s.size()].g;
    BOOST_TEST_CONTEXT("sample " << i) {
      BOOST_TEST(maxdiff((a * b).matrix(), a.matrix() * b.matrix()) < kTol);
      // Associativity and identity.
      BOOST_TEST(maxdiff(((a * b) * c).matrix(), (a * (b * c)).matrix()) < 1e-11);
      BOOST_TEST(maxdiff((a * SE2<double>()).matrix(), a.matrix()) == 0.0);
      // act = matrix on homogeneous point; rotate ignores translation.
      const V2 p(0.25, -1.5);
      const Eigen::Vector3d hp = a.matrix() * Eigen::Vector3d(p.x(), p.y(), 1.0);
      const Eigen::Matrix2d R = a.matrix().topLeftCorner(2, 2);
      BOOST_TEST(maxdiff(a.act(p), hp.head(2)) < kTol);
      BOOST_TEST(maxdiff(a.rotate(p), R * p) < kTol);
    }
  }
}

BOOST_AUTO_TEST_CASE(inverse_matches_matrix_inverse) {
  for (const auto& smp : samples()) {
    const auto& g = smp.g;
    BOOST_TEST(maxdiff(g.inverse().matrix(), g.matrix().inverse()) < kTol);
    BOOST_TEST(maxdiff((g * g.inverse()).matrix(), M3::Identity()) < kTol);
    BOOST_TEST(maxdiff((g.inverse() * g).matrix(), M3::Identity()) < kTol);
    BOOST_TEST(maxdiff(g.inverse().inverse().matrix(), g.matrix()) < kTol);
  }
}

BOOST_AUTO_TEST_CASE(adjoint_matches_conjugation) {
  for (const auto& smp : samples()) {
    const auto& g = smp.g;
    const M3 conj = g.matrix() * hat(smp.xi) * g.matrix().inverse();
    BOOST_TEST(maxdiff(g.adjoint(smp.xi), vee(conj, 1e-11)) < 1e-11);
    // Ad is a homomorphism: Ad_{gh} = Ad_g Ad_h, and Ad_{g^-1} = Ad_g^-1.
    const SE2<double> h(0.9, V2(-0.4, 2.2));
    BOOST_TEST(maxdiff((g * h).adjoint(smp.xi), g.adjoint(h.adjoint(smp.xi))) < 1e-11);
    BOOST_TEST(maxdiff(g.inverse().adjoint(g.adjoint(smp.xi)), smp.xi) < 1e-11);
  }
}

BOOST_AUTO_TEST_CASE(lie_bracket_matches_commutator) {
  const auto s = samples();
  for (std::size_t i = 0; i < s.size(); ++i) {
    const Twist<double>& a = s[i].xi;
    const Twist<double>& b = s[(i * 5 + 1) % s.size()].xi;
    const M3 comm = hat(a) * hat(b) - hat(b) * hat(a);
    BOOST_TEST(maxdiff(rollkin::lie_bracket(a, b), vee(comm)) < 1e-12);
    // Antisymmetry; [a, a] = 0.
    BOOST_TEST(maxdiff(rollkin::lie_bracket(a, b), -rollkin::lie_bracket(b, a)) == 0.0);
    BOOST_TEST(rollkin::lie_bracket(a, a).cwiseAbs().maxCoeff() == 0.0);
    // Bracket and adjoint commute: Ad_g [a, b] = [Ad_g a, Ad_g b].
    const auto& g = s[i].g;
    BOOST_TEST(maxdiff(g.adjoint(rollkin::lie_bracket(a, b)), rollkin::lie_bracket(g.adjoint(a), g.adjoint(b))) <
               1e-10);
  }
}

namespace {
/// A transform moving along a smooth path: T(t) = exp-free closed form with angle and translation polynomials.
SE2<double> moving(double t, double a0) {
  const double angle = a0 + 1.3 * t - 0.4 * t * t;
  return SE2<double>(angle, V2(0.5 + 2.0 * t + t * t * t, -1.0 + std::sin(t)));
}
/// Its spatial twist V with V^ = Tdot T^-1: omega = angle', v = pdot - omega J p.
Twist<double> moving_twist(double t, double a0) {
  const SE2<double> T = moving(t, a0);
  const double omega = 1.3 - 0.8 * t;
  const V2 pdot(2.0 + 3.0 * t * t, std::cos(t));
  const V2 p = T.translation();
  return Twist<double>(pdot.x() + omega * p.y(), pdot.y() - omega * p.x(), omega);
}
}  // namespace

BOOST_AUTO_TEST_CASE(residual_rate_matches_finite_differences) {
  const double h = 1e-5;
  for (double a0 : test_angles()) {
    for (double t : {-0.7, 0.0, 0.3, 1.1}) {
      const SE2<double> T = moving(t, a0);
      const Twist<double> V = moving_twist(t, a0);
      // The twist is the spatial one: Tdot T^-1 = V^ (central differences of the matrix).
      const M3 Tdot = (moving(t + h, a0).matrix() - moving(t - h, a0).matrix()) / (2.0 * h);
      BOOST_TEST(maxdiff(vee(Tdot * T.matrix().inverse(), 1e-8), V) < 1e-8);
      // residual (x, y, angle): central differences, angle unwrapped.
      const SE2<double> Tp = moving(t + h, a0), Tm = moving(t - h, a0);
      const double dangle = std::remainder(Tp.angle() - Tm.angle(), 2.0 * kPi) / (2.0 * h);
      const Eigen::Vector3d fd((Tp.translation().x() - Tm.translation().x()) / (2.0 * h),
                               (Tp.translation().y() - Tm.translation().y()) / (2.0 * h), dangle);
      BOOST_TEST_CONTEXT("a0 " << a0 << " t " << t) {
        BOOST_TEST(maxdiff(rollkin::residual_rate(T, V), fd) < 1e-8);
      }
    }
  }
}
