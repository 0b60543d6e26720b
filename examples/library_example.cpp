// Using rollkin as a library: a planet disk (radius r = 1) on an arm rolls inside a fixed ring (radius
// R = 4). The mechanism is described in code with MechanismBuilder, assembled, swept over a full turn of
// the arm, and checked against its closed form (docs/method.md section 5): the planet turns -(R - r)/r
// times the arm angle, and the rim point that starts at the contact traces the astroid
// (4 cos^3 phi, 4 sin^3 phi). Exit status 0 when every pose is solved and matches, 1 otherwise.
// Built and run by ctest as the test `library_example` (examples/CMakeLists.txt).
#include "rollkin/builder.hpp"
#include "rollkin/io/units.hpp"
#include "rollkin/solve/continuation.hpp"

#include <cmath>
#include <cstdio>
#include <vector>

using namespace rollkin;

int main() {
  const double R = 4, r = 1;

  // [describe] links, contours and pairs by name; build() numbers the variables and finds the loops.
  MechanismBuilder<double> b;
  const int ground = b.link("ground", true), arm = b.link("arm"), planet = b.link("planet");
  const int ring = b.contour(ground, "ring", Circle<double>(R), SE2<double>(), /*material outside*/ true);
  const int rim = b.contour(planet, "rim", Circle<double>(r));
  const int drive = b.revolute("arm", ground, arm, SE2<double>(), SE2<double>(), "phi");
  b.revolute("planet", arm, planet, SE2<double>(0, Vec2<double>(R - r, 0)), SE2<double>(), "psi");
  b.contact("mesh", /*rolling*/ true, ring, rim);
  b.driver(drive);
  const Mechanism<double> m = b.build();

  // [solve] assemble from a guess, then sweep the driver (radians) by continuation.
  SolveData<double> sd(m);
  VectorX<double> q = VectorX<double>::Zero(m.variable_count());  // phi, psi, u (ring), v (rim)
  const SolveReport<double> assembly = assemble(m, q, sd);        // 4 equations of rank 3: redundant, consistent
  std::vector<double> inputs;
  for (int k = 0; k <= 24; ++k) inputs.push_back(2 * pi<double>() * k / 24);
  const SweepResult<double> result = sweep(m, sd, q, assembly, 0, inputs);
  // [end]

  std::printf("assembly: %s\n", to_string(assembly.status));
  std::printf("%10s %12s %12s %12s %12s\n", "phi [deg]", "psi [deg]", "rim x", "rim y", "error");
  const double tol = 1e-9 * R;  // relative to the mechanism's size
  bool ok = result.all_solved();
  for (std::size_t i = 0; i < result.poses.size(); ++i) {
    const SweepPose<double>& pose = result.poses[i];
    const double phi = pose.q(0), psi = pose.q(1);
    // Rim point that started at the contact (planet frame (r, 0)), in world coordinates.
    const double turn = phi + psi;
    const Vec2<double> rim_point = (R - r) * Vec2<double>(std::cos(phi), std::sin(phi)) + r * Vec2<double>(std::cos(turn), std::sin(turn));
    const Vec2<double> astroid(R * std::pow(std::cos(phi), 3), R * std::pow(std::sin(phi), 3));
    const double error = std::max((rim_point - astroid).norm(), R * std::abs(turn + (R - r) / r * phi));
    ok = ok && pose.report.ok() && error <= tol;
    if (i % 4 == 0 || error > tol)
      std::printf("%10.1f %12.6f %12.8f %12.8f %12.2e %s\n", rad_to_deg(phi), rad_to_deg(psi), rim_point.x(),
                  rim_point.y(), error, to_string(pose.report.status));
  }
  std::printf("%s: %zu poses against the hypocycloid's closed form, tolerance %.1e\n", ok ? "ok" : "FAILED",
              result.poses.size(), tol);
  return ok ? 0 : 1;
}
