// The forces of a solved pose (analysis/forces.hpp, docs/forces.md) against independent truth:
//  - closed forms: an eccentric circular cam under a flat-faced follower with a spring, N = P + k e (1 - cos th)
//    + m e w^2 cos th, torque N e sin th, separation speed w^2 = (P + 2 k e) / (m e); a slider-crank whose rod is
//    dynamically two point masses, crank torque (m4 + m3 a / l) w^2 x' x''; a disk rolling under a brake torque T,
//    friction needed T / (r N);
//  - energy: on every example scene with masses, gravity, a spring, loads and cam friction added, the drive power
//    equals dKE/dt - the power of gravity, springs and loads + the friction loss, at every pose;
//  - the links' accelerations against central differences of their velocities;
//  - each link's Newton-Euler residual at round-off; MPFR (50 digits) against double; mm against m;
//  - redundant constraints: the effort unique, the redundant reactions reported as not unique.
#define BOOST_TEST_MODULE analysis_forces
#include <boost/test/unit_test.hpp>

#include "test_support.hpp"

#include "rollkin/analysis/forces.hpp"
#include "rollkin/io/scene/reader.hpp"
#include "rollkin/scalar_mpfr.hpp"
#include "rollkin/solve/continuation.hpp"
#include "rollkin/solve/mpfr50_instances.hpp"

#include <cmath>
#include <filesystem>

using namespace rollkin;
using namespace rollkin::testing;

namespace {

const std::string kData = std::string(ROLLKIN_SOURCE_DIR) + "/tests/data/forces/";
const std::string kExamples = std::string(ROLLKIN_SOURCE_DIR) + "/examples/";
const double kDeg = rollkin::deg_to_rad(1.0);

/// A scene assembled and swept over `inputs` (internal units; default: the scene's sweep).
struct Solved {
  io::Scene scene;
  SweepResult<double> result;
};

Solved solve(io::Scene scene, std::vector<double> inputs = {}) {
  if (inputs.empty()) inputs = sweep_inputs(*scene.sweep);
  SolveData<double> sd(scene.mechanism);
  VectorX<double> q = scene.guess;
  const SolveReport<double> rep = assemble(scene.mechanism, q, sd, scene.held);
  BOOST_REQUIRE_MESSAGE(rep.ok(), scene.file << ": assembly " << to_string(rep.status));
  const int driver = scene.sweep ? scene.sweep->driver : 0;
  SweepResult<double> res = sweep(scene.mechanism, sd, q, rep, driver, inputs);
  return {std::move(scene), std::move(res)};
}

/// The value at speed w of the unknown of `kind` at pair `pair` (driver effort: pair of the driver).
double unknown(const ForceLayout& l, const PoseForces<double>& f, int pair, ReactionKind kind, double w) {
  for (int k = 0; k < l.size(); ++k)
    if (l.unknowns[static_cast<std::size_t>(k)].pair == pair && l.unknowns[static_cast<std::size_t>(k)].kind == kind) {
      BOOST_TEST(f.unique[static_cast<std::size_t>(k)]);
      return f.value(k, w);
    }
  BOOST_FAIL("no such unknown");
  return 0;
}

}  // namespace

BOOST_AUTO_TEST_CASE(eccentric_cam_normal_force_torque_and_separation_speed_closed_forms) {
  // SI: R = 0.04 m, e = 0.01 m, k = 2000 N/m, P = 30 N, m = 0.5 kg (the scene is in mm).
  const double e = 0.01, k = 2000, P = 30, mass = 0.5;
  const Solved s = solve(io::load_scene(kData + "eccentric_cam.json"));
  const Mechanism<double>& m = s.scene.mechanism;
  const Dynamics<double>& dyn = *s.scene.dynamics;
  const double w = dyn.speed;
  BOOST_TEST(std::abs(w - 500 * 2 * M_PI / 60) < 1e-12);
  ForceData<double> data(m);
  const int C = m.find_pair("C"), O = m.find_pair("O");
  double worst_n = 0, worst_t = 0, worst_sep = 0;
  for (const auto& pose : s.result.poses) {
    BOOST_REQUIRE(pose.report.ok());
    const PoseForces<double> f = pose_forces(m, dyn, pose.q, pose.qdot, data);
    BOOST_REQUIRE(f.determined);
    const double th = pose.input + M_PI / 2;
    const double n = P + k * e * (1 - std::cos(th)) + mass * e * w * w * std::cos(th);
    const double torque = n * (e * 1000) * std::sin(th);  // N * mm
    worst_n = std::max(worst_n, std::abs(unknown(data.layout, f, C, ReactionKind::Normal, w) - n) / n);
    worst_t = std::max(worst_t, std::abs(unknown(data.layout, f, O, ReactionKind::Effort, w) - torque) / (n * e * 1000));
    // The normal force as a + w^2 b: where b < 0, it reaches zero at w^2 = -a / b, (P + k e (1 - cos)) / (-m e cos).
    const int nk = data.layout.first[static_cast<std::size_t>(C)];
    if (std::cos(th) < -1e-3) {
      const double w2 = -f.a(nk) / f.b(nk), expected = (P + k * e * (1 - std::cos(th))) / (-mass * e * std::cos(th));
      worst_sep = std::max(worst_sep, std::abs(w2 - expected) / expected);
    }
  }
  BOOST_TEST_MESSAGE("eccentric cam over " << s.result.poses.size() << " poses: normal force " << worst_n
                                           << ", torque " << worst_t << ", separation speed^2 " << worst_sep << " relative");
  BOOST_TEST(worst_n < 1e-12);
  BOOST_TEST(worst_t < 1e-12);
  BOOST_TEST(worst_sep < 1e-12);
}

BOOST_AUTO_TEST_CASE(slider_crank_crank_torque_against_the_two_mass_formula) {
  const double r = 0.05, l = 0.2, a = 0.08, m3 = 1.2, m4 = 0.8;
  const Solved s = solve(io::load_scene(kData + "slider_crank.json"));
  const Mechanism<double>& m = s.scene.mechanism;
  const Dynamics<double>& dyn = *s.scene.dynamics;
  const double w = dyn.speed;
  ForceData<double> data(m);
  double worst = 0, largest = 0;
  for (const auto& pose : s.result.poses) {
    const double th = pose.input, sn = std::sin(th), cs = std::cos(th);
    const double d = std::sqrt(l * l - r * r * sn * sn);
    const double x1 = -r * sn - r * r * sn * cs / d;
    const double x2 = -r * cs - r * r * (cs * cs - sn * sn) / d - std::pow(r, 4) * sn * sn * cs * cs / (d * d * d);
    const double torque = (m4 + m3 * a / l) * w * w * x1 * x2;
    const PoseForces<double> f = pose_forces(m, dyn, pose.q, pose.qdot, data);
    const double got = unknown(data.layout, f, m.find_pair("O"), ReactionKind::Effort, w);
    worst = std::max(worst, std::abs(got - torque));
    largest = std::max(largest, std::abs(torque));
  }
  BOOST_TEST_MESSAGE("slider-crank: crank torque error " << worst / largest << " of its peak " << largest << " N m");
  BOOST_TEST(worst < 1e-12 * largest);
}

BOOST_AUTO_TEST_CASE(disk_rolling_under_a_brake_torque_needs_friction_t_over_r_n) {
  const double r = 0.3, T = 12, N = 200;
  const Solved s = solve(io::load_scene(kData + "disk_brake.json"));
  const Mechanism<double>& m = s.scene.mechanism;
  const Dynamics<double>& dyn = *s.scene.dynamics;
  ForceData<double> data(m);
  const int C = m.find_pair("C");
  for (const auto& pose : s.result.poses) {
    const PoseForces<double> f = pose_forces(m, dyn, pose.q, pose.qdot, data);
    const double normal = unknown(data.layout, f, C, ReactionKind::Normal, dyn.speed);
    const double tangential = unknown(data.layout, f, C, ReactionKind::Tangential, dyn.speed);
    BOOST_TEST(std::abs(normal - N) < 1e-12 * N);
    BOOST_TEST(std::abs(std::abs(tangential) / normal - T / (r * N)) < 1e-13);
    BOOST_TEST(std::abs(unknown(data.layout, f, m.find_pair("X"), ReactionKind::Effort, dyn.speed) - T / r) < 1e-12 * T / r);
  }
}

// ---- energy --------------------------------------------------------------------------------------------------

namespace {

/// Dynamics for any scene: every moving link a mass with its centre off its origin, gravity, a spring from the
/// ground to the last link, a force and a torque on the first moving link, friction 0.2 on every cam pair.
Dynamics<double> test_dynamics(const Mechanism<double>& m, double w) {
  Dynamics<double> d(m.links.size(), m.pairs.size());
  const double L = m.length_scale;
  for (std::size_t i = 0; i < m.links.size(); ++i) {
    if (static_cast<int>(i) == m.ground) continue;
    const double t = static_cast<double>(i);
    d.links[i] = {1.0 + 0.3 * t, Vec2<double>(0.11 * L * t, -0.07 * L), 0.05 * L * L * (1 + t)};
  }
  d.gravity = Vec2<double>(0.3, -9.81);
  d.metres_per_length = 0.001;
  const int last = static_cast<int>(m.links.size()) - 1 == m.ground ? 1 : static_cast<int>(m.links.size()) - 1;
  d.springs.push_back({"s", m.ground, last, Vec2<double>(0.3 * L, 1.7 * L), Vec2<double>(0.05 * L, 0.02 * L), 3.0, 0.5 * L});
  const int first = m.ground == 0 ? 1 : 0;
  d.loads.push_back({first, Vec2<double>(0.2 * L, 0.1 * L), Vec2<double>(-4, 2.5), 0.7 * L});
  for (std::size_t k = 0; k < m.pairs.size(); ++k)
    if (m.pairs[k].kind == PairKind::Cam) d.friction[k] = 0.2;
  d.speed = w;
  return d;
}

/// Drive power - (dKE/dt - power of gravity, springs, loads + friction loss), and the largest term, at speed
/// w (every term in N * length / s). Velocities from the link twists, the point accelerations from the links'
/// spatial accelerations.
std::pair<double, double> energy_balance(const Mechanism<double>& m, const Dynamics<double>& d, const PoseForces<double>& f,
                                         const ForceLayout& layout, int driver, double w) {
  const double l = d.metres_per_length;
  const auto& pose = f.motion.link_pose;
  const auto& twist = f.motion.link_velocity;
  std::vector<double> terms;
  double kinetic = 0;
  for (std::size_t i = 0; i < m.links.size(); ++i) {
    const LinkMass<double>& b = d.links[i];
    if (static_cast<int>(i) == m.ground || b.mass == 0) continue;
    const Vec2<double> g = pose[i].act(b.centre);
    const Vec2<double> v = detail::point_velocity(twist[i], g) * w;
    const Vec2<double> a = point_acceleration(twist[i], f.link_acceleration[i], g) * (w * w);
    kinetic += l * (b.mass * v.dot(a) + b.inertia * twist[i].z() * w * f.link_acceleration[i].z() * w * w);
    terms.push_back(l * b.mass * d.gravity.dot(v));
  }
  for (const Spring<double>& s : d.springs) {
    const Vec2<double> pa = pose[static_cast<std::size_t>(s.link_a)].act(s.at_a), pb = pose[static_cast<std::size_t>(s.link_b)].act(s.at_b);
    const Vec2<double> va = detail::point_velocity(twist[static_cast<std::size_t>(s.link_a)], pa) * w;
    const Vec2<double> vb = detail::point_velocity(twist[static_cast<std::size_t>(s.link_b)], pb) * w;
    const double length = (pb - pa).norm();
    terms.push_back(-s.rate * (length - s.free_length) * (pb - pa).dot(vb - va) / length);
  }
  for (const Load<double>& ld : d.loads) {
    const Vec2<double> p = pose[static_cast<std::size_t>(ld.link)].act(ld.at);
    terms.push_back(ld.force.dot(detail::point_velocity(twist[static_cast<std::size_t>(ld.link)], p) * w) +
                    ld.torque * twist[static_cast<std::size_t>(ld.link)].z() * w);
  }
  for (const ContactAnalysis<double>& c : f.contacts) {
    const double mu = d.friction[static_cast<std::size_t>(c.pair)];
    if (!(mu > 0)) continue;
    const double normal = f.value(layout.first[static_cast<std::size_t>(c.pair)], w);
    terms.push_back(-mu * normal * std::abs(c.sliding * w));
  }
  const double drive = f.value(layout.effort[static_cast<std::size_t>(driver)], w) * w;
  double sum = drive - kinetic, size = std::max(std::abs(drive), std::abs(kinetic));
  for (double t : terms) {
    sum += t;
    size = std::max(size, std::abs(t));
  }
  return {sum, size};
}

}  // namespace

BOOST_AUTO_TEST_CASE(energy_balance_on_every_example_scene) {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(kExamples))
    if (e.path().extension() == ".json") files.push_back(e.path().string());
  for (const auto& e : std::filesystem::directory_iterator(kData)) files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  for (const std::string& file : files) {
    io::Scene scene = io::load_scene(file);
    if (!scene.sweep) continue;
    {  // the osculating variant of the paper example cannot be assembled (its stress case): nothing to balance
      SolveData<double> sd(scene.mechanism);
      VectorX<double> q = scene.guess;
      if (!assemble(scene.mechanism, q, sd, scene.held).ok()) continue;
    }
    const Solved s = solve(std::move(scene));
    const Mechanism<double>& m = s.scene.mechanism;
    for (double w : {7.0, -3.0}) {
      const Dynamics<double> d = test_dynamics(m, w);
      ForceData<double> data(m);
      double worst = 0;
      int poses = 0;
      for (const auto& pose : s.result.poses) {
        if (!pose.report.ok()) continue;
        const PoseForces<double> f = pose_forces(m, d, pose.q, pose.qdot, data);
        if (!f.determined) continue;
        const auto [sum, size] = energy_balance(m, d, f, data.layout, s.scene.sweep->driver, w);
        worst = std::max(worst, std::abs(sum) / size);
        ++poses;
      }
      BOOST_TEST_MESSAGE(std::filesystem::path(file).filename().string() << " at w = " << w << ": energy balance " << worst
                                                                           << " relative over " << poses << " poses");
      BOOST_TEST(poses > 0, file);
      BOOST_TEST(worst < 1e-10, file << " w = " << w);
    }
  }
}

BOOST_AUTO_TEST_CASE(link_accelerations_match_differences_of_velocities) {
  // Paper example: each moving link's point (1, 0.5) (its frame), velocity v(x) from the link twists at the
  // neighbours x +- h, against the point acceleration from the links' spatial accelerations.
  io::Scene scene = io::load_scene(kExamples + "paper_fourbar.json");
  const double h = 1e-4;
  std::vector<double> inputs;
  for (int deg = -40; deg <= 90; deg += 10)
    for (int j = -1; j <= 1; ++j) inputs.push_back(deg * kDeg + j * h);
  const Solved s = solve(std::move(scene), inputs);
  const Mechanism<double>& m = s.scene.mechanism;
  const Dynamics<double> d = test_dynamics(m, 1.0);
  ForceData<double> data(m);
  double worst = 0;
  for (std::size_t k = 0; k + 2 < inputs.size(); k += 3) {
    std::array<PoseForces<double>, 3> f;
    for (int j = 0; j < 3; ++j) f[j] = pose_forces(m, d, s.result.poses[k + j].q, s.result.poses[k + j].qdot, data);
    for (std::size_t i = 0; i < m.links.size(); ++i) {
      if (static_cast<int>(i) == m.ground) continue;
      const Vec2<double> x(1, 0.5);
      const auto velocity = [&](int j) {
        return detail::point_velocity(f[j].motion.link_velocity[i], f[j].motion.link_pose[i].act(x));
      };
      const Vec2<double> diff = (velocity(2) - velocity(0)) / (2 * h);
      const Vec2<double> acc = point_acceleration(f[1].motion.link_velocity[i], f[1].link_acceleration[i], f[1].motion.link_pose[i].act(x));
      worst = std::max(worst, (diff - acc).norm() / std::max(1.0, acc.norm()));
      // The angular part against the analysis' own sum along the tree (analysis.hpp, link_motion).
      BOOST_TEST(std::abs(f[1].link_acceleration[i].z() - f[1].motion.angular_acceleration[i]) < 1e-13 * std::max(1.0, acc.norm()));
    }
  }
  BOOST_TEST_MESSAGE("paper example: point accelerations against differences of velocities " << worst);
  BOOST_TEST(worst < 1e-6);
}

BOOST_AUTO_TEST_CASE(newton_euler_residual_of_every_link_at_round_off) {
  const Solved s = solve(io::load_scene(kExamples + "paper_fourbar.json"));
  const Mechanism<double>& m = s.scene.mechanism;
  const Dynamics<double> d = test_dynamics(m, 5.0);
  ForceData<double> data(m);
  double worst = 0;
  for (const auto& pose : s.result.poses) {
    const PoseForces<double> f = pose_forces(m, d, pose.q, pose.qdot, data);
    BOOST_REQUIRE(f.determined);
    BOOST_TEST(f.rank == data.layout.size());
    for (int c = 0; c < 2; ++c) {
      const VectorX<double> x = c == 0 ? f.a : f.b;
      const VectorX<double> residual = data.matrix * x - data.rhs.col(c);
      // Every row (moments per unit of the length scale) against the largest term of the system: the backward
      // error of the solve.
      const auto weight = [&](int row) { return row % 3 == 2 ? 1 / m.length_scale : 1.0; };
      double size = 0;
      for (int row = 0; row < data.layout.rows; ++row) {
        size = std::max(size, std::abs(data.rhs(row, c)) * weight(row));
        for (int k = 0; k < data.layout.size(); ++k) size = std::max(size, std::abs(data.matrix(row, k) * x(k)) * weight(row));
      }
      for (int row = 0; row < data.layout.rows; ++row) worst = std::max(worst, std::abs(residual(row)) * weight(row) / size);
    }
  }
  BOOST_TEST_MESSAGE("paper example: Newton-Euler residual per link row " << worst << " of the largest term");
  BOOST_TEST(worst < 1e-14);
}

BOOST_AUTO_TEST_CASE(mpfr_forces_agree_with_double) {
  for (const std::string& file : {kExamples + "paper_fourbar.json", kData + "eccentric_cam.json"}) {
    const Solved s = solve(io::load_scene(file));
    const Mechanism<double>& m = s.scene.mechanism;
    const Dynamics<double> d = test_dynamics(m, 9.0);
    const Mechanism<mpfr50> mp = m.cast<mpfr50>();
    const Dynamics<mpfr50> dp = d.cast<mpfr50>();
    ForceData<double> data(m);
    ForceData<mpfr50> data_mp(mp);
    // A pose of the sweep, solved again in MPFR from the double pose (Newton at 50 digits), its rates too.
    const auto& pose = s.result.poses[s.result.poses.size() / 3];
    VectorX<mpfr50> q = VectorX<double>(pose.q).cast<mpfr50>();
    SolveData<mpfr50> sd(mp);
    sd.kin.reference = q;  // arc lengths counted from here: only the loops' closure matters for a pose
    BOOST_REQUIRE(solve_position(mp, q, sd).ok());
    VectorX<mpfr50> rates = VectorX<mpfr50>::Zero(static_cast<Eigen::Index>(mp.drivers.size()));
    rates(0) = 1;
    const VectorX<mpfr50> qdot = solve_velocity(mp, sd, rates);
    const PoseForces<mpfr50> fm = pose_forces(mp, dp, q, qdot, data_mp);
    const PoseForces<double> fd = pose_forces(m, d, pose.q, pose.qdot, data);
    double worst = 0, size = 0;
    for (int k = 0; k < data.layout.size(); ++k) size = std::max(size, std::abs(fd.value(k, 9.0)));
    for (int k = 0; k < data.layout.size(); ++k)
      worst = std::max(worst, std::abs(fd.value(k, 9.0) - to_double(fm.value(k, mpfr50(9)))) / size);
    BOOST_TEST_MESSAGE(std::filesystem::path(file).filename().string() << ": MPFR against double " << worst << " of the largest force");
    BOOST_TEST(worst < 1e-12);
  }
}

BOOST_AUTO_TEST_CASE(the_same_cam_in_millimetres_and_in_metres) {
  // The eccentric cam's scene in metres: every length divided by 1000, the spring rate (N/length) and the
  // inertia (kg length^2) converted; forces come out the same in N, torques in N m = N mm / 1000.
  const nlohmann::ordered_json mm = io::read_scene_document(kData + "eccentric_cam.json");
  nlohmann::ordered_json metres = mm;
  metres["units"]["length"] = "m";
  metres["links"][1]["contours"][0]["radius"] = 0.04;
  metres["links"][1]["contours"][0]["at"]["x"] = 0.01;
  metres["links"][2]["contours"][0]["from"] = -0.08;
  metres["links"][2]["contours"][0]["to"] = 0.08;
  metres["pairs"][1]["value"] = 0.04;
  metres["dynamics"]["links"]["follower"]["inertia"] = 100e-6;
  metres["dynamics"]["springs"][0]["from"][1] = {0, 0.2};
  metres["dynamics"]["springs"][0]["rate"] = 2000;
  metres["dynamics"]["springs"][0]["free_length"] = 0.185;
  metres["dynamics"]["gravity"] = {0, -9.80665};
  nlohmann::ordered_json mm_g = mm;
  mm_g["dynamics"]["gravity"] = {0, -9806.65};
  const Solved a = solve(io::build_scene(mm_g, kData + "eccentric_cam.json"));
  const Solved b = solve(io::build_scene(metres, kData + "eccentric_cam_m.json"));
  ForceData<double> da(a.scene.mechanism), db(b.scene.mechanism);
  const double w = a.scene.dynamics->speed;
  double worst = 0;
  for (std::size_t p = 0; p < a.result.poses.size(); ++p) {
    const PoseForces<double> fa = pose_forces(a.scene.mechanism, *a.scene.dynamics, a.result.poses[p].q, a.result.poses[p].qdot, da);
    const PoseForces<double> fb = pose_forces(b.scene.mechanism, *b.scene.dynamics, b.result.poses[p].q, b.result.poses[p].qdot, db);
    for (int k = 0; k < da.layout.size(); ++k) {
      const ReactionKind kind = da.layout.unknowns[static_cast<std::size_t>(k)].kind;
      const bool moment = kind == ReactionKind::GuideMoment || (kind == ReactionKind::Effort);
      const double in_newtons = moment ? fa.value(k, w) / 1000 : fa.value(k, w);
      worst = std::max(worst, std::abs(in_newtons - fb.value(k, w)) / 100);
    }
  }
  BOOST_TEST_MESSAGE("eccentric cam, mm against m: " << worst << " N (per 100 N)");
  BOOST_TEST(worst < 1e-12);
}

BOOST_AUTO_TEST_CASE(redundant_constraints_leave_reactions_open_and_the_effort_unique) {
  // The hypocycloid: the planet's centre is held both by the arm (pair P) and by the ring's contact (C).
  const Solved s = solve(io::load_scene(kExamples + "hypocycloid.json"));
  const Mechanism<double>& m = s.scene.mechanism;
  const Dynamics<double> d = test_dynamics(m, 4.0);
  ForceData<double> data(m);
  for (const auto& pose : s.result.poses) {
    const PoseForces<double> f = pose_forces(m, d, pose.q, pose.qdot, data);
    BOOST_REQUIRE(f.determined);
    BOOST_TEST(f.rank == data.layout.size() - 1);
    BOOST_TEST(f.unique[static_cast<std::size_t>(data.layout.effort[0])]);
    for (const char* pair : {"O", "P", "C"}) {
      const int k = m.find_pair(pair);
      bool open = false;
      for (int j = 0; j < data.layout.count[static_cast<std::size_t>(k)]; ++j)
        open = open || !f.unique[static_cast<std::size_t>(data.layout.first[static_cast<std::size_t>(k)] + j)];
      BOOST_TEST(open, pair);
    }
  }
}

BOOST_AUTO_TEST_CASE(bad_dynamics_are_input_errors_with_file_and_path) {
  const nlohmann::ordered_json good = io::read_scene_document(kData + "eccentric_cam.json");
  struct Case {
    const char* path;
    nlohmann::ordered_json value;
    const char* where;
    const char* says;
  };
  const std::vector<Case> cases = {
      {"/dynamics/speed", nullptr, "dynamics", "speed"},
      {"/dynamics/speed/unit", "mm/s", "dynamics.speed.unit", "rpm"},
      {"/dynamics/links/follower/mass", 0, "dynamics.links.follower.mass", "positive"},
      {"/dynamics/links/follower/inertia", -1, "dynamics.links.follower.inertia", "positive"},
      {"/dynamics/links/nope", {{"mass", 1}, {"inertia", 1}}, "dynamics.links.nope", "unknown link"},
      {"/dynamics/links/frame", {{"mass", 1}, {"inertia", 1}}, "dynamics.links.frame", "ground"},
      {"/dynamics/springs/0/to/0", "frame", "dynamics.springs[0]", "one link"},
      {"/dynamics/friction", {{"O", 0.1}}, "dynamics.friction.O", "revolute"},
      {"/dynamics/contact/C/poisson/1", 0.6, "dynamics.contact.C.poisson[1]", "[0, 0.5)"},
      {"/dynamics/loads", {{{"link", "follower"}}}, "dynamics.loads[0]", "force"},
      {"/dynamics/mass", 1, "dynamics", "mass"},
  };
  for (const Case& c : cases) {
    nlohmann::ordered_json bad = good;
    if (c.value.is_null()) bad["dynamics"].erase("speed");
    else bad[nlohmann::ordered_json::json_pointer(c.path)] = c.value;
    const std::string msg = input_error_of([&] { io::build_scene(bad, "cam.json"); });
    BOOST_TEST_CONTEXT(c.path) {
      BOOST_TEST(contains(msg, "cam.json"));
      BOOST_TEST(contains(msg, c.where));
      BOOST_TEST(contains(msg, c.says), msg);
    }
  }
}
