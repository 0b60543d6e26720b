#define BOOST_TEST_MODULE profile_spline
#include <boost/test/unit_test.hpp>

#include "rollkin/profile/spline.hpp"
#include "rollkin/scalar_mpfr.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

using rollkin::SampledProfile;
using rollkin::SplineEnd;
using rollkin::SplineOptions;
using V = rollkin::Vec2<double>;

namespace {

template <class S> std::vector<rollkin::Vec2<S>> circle_samples(int n, const S& r, bool repeat_first = false) {
  std::vector<rollkin::Vec2<S>> q;
  for (int k = 0; k < n; ++k) {
    using std::cos;
    using std::sin;
    const S t = S(2) * rollkin::pi<S>() * S(k) / S(n);
    q.emplace_back(r * cos(t), r * sin(t));
  }
  if (repeat_first) q.push_back(q.front());
  return q;
}

std::vector<V> parabola_samples(int n, double a, double x0, double x1) {
  std::vector<V> q;
  for (int k = 0; k <= n; ++k) {
    const double x = x0 + (x1 - x0) * k / n;
    q.emplace_back(x, a * x * x);
  }
  return q;
}

/// s(x) = x/2 sqrt(1 + 4a^2x^2) + asinh(2ax)/(4a) (docs/method.md section 5).
double parabola_arc(double a, double x) { return x / 2 * std::sqrt(1 + 4 * a * a * x * x) + std::asinh(2 * a * x) / (4 * a); }

std::vector<V> wavy_samples() {
  std::vector<V> q;
  for (int k = 0; k < 40; ++k) {
    const double t = 0.17 * k + 0.03 * std::sin(3.0 * k);
    q.emplace_back(t, std::sin(t) + 0.2 * std::cos(2.3 * t));
  }
  return q;
}

/// Largest distance from the spline to the circle of radius r, sampled densely.
double circle_error(const SampledProfile<double>& s, double r) {
  double e = 0;
  const double L = s.domain().hi;
  for (int k = 0; k < 20000; ++k) e = std::max(e, std::abs(s.jet(L * k / 20000.0, 0).p.norm() - r));
  return e;
}

double parabola_error(const SampledProfile<double>& s, double a) {
  double e = 0;
  const double L = s.domain().hi;
  for (int k = 0; k <= 20000; ++k) {
    const V p = s.jet(L * k / 20000.0, 0).p;
    e = std::max(e, std::abs(p.y() - a * p.x() * p.x()));
  }
  return e;
}

double observed_order(const std::vector<int>& n, const std::vector<double>& err, const char* title) {
  std::printf("%s\n   n      max error    order\n", title);
  double worst = 1e9;
  for (std::size_t i = 0; i < n.size(); ++i) {
    if (i == 0) {
      std::printf("%5d  %12.4e\n", n[i], err[i]);
      continue;
    }
    const double p = std::log(err[i - 1] / err[i]) / std::log(double(n[i]) / n[i - 1]);
    worst = std::min(worst, p);
    std::printf("%5d  %12.4e  %6.3f\n", n[i], err[i], p);
  }
  return worst;
}

}  // namespace

BOOST_AUTO_TEST_CASE(interpolates_samples_and_is_c2_at_knots) {
  for (SplineEnd end : {SplineEnd::Natural, SplineEnd::NotAKnot}) {
    SplineOptions<double> o;
    o.end = end;
    const auto q = wavy_samples();
    const SampledProfile<double> s(q, o);
    BOOST_TEST(s.max_deviation() < 1e-14);
    BOOST_TEST(s.continuity() == 2);
    for (std::size_t k = 0; k < q.size(); ++k) BOOST_TEST((s.jet(s.knots()[k], 0).p - q[k]).norm() < 1e-14);
    for (std::size_t k = 1; k + 1 < q.size(); ++k) {
      const double u = s.knots()[k], d = 1e-9;
      const auto l = s.jet(u - d, 3), r = s.jet(u + d, 3);
      BOOST_TEST((l.d1 - r.d1).norm() < 1e-7);
      BOOST_TEST((l.d2 - r.d2).norm() < 1e-6);
      if (end == SplineEnd::NotAKnot && (k == 1 || k + 2 == q.size())) BOOST_TEST((l.d3 - r.d3).norm() < 1e-6);
    }
    if (end == SplineEnd::Natural) {
      BOOST_TEST(s.jet(0.0, 2).d2.norm() < 1e-12);
      BOOST_TEST(s.jet(s.domain().hi, 2).d2.norm() < 1e-12);
    }
  }
}

BOOST_AUTO_TEST_CASE(derivatives_match_central_differences) {
  const SampledProfile<double> s(wavy_samples());
  const double h = 1e-5;
  for (std::size_t k = 0; k + 1 < s.knots().size(); k += 3) {
    const double u = 0.5 * (s.knots()[k] + s.knots()[k + 1]);  // inside a span: p''' is constant there
    const auto j = s.jet(u, 3), jp = s.jet(u + h, 3), jm = s.jet(u - h, 3);
    BOOST_TEST((j.d1 - (jp.p - jm.p) / (2 * h)).norm() < 1e-8);
    BOOST_TEST((j.d2 - (jp.d1 - jm.d1) / (2 * h)).norm() < 1e-7);
    BOOST_TEST((j.d3 - (jp.d2 - jm.d2) / (2 * h)).norm() < 1e-6);
  }
}

BOOST_AUTO_TEST_CASE(fourth_order_convergence_on_circle_and_parabola) {
  const std::vector<int> ns{16, 32, 64, 128, 256};
  std::vector<double> circle, parabola;
  SplineOptions<double> periodic;
  periodic.closed = true;
  SplineOptions<double> not_a_knot;
  not_a_knot.end = SplineEnd::NotAKnot;
  for (int n : ns) {
    circle.push_back(circle_error(SampledProfile<double>(circle_samples<double>(n, 2.0), periodic), 2.0));
    parabola.push_back(parabola_error(SampledProfile<double>(parabola_samples(n, 0.5, -2.0, 2.0), not_a_knot), 0.5));
  }
  BOOST_TEST(observed_order(ns, circle, "periodic spline through circle r = 2 (radial error)") > 3.5);
  BOOST_TEST(observed_order(ns, parabola, "not-a-knot spline through y = x^2/2, x in [-2, 2] (|y - a x^2|)") > 3.5);
}

BOOST_AUTO_TEST_CASE(arc_length_matches_closed_forms) {
  SplineOptions<double> periodic;
  periodic.closed = true;
  const SampledProfile<double> c(circle_samples<double>(512, 2.0, true), periodic);
  BOOST_TEST(c.span_count() == 512u);  // the repeated closing sample is dropped
  BOOST_TEST(std::abs(c.total_length() - 4 * M_PI) < 1e-8);
  BOOST_TEST(std::abs(c.arc_length(0.0, c.domain().hi) - 4 * M_PI) < 1e-8);
  BOOST_TEST(std::abs(c.arc_length(0.0, 3 * c.domain().hi) - 12 * M_PI) < 1e-7);  // wraps whole turns

  SplineOptions<double> not_a_knot;
  not_a_knot.end = SplineEnd::NotAKnot;
  const double a = 0.5;
  const SampledProfile<double> p(parabola_samples(800, a, -2.0, 2.0), not_a_knot);
  const double exact = parabola_arc(a, 2.0) - parabola_arc(a, -2.0);
  std::printf("parabola arc length: spline %.15f exact %.15f\n", p.total_length(), exact);
  BOOST_TEST(std::abs(p.total_length() - exact) < 1e-9);
  // Partial lengths: between samples 200 (x = -1) and 700 (x = 1.5).
  const double part = p.arc_length(p.knots()[200], p.knots()[700]);
  BOOST_TEST(std::abs(part - (parabola_arc(a, 1.5) - parabola_arc(a, -1.0))) < 1e-9);
}

BOOST_AUTO_TEST_CASE(arc_length_is_consistent_with_fine_quadrature_of_the_spline) {
  const SampledProfile<double> s(wavy_samples());
  rollkin::QuadratureRule fine;
  fine.order = 20;
  fine.panels = 4000;
  const double u0 = 0.37, u1 = 5.81;
  const double ref = rollkin::integrate<double>([&](double u) { return s.jet(u, 1).d1.norm(); }, u0, u1, fine);
  BOOST_TEST(std::abs(s.arc_length(u0, u1) - ref) < 1e-13 * ref);
  BOOST_TEST(std::abs(s.arc_length(u1, u0) + ref) < 1e-13 * ref);
}

BOOST_AUTO_TEST_CASE(inverse_arc_length_round_trips) {
  const SampledProfile<double> s(wavy_samples());
  const double L = s.domain().hi;
  for (double u0 : {0.0, 0.3 * L, 0.77 * L})
    for (double u1 : {0.01 * L, 0.29 * L, 0.31 * L, 0.9 * L, L}) {
      const double ds = s.arc_length(u0, u1);
      BOOST_TEST(std::abs(s.param_at_arc_length(u0, ds) - u1) < 1e-12 * L);
    }
  SplineOptions<double> periodic;
  periodic.closed = true;
  const SampledProfile<double> c(circle_samples<double>(50, 1.5), periodic);
  const double P = c.domain().period();
  for (double u1 : {-1.3 * P, -0.2, 0.4 * P, 2.7 * P}) {
    const double ds = c.arc_length(0.1, u1);
    BOOST_TEST(std::abs(c.param_at_arc_length(0.1, ds) - u1) < 1e-12 * P);
  }
}

BOOST_AUTO_TEST_CASE(closed_spline_wraps) {
  SplineOptions<double> periodic;
  periodic.closed = true;
  const SampledProfile<double> c(circle_samples<double>(37, 3.0), periodic);
  const double P = c.domain().period();
  BOOST_TEST(c.domain().closed);
  for (double u : {0.0, 0.123, 5.0, P - 1e-9}) {
    const auto a = c.jet(u, 3), b = c.jet(u + P, 3), m = c.jet(u - 2 * P, 3);
    BOOST_TEST((a.p - b.p).norm() < 1e-12);
    BOOST_TEST((a.d1 - b.d1).norm() < 1e-12);
    BOOST_TEST((a.d2 - m.d2).norm() < 1e-11);
  }
  // C2 across the seam u = 0 = P.
  const auto l = c.jet(P - 1e-9, 2), r = c.jet(1e-9, 2);
  BOOST_TEST((l.d1 - r.d1).norm() < 1e-7);
  BOOST_TEST((l.d2 - r.d2).norm() < 1e-7);
}

BOOST_AUTO_TEST_CASE(smoothing_respects_the_tolerance) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> noise(-1e-3, 1e-3);
  for (bool closed : {false, true}) {
    auto q = circle_samples<double>(400, 2.0);
    if (!closed) q.resize(300);
    for (auto& p : q) p += V(noise(rng), noise(rng));
    SplineOptions<double> o;
    o.closed = closed;
    o.smoothing_tolerance = 2e-3;
    const SampledProfile<double> s(q, o);
    double dev = 0;  // independent measurement of the reported deviation
    for (std::size_t k = 0; k < q.size(); ++k) dev = std::max(dev, (s.jet(s.knots()[k], 0).p - q[k]).norm());
    std::printf("smoothing (%s): max deviation %.3e (tol 2e-3), interpolating radial error %.3e -> smoothed %.3e\n",
                closed ? "closed" : "open", s.max_deviation(), circle_error(SampledProfile<double>(q, {closed}), 2.0),
                circle_error(s, 2.0));
    BOOST_TEST(s.max_deviation() <= 2e-3);
    BOOST_TEST(s.max_deviation() > 1e-3);  // it actually smooths
    BOOST_TEST(std::abs(dev - s.max_deviation()) < 1e-12);
    // Smoothing reduces the curvature noise: curvature stays near 1/r = 0.5 in the interior.
    double worst = 0;
    for (std::size_t k = 30; k + 30 < q.size(); ++k) {
      const auto c = rollkin::contour_point(s.jet(s.knots()[k], 2), 2);
      worst = std::max(worst, std::abs(c.curvature() - 0.5));
    }
    BOOST_TEST(worst < 0.1);
  }
}

// The smoothing weight is searched by factors of 10 from the samples' own scale, then bisected (smoothing_weight).
// At large scales the trial fits overflow: a NaN fit once counted as within the tolerance (std::max(dev, NaN) is
// dev), and a bisection between weights whose product overflowed (from about 1e154) had no end. Every scale
// gives a finite fit within its tolerance, found in bounded time, with the deviation it reports.
BOOST_AUTO_TEST_CASE(smoothing_at_every_scale_is_finite_and_within_the_tolerance) {
  for (double scale : {1e-100, 1.0, 1e50, 1e60, 1e80, 1e100, 1e150}) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> noise(-1e-3, 1e-3);
    auto q = circle_samples<double>(60, 2.0);
    for (auto& p : q) p = scale * (p + V(noise(rng), noise(rng)));
    SplineOptions<double> o;
    o.closed = true;
    o.smoothing_tolerance = 2e-3 * scale;
    const SampledProfile<double> s(q, o);
    double dev = 0;
    bool finite = true;
    for (std::size_t k = 0; k < q.size(); ++k) {
      const V p = s.jet(s.knots()[k], 0).p;
      finite = finite && std::isfinite(p.x()) && std::isfinite(p.y());
      dev = std::max(dev, (p - q[k]).norm());
    }
    BOOST_TEST(finite, "scale " << scale);
    BOOST_TEST(dev <= o.smoothing_tolerance, "scale " << scale << ": deviation " << dev);
    BOOST_TEST(std::abs(dev - s.max_deviation()) <= 1e-12 * scale, "scale " << scale);
  }
}

BOOST_AUTO_TEST_CASE(bad_samples_are_rejected) {
  BOOST_CHECK_THROW(SampledProfile<double>(std::vector<V>{V(0, 0)}), std::invalid_argument);
  BOOST_CHECK_THROW(SampledProfile<double>(std::vector<V>{V(0, 0), V(1, 0), V(1, 0)}), std::invalid_argument);
  SplineOptions<double> o;
  o.end = SplineEnd::NotAKnot;
  BOOST_CHECK_THROW(SampledProfile<double>(std::vector<V>{V(0, 0), V(1, 0), V(2, 1)}, o), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(million_points_build_fast) {
  const int n = 1000000;
  std::vector<V> q(n);
  for (int k = 0; k < n; ++k) {
    const double t = 2 * M_PI * k / n;
    q[k] = V((3 + 0.5 * std::cos(5 * t)) * std::cos(t), (3 + 0.5 * std::cos(5 * t)) * std::sin(t));
  }
  SplineOptions<double> periodic;
  periodic.closed = true;
  const auto t0 = std::chrono::steady_clock::now();
  const SampledProfile<double> s(q, periodic);
  const double build = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // 10^5 continuous queries (the solver's access pattern) and 10^5 random ones.
  const auto t1 = std::chrono::steady_clock::now();
  double sum = 0;
  const double L = s.domain().hi;
  for (int k = 0; k < 100000; ++k) sum += s.jet(L * k / 100000.0, 2).d2.x();
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> any(0, L);
  for (int k = 0; k < 100000; ++k) sum += s.param_at_arc_length(any(rng), 0.01);
  const double queries = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  std::printf("10^6-point periodic spline: build + arc table %.3f s; 2x10^5 queries %.3f s (checksum %.3f)\n", build,
              queries, sum);
  BOOST_TEST(s.span_count() == static_cast<std::size_t>(n));
}

BOOST_AUTO_TEST_CASE(mpfr_spline_is_scalar_generic) {
  using mp = rollkin::mpfr50;
  SplineOptions<mp> periodic;
  periodic.closed = true;
  const auto q = circle_samples<mp>(24, mp(2));
  const SampledProfile<mp> s(q, periodic);
  for (std::size_t k = 0; k < q.size(); ++k) BOOST_TEST(double((s.jet(s.knots()[k], 0).p - q[k]).norm()) < 1e-45);
  const mp u = s.knots()[5], d = mp(1) / mp("1e25");
  BOOST_TEST(double((s.jet(u - d, 2).d2 - s.jet(u + d, 2).d2).norm()) < 1e-20);  // C2: jump ~ p''' d
  const mp u0 = mp(1) / mp(3), u1 = mp(11) / mp(2);
  const mp ds = s.arc_length(u0, u1);
  BOOST_TEST(double(abs(s.param_at_arc_length(u0, ds) - u1)) < 1e-40);
  // Same curve in double: the cast agrees with a double fit to double precision.
  const SampledProfile<double> sd = s.cast<double>();
  const SampledProfile<double> fd(circle_samples<double>(24, 2.0), SplineOptions<double>{true});
  BOOST_TEST((sd.jet(1.234, 3).d2 - fd.jet(1.234, 3).d2).norm() < 1e-12);
  BOOST_TEST(std::abs(double(ds) - fd.arc_length(1.0 / 3, 5.5)) < 1e-13);
}
