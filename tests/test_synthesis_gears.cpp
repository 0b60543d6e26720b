// Non-circular gears (include/rollkin/synthesis/gears.hpp) against closed forms and by round trip:
//  - the elliptical transmission function of eccentricity e (tan(f/2) = k tan(p/2)) gives twin ellipses back:
//    every sample of both pitch curves on the focal ellipse r = a (1 - e^2) / (1 - e cos theta), a = E/2, to
//    1e-10 relative; the smallest curvature of the fitted splines is the ellipse's b/a^2 (1e-6 relative);
//  - its f and f' against a central difference and against the closed form of the half-angle relation;
//  - the round trip of the written scene (rolling pair of the two sampled curves, 998 poses) keeps gear 2 at
//    -f(phi1) to 1e-9 of a turn, for the elliptical and the sinusoidal pair;
//  - a table whose last phi2 is not the first + 360 deg is read with its closure error (the pair does not close);
//  - one pose, one status: the round trip's statuses are `rollkin solve`'s (SweepRun) pose by pose (e = 0.999).
#define BOOST_TEST_MODULE synthesis_gears
#include <boost/test/unit_test.hpp>

#include "rollkin/output/sweep_run.hpp"
#include "rollkin/solve/continuation.hpp"
#include "rollkin/synthesis/gears.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>

using namespace rollkin;
using namespace rollkin::synthesis;

namespace {

const double kPi = M_PI;
const std::filesystem::path kDir = std::filesystem::path(ROLLKIN_BINARY_DIR) / "synthesis_gears_test";

GearSpec spec_of(const std::string& kind, double parameter, double E) {
  GearSpec s;
  s.file = "test";
  s.length_label = "mm";
  s.centre_distance = E;
  s.kind = kind;
  s.parameter = parameter;
  return s;
}

/// Writes the design's pitch curves and scene as kDir/NAME.1.txt, NAME.2.txt and NAME.json; returns the scene's path.
std::string write_design(const GearSpec& spec, const GearDesign& d, const std::string& name) {
  std::filesystem::create_directories(kDir);
  auto write = [](const std::filesystem::path& p, const std::vector<Vec2<double>>& pts) {
    std::ofstream f(p);
    f << std::setprecision(17);
    for (const auto& x : pts) f << x.x() << " " << x.y() << "\n";
  };
  write(kDir / (name + ".1.txt"), d.pair.gear1);
  write(kDir / (name + ".2.txt"), d.pair.gear2);
  std::ofstream(kDir / (name + ".json")) << gear_scene(spec, d, name + ".1.txt", name + ".2.txt").dump(2);
  return (kDir / (name + ".json")).string();
}

GearRoundTrip round_trip(const GearSpec& spec, const GearDesign& d, const std::string& name) {
  return gear_round_trip(spec, write_design(spec, d, name));
}

}  // namespace

BOOST_AUTO_TEST_CASE(elliptical_transmission_against_its_half_angle_form) {
  const double e = 0.4, k = (1 + e) / (1 - e);
  const TransmissionFunction<double> t = transmission(spec_of("elliptical", e, 10));
  for (int i = -20; i <= 20; ++i) {
    const double p = 0.37 * i;
    BOOST_TEST(std::abs(std::tan(t.f(p) / 2) - k * std::tan(p / 2)) < 1e-9 * (1 + std::abs(k * std::tan(p / 2))));
    const double h = 1e-6;
    BOOST_TEST(std::abs((t.f(p + h) - t.f(p - h)) / (2 * h) - t.df(p)) < 1e-7);
    BOOST_TEST(std::abs(t.f(p + 2 * kPi) - t.f(p) - 2 * kPi) < 1e-13);  // closes
  }
}

BOOST_AUTO_TEST_CASE(twin_elliptical_gears_come_back) {
  const double e = 0.5, E = 80, a = E / 2, b = a * std::sqrt(1 - e * e);
  const GearSpec spec = spec_of("elliptical", e, E);
  const GearDesign d = synthesise_gears(spec);
  for (const auto* curve : {&d.pair.gear1, &d.pair.gear2}) {
    double worst = 0;
    for (const auto& p : *curve) {
      const double theta = std::atan2(p.y(), p.x());
      worst = std::max(worst, std::abs(p.norm() - a * (1 - e * e) / (1 - e * std::cos(theta))));
    }
    BOOST_TEST(worst < 1e-10 * a);
  }
  BOOST_TEST(std::abs(d.min_curvature1 - b / (a * a)) < 1e-6 * b / (a * a));
  BOOST_TEST(std::abs(d.min_curvature2 - b / (a * a)) < 1e-6 * b / (a * a));
  const GearRoundTrip rt = round_trip(spec, d, "elliptical");
  BOOST_TEST(rt.solved == rt.poses);
  BOOST_TEST(rt.problems.empty());
  BOOST_TEST(rt.worst_deviation <= 2 * kPi * 1e-9);
}

BOOST_AUTO_TEST_CASE(sinusoidal_gears_by_round_trip) {
  const GearSpec spec = spec_of("sinusoidal", 0.3, 60);
  const GearDesign d = synthesise_gears(spec);
  const GearRoundTrip rt = round_trip(spec, d, "sinusoidal");
  BOOST_TEST(rt.solved == rt.poses);
  BOOST_TEST(rt.worst_deviation <= 2 * kPi * 1e-9);
}

BOOST_AUTO_TEST_CASE(a_table_that_does_not_close_is_reported) {
  std::filesystem::create_directories(kDir);
  {
    std::ofstream f(kDir / "open.txt");
    for (int deg = 0; deg <= 360; deg += 10) f << deg << " " << deg * 1.01 + 5 * std::sin(deg * kPi / 180) << "\n";
    std::ofstream s(kDir / "open.json");
    s << R"({"units": {"length": "mm", "angle": "deg"}, "centre_distance": 50, "transmission": {"file": "open.txt"}})";
  }
  const GearSpec spec = read_gear_spec((kDir / "open.json").string());
  BOOST_TEST(std::abs(spec.closure_error - 3.6 * kPi / 180) < 1e-12);  // f(360) - f(0) = 363.6 deg
}

// One pose, one status, whichever command solves it (issue 37): `synthesize gears` with eccentricity 0.999
// said 998/998 poses solved (it counted a singular pose as solved) where `rollkin solve` of the scene it wrote
// reported 118 singular poses. The round trip now sweeps by the library's path and counts what `rollkin
// solve` counts: on the scene's own sweep (the inputs `rollkin solve` takes, through output::SweepRun as the
// command line does) every pose has the same status in both, and the round trip counts as solved exactly the
// poses that are `ok`, naming the others among its problems.
BOOST_AUTO_TEST_CASE(one_pose_one_status_whichever_command_solves_it) {
  const GearSpec spec = spec_of("elliptical", 0.999, 80);
  const GearDesign d = synthesise_gears(spec);
  auto scene = std::make_shared<const io::Scene>(io::load_scene(write_design(spec, d, "eccentric")));

  output::SweepRun run(scene, {}, {}, output::SweepRequest{}, output::RequestNames{"--from/--to/--step", "--from, --to and --step", "--max-steps"});
  SolveData<double> sd(run.mechanism());
  VectorX<double> q;
  const SolveReport<double> assembly = run.assemble(sd, q);
  const SweepResult<double> solved = run.solve(sd, q, assembly);
  const SweepSummary<double> summary = summarise(solved);

  const GearRoundTrip rt = gear_round_trip(spec, *scene, run.inputs());
  BOOST_TEST_REQUIRE(rt.statuses.size() == solved.size());
  std::size_t differ = 0;
  for (std::size_t k = 0; k < solved.size(); ++k) differ += rt.statuses[k] != solved.status(k);
  BOOST_TEST(differ == 0u);
  BOOST_TEST(rt.solved == summary.solved());
  BOOST_TEST_MESSAGE("e = 0.999: " << summary.solved() << "/" << solved.size() << " ok, " << summary.singular.size() << " singular");
  const bool all_ok = summary.solved() == solved.size() && solved.limits.empty();
  BOOST_TEST(rt.problems.empty() == all_ok);
  if (!summary.singular.empty()) {
    bool named = false;
    for (const auto& p : rt.problems) named = named || p.find(std::to_string(summary.singular.size()) + " singular pose") != std::string::npos;
    BOOST_TEST(named);
  }
  // The round trip's own 998 poses: solved is the number of `ok` poses, never more.
  const GearRoundTrip own = gear_round_trip(spec, *scene);
  BOOST_TEST(own.solved == static_cast<std::size_t>(std::count(own.statuses.begin(), own.statuses.end(), SolveStatus::Converged)));
}
