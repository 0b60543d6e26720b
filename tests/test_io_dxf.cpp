// DXF contours (io/dxf/reader.hpp) against an independent producer: tests/data/dxf/make_fixtures.py writes the
// drawings with ezdxf and, next to each, the points ezdxf itself evaluates on the drawn entities and the facts
// of the fixture (entities, closed, corners, $INSUNITS, what an error must name). Every ezdxf point must lie
// on the imported contour (nearest-point distance by Newton projection) within 1e-12 of the drawing size; closed
// forms: the two-bulge circle and the NURBS circle keep their radius, the 2-span quadratic SPLINE is the
// parabola y = x^2 / 2, the stadium's length is 2 x 40 + 2 pi 10. Malformed texts and unsupported content give
// InputErrors that name the entity (type and handle) and what is wrong.
#define BOOST_TEST_MODULE io_dxf
#include <boost/test/unit_test.hpp>

#include "bezier_distance.hpp"
#include "test_support.hpp"

#include "rollkin/io/contour_listing.hpp"
#include "rollkin/io/dxf/reader.hpp"

#include <cmath>
#include <filesystem>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using rollkin::BezierPath;
using rollkin::BezierSegment;
using rollkin::io::DxfContour;
using rollkin::io::DxfSelection;
using rollkin::testing::contains;
using rollkin::testing::input_error_of;
using V = rollkin::Vec2<double>;

namespace {

const std::string kDir = std::string(ROLLKIN_SOURCE_DIR) + "/tests/data/dxf/";

/// A fixture's answer file: "# key value" header lines and ezdxf's points.
struct Answer {
  std::multimap<std::string, std::string> facts;
  std::vector<V> points;

  std::string fact(const std::string& key) const {
    const auto it = facts.find(key);
    BOOST_REQUIRE_MESSAGE(it != facts.end(), "answer file lacks " << key);
    return it->second;
  }
};

Answer answer(const std::string& file, const std::string& layer) {
  std::ifstream in(kDir + file + "." + layer + ".txt");
  BOOST_REQUIRE_MESSAGE(in, "missing answer file for " << file << " " << layer);
  Answer a;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("# ", 0) == 0) {
      const std::size_t sp = line.find(' ', 2);
      if (sp != std::string::npos) a.facts.emplace(line.substr(2, sp - 2), line.substr(sp + 1));
      continue;
    }
    std::istringstream s(line);
    double x, y;
    if (s >> x >> y) a.points.emplace_back(x, y);
  }
  return a;
}

DxfContour read(const std::string& file, const std::string& layer) {
  return rollkin::io::read_dxf_contour(kDir + file + ".dxf", DxfSelection{layer, ""});
}

double extent(const std::vector<V>& pts) {
  V lo = pts[0], hi = pts[0];
  for (const V& p : pts) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return (hi - lo).norm();
}

/// The checks every fixture gets: entities in order, closed flag, corners, units, ezdxf's points on the curve,
/// the chain starting where the first entity starts. Returns the contour.
DxfContour check_fixture(const std::string& file, const std::string& layer) {
  BOOST_TEST_CONTEXT(file << " layer " << layer) {
    const Answer a = answer(file, layer);
    const DxfContour c = read(file, layer);
    std::string labels;
    for (const auto& e : c.entities) labels += (labels.empty() ? "" : ", ") + e;
    BOOST_TEST(labels == a.fact("entities"));
    BOOST_TEST(c.closed == (a.fact("closed") == "1"));
    BOOST_TEST(c.insunits == std::stoi(a.fact("insunits")));
    std::vector<V> corners;
    for (auto [it, end] = a.facts.equal_range("corner"); it != end; ++it) {
      std::istringstream s(it->second);
      double x, y;
      s >> x >> y;
      corners.emplace_back(x, y);
    }
    BOOST_TEST(c.corners.size() == corners.size());
    for (std::size_t i = 0; i < std::min(corners.size(), c.corners.size()); ++i)
      BOOST_TEST((c.corners[i].point - corners[i]).norm() == 0.0);
    const double size = extent(a.points);
    const BezierPath<double> path(c.segments, c.closed);  // the path splits at the same corners
    double worst = 0;
    for (const V& q : a.points) worst = std::max(worst, rollkin::testing::distance_to_path(path, q) / size);
    std::printf("%-16s %-18s %3zu segments, %4zu ezdxf points, max distance / size = %.2e\n", file.c_str(), layer.c_str(),
                c.segments.size(), a.points.size(), worst);
    BOOST_TEST(worst < 1e-12);
    BOOST_TEST((c.segments.front().points.front() - a.points.front()).norm() <= 1e-12 * size);
    BOOST_TEST(path.corners().size() == c.corners.size());
    return c;
  }
  return {};
}

std::string dxf_error(const std::string& text, const std::string& layer) {
  return input_error_of([&] { rollkin::io::parse_dxf_contour(text, DxfSelection{layer, ""}, "inline.dxf"); });
}

/// A minimal DXF: an ENTITIES section holding `entities` (group pairs, one per line pair).
std::string minimal_dxf(const std::string& entities) { return "0\nSECTION\n2\nENTITIES\n" + entities + "0\nENDSEC\n0\nEOF\n"; }

const std::string kLine = "0\nLINE\n5\n2A\n8\nL\n10\n0\n20\n0\n30\n0\n11\n1\n21\n0\n31\n0\n";

std::string exact(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

/// An open LWPOLYLINE 7A on layer L from a to b with bulge k at a.
std::string bulge_polyline(const V& a, const V& b, double k) {
  return minimal_dxf("0\nLWPOLYLINE\n5\n7A\n8\nL\n90\n2\n70\n0\n10\n" + exact(a.x()) + "\n20\n" + exact(a.y()) + "\n42\n" +
                     exact(k) + "\n10\n" + exact(b.x()) + "\n20\n" + exact(b.y()) + "\n");
}

/// The arc from a to b with bulge k in closed form, in the chord's frame (origin at the chord's middle, x
/// along the chord, y along its left normal; h the half chord): the circle with centre (0, yc) and signed
/// radius r, yc = h (1 - k^2) / (2 k), r = h (1 + k^2) / (2 k), run over alpha in [-theta / 2, theta / 2] with
/// theta = 4 atan k as (r sin alpha, 2 r sin^2(alpha / 2) - h k) (= (r sin alpha, yc - r cos alpha), written
/// without the cancellation of yc and r, each (1 - k^2) / (4 k) chords for a small bulge).
struct ClosedFormArc {
  V a, b, mid, along, left;
  double h, k;

  ClosedFormArc(const V& a_, const V& b_, double k_) : a(a_), b(b_), mid((a_ + b_) / 2), k(k_) {
    h = (b - a).norm() / 2;
    along = (b - a) / (2 * h);
    left = V(-along.y(), along.x());
  }
  double r() const { return h * (1 + k * k) / (2 * k); }
  double yc() const { return h * (1 - k * k) / (2 * k); }
  V point(double s) const {  // s in [0, 1] along the arc
    const double alpha = (2 * s - 1) * 2 * std::atan(k), half = std::sin(alpha / 2);
    const V local(r() * std::sin(alpha), 2 * r() * half * half - h * k);
    return mid + local.x() * along + local.y() * left;
  }
  /// Distance from q to the circle: (|q - C|^2 - r^2) / (|q - C| + |r|) with yc^2 - r^2 = -h^2 taken exactly.
  double distance(const V& q) const {
    const double x = (q - mid).dot(along), y = (q - mid).dot(left);
    if (!std::isfinite(yc())) return std::abs(y);  // k = 0
    const double power = (x - h) * (x + h) + y * y - 2 * y * yc();
    return std::abs(power) / (std::hypot(x, y - yc()) + std::abs(r()));
  }
  double size() const {  // the arc's extent: its chord, or its diameter once it passes a half turn
    return std::abs(k) <= 1 ? 2 * h : 2 * std::abs(r());
  }
};

}  // namespace

BOOST_AUTO_TEST_CASE(lines_and_arcs_chain_into_a_closed_stadium_in_mm) {
  const DxfContour c = check_fixture("chain_mm", "STADIUM");
  BOOST_TEST(c.unit == "mm");
  BOOST_TEST(c.metres_per_unit == 0.001);
  const BezierPath<double> path(c.segments, true);
  const double length = 80 + 2 * M_PI * 10;
  BOOST_TEST(std::abs(path.total_length() - length) < 1e-14 * length);
  BOOST_TEST(contains(c.description, "4 entities"));
  BOOST_TEST(contains(c.description, "closed"));
  BOOST_TEST(contains(c.description, "unit mm"));
}

BOOST_AUTO_TEST_CASE(table_edge_polyline_has_one_corner_inside_the_entity) {
  const DxfContour c = check_fixture("scenes_mm", "TABLE_MM");
  BOOST_REQUIRE_EQUAL(c.corners.size(), 1u);
  BOOST_TEST(c.corners[0].entity == answer("scenes_mm", "TABLE_MM").fact("entities"));
  BOOST_TEST(std::abs(c.corners[0].turn_degrees + 45) < 1e-12);  // a right turn of 45 degrees
}

BOOST_AUTO_TEST_CASE(kink_between_two_lines_is_a_corner_naming_both) {
  const DxfContour c = check_fixture("chain_mm", "KINK");
  const Answer a = answer("chain_mm", "KINK");
  BOOST_REQUIRE(c.corners.size() == 1u);
  BOOST_TEST(c.corners[0].entity == a.fact("entities").replace(a.fact("entities").find(", "), 2, " / "));
  BOOST_TEST(c.corners[0].segment == 1u);
  BOOST_TEST(std::abs(c.corners[0].turn_degrees - 90) < 1e-12);
}

BOOST_AUTO_TEST_CASE(lwpolylines_with_bulges_in_inches) {
  const DxfContour open = check_fixture("polyline_in", "LW_OPEN");
  BOOST_TEST(open.unit == "in");
  BOOST_TEST(open.metres_per_unit == 0.0254);
  for (const auto& k : open.corners) BOOST_TEST(k.entity == answer("polyline_in", "LW_OPEN").fact("entities"));
  check_fixture("polyline_in", "LW_CLOSED");
}

BOOST_AUTO_TEST_CASE(mirrored_extrusion_arc_circle_and_ellipse) {
  check_fixture("polyline_in", "MIRROR");
  check_fixture("curves", "CIRCLE_M");
  check_fixture("curves", "ELLIPSE_M");
}

// A POLYLINE's extrusion is its own (groups 210-230 of the POLYLINE), not that of its VERTEX entities, which
// libdxflib reports with each vertex as (0, 0, 1) by default: a mirrored POLYLINE was read unmirrored (found
// by the differential test against ezdxf, test_io_dxf_differential.cpp).
BOOST_AUTO_TEST_CASE(a_mirrored_polyline_keeps_its_extrusion_over_its_vertices) {
  const std::string vertex = "0\nVERTEX\n8\nL\n10\n";
  const std::string text = minimal_dxf("0\nPOLYLINE\n5\n8A\n8\nL\n66\n1\n70\n0\n210\n0\n220\n0\n230\n-1\n" + vertex + "1\n20\n2\n" +
                                       vertex + "3\n20\n2\n42\n0.5\n" + vertex + "3\n20\n5\n0\nSEQEND\n8\nL\n");
  const DxfContour c = rollkin::io::parse_dxf_contour(text, DxfSelection{"L", ""});
  BOOST_REQUIRE(c.segments.size() >= 2u);
  BOOST_TEST((c.segments.front().points.front() - V(-1, 2)).norm() == 0.0);
  BOOST_TEST((c.segments.back().points.back() - V(-3, 5)).norm() == 0.0);
  // The bulge 0.5, counter-clockwise in the OCS from (3, 2) to (3, 5), passes 0.75 to the right of the chord
  // there, (3.75, 3.5): in the world (-3.75, 3.5), where its two halves meet.
  BOOST_REQUIRE_EQUAL(c.segments.size(), 3u);
  BOOST_TEST((c.segments[2].points.front() - V(-3.75, 3.5)).norm() <= 1e-15);
}

BOOST_AUTO_TEST_CASE(circles_and_ellipses_full_and_partial_unitless) {
  const DxfContour circle = check_fixture("curves", "CIRCLE");
  BOOST_TEST(circle.unit.empty());
  BOOST_TEST(circle.metres_per_unit == 0.0);
  BOOST_TEST(std::abs(BezierPath<double>(circle.segments, true).total_length() - 6 * M_PI) < 1e-14 * 6 * M_PI);
  check_fixture("curves", "ELLIPSE_FULL");
  check_fixture("curves", "ELLIPSE_PART");
}

BOOST_AUTO_TEST_CASE(two_bulge_arcs_make_an_exact_circle) {
  const DxfContour c = check_fixture("curves", "TWO_BULGE_CIRCLE");
  const BezierPath<double> path(c.segments, true);
  double worst = 0;
  for (int k = 0; k <= 4000; ++k) worst = std::max(worst, std::abs(path.jet(path.domain().hi * k / 4000, 0).p.norm() - 5) / 5);
  std::printf("two bulge arcs, r = 5: max | |p| - r | / r = %.2e\n", worst);
  BOOST_TEST(worst < 1e-14);
}

// A polyline piece with bulge k is the circular arc of included angle 4 atan k, whatever k: tiny bulges (whose
// centre lies (1 - k^2) / (4 k) chords away, 10^18 chords for k = 1e-18), arcs past a half turn (k > 1) and
// nearly whole circles (k = 1e3), both signs, on chords from 1e-3 to 1e6 in several directions. The read
// contour and the closed form (ClosedFormArc) must lie within 1e-12 of the arc's size of each other both ways
// (every read point near the circle, every closed-form point near the read contour), the ends exactly at
// the vertices; a bulge below round-off (|k| <= eps) is read as the straight line it is.
BOOST_AUTO_TEST_CASE(bulge_arcs_are_exact_for_every_bulge) {
  const double bulges[] = {1e-18, 1e-17, 5e-17, 1e-16, 2.3e-16, 1e-15, 1e-13, 1e-10, 1e-6, 1e-3, 0.1, 0.41421356237309503,
                           0.5, 0.99, 1, 1.01, 2, 10, 1e3};
  const double chords[] = {1e-3, 1, 500, 1e6};
  double worst_read = 0, worst_closed = 0;
  int cases = 0;
  for (const double chord : chords)
    for (const double magnitude : bulges)
      for (const double sign : {1.0, -1.0}) {
        const double k = sign * magnitude, turn = 0.3 + cases * 0.7;  // chord directions around the circle
        const V a = chord * V(0.25, -1.5), b = a + chord * V(std::cos(turn), std::sin(turn));
        const ClosedFormArc arc(a, b, k);
        BOOST_TEST_CONTEXT("bulge " << k << " chord " << chord) {
          const DxfContour c = rollkin::io::parse_dxf_contour(bulge_polyline(a, b, k), DxfSelection{"L", ""});
          BOOST_TEST((c.segments.front().points.front() - a).norm() == 0.0);
          BOOST_TEST((c.segments.back().points.back() - b).norm() == 0.0);
          if (magnitude <= std::numeric_limits<double>::epsilon()) {
            BOOST_TEST(c.segments.size() == 1u);
            BOOST_TEST(c.segments[0].degree() == 1);
          }
          const BezierPath<double> path(c.segments, false);
          double read = 0, closed = 0;
          for (int j = 0; j <= 64 * static_cast<int>(c.segments.size()); ++j)
            read = std::max(read, arc.distance(path.jet(j / 64.0, 0).p) / arc.size());
          for (int j = 0; j <= 100; ++j)
            closed = std::max(closed, rollkin::testing::distance_to_path(path, arc.point(j / 100.0)) / arc.size());
          BOOST_TEST(read < 1e-12);
          BOOST_TEST(closed < 1e-12);
          worst_read = std::max(worst_read, read);
          worst_closed = std::max(worst_closed, closed);
        }
        ++cases;
      }
  std::printf("%d bulge arcs: max distance / arc size, read -> closed form %.2e, closed form -> read %.2e\n", cases,
              worst_read, worst_closed);
}

/// A LWPOLYLINE 7C on layer L through `points` with `bulges` (one per point, the last unused).
std::string polyline_text(const std::vector<V>& points, const std::vector<double>& bulges) {
  std::string groups = "0\nLWPOLYLINE\n5\n7C\n8\nL\n90\n" + std::to_string(points.size()) + "\n70\n0\n";
  for (std::size_t i = 0; i < points.size(); ++i)
    groups += "10\n" + exact(points[i].x()) + "\n20\n" + exact(points[i].y()) + "\n42\n" + exact(bulges[i]) + "\n";
  return minimal_dxf(groups);
}

// Consecutive bulge arcs of one circle are one arc, as a straight run of lines is one line: 1,200 arcs of
// 0.05 and 0.15 degrees in turn over 120 degrees of a circle of radius 500 become one arc of two 60-degree
// pieces through every vertex (before, the native parameter's speed jumped at each vertex and a disk rolling
// on it met no_convergence at its first step). Arcs turning the other way, or of another circle, stay apart.
BOOST_AUTO_TEST_CASE(bulge_arcs_of_one_circle_are_one_arc) {
  const double r = 500, to_rad = M_PI / 180;
  std::vector<double> degrees{150};
  for (int k = 0; degrees.back() > 30 + 1e-9; ++k) degrees.push_back(degrees.back() - (k % 2 ? 0.15 : 0.05));
  std::vector<V> points;
  std::vector<double> bulges;
  for (std::size_t i = 0; i < degrees.size(); ++i) {
    points.emplace_back(r * std::cos(degrees[i] * to_rad), r * std::sin(degrees[i] * to_rad));
    bulges.push_back(i + 1 < degrees.size() ? std::tan((degrees[i + 1] - degrees[i]) * to_rad / 4) : 0.0);
  }
  const DxfContour c = rollkin::io::parse_dxf_contour(polyline_text(points, bulges), DxfSelection{"L", ""});
  BOOST_TEST(c.segments.size() == 2u);
  const BezierPath<double> path(c.segments, false);
  double vertices = 0, circle = 0;
  for (const V& q : points) vertices = std::max(vertices, rollkin::testing::distance_to_path(path, q) / (2 * r));
  for (int k = 0; k <= 2000; ++k) circle = std::max(circle, std::abs(path.jet(2.0 * k / 2000, 0).p.norm() - r) / r);
  std::printf("%zu arcs of one circle read as %zu pieces: vertices off the contour %.2e, contour off the circle %.2e (/ size)\n",
              points.size() - 1, c.segments.size(), vertices, circle);
  BOOST_TEST(vertices < 1e-12);
  BOOST_TEST(circle < 1e-12);
}

/// The largest distance of the contour's points (2000 per segment) from the circle (centre, radius) of the
/// segment's own arc, relative to the radius; segments i of the contour belong to circle circle_of[i].
double off_circles(const DxfContour& c, const std::vector<std::pair<V, double>>& circles, const std::vector<std::size_t>& circle_of) {
  const BezierPath<double> path(c.segments, false);
  double worst = 0;
  for (std::size_t i = 0; i < c.segments.size(); ++i)
    for (int k = 0; k <= 2000; ++k) {
      const auto& [centre, r] = circles[circle_of[i]];
      worst = std::max(worst, std::abs((path.jet(double(i) + k / 2000.0, 0).p - centre).norm() - r) / r);
    }
  return worst;
}

// Tangent bulge arcs of different circles stay apart (docs/reliability.md, "CAD readers (issue 37)": arcs are
// joined only when they are one circle, centre and radius). The LWPOLYLINE through (1, 0), (0, 1), (-2, -1) with
// both bulges tan(22.5 deg) is a quarter circle of radius 1 about (0, 0) and a quarter circle of radius 2 about
// (0, -1), length 3 pi / 2 (read as one half circle of radius 1.581 before: its common vertex lies on that
// circle, as that of every tangent pair does). Likewise an S of equal radii, and radii 1e-6 apart.
BOOST_AUTO_TEST_CASE(tangent_bulge_arcs_of_different_circles_stay_apart) {
  const double q = std::tan(M_PI / 8);
  const DxfContour two = rollkin::io::parse_dxf_contour(polyline_text({V(1, 0), V(0, 1), V(-2, -1)}, {q, q, 0}), DxfSelection{"L", ""});
  const BezierPath<double> path(two.segments, false);
  BOOST_TEST(std::abs(path.total_length() - 1.5 * M_PI) < 1e-13);
  BOOST_TEST(two.segments.size() == 2u);
  BOOST_TEST(off_circles(two, {{V(0, 0), 1.0}, {V(0, -1), 2.0}}, {0, 1}) < 1e-14);
  // the listing says the same: length 3 pi / 2, box (-2, -1) to (1, 1)
  const std::filesystem::path file = rollkin::testing::scratch_dir("io_dxf_tangent_arcs") / "two_arcs.dxf";
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file) << polyline_text({V(1, 0), V(0, 1), V(-2, -1)}, {q, q, 0});
  const std::vector<rollkin::io::ListedChain> listed = rollkin::io::list_dxf_contours(file.string());
  BOOST_TEST_REQUIRE(listed.size() == 1u);
  BOOST_TEST(std::abs(listed[0].length - 1.5 * M_PI) < 1e-12);
  BOOST_TEST((listed[0].min - V(-2, -1)).norm() < 1e-12);
  BOOST_TEST((listed[0].max - V(1, 1)).norm() < 1e-12);
  // an S: quarter arcs of radius 1 about (0, 1) and (2, 1), one counter-clockwise, one clockwise
  const DxfContour s = rollkin::io::parse_dxf_contour(polyline_text({V(0, 0), V(1, 1), V(2, 2)}, {q, -q, 0}), DxfSelection{"L", ""});
  BOOST_TEST(std::abs(BezierPath<double>(s.segments, false).total_length() - M_PI) < 1e-13);
  BOOST_TEST(off_circles(s, {{V(0, 1), 1.0}, {V(2, 1), 1.0}}, {0, 1}) < 1e-14);
  // radii 1 and 1 + 1e-6, tangent at (0, 1), 60 degrees each, counter-clockwise: two circles
  const double r2 = 1 + 1e-6, t = M_PI / 3;
  const V c2(0, 1 - r2), end = c2 + r2 * V(std::cos(M_PI / 2 + t), std::sin(M_PI / 2 + t));
  const V start(std::cos(M_PI / 2 - t), std::sin(M_PI / 2 - t));
  const double k = std::tan(t / 4);
  const DxfContour near = rollkin::io::parse_dxf_contour(polyline_text({start, V(0, 1), end}, {k, k, 0}), DxfSelection{"L", ""});
  BOOST_TEST(off_circles(near, {{V(0, 0), 1.0}, {c2, r2}}, {0, 1}) < 1e-14);
  BOOST_TEST(std::abs(BezierPath<double>(near.segments, false).total_length() - t * (1 + r2)) < 1e-13);
}

// A bulge so large that the arc's ends are closer than the join tolerance of its own diameter cannot be told
// from a whole circle: refused, naming the vertex and the bulge.
BOOST_AUTO_TEST_CASE(a_bulge_indistinguishable_from_a_whole_circle_is_refused) {
  const std::string m = dxf_error(bulge_polyline(V(0, 0), V(1, 0), 1e300), "L");
  BOOST_TEST(contains(m, "LWPOLYLINE 7A at vertex 0: bulge 1e+300 makes an arc whose ends are"));
  BOOST_TEST(contains(m, "cannot be told from a whole circle"));
  BOOST_TEST(rollkin::io::parse_dxf_contour(bulge_polyline(V(0, 0), V(1, 0), 1e9), DxfSelection{"L", ""}).segments.size() >= 4u);
}

BOOST_AUTO_TEST_CASE(old_style_polyline_from_r12) { check_fixture("polyline_r12", "P2D"); }

BOOST_AUTO_TEST_CASE(rational_spline_circle_and_cubic) {
  const DxfContour circle = check_fixture("splines_mm", "SPLINE_CIRCLE");
  const double r = std::stod(answer("splines_mm", "SPLINE_CIRCLE").fact("radius"));
  const BezierPath<double> path(circle.segments, true);
  double worst = 0;
  for (int k = 0; k <= 4000; ++k) worst = std::max(worst, std::abs(path.jet(path.domain().hi * k / 4000, 0).p.norm() - r) / r);
  BOOST_TEST(worst < 1e-14);
  BOOST_TEST(std::abs(path.total_length() - 2 * M_PI * r) < 1e-14 * 2 * M_PI * r);
  check_fixture("splines_mm", "SPLINE_CUBIC");
  check_fixture("splines_mm", "SPLINE_PERIODIC");
}

BOOST_AUTO_TEST_CASE(two_span_quadratic_spline_is_the_parabola_in_mm) {
  const DxfContour c = check_fixture("splines_mm", "PARABOLA");
  BOOST_TEST(c.metres_per_unit == 0.001);
  BOOST_TEST(c.segments.size() == 2u);
  const BezierPath<double> path(c.segments, false);
  double worst = 0;
  for (int k = 0; k <= 2000; ++k) {
    const V p = path.jet(2.0 * k / 2000, 0).p;
    worst = std::max(worst, std::abs(p.y() - 0.5 * p.x() * p.x()) / 2);
  }
  std::printf("parabola SPLINE: max |y - x^2/2| / 2 = %.2e\n", worst);
  BOOST_TEST(worst < 1e-14);
  BOOST_TEST((path.jet(0, 0).p - V(-2, 2)).norm() == 0.0);
  BOOST_TEST((path.jet(2, 0).p - V(2, 2)).norm() == 0.0);
}

BOOST_AUTO_TEST_CASE(selection_by_handle_case_insensitive) {
  const std::string handle = answer("splines_mm", "SPLINE_CIRCLE").fact("entities").substr(7);
  std::string lower = handle;
  for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  const DxfContour c = rollkin::io::read_dxf_contour(kDir + "splines_mm.dxf", DxfSelection{"", lower});
  BOOST_TEST(c.closed);
  BOOST_TEST(c.entities.size() == 1u);
  BOOST_TEST(contains(c.description, "handle " + lower));
}

// One wording for a selection in every message (the reader's description and errors, the scene reader's):
// io::selection_text, for each way of selecting.
BOOST_AUTO_TEST_CASE(every_selection_is_named_one_way) {
  DxfSelection by_layer{"CAM", ""}, near_layer{"CAM", ""}, near_only, one{"", "2F"}, several;
  near_layer.near = V(1, 2.5);
  near_only.near = V(-3, 0);
  several.handles = {"2F", "30"};
  BOOST_TEST(rollkin::io::selection_text(by_layer) == "layer \"CAM\"");
  BOOST_TEST(rollkin::io::selection_text(near_layer) == "layer \"CAM\", near (1, 2.5)");
  BOOST_TEST(rollkin::io::selection_text(near_only) == "all layers, near (-3, 0)");
  BOOST_TEST(rollkin::io::selection_text(one) == "handle 2F");
  BOOST_TEST(rollkin::io::selection_text(several) == "handles 2F, 30");
  const std::string handle = answer("splines_mm", "SPLINE_CIRCLE").fact("entities").substr(7);
  DxfSelection listed;
  listed.handles = {handle};
  for (const DxfSelection& sel : {DxfSelection{"", handle}, listed}) {
    const DxfContour c = rollkin::io::read_dxf_contour(kDir + "splines_mm.dxf", sel);
    BOOST_TEST(contains(c.description, rollkin::io::selection_text(sel)), c.description);
  }
}

BOOST_AUTO_TEST_CASE(fixture_errors_name_the_entities) {
  for (const std::string layer : {"GAP", "BRANCH", "INSERT", "FITONLY"}) {
    const Answer a = answer("errors", layer);
    const std::string message = input_error_of([&] { read("errors", layer); });
    BOOST_TEST_MESSAGE(layer << ": " << message);
    BOOST_TEST(contains(message, "errors.dxf"));
    for (auto [it, end] = a.facts.equal_range("names"); it != end; ++it) BOOST_TEST(contains(message, it->second));
  }
  const std::string units = input_error_of([&] { read("units_miles", "L"); });
  BOOST_TEST(contains(units, "$INSUNITS"));
  BOOST_TEST(contains(units, "unit code 3"));
}

BOOST_AUTO_TEST_CASE(entities_libdxflib_does_not_know_are_found_by_the_scan) {
  const std::string mline = "0\nMLINE\n5\n3C\n8\nL\n10\n0\n20\n0\n";
  const std::string m = dxf_error(minimal_dxf(kLine + mline), "L");
  BOOST_TEST(contains(m, "unsupported entities: MLINE 3C"));
  // A HATCH is never a curve: passed over (an error only when named by its handle).
  const std::string hatch = "0\nHATCH\n5\n3D\n8\nL\n10\n0\n20\n0\n";
  BOOST_TEST(rollkin::io::parse_dxf_contour(minimal_dxf(kLine + hatch), DxfSelection{"L", ""}).entities.size() == 1u);
  BOOST_TEST(contains(input_error_of([&] { rollkin::io::parse_dxf_contour(minimal_dxf(kLine + hatch), DxfSelection{"", "3D"}); }),
                      "HATCH 3D is not a curve"));
  // the same entities on another layer do not matter
  const std::string other = "0\nMLINE\n5\n3C\n8\nNOTES\n10\n0\n20\n0\n";
  BOOST_TEST(rollkin::io::parse_dxf_contour(minimal_dxf(kLine + other), DxfSelection{"l", ""}).segments.size() == 1u);
}

BOOST_AUTO_TEST_CASE(malformed_text_is_refused_with_its_location) {
  const std::string bad_number = "0\nLINE\n5\n2A\n8\nL\n10\n0\n20\n1.5abc\n11\n1\n21\n0\n";
  const std::string m1 = dxf_error(minimal_dxf(bad_number), "L");
  BOOST_TEST(contains(m1, "inline.dxf:line 14"));
  BOOST_TEST(contains(m1, "LINE 2A: group 20 value \"1.5abc\" is not a decimal number"));
  BOOST_TEST(contains(dxf_error("0\nSECTION\nfoo\nENTITIES\n", "L"), "line 3: expected a group code"));
  BOOST_TEST(contains(dxf_error(minimal_dxf("999\n" + std::string(2000, 'x') + "\n"), "L"), "line 6: line of 2000 characters"));
  BOOST_TEST(contains(dxf_error("AutoCAD Binary DXF\r\n\x1a", "L"), "binary DXF is not supported"));
  const std::string lw = "0\nLWPOLYLINE\n5\n4A\n8\nL\n90\n3\n70\n0\n10\n0\n20\n0\n10\n1\n20\n0\n";
  BOOST_TEST(contains(dxf_error(minimal_dxf(lw), "L"), "LWPOLYLINE 4A: group 90 gives a count of 3 vertices but 2 vertices"));
  const std::string huge = "0\nLWPOLYLINE\n5\n4B\n8\nL\n90\n2000000000\n";
  BOOST_TEST(contains(dxf_error(minimal_dxf(huge), "L"), "LWPOLYLINE 4B: group 90 count 2000000000 is impossible"));
  const std::string early_bulge = "0\nLWPOLYLINE\n5\n4C\n8\nL\n90\n2\n42\n1\n10\n0\n20\n0\n10\n1\n20\n0\n";
  BOOST_TEST(contains(dxf_error(minimal_dxf(early_bulge), "L"), "LWPOLYLINE 4C: group 42 (bulge) before the first vertex"));
  const std::string no_count = "0\nLWPOLYLINE\n5\n4D\n8\nL\n10\n0\n20\n0\n10\n1\n20\n0\n";
  BOOST_TEST(contains(dxf_error(minimal_dxf(no_count), "L"), "LWPOLYLINE 4D: group 10 (vertex) before the vertex count"));
  const std::string spline = "0\nSPLINE\n5\n5A\n8\nL\n71\n1\n72\n5\n73\n2\n40\n0\n40\n0\n40\n1\n40\n1\n10\n0\n20\n0\n10\n1\n20\n1\n";
  BOOST_TEST(contains(dxf_error(minimal_dxf(spline), "L"), "SPLINE 5A: group 72 gives a count of 5 knots but 4 knots"));
}

BOOST_AUTO_TEST_CASE(bad_geometry_is_refused_naming_the_entity) {
  const std::string tilted = "0\nCIRCLE\n5\n6A\n8\nL\n10\n0\n20\n0\n40\n1\n210\n0\n220\n1\n230\n0\n";
  BOOST_TEST(contains(dxf_error(minimal_dxf(tilted), "L"), "CIRCLE 6A has extrusion direction (0, 1, 0)"));
  const std::string zero = "0\nCIRCLE\n5\n6B\n8\nL\n10\n0\n20\n0\n40\n0\n";
  BOOST_TEST(contains(dxf_error(minimal_dxf(zero), "L"), "CIRCLE 6B has radius 0; it must be positive"));
  const std::string ratio = "0\nELLIPSE\n5\n6C\n8\nL\n10\n0\n20\n0\n11\n2\n21\n0\n40\n-1.5\n41\n0\n42\n1\n";
  BOOST_TEST(contains(dxf_error(minimal_dxf(ratio), "L"), "ELLIPSE 6C has axis ratio -1.5; it must be positive"));
  const std::string bad_knots = "0\nSPLINE\n5\n6D\n8\nL\n71\n1\n72\n4\n73\n2\n40\n0\n40\n1\n40\n0\n40\n1\n10\n0\n20\n0\n10\n1\n20\n1\n";
  BOOST_TEST(contains(dxf_error(minimal_dxf(bad_knots), "L"), "SPLINE 6D is not a valid NURBS curve: NURBS: knots must be non-decreasing"));
  const std::string circle = "0\nCIRCLE\n5\n6E\n8\nL\n10\n5\n20\n0\n40\n1\n";
  // A closed entity beside an open one: two chains, each listed with a point on it.
  const std::string two = dxf_error(minimal_dxf(kLine + circle), "L");
  BOOST_TEST(contains(two, "the entities on layer \"L\" form 2 chains, not one"));
  BOOST_TEST(contains(two, "CIRCLE 6E"));
  BOOST_TEST(contains(two, "\"near\""));
  // Angles far outside one turn are reduced, not looped over (a fuzzer's 1e300 degrees must not hang).
  const std::string far_arc = "0\nARC\n5\n6H\n8\nL\n10\n0\n20\n0\n40\n1\n50\n1e300\n51\n-1e300\n";
  BOOST_TEST(rollkin::io::parse_dxf_contour(minimal_dxf(far_arc), DxfSelection{"L", ""}).segments.size() >= 1u);
  // An ELLIPSE whose end parameter was rounded just past start + 2 pi is still the full ellipse.
  const std::string rounded = "0\nELLIPSE\n5\n6J\n8\nL\n10\n0\n20\n0\n11\n2\n21\n0\n40\n0.5\n41\n0.5\n42\n6.783185307179587\n";
  const DxfContour full = rollkin::io::parse_dxf_contour(minimal_dxf(rounded), DxfSelection{"L", ""});
  BOOST_TEST(full.closed);
  BOOST_TEST(full.segments.size() == 4u);
  // Two vertices 1e-14 apart in a drawing of size 1: a piece below the join tolerance (found by fuzzing).
  const std::string tiny = "0\nLWPOLYLINE\n5\n6K\n8\nL\n90\n3\n10\n0\n20\n0\n10\n1\n20\n0\n42\n1\n10\n1\n20\n1e-14\n";
  BOOST_TEST(contains(dxf_error(minimal_dxf(tiny), "L"), "LWPOLYLINE 6K has a piece at (1, 0) no longer than the join tolerance"));
  const std::string zero_line = "0\nLINE\n5\n6F\n8\nL\n10\n1\n20\n1\n11\n1\n21\n1\n";
  BOOST_TEST(contains(dxf_error(minimal_dxf(zero_line), "L"), "LINE 6F has zero length"));
}

// A handle names one entity: a selection by a handle two entities share (here 2A on layers A and B, one written
// in lower case) is an error naming the handle and both entities with their lines and layers, whether it is
// selected alone or in a list; every other selection of the drawing is read (docs/reliability.md, "CAD
// readers (issue 37)"): a unique handle, a layer, a point near, and the listing.
BOOST_AUTO_TEST_CASE(a_shared_handle_refuses_only_the_selections_that_use_it) {
  const std::string first = "0\nLINE\n5\n2A\n8\nA\n10\n0\n20\n0\n11\n1\n21\n0\n";
  const std::string second = "0\nLINE\n5\n2a\n8\nB\n10\n1\n20\n0\n11\n2\n21\n0\n";
  const std::string third = "0\nLINE\n5\n2C\n8\nC\n10\n5\n20\n5\n11\n6\n21\n5\n";
  const std::string text = minimal_dxf(first + second + third);
  DxfSelection list;
  list.handles = {"2C", "2a"};
  for (const DxfSelection& sel : {DxfSelection{"", "2A"}, DxfSelection{"", "2a"}, list}) {
    const std::string m = input_error_of([&] { rollkin::io::parse_dxf_contour(text, sel, "dup.dxf"); });
    BOOST_TEST(contains(m, "dup.dxf:handle 2"));
    BOOST_TEST(contains(m, "is ambiguous: LINE 2A (line 5, layer \"A\") and LINE 2a (line 19, layer \"B\") have it"));
  }
  // the unique handle, each layer and a point near: read, each its own entity
  const DxfContour unique = rollkin::io::parse_dxf_contour(text, DxfSelection{"", "2C"});
  BOOST_TEST(unique.entities == std::vector<std::string>{"LINE 2C"});
  BOOST_TEST((unique.segments.front().points.front() - V(5, 5)).norm() == 0);
  BOOST_TEST(rollkin::io::parse_dxf_contour(text, DxfSelection{"A", ""}).segments.front().points.back().x() == 1);
  BOOST_TEST(rollkin::io::parse_dxf_contour(text, DxfSelection{"B", ""}).segments.front().points.back().x() == 2);
  DxfSelection near;
  near.near = V(1.9, 0.1);
  // (near on all layers: the two LINEs sharing the handle meet at (1, 0), one chain)
  BOOST_TEST(rollkin::io::parse_dxf_contour(text, near).entities == (std::vector<std::string>{"LINE 2A", "LINE 2a"}));
  // Distinct handles on the same two entities chain as before.
  const std::string distinct = minimal_dxf(first + "0\nLINE\n5\n2B\n8\nA\n10\n1\n20\n0\n11\n2\n21\n0\n");
  BOOST_TEST(rollkin::io::parse_dxf_contour(distinct, DxfSelection{"A", ""}).segments.size() == 2u);
}

// A file cut short inside its last entity (no group 0 after it, no ENDSEC, no EOF): libdxflib never completes
// the entity; the message says where the file ends and in which entity, whichever group it ends after.
BOOST_AUTO_TEST_CASE(a_file_cut_inside_an_entity_says_so) {
  const std::string whole = "0\nSECTION\n2\nENTITIES\n" + kLine + "0\nLINE\n5\n2B\n8\nL\n10\n1\n20\n0\n11\n2\n21\n0\n";
  BOOST_TEST(contains(dxf_error(whole, "L"), "inline.dxf:line 36: the file ends inside entity LINE 2B (line 23): the DXF is cut short"));
  const std::string mid_value = whole.substr(0, whole.rfind("21\n"));  // ends after "11\n2\n"
  BOOST_TEST(contains(dxf_error(mid_value, "L"), "line 34: the file ends inside entity LINE 2B (line 23)"));
  const std::string no_value = whole.substr(0, whole.rfind("0\n"));  // a group code 21 without its value
  BOOST_TEST(contains(dxf_error(no_value, "L"), "line 35: the file ends inside entity LINE 2B (line 23) after group code 21 without its value"));
  const std::string polyline = "0\nSECTION\n2\nENTITIES\n0\nPOLYLINE\n5\n3A\n8\nL\n66\n1\n70\n0\n0\nVERTEX\n5\n3B\n8\nL\n10\n0\n20\n0\n";
  BOOST_TEST(contains(dxf_error(polyline, "L"), "the file ends inside entity POLYLINE 3A (line 5)"));
  // Complete entities without ENDSEC and EOF are read.
  const std::string no_eof = "0\nSECTION\n2\nENTITIES\n" + kLine + "0\nENDSEC\n";
  BOOST_TEST(rollkin::io::parse_dxf_contour(no_eof, DxfSelection{"L", ""}).segments.size() == 1u);
}

// An extrusion direction within 1e-12 radians of +Z or -Z is +Z or -Z (a written unit normal rounds to
// 0.99999999999999989); a message about any other prints the values exactly.
BOOST_AUTO_TEST_CASE(extrusion_within_round_off_of_z_is_z) {
  auto circle = [](const std::string& n) {
    return minimal_dxf("0\nCIRCLE\n5\n6A\n8\nL\n10\n1\n20\n0\n40\n1\n" + n);
  };
  const DxfContour plus = rollkin::io::parse_dxf_contour(circle("230\n0.99999999999999989\n"), DxfSelection{"L", ""});
  const DxfContour minus = rollkin::io::parse_dxf_contour(circle("210\n1e-13\n220\n0\n230\n-0.99999999999999989\n"), DxfSelection{"L", ""});
  const DxfContour reference = rollkin::io::parse_dxf_contour(circle(""), DxfSelection{"L", ""});
  for (std::size_t i = 0; i < reference.segments.size(); ++i)
    for (std::size_t j = 0; j < 3; ++j) {
      BOOST_TEST((plus.segments[i].points[j] - reference.segments[i].points[j]).norm() == 0.0);
      // -Z mirrors the OCS x axis: the circle about (-1, 0), run clockwise
      const V p = reference.segments[i].points[j];
      BOOST_TEST((minus.segments[i].points[j] - V(-p.x(), p.y())).norm() == 0.0);
    }
  const std::string tilted = dxf_error(circle("210\n1e-9\n220\n0\n230\n0.99999999999999989\n"), "L");
  BOOST_TEST(contains(tilted, "CIRCLE 6A has extrusion direction (1e-09, 0, 0.9999999999999999): only drawings in the XY plane"));
  BOOST_TEST(contains(dxf_error(circle("230\n0\n"), "L"), "extrusion direction (0, 0, 0)"));
  // Every value a message tests against a bound is printed exactly: an axis ratio just above the largest, z
  // values that differ in the last digit.
  const std::string ratio = "0\nELLIPSE\n5\n6C\n8\nL\n10\n0\n20\n0\n11\n2\n21\n0\n40\n1000000000.0000002\n41\n0\n42\n1\n";
  BOOST_TEST(contains(dxf_error(minimal_dxf(ratio), "L"), "ELLIPSE 6C has axis ratio 1000000000.0000002; it must be positive (and at most 1000000000)"));
  const std::string z = "0\nLINE\n5\n2A\n8\nL\n10\n0\n20\n0\n30\n1\n11\n1\n21\n0\n31\n1.0000000000000002\n";
  BOOST_TEST(contains(dxf_error(minimal_dxf(z), "L"), "LINE 2A is not parallel to the XY plane (z 1 and 1.0000000000000002)"));
}

// Numbers are read once: a value is a plain decimal ([sign] digits [. digits] [E [sign] digits]), which
// rollkin's check and libdxflib's conversion read alike, in range; everything else is refused with the group,
// the line, the value and what libdxflib would have read.
BOOST_AUTO_TEST_CASE(numbers_are_plain_decimals_read_alike_by_check_and_libdxflib) {
  // Spellings of 0.5 and 2 that both read the same: the line's end is (0.5, 2).
  for (const std::string& half : {"0.5", "+0.5", ".5", "5e-1", "5.E-1", "  0.50  ", "0.5\r"})
    for (const std::string& two : {"2", "2.", "+2", "0.2e1", "200e-2", "2\r"}) {
      const std::string text = minimal_dxf("0\nLINE\n5\n2A\n8\nL\n10\n0\n20\n0\n11\n" + half + "\n21\n" + two + "\n");
      const DxfContour c = rollkin::io::parse_dxf_contour(text, DxfSelection{"L", ""});
      BOOST_TEST((c.segments[0].points[1] - V(0.5, 2)).norm() == 0.0, half << " " << two);
    }
  auto line_with = [](const std::string& x) { return minimal_dxf("0\nLINE\n5\n2A\n8\nL\n10\n" + x + "\n20\n0\n11\n1\n21\n0\n"); };
  const std::string hex = dxf_error(line_with("0x1p8"), "L");
  BOOST_TEST(contains(hex, "inline.dxf:line 12: LINE 2A: group 10 value \"0x1p8\" is not a decimal number"));
  BOOST_TEST(contains(hex, "libdxflib would read it as 0"));
  BOOST_TEST(contains(dxf_error(line_with("1.5abc"), "L"), "group 10 value \"1.5abc\" is not a decimal number"));
  BOOST_TEST(contains(dxf_error(line_with("1.5abc"), "L"), "libdxflib would read it as 1.5"));
  BOOST_TEST(contains(dxf_error(line_with("1,5"), "L"), "write a decimal point, not a comma"));
  for (const std::string bad : {"1e", "inf", "nan", "-", ".", "1e+", "1 2", "0x10", "1d0"})
    BOOST_TEST(contains(dxf_error(line_with(bad), "L"), "group 10 value \"" + bad + "\" is not a decimal number"));
  for (const std::string far : {"1e400", "-1e309", "1e-400"})
    BOOST_TEST(contains(dxf_error(line_with(far), "L"), "group 10 value \"" + far + "\" is out of the range of a double"));
  // Integers: $INSUNITS beyond an int (libdxflib truncates 99999999999 to 1215752191), not an integer.
  auto units = [](const std::string& u) { return "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n" + u + "\n0\nENDSEC\n" + minimal_dxf(kLine); };
  const std::string big = dxf_error(units("99999999999"), "L");
  BOOST_TEST(contains(big, "inline.dxf:line 8: $INSUNITS: group 70 value \"99999999999\" is out of the range of a DXF integer"));
  BOOST_TEST(contains(big, "libdxflib would read it as 1215752191"));
  BOOST_TEST(contains(dxf_error(units("4.0"), "L"), "$INSUNITS: group 70 value \"4.0\" is not an integer ([sign] digits): libdxflib would read it as 4"));
  BOOST_TEST(rollkin::io::parse_dxf_contour(units("+4"), DxfSelection{"L", ""}).unit == "mm");
  const std::string lw = "0\nLWPOLYLINE\n5\n4A\n8\nL\n90\n0x2\n10\n0\n20\n0\n10\n1\n20\n0\n";
  BOOST_TEST(contains(dxf_error(minimal_dxf(lw), "L"), "LWPOLYLINE 4A: group 90 value \"0x2\" is not an integer"));
  BOOST_TEST(contains(dxf_error("0\nSECTION\n0x2\nENTITIES\n", "L"), "line 3: expected a group code"));
}

BOOST_AUTO_TEST_CASE(selection_errors) {
  const std::string text = minimal_dxf(kLine);
  BOOST_TEST(contains(dxf_error(text, "CAM"), "no entity on layer \"CAM\" in the ENTITIES section (layers with entities: \"L\")"));
  BOOST_TEST(contains(input_error_of([&] { rollkin::io::parse_dxf_contour(text, DxfSelection{"", "FF"}); }), "no entity with handle FF"));
  BOOST_TEST(contains(input_error_of([&] { rollkin::io::parse_dxf_contour(text, DxfSelection{"L", "2A"}); }), "exactly one of these"));
  BOOST_TEST(contains(input_error_of([&] { rollkin::io::read_dxf_contour(kDir + "missing.dxf", DxfSelection{"L", ""}); }),
                      "cannot open the DXF file"));
}

// fuzz_dxf (session 6): an input error found while libdxflib read the text was thrown through DL_Dxf::in,
// which then never closed its FILE; after some 10^5 rejected inputs the reader could not even make its
// temporary copy. Rejected inputs must leave no descriptor open.
BOOST_AUTO_TEST_CASE(rejected_inputs_leave_no_file_open) {
  auto open_descriptors = [] {
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator("/proc/self/fd")) ++n;
    return n;
  };
  const std::string bad_value = "0\nSECTION\n2\nENTITIES\n0\nLINE\n8\n0\n10\nabc\n0\nENDSEC\n0\nEOF\n";
  const std::string bad_count = "0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\n0\n10\n1\n20\n2\n0\nENDSEC\n0\nEOF\n";
  const std::size_t before = open_descriptors();
  for (int k = 0; k < 50; ++k)
    for (const std::string& text : {bad_value, bad_count}) {
      const std::string message = input_error_of([&] { rollkin::io::parse_dxf_contour(text, DxfSelection{}, "bad.dxf"); });
      BOOST_TEST(contains(message, "bad.dxf"));
    }
  BOOST_TEST(open_descriptors() == before);
}

// fuzz_dxf (session 6): libdxflib reads entities in any section and sizes its arrays from their counts; a
// SPLINE in a misspelt section with 1056964608 fit points (group 74) overflowed new double[3 n]. Counts that
// size arrays are bounded wherever the entity is.
BOOST_AUTO_TEST_CASE(array_counts_are_bounded_in_every_section) {
  for (const char* section : {"BLOCKS", "ENTITM-rES"}) {
    const std::string text = std::string("0\nSECTION\n2\n") + section + "\n0\nSPLINE\n71\n3\n74\n1056964608\n0\nENDSEC\n0\nEOF\n";
    const std::string message = input_error_of([&] { rollkin::io::parse_dxf_contour(text, DxfSelection{}, "fit.dxf"); });
    BOOST_TEST(contains(message, "fit.dxf"));
    BOOST_TEST(contains(message, "line 10"));  // the value line of group 74
    // (in BLOCKS, whose entities are recorded for INSERTs, the SPLINE is named by its line)
    BOOST_TEST(contains(message, "SPLINE"));
    BOOST_TEST(contains(message, "group 74 count"));
    BOOST_TEST(contains(message, "1056964608"));
    BOOST_TEST(contains(message, "is impossible"));
  }
  // A LEADER's vertex count (group 76) in ENTITIES, named by its handle.
  const std::string leader = "0\nSECTION\n2\nENTITIES\n0\nLEADER\n5\n4C\n76\n1500000000\n0\nENDSEC\n0\nEOF\n";
  BOOST_TEST(contains(input_error_of([&] { rollkin::io::parse_dxf_contour(leader, DxfSelection{}, "l.dxf"); }),
                      "LEADER 4C: group 76 count 1500000000 is impossible"));
}
