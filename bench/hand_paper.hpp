// The hand-specialised limit for the paper example (docs/method.md section 4): what a programmer who knows
// this one mechanism would write, with nothing general left. Two unknowns instead of the library's five:
//   X     the contact parameter on the parabola y = a X^2 (the CSV's A.x),
//   phi   the angle of disk 4 about O_B (the CSV's O_B.theta5, link4.angle),
// and two equations for a crank angle theta2:
//   F1 = |C4 - C3|^2 - (r3 + r4)^2 = 0                         disks 3 and 4 touch externally
//   F2 = (r3 + r4) gamma - r3 psi3 - r4 phi - K = 0              rolling at B, eq. (7b) with the contact angles
//        theta34 = gamma - psi3 and theta4 = gamma + pi - phi (gamma: direction from C3 to C4)
// where C3(X) is disk 3's centre (the parabola point offset by r3 along its convex normal, turned by
// theta2), C4(phi) = O_B + l4 (cos phi, sin phi), and disk 3's angle psi3 follows from rolling at A, eq. (7a),
// with the closed-form arc length of the parabola (method.md section 5):
//   psi3 = theta2 + atan(2 a X) + s(X) / r3,   s(X) = X/2 sqrt(1 + 4a^2X^2) + asinh(2aX)/(4a).
// The Jacobian is in closed form; Newton from a secant prediction through the last two poses.
#pragma once

#include "rollkin/scalar.hpp"  // deg_to_rad only

#include <cmath>
#include <vector>

namespace hand_paper {

constexpr double a = 0.5, r3 = 1, r4 = 4, l2 = 2, l4 = 2, obx = 7, oby = -2;

struct Unknowns {
  double X, phi;
};

/// The residual F and the 2x2 Jacobian J (row-major) at crank angle t (radians).
inline void residual(double t, const Unknowns& u, double K, double F[2], double J[4]) {
  const double X = u.X, w2 = 1 + 4 * a * a * X * X, w = std::sqrt(w2);
  const double ct = std::cos(t), st = std::sin(t), cp = std::cos(u.phi), sp = std::sin(u.phi);
  // Disk 3's centre in link 2's frame (parabola turned by 90 degrees, vertex at (l2, 0)) and its derivative.
  const double cx = l2 - a * X * X + r3 / w, cy = X + 2 * a * r3 * X / w;
  const double dcx = -2 * a * X - r3 * 4 * a * a * X / (w2 * w), dcy = 1 + 2 * a * r3 / (w2 * w);
  const double c3x = ct * cx - st * cy, c3y = st * cx + ct * cy;
  const double d3x = ct * dcx - st * dcy, d3y = st * dcx + ct * dcy;
  const double c4x = obx + l4 * cp, c4y = oby + l4 * sp, d4x = -l4 * sp, d4y = l4 * cp;
  const double dx = c4x - c3x, dy = c4y - c3y, n2 = dx * dx + dy * dy;
  const double s = X / 2 * w + std::asinh(2 * a * X) / (4 * a);
  const double psi3 = t + std::atan(2 * a * X) + s / r3;
  const double gamma = std::atan2(dy, dx);
  F[0] = n2 - (r3 + r4) * (r3 + r4);
  F[1] = (r3 + r4) * gamma - r3 * psi3 - r4 * u.phi - K;
  J[0] = -2 * (dx * d3x + dy * d3y);
  J[1] = 2 * (dx * d4x + dy * d4y);
  const double dgX = (dx * -d3y - dy * -d3x) / n2, dgP = (dx * d4y - dy * d4x) / n2;
  J[2] = (r3 + r4) * dgX - r3 * (2 * a / w2 + w / r3);
  J[3] = (r3 + r4) * dgP - r4;
}

/// Newton from u; returns the iterations taken (each one residual + Jacobian), or -1 without convergence.
inline int newton(double t, Unknowns& u, double K) {
  double F[2], J[4];
  for (int it = 1; it <= 20; ++it) {
    residual(t, u, K, F, J);
    const double det = J[0] * J[3] - J[1] * J[2];
    const double sX = (F[0] * J[3] - F[1] * J[1]) / det, sP = (J[0] * F[1] - J[2] * F[0]) / det;
    u.X -= sX;
    u.phi -= sP;
    if (std::abs(sX) <= 1e-15 && std::abs(sP) <= 1e-15) return it;
    if (std::abs(sX) <= 1e-11 && std::abs(sP) <= 1e-11) {  // quadratic convergence: one more step is exact
      residual(t, u, K, F, J);
      const double d2 = J[0] * J[3] - J[1] * J[2];
      u.X -= (F[0] * J[3] - F[1] * J[1]) / d2;
      u.phi -= (J[0] * F[1] - J[2] * F[0]) / d2;
      return it + 1;
    }
  }
  return -1;
}

/// The assembly pose (theta2 = 0, X = 0, disk 3's centre at (l2 + r3, 0)): disk 4's centre the upper point
/// at r3 + r4 from it and l4 from O_B; K from the assembly contact angles.
struct Assembly {
  Unknowns u;
  double K;
};
inline Assembly assemble() {
  const double c3x = l2 + r3, c3y = 0, R = r3 + r4;
  const double ex = obx - c3x, ey = oby - c3y, d = std::sqrt(ex * ex + ey * ey);
  const double along = (R * R - l4 * l4 + d * d) / (2 * d), h = std::sqrt(R * R - along * along);
  const double mx = c3x + along * ex / d, my = c3y + along * ey / d;
  double px = mx - h * ey / d, py = my + h * ex / d;
  if (py < my + h * -ex / d) {  // the upper of the two intersections
    px = mx + h * ey / d;
    py = my - h * ex / d;
  }
  const double phi = std::atan2(py - oby, px - obx), gamma = std::atan2(py - c3y, px - c3x);
  return {{0, phi}, (r3 + r4) * gamma - r4 * phi};  // psi3 = 0 at the assembly
}

/// Sweeps theta2 (degrees) over from + k step, k = 0..n-1, from the assembly (reached from 0 in 1-degree
/// steps); writes X and phi per pose. Returns the Newton iterations over the n poses, or -1 on a failure.
inline long sweep(double from_deg, double step_deg, long n, std::vector<Unknowns>& out) {
  const double deg = rollkin::deg_to_rad(1.0);
  const Assembly as = assemble();
  Unknowns u = as.u;
  for (double t = 0; t > from_deg; t = std::fmax(t - 1, from_deg))
    if (newton(std::fmax(t - 1, from_deg) * deg, u, as.K) < 0) return -1;
  out.resize(static_cast<std::size_t>(n));
  long iterations = 0;
  Unknowns prev = u;
  for (long k = 0; k < n; ++k) {
    const double t = (from_deg + step_deg * static_cast<double>(k)) * deg;
    Unknowns guess = u;
    if (k > 0) guess = {2 * u.X - prev.X, 2 * u.phi - prev.phi};  // secant through the last two poses
    const int it = newton(t, guess, as.K);
    if (it < 0) return -1;
    iterations += it;
    prev = u;
    u = guess;
    out[static_cast<std::size_t>(k)] = u;
  }
  return iterations;
}

}  // namespace hand_paper
