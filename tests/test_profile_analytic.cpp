// Analytic profiles (line, circle, parabola, ellipse) and the Contour wrapper: jets against central finite
// differences, arc length against closed forms and against fine quadrature, inverse round trips, curvature
// against textbook formulas, material-side reversal and placement.
#define BOOST_TEST_MODULE profile_analytic
#include <boost/test/unit_test.hpp>

#include "rollkin/profile/profile.hpp"

#include <boost/math/special_functions/ellint_2.hpp>

using namespace rollkin;

namespace {

/// Max deviation between the jet's derivative of order k+1 and a central difference of order k.
template <class P> double jet_fd_error(const P& prof, double u, double h = 1e-5) {
  const Jet<double> j = prof.jet(u, 3), jp = prof.jet(u + h, 3), jm = prof.jet(u - h, 3);
  double err = ((jp.p - jm.p) / (2 * h) - j.d1).norm();
  err = std::max(err, ((jp.d1 - jm.d1) / (2 * h) - j.d2).norm());
  err = std::max(err, ((jp.d2 - jm.d2) / (2 * h) - j.d3).norm());
  return err;
}

template <class P> double curvature_at(const P& prof, double u) {
  return contour_point(prof.jet(u, 3), 3).curvature();
}

const QuadratureRule fine{Quadrature::GaussLegendre, 20, 64};

}  // namespace

BOOST_AUTO_TEST_CASE(jets_match_finite_differences) {
  const Line<double> line(-1, 3);
  const Circle<double> circle(1.7);
  const Parabola<double> parabola(0.5, -2, 2);
  const Ellipse<double> ellipse(2, 1.2);
  for (double u : {-1.3, -0.2, 0.0, 0.4, 1.9}) {
    BOOST_TEST(jet_fd_error(line, u) < 1e-9);
    BOOST_TEST(jet_fd_error(circle, u) < 1e-9);
    BOOST_TEST(jet_fd_error(parabola, u) < 1e-9);
    BOOST_TEST(jet_fd_error(ellipse, u) < 1e-9);
  }
}

BOOST_AUTO_TEST_CASE(curvatures_match_closed_forms) {
  const double a = 0.5;
  const Parabola<double> parabola(a, -2, 2);
  for (double x : {-2.0, -0.7, 0.0, 1.1, 2.0})
    BOOST_TEST(curvature_at(parabola, x) == 2 * a / std::pow(1 + 4 * a * a * x * x, 1.5), boost::test_tools::tolerance(1e-14));
  const double A = 2, B = 1.2;
  const Ellipse<double> ellipse(A, B);
  for (double t : {0.0, 0.5, 1.6, 3.0, 5.5}) {
    const double s = std::sin(t), c = std::cos(t);
    BOOST_TEST(curvature_at(ellipse, t) == A * B / std::pow(A * A * s * s + B * B * c * c, 1.5), boost::test_tools::tolerance(1e-14));
  }
  BOOST_TEST(curvature_at(Circle<double>(2.5), 0.3) == 0.4, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(curvature_at(Line<double>(0, 1), 0.3) == 0.0);
}

BOOST_AUTO_TEST_CASE(parabola_arc_length_closed_form_and_quadrature) {
  const double a = 0.5;
  const Parabola<double> closed(a, -2, 2);
  // docs/method.md section 5: s(x) = x/2 sqrt(1 + 4a^2x^2) + asinh(2ax)/(4a); from 0 to 2 with a = 1/2:
  const double expected = std::sqrt(5.0) + std::asinh(2.0) / 2;
  BOOST_TEST(closed.arc_length(0, 2) == expected, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(closed.arc_length(2, -2) == -2 * expected, boost::test_tools::tolerance(1e-15));
  const Parabola<double> gauss(a, -2, 2, ArcLengthMethod{false, fine});
  BOOST_TEST(gauss.arc_length(-1.3, 1.7) == closed.arc_length(-1.3, 1.7), boost::test_tools::tolerance(1e-14));
  const Parabola<double> simpson(a, -2, 2, ArcLengthMethod{false, QuadratureRule{Quadrature::NewtonCotes, 2, 2000}});
  BOOST_TEST(simpson.arc_length(-1.3, 1.7) == closed.arc_length(-1.3, 1.7), boost::test_tools::tolerance(1e-11));
}

BOOST_AUTO_TEST_CASE(newton_cotes_and_gauss_converge_at_their_orders) {
  const Parabola<double> exact(0.5, -2, 2);
  const double truth = exact.arc_length(-1.3, 1.7);
  auto error = [&](Quadrature kind, int order, int panels) {
    const Parabola<double> p(0.5, -2, 2, ArcLengthMethod{false, QuadratureRule{kind, order, panels}});
    return std::abs(p.arc_length(-1.3, 1.7) - truth);
  };
  // Simpson: error ~ h^4, so doubling the panels divides it by ~16.
  const double s1 = error(Quadrature::NewtonCotes, 2, 20), s2 = error(Quadrature::NewtonCotes, 2, 40);
  BOOST_TEST(std::log2(s1 / s2) > 3.8);
  BOOST_TEST(std::log2(s1 / s2) < 4.2);
  // Boole: ~ h^6.
  const double b1 = error(Quadrature::NewtonCotes, 4, 10), b2 = error(Quadrature::NewtonCotes, 4, 20);
  BOOST_TEST(std::log2(b1 / b2) > 5.6);
  // Gauss-Legendre, 2n points reach round-off on this smooth integrand quickly.
  BOOST_TEST(error(Quadrature::GaussLegendre, 16, 4) < 1e-14);
}

BOOST_AUTO_TEST_CASE(ellipse_arc_length_against_quadrature_and_perimeter) {
  for (auto axes : {std::pair{2.0, 1.2}, std::pair{0.8, 3.0}}) {
    const Ellipse<double> e(axes.first, axes.second);
    const Ellipse<double> q(axes.first, axes.second, ArcLengthMethod{false, fine});
    for (auto [t0, t1] : {std::pair{0.0, 1.0}, {-2.0, 4.5}, {1.0, 13.0}, {5.0, -7.0}})
      BOOST_TEST(e.arc_length(t0, t1) == q.arc_length(t0, t1), boost::test_tools::tolerance(1e-13));
    // Whole perimeter 4 a E(k) with a the larger semi-axis.
    const double big = std::max(axes.first, axes.second), small = std::min(axes.first, axes.second);
    const double perimeter = 4 * big * boost::math::ellint_2(std::sqrt(1 - small * small / (big * big)));
    BOOST_TEST(e.arc_length(0.3, 0.3 + 2 * pi<double>()) == perimeter, boost::test_tools::tolerance(1e-14));
  }
}

BOOST_AUTO_TEST_CASE(inverse_arc_length_round_trips) {
  const Parabola<double> parabola(0.5, -2, 2);
  const Ellipse<double> ellipse(2, 1.2);
  const Circle<double> circle(1.5);
  for (double u0 : {-1.5, 0.0, 0.8})
    for (double ds : {-2.0, -0.01, 0.0, 0.3, 3.0}) {
      // Round-off bound: a few ulps of the arc-length primitive at u0 and at the result.
      const double bound = 1e-14 * (1 + std::abs(u0) + std::abs(ds));
      BOOST_TEST(std::abs(parabola.arc_length(u0, parabola.param_at_arc_length(u0, ds)) - ds) < bound);
      BOOST_TEST(std::abs(ellipse.arc_length(u0, ellipse.param_at_arc_length(u0, ds)) - ds) < bound);
      BOOST_TEST(std::abs(circle.arc_length(u0, circle.param_at_arc_length(u0, ds)) - ds) < bound);
    }
  // Small steps keep their absolute accuracy (no bracket or tolerance floor above round-off).
  BOOST_TEST(std::abs(parabola.arc_length(0.2, parabola.param_at_arc_length(0.2, 1e-9)) - 1e-9) < 2e-17);
}

BOOST_AUTO_TEST_CASE(contour_reversal_keeps_material_on_the_left) {
  // A ring: circle with the material outside. Reversed, it runs clockwise and its curvature is -1/r.
  const double r = 2;
  const Contour<double> disk("disk", 0, Circle<double>(r), SE2<double>(), false);
  const Contour<double> ring("ring", 0, Circle<double>(r), SE2<double>(), true);
  BOOST_TEST(contour_point(disk.jet(0.4, 3), 3).curvature() == 1 / r, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(contour_point(ring.jet(0.4, 3), 3).curvature() == -1 / r, boost::test_tools::tolerance(1e-15));
  // Outward normal of the disk points away from the centre, of the ring toward it.
  const Jet<double> jd = disk.jet(0.4, 1), jr = ring.jet(-0.4, 1);
  BOOST_TEST((jd.p - jr.p).norm() < 1e-15);
  BOOST_TEST(contour_point(jd, 1).outward_normal().dot(jd.p) > 0);
  BOOST_TEST(contour_point(jr, 1).outward_normal().dot(jr.p) < 0);
  // Arc length runs with the parameter in both directions.
  BOOST_TEST(ring.arc_length(-0.4, 0.6) == r, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(ring.param_at_arc_length(-0.4, r) == 0.6, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(jet_fd_error(ring, 0.7) < 1e-9);
  // Domain of the reversed parabola is mirrored.
  const Contour<double> flipped("p", 0, Parabola<double>(0.5, -1, 2), SE2<double>(), true);
  BOOST_TEST(flipped.domain().lo == -2.0);
  BOOST_TEST(flipped.domain().hi == 1.0);
}

BOOST_AUTO_TEST_CASE(contour_placement_moves_jet_rigidly) {
  const SE2<double> place(0.7, Vec2<double>(1.5, -0.5));
  const Contour<double> c("e", 0, Ellipse<double>(2, 1), place, false);
  const Ellipse<double> e(2, 1);
  for (double t : {0.0, 1.0, 2.5}) {
    const Jet<double> jc = c.jet(t, 3), je = e.jet(t, 3);
    BOOST_TEST((jc.p - place.act(je.p)).norm() < 1e-15);
    BOOST_TEST((jc.d2 - place.rotate(je.d2)).norm() < 1e-15);
    BOOST_TEST(contour_point(jc, 3).curvature() == contour_point(je, 3).curvature(), boost::test_tools::tolerance(1e-14));
  }
  BOOST_TEST(jet_fd_error(c, 1.2) < 1e-9);
}

BOOST_AUTO_TEST_CASE(contour_point_rates_match_finite_differences) {
  // speed_rate = d sigma/du and turn_accel = d(kappa sigma)/du, used by the acceleration terms.
  const Contour<double> c("p", 0, Parabola<double>(0.7, -2, 2), SE2<double>(0.3, Vec2<double>(1, 2)), true);
  const double h = 1e-5;
  for (double u : {-1.2, 0.1, 1.4}) {
    const auto p = contour_point(c.jet(u, 3), 3);
    const auto pp = contour_point(c.jet(u + h, 3), 3), pm = contour_point(c.jet(u - h, 3), 3);
    BOOST_TEST(std::abs((pp.speed - pm.speed) / (2 * h) - p.speed_rate) < 1e-9);
    BOOST_TEST(std::abs((pp.turn_rate - pm.turn_rate) / (2 * h) - p.turn_accel) < 1e-9);
  }
}
