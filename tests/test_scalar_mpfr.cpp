// MPFR (50 digits) as a rollkin scalar: SE(2) algebra against closed forms, Gauss-Legendre and Newton-Cotes
// quadrature against exact integrals, and Eigen's dense decompositions solving to working precision.
#define BOOST_TEST_MODULE scalar_mpfr
#include <boost/test/unit_test.hpp>

#include "rollkin/profile/quadrature.hpp"
#include "rollkin/scalar_mpfr.hpp"
#include "rollkin/se2.hpp"

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

using rollkin::mpfr50;
using S = mpfr50;
using V2 = rollkin::Vec2<S>;
using M3 = Eigen::Matrix<S, 3, 3>;

namespace {

// Exact decimal inputs (not rounded through double) so the tests exercise all 50 digits.
S dec(const char* s) { return S(std::string(s)); }

const S tol45 = S(std::string("1e-45"));
const S tol40 = S(std::string("1e-40"));

S max_abs_diff(const M3& a, const M3& b) { return (a - b).cwiseAbs().maxCoeff(); }

M3 closed_form(const S& angle, const S& x, const S& y) {
  using std::cos;
  using std::sin;
  M3 m;
  m << cos(angle), -sin(angle), x, sin(angle), cos(angle), y, S(0), S(0), S(1);
  return m;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(traits)

BOOST_AUTO_TEST_CASE(precision_and_numtraits) {
  BOOST_TEST(std::numeric_limits<S>::digits10 >= 50);
  BOOST_TEST(rollkin::epsilon<S>() < S(std::string("1e-49")));
  // Boost 1.74's generic NumTraits::lowest() is +min(); ours must be the most negative value.
  BOOST_TEST(Eigen::NumTraits<S>::lowest() < S(0));
  BOOST_TEST(Eigen::NumTraits<S>::highest() > S(1e300));
  BOOST_TEST(Eigen::NumTraits<S>::epsilon() == rollkin::epsilon<S>());
  // Other digit counts through the template alias.
  using S30 = rollkin::mpfr_scalar<30>;
  BOOST_TEST(std::numeric_limits<S30>::digits10 >= 30);
  BOOST_TEST(std::numeric_limits<S30>::digits10 < 50);
  // pi to 50 digits.
  const S pi_ref = dec("3.14159265358979323846264338327950288419716939937510582097494");
  BOOST_TEST(abs(rollkin::pi<S>() - pi_ref) < tol45);
}

BOOST_AUTO_TEST_CASE(aligned_box_uses_lowest) {
  Eigen::AlignedBox<S, 2> box;  // setEmpty(): min = highest, max = lowest
  box.extend(V2(S(-3), S(-2)));
  box.extend(V2(S(-1), S(-5)));
  BOOST_TEST(box.max().x() == S(-1));
  BOOST_TEST(box.max().y() == S(-2));
  BOOST_TEST(box.min().y() == S(-5));
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(se2_mpfr)

BOOST_AUTO_TEST_CASE(composition_inverse_closed_form) {
  using std::cos;
  using std::sin;
  const S a = dec("0.7234567890123456789012345678901234567890123456789");
  const S b = dec("-2.3456789012345678901234567890123456789012345678901");
  const V2 ta(dec("1.25"), dec("-0.3333333333333333333333333333333333333333333333333"));
  const V2 tb(dec("-4.1"), dec("2.7182818284590452353602874713526624977572470937"));
  const rollkin::SE2<S> ga(a, ta), gb(b, tb);

  // Composition: R(a) R(b) = R(a + b), t = R(a) tb + ta.
  const S x = cos(a) * tb.x() - sin(a) * tb.y() + ta.x();
  const S y = sin(a) * tb.x() + cos(a) * tb.y() + ta.y();
  BOOST_TEST(max_abs_diff((ga * gb).matrix(), closed_form(a + b, x, y)) < tol45);
  BOOST_TEST(abs(rollkin::wrap_angle(S((ga * gb).angle() - (a + b)))) < tol45);

  // Inverse: R(-a), -R(a)^T ta.
  const S xi = -(cos(a) * ta.x() + sin(a) * ta.y());
  const S yi = sin(a) * ta.x() - cos(a) * ta.y();
  BOOST_TEST(max_abs_diff(ga.inverse().matrix(), closed_form(-a, xi, yi)) < tol45);
  BOOST_TEST(max_abs_diff((ga * ga.inverse()).matrix(), M3::Identity()) < tol45);
  BOOST_TEST(max_abs_diff((gb.inverse() * gb).matrix(), M3::Identity()) < tol45);

  // Act on a point.
  const V2 p(dec("0.1"), dec("0.2"));
  const V2 q = ga.act(p);
  BOOST_TEST(abs(q.x() - (cos(a) * p.x() - sin(a) * p.y() + ta.x())) < tol45);
  BOOST_TEST(abs(q.y() - (sin(a) * p.x() + cos(a) * p.y() + ta.y())) < tol45);
}

BOOST_AUTO_TEST_CASE(adjoint_closed_form) {
  using std::cos;
  using std::sin;
  const S a = dec("1.1111111111111111111111111111111111111111111111111");
  const V2 t(dec("0.5"), dec("-1.75"));
  const rollkin::SE2<S> g(a, t);
  const rollkin::Twist<S> xi(dec("0.3"), dec("-0.6"), dec("1.9"));
  // Ad_g xi = (R v - omega J t, omega),  J t = (-t_y, t_x).
  const rollkin::Twist<S> expect(cos(a) * xi.x() - sin(a) * xi.y() + xi.z() * t.y(),
                                 sin(a) * xi.x() + cos(a) * xi.y() - xi.z() * t.x(), xi.z());
  BOOST_TEST((g.adjoint(xi) - expect).cwiseAbs().maxCoeff() < tol45);
  // Matrix form: (Ad_g xi)^ = G xi^ G^-1.
  M3 hat = M3::Zero();
  hat(0, 1) = -xi.z();
  hat(1, 0) = xi.z();
  hat(0, 2) = xi.x();
  hat(1, 2) = xi.y();
  const M3 conj = g.matrix() * hat * g.inverse().matrix();
  const rollkin::Twist<S> ad = g.adjoint(xi);
  BOOST_TEST(abs(conj(0, 2) - ad.x()) < tol45);
  BOOST_TEST(abs(conj(1, 2) - ad.y()) < tol45);
  BOOST_TEST(abs(conj(1, 0) - ad.z()) < tol45);
}

BOOST_AUTO_TEST_CASE(cast_roundtrip) {
  const rollkin::SE2<double> gd(0.3, rollkin::Vec2<double>(1.0, 2.0));
  const rollkin::SE2<S> gm = gd.cast<S>();  // double -> MPFR is exact
  BOOST_TEST(gm.cos_angle() == S(gd.cos_angle()));
  const rollkin::SE2<double> back = gm.cast<double>();
  BOOST_TEST(back.translation().y() == 2.0);
  BOOST_TEST(rollkin::to_double(gm.sin_angle()) == gd.sin_angle());
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(quadrature_mpfr)

BOOST_AUTO_TEST_CASE(gauss_legendre_exact_for_degree_2n_minus_1) {
  using std::pow;
  // integral over [a, b] of sum_k c_k x^k with c_k = (k + 1) / 7, exact by antiderivative.
  const S a = dec("-0.4"), b = dec("1.3");
  for (int n : {1, 2, 3, 5, 8, 12, 20}) {
    const int deg = 2 * n - 1;
    auto poly = [deg](const S& x) {
      S sum(0), xk(1);
      for (int k = 0; k <= deg; ++k, xk *= x) sum += S(k + 1) / S(7) * xk;
      return sum;
    };
    S exact(0);
    for (int k = 0; k <= deg; ++k) exact += S(k + 1) / S(7) * (pow(b, k + 1) - pow(a, k + 1)) / S(k + 1);
    const rollkin::QuadratureRule rule{rollkin::Quadrature::GaussLegendre, n, 1};
    const S got = rollkin::integrate<S>(poly, a, b, rule);
    BOOST_TEST_CONTEXT("n = " << n) { BOOST_TEST(abs(got - exact) < tol45 * (S(1) + abs(exact))); }
    // Nodes symmetric, weights sum to 2.
    const auto& g = rollkin::gauss_legendre<S>(n);
    S wsum(0);
    for (std::size_t i = 0; i < g.w.size(); ++i) {
      wsum += g.w[i];
      BOOST_TEST(abs(g.x[i] + g.x[g.x.size() - 1 - i]) < tol45);
    }
    BOOST_TEST(abs(wsum - S(2)) < tol45);
  }
}

BOOST_AUTO_TEST_CASE(parabola_arc_length_closed_form) {
  using std::asinh;
  using std::sqrt;
  // integral_0^1 sqrt(1 + 4 x^2) dx = sqrt(5)/2 + asinh(2)/4  (docs/method.md section 5, a = 1).
  const S exact = sqrt(S(5)) / S(2) + asinh(S(2)) / S(4);
  auto f = [](const S& x) { return sqrt(S(1) + S(4) * x * x); };
  const rollkin::QuadratureRule rule{rollkin::Quadrature::GaussLegendre, 20, 8};
  const S got = rollkin::integrate<S>(f, S(0), S(1), rule);
  BOOST_TEST(abs(got - exact) < tol40);
  // Reversed limits negate.
  BOOST_TEST(abs(rollkin::integrate<S>(f, S(1), S(0), rule) + exact) < tol40);
}

BOOST_AUTO_TEST_CASE(newton_cotes_exact) {
  using std::pow;
  const S a = dec("0.25"), b = dec("2.5");
  auto cubic = [](const S& x) { return S(3) * x * x * x - S(2) * x * x + x / S(3) - S(5); };
  auto anti = [](const S& x) {
    return S(3) / S(4) * pow(x, 4) - S(2) / S(3) * pow(x, 3) + x * x / S(6) - S(5) * x;
  };
  const S exact = anti(b) - anti(a);
  for (int panels : {1, 3}) {
    const rollkin::QuadratureRule simpson{rollkin::Quadrature::NewtonCotes, 2, panels};
    BOOST_TEST(abs(rollkin::integrate<S>(cubic, a, b, simpson) - exact) < tol45);
  }
  // Boole's rule: exact for quintics.
  auto quintic = [](const S& x) { return pow(x, 5) - x; };
  const S exact5 = (pow(b, 6) - pow(a, 6)) / S(6) - (b * b - a * a) / S(2);
  const rollkin::QuadratureRule boole{rollkin::Quadrature::NewtonCotes, 4, 2};
  BOOST_TEST(abs(rollkin::integrate<S>(quintic, a, b, boole) - exact5) < tol45);
  // Simpson is not exact for a quartic (sanity check that the test can fail).
  auto quartic = [](const S& x) { return pow(x, 4); };
  const rollkin::QuadratureRule simpson1{rollkin::Quadrature::NewtonCotes, 2, 1};
  const S exact4 = (pow(b, 5) - pow(a, 5)) / S(5);
  BOOST_TEST(abs(rollkin::integrate<S>(quartic, a, b, simpson1) - exact4) > S(1e-3));
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(eigen_mpfr)

namespace {
using M5 = Eigen::Matrix<S, 5, 5>;
using V5 = Eigen::Matrix<S, 5, 1>;

// A well-conditioned, non-symmetric 5x5 matrix with a known solution.
void make_system(M5& A, V5& x, V5& b) {
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 5; ++j) A(i, j) = S(1) / S(i + 2 * j + 1) + (i == j ? S(3) : S(0)) + S(i - j) / S(11);
    x(i) = S(i + 1) / S(3) - S(1) / S(7);
  }
  b = A * x;
}
}  // namespace

BOOST_AUTO_TEST_CASE(col_piv_householder_qr) {
  M5 A;
  V5 x, b;
  make_system(A, x, b);
  const Eigen::ColPivHouseholderQR<M5> qr(A);
  BOOST_TEST(qr.rank() == 5);
  const V5 sol = qr.solve(b);
  BOOST_TEST((sol - x).cwiseAbs().maxCoeff() < tol45);
  BOOST_TEST((A * sol - b).cwiseAbs().maxCoeff() < tol45);
}

BOOST_AUTO_TEST_CASE(partial_piv_lu) {
  M5 A;
  V5 x, b;
  make_system(A, x, b);
  const Eigen::PartialPivLU<M5> lu(A);
  BOOST_TEST((lu.solve(b) - x).cwiseAbs().maxCoeff() < tol45);
  BOOST_TEST(abs(lu.determinant() - A.transpose().partialPivLu().determinant()) < tol45 * abs(lu.determinant()));
}

BOOST_AUTO_TEST_CASE(complete_orthogonal_decomposition_rank_deficient) {
  // 3x4, rank 2: minimum-norm solution of a consistent system equals the pseudo-inverse solution.
  Eigen::Matrix<S, 3, 4> A;
  A << S(1), S(2), S(3), S(4), S(2), S(1), S(0), S(-1), S(3), S(3), S(3), S(3);  // row3 = row1 + row2
  const Eigen::Matrix<S, 4, 1> x0(S(1), S(-1), S(2), S(1) / S(3));
  const Eigen::Matrix<S, 3, 1> b = A * x0;
  const Eigen::CompleteOrthogonalDecomposition<Eigen::Matrix<S, 3, 4>> cod(A);
  BOOST_TEST(cod.rank() == 2);
  const Eigen::Matrix<S, 4, 1> x = cod.solve(b);
  BOOST_TEST((A * x - b).cwiseAbs().maxCoeff() < tol45);
  // Minimum norm: x is orthogonal to the null space of A.
  const Eigen::Matrix<S, 4, 4> P = cod.pseudoInverse() * A;  // projector onto the row space
  BOOST_TEST(((P * x) - x).cwiseAbs().maxCoeff() < tol45);
}

BOOST_AUTO_TEST_CASE(jacobi_svd) {
  M5 A;
  V5 x, b;
  make_system(A, x, b);
  const Eigen::JacobiSVD<M5> svd(A, Eigen::ComputeFullU | Eigen::ComputeFullV);
  BOOST_TEST(svd.rank() == 5);
  BOOST_TEST((svd.solve(b) - x).cwiseAbs().maxCoeff() < tol45);
  const M5 recon = svd.matrixU() * svd.singularValues().asDiagonal() * svd.matrixV().transpose();
  BOOST_TEST((recon - A).cwiseAbs().maxCoeff() < tol45);
  // Singular values of a diagonal matrix are its absolute entries, sorted.
  Eigen::Matrix<S, 3, 3> D = Eigen::Matrix<S, 3, 3>::Zero();
  D(0, 0) = S(-2);
  D(1, 1) = S(1) / S(3);
  D(2, 2) = S(5);
  const Eigen::JacobiSVD<Eigen::Matrix<S, 3, 3>> svd3(D);
  BOOST_TEST(abs(svd3.singularValues()(0) - S(5)) < tol45);
  BOOST_TEST(abs(svd3.singularValues()(2) - S(1) / S(3)) < tol45);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_CASE(double_sin_cos_against_mpfr) {
  // The double sin_cos (inline reduction and series up to 1e5 rad, libm beyond) against 50-digit sin and
  // cos of the same double: at most 2 ulp of 1 absolute, and sin x == x for tiny x. Points: random over
  // several ranges, and the neighbours of multiples of pi/4 and pi/2 where the reduction cancels most.
  std::mt19937_64 rng(4242u);
  std::vector<double> xs = {0.0, -0.0, 1e-300, -1e-20, 1e-8, 0x1.921fb54442d18p+0, 0x1.921fb54442d18p+1, 99999.0,
                            1e5, -1e5, 1e5 + 1, 3e7, -1e12};
  for (double range : {1.0, 10.0, 1e3, 1e5, 2e5}) {
    std::uniform_real_distribution<double> u(-range, range);
    for (int i = 0; i < 20000; ++i) xs.push_back(u(rng));
  }
  for (int k = -4000; k <= 4000; k += 7)
    for (double q : {0.25, 0.5}) {
      const double x = k * q * 3.14159265358979323846;
      xs.insert(xs.end(), {x, std::nextafter(x, 1e300), std::nextafter(x, -1e300)});
    }
  double worst = 0;
  for (double x : xs) {
    double s = 0, c = 0;
    rollkin::sin_cos(x, s, c);
    const S xm(x);
    const double es = std::abs(s - static_cast<double>(sin(xm))), ec = std::abs(c - static_cast<double>(cos(xm)));
    worst = std::max({worst, es, ec});
    BOOST_TEST_CONTEXT("x = " << std::hexfloat << x) {
      BOOST_TEST(es <= 2 * std::numeric_limits<double>::epsilon());
      BOOST_TEST(ec <= 2 * std::numeric_limits<double>::epsilon());
    }
  }
  BOOST_TEST_MESSAGE("double sin_cos vs mpfr50: largest error " << worst << " on " << xs.size() << " points");
  double s = 0, c = 0;
  rollkin::sin_cos(1e-20, s, c);
  BOOST_TEST(s == 1e-20);
  BOOST_TEST(c == 1.0);
}
