// Mechanisms of the benchmark: the reference example and the gear pairs with any profile representation
// in place of the analytic curves (sampled spline, Bezier path), built exactly like the fixtures of
// rollkin/samples/mechanisms.hpp (same links, placements, pairs and variable order), and the samples they use.
#pragma once

#include "rollkin/samples/mechanisms.hpp"
#include "rollkin/builder.hpp"
#include "rollkin/synthesis/pitch_curves.hpp"

#include <cmath>
#include <type_traits>
#include <vector>

namespace rollkin::bench {

using testing::Fixture;
using Vec2d = Vec2<double>;
using Shape = ProfileShape<double>;

// ---- contact parameters for an assembly guess ---------------------------------------------------------

/// Parameter of the profile point nearest `target` (profile frame). Analytic curves use their own
/// parametrisation; sampled and Bezier profiles a scan of the domain followed by Newton on (p - target).p'.
inline double param_near(const Shape& shape, const Vec2d& target) {
  return std::visit(
      [&](const auto& prof) -> double {
        using P = std::decay_t<decltype(prof)>;
        if constexpr (std::is_same_v<P, Circle<double>>) return std::atan2(target.y(), target.x());
        else if constexpr (std::is_same_v<P, Parabola<double>>) return target.x();
        else if constexpr (std::is_same_v<P, Ellipse<double>>)
          return std::atan2(target.y() / prof.semi_y(), target.x() / prof.semi_x());
        else {
          const Domain<double> d = prof.domain();
          const int scan = 20000;
          double best = d.lo, best_dist = INFINITY;
          for (int k = 0; k <= scan; ++k) {
            const double u = d.lo + (d.hi - d.lo) * k / scan;
            const double dist = (prof.jet(u, 0).p - target).norm();
            if (dist < best_dist) best = u, best_dist = dist;
          }
          double u = best;
          for (int it = 0; it < 50; ++it) {
            const Jet<double> j = prof.jet(u, 2);
            const double f = (j.p - target).dot(j.d1), df = j.d1.squaredNorm() + (j.p - target).dot(j.d2);
            const double step = f / df;
            u -= step;
            if (std::abs(step) < 1e-15 * (1 + std::abs(u))) break;
          }
          return u;
        }
      },
      shape);
}

/// Point of an angle on a circle of radius r about the origin.
inline Vec2d on_circle(double r, double angle) { return r * Vec2d(std::cos(angle), std::sin(angle)); }

// ---- the reference example (docs/method.md section 4) with any parabola / disk representation --------------

/// Same mechanism as testing::paper_fourbar<double>() (scale 1, convex side), with the parabola and the two
/// disks given as any profile. Variables: theta2, x, theta23, theta34, theta4, theta5.
inline Fixture<double> paper_scene(const Shape& parabola, const Shape& rim3, const Shape& rim4) {
  MechanismBuilder<double> b;
  const int l1 = b.link("link1", true), l2 = b.link("link2"), l3 = b.link("link3"), l4 = b.link("link4");
  const int par = b.contour(l2, "parabola", parabola, SE2<double>(pi<double>() / 2, Vec2d(2, 0)), false);
  const int c3 = b.contour(l3, "rim", rim3);
  const int c4 = b.contour(l4, "rim", rim4, SE2<double>(0, Vec2d(2, 0)));
  const int oa = b.revolute("O_A", l1, l2, SE2<double>(), SE2<double>(), "theta2");
  b.contact("A", true, par, c3, "x", "theta23");
  b.contact("B", true, c3, c4, "theta34", "theta4");
  b.revolute("O_B", l1, l4, SE2<double>(0, Vec2d(7, -2)), SE2<double>(), "theta5");
  b.driver(oa);
  Fixture<double> f{b.build(), VectorX<double>(6), {1, 2}};
  const double deg = pi<double>() / 180;
  // The analytic fixture's guess, mapped to each representation's parameters: vertex, disk 3 at 180 deg
  // (both held at assembly), disk 3 at -3 deg, disk 4 at 117 deg.
  f.guess << 0, param_near(parabola, Vec2d(0, 0)), param_near(rim3, on_circle(1, 180 * deg)),
      param_near(rim3, on_circle(1, -3 * deg)), param_near(rim4, on_circle(4, 117 * deg)), 60 * deg;
  return f;
}

/// y = a x^2, x uniform in [lo, hi], n samples.
inline std::vector<Vec2d> parabola_samples(double a, double lo, double hi, std::size_t n) {
  std::vector<Vec2d> q(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double x = lo + (hi - lo) * static_cast<double>(k) / static_cast<double>(n - 1);
    q[k] = Vec2d(x, a * x * x);
  }
  return q;
}

// ---- twin elliptical gears --------------------------------------------------------------------------------

/// Same mechanism as testing::elliptical_gears<double>(a, e, rolling, {}, start) with the two pitch
/// ellipses given as any profile (in the ellipse's centre frame). Variables: phi1, u, v, phi2.
inline Fixture<double> gear_scene(const Shape& pitch1, const Shape& pitch2, double a, double e, bool rolling,
                                  double start) {
  MechanismBuilder<double> b;
  const int ground = b.link("ground", true), g1 = b.link("gear1"), g2 = b.link("gear2");
  const SE2<double> centre_left_of_focus(0, Vec2d(-a * e, 0));
  const int e1 = b.contour(g1, "pitch", pitch1, centre_left_of_focus);
  const int e2 = b.contour(g2, "pitch", pitch2, centre_left_of_focus);
  const int drive = b.revolute("pivot1", ground, g1, SE2<double>(), SE2<double>(), "phi1");
  b.contact("mesh", rolling, e1, e2, "u", "v");
  b.revolute("pivot2", ground, g2, SE2<double>(0, Vec2d(2 * a, 0)), SE2<double>(), "phi2");
  b.driver(drive);
  // The analytic fixture's exact guess (eccentric anomalies), mapped to the profiles' parameters.
  const Fixture<double> exact = testing::elliptical_gears<double>(a, e, rolling, {}, start);
  const double bminor = a * std::sqrt(1 - e * e);
  Fixture<double> f{b.build(), VectorX<double>(4), {}};
  const auto point = [&](double t) { return Vec2d(a * std::cos(t), bminor * std::sin(t)); };
  f.guess << exact.guess(0), param_near(pitch1, point(exact.guess(1))), param_near(pitch2, point(exact.guess(2))),
      exact.guess(3);
  return f;
}

/// Ellipse (a cos t, b sin t) at n uniform eccentric anomalies, counter-clockwise from t = 0 (closed).
inline std::vector<Vec2d> ellipse_samples(double a, double b, std::size_t n) {
  std::vector<Vec2d> q(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double t = 2 * pi<double>() * static_cast<double>(k) / static_cast<double>(n);
    q[k] = Vec2d(a * std::cos(t), b * std::sin(t));
  }
  return q;
}

// ---- a non-circular gear pair synthesised from a transmission function (synthesis/pitch_curves.hpp) -------------------
// phi2 = -f(phi1), f(p) = p + k sin p (one turn of gear 2 per turn of gear 1), centre distance E:
// pitch radii r1 = E f'/(1 + f'), r2 = E/(1 + f') (docs/method.md section 5). The contact lies on the line of
// centres: gear 1's pitch point of body polar angle -p (radius r1(p)) touches gear 2's point of body polar
// angle pi + f(p) (radius r2(p)) when phi1 = p.

struct NonCircularGears {
  double E = 2, k = 0.3;
  double f(double p) const { return p + k * std::sin(p); }
  double df(double p) const { return 1 + k * std::cos(p); }
  double r1(double p) const { return E * df(p) / (1 + df(p)); }
  double r2(double p) const { return E / (1 + df(p)); }

  /// Pitch curves of n samples each from synthesis/pitch_curves.hpp (equal body polar angles, counter-clockwise).
  GearPair<double> pitch_curves(std::size_t n) const {
    return synthesise_gear_pair(TransmissionFunction<double>::sinusoidal(k), E, n, n);
  }

  /// Pivots E apart; contact pair (rolling or cam) between the two pitch curves. Variables: phi1, u, v, phi2.
  /// Assembled at phi1 = start (a cam pair is singular where the pitch radii are extremal, p = 0 and pi).
  Fixture<double> scene(const Shape& pitch1, const Shape& pitch2, bool rolling, double start = 0) const {
    MechanismBuilder<double> b;
    const int ground = b.link("ground", true), g1 = b.link("gear1"), g2 = b.link("gear2");
    const int c1 = b.contour(g1, "pitch", pitch1), c2 = b.contour(g2, "pitch", pitch2);
    const int drive = b.revolute("pivot1", ground, g1, SE2<double>(), SE2<double>(), "phi1");
    b.contact("mesh", rolling, c1, c2, "u", "v");
    b.revolute("pivot2", ground, g2, SE2<double>(0, Vec2d(E, 0)), SE2<double>(), "phi2");
    b.driver(drive);
    Fixture<double> fx{b.build(), VectorX<double>(4), {}};
    const double p = start;
    fx.guess << p, param_near(pitch1, r1(p) * Vec2d(std::cos(-p), std::sin(-p))),
        param_near(pitch2, r2(p) * Vec2d(std::cos(pi<double>() + f(p)), std::sin(pi<double>() + f(p)))), -f(p);
    return fx;
  }
};

}  // namespace rollkin::bench
