// Closest points and interference of sampled contours against circle/ellipse geometry known in closed form.
#define BOOST_TEST_MODULE geometry_contact
#include <boost/test/unit_test.hpp>

#include "rollkin/geometry/contact.hpp"
#include "rollkin/se2.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <stdexcept>

using rollkin::Vec2;
using namespace rollkin::geometry;
using Points = std::vector<Vec2<double>>;
namespace tt = boost::test_tools;

namespace {

const double kPi = std::acos(-1.0);

/// n samples of the ellipse centre + (rx cos t, ry sin t), t_k = dir * 2 pi (k + phase) / n: counter-clockwise
/// for dir = +1 (a disk: material inside), clockwise for dir = -1 (the inner contour of a ring).
Points ellipse(std::size_t n, const Vec2<double>& centre, double rx, double ry, double phase = 0, int dir = 1) {
  Points p;
  for (std::size_t k = 0; k < n; ++k) {
    const double t = dir * 2 * kPi * (double(k) + phase) / double(n);
    p.emplace_back(centre.x() + rx * std::cos(t), centre.y() + ry * std::sin(t));
  }
  return p;
}

Points circle(std::size_t n, const Vec2<double>& centre, double r, double phase = 0, int dir = 1) {
  return ellipse(n, centre, r, r, phase, dir);
}

/// Depth of a chord of an n-gon inscribed in a circle of radius r below the arc (the sagitta).
double sagitta(double r, std::size_t n) { return r * (1 - std::cos(kPi / double(n))); }

double point_segment_distance(const Vec2<double>& q, const Vec2<double>& a, const Vec2<double>& b) {
  const Vec2<double> d = b - a;
  const double t = std::clamp((q - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (a + t * d - q).norm();
}

/// O(n m) reference for non-crossing open polylines.
double brute_force_distance(const Points& a, const Points& b) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < a.size(); ++i)
    for (std::size_t j = 0; j + 1 < b.size(); ++j)
      best = std::min({best, point_segment_distance(a[i], b[j], b[j + 1]),
                       point_segment_distance(a[i + 1], b[j], b[j + 1]), point_segment_distance(b[j], a[i], a[i + 1]),
                       point_segment_distance(b[j + 1], a[i], a[i + 1])});
  return best;
}

void check_consistent(const PolylinePoint& p, const Points& pts) {
  const std::size_t n = pts.size();
  const Vec2<double> expected = (1 - p.fraction) * pts[p.segment] + p.fraction * pts[(p.segment + 1) % n];
  BOOST_TEST((p.point - expected).norm() < 1e-12);
  BOOST_TEST(p.fraction >= 0.0);
  BOOST_TEST(p.fraction <= 1.0);
}

}  // namespace

// Circles of radii 1 and 4 with centres 5 + d apart: the true gap is d along the centre line.
BOOST_AUTO_TEST_CASE(separated_circles_with_aligned_samples) {
  const double d = 0.25;
  const std::size_t n1 = 200, n4 = 400;
  const auto a = circle(n1, {0, 0}, 1), b = circle(n4, {5 + d, 0}, 4);  // samples at (1, 0) and (1 + d, 0)
  const auto c = find_contact(a, true, b, true);
  BOOST_TEST(!c.intersect);
  BOOST_TEST(c.distance == d, tt::tolerance(1e-12));
  BOOST_TEST((c.on_a.point - Vec2<double>(1, 0)).norm() < 1e-12);
  BOOST_TEST((c.on_b.point - Vec2<double>(1 + d, 0)).norm() < 1e-12);
  BOOST_TEST(c.on_a.segment == 0u);
  BOOST_TEST(c.on_b.segment == n4 / 2 - (c.on_b.fraction == 1.0 ? 1 : 0));
  check_consistent(c.on_a, a);
  check_consistent(c.on_b, b);
}

// With the samples straddling the centre line both contours show a chord there, each a sagitta
// r (1 - cos(pi / n)) inside its circle: the polyline gap is d + s1 + s4 exactly, between parallel chords.
BOOST_AUTO_TEST_CASE(separated_circles_with_straddling_samples) {
  const double d = 0.25;
  const std::size_t n1 = 200, n4 = 400;
  const auto a = circle(n1, {0, 0}, 1, 0.5), b = circle(n4, {5 + d, 0}, 4, 0.5);
  const auto c = find_contact(a, true, b, true);
  const double bound = sagitta(1, n1) + sagitta(4, n4);
  BOOST_TEST_MESSAGE("sagitta bound " << bound);
  BOOST_TEST(c.distance == d + bound, tt::tolerance(1e-12));
  BOOST_TEST(c.on_a.point.x() == std::cos(kPi / n1), tt::tolerance(1e-12));
  BOOST_TEST(std::abs(c.on_a.point.y()) <= std::sin(kPi / n1));
  BOOST_TEST(std::abs(c.on_b.point.y()) <= std::sin(kPi / n1));
}

BOOST_AUTO_TEST_CASE(separated_circles_with_random_phases_stay_within_the_sagitta_bound) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  const double d = 0.1;
  for (int trial = 0; trial < 20; ++trial) {
    const std::size_t n1 = 50 + trial * 7, n4 = 300 - trial * 5;
    const auto a = circle(n1, {0, 0}, 1, u(rng)), b = circle(n4, {5 + d, 0}, 4, u(rng));
    const auto c = find_contact(a, true, b, true);
    BOOST_TEST(c.distance >= d - 1e-12);
    BOOST_TEST(c.distance <= d + sagitta(1, n1) + sagitta(4, n4) + 1e-12);
    // The points lie within one chord of the centre line.
    BOOST_TEST(std::abs(c.on_a.point.y()) <= 2 * kPi / n1 + 8 * kPi / n4);
    BOOST_TEST(std::abs(c.on_b.point.y()) <= 2 * kPi / n1 + 8 * kPi / n4);
    check_consistent(c.on_a, a);
    check_consistent(c.on_b, b);
  }
}

BOOST_AUTO_TEST_CASE(agrees_with_brute_force_on_random_open_polylines) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 20; ++trial) {
    Points a(40), b(30);
    for (auto& p : a) p = Vec2<double>(u(rng), u(rng));
    for (auto& p : b) p = Vec2<double>(2.5 + u(rng), u(rng));
    const auto c = find_contact(a, false, b, false);
    BOOST_TEST(!c.intersect);
    BOOST_TEST(c.distance == brute_force_distance(a, b), tt::tolerance(1e-12));
    BOOST_TEST((c.on_a.point - c.on_b.point).norm() == c.distance, tt::tolerance(1e-12));
  }
}

// Polylines given in their own frames and placed by rigid motions: the hierarchies' descent finds exactly the
// segment pairs an O(n m) comparison of the placed polylines finds (within the tolerance, and crossing).
BOOST_AUTO_TEST_CASE(hierarchies_in_link_frames_find_the_brute_force_pairs) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(0, 1);
  auto wiggly_circle = [&](std::size_t n, double r) {
    Points p = circle(n, {0, 0}, r, u(rng));
    for (auto& q : p) q *= 1 + 0.05 * (u(rng) - 0.5);
    return p;
  };
  auto segment_distance = [](const Vec2<double>& a0, const Vec2<double>& a1, const Vec2<double>& b0,
                             const Vec2<double>& b1) {
    return std::min({point_segment_distance(a0, b0, b1), point_segment_distance(a1, b0, b1),
                     point_segment_distance(b0, a0, a1), point_segment_distance(b1, a0, a1)});
  };
  auto cross = [](const Vec2<double>& o, const Vec2<double>& p, const Vec2<double>& q) {
    return (p - o).x() * (q - o).y() - (p - o).y() * (q - o).x();
  };
  int zones = 0, crossings = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const Points a = wiggly_circle(200, 1), b = wiggly_circle(150, 0.7);
    const rollkin::SE2<double> ga(2 * kPi * u(rng), Vec2<double>(u(rng), u(rng)));
    const rollkin::SE2<double> gb(2 * kPi * u(rng), ga.act(Vec2<double>(1.6 + 0.2 * u(rng), 0.1 * u(rng))));
    const double tol = 0.02;
    const InterferenceReport r = check_interference(SegmentHierarchy(a, true), ga, SegmentHierarchy(b, true), gb, tol);
    std::vector<std::size_t> near_a, found_a;
    std::size_t crossing_pairs = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
      for (std::size_t j = 0; j < b.size(); ++j) {
        const Vec2<double> a0 = ga.act(a[i]), a1 = ga.act(a[(i + 1) % a.size()]);
        const Vec2<double> b0 = gb.act(b[j]), b1 = gb.act(b[(j + 1) % b.size()]);
        const bool crossing = cross(a0, a1, b0) * cross(a0, a1, b1) < 0 && cross(b0, b1, a0) * cross(b0, b1, a1) < 0;
        crossing_pairs += crossing;
        if (crossing || segment_distance(a0, a1, b0, b1) <= tol) near_a.push_back(i);
      }
    std::sort(near_a.begin(), near_a.end());
    near_a.erase(std::unique(near_a.begin(), near_a.end()), near_a.end());
    for (const auto& z : r.zones) found_a.insert(found_a.end(), z.a_segments.begin(), z.a_segments.end());
    std::sort(found_a.begin(), found_a.end());
    BOOST_TEST(found_a == near_a, tt::per_element());
    BOOST_TEST(r.crossings.size() == crossing_pairs);
    for (const auto& c : r.crossings) BOOST_TEST((c.on_a.point - c.on_b.point).norm() < 1e-12);
    zones += static_cast<int>(r.zone_count());
    crossings += static_cast<int>(crossing_pairs);
  }
  BOOST_TEST(zones > 0);  // the trials include touching and crossing placements
  BOOST_TEST(crossings > 0);
}

BOOST_AUTO_TEST_CASE(crossing_circles_intersect) {
  const double centre = 4.5;  // radii 1 and 4: the circles cross at x = (c^2 + 1 - 16) / (2 c)
  const auto a = circle(360, {0, 0}, 1), b = circle(720, {centre, 0}, 4);
  const auto c = find_contact(a, true, b, true);
  BOOST_TEST(c.intersect);
  BOOST_TEST(c.distance == 0.0);
  const double x = (centre * centre + 1 - 16) / (2 * centre), y = std::sqrt(1 - x * x);
  BOOST_TEST(c.on_a.point.x() == x, tt::tolerance(1e-3));
  BOOST_TEST(std::abs(c.on_a.point.y()) == y, tt::tolerance(1e-3));
  BOOST_TEST((c.on_a.point - c.on_b.point).norm() == 0.0);
  check_consistent(c.on_b, b);
}

BOOST_AUTO_TEST_CASE(too_few_samples_throw) {
  BOOST_CHECK_THROW(find_contact({{0, 0}}, false, {{1, 0}, {2, 0}}, false), std::invalid_argument);
  BOOST_CHECK_THROW(check_interference({{0, 0}, {1, 0}}, true, {{1, 0}, {2, 0}}, false, 0.1),
                    std::invalid_argument);
}

// A disk of radius 1 inside the inner contour (clockwise) of a ring; gap g at the contact.
BOOST_AUTO_TEST_CASE(disk_touching_a_circular_ring_at_one_point) {
  const double g = 1e-4, tol = 1e-3;
  const auto disk = circle(720, {0, 0}, 1);
  const auto ring = circle(720, {1 - g, 0}, 2, 0, -1);  // inner circle through (-1 - g, 0)
  const auto r = check_interference(disk, true, ring, true, tol);
  BOOST_TEST(!r.penetrate);
  BOOST_TEST_REQUIRE(r.zone_count() == 1u);
  const auto& z = r.zones.front();
  BOOST_TEST(!z.penetrating);
  // Both contours have a sample on the centre line; the ring's chords next to its sample lean towards the
  // disk by half the ring's sample angle h, so the polyline gap is g cos(h / 2), reached near (-1, 0).
  const double h = 2 * kPi / 720;
  BOOST_TEST(z.distance == g * std::cos(h / 2), tt::tolerance(1e-9));
  BOOST_TEST((z.on_a.point - Vec2<double>(-1, 0)).norm() < 1e-12);
  BOOST_TEST((z.on_b.point - Vec2<double>(-1 - g, 0)).norm() <= g * std::sin(h / 2) + 1e-12);
  BOOST_TEST(z.a_segments.size() > 2u);  // the near region spans several samples, still one zone
}

// The same disk (shrunk by g) inside an elliptic ring with semi-axes 2 and 1 touches at (0, +-1).
BOOST_AUTO_TEST_CASE(disk_touching_an_elliptic_ring_at_two_points) {
  const double g = 1e-4, tol = 1e-3;
  const auto disk = circle(720, {0, 0}, 1 - g);
  const auto ring = ellipse(720, {0, 0}, 2, 1, 0, -1);
  const auto r = check_interference(disk, true, ring, true, tol);
  BOOST_TEST(!r.penetrate);
  BOOST_TEST_REQUIRE(r.zone_count() == 2u);
  for (const auto& z : r.zones) {
    // The ellipse's chords next to its samples at (0, +-1) lean towards the disk: gap a little below g.
    BOOST_TEST(z.distance <= g);
    BOOST_TEST(z.distance >= g * std::cos(2 * kPi / 720));
    BOOST_TEST(std::abs(z.on_a.point.x()) < 1e-9);
    BOOST_TEST(std::abs(std::abs(z.on_a.point.y()) - (1 - g)) < 1e-9);
  }
  BOOST_TEST(r.zones[0].on_a.point.y() * r.zones[1].on_a.point.y() < 0);  // one on each side
}

// Pushed past the ring by 0.01 the disk crosses it twice; each crossing is its own zone.
BOOST_AUTO_TEST_CASE(disk_penetrating_a_ring) {
  const double overlap = 0.01;
  const Vec2<double> centre(1 + overlap, 0);
  const auto disk = circle(720, {0, 0}, 1);
  const auto ring = circle(1440, centre, 2, 0.5, -1);
  const auto r = check_interference(disk, true, ring, true, 1e-3);
  BOOST_TEST(r.penetrate);
  BOOST_TEST_REQUIRE(r.crossings.size() == 2u);
  const double x = (centre.squaredNorm() + 1 - 4) / (2 * centre.x()), y = std::sqrt(1 - x * x);
  for (const auto& c : r.crossings) {
    BOOST_TEST(c.on_a.point.x() == x, tt::tolerance(1e-4));
    BOOST_TEST(std::abs(c.on_a.point.y()) == y, tt::tolerance(1e-3));
  }
  BOOST_TEST_REQUIRE(r.zone_count() == 2u);
  BOOST_TEST(r.zones[0].penetrating);
  BOOST_TEST(r.zones[1].penetrating);
  BOOST_TEST(find_contact(disk, true, ring, true).intersect);
}

BOOST_AUTO_TEST_CASE(query_timing) {
  const std::size_t n = 100000;
  struct Case {
    const char* name;
    Points a, b;
    double lo, hi;  // bounds on the polyline gap: the curves' gap 0.001 -+ the sagittas of the chords
  };
  const Case cases[] = {
      {"circles 1 and 4 side by side", circle(n, {0, 0}, 1, 0.3), circle(n, {5.001, 0}, 4, 0.7), 0.001,
       0.001 + sagitta(1, n) + sagitta(4, n)},
      {"disk 1 inside ring 2", circle(n, {0, 0}, 1, 0.3), circle(n, {0.999, 0}, 2, 0.7, -1),
       0.001 - sagitta(2, n), 0.001 + sagitta(1, n)}};
  for (const auto& c : cases) {
    auto t0 = std::chrono::steady_clock::now();
    const auto contact = find_contact(c.a, true, c.b, true);
    const double t_contact = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    t0 = std::chrono::steady_clock::now();
    const auto r = check_interference(c.a, true, c.b, true, 0.01);
    const double t_interference = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::cout << c.name << ", 2 x " << n << " samples: find_contact " << t_contact << " s, check_interference "
              << t_interference << " s\n";
    BOOST_TEST(contact.distance >= c.lo - 1e-15);
    BOOST_TEST(contact.distance <= c.hi + 1e-15);
    BOOST_TEST(r.zone_count() == 1u);
  }
}
