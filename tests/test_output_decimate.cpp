// Outputs reduced to what can be seen (rollkin/output/decimate.hpp), against brute-force truth computed here from
// the whole input: a reduced chart series keeps, for random series of any length, the first and last points,
// the global extremes and every pixel column's extremes, in input order, and its size is bounded by the
// columns, not by the number of points; a series below the resolution is unchanged. The frames of an
// animation are evenly spaced, bounded in number, and include both poses of every status change.
#define BOOST_TEST_MODULE io_decimate
#include <boost/test/unit_test.hpp>

#include "rollkin/output/decimate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <vector>

using namespace rollkin::io;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Series {
  std::vector<double> x, y;
};

/// n points with increasing x over [0, 1] (uneven steps) and y a random walk with rare spikes.
Series random_series(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> step(0.1, 1.9), walk(-1, 1), u(0, 1);
  Series s;
  double x = 0, y = 0;
  for (std::size_t i = 0; i < n; ++i) {
    x += step(rng);
    y += walk(rng) + (u(rng) < 1e-3 ? 50 * walk(rng) : 0);  // peaks a few points wide
    s.x.push_back(x);
    s.y.push_back(y);
  }
  for (double& v : s.x) v /= x;
  return s;
}

SeriesReducer reduce(const Series& s, int columns) {
  SeriesReducer r(0, 1, columns);  // random_series: x in (0, 1]
  for (std::size_t i = 0; i < s.x.size(); ++i) r.add(s.x[i], s.y[i]);
  r.finish();
  return r;
}

/// Whether the kept points are input points in input order (each kept at most once; NaN matches a break).
bool is_subsequence(const SeriesReducer& r, const Series& s) {
  std::size_t j = 0;
  for (std::size_t i = 0; i < r.x().size(); ++i) {
    const bool brk = std::isnan(r.x()[i]);
    while (j < s.x.size() && !(brk ? !std::isfinite(s.x[j]) || !std::isfinite(s.y[j])
                                   : s.x[j] == r.x()[i] && s.y[j] == r.y()[i]))
      ++j;
    if (j == s.x.size()) return false;
    ++j;
  }
  return true;
}

bool kept(const SeriesReducer& r, double x, double y) {
  for (std::size_t i = 0; i < r.x().size(); ++i)
    if (r.x()[i] == x && r.y()[i] == y) return true;
  return false;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(series_reducer)

BOOST_AUTO_TEST_CASE(random_series_keep_every_columns_extremes_in_bounded_size) {
  const int columns = 600;
  for (const std::size_t n : {std::size_t(3000), std::size_t(20000), std::size_t(400000)})
    for (unsigned seed = 1; seed <= 3; ++seed) {
      BOOST_TEST_CONTEXT("n = " << n << ", seed " << seed) {
        const Series s = random_series(n, seed);
        const SeriesReducer r = reduce(s, columns);
        BOOST_TEST(r.seen() == n);
        BOOST_TEST(r.x().size() <= 4u * columns);  // bounded by the columns, whatever n
        BOOST_TEST(r.x().size() >= static_cast<std::size_t>(columns) / 2);
        BOOST_TEST(is_subsequence(r, s));
        BOOST_TEST((r.x().front() == s.x.front() && r.y().front() == s.y.front()));
        BOOST_TEST((r.x().back() == s.x.back() && r.y().back() == s.y.back()));
        // The global extremes, and each column's (columns computed here from the x range, not by the reducer).
        const auto [lo, hi] = std::minmax_element(s.y.begin(), s.y.end());
        BOOST_TEST(kept(r, s.x[lo - s.y.begin()], *lo));
        BOOST_TEST(kept(r, s.x[hi - s.y.begin()], *hi));
        std::map<int, std::pair<std::size_t, std::size_t>> extremes;  // column -> (lowest, highest) index
        for (std::size_t i = 0; i < n; ++i) {
          const int c = std::min(columns - 1, static_cast<int>(std::floor(s.x[i] * columns)));
          const auto at = extremes.emplace(c, std::make_pair(i, i)).first;
          if (s.y[i] < s.y[at->second.first]) at->second.first = i;
          if (s.y[i] > s.y[at->second.second]) at->second.second = i;
        }
        std::size_t missing = 0;
        for (const auto& [c, e] : extremes)
          missing += !kept(r, s.x[e.first], s.y[e.first]) + !kept(r, s.x[e.second], s.y[e.second]);
        BOOST_TEST(missing == 0u);
      }
    }
}

BOOST_AUTO_TEST_CASE(size_does_not_grow_with_the_number_of_points) {
  const std::size_t a = reduce(random_series(100000, 7), 300).x().size();
  const std::size_t b = reduce(random_series(1000000, 7), 300).x().size();
  BOOST_TEST(a <= 1200u);
  BOOST_TEST(b <= 1200u);
}

BOOST_AUTO_TEST_CASE(a_series_below_the_resolution_is_unchanged) {
  // 37 points over 600 columns (a chart of a coarse sweep), and 4 points in each of 100 columns.
  for (const std::size_t n : {std::size_t(37), std::size_t(400)}) {
    const Series s = random_series(n, 11);
    const int columns = n == 37 ? 600 : 100;
    Series even;  // x exactly at 4 points per column for the second case
    for (std::size_t i = 0; i < n; ++i) {
      even.x.push_back(n == 37 ? s.x[i] : (static_cast<double>(i / 4) + 0.1 + 0.2 * static_cast<double>(i % 4)) / columns);
      even.y.push_back(s.y[i]);
    }
    SeriesReducer r(0, 1, columns);
    for (std::size_t i = 0; i < n; ++i) r.add(even.x[i], even.y[i]);
    r.finish();
    BOOST_TEST(r.x() == even.x, boost::test_tools::per_element());
    BOOST_TEST(r.y() == even.y, boost::test_tools::per_element());
  }
}

BOOST_AUTO_TEST_CASE(breaks_are_kept_once_and_bound_the_runs) {
  // 10^5 points with three gaps of non-finite values (NaN y, infinite y, NaN x) of 1000 points each.
  Series s = random_series(100000, 5);
  for (std::size_t i = 20000; i < 21000; ++i) s.y[i] = kNaN;
  for (std::size_t i = 50000; i < 51000; ++i) s.y[i] = std::numeric_limits<double>::infinity();
  for (std::size_t i = 80000; i < 81000; ++i) s.x[i] = kNaN;
  SeriesReducer r(0, 1, 500);
  for (std::size_t i = 0; i < s.x.size(); ++i) r.add(s.x[i], s.y[i]);
  r.finish();
  std::size_t breaks = 0;
  for (std::size_t i = 0; i < r.x().size(); ++i) {
    const bool brk = std::isnan(r.x()[i]);
    breaks += brk;
    if (brk) {
      BOOST_TEST(std::isnan(r.y()[i]));
      BOOST_TEST((i > 0 && !std::isnan(r.x()[i - 1])));  // one NaN per gap
    }
  }
  BOOST_TEST(breaks == 3u);
  BOOST_TEST(r.x().size() <= 4u * 500 + 5 * breaks);
  BOOST_TEST(is_subsequence(r, s));
  // The last point before each gap and the first after it are drawn (the line ends where it did).
  for (const std::size_t gap : {20000, 50000, 80000}) {
    BOOST_TEST(kept(r, s.x[gap - 1], s.y[gap - 1]));
    BOOST_TEST(kept(r, s.x[gap + 1000], s.y[gap + 1000]));
  }
  // Leading and trailing non-finite points add nothing.
  SeriesReducer edge(0, 1, 10);
  edge.add(kNaN, 1);
  edge.add(0.5, 2);
  edge.add(0.6, kNaN);
  edge.finish();
  BOOST_TEST(edge.x().size() == 2u);  // the point and the break after it
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(animation_frames)

BOOST_AUTO_TEST_CASE(short_sweeps_show_every_pose) {
  const std::vector<std::size_t> f = pick_frames(1500, [](std::size_t k) { return static_cast<int>(k % 3); });
  BOOST_TEST(f.size() == 1500u);
  for (std::size_t k = 0; k < f.size(); ++k) BOOST_TEST(f[k] == k);
  BOOST_TEST(pick_frames(0, [](std::size_t) { return 0; }).empty());
}

BOOST_AUTO_TEST_CASE(long_sweeps_are_evenly_spaced_and_bounded) {
  for (const std::size_t n : {std::size_t(2001), std::size_t(150001), std::size_t(1000000)}) {
    BOOST_TEST_CONTEXT("n = " << n) {
      std::size_t calls = 0;
      const std::vector<std::size_t> f = pick_frames(n, [&](std::size_t) { return ++calls, 0; });
      BOOST_TEST(calls == n);  // one pass
      BOOST_TEST(f.size() == kAnimationFrames);
      BOOST_TEST(f.front() == 0u);
      BOOST_TEST(f.back() == n - 1);
      const double spacing = static_cast<double>(n - 1) / static_cast<double>(kAnimationFrames - 1);
      for (std::size_t k = 1; k < f.size(); ++k) BOOST_TEST(std::abs(static_cast<double>(f[k] - f[k - 1]) - spacing) <= 1.0);
    }
  }
}

BOOST_AUTO_TEST_CASE(both_poses_of_every_status_change_are_frames) {
  // 10^6 poses: ok, a limit at pose 700,003 (then not reached to the end), 40 isolated singular poses.
  const std::size_t n = 1000000;
  std::mt19937_64 rng(3);
  std::vector<std::size_t> singular;
  for (int i = 0; i < 40; ++i) singular.push_back(1 + rng() % 699000);
  auto status = [&](std::size_t k) {
    if (k == 700003) return 3;
    if (k > 700003) return 4;
    return std::find(singular.begin(), singular.end(), k) != singular.end() ? 1 : 0;
  };
  const std::vector<std::size_t> f = pick_frames(n, status);
  BOOST_TEST(std::is_sorted(f.begin(), f.end()));
  BOOST_TEST((std::adjacent_find(f.begin(), f.end()) == f.end()));  // each pose once
  auto has = [&](std::size_t k) { return std::binary_search(f.begin(), f.end(), k); };
  std::size_t changes = 0, missing = 0;
  for (std::size_t k = 1; k < n; ++k)
    if (status(k) != status(k - 1)) {
      ++changes;
      missing += !has(k - 1) + !has(k);
    }
  BOOST_TEST(missing == 0u);
  BOOST_TEST(f.size() <= kAnimationFrames + 2 * changes);
  BOOST_TEST(f.size() > kAnimationFrames);
}

BOOST_AUTO_TEST_CASE(a_status_changing_at_every_pose_still_gives_a_bounded_page) {
  const std::size_t n = 1000000;
  const std::vector<std::size_t> f = pick_frames(n, [](std::size_t k) { return static_cast<int>(k % 2); });
  BOOST_TEST(f.size() <= 2 * kAnimationFrames + 1);
  BOOST_TEST(f.size() >= kAnimationFrames);
  // The changes shown spread over the whole sweep (not the first thousand only).
  std::size_t late = 0;
  for (std::size_t k : f) late += k > n / 2;
  BOOST_TEST(late >= f.size() / 3);
}

BOOST_AUTO_TEST_SUITE_END()
