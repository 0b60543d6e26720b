// The envelope engine (include/rollkin/synthesis/envelope.hpp) against closed forms:
//  - a roller of radius r on a translating follower (in-line and offset), cycloidal rise-dwell-return: the
//    envelope on the turning cam is the pitch curve c(theta) = R(-theta) (e, s0 + s) offset by r along its
//    normal, c - r J c'/|c'| (closed form of c' from the law's derivative), to 1e-10 of the cam's size;
//  - a flat-faced translating follower: the envelope of the lines x . n = h(theta), n = (sin, cos)(theta),
//    h = Rb + s, is h n + h' n' (the support-function form), to 1e-10;
//  - a circle of radius r whose centre is at distance a from a centre of rotation: the inner envelope is the
//    circle of radius a - r; the spline fitted through the samples stays within the stated tolerance of it
//    (checked densely, not only at the mid-poses the engine checks);
//  - an undercut: a roller larger than the smallest radius of curvature of the pitch curve; the engine's
//    folds against the cam angles where the pitch curve's radius of curvature (closed form) equals r, 1e-6,
//    also from a first grid coarser than the undercut regions;
//  - a straight rack flank rolled with its pitch line on a pitch circle envelopes the involute of the base
//    circle: theta - inv(alpha) the same at every point to 1e-10.
#define BOOST_TEST_MODULE synthesis_envelope
#include <boost/test/unit_test.hpp>

#include "rollkin/synthesis/envelope.hpp"
#include "rollkin/synthesis/motion_law.hpp"

#include <cmath>

using namespace rollkin;
using namespace rollkin::synthesis;

namespace {

const double kPi = M_PI;
const double kDeg = kPi / 180;
using V = Vec2<double>;

V perp(const V& x) { return V(-x.y(), x.x()); }
V rot(double a, const V& x) { return V(std::cos(a) * x.x() - std::sin(a) * x.y(), std::sin(a) * x.x() + std::cos(a) * x.y()); }

MotionLaw<double> cycloidal_law(double h, double rise_deg = 90) {
  return MotionLaw<double>::from_segments({{0, rise_deg * kDeg, h, RiseKind::Cycloidal},
                                           {rise_deg * kDeg, 180 * kDeg, 0, RiseKind::Dwell},
                                           {180 * kDeg, (180 + rise_deg) * kDeg, -h, RiseKind::Cycloidal},
                                           {(180 + rise_deg) * kDeg, 360 * kDeg, 0, RiseKind::Dwell}});
}

/// Follower translating along world y at x = e, its origin at (e, y0 + s(theta)); cam turning ccw by theta.
std::function<MotionJet<double>(const double&)> translating(const MotionLaw<double>& law, double e, double y0) {
  return [law, e, y0](const double& th) {
    const LawValue<double> v = law(th);
    return relative_to_turning_frame<double>(th, 1, 0, 0, 0, 0, V(e, y0 + v.s), V(0, v.v), V(0, v.a));
  };
}

Jet<double> circle_jet(double r, double u) {
  Jet<double> j;
  j.p = V(r * std::cos(u), r * std::sin(u));
  j.d1 = V(-r * std::sin(u), r * std::cos(u));
  j.d2 = -j.p;
  return j;
}

/// Pitch curve of the roller centre in the cam frame, c = R(-theta) v with v = (e, s0 + s), and c', c''.
struct Pitch {
  V c, dc, ddc;
};
Pitch pitch(const MotionLaw<double>& law, double e, double s0, double th) {
  const LawValue<double> l = law(th);
  const V v(e, s0 + l.s), dv(0, l.v), ddv(0, l.a);
  return {rot(-th, v), rot(-th, V(dv - perp(v))), rot(-th, V(ddv - 2 * perp(dv) - v))};
}

EnvelopeProblem<double> roller_problem(const MotionLaw<double>& law, double e, double s0, double r) {
  EnvelopeProblem<double> pr;
  pr.contour = [r](const double& u) { return circle_jet(r, u); };
  pr.motion = translating(law, e, s0);
  pr.t_begin = 0;
  pr.t_end = 2 * kPi;
  pr.periodic = true;
  pr.u_guess = std::atan2(-s0, -e);  // the roller's point facing the cam centre
  pr.u_scale = 2 * kPi;
  return pr;
}

}  // namespace

BOOST_AUTO_TEST_CASE(roller_follower_gives_the_offset_pitch_curve) {
  const double Rb = 40, r = 10, h = 15;
  const MotionLaw<double> law = cycloidal_law(h);
  for (double e : {0.0, 12.0}) {
    const double s0 = std::sqrt((Rb + r) * (Rb + r) - e * e);
    const EnvelopeProblem<double> pr = roller_problem(law, e, s0, r);
    const Envelope<double> env = envelope(pr, EnvelopeOptions{1e-6});
    BOOST_TEST(env.defects.empty());
    BOOST_TEST(env.samples.size() >= 64u);
    double worst = 0;
    for (const auto& s : env.samples) {
      const Pitch p = pitch(law, e, s0, s.t);
      const V closed = p.c - r * perp(p.dc) / p.dc.norm();
      worst = std::max(worst, (s.point - closed).norm());
    }
    BOOST_TEST_INFO("offset " << e << " samples " << env.samples.size());
    BOOST_TEST(worst < 1e-10 * (Rb + h));
    BOOST_TEST(env.max_midpoint_deviation <= 1e-6);
  }
}

BOOST_AUTO_TEST_CASE(flat_faced_follower_gives_the_support_function_profile) {
  const double Rb = 40, h = 8;
  const MotionLaw<double> law = cycloidal_law(h);
  for (double e : {0.0, 5.0}) {
    EnvelopeProblem<double> pr;
    pr.contour = [](const double& u) {
      Jet<double> j;
      j.p = V(u, 0);
      j.d1 = V(1, 0);
      return j;
    };
    pr.motion = translating(law, e, Rb);
    pr.t_begin = 0;
    pr.t_end = 2 * kPi;
    pr.periodic = true;
    pr.u_guess = -e;
    pr.u_scale = Rb;
    const Envelope<double> env = envelope(pr, EnvelopeOptions{1e-7});
    BOOST_TEST(env.defects.empty());
    double worst = 0;
    for (const auto& s : env.samples) {
      const LawValue<double> l = law(s.t);
      const V n(std::sin(s.t), std::cos(s.t)), dn(std::cos(s.t), -std::sin(s.t));
      const V closed = (Rb + l.s) * n + l.v * dn;
      worst = std::max(worst, (s.point - closed).norm());
    }
    BOOST_TEST(worst < 1e-10 * (Rb + h));
  }
}

BOOST_AUTO_TEST_CASE(circle_under_rotation_envelopes_a_circle_within_the_tolerance) {
  const double a = 30, r = 7, tol = 1e-7;
  EnvelopeProblem<double> pr;
  pr.contour = [r, a](const double& u) {
    Jet<double> j = circle_jet(r, u);
    j.p += V(a, 0);
    return j;
  };
  pr.motion = [](const double& t) { return MotionJet<double>{t, 1, 0, V(0, 0), V(0, 0), V(0, 0)}; };
  pr.t_begin = 0;
  pr.t_end = 2 * kPi;
  pr.periodic = true;
  pr.u_guess = kPi;
  pr.u_scale = 2 * kPi;
  const Envelope<double> env = envelope(pr, EnvelopeOptions{tol});
  BOOST_TEST(env.defects.empty());
  for (const auto& s : env.samples) BOOST_TEST(std::abs(s.point.norm() - (a - r)) < 1e-12 * a);
  SplineOptions<double> o;
  o.closed = true;
  const SampledProfile<double> spline(env.points(), o);
  double worst = 0;
  for (int i = 0; i < 20000; ++i) {
    const double u = spline.domain().hi * (i + 0.5) / 20000;
    worst = std::max(worst, std::abs(spline.jet(u, 0).p.norm() - (a - r)));
  }
  BOOST_TEST_INFO("samples " << env.samples.size() << " worst " << worst);
  BOOST_TEST(worst <= 1.5 * tol);
  BOOST_TEST(worst > tol / 100);  // not oversampled by orders of magnitude either
}

BOOST_AUTO_TEST_CASE(undercut_roller_folds_where_the_pitch_radius_equals_the_roller) {
  const double Rb = 20, r = 15, h = 30, e = 0;
  const MotionLaw<double> law = cycloidal_law(h, 30);
  const double s0 = Rb + r;
  // Closed form: radius of curvature of the (clockwise) pitch curve, convex where positive.
  auto rho = [&](double th) {
    const Pitch p = pitch(law, e, s0, th);
    const double cross = p.dc.x() * p.ddc.y() - p.dc.y() * p.ddc.x();
    return std::pow(p.dc.norm(), 3) / -cross;
  };
  std::vector<double> truth;
  const int n = 36000;
  for (int i = 0; i < n; ++i) {
    const double t0 = 2 * kPi * i / n, t1 = 2 * kPi * (i + 1) / n;
    const double g0 = rho(t0) - r, g1 = rho(t1) - r;
    if (rho(t0) > 0 && rho(t1) > 0 && (g0 < 0) != (g1 < 0)) {
      double lo = t0, hi = t1;
      for (int k = 0; k < 60; ++k) {
        const double mid = (lo + hi) / 2;
        if ((rho(mid) - r < 0) == (g0 < 0)) lo = mid; else hi = mid;
      }
      truth.push_back((lo + hi) / 2);
    }
  }
  BOOST_TEST_REQUIRE(truth.size() >= 2u);  // the roller is larger than the pitch curve's smallest radius
  const Envelope<double> env = envelope(roller_problem(law, e, s0, r), EnvelopeOptions{1e-6, 720});
  std::vector<double> folds;
  for (const auto& d : env.defects) folds.push_back(d.t);
  BOOST_TEST_REQUIRE(folds.size() == truth.size());
  for (std::size_t k = 0; k < folds.size(); ++k) {
    BOOST_TEST_INFO("fold " << k << " at " << folds[k] / kDeg << " deg, closed form " << truth[k] / kDeg);
    BOOST_TEST(std::abs(folds[k] - truth[k]) < 1e-6 * kDeg);
  }
  // From a first grid of 45 deg, coarser than the undercut regions (about 7 deg wide): the folds show between
  // the refined samples and are found all the same.
  const Envelope<double> coarse = envelope(roller_problem(law, e, s0, r), EnvelopeOptions{1e-6, 8});
  BOOST_TEST_REQUIRE(coarse.defects.size() == truth.size());
  for (std::size_t k = 0; k < truth.size(); ++k) BOOST_TEST(std::abs(coarse.defects[k].t - truth[k]) < 1e-6 * kDeg);
}

// A straight rack flank (pressure angle a0, through the pitch point) under the rolling of the rack's pitch line
// on the gear's pitch circle (radius Rp): the envelope on the gear is the involute of the base circle
// Rb = Rp cos(a0). An involute's point at radius rho lies at polar angle theta0 + inv(alpha), cos(alpha) =
// Rb / rho, inv(alpha) = tan(alpha) - alpha: theta - inv(alpha) is the same for every point (to 1e-10).
BOOST_AUTO_TEST_CASE(rack_flank_generates_the_involute) {
  const double Rp = 50, a0 = 20 * kDeg, Rb = Rp * std::cos(a0);
  EnvelopeProblem<double> pr;
  const V dir(std::sin(a0), -std::cos(a0));
  pr.contour = [dir](const double& u) {
    Jet<double> j;
    j.p = u * dir;
    j.d1 = dir;
    return j;
  };
  // The gear turns by phi about its centre; the rack (pitch line y = Rp) moves by -Rp phi along x.
  pr.motion = [Rp](const double& phi) {
    return relative_to_turning_frame<double>(phi, 1, 0, 0, 0, 0, V(-Rp * phi, Rp), V(-Rp, 0), V(0, 0));
  };
  // The contact runs along the line of action at Rb per radian; it reaches the base circle (the involute's cusp)
  // Rp sin(a0) from the pitch point, at |phi| = tan(a0) = 20.85 deg: stay within 15 deg.
  pr.t_begin = -15 * kDeg;
  pr.t_end = 15 * kDeg;
  pr.u_guess = 0;
  pr.u_scale = 10;
  const Envelope<double> env = envelope(pr, EnvelopeOptions{1e-8, 64});
  BOOST_TEST(env.defects.empty());
  BOOST_TEST_REQUIRE(env.samples.size() >= 64u);
  std::vector<double> theta0;
  for (const auto& s : env.samples) {
    const double rho = s.point.norm();
    BOOST_TEST(rho >= Rb * (1 - 1e-12));
    const double alpha = std::acos(std::min(1.0, Rb / rho)), inv = std::tan(alpha) - alpha;
    const double theta = std::atan2(s.point.y(), s.point.x());
    theta0.push_back(theta - inv);  // this flank unwinds counter-clockwise from the base circle
  }
  double spread = 0;
  for (double t : theta0) spread = std::max(spread, std::abs(t - theta0.front()));
  BOOST_TEST_INFO("spread of theta - inv(alpha): " << spread);
  BOOST_TEST(spread < 1e-10);
}
