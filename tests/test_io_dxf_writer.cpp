// The DXF writer (io/dxf/writer.hpp) against the DXF reader (io/dxf/reader.hpp, libdxflib's parser and the Boehm
// knot insertion of profile/nurbs.hpp, written independently of the writer): a sampled contour written as a
// SPLINE and read back is the same curve. Every span's Bezier segment read back equals the spline's cubic at
// its two ends and two inner points (1e-14 of the contour's size); a closed contour comes back closed, ends
// where it starts, and without corners; the polyline form keeps its points; $INSUNITS follows the unit.
// ezdxf, an independent consumer, reads the centrodes the CLI writes (tests/cli/run_cli_tests.sh).
#define BOOST_TEST_MODULE io_dxf_writer
#include <boost/test/unit_test.hpp>

#include "rollkin/io/dxf/reader.hpp"
#include "rollkin/io/dxf/writer.hpp"

#include <cmath>
#include <vector>

namespace {

using rollkin::BezierSegment;
using rollkin::io::DxfContour;
using rollkin::SampledProfile;
using rollkin::SplineOptions;
using V = rollkin::Vec2<double>;

/// Points of the curve r(t) = (3 cos t + 0.4 cos 3t, 2 sin t): n samples over [0, 2 pi) (closed) or [0, 5].
std::vector<V> samples(int n, bool closed) {
  std::vector<V> q;
  const double span = closed ? 2 * M_PI : 5.0;
  for (int k = 0; k < n; ++k) {
    const double t = span * k / (closed ? n : n - 1);
    q.emplace_back(3 * std::cos(t) + 0.4 * std::cos(3 * t), 2 * std::sin(t));
  }
  return q;
}

/// de Casteljau evaluation of a polynomial Bezier segment at t in [0, 1].
V bezier_point(const BezierSegment<double>& s, double t) {
  std::vector<V> p = s.points;
  for (std::size_t r = 1; r < p.size(); ++r)
    for (std::size_t k = 0; k + r < p.size(); ++k) p[k] = (1 - t) * p[k] + t * p[k + 1];
  return p[0];
}

DxfContour written_and_read(const SampledProfile<double>& p, const std::string& unit) {
  const std::string text = rollkin::io::dxf_text({rollkin::io::spline_of(p, "CENTRODE")}, unit);
  return rollkin::io::parse_dxf_contour(text, {"CENTRODE", ""}, "written.dxf");
}

/// Largest distance between each read-back segment and the spline's span, at t = 0, 1/3, 2/3, 1.
double worst_span_distance(const SampledProfile<double>& p, const DxfContour& c) {
  double worst = 0;
  const std::vector<double>& u = p.knots();
  for (std::size_t k = 0; k + 1 < u.size(); ++k)
    for (double t : {0.0, 1.0 / 3, 2.0 / 3, 1.0}) {
      const double at = k + 2 == u.size() && t == 1.0 ? u[k + 1] : u[k] + t * (u[k + 1] - u[k]);
      worst = std::max(worst, (bezier_point(c.segments[k], t) - p.jet(at, 0).p).norm());
    }
  return worst;
}

}  // namespace

BOOST_AUTO_TEST_CASE(an_open_sampled_contour_reads_back_as_the_same_cubic_spans) {
  const SampledProfile<double> p(samples(40, false));
  const DxfContour c = written_and_read(p, "mm");
  BOOST_TEST(c.segments.size() == p.span_count());
  BOOST_TEST(!c.closed);
  BOOST_TEST(c.corners.empty());
  BOOST_TEST(c.insunits == 4);
  BOOST_TEST(worst_span_distance(p, c) < 1e-14 * 3);
}

BOOST_AUTO_TEST_CASE(a_closed_sampled_contour_reads_back_closed_and_without_corners) {
  SplineOptions<double> closed;
  closed.closed = true;
  const SampledProfile<double> p(samples(60, true), closed);
  const DxfContour c = written_and_read(p, "m");
  BOOST_TEST(c.segments.size() == p.span_count());
  BOOST_TEST(c.closed);
  BOOST_TEST(c.corners.empty());  // tangent continuous at every knot and at the closing point
  BOOST_TEST(c.insunits == 6);
  BOOST_TEST((c.segments.back().points.back() - c.segments.front().points.front()).norm() == 0.0);
  BOOST_TEST(worst_span_distance(p, c) < 1e-14 * 3);
}

BOOST_AUTO_TEST_CASE(the_polyline_form_keeps_its_points_and_an_unknown_unit_is_unitless) {
  const std::vector<V> q{{0, 0}, {1, 0.5}, {2, 0}};
  const std::string text = rollkin::io::dxf_text({rollkin::io::polyline_spline(q, "P")}, "furlong");
  const DxfContour c = rollkin::io::parse_dxf_contour(text, {"P", ""}, "polyline.dxf");
  BOOST_TEST(c.insunits == 0);
  BOOST_TEST_REQUIRE(c.segments.size() == 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    BOOST_TEST((c.segments[k].points.front() - q[k]).norm() == 0.0);
    BOOST_TEST((c.segments[k].points.back() - q[k + 1]).norm() == 0.0);
  }
  BOOST_TEST(c.corners.size() == 1u);  // the polyline turns at its middle point
}
