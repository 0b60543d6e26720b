// The undercut and conformity check (analysis/design_check.hpp, geometry/curvature_sign.hpp) against closed forms:
//  - an eccentric circular cam (radius R) with a roller r: the cam's radius of curvature is R everywhere, the
//    relative curvature 1/R + 1/r, no undercut;
//  - a roller of radius r inside an elliptical groove (semi-axes a > b, tests/data/undercut_ellipse.json): the
//    wall's smallest concave radius is b^2/a at the ends of the major axis (x = +-a), touched between two
//    solved poses; with r > b^2/a the pair interpenetrates there (undercut), and the undercut region ends
//    where the ellipse's radius of curvature (a^2 sin^2 t + b^2 cos^2 t)^(3/2) / (ab) equals r; with
//    r < b^2/a the design is possible;
//  - the paper's example: the parabola's smallest radius of curvature where touched is
//    (1 + 4 a^2 x^2)^(3/2) / (2a) at the touched x nearest the vertex, the disks' radii 1 and 4, no finding;
//  - the exact sign test on cases whose sign is known exactly.
#define BOOST_TEST_MODULE design_check
#include <boost/test/unit_test.hpp>

#include "rollkin/samples/mechanisms.hpp"
#include "rollkin/analysis/design_check.hpp"
#include "rollkin/io/scene/reader.hpp"
#include "rollkin/scalar_mpfr.hpp"
#include "rollkin/solve/mpfr50_instances.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

using namespace rollkin;
using namespace rollkin::testing;

namespace {

const double kDeg = M_PI / 180;
const std::string kSource = ROLLKIN_SOURCE_DIR;

/// The scene's sweep (or --from/--to/--step as given) from its assembly.
SweepResult<double> swept(const io::Scene& s, const std::vector<double>& inputs) {
  const Mechanism<double>& m = s.mechanism;
  SolveData<double> sd(m);
  VectorX<double> q = s.guess;
  const SolveReport<double> rep = assemble(m, q, sd, s.held);
  BOOST_REQUIRE_MESSAGE(rep.ok(), "assembly: " << to_string(rep.status));
  return sweep(m, sd, q, rep, s.sweep->driver, inputs);
}

std::string file_text(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// tests/data/undercut_ellipse.json with another roller radius (the follower assembled at a - r).
io::Scene groove_with_roller(double r) {
  const std::string file = kSource + "/tests/data/undercut_ellipse.json";
  nlohmann::json j = nlohmann::json::parse(file_text(file));
  j["links"][2]["contours"][0]["radius"] = r;
  j["pairs"][1]["value"] = 3 - r;
  return io::parse_scene(j.dump(), file);
}

/// tests/data/undercut_ellipse.json with the roller given as an ellipse of equal semi-axes r: the same disk,
/// but not a circle to the check, so its generic (two-contour) conformity test decides.
io::Scene groove_with_round_ellipse(double r) {
  const std::string file = kSource + "/tests/data/undercut_ellipse.json";
  nlohmann::json j = nlohmann::json::parse(file_text(file));
  j["links"][2]["contours"][0] = {{"name", "roller"}, {"type", "ellipse"}, {"semi_axes", {r, r}}};
  j["pairs"][1]["value"] = 3 - r;
  return io::parse_scene(j.dump(), file);
}

/// Radius of curvature of the ellipse (a cos t, b sin t).
double ellipse_radius(double a, double b, double t) {
  const double s = std::sin(t), c = std::cos(t);
  return std::pow(a * a * s * s + b * b * c * c, 1.5) / (a * b);
}

}  // namespace

BOOST_AUTO_TEST_CASE(eccentric_circular_cam_has_its_radius_everywhere_and_no_undercut) {
  const double R = 3, e = 1, r = 1;
  const auto f = eccentric_cam<double>(R, e, true, r);
  VectorX<double> q;
  SolveData<double> sd(f.mech);
  const auto assembly = assemble_fixture(f, q, sd);
  BOOST_REQUIRE(assembly.ok());
  std::vector<double> inputs;
  for (int d = 0; d <= 360; d += 5) inputs.push_back(d * kDeg);
  const SweepResult<double> res = sweep(f.mech, sd, q, assembly, 0, inputs);
  BOOST_REQUIRE(res.all_solved());
  const DesignCheck<double> check = check_design(f.mech, res);
  BOOST_REQUIRE_EQUAL(check.pairs.size(), 1u);
  const PairDesignCheck<double>& p = check.pairs[0];
  BOOST_TEST(p.touched);
  BOOST_TEST(p.contours[0].circle);
  BOOST_TEST(p.contours[0].radius == R);
  BOOST_TEST(std::abs(p.contours[0].min_radius() - R) <= 1e-14 * R);
  BOOST_TEST(!p.contours[0].sharpest_concave.found);
  BOOST_TEST(std::abs(p.contours[1].min_radius() - r) <= 1e-14 * r);
  BOOST_TEST(p.roller == 1);  // the smaller convex circle
  BOOST_TEST(std::abs(p.worst_relative - (1 / R + 1 / r)) <= 1e-14);
  BOOST_TEST(to_string(p.conformity) == to_string(Conformity::Conforming));
  BOOST_TEST(!p.cusps[0].found);
  BOOST_TEST(!check.impossible());
  BOOST_TEST_MESSAGE("eccentric cam: min radius - R = " << p.contours[0].min_radius() - R
                                                      << ", relative curvature - (1/R + 1/r) = " << p.worst_relative - (1 / R + 1 / r));
}

BOOST_AUTO_TEST_CASE(roller_larger_than_the_groove_vertex_radius_is_an_undercut_at_the_vertex) {
  const double a = 3, b = 2, r = 1.5;  // b^2 / a = 4/3 < r
  const io::Scene scene = io::load_scene(kSource + "/tests/data/undercut_ellipse.json");
  const Mechanism<double>& m = scene.mechanism;
  const SweepResult<double> res = swept(scene, sweep_inputs(*scene.sweep));
  BOOST_REQUIRE(res.all_solved());
  // The vertex (u = 0) is touched between two solved poses, at none of them.
  const int u_var = m.pairs[2].first_variable;
  for (const auto& pose : res.poses) BOOST_TEST(std::abs(pose.q(u_var)) > 1 * kDeg);

  const DesignCheck<double> check = check_design(m, res);
  BOOST_REQUIRE_EQUAL(check.pairs.size(), 1u);
  const PairDesignCheck<double>& p = check.pairs[0];
  BOOST_TEST(check.impossible());
  BOOST_TEST(to_string(p.conformity) == to_string(Conformity::Interpenetrating));
  BOOST_TEST(p.roller == 1);
  const TouchedPoint<double>& vertex = p.contours[0].sharpest_concave;
  BOOST_REQUIRE(vertex.found);
  BOOST_TEST(!p.contours[0].sharpest_convex.found);
  const double rho = b * b / a;
  BOOST_TEST(std::abs(std::abs(vertex.point.x()) - a) <= 1e-9 * a);
  BOOST_TEST(std::abs(vertex.point.y()) <= 1e-9 * a);
  BOOST_TEST(std::abs(-1 / vertex.kappa - rho) <= 1e-9 * rho);
  BOOST_TEST(std::abs(p.contours[0].min_radius() - rho) <= 1e-9 * rho);
  // The worst contact is the same point; by symmetry it is touched at phi = 90 deg (Hermite interpolation
  // between the poses at 89.7 and 90.4 deg).
  BOOST_TEST(std::abs(std::abs(p.worst[0].point.x()) - a) <= 1e-9 * a);
  BOOST_TEST(std::abs(p.worst_relative - (1 / r - a / (b * b))) <= 1e-12);
  BOOST_TEST(std::abs(p.worst[0].input - 90 * kDeg) <= 1e-4 * kDeg);
  // The undercut region's ends: the ellipse's radius of curvature equals r at eccentric anomaly +-t_c.
  const double t_c = std::asin(std::sqrt((std::cbrt(r * a * b * r * a * b) - b * b) / (a * a - b * b)));
  BOOST_TEST(std::abs(ellipse_radius(a, b, t_c) - r) <= 1e-14);
  for (int side = 0; side < 2; ++side) {
    const TouchedPoint<double>& cusp = p.cusps[static_cast<std::size_t>(side)];
    BOOST_REQUIRE(cusp.found);
    BOOST_TEST(std::abs(std::abs(cusp.u) - t_c) <= 1e-9 * t_c);
    BOOST_TEST(std::abs(cusp.point.x() - a * std::cos(t_c)) <= 1e-9 * a);
    BOOST_TEST(std::abs(std::abs(cusp.point.y()) - b * std::sin(t_c)) <= 1e-9 * a);
    BOOST_TEST(std::abs(1 + r * cusp.kappa) <= 1e-12);
  }
  BOOST_TEST(p.cusps[0].u < 0);
  BOOST_TEST(p.cusps[1].u > 0);
  BOOST_TEST_MESSAGE("undercut: vertex |x| - a = " << std::abs(vertex.point.x()) - a << ", y = " << vertex.point.y()
                                                << ", radius - b^2/a = " << -1 / vertex.kappa - rho << ", touched at phi - 90 deg = "
                                                << vertex.input / kDeg - 90 << " deg; cusp |u| - t_c = "
                                                << std::abs(p.cusps[1].u) - t_c << ", " << std::abs(p.cusps[0].u) - t_c);
}

BOOST_AUTO_TEST_CASE(roller_smaller_than_the_groove_vertex_radius_fits) {
  const double a = 3, b = 2, r = 1.2;  // b^2 / a = 4/3 > r
  const io::Scene scene = groove_with_roller(r);
  std::vector<double> inputs;
  for (double d = 60; d <= 120; d += 2.5) inputs.push_back(d * kDeg);
  const SweepResult<double> res = swept(scene, inputs);
  BOOST_REQUIRE(res.all_solved());
  const DesignCheck<double> check = check_design(scene.mechanism, res);
  const PairDesignCheck<double>& p = check.pairs.at(0);
  BOOST_TEST(!check.impossible());
  BOOST_TEST(to_string(p.conformity) == to_string(Conformity::Conforming));
  const double rho = b * b / a;
  BOOST_TEST(std::abs(-1 / p.contours[0].sharpest_concave.kappa - rho) <= 1e-9 * rho);
  BOOST_TEST(std::abs(p.worst_relative - (1 / r - 1 / rho)) <= 1e-12);
  BOOST_TEST(!p.cusps[0].found);
  BOOST_TEST(!p.cusps[1].found);
}

BOOST_AUTO_TEST_CASE(two_non_circular_contours_interpenetrating_are_found_by_the_generic_test) {
  const double a = 3, b = 2, r = 1.5;
  const io::Scene scene = groove_with_round_ellipse(r);
  const SweepResult<double> res = swept(scene, sweep_inputs(*scene.sweep));
  BOOST_REQUIRE(res.all_solved());
  const DesignCheck<double> check = check_design(scene.mechanism, res);
  const PairDesignCheck<double>& p = check.pairs.at(0);
  BOOST_TEST(p.roller == -1);
  BOOST_TEST(!p.contours[1].circle);
  BOOST_TEST(check.impossible());
  BOOST_TEST(to_string(p.conformity) == to_string(Conformity::Interpenetrating));
  BOOST_TEST(std::abs(std::abs(p.worst[0].point.x()) - a) <= 1e-9 * a);
  BOOST_TEST(std::abs(p.worst_relative - (1 / r - a / (b * b))) <= 1e-12);
  BOOST_TEST(std::abs(p.contours[1].min_radius() - r) <= 1e-12 * r);
  BOOST_TEST(!p.cusps[0].found);
}

BOOST_AUTO_TEST_CASE(paper_example_radii_are_the_parabola_closed_form_and_the_disk_radii) {
  const io::Scene scene = io::load_scene(kSource + "/examples/paper_fourbar.json");
  const Mechanism<double>& m = scene.mechanism;
  // From 20 to 100 deg: the vertex is not touched, the parabola's sharpest touched point is the contact at
  // one end of the range.
  std::vector<double> inputs;
  for (int d = 20; d <= 100; ++d) inputs.push_back(d * kDeg);
  const SweepResult<double> res = swept(scene, inputs);
  BOOST_REQUIRE(res.all_solved());
  const DesignCheck<double> check = check_design(m, res);
  BOOST_REQUIRE_EQUAL(check.pairs.size(), 2u);
  BOOST_TEST(!check.impossible());
  const double a = 0.5;
  const int x_var = m.pairs[static_cast<std::size_t>(check.pairs[0].pair)].first_variable;
  double x_near = res.poses.front().q(x_var);
  for (const auto& pose : res.poses)
    if (std::abs(pose.q(x_var)) < std::abs(x_near)) x_near = pose.q(x_var);
  const double rho_closed = std::pow(1 + 4 * a * a * x_near * x_near, 1.5) / (2 * a);
  const PairDesignCheck<double>& A = check.pairs[0];
  BOOST_TEST(std::abs(A.contours[0].min_radius() - rho_closed) <= 1e-12 * rho_closed);
  BOOST_TEST(std::abs(A.contours[0].sharpest_convex.u - x_near) <= 1e-12);
  BOOST_TEST(!A.contours[0].sharpest_concave.found);
  BOOST_TEST(A.contours[1].radius == 1.0);
  BOOST_TEST(to_string(A.conformity) == to_string(Conformity::Conforming));
  const PairDesignCheck<double>& B = check.pairs[1];
  BOOST_TEST(std::abs(B.contours[0].min_radius() - 1) <= 1e-14);
  BOOST_TEST(std::abs(B.contours[1].min_radius() - 4) <= 1e-14);
  BOOST_TEST(std::abs(B.worst_relative - 1.25) <= 1e-14);
  BOOST_TEST(to_string(B.conformity) == to_string(Conformity::Conforming));

  // Over the scene's own sweep (-50 to 100 deg) the vertex is touched: radius 1/(2a) at x = 0.
  const SweepResult<double> full = swept(scene, sweep_inputs(*scene.sweep));
  const DesignCheck<double> whole = check_design(m, full);
  BOOST_TEST(std::abs(whole.pairs[0].contours[0].min_radius() - 1 / (2 * a)) <= 1e-14);
  BOOST_TEST(std::abs(whole.pairs[0].contours[0].sharpest_convex.u) <= 1e-12);
  BOOST_TEST(!whole.impossible());
  BOOST_TEST_MESSAGE("paper: parabola's smallest radius from 20 to 100 deg " << A.contours[0].min_radius() << " at x = "
                     << x_near << ", minus the closed form " << A.contours[0].min_radius() - rho_closed
                     << "; over -50..100 deg minus 1/(2a): " << whole.pairs[0].contours[0].min_radius() - 1 / (2 * a));
}

BOOST_AUTO_TEST_CASE(exact_relative_curvature_sign) {
  using geometry::circle_derivatives;
  using geometry::relative_curvature_sign;
  // Ellipse (4 cos t, 2 sin t) at its vertex t = 0: p' = (0, 2), p'' = (-4, 0), curvature 4*2/2^3 = 1.
  const Vec2<double> d1(0, 2), d2(-4, 0);
  const auto ring = [](double radius) { return circle_derivatives(radius, false); };
  BOOST_TEST(relative_curvature_sign(d1, d2, ring(1)[0], ring(1)[1], 0) == 0);     // exactly osculating
  const double above = std::nextafter(1.0, 2.0), below = std::nextafter(1.0, 0.0);
  BOOST_TEST(relative_curvature_sign(d1, d2, ring(above)[0], ring(above)[1], 0) == 1);   // ring flatter: apart
  BOOST_TEST(relative_curvature_sign(d1, d2, ring(below)[0], ring(below)[1], 0) == -1);  // ring sharper: overlap
  BOOST_TEST(relative_curvature_sign(d1, d2, ring(above)[0], ring(above)[1], 1e-9) == 0);  // within the band
  BOOST_TEST(relative_curvature_sign(d1, d2, ring(1.5)[0], ring(1.5)[1], 1e-9) == 1);
  BOOST_TEST(relative_curvature_sign(d1, d2, ring(0.75)[0], ring(0.75)[1], 1e-9) == -1);
  // The same sum with the ellipse second: the sign is symmetric; a convex circle always conforms.
  BOOST_TEST(relative_curvature_sign(ring(below)[0], ring(below)[1], d1, d2, 0) == -1);
  const auto disk = circle_derivatives(1e-3, true);
  BOOST_TEST(relative_curvature_sign(d1, d2, disk[0], disk[1], 1e-9) == 1);
  // Two straight lines osculate; a line against a ring interpenetrates.
  const Vec2<double> straight1(1, 0), straight2(0, 0);
  BOOST_TEST(relative_curvature_sign(straight1, straight2, straight1, straight2, 1e-9) == 0);
  BOOST_TEST(relative_curvature_sign(straight1, straight2, ring(1e6)[0], ring(1e6)[1], 1e-9) == -1);
}

BOOST_AUTO_TEST_CASE(mpfr_finds_the_parabola_vertex_between_poses_to_full_precision) {
  // The paper's crank at -7, 3 and 13 deg: the vertex (x = 0, radius 1/(2a) = 1) is passed between the first
  // two poses; the refinement (zero of the curvature's slope) finds it to the precision of the scalar.
  using M = mpfr50;
  const auto f = paper_fourbar<M>();
  SolveData<M> sd(f.mech);
  VectorX<M> q;
  const auto assembly = assemble_fixture(f, q, sd);
  BOOST_TEST_REQUIRE(assembly.ok());
  const M deg = pi<M>() / M(180);
  const auto res = sweep(f.mech, sd, q, assembly, 0, std::vector<M>{M(-7) * deg, M(3) * deg, M(13) * deg});
  BOOST_TEST_REQUIRE(res.all_solved());
  const DesignCheck<M> check = check_design(f.mech, res);
  const TouchedPoint<M>& vertex = check.pairs.at(0).contours[0].sharpest_convex;
  BOOST_TEST_REQUIRE(vertex.found);
  const double x_error = to_double(M(abs(vertex.u))), rho_error = to_double(M(abs(M(1) / vertex.kappa - M(1))));
  BOOST_TEST(x_error <= 1e-40);
  BOOST_TEST(rho_error <= 1e-40);
  BOOST_TEST(!check.impossible());
  BOOST_TEST_MESSAGE("MPFR50: vertex found at input " << to_double(M(vertex.input / deg)) << " deg, |x| = " << x_error << ", radius - 1/(2a) = " << rho_error);
}
