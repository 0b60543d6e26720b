// Contour::representation_error: the interpolation error estimate of a sampled contour against the true
// distance of the spline from the curve it samples, and its use as the consistency tolerance of redundant
// constraints (twin elliptical gears from coarse samples assemble and sweep with default settings).
#define BOOST_TEST_MODULE profile_representation
#include <boost/test/unit_test.hpp>

#include "rollkin/samples/mechanisms.hpp"
#include "rollkin/solve/continuation.hpp"
#include "rollkin/builder.hpp"

using namespace rollkin;
using namespace rollkin::testing;

namespace {

std::vector<Vec2<double>> ellipse_samples(double a, double b, double cx, int n) {
  std::vector<Vec2<double>> pts;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * pi<double>() * k / n;
    pts.emplace_back(cx + a * std::cos(t), b * std::sin(t));
  }
  return pts;
}

/// Largest distance from the spline to the ellipse, measured through the ellipse's implicit equation
/// (first order: |x^2/a^2 + y^2/b^2 - 1| / |gradient|), on a fine grid of the spline's parameter.
double true_error(const Contour<double>& c, double a, double b) {
  const Domain<double> d = c.domain();
  double worst = 0;
  for (int k = 0; k < 20000; ++k) {
    const Vec2<double> p = c.jet(d.lo + d.period() * k / 20000, 0).p;
    const double f = p.x() * p.x() / (a * a) + p.y() * p.y() / (b * b) - 1;
    const double g = 2 * std::hypot(p.x() / (a * a), p.y() / (b * b));
    worst = std::max(worst, std::abs(f) / g);
  }
  return worst;
}

}  // namespace

BOOST_AUTO_TEST_CASE(estimate_tracks_the_true_interpolation_error) {
  const double a = 2, b = 1.2;
  BOOST_TEST(Contour<double>("c", 0, Ellipse<double>(a, b), SE2<double>(), false).representation_error() == 0.0);
  for (int n : {16, 32, 64, 128}) {
    SplineOptions<double> closed;
    closed.closed = true;
    const Contour<double> c("c", 0, SampledProfile<double>(ellipse_samples(a, b, 0, n), closed), SE2<double>(), false);
    const double est = c.representation_error(), truth = true_error(c, a, b);
    BOOST_TEST_MESSAGE("n " << n << ": estimate " << est << ", true " << truth);
    BOOST_TEST(est > truth / 4);  // same order of magnitude, not an underestimate by much
    BOOST_TEST(est < truth * 8);
  }
}

BOOST_AUTO_TEST_CASE(coarse_sampled_gears_are_consistent_within_their_sampling_error) {
  const double a = 2, e = 0.5, b = a * std::sqrt(1 - e * e), c = a * e;
  SplineOptions<double> closed;
  closed.closed = true;
  MechanismBuilder<double> mb;
  const int ground = mb.link("ground", true), g1 = mb.link("gear1"), g2 = mb.link("gear2");
  // Samples of the ellipse with its pivot focus at the origin (centre at (-c, 0)).
  const int e1 = mb.contour(g1, "pitch", SampledProfile<double>(ellipse_samples(a, b, -c, 32), closed));
  const int e2 = mb.contour(g2, "pitch", SampledProfile<double>(ellipse_samples(a, b, -c, 32), closed));
  const int drive = mb.revolute("pivot1", ground, g1);
  mb.contact("mesh", true, e1, e2);
  mb.revolute("pivot2", ground, g2, SE2<double>(0, Vec2<double>(2 * a, 0)));
  mb.driver(drive);
  const auto m = mb.build();
  SolveData<double> sd(m);
  BOOST_TEST(sd.settings.consistency_tolerance > 1e-8);  // raised from sqrt(eps) by the sampling error
  // Contact at the samples of the nearest (u = 0) and farthest vertex (u = half the perimeter).
  VectorX<double> q(4);
  q << 0, 0, m.contours[1].domain().period() / 2, 0;
  const auto rep = assemble(m, q, sd);
  BOOST_TEST_REQUIRE(rep.ok());
  const auto res = sweep(m, sd, q, rep, 0, degrees<double>(-170, 170, 10));
  BOOST_TEST(res.all_solved());
  for (const auto& p : res.poses) {
    const double expected = -2 * std::atan((1 - e) / (1 + e) * std::tan(p.input / 2));
    BOOST_TEST(std::abs(wrap_angle(p.q(3) - expected)) < 1e-3);  // coarse: 32 samples
  }
}
