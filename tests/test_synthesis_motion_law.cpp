// Motion laws (include/rollkin/synthesis/motion_law.hpp) against independent truth:
//  - every normalised rise starts at 0 with zero velocity and ends at 1 with zero velocity;
//  - the peak velocity and acceleration coefficients against the textbook values (Norton, "Cam Design and
//    Manufacturing Handbook", table 3-3: cycloidal 2 and 2 pi, harmonic pi/2 and pi^2/2, 3-4-5 1.875 and
//    10/sqrt(3), 4-5-6-7 2.1875 and 7.5132, modified trapezoid 2 and 4.888, modified sine 1.76 and 5.528);
//  - the closed-form cycloidal law y = x - sin(2 pi x)/(2 pi) on a whole law (lift scaled, angle shifted);
//  - each derivative against the central difference of the one below, for every kind, on a seeded sample;
//  - continuity: cycloidal rise-dwell-return-dwell has no jump; the harmonic one jumps in acceleration at
//    each of its four joins by exactly pi^2/2 h/beta^2 (infinite jerk), reported at the join;
//  - a table of points of a smooth periodic law gives it back (within the cubic spline's h^4 bound; the
//    quintic spline converges as h^6: halving the step divides the error by more than 40), and its spline is
//    C3 (no jump reported, the jerk continuous at every row to round-off); malformed laws (gap, wrong total,
//    net lift) are refused;
//  - a periodic table is periodic wherever it starts (issue 37): the same rows listed from -5, -90, -180 or
//    720 degrees give the same law as from 0 at every angle of two turns either way (before, the rows from
//    -5 degrees were extrapolated over the rest of the turn).
#define BOOST_TEST_MODULE synthesis_motion_law
#include <boost/test/unit_test.hpp>

#include "rollkin/synthesis/motion_law.hpp"

#include <cmath>
#include <functional>
#include <random>

using namespace rollkin;
using namespace rollkin::synthesis;

namespace {

const double kPi = M_PI;
const double kDeg = kPi / 180;

std::vector<RiseKind> rising_kinds() {
  return {RiseKind::Cycloidal, RiseKind::Harmonic, RiseKind::ModifiedTrapezoid, RiseKind::ModifiedSine,
          RiseKind::Poly345, RiseKind::Poly4567};
}

/// Largest |y'| and |y''| on a grid of 200001 points (the peaks are smooth maxima: grid error ~1e-10).
std::pair<double, double> peaks(RiseKind kind) {
  double v = 0, a = 0;
  const int n = 200000;
  for (int i = 0; i <= n; ++i) {
    const auto y = normalised_rise(kind, double(i) / n);
    v = std::max(v, std::abs(y[1]));
    a = std::max(a, std::abs(y[2]));
  }
  return {v, a};
}

MotionLaw<double> rise_dwell_return(RiseKind kind, double h) {
  return MotionLaw<double>::from_segments({{0, 90 * kDeg, h, kind},
                                           {90 * kDeg, 180 * kDeg, 0, RiseKind::Dwell},
                                           {180 * kDeg, 270 * kDeg, -h, kind},
                                           {270 * kDeg, 360 * kDeg, 0, RiseKind::Dwell}});
}

}  // namespace

BOOST_AUTO_TEST_CASE(rises_start_and_end_at_rest) {
  for (RiseKind kind : rising_kinds()) {
    const auto y0 = normalised_rise(kind, 0.0), y1 = normalised_rise(kind, 1.0);
    BOOST_TEST(std::abs(y0[0]) < 1e-15);
    BOOST_TEST(std::abs(y0[1]) < 1e-14);
    BOOST_TEST(std::abs(y1[0] - 1) < 1e-14);
    BOOST_TEST(std::abs(y1[1]) < 1e-13);
  }
}

BOOST_AUTO_TEST_CASE(peak_coefficients_against_the_textbook) {
  struct Row {
    RiseKind kind;
    double cv, ca, tol;  // tol: the textbook's rounding
  };
  const Row rows[] = {{RiseKind::Cycloidal, 2, 2 * kPi, 1e-9},
                      {RiseKind::Harmonic, kPi / 2, kPi * kPi / 2, 1e-9},
                      {RiseKind::Poly345, 1.875, 10 / std::sqrt(3.0), 1e-9},
                      {RiseKind::Poly4567, 2.1875, 7.5132, 5e-5},
                      {RiseKind::ModifiedTrapezoid, 2.0, 4.888, 5e-4},
                      {RiseKind::ModifiedSine, 1.76, 5.528, 5e-3}};
  for (const Row& r : rows) {
    const auto [v, a] = peaks(r.kind);
    BOOST_TEST_INFO("kind " << int(r.kind) << " peak v " << v << " peak a " << a);
    BOOST_TEST(std::abs(v - r.cv) < r.tol * r.cv);
    BOOST_TEST(std::abs(a - r.ca) < r.tol * r.ca);
  }
}

BOOST_AUTO_TEST_CASE(cycloidal_law_against_its_closed_form) {
  const double h = 12.5, beta = 90 * kDeg;
  const MotionLaw<double> law = rise_dwell_return(RiseKind::Cycloidal, h);
  for (int i = 0; i <= 90; ++i) {
    const double th = 180 * kDeg + i * kDeg, x = (th - 180 * kDeg) / beta;
    const auto v = law(th);
    const double s = h - h * (x - std::sin(2 * kPi * x) / (2 * kPi));
    const double ds = -h / beta * (1 - std::cos(2 * kPi * x));
    const double dds = -h / (beta * beta) * 2 * kPi * std::sin(2 * kPi * x);
    BOOST_TEST(std::abs(v.s - s) < 1e-13 * h);
    BOOST_TEST(std::abs(v.v - ds) < 1e-13 * h);
    BOOST_TEST(std::abs(v.a - dds) < 1e-12 * h);
  }
  BOOST_TEST(std::abs(law.stroke() - h) < 1e-12);
  BOOST_TEST(std::abs(law(360 * kDeg + 45 * kDeg).s - law(45 * kDeg).s) < 1e-13);  // repeats every turn
}

BOOST_AUTO_TEST_CASE(derivatives_against_finite_differences) {
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> where(0.02, 0.98);
  for (RiseKind kind : rising_kinds()) {
    for (int trial = 0; trial < 40; ++trial) {
      const double x = where(rng), e = 1e-5;
      const auto lo = normalised_rise(kind, x - e), hi = normalised_rise(kind, x + e), mid = normalised_rise(kind, x);
      for (int order = 0; order < 3; ++order) {
        const double fd = (hi[order] - lo[order]) / (2 * e);
        BOOST_TEST_INFO("kind " << int(kind) << " x " << x << " derivative " << order + 1);
        // Central differences: error e^2 y'''' / 6 (~1e-7 of these sizes) except across the piece joins of the
        // modified laws, whose y''' jumps: there only the first two orders are compared.
        const bool near_piece_join = (kind == RiseKind::ModifiedTrapezoid || kind == RiseKind::ModifiedSine) &&
                                     order == 2 && std::abs(x * 8 - std::round(x * 8)) < 8 * 2 * e;
        if (!near_piece_join) BOOST_TEST(std::abs(fd - mid[order + 1]) < 1e-6 * (1 + std::abs(mid[order + 1])));
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(continuity_of_joins) {
  BOOST_TEST(rise_dwell_return(RiseKind::Cycloidal, 10).check_continuity().empty());
  BOOST_TEST(rise_dwell_return(RiseKind::Poly345, 10).check_continuity().empty());
  BOOST_TEST(rise_dwell_return(RiseKind::ModifiedSine, 10).check_continuity().empty());
  const double h = 10, beta = 90 * kDeg;
  const auto jumps = rise_dwell_return(RiseKind::Harmonic, h).check_continuity();
  BOOST_TEST_REQUIRE(jumps.size() == 4u);
  const double expected_theta[] = {0, 90 * kDeg, 180 * kDeg, 270 * kDeg};
  for (std::size_t k = 0; k < 4; ++k) {
    BOOST_TEST(jumps[k].order == 2);
    BOOST_TEST(std::abs(jumps[k].theta - expected_theta[k]) < 1e-15);
    BOOST_TEST(std::abs(std::abs(jumps[k].right - jumps[k].left) - kPi * kPi / 2 * h / (beta * beta)) < 1e-12);
  }
}

BOOST_AUTO_TEST_CASE(table_law_gives_a_smooth_law_back) {
  auto truth = [](double t) { return 3 * std::sin(t) + std::cos(2 * t); };
  std::vector<double> th, s;
  const int n = 180;
  for (int i = 0; i <= n; ++i) {  // the last point at 2 pi repeats the first: dropped
    th.push_back(2 * kPi * i / n);
    s.push_back(truth(th.back()));
  }
  const MotionLaw<double> law = MotionLaw<double>::from_table(th, s);
  BOOST_TEST(law.check_continuity().empty());
  double worst = 0;
  for (int i = 0; i < 3600; ++i) {
    const double t = 2 * kPi * (i + 0.37) / 3600;
    worst = std::max(worst, std::abs(law(t).s - truth(t)));
  }
  // Within the periodic cubic spline's bound (5/384) h^4 max|s''''| (h = 2 deg, max|s''''| = 3 + 16); the
  // quintic does better (its h^6 order is checked below).
  const double hstep = 2 * kPi / n;
  BOOST_TEST(worst < 5.0 / 384 * std::pow(hstep, 4) * 19);
  BOOST_TEST(worst > 0);
  for (int i = 0; i < n; ++i) {  // the spline interpolates
    BOOST_TEST(std::abs(law(th[i]).s - s[i]) < 1e-13);
  }
}

namespace {

/// The rows of `truth` at n equal steps from `start` (radians), with the closing row one turn later.
MotionLaw<double> table_of(const std::function<double(double)>& truth, int n, double start) {
  std::vector<double> th, s;
  for (int i = 0; i <= n; ++i) {
    th.push_back(start + 2 * kPi * i / n);
    s.push_back(truth(th.back()));
  }
  s.back() = s.front();  // the same value one turn later, exactly
  return MotionLaw<double>::from_table(th, s);
}

double worst_error(const MotionLaw<double>& law, const std::function<double(double)>& truth) {
  double worst = 0;
  for (int i = 0; i < 3600; ++i) {
    const double t = 2 * kPi * (i + 0.37) / 3600;
    worst = std::max(worst, std::abs(law(t).s - truth(t)));
  }
  return worst;
}

}  // namespace

BOOST_AUTO_TEST_CASE(table_law_converges_as_a_quintic_and_its_jerk_is_continuous) {
  auto truth = [](double t) { return 3 * std::sin(t) + std::cos(2 * t); };
  const double coarse = worst_error(table_of(truth, 45, 0), truth), fine = worst_error(table_of(truth, 90, 0), truth);
  BOOST_TEST_MESSAGE("table of 45 rows: " << coarse << ", of 90: " << fine);
  BOOST_TEST(coarse / fine > 40);  // h^6: 64
  const MotionLaw<double> law = table_of(truth, 90, 0);
  for (double join : law.joins()) {
    const LawValue<double> l = law.left_of(join), r = law(join);
    BOOST_TEST(std::abs(l.j - r.j) < 1e-9 * 11);  // |s'''| <= 3 + 8: jumps of round-off only
  }
}

BOOST_AUTO_TEST_CASE(a_periodic_table_is_periodic_wherever_it_starts) {
  // Rows at every 5 degrees of a law whose s(0) is not zero, listed from different first angles: the knots
  // are the same angles modulo a turn, so the laws must agree everywhere.
  auto truth = [](double t) { return 5 + 4 * (1 - std::cos(t - 0.7)) + 0.5 * std::sin(3 * t); };
  const MotionLaw<double> from_zero = table_of(truth, 72, 0);
  for (double start_deg : {-5.0, -90.0, -180.0, 720.0, 1085.0}) {
    const MotionLaw<double> law = table_of(truth, 72, start_deg * kDeg);
    double worst = 0;
    for (int i = -1440; i <= 1440; ++i) {
      const double t = i * 0.5 * kDeg + 0.013;
      const LawValue<double> a = law(t), b = from_zero(t);
      worst = std::max({worst, std::abs(a.s - b.s), std::abs(a.v - b.v), std::abs(a.a - b.a) / 10});
    }
    BOOST_TEST_INFO("table from " << start_deg << " deg");
    BOOST_TEST(worst < 1e-10);
    BOOST_TEST(std::abs(law(0).s - truth(0)) < 1e-12);  // a row of every table: interpolated exactly
    BOOST_TEST(law.check_continuity().empty());
  }
}

BOOST_AUTO_TEST_CASE(malformed_laws_are_refused) {
  using L = MotionLaw<double>;
  BOOST_CHECK_THROW(L::from_segments({{0, 1, 1, RiseKind::Cycloidal}, {1, 2 * kPi, -0.5, RiseKind::Cycloidal}}),
                    std::invalid_argument);  // net lift
  BOOST_CHECK_THROW(L::from_segments({{0, 1, 1, RiseKind::Cycloidal}, {1.1, 2 * kPi, -1, RiseKind::Cycloidal}}),
                    std::invalid_argument);  // gap
  BOOST_CHECK_THROW(L::from_segments({{0, 1, 1, RiseKind::Cycloidal}, {1, 6, -1, RiseKind::Cycloidal}}),
                    std::invalid_argument);  // not one turn
  BOOST_CHECK_THROW(L::from_segments({{0, 2 * kPi, 1, RiseKind::Dwell}}), std::invalid_argument);
  BOOST_CHECK_THROW(L::from_table({0, 1, 2, 1.5}, {0, 1, 2, 3}), std::invalid_argument);
  BOOST_CHECK_THROW(rise_kind("cycloid"), std::invalid_argument);
  BOOST_TEST(int(rise_kind("poly4567")) == int(RiseKind::Poly4567));
}
