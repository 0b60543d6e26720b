// Sampled-contour validation against shapes whose defects are known by construction.
#define BOOST_TEST_MODULE geometry_validation
#include <boost/test/unit_test.hpp>

#include "rollkin/geometry/validation.hpp"

#include <chrono>
#include <cmath>
#include <iostream>
#include <random>
#include <stdexcept>

using rollkin::Vec2;
using namespace rollkin::geometry;
using Points = std::vector<Vec2<double>>;

namespace {

const double kPi = std::acos(-1.0);

/// n samples of a circle, counter-clockwise (material inside, on the left) unless `clockwise`;
/// `phase` shifts the samples by that fraction of the spacing.
Points circle(std::size_t n, double r, bool clockwise = false, double phase = 0) {
  Points p;
  for (std::size_t k = 0; k < n; ++k) {
    const double t = 2 * kPi * (double(k) + phase) / double(n) * (clockwise ? -1 : 1);
    p.emplace_back(r * std::cos(t), r * std::sin(t));
  }
  return p;
}

/// Figure-eight x = sin t, y = sin t cos t sampled at t_k = 2 pi (k + 1/2) / n (n even): the curve crosses
/// itself at the origin, halfway along segment n - 1 (closing, t = -h..h) and segment n/2 - 1 (t = pi -+ h).
Points figure_eight(std::size_t n) {
  Points p;
  for (std::size_t k = 0; k < n; ++k) {
    const double t = 2 * kPi * (double(k) + 0.5) / double(n);
    p.emplace_back(std::sin(t), std::sin(t) * std::cos(t));
  }
  return p;
}

std::size_t count(const ValidationReport& r, IssueKind kind) {
  std::size_t n = 0;
  for (const auto& i : r.issues) n += i.kind == kind;
  return n;
}

ValidationIssue only(const ValidationReport& r, IssueKind kind) {
  BOOST_TEST_REQUIRE(count(r, kind) == 1u);
  for (const auto& i : r.issues)
    if (i.kind == kind) return i;
  throw std::logic_error("unreachable");
}

// Independent crossing test for segments in general position (random data, no collinear triples).
bool segments_cross(const Vec2<double>& a, const Vec2<double>& b, const Vec2<double>& c, const Vec2<double>& d) {
  auto side = [](const Vec2<double>& p, const Vec2<double>& q, const Vec2<double>& r) {
    return (q - p).x() * (r - p).y() - (q - p).y() * (r - p).x() > 0;
  };
  return side(a, b, c) != side(a, b, d) && side(c, d, a) != side(c, d, b);
}

}  // namespace

BOOST_AUTO_TEST_CASE(clean_contours_have_no_issues) {
  const auto r = validate_polyline(circle(100, 2), true, MaterialSide::Left, 1e-9);
  BOOST_TEST(r.issues.empty());
  BOOST_TEST(r.signed_area > 0);
  BOOST_TEST(r.contour_size == 4 * std::sqrt(2.0), boost::test_tools::tolerance(1e-3));
  const auto open = validate_polyline({{0, 0}, {1, 0}, {1, 1}}, false, MaterialSide::Left, 1e-9);
  BOOST_TEST(open.issues.empty());
}

BOOST_AUTO_TEST_CASE(duplicated_sample_of_a_square) {
  const Points square{{0, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 1}};
  const auto r = validate_polyline(square, true, MaterialSide::Left, 1e-9);
  const auto i = only(r, IssueKind::CoincidentSamples);
  BOOST_TEST(i.first == 1u);
  BOOST_TEST(i.second == 2u);
  BOOST_TEST(r.issues.size() == 1u);  // the duplicate does not make the square self-intersecting
  BOOST_CHECK_EXCEPTION(throw_if_invalid(r, "shapes/cam.txt"), std::runtime_error, [](const std::runtime_error& e) {
    BOOST_TEST_MESSAGE(e.what());
    return std::string(e.what()) ==
           "shapes/cam.txt: samples 1 and 2 coincide (distance 0 < 1e-09 of the contour size); remove one";
  });
}

BOOST_AUTO_TEST_CASE(near_duplicate_within_relative_tolerance) {
  const Points pts{{0, 0}, {1, 0}, {1 + 1e-12, 0}, {1, 1}};
  const auto i = only(validate_polyline(pts, false, MaterialSide::Left, 1e-9), IssueKind::CoincidentSamples);
  BOOST_TEST(i.first == 1u);
  BOOST_TEST(i.value == 1e-12, boost::test_tools::tolerance(1e-3));
  BOOST_TEST(validate_polyline(pts, false, MaterialSide::Left, 1e-13).issues.empty());
}

BOOST_AUTO_TEST_CASE(figure_eight_crosses_at_the_origin) {
  const std::size_t n = 200;
  const auto r = validate_polyline(figure_eight(n), true, MaterialSide::Left, 1e-9);
  const auto i = only(r, IssueKind::SelfIntersection);
  BOOST_TEST(i.first == n / 2 - 1);
  BOOST_TEST(i.second == n - 1);
  BOOST_TEST(std::abs(i.point.x()) < 1e-15);
  BOOST_TEST(std::abs(i.point.y()) < 1e-15);
  BOOST_TEST(count(r, IssueKind::WrongMaterialSide) == 0u);  // undefined for a non-simple contour
  for (const auto& line : describe_issues(r, "eight.txt")) BOOST_TEST_MESSAGE(line);
}

BOOST_AUTO_TEST_CASE(bow_tie_crosses_through_the_closing_segment) {
  const Points bow{{0, 0}, {1, 1}, {1, 0}, {0, 1}};
  const auto i = only(validate_polyline(bow, true, MaterialSide::Left, 1e-9), IssueKind::SelfIntersection);
  BOOST_TEST(i.first == 0u);
  BOOST_TEST(i.second == 2u);
  BOOST_TEST(i.point == Vec2<double>(0.5, 0.5));
  // As an open polyline the segment 2 -> 3 is the one crossing segment 0.
  const auto open = validate_polyline(bow, false, MaterialSide::Left, 1e-9);
  BOOST_TEST(only(open, IssueKind::SelfIntersection).second == 2u);
}

BOOST_AUTO_TEST_CASE(spike_folds_back) {
  const auto end_spike = validate_polyline({{0, 0}, {2, 0}, {1, 0}}, false, MaterialSide::Left, 1e-9);
  BOOST_TEST(only(end_spike, IssueKind::FoldsBack).first == 1u);
  BOOST_TEST(end_spike.issues.size() == 1u);
  // Continuing after the spike starts segment 2 on segment 0: that touch is a self-intersection too.
  const auto spike = validate_polyline({{0, 0}, {2, 0}, {1, 0}, {1, 1}}, false, MaterialSide::Left, 1e-9);
  BOOST_TEST(only(spike, IssueKind::FoldsBack).first == 1u);
  const auto touch = only(spike, IssueKind::SelfIntersection);
  BOOST_TEST(touch.first == 0u);
  BOOST_TEST(touch.second == 2u);
  BOOST_TEST(touch.point == Vec2<double>(1, 0));
}

BOOST_AUTO_TEST_CASE(material_side_from_orientation) {
  const auto cw = circle(64, 1, true);
  const auto r = validate_polyline(cw, true, MaterialSide::Left, 1e-9);
  const auto i = only(r, IssueKind::WrongMaterialSide);
  BOOST_TEST(i.value < 0);
  BOOST_TEST(i.value == -64 / 2.0 * std::sin(2 * kPi / 64), boost::test_tools::tolerance(1e-12));
  BOOST_TEST(describe_issues(r, "c.txt").front().find("reverse the sample order") != std::string::npos);
  BOOST_TEST(validate_polyline(cw, true, MaterialSide::Right, 1e-9).issues.empty());
  BOOST_TEST(count(validate_polyline(circle(64, 1), true, MaterialSide::Right, 1e-9),
                   IssueKind::WrongMaterialSide) == 1u);
}

BOOST_AUTO_TEST_CASE(closed_contour_repeating_its_first_sample) {
  auto pts = circle(50, 1);
  pts.push_back(pts.front() + Vec2<double>(1e-13, 0));
  const auto r = validate_polyline(pts, true, MaterialSide::Left, 1e-9);
  BOOST_TEST(r.issues.empty());
  BOOST_TEST(r.dropped_closing_repeat);
  BOOST_TEST(r.sample_count == 50u);
  BOOST_TEST(r.notes.size() == 1u);
}

BOOST_AUTO_TEST_CASE(open_and_closed_declarations_that_do_not_fit) {
  // Closed contour given as open with its first sample repeated: warning only.
  auto loop = circle(40, 1);
  loop.push_back(loop.front());
  const auto open = validate_polyline(loop, false, MaterialSide::Left, 1e-9);
  const auto ends = only(open, IssueKind::OpenEndsMeet);
  BOOST_TEST(ends.first == 40u);
  BOOST_TEST(!open.has_errors());
  BOOST_CHECK_NO_THROW(throw_if_invalid(open, "loop.txt"));

  // Three quarters of a circle declared closed: the implicit closing chord spans the missing quarter.
  Points arc;
  for (int k = 0; k <= 30; ++k) arc.emplace_back(std::cos(1.5 * kPi * k / 30), std::sin(1.5 * kPi * k / 30));
  const auto closed = validate_polyline(arc, true, MaterialSide::Left, 1e-9);
  const auto gap = only(closed, IssueKind::LongClosingSegment);
  BOOST_TEST(gap.first == 30u);
  BOOST_TEST(gap.value == std::sqrt(2.0) / (2 * std::sin(1.5 * kPi / 60)), boost::test_tools::tolerance(1e-12));
  BOOST_TEST(validate_polyline(arc, false, MaterialSide::Left, 1e-9).issues.empty());
}

BOOST_AUTO_TEST_CASE(too_few_and_non_finite_samples) {
  BOOST_TEST(only(validate_polyline({{0, 0}, {1, 0}}, true, MaterialSide::Left, 1e-9), IssueKind::TooFewSamples)
                 .first == 2u);
  BOOST_TEST(count(validate_polyline({}, false, MaterialSide::Left, 1e-9), IssueKind::TooFewSamples) == 1u);
  const auto r = validate_polyline({{0, 0}, {NAN, 1}, {2, 2}}, false, MaterialSide::Left, 1e-9);
  BOOST_TEST(only(r, IssueKind::NonFiniteSample).first == 1u);
}

BOOST_AUTO_TEST_CASE(issue_lists_are_capped_with_a_note) {
  // A zig-zag between y = 0 and y = 1 followed by a straight line back along y = 1/2 crosses every tooth.
  Points p;
  for (int k = 0; k <= 20; ++k) p.emplace_back(k, k % 2);
  p.emplace_back(20, 0.5);
  p.emplace_back(-1, 0.5);
  const auto r = validate_polyline(p, false, MaterialSide::Left, 1e-9, 3);
  BOOST_TEST(r.self_intersections_found == 20u);
  BOOST_TEST(count(r, IssueKind::SelfIntersection) == 3u);
  BOOST_TEST_REQUIRE(r.notes.size() == 1u);
  BOOST_TEST(r.notes.front() == "17 more self-intersections not listed (20 in total)");
}

BOOST_AUTO_TEST_CASE(crossings_agree_with_brute_force_on_random_polylines) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 20; ++trial) {
    Points p(60);
    for (auto& q : p) q = Vec2<double>(u(rng), u(rng));
    std::size_t expected = 0;
    const std::size_t m = p.size() - 1;
    for (std::size_t i = 0; i < m; ++i)
      for (std::size_t j = i + 2; j < m; ++j) expected += segments_cross(p[i], p[i + 1], p[j], p[j + 1]);
    const auto r = validate_polyline(p, false, MaterialSide::Left, 1e-12, 10000);
    BOOST_TEST(r.self_intersections_found == expected);
    BOOST_TEST(count(r, IssueKind::SelfIntersection) == expected);
  }
}

BOOST_AUTO_TEST_CASE(million_samples_timing) {
  for (const bool eight : {false, true}) {
    const std::size_t n = 1000000;
    const Points pts = eight ? figure_eight(n) : circle(n, 1);
    const auto t0 = std::chrono::steady_clock::now();
    const auto r = validate_polyline(pts, true, MaterialSide::Left, 1e-12);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::cout << "validate_polyline, " << n << " samples (" << (eight ? "figure-eight" : "circle")
              << "): " << s << " s, " << r.issues.size() << " issue(s)\n";
    BOOST_TEST(r.issues.size() == (eight ? 1u : 0u));
  }
}
