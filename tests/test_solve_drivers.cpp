// Several inputs: a five-bar linkage with both cranks driven (2 DOF), against the closed-form position of
// its coupler joint (intersection of two circles), and its mobility from the Jacobian rank: with one
// driver only, the solver reports one degree of freedom too many.
#define BOOST_TEST_MODULE solve_drivers
#include <boost/test/unit_test.hpp>

#include "rollkin/samples/mechanisms.hpp"
#include "rollkin/solve/continuation.hpp"
#include "rollkin/builder.hpp"

using namespace rollkin;
using namespace rollkin::testing;

namespace {

// Ground pivots A = (0, 0), E = (d, 0); cranks a, b; couplers c (from the end of crank 1) and e (from the
// end of crank 2), joined at P.
constexpr double d = 3, a = 1, b = 1.2, c = 2.5, e = 2.2;

struct FiveBar {
  Mechanism<double> mech;
  VectorX<double> guess;
};

FiveBar five_bar(bool both_driven) {
  MechanismBuilder<double> mb;
  const int ground = mb.link("ground", true), crank1 = mb.link("crank1"), crank2 = mb.link("crank2");
  const int coupler1 = mb.link("coupler1"), coupler2 = mb.link("coupler2");
  const int in1 = mb.revolute("A", ground, crank1, SE2<double>(), SE2<double>(), "phi1");
  const int in2 = mb.revolute("E", ground, crank2, SE2<double>(0, Vec2<double>(d, 0)), SE2<double>(), "phi2");
  mb.revolute("B", crank1, coupler1, SE2<double>(0, Vec2<double>(a, 0)), SE2<double>(), "beta");
  mb.revolute("D", crank2, coupler2, SE2<double>(0, Vec2<double>(b, 0)), SE2<double>(), "delta");
  mb.revolute("P", coupler1, coupler2, SE2<double>(0, Vec2<double>(c, 0)), SE2<double>(0, Vec2<double>(e, 0)), "pin");
  mb.driver(in1);
  if (both_driven) mb.driver(in2);
  FiveBar f{mb.build(), VectorX<double>(5)};
  // Rough guess for the "elbow up" mode at phi1 = 90 deg, phi2 = 60 deg.
  f.guess << pi<double>() / 2, pi<double>() / 3, -1.2, 1.4, 2.0;
  return f;
}

/// Closed form: P is the upper intersection of the circles |P - B| = c and |P - D| = e.
Vec2<double> coupler_point(double phi1, double phi2) {
  const Vec2<double> B(a * std::cos(phi1), a * std::sin(phi1)), D(d + b * std::cos(phi2), b * std::sin(phi2));
  const double dist = (D - B).norm(), along = (c * c - e * e + dist * dist) / (2 * dist);
  const double h = std::sqrt(c * c - along * along);
  const Vec2<double> u = (D - B) / dist;
  return B + along * u + h * perp(u);
}

}  // namespace

BOOST_AUTO_TEST_CASE(two_drivers_fix_the_five_bar) {
  FiveBar f = five_bar(true);
  SolveData<double> sd(f.mech);
  VectorX<double> q = f.guess;
  const auto rep = assemble(f.mech, q, sd);
  BOOST_TEST_REQUIRE(rep.ok());
  BOOST_TEST(rep.rank == 3);
  // Sweep crank 1 with crank 2 held at its assembly value; then check the joint P against the closed form.
  const auto res = sweep(f.mech, sd, q, rep, 0, degrees<double>(60, 120, 5));
  BOOST_TEST_REQUIRE(res.all_solved());
  for (const auto& p : res.poses) {
    const double phi1 = p.q(0), phi2 = p.q(1), beta = p.q(2);
    BOOST_TEST(phi2 == q(1));  // the second driver stays where it was put
    const Vec2<double> B(a * std::cos(phi1), a * std::sin(phi1));
    const Vec2<double> P = B + c * Vec2<double>(std::cos(phi1 + beta), std::sin(phi1 + beta));
    BOOST_TEST((P - coupler_point(phi1, phi2)).norm() < 1e-12);
  }
  // Sweeping the second driver works the same way.
  const auto res2 = sweep(f.mech, sd, q, rep, 1, degrees<double>(40, 80, 10));
  BOOST_TEST_REQUIRE(res2.all_solved());
  for (const auto& p : res2.poses) BOOST_TEST(p.q(0) == q(0));
}

BOOST_AUTO_TEST_CASE(one_driver_leaves_one_degree_of_freedom) {
  FiveBar f = five_bar(false);
  SolveData<double> sd(f.mech);
  VectorX<double> q = f.guess;
  const auto rep = assemble(f.mech, q, sd);
  BOOST_TEST(rep.status == SolveStatus::Underdetermined);
  BOOST_TEST(rep.unknowns - rep.rank == 1);  // mobility 2 (five-bar) minus 1 driver
  BOOST_TEST(rep.detail.find("1 more degree(s) of freedom") != std::string::npos);
}
