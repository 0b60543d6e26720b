#define BOOST_TEST_MODULE io_svg_path
#include <boost/test/unit_test.hpp>

#include "test_support.hpp"

#include "rollkin/io/svg/path_data.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

using rollkin::BezierPath;
using rollkin::io::InputError;
using rollkin::io::parse_svg_path_data;
using rollkin::io::SvgPathOptions;
using rollkin::io::SvgSubpath;
using V = rollkin::Vec2<double>;

namespace {

const SvgPathOptions kNoFlip{false, 1.0};

std::vector<SvgSubpath> parse(const std::string& d) { return parse_svg_path_data(d, kNoFlip); }

/// End points of all segments of the first subpath.
std::vector<V> ends(const std::string& d) {
  const auto subpaths = parse(d);
  std::vector<V> out;
  for (const auto& s : subpaths.at(0).segments) out.push_back(s.points.back());
  return out;
}

bool same(const V& a, const V& b) { return (a - b).norm() < 1e-14; }

std::string error_for(const std::string& d) {
  return rollkin::testing::input_error_of([&] { parse_svg_path_data(d, kNoFlip, "shape.svg", "cam"); });
}

using rollkin::testing::contains;

std::string write_temp(const std::string& name, const std::string& text) {
  return rollkin::testing::write_text(rollkin::testing::scratch_dir("io_svg_path") / name, text);
}

}  // namespace

BOOST_AUTO_TEST_CASE(lines_absolute_relative_and_close) {
  const auto subs = parse("M 10 20 L 30 40 H 50 V 60 l 5 5 h -5 v -5 Z");
  BOOST_TEST(subs.size() == 1u);
  BOOST_TEST(subs[0].closed);
  const std::vector<V> expected{V(30, 40), V(50, 40), V(50, 60), V(55, 65), V(50, 65), V(50, 60), V(10, 20)};
  const auto& segs = subs[0].segments;
  BOOST_TEST(segs.size() == expected.size());
  for (std::size_t i = 0; i < segs.size(); ++i) {
    BOOST_TEST(segs[i].degree() == 1);
    BOOST_TEST(same(segs[i].points.back(), expected[i]));
  }
  BOOST_TEST(same(segs[0].points.front(), V(10, 20)));
}

BOOST_AUTO_TEST_CASE(implicit_repetition_and_compact_numbers) {
  const auto e = ends("M 0 0 1 1 2 0");  // extra pairs after M are line-tos
  BOOST_TEST(e.size() == 2u);
  BOOST_TEST(same(e[1], V(2, 0)));
  const auto r = parse("m 1 1 2 2");
  BOOST_TEST(same(r[0].segments[0].points.front(), V(1, 1)));
  BOOST_TEST(same(r[0].segments[0].points.back(), V(3, 3)));
  const auto c = parse("M-.5.5L1e-1-2l.5-.5,1E1 0");
  BOOST_TEST(same(c[0].segments[0].points.front(), V(-0.5, 0.5)));
  BOOST_TEST(same(c[0].segments[0].points.back(), V(0.1, -2)));
  BOOST_TEST(same(c[0].segments[1].points.back(), V(0.6, -2.5)));
  BOOST_TEST(same(c[0].segments[2].points.back(), V(10.6, -2.5)));
  const auto two = parse("M0 0 L1 0 M 5 5 L 6 6");
  BOOST_TEST(two.size() == 2u);
  BOOST_TEST(!two[0].closed);
}

BOOST_AUTO_TEST_CASE(cubic_and_quadratic_with_reflection) {
  const auto c = parse("M0 0 C 1 2 3 4 5 6 S 9 10 11 12 s 1 1 2 0")[0].segments;
  BOOST_TEST(c.size() == 3u);
  BOOST_TEST(c[0].degree() == 3);
  BOOST_TEST(same(c[1].points[1], V(7, 8)));  // (3, 4) reflected through (5, 6)
  BOOST_TEST(same(c[1].points[2], V(9, 10)));
  BOOST_TEST(same(c[2].points[1], V(13, 14)));  // (9, 10) reflected through (11, 12)
  BOOST_TEST(same(c[2].points[2], V(12, 13)));
  BOOST_TEST(same(c[2].points[3], V(13, 12)));
  const auto rc = parse("M1 1 c 1 0 2 1 2 2")[0].segments[0];
  BOOST_TEST(same(rc.points[1], V(2, 1)));
  BOOST_TEST(same(rc.points[3], V(3, 3)));
  const auto q = parse("M0 0 Q 1 1 2 0 T 4 0 t 2 0")[0].segments;
  BOOST_TEST(q[0].degree() == 2);
  BOOST_TEST(same(q[1].points[1], V(3, -1)));  // (1, 1) reflected through (2, 0)
  BOOST_TEST(same(q[2].points[1], V(5, 1)));
  BOOST_TEST(same(q[2].points[2], V(6, 0)));
  // S without a preceding C uses the current point as first control point.
  BOOST_TEST(same(parse("M0 0 L 1 0 S 2 1 3 0")[0].segments[1].points[1], V(1, 0)));
}

BOOST_AUTO_TEST_CASE(arc_flags_compact_and_endpoints) {
  const auto a = parse("M0 0a 1 1 0 01 1 1");  // large-arc 0, sweep 1 packed as "01"
  const auto& segs = a[0].segments;
  BOOST_TEST(segs.size() == 1u);
  BOOST_TEST(segs[0].rational());
  BOOST_TEST(same(segs[0].points.back(), V(1, 1)));
  // Quarter circle of radius 1: centre at (1, 0) or (0, 1); sweep 1 (clockwise on screen) gives (0, 1).
  const BezierPath<double> p(segs, false);
  for (double u = 0; u <= 1; u += 0.05) BOOST_TEST(std::abs((p.jet(u, 0).p - V(0, 1)).norm() - 1) < 1e-15);
  BOOST_TEST(std::abs(segs[0].weights[1] - std::sqrt(0.5)) < 1e-15);
}

BOOST_AUTO_TEST_CASE(arc_reproduces_the_circle_exactly) {
  const auto subs = parse("M 3 2 A 2 2 0 1 1 -1 2 A 2 2 0 1 1 3 2 Z");  // full circle, centre (1, 2)
  BOOST_TEST(subs[0].closed);
  BOOST_TEST(subs[0].segments.size() == 4u);  // two half circles, two quarter pieces each
  const BezierPath<double> circle(subs[0].segments, true);
  double worst = 0;
  for (int k = 0; k <= 400; ++k) {
    const auto j = circle.jet(k / 100.0, 2);
    worst = std::max(worst, std::abs((j.p - V(1, 2)).norm() - 2));
    BOOST_TEST(std::abs(std::abs(rollkin::contour_point(j, 2).curvature()) - 0.5) < 1e-14);
  }
  BOOST_TEST(worst < 1e-14);
  BOOST_TEST(std::abs(circle.total_length() - 4 * M_PI) < 1e-13);
  // Sweep 1 passes through the screen-"positive" angle side: (1, 4) in y-down coordinates.
  BOOST_TEST(same(circle.jet(1.0, 0).p, V(1, 4)));
  // Flipped into y-up: the same point becomes (1, -4); points stay on the mirrored circle.
  const auto flipped = parse_svg_path_data("M 3 2 A 2 2 0 1 1 -1 2 A 2 2 0 1 1 3 2 Z");
  const BezierPath<double> fc(flipped[0].segments, true);
  BOOST_TEST(same(fc.jet(1.0, 0).p, V(1, -4)));
  BOOST_TEST(std::abs((fc.jet(0.37, 0).p - V(1, -2)).norm() - 2) < 1e-14);
}

BOOST_AUTO_TEST_CASE(arc_radii_correction_and_rotated_ellipse) {
  // Radius 1 cannot span a chord of 4: scaled to 2, a half circle centred at (2, 0).
  const auto small = parse("M 0 0 A 1 1 0 0 1 4 0")[0].segments;
  const BezierPath<double> half(small, false);
  for (double u = 0; u <= 2; u += 0.1) BOOST_TEST(std::abs((half.jet(u, 0).p - V(2, 0)).norm() - 2) < 1e-14);
  // Ellipse rx = 2, ry = 1 rotated 30 degrees, centre (0, 0): from its +a vertex to its +b vertex.
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  const V a_vertex(2 * c, 2 * s), b_vertex(-s, c);
  const std::string d = "M " + std::to_string(a_vertex.x()) + " " + std::to_string(a_vertex.y()) + " A 2 1 30 0 1 " +
                        std::to_string(b_vertex.x()) + " " + std::to_string(b_vertex.y());
  const auto segs = parse(d)[0].segments;
  const BezierPath<double> arc(segs, false);
  for (double u = 0; u <= arc.domain().hi; u += 0.05) {
    const V p = arc.jet(u, 0).p;
    const double x = c * p.x() + s * p.y(), y = -s * p.x() + c * p.y();
    BOOST_TEST(std::abs(x * x / 4 + y * y - 1) < 1e-6);  // endpoints were printed with 6 decimals
  }
  BOOST_TEST(same(segs.back().points.back(), V(std::stod(std::to_string(b_vertex.x())), std::stod(std::to_string(b_vertex.y())))));
  // Zero radius: a straight line.
  BOOST_TEST(parse("M 0 0 A 0 1 0 0 1 4 0")[0].segments[0].degree() == 1);
}

BOOST_AUTO_TEST_CASE(flip_and_scale) {
  const auto subs = parse_svg_path_data("M 1 2 L 3 4", SvgPathOptions{true, 10.0});
  BOOST_TEST(same(subs[0].segments[0].points[0], V(10, -20)));
  BOOST_TEST(same(subs[0].segments[0].points[1], V(30, -40)));
}

BOOST_AUTO_TEST_CASE(path_data_errors_name_the_command_and_offset) {
  BOOST_TEST(contains(error_for("L 0 0"), "shape.svg:path \"cam\", d offset 0: path data must begin with a moveto"));
  BOOST_TEST(contains(error_for(""), "empty"));
  BOOST_TEST(contains(error_for("M 0 0 X 1"), "command 2 (X), d offset 6: unknown path command 'X'"));
  BOOST_TEST(contains(error_for("M 0 0 L 1"), "command 2 (L), d offset 9: expected a number (argument 2 of 2 of the 'L' command), got the end"));
  BOOST_TEST(contains(error_for("M 0 0 C 1 1 2 x 3 3"), "command 2 (C), d offset 14: expected a number (argument 4 of 6"));
  BOOST_TEST(contains(error_for("M0 0 A 1 1 0 2 1 3 3"), "command 2 (A), d offset 13: expected a flag 0 or 1"));
  BOOST_TEST(contains(error_for("M 0 0 Z 1 1"), "command 2 (Z), d offset 8: unexpected character '1'"));
  // Coordinate sets repeated without their letter are counted within the command, as the user reads them.
  BOOST_TEST(contains(error_for("M 0 0 L 1 1 2 2 3"), "command 2 (L, set 3), d offset 17: expected a number"));
  BOOST_TEST(contains(error_for("M 0 0 L 1 1 2 1e999"), "command 2 (L, set 2), d offset 14: number 1e999 out of range"));
  BOOST_TEST(contains(error_for("m 1e308 0 l 1e308 0"), "command 2 (l), d offset 19: the coordinates overflow"));
}

// A defect the fuzzing found (docs/reliability.md, "How it is tested"): a path closed by Z after a last point equal
// to the first up to round-off used to keep a closing segment of length 4e-16, which BezierPath rejects as "segment 4
// is degenerate".
BOOST_AUTO_TEST_CASE(closing_point_equal_to_the_first_to_round_off_is_dropped) {
  const auto subs = parse("M 3 2 A 2 2 0 1 1 -1 2 A 2 2 0 1 1 3.0000000000000004 2 Z");
  BOOST_TEST(subs.size() == 1u);
  BOOST_TEST(subs[0].closed);
  BOOST_TEST(subs[0].segments.size() == 4u);  // two half circles, two quarter pieces each; no closing line
  BOOST_TEST((subs[0].segments.back().points.back() == V(3, 2)));  // snapped onto the first point
  const BezierPath<double> circle(subs[0].segments, true);
  BOOST_TEST(std::abs(circle.total_length() - 4 * M_PI) < 1e-13);
  // The origins name the commands in the user's numbering.
  BOOST_TEST(subs[0].origins.front() == "command 2 (A)");
  BOOST_TEST(subs[0].origins.back() == "command 3 (A)");
  // The same with a polygonal path: the duplicate closing point goes, the last L becomes the closing edge.
  const auto poly = parse("M 0.1 0.2 L 10 0 L 10 10 L 0.10000000000000002 0.2 Z");
  BOOST_TEST(poly[0].segments.size() == 3u);
  BOOST_TEST((poly[0].segments.back().points.back() == V(0.1, 0.2)));
  BOOST_TEST(poly[0].origins.back() == "command 4 (L)");
  // A visible gap is not round-off: Z draws the closing line.
  BOOST_TEST(parse("M 0 0 L 10 0 L 10 10 L 0.001 0 Z")[0].segments.size() == 4u);
}

// Radii scaled up to span the chord (F.6.6) make the arc a half ellipse about the chord's midpoint; the
// centre formula F.6.5.2 reaches it only through sqrt(round-off), which used to leave the end tangents of
// this arc 1.3e-7 rad from parallel. Exactly half: the tangents at both ends are parallel, to round-off.
BOOST_AUTO_TEST_CASE(scaled_up_radii_give_an_exact_half_ellipse) {
  const auto segs = parse("M 100 200 A 59 11 12 0 1 260 230")[0].segments;
  BOOST_TEST(segs.size() == 2u);
  const V t0 = segs.front().points[1] - segs.front().points[0], t1 = segs.back().points[2] - segs.back().points[1];
  BOOST_TEST(std::abs(t0.x() * t1.y() - t0.y() * t1.x()) / (t0.norm() * t1.norm()) < 1e-15);
}

// Radii so small that lambda = (x1/rx)^2 + (y1/ry)^2 overflows (fuzz_svg: NaN radii, then a NaN cast to int):
// scaled up they span the chord, the half circle of diameter (0, 0)-(10, 10); radii whose ratio overflows
// leave the chord itself.
BOOST_AUTO_TEST_CASE(tiny_radii_give_the_half_circle_over_the_chord) {
  for (const std::string d : {"M0 0 A1e-300 1e-300 45 1 1 10 10", "M0 0 A1e-300 1e-300 0 0 0 10 10"}) {
    BOOST_TEST_CONTEXT(d) {
      const auto segs = parse(d)[0].segments;
      BOOST_REQUIRE_EQUAL(segs.size(), 2u);
      for (const auto& s : segs) {
        BOOST_REQUIRE_EQUAL(s.weights.size(), 3u);
        for (double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {  // the rational quadratic at t
          const double b0 = (1 - t) * (1 - t), b1 = 2 * t * (1 - t), b2 = t * t;
          const double w = b0 * s.weights[0] + b1 * s.weights[1] + b2 * s.weights[2];
          const V p = (b0 * s.weights[0] * s.points[0] + b1 * s.weights[1] * s.points[1] + b2 * s.weights[2] * s.points[2]) / w;
          BOOST_TEST(std::abs((p - V(5, 5)).norm() - std::sqrt(50.0)) < 1e-13);
        }
      }
    }
  }
  const auto flat = parse("M0 0 A1e300 1e-300 30 0 1 10 10")[0].segments;
  BOOST_REQUIRE_EQUAL(flat.size(), 1u);
  BOOST_TEST(flat[0].points.size() == 2u);
}

// fuzz_svg (session 6): a chord of 1.1e-299 under radii (300, 45) underflowed the centre formula (F.6.5.2) to
// an infinite factor and a NaN centre, later cast to int. The large arc is then the whole ellipse but for the
// chord: 600 wide and 90 high; the small arc is no more than the chord.
BOOST_AUTO_TEST_CASE(a_chord_tiny_against_the_radii_keeps_the_ellipse) {
  auto extent = [](const auto& segs) {
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (const auto& s : segs)
      for (double t = 0; t <= 1; t += 1.0 / 64) {  // the rational quadratic at t
        const double b0 = (1 - t) * (1 - t), b1 = 2 * t * (1 - t), b2 = t * t;
        const double w = b0 * s.weights[0] + b1 * s.weights[1] + b2 * s.weights[2];
        const V p = (b0 * s.weights[0] * s.points[0] + b1 * s.weights[1] * s.points[1] + b2 * s.weights[2] * s.points[2]) / w;
        BOOST_REQUIRE(std::isfinite(p.x()) && std::isfinite(p.y()));
        x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x()), y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
      }
    return V(x1 - x0, y1 - y0);
  };
  const V large = extent(parse("M0 0 A-300 45 0 1 1 0 1.1e-299")[0].segments);
  BOOST_TEST(std::abs(large.x() - 600) < 1e-9 * 600);
  BOOST_TEST(std::abs(large.y() - 90) < 1e-9 * 90);
  // Radii 10 and 1e-310 (a subnormal): the direction to the centre overflows; the chord is left.
  for (const auto& sub : parse("M0 0 A10 1e-310 45 1 1 0 1e-310"))
    for (const auto& seg : sub.segments)
      for (const V& p : seg.points) BOOST_TEST((std::isfinite(p.x()) && std::isfinite(p.y())));
  // The small arc is as degenerate as the straight line over the same chord, and read like it.
  BOOST_TEST(parse("M0 0 A300 45 0 0 1 0 1.1e-299").size() == parse("M0 0 L0 1.1e-299").size());
}

// Pieces shorter than the tolerance are merged into their neighbours, not removed: the path still ends where
// it ends. 10^5 steps "l 0 1e-6" after a 500-long line are each below the tolerance (joint tolerance 1.5e-8
// times the extent 500: 7.5e-6) but carry the path 0.1 up; they used to be folded one by one into the line,
// which ended at (400, 0.1) tilted, 500.00001 long and without its corner. Closed form: a line of 500 and
// a line of 0.1 at right angles, 500.1 long.
BOOST_AUTO_TEST_CASE(pieces_shorter_than_the_tolerance_are_merged_and_the_path_ends_where_it_ends) {
  std::string d = "M -100 0 L 400 0";
  for (int i = 0; i < 100000; ++i) d += " l 0 1e-6";
  const auto subs = parse(d);
  BOOST_REQUIRE(subs.size() == 1u);
  const BezierPath<double> path(subs[0].segments, false);
  const V end = path.jet(path.domain().hi, 0).p;
  BOOST_TEST((end - V(400, 0.1)).norm() < 1e-11);  // 10^5 additions of 1e-6: round-off about 1e-12
  BOOST_TEST(std::abs(path.total_length() - 500.1) < 1e-12 * 500.1);
  BOOST_TEST(subs[0].segments.size() == 2u);  // the steps, collinear, are one line
  BOOST_TEST(((subs[0].segments.front().points.back() - V(400, 0)).norm() < 1e-5));  // the line keeps its end
  BOOST_REQUIRE(path.corners().size() == 1u);  // the right angle at (400, 0)
  BOOST_TEST(std::abs(path.corners()[0].turn - M_PI / 2) < 1e-4);
  BOOST_TEST(contains(subs[0].origins.back(), "through command 100002 (l)"));

  // A curved run of short steps keeps its shape: 10^4 steps of 6.3e-6 around a circle of radius 0.01 after a
  // 1000-long line (tolerance 1.5e-5). Every vertex of the merged pieces is a vertex of the path (on the circle
  // to round-off), every vertex of the path lies within twice the tolerance of them, and the length is the
  // line's plus the circle's, short of it by at most the chords' sagitta (h / 3r of the circle for h <= 2 tol).
  const int steps = 10000;
  const double r = 0.01;
  std::string c = "M -1000 0 L 0 0";
  V at(0, 0);
  for (int k = 1; k <= steps; ++k) {
    const double t = 2 * M_PI * k / steps;
    const V next(r * std::sin(t), r - r * std::cos(t));
    char buf[96];
    std::snprintf(buf, sizeof buf, " l %.17g %.17g", next.x() - at.x(), next.y() - at.y());
    c += buf;
    at = next;
  }
  const auto circle = parse(c);
  BOOST_REQUIRE(circle.size() == 1u);
  const auto& chords = circle[0].segments;
  BOOST_TEST(chords.size() > 20u);  // not one chord
  double worst = 0;
  for (std::size_t i = 1; i < chords.size(); ++i)
    worst = std::max(worst, std::abs((chords[i].points.front() - V(0, r)).norm() - r));
  BOOST_TEST(worst < 1e-12);
  const double tol = rollkin::BezierPathOptions<double>{}.joint_tolerance * std::hypot(1000.0, 2 * r);
  auto distance_to_chords = [&](const V& q) {
    double d = INFINITY;
    for (std::size_t i = 1; i < chords.size(); ++i) {
      const V a = chords[i].points.front(), b = chords[i].points.back();
      const double t = std::clamp((q - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      d = std::min(d, (a + t * (b - a) - q).norm());
    }
    return d;
  };
  double farthest = 0;
  for (int k = 1; k <= steps; ++k) {
    const double t = 2 * M_PI * k / steps;
    farthest = std::max(farthest, distance_to_chords(V(r * std::sin(t), r - r * std::cos(t))));
  }
  BOOST_TEST(farthest <= 2 * tol);
  const BezierPath<double> loop(chords, false);
  BOOST_TEST(loop.total_length() <= 1000 + 2 * M_PI * r + 1e-12 * 1000);
  BOOST_TEST(loop.total_length() >= 1000 + 2 * M_PI * r - 2 * M_PI * r * (2 * tol) / (3 * r) - 1e-12 * 1000);
  BOOST_TEST(((loop.jet(loop.domain().hi, 0).p - V(0, 0)).norm() < 1e-12));
}
