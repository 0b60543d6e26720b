// Exact predicates and tables against exact rational arithmetic done by hand (the expected decimal strings
// were derived independently with Python's fractions.Fraction from the same doubles).
#define BOOST_TEST_MODULE geometry_exact
#include <boost/test/unit_test.hpp>

#include "rollkin/geometry/exact.hpp"

#include <cmath>

BOOST_TEST_DONT_PRINT_LOG_VALUE(rollkin::geometry::SegmentLocation)
BOOST_TEST_DONT_PRINT_LOG_VALUE(rollkin::geometry::PolylineLocation::Kind)

using rollkin::Vec2;
using namespace rollkin::geometry;
using P = Vec2<double>;

namespace {

/// The naive double orientation test: the cross product of the edge vectors, rounded at each step.
double naive_cross(const P& p, const P& q, const P& r) {
  return (q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x());
}

}  // namespace

BOOST_AUTO_TEST_CASE(decimal_expansion_of_doubles) {
  BOOST_TEST(exact_decimal(0.1) == "0.1000000000000000055511151231257827021181583404541015625");
  BOOST_TEST(exact_decimal(-2.5) == "-2.5");
  BOOST_TEST(exact_decimal(3) == "3");
  BOOST_TEST(exact_decimal(0) == "0");
  BOOST_TEST(exact_decimal(0.0625) == "0.0625");
  BOOST_TEST(exact_decimal(1e20) == "100000000000000000000");
}

// On the line y = x + 0.2 in decimal, but not in binary: the doubles 0.1, 0.2, 0.3, 0.4, 0.5 are not the
// decimals. Rounding makes the naive test say "collinear"; exactly, the turn is clockwise.
BOOST_AUTO_TEST_CASE(naive_double_says_collinear_exact_says_clockwise) {
  const P p(0.1, 0.3), q(0.2, 0.4), r(0.3, 0.5);
  BOOST_TEST(naive_cross(p, q, r) == 0.0);
  BOOST_TEST(exact_orientation(p, q, r) == -1);
  BOOST_TEST(!exactly_collinear(p, q, r));
  BOOST_TEST(exact_orientation(q, p, r) == 1);
  // Half the exact cross product, i.e. the signed area of the triangle.
  BOOST_TEST(exact_signed_area({p, q, r}) ==
             "-0.0000000000000000013877787807814453673807484831557889016685291864116290339037362855378887616"
             "097927093505859375");
}

// The converse: the naive test sees a turn where the doubles are exactly collinear.
BOOST_AUTO_TEST_CASE(naive_double_sees_a_turn_exact_says_collinear) {
  const P p(0.1, 0.1), q(0.2, 0.4), r(0.3, 0.7);
  BOOST_TEST(naive_cross(p, q, r) != 0.0);
  BOOST_TEST(exactly_collinear(p, q, r));
  BOOST_TEST(exact_orientation(p, q, r) == 0);
  BOOST_TEST(locate_on_segment_exact(q, p, r) == SegmentLocation::Inside);
}

BOOST_AUTO_TEST_CASE(points_on_segments) {
  const P a(0, 0), b(1, 3);
  BOOST_TEST(locate_on_segment_exact(a, a, b) == SegmentLocation::AtStart);
  BOOST_TEST(locate_on_segment_exact(b, a, b) == SegmentLocation::AtEnd);
  BOOST_TEST(locate_on_segment_exact(P(0.5, 1.5), a, b) == SegmentLocation::Inside);
  // 3 * 0.1 (as doubles, exactly) is not the double 0.3: the point read as "0.1 0.3" is off the segment.
  BOOST_TEST(locate_on_segment_exact(P(0.1, 0.3), a, b) == SegmentLocation::Off);
  BOOST_TEST(point_on_segment_exact(P(0.25, 0.75), a, b));
  BOOST_TEST(!point_on_segment_exact(P(2, 6), a, b));  // on the line, beyond the end
  BOOST_TEST(!point_on_segment_exact(P(-1, -3), a, b));
  BOOST_TEST(locate_on_segment_exact(P(1, 1), P(1, 1), P(1, 1)) == SegmentLocation::AtStart);
  BOOST_TEST(locate_on_segment_exact(P(2, 2), P(1, 1), P(1, 1)) == SegmentLocation::Off);
}

BOOST_AUTO_TEST_CASE(contact_exactly_at_a_sample_or_inside_a_segment) {
  const std::vector<P> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  using Kind = PolylineLocation::Kind;
  const auto at_joint = locate_on_polyline_exact(P(1, 1), square, true);
  BOOST_TEST(at_joint.kind == Kind::AtSample);
  BOOST_TEST(at_joint.index == 2u);
  const auto on_closing = locate_on_polyline_exact(P(0, 0.5), square, true);
  BOOST_TEST(on_closing.kind == Kind::InsideSegment);
  BOOST_TEST(on_closing.index == 3u);
  BOOST_TEST((locate_on_polyline_exact(P(0, 0.5), square, false).kind == Kind::Off));  // no closing segment
  BOOST_TEST((locate_on_polyline_exact(P(0.5, 0.5), square, true).kind == Kind::Off));
  // One ulp beside a sample is not at the sample, and not on either segment through it.
  BOOST_TEST((locate_on_polyline_exact(P(1, std::nextafter(1.0, 2.0)), square, true).kind == Kind::Off));
}

BOOST_AUTO_TEST_CASE(squared_chords_and_areas) {
  const std::vector<P> pts{{0, 0}, {0.1, 0}, {0.1, 0.2}};
  const auto chords = exact_squared_chords(pts, false);
  BOOST_TEST_REQUIRE(chords.size() == 2u);
  BOOST_TEST(chords[0] == "0.010000000000000001110223024625156571238510778286593961395647081358837096609626371"
                          "44621112383902072906494140625");  // 0.1^2 in doubles, exactly
  BOOST_TEST(chords[1] == "0.040000000000000004440892098500626284954043113146375845582588325435348386438505485"
                          "784844495356082916259765625");  // 0.2^2
  const auto closed = exact_squared_chords({{0, 0}, {3, 0}, {3, 4}}, true);
  BOOST_TEST_REQUIRE(closed.size() == 3u);
  BOOST_TEST(closed[0] == "9");
  BOOST_TEST(closed[1] == "16");
  BOOST_TEST(closed[2] == "25");
  BOOST_TEST(exact_signed_area({{0, 0}, {1, 0}, {1, 1}, {0, 1}}) == "1");
  BOOST_TEST(exact_signed_area({{0, 0}, {0, 1}, {1, 1}, {1, 0}}) == "-1");
  BOOST_TEST(exact_signed_area({{0, 0}, {3, 0}, {3, 4}}) == "6");
}
