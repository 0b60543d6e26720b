// Exact sign of a relative curvature (geometry/curvature_sign.hpp) in CGAL::Simple_cartesian over GMP
// rationals: every double converts exactly, and the cross products, squared lengths and their products stay
// exact.
#include "rollkin/geometry/curvature_sign.hpp"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost_mp.h>

#include <boost/multiprecision/gmp.hpp>

namespace rollkin::geometry {
namespace {

using Rational = boost::multiprecision::mpq_rational;
using ExactKernel = CGAL::Simple_cartesian<Rational>;
using ExactVector = ExactKernel::Vector_2;

ExactVector exact(const Vec2<double>& v) { return ExactVector(Rational(v.x()), Rational(v.y())); }

/// A curvature kappa = k / s^(3/2) held exactly as the cross product k = d1 x d2 and s = |d1|^2.
struct ExactCurvature {
  Rational k, s;
  ExactCurvature(const Vec2<double>& d1, const Vec2<double>& d2)
      : k(CGAL::determinant(exact(d1), exact(d2))), s(exact(d1).squared_length()) {}
  int sign() const { return static_cast<int>(CGAL::sign(k)); }
};

/// Sign of c1 |x| - c2 |y| for curvatures x, y and factors c1, c2 >= 0: of c1^2 k_x^2 s_y^3 - c2^2 k_y^2 s_x^3.
int compare_magnitudes(const Rational& c1, const ExactCurvature& x, const Rational& c2, const ExactCurvature& y) {
  const Rational lhs = c1 * c1 * x.k * x.k * y.s * y.s * y.s;
  const Rational rhs = c2 * c2 * y.k * y.k * x.s * x.s * x.s;
  return static_cast<int>(CGAL::compare(lhs, rhs));
}

}  // namespace

int relative_curvature_sign(const Vec2<double>& a1, const Vec2<double>& a2, const Vec2<double>& b1,
                            const Vec2<double>& b2, double band) {
  const ExactCurvature a(a1, a2), b(b1, b2);
  const int sa = a.sign(), sb = b.sign();
  // Same signs: |sum| = |kappa_a| + |kappa_b|, outside the band (< 1) unless both vanish.
  if (sa >= 0 && sb >= 0) return sa + sb > 0 ? 1 : 0;
  if (sa <= 0 && sb <= 0) return -1;
  // Opposite signs: with P the positive one and N the magnitude of the negative one, the sum P - N lies above
  // the band when P (1 - band) > N (1 + band), below it when P (1 + band) < N (1 - band).
  const ExactCurvature& positive = sa > 0 ? a : b;
  const ExactCurvature& negative = sa > 0 ? b : a;
  const Rational lo = Rational(1) - Rational(band), hi = Rational(1) + Rational(band);
  if (compare_magnitudes(lo, positive, hi, negative) > 0) return 1;
  if (compare_magnitudes(hi, positive, lo, negative) < 0) return -1;
  return 0;
}

}  // namespace rollkin::geometry
