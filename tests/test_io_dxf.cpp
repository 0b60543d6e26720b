// DXF contours (io/dxf.hpp) against an independent producer: tests/data/dxf/make_fixtures.py writes the
// drawings with ezdxf and, next to each, the points ezdxf itself evaluates on the drawn entities and the facts
// of the fixture (entities, closed, corners, $INSUNITS, what an error must name). Every ezdxf point must lie
// on the imported contour (nearest-point distance by Newton projection) within 1e-12 of the drawing size; closed
// forms: the two-bulge circle and the NURBS circle keep their radius, the 2-span quadratic SPLINE is the
// parabola y = x^2 / 2, the stadium's length is 2 x 40 + 2 pi 10. Malformed texts and unsupported content give
// InputErrors that name the entity (type and handle) and what is wrong.
#define BOOST_TEST_MODULE io_dxf
#include <boost/test/unit_test.hpp>

#include "test_support.hpp"

#include "rollkin/io/dxf.hpp"

#include <cmath>
#include <filesystem>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using rollkin::BezierPath;
using rollkin::BezierSegment;
using rollkin::DxfContour;
using rollkin::DxfSelection;
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
  return rollkin::read_dxf_contour(kDir + file + ".dxf", DxfSelection{layer, ""});
}

/// Distance from q to one Bezier segment: the best of 64 samples, then Newton on (C(t) - q) . C'(t) = 0.
double distance_to_segment(const BezierSegment<double>& seg, const V& q) {
  const BezierPath<double> path({seg}, false);
  double best_t = 0, best = 1e300;
  for (int k = 0; k <= 64; ++k) {
    const double t = k / 64.0, d = (path.jet(t, 0).p - q).norm();
    if (d < best) best = d, best_t = t;
  }
  double t = best_t;
  for (int it = 0; it < 8; ++it) {
    const auto j = path.jet(t, 2);
    const double f = (j.p - q).dot(j.d1), df = j.d1.squaredNorm() + (j.p - q).dot(j.d2);
    if (!(df > 0)) break;
    t = std::min(1.0, std::max(0.0, t - f / df));
  }
  return std::min(best, (path.jet(t, 0).p - q).norm());
}

double distance_to_contour(const DxfContour& c, const V& q) {
  double best = 1e300;
  for (const auto& s : c.segments) best = std::min(best, distance_to_segment(s, q));
  return best;
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
    double worst = 0;
    for (const V& q : a.points) worst = std::max(worst, distance_to_contour(c, q) / size);
    std::printf("%-16s %-18s %3zu segments, %4zu ezdxf points, max distance / size = %.2e\n", file.c_str(), layer.c_str(),
                c.segments.size(), a.points.size(), worst);
    BOOST_TEST(worst < 1e-12);
    BOOST_TEST((c.segments.front().points.front() - a.points.front()).norm() <= 1e-12 * size);
    const BezierPath<double> path(c.segments, c.closed);  // the path splits at the same corners
    BOOST_TEST(path.corners().size() == c.corners.size());
    return c;
  }
  return {};
}

std::string dxf_error(const std::string& text, const std::string& layer) {
  return input_error_of([&] { rollkin::parse_dxf_contour(text, DxfSelection{layer, ""}, "inline.dxf"); });
}

/// A minimal DXF: an ENTITIES section holding `entities` (group pairs, one per line pair).
std::string minimal_dxf(const std::string& entities) { return "0\nSECTION\n2\nENTITIES\n" + entities + "0\nENDSEC\n0\nEOF\n"; }

const std::string kLine = "0\nLINE\n5\n2A\n8\nL\n10\n0\n20\n0\n30\n0\n11\n1\n21\n0\n31\n0\n";

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
  const DxfContour c = rollkin::read_dxf_contour(kDir + "splines_mm.dxf", DxfSelection{"", lower});
  BOOST_TEST(c.closed);
  BOOST_TEST(c.entities.size() == 1u);
  BOOST_TEST(contains(c.description, "handle " + lower));
}

BOOST_AUTO_TEST_CASE(fixture_errors_name_the_entities) {
  for (const std::string layer : {"GAP", "BRANCH", "TEXT", "INSERT", "FITONLY", "ORDER"}) {
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
  const std::string hatch = "0\nHATCH\n5\n3D\n8\nL\n10\n0\n20\n0\n";
  BOOST_TEST(contains(dxf_error(minimal_dxf(kLine + hatch), "L"), "HATCH 3D"));
  // the same entities on another layer do not matter
  const std::string other = "0\nMLINE\n5\n3C\n8\nNOTES\n10\n0\n20\n0\n";
  BOOST_TEST(rollkin::parse_dxf_contour(minimal_dxf(kLine + other), DxfSelection{"l", ""}).segments.size() == 1u);
}

BOOST_AUTO_TEST_CASE(malformed_text_is_refused_with_its_location) {
  const std::string bad_number = "0\nLINE\n5\n2A\n8\nL\n10\n0\n20\n1.5abc\n11\n1\n21\n0\n";
  const std::string m1 = dxf_error(minimal_dxf(bad_number), "L");
  BOOST_TEST(contains(m1, "inline.dxf:line 14"));
  BOOST_TEST(contains(m1, "LINE 2A: group 20 value \"1.5abc\" is not a finite number"));
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
  const std::string ratio = "0\nELLIPSE\n5\n6C\n8\nL\n10\n0\n20\n0\n11\n2\n21\n0\n40\n1.5\n41\n0\n42\n1\n";
  BOOST_TEST(contains(dxf_error(minimal_dxf(ratio), "L"), "ELLIPSE 6C has axis ratio 1.5"));
  const std::string bad_knots = "0\nSPLINE\n5\n6D\n8\nL\n71\n1\n72\n4\n73\n2\n40\n0\n40\n1\n40\n0\n40\n1\n10\n0\n20\n0\n10\n1\n20\n1\n";
  BOOST_TEST(contains(dxf_error(minimal_dxf(bad_knots), "L"), "SPLINE 6D is not a valid NURBS curve: NURBS: knots must be non-decreasing"));
  const std::string circle = "0\nCIRCLE\n5\n6E\n8\nL\n10\n5\n20\n0\n40\n1\n";
  BOOST_TEST(contains(dxf_error(minimal_dxf(kLine + circle), "L"), "CIRCLE 6E is closed on its own but is not the only entity selected"));
  const std::string huge_bulge = "0\nLWPOLYLINE\n5\n6G\n8\nL\n90\n2\n10\n0\n20\n0\n42\n1e300\n10\n1\n20\n0\n";
  BOOST_TEST(contains(dxf_error(minimal_dxf(huge_bulge), "L"), "LWPOLYLINE 6G at vertex 0: bulge 1e+300 gives no finite arc"));
  // Angles far outside one turn are reduced, not looped over (a fuzzer's 1e300 degrees must not hang).
  const std::string far_arc = "0\nARC\n5\n6H\n8\nL\n10\n0\n20\n0\n40\n1\n50\n1e300\n51\n-1e300\n";
  BOOST_TEST(rollkin::parse_dxf_contour(minimal_dxf(far_arc), DxfSelection{"L", ""}).segments.size() >= 1u);
  // An ELLIPSE whose end parameter was rounded just past start + 2 pi is still the full ellipse.
  const std::string rounded = "0\nELLIPSE\n5\n6J\n8\nL\n10\n0\n20\n0\n11\n2\n21\n0\n40\n0.5\n41\n0.5\n42\n6.783185307179587\n";
  const DxfContour full = rollkin::parse_dxf_contour(minimal_dxf(rounded), DxfSelection{"L", ""});
  BOOST_TEST(full.closed);
  BOOST_TEST(full.segments.size() == 4u);
  // Two vertices 1e-14 apart in a drawing of size 1: a piece below the join tolerance (found by fuzzing).
  const std::string tiny = "0\nLWPOLYLINE\n5\n6K\n8\nL\n90\n3\n10\n0\n20\n0\n10\n1\n20\n0\n42\n1\n10\n1\n20\n1e-14\n";
  BOOST_TEST(contains(dxf_error(minimal_dxf(tiny), "L"), "LWPOLYLINE 6K has a piece at (1, 0) no longer than the join tolerance"));
  const std::string zero_line = "0\nLINE\n5\n6F\n8\nL\n10\n1\n20\n1\n11\n1\n21\n1\n";
  BOOST_TEST(contains(dxf_error(minimal_dxf(zero_line), "L"), "LINE 6F has zero length"));
}

BOOST_AUTO_TEST_CASE(selection_errors) {
  const std::string text = minimal_dxf(kLine);
  BOOST_TEST(contains(dxf_error(text, "CAM"), "no entity on layer \"CAM\" in the ENTITIES section (layers with entities: \"L\")"));
  BOOST_TEST(contains(input_error_of([&] { rollkin::parse_dxf_contour(text, DxfSelection{"", "FF"}); }), "no entity with handle FF"));
  BOOST_TEST(contains(input_error_of([&] { rollkin::parse_dxf_contour(text, DxfSelection{"L", "2A"}); }), "exactly one of the two"));
  BOOST_TEST(contains(input_error_of([&] { rollkin::read_dxf_contour(kDir + "missing.dxf", DxfSelection{"L", ""}); }),
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
      const std::string message = input_error_of([&] { rollkin::parse_dxf_contour(text, DxfSelection{}, "bad.dxf"); });
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
    const std::string message = input_error_of([&] { rollkin::parse_dxf_contour(text, DxfSelection{}, "fit.dxf"); });
    BOOST_TEST(contains(message, "fit.dxf"));
    BOOST_TEST(contains(message, "line 10"));  // the value line of group 74
    BOOST_TEST(contains(message, "SPLINE: group 74 count \"1056964608\" is impossible"));
  }
  // A LEADER's vertex count (group 76) in ENTITIES, named by its handle.
  const std::string leader = "0\nSECTION\n2\nENTITIES\n0\nLEADER\n5\n4C\n76\n1500000000\n0\nENDSEC\n0\nEOF\n";
  BOOST_TEST(contains(input_error_of([&] { rollkin::parse_dxf_contour(leader, DxfSelection{}, "l.dxf"); }),
                      "LEADER 4C: group 76 count 1500000000 is impossible"));
}
