// The sign of the relative curvature of two contours at a contact, decided exactly: the sign test behind
// the design check (analysis/design_check.hpp, docs/analysis.md "Design check").
//
// Each contour enters by the first two derivatives of its parameterisation at the contact, d1 = p', d2 = p''
// (material on the left), whose signed curvature is kappa = (d1 x d2) / |d1|^3 (profile/jet.hpp). The sign of
// kappa_a + kappa_b, with a zero band of relative width `band` around it,
//   +1  kappa_a + kappa_b >  band (|kappa_a| + |kappa_b|)   the contours conform (bodies apart near the contact)
//    0  |kappa_a + kappa_b| <= band (|kappa_a| + |kappa_b|)  they osculate (within the band)
//   -1  kappa_a + kappa_b < -band (|kappa_a| + |kappa_b|)   they interpenetrate near the contact
// is decided from the doubles given, without rounding: with k = d1 x d2 and s = |d1|^2 (exact in rationals),
// comparing c1 |kappa_a| with c2 |kappa_b| is comparing c1^2 k_a^2 s_b^3 with c2^2 k_b^2 s_a^3, a polynomial
// in the inputs evaluated in CGAL's exact rational kernel (src/geometry/curvature_sign.cpp). The band is a
// pure number (curvature relative to curvature), so the decision does not depend on the scene's size.
//
// A circle of radius r is given exactly by d1 = (r, 0), d2 = (0, r) (convex, kappa = 1/r) or (0, -r) (concave):
// circle_derivatives() below.
#pragma once

#include "rollkin/scalar.hpp"

#include <array>

namespace rollkin::geometry {

/// Sign of kappa_a + kappa_b with the zero band described above (band in [0, 1)).
int relative_curvature_sign(const Vec2<double>& a1, const Vec2<double>& a2, const Vec2<double>& b1,
                            const Vec2<double>& b2, double band);

/// {d1, d2} of a circle of radius r whose curvature is exactly +1/r (convex) or -1/r (concave, a ring).
inline std::array<Vec2<double>, 2> circle_derivatives(double r, bool convex) {
  return {Vec2<double>(r, 0), Vec2<double>(0, convex ? r : -r)};
}

}  // namespace rollkin::geometry
