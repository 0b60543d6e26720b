// Uses the installed rollkin: header-only SE(2) algebra in double and in MPFR (links MPFR/GMP through the
// exported targets) and the compiled library (number formatting). Exit status 0 only if every check passes.
#include <rollkin/io/format.hpp>
#include <rollkin/scalar_mpfr.hpp>
#include <rollkin/se2.hpp>

#include <cmath>
#include <cstdio>
#include <string>

namespace {
int failures = 0;
void check(bool ok, const char* what) {
  std::printf("%s: %s\n", ok ? "ok  " : "FAIL", what);
  if (!ok) ++failures;
}
}  // namespace

int main() {
  using rollkin::SE2;
  using V2 = rollkin::Vec2<double>;
  const double pi = rollkin::pi<double>();

  // Quarter turn about the origin after a unit translation along x: (1, 0) -> (0, 1); then the same again.
  const SE2<double> a(pi / 2, V2(0.0, 0.0)), b(0.0, V2(1.0, 0.0));
  const SE2<double> ab = a * b;
  check(std::abs(ab.translation().x() - 0.0) < 1e-15 && std::abs(ab.translation().y() - 1.0) < 1e-15,
        "SE2<double> composition translation = (0, 1)");
  const SE2<double> abab = ab * ab;  // rotation pi, translation R(pi/2)(0,1) + (0,1) = (-1, 1)
  check(std::abs(abab.angle() - pi) < 1e-15, "SE2<double> composition angle = pi");
  const V2 p = abab.act(V2(2.0, 0.0));  // (-2, 0) + (-1, 1) = (-3, 1)
  check(std::abs(p.x() + 3.0) < 1e-14 && std::abs(p.y() - 1.0) < 1e-14, "act on a point = (-3, 1)");
  check((ab * ab.inverse()).matrix().isIdentity(1e-15), "g * g^-1 = I");

  // The same in 50-digit MPFR: sin(pi/6) = 1/2 to ~1e-49.
  using rollkin::mpfr50;
  const SE2<mpfr50> r = SE2<mpfr50>::rotation(rollkin::pi<mpfr50>() / 6);
  const mpfr50 err = abs(r.sin_angle() - mpfr50(1) / 2);
  check(err < mpfr50(std::string("1e-45")), "SE2<mpfr50> sin(pi/6) = 1/2 to 1e-45");

  // Compiled part of the library.
  check(rollkin::io::format_double(0.1) == "0.1", "rollkin::io::format_double (compiled library)");

  if (failures != 0) std::printf("%d check(s) failed\n", failures);
  return failures == 0 ? 0 : 1;
}
