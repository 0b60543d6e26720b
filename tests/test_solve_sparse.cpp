// The sparse path of the position solver (solve/sparse_lu.hpp) on generated mechanisms of n loops
// (rollkin/samples/mechanisms.hpp: disk_train, four_bar_chain, cam_gear_train) up to n = 256: results equal the closed
// forms and the dense solver's; redundant constraints found as by the dense path; inconsistent and
// underdetermined mechanisms reported as before; the determinant sign that the continuation tracks branches
// with is the dense path's, and a sweep through the change points of a parallelogram stage keeps its branch
// as on the dense path; a scalar without a sparse back end (MPFR) falls back to the dense path.
#define BOOST_TEST_MODULE solve_sparse
#include <boost/test/unit_test.hpp>

#include "rollkin/samples/mechanisms.hpp"
#include "rollkin/scalar_mpfr.hpp"
#include "rollkin/solve/mpfr50_instances.hpp"

#include <cmath>
#include <functional>

using namespace rollkin;
using namespace rollkin::testing;

namespace {

const double kDeg = pi<double>() / 180;

/// Solves the poses of a fixture for the inputs (radians, in small steps from the assembly pose's), each Newton
/// run started from the previous pose moved along its velocity.
/// Returns the poses; each report must be ok. signs receives the determinant sign at each pose.
/// sparse_poses (if given) counts the poses whose last factorisation was the sparse LU (SolveData::sparse_active).
std::vector<VectorX<double>> follow(const Fixture<double>& f, Factorisation how, const std::vector<double>& inputs,
                                    SolveReport<double>* assembly = nullptr, std::vector<int>* signs = nullptr,
                                    int* sparse_poses = nullptr) {
  SolveData<double> sd(f.mech, how);
  VectorX<double> q = f.guess;
  const SolveReport<double> rep = assemble(f.mech, q, sd, f.held);
  if (assembly) *assembly = rep;
  std::vector<VectorX<double>> out;
  if (!rep.ok()) return out;
  const VectorX<double> unit_rate = VectorX<double>::Ones(1);
  for (double x : inputs) {
    // Euler predictor along the motion, then Newton (what the continuation does, without its step control).
    const VectorX<double> rates = solve_velocity(f.mech, sd, unit_rate);
    q += rates * (x - q(f.mech.drivers[0]));
    q(f.mech.drivers[0]) = x;
    const SolveReport<double> r = solve_position(f.mech, q, sd);
    BOOST_TEST_REQUIRE(r.ok(), "input " << x / kDeg << " deg: " << r.detail);
    out.push_back(q);
    if (signs) signs->push_back(sd.determinant_sign());
    if (sparse_poses && sd.sparse_active) ++*sparse_poses;
  }
  return out;
}

const char* backend_name(Factorisation how) {
  switch (how) {
    case Factorisation::Automatic: return "automatic";
    case Factorisation::Dense: return "dense";
    case Factorisation::EigenSparseLU: return "eigen_sparselu";
    case Factorisation::Klu: return "klu";
  }
  return "?";
}

std::vector<double> inputs_deg(double from, double to, double step) {
  std::vector<double> v;
  for (double d = from; d <= to + 1e-9; d += step) v.push_back(d * kDeg);
  return v;
}

/// Largest difference of two pose lists (radians or lengths).
double max_difference(const std::vector<VectorX<double>>& a, const std::vector<VectorX<double>>& b) {
  BOOST_TEST_REQUIRE(a.size() == b.size());
  double d = 0;
  for (std::size_t k = 0; k < a.size(); ++k) d = std::max(d, (a[k] - b[k]).cwiseAbs().maxCoeff());
  return d;
}

/// Gear train: phi_k = (-1)^k (r_0 / r_k) phi_0 (rollkin/samples/mechanisms.hpp).
double gear_train_error_deg(int n, const std::vector<VectorX<double>>& poses) {
  double worst = 0;
  for (const auto& q : poses)
    for (int k = 0; k <= n; ++k) {
      const double expected = (k % 2 ? -1 : 1) * disk_train_radius<double>(0) / disk_train_radius<double>(k) * q(0);
      worst = std::max(worst, std::abs(q(k) - expected) / kDeg);
    }
  return worst;
}

/// Rocker k+1's angle in a four-bar chain from rocker k's (rollkin/samples/mechanisms.hpp four_bar_chain): pin B_k is
/// where the circle of radius `coupler` about pin A_k meets the circle of radius c about pivot k+1, on the left
/// of the line from A_k to pivot k+1, where it lies at rest (pins straight up) and stays while the bar's
/// transmission angle is neither 0 nor 180 deg. A parallelogram bar (a = c, coupler = pivot spacing) on its
/// parallelogram branch turns rocker k+1 with rocker k. An independent closed form, bar by bar from the
/// solved input of each bar (round-off is not amplified along 256 bars).
double next_rocker_angle(int k, double theta, const ChainBar<double>& bar) {
  if (bar.a == bar.c && bar.coupler == bar.d) return theta;
  const Vec2<double> pin(4.0 * k - bar.a * std::sin(theta), bar.a * std::cos(theta));
  const Vec2<double> pivot(4.0 * (k + 1), 0);
  const Vec2<double> d = pivot - pin;
  const double dist = d.norm();
  const double along = (bar.coupler * bar.coupler - bar.c * bar.c + dist * dist) / (2 * dist);
  const double h = std::sqrt(std::max(0.0, bar.coupler * bar.coupler - along * along));
  const Vec2<double> b = pin + along / dist * d + h * Vec2<double>(-d.y() / dist, d.x() / dist);
  // pin B at (0, c) in the rocker's frame: B = pivot + c (-sin theta, cos theta)
  return std::atan2(-(b.x() - pivot.x()), b.y() - pivot.y());
}

/// Largest error (deg) of the rockers 1 .. n of a four-bar chain against next_rocker_angle.
double chain_error_deg(int n, const std::vector<VectorX<double>>& poses,
                       ChainBar<double> (*bar_of)(int) = four_bar_chain_bar<double>) {
  double worst = 0;
  for (const auto& q : poses)
    for (int k = 0; k < n; ++k)
      worst = std::max(worst, std::abs(wrap_angle(q(k + 1) - next_rocker_angle(k, q(k), bar_of(k)))) / kDeg);
  return worst;
}

/// Height of a follower of cam_gear_train above its disk's pivot at the cam's angle phi (the closed forms of
/// rollkin/samples/mechanisms.hpp): roller centre at distance R + r from the cam centre e (cos phi, sin phi) on the
/// vertical through the pivot; flat face through (0, s) with normal (-sin beta, cos beta) at distance R.
double follower_height(const CamFollowerDims<double>& d, double phi) {
  if (d.roller) return d.e * std::sin(phi) + std::sqrt((d.R + d.r) * (d.R + d.r) - std::pow(d.e * std::cos(phi), 2));
  return (d.e * std::sin(phi - d.beta) + d.R) / std::cos(d.beta);
}

/// Largest error of the followers' heights of cam_gear_train(n), relative to each cam's size R + e, each from
/// its own disk's solved angle (the disks' angles are checked by gear_train_error_deg).
double follower_relative_error(const Fixture<double>& f, int n, const std::vector<VectorX<double>>& poses) {
  std::vector<int> s(static_cast<std::size_t>(n + 1), -1);
  for (int k = 1; k <= n; ++k) {
    s[static_cast<std::size_t>(k)] = f.mech.find_variable("guide" + std::to_string(k) + ".s");
    BOOST_TEST_REQUIRE(s[static_cast<std::size_t>(k)] >= 0);
  }
  double worst = 0;
  for (const auto& q : poses)
    for (int k = 1; k <= n; ++k) {
      const CamFollowerDims<double> d = cam_gear_train_cam<double>(k);
      const double expected = follower_height(d, q(k));
      worst = std::max(worst, std::abs(q(s[static_cast<std::size_t>(k)]) - expected) / (d.R + d.e));
    }
  return worst;
}

/// Sweeps f's input over 0 .. 360 deg (steps of 1 deg, landing on the change points at 90 and 270 deg, and of
/// 0.7 deg, stepping over them) with the dense path and both sparse back ends (the scene must be large enough
/// for them: sparse_threshold unknowns). Every pose must follow the assembled branch (branch_error_deg: the
/// largest error of the pose against the closed form, deg) to 1e-9 deg; a requested input on a change point
/// may get status Singular (values interpolated on the branch, to 1e-6 deg) or, polished by Newton,
/// Converged (continuation.hpp's file comment). The sparse back ends must follow the dense path pose by pose.
void check_sweeps_through_change_points(const Fixture<double>& f,
                                        const std::function<double(const VectorX<double>&)>& branch_error_deg) {
  for (double step : {1.0, 0.7}) {  // landing on both change points; stepping over them between grid values
    const std::vector<double> inputs = inputs_deg(0, 360, step);
    std::vector<SweepResult<double>> results;
    for (Factorisation how : {Factorisation::Dense, Factorisation::EigenSparseLU, Factorisation::Klu}) {
      SolveData<double> sd(f.mech, how);
      BOOST_TEST_REQUIRE((sd.method == how));
      VectorX<double> q = f.guess;
      const SolveReport<double> rep = assemble(f.mech, q, sd, f.held);
      BOOST_TEST_REQUIRE(rep.ok());
      results.push_back(sweep(f.mech, sd, q, rep, 0, inputs));
      if (how != Factorisation::Dense) BOOST_TEST(sd.sparse_active, backend_name(how));
      const SweepResult<double>& res = results.back();
      const std::string label = std::string(backend_name(how)) + ", step " + std::to_string(step) + " deg";
      BOOST_TEST(res.limits.empty(), label << ": " << (res.limits.empty() ? "" : res.limits[0].detail));
      int singular = 0, missing = 0, off_branch = 0, misplaced = 0;
      for (std::size_t k = 0; k < res.size(); ++k) {
        if (!res.has_pose(k)) {
          ++missing;
          continue;
        }
        const double input_deg = res.input(k) / kDeg;
        const double error_deg = branch_error_deg(res.q(k));
        if (res.status(k) == SolveStatus::Singular) {
          ++singular;
          // Only on a change point; the values still follow the branch (interpolated between regular poses).
          if (std::abs(std::remainder(input_deg - 90, 180.0)) > 1e-9) ++misplaced;
          if (!(error_deg < 1e-6)) ++off_branch;
        } else if (!res.ok(k) || !(error_deg < 1e-9)) {
          ++off_branch;
        }
      }
      BOOST_TEST(missing == 0, label << ": " << missing << " poses not reached");
      BOOST_TEST(off_branch == 0, label << ": " << off_branch << " poses off the branch or not converged");
      BOOST_TEST(misplaced == 0, label << ": " << misplaced << " singular poses off the change points");
      BOOST_TEST(singular <= (step == 1.0 ? 2 : 0), label << ": " << singular << " singular poses");
    }
    // The sparse back ends follow the dense path pose by pose: same statuses, same values to round-off (the
    // interpolated singular poses to the interpolation's accuracy).
    for (std::size_t b = 1; b < results.size(); ++b) {
      int other_status = 0;
      double worst_regular = 0, worst_singular_deg = 0;
      for (std::size_t k = 0; k < inputs.size(); ++k) {
        if (results[b].status(k) != results[0].status(k)) ++other_status;
        if (!results[b].has_pose(k) || !results[0].has_pose(k)) continue;
        const double d = (results[b].q(k) - results[0].q(k)).cwiseAbs().maxCoeff();
        // Round-off: relative to the pose's largest variable (a gear train's angles reach several turns), and
        // amplified by the condition next to a singular pose (16 eps x condition, at least 1e-12; the larger of
        // the two paths' estimates: a redundant system's comes from the independent rows each path chose).
        const double size = std::max(1.0, results[0].q(k).cwiseAbs().maxCoeff());
        const double condition = std::max(results[0].report(k).condition, results[b].report(k).condition);
        const double round_off = std::max(1e-12, 16 * epsilon<double>() * condition);
        if (results[0].ok(k) && results[b].ok(k)) worst_regular = std::max(worst_regular, d / size / round_off);
        else worst_singular_deg = std::max(worst_singular_deg, d / kDeg);
      }
      const char* name = b == 1 ? "eigen_sparselu" : "klu";
      BOOST_TEST(other_status == 0, name << ", step " << step << " deg: " << other_status << " statuses differ from dense");
      BOOST_TEST(worst_regular <= 1, name << ", step " << step << " deg: " << worst_regular << " x round-off from dense");
      BOOST_TEST(worst_singular_deg < 1e-6, name << ", step " << step << " deg: " << worst_singular_deg << " deg from dense");
    }
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(automatic_choice_is_dense_for_small_and_sparse_for_large_mechanisms) {
  BOOST_TEST((SolveData<double>(paper_fourbar<double>().mech).method == Factorisation::Dense));
  BOOST_TEST((SolveData<double>(disk_train<double>(2).mech).method == Factorisation::Dense));
  BOOST_TEST((SolveData<double>(disk_train<double>(64).mech).method == default_sparse_factorisation()));
  BOOST_TEST((SolveData<double>(four_bar_chain<double>(64).mech).method == default_sparse_factorisation()));
  // The sparse path does not hold the dense Jacobian.
  BOOST_TEST(SolveData<double>(disk_train<double>(64).mech).kin.jacobian.size() == 0);
}

BOOST_AUTO_TEST_CASE(gear_trains_follow_the_ratio_products_and_the_dense_solver) {
  const std::vector<double> inputs = inputs_deg(0, 180, 15);
  for (int n : {2, 8, 32, 256}) {
    const Fixture<double> f = disk_train<double>(n);
    for (Factorisation how : {Factorisation::EigenSparseLU, Factorisation::Klu}) {
      SolveReport<double> rep;
      const auto poses = follow(f, how, inputs, &rep);
      BOOST_TEST_REQUIRE(rep.ok(), "n " << n << ": " << rep.detail);
      // Redundant constraints found as by the dense path: 4n equations, rank 3n, n redundant.
      BOOST_TEST(rep.equations == 4 * n);
      BOOST_TEST(rep.rank == 3 * n);
      BOOST_TEST(rep.redundant() == n);
      BOOST_TEST(gear_train_error_deg(n, poses) < 1e-9, "n " << n);
      if (n <= 32) BOOST_TEST(max_difference(poses, follow(f, Factorisation::Dense, inputs)) < 1e-12, "n " << n);
    }
  }
  // n = 256 against the dense solver at a few inputs (its dense decomposition costs ~N^3 per step).
  const Fixture<double> f = disk_train<double>(256);
  const std::vector<double> few{10 * kDeg, 25 * kDeg};
  BOOST_TEST(max_difference(follow(f, Factorisation::Automatic, few), follow(f, Factorisation::Dense, few)) < 1e-12);
}

BOOST_AUTO_TEST_CASE(four_bar_chains_follow_the_closed_form_and_the_dense_solver) {
  // Up to 8 deg, back and down to -10 deg: the chain of 256 bars amplifies the input (to 19 deg at 8 deg and
  // to 52 deg, near a dead point, at 10 deg).
  std::vector<double> inputs = inputs_deg(0, 8, 2);
  for (double d = 6; d >= -10; d -= 2) inputs.push_back(d * kDeg);
  for (int n : {2, 8, 32, 256}) {
    const Fixture<double> f = four_bar_chain<double>(n);
    for (Factorisation how : {Factorisation::EigenSparseLU, Factorisation::Klu}) {
      SolveReport<double> rep;
      std::vector<int> signs;
      const auto poses = follow(f, how, inputs, &rep, &signs);
      BOOST_TEST_REQUIRE(rep.ok(), "n " << n << ": " << rep.detail);
      BOOST_TEST(rep.equations == 3 * n);
      BOOST_TEST(rep.rank == 3 * n);
      BOOST_TEST(chain_error_deg(n, poses) < 1e-9, "n " << n);
      if (n <= 32) {
        // Same poses and, the system being square, the same determinant sign (the continuation's branch
        // tracking) as the dense LU of the same matrix.
        std::vector<int> dense_signs;
        BOOST_TEST(max_difference(poses, follow(f, Factorisation::Dense, inputs, nullptr, &dense_signs)) < 1e-12);
        BOOST_TEST(signs == dense_signs, "n " << n);
        for (int s : signs) BOOST_TEST(s != 0);
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(inconsistent_and_underdetermined_trains_are_reported_as_by_the_dense_path) {
  for (Factorisation how : {Factorisation::Dense, Factorisation::EigenSparseLU, Factorisation::Klu}) {
    // The last disk's pivot 1% too far: the last contact cannot close.
    Fixture<double> f = disk_train<double>(32);
    const int last = static_cast<int>(f.mech.pairs.size()) - 33;  // pivot32: the revolutes come first
    BOOST_TEST_REQUIRE(f.mech.pairs[last].name == "pivot32");
    f.mech.pairs[last].frame_a = SE2<double>(0, f.mech.pairs[last].frame_a.translation() * 1.01);
    SolveReport<double> rep;
    follow(f, how, {}, &rep);
    BOOST_TEST((rep.status == SolveStatus::CannotAssemble), "backend " << static_cast<int>(how));
    // No driver: the chain keeps one degree of freedom.
    Fixture<double> free = four_bar_chain<double>(32);
    free.mech.drivers.clear();
    free.mech.finalize();
    follow(free, how, {}, &rep);
    BOOST_TEST((rep.status == SolveStatus::Underdetermined), "backend " << static_cast<int>(how));
    BOOST_TEST(rep.rank == 3 * 32);
    BOOST_TEST(rep.unknowns == 3 * 32 + 1);
  }
}

BOOST_AUTO_TEST_CASE(velocities_and_accelerations_equal_the_dense_path) {
  const Fixture<double> f = four_bar_chain<double>(16);
  VectorX<double> rates[2], accels[2];
  int i = 0;
  for (Factorisation how : {Factorisation::Dense, Factorisation::Klu}) {
    SolveData<double> sd(f.mech, how);
    VectorX<double> q = f.guess;
    BOOST_TEST_REQUIRE(assemble(f.mech, q, sd, f.held).ok());
    q(0) = 20 * kDeg;
    BOOST_TEST_REQUIRE(solve_position(f.mech, q, sd).ok());
    const VectorX<double> one = VectorX<double>::Ones(1), zero = VectorX<double>::Zero(1);
    rates[i] = solve_velocity(f.mech, sd, one);
    accels[i] = solve_acceleration(f.mech, q, sd, rates[i], zero);
    ++i;
  }
  BOOST_TEST((rates[0] - rates[1]).cwiseAbs().maxCoeff() < 1e-12);
  BOOST_TEST((accels[0] - accels[1]).cwiseAbs().maxCoeff() < 1e-11);
  BOOST_TEST(rates[0].cwiseAbs().maxCoeff() > 0.1);  // not trivially zero
}

BOOST_AUTO_TEST_CASE(mpfr_falls_back_to_the_dense_path) {
  using Mp = mpfr50;
  const Fixture<Mp> f = disk_train<Mp>(sparse_threshold);
  SolveData<Mp> sd(f.mech, Factorisation::Klu);
  BOOST_TEST((sd.method == Factorisation::Dense));
  VectorX<Mp> q = f.guess;
  BOOST_TEST_REQUIRE(assemble(f.mech, q, sd, f.held).ok());
  q(0) = Mp(30) * pi<Mp>() / Mp(180);
  BOOST_TEST_REQUIRE(solve_position(f.mech, q, sd).ok());
  const Mp expected = -disk_train_radius<Mp>(0) / disk_train_radius<Mp>(1) * q(0);
  BOOST_TEST(abs(q(1) - expected) < Mp("1e-40"));
}

BOOST_AUTO_TEST_CASE(cam_gear_trains_follow_the_closed_forms_and_the_dense_solver) {
  // Mixed mechanism: rolling pairs (gears), cam pairs (followers), revolutes and prismatics, 2n loops.
  const std::vector<double> inputs = inputs_deg(0, 180, 15);
  for (int n : {2, 8, 32, 64, 256}) {
    const Fixture<double> f = cam_gear_train<double>(n);
    BOOST_TEST_REQUIRE(f.mech.unknowns.size() == static_cast<std::size_t>(6 * n));
    // From 12 unknowns (n = 2) the automatic choice is the sparse path.
    BOOST_TEST((SolveData<double>(f.mech).method == default_sparse_factorisation()), "n " << n);
    std::vector<VectorX<double>> dense;
    // The dense path (a COD of 7n x 6n per Newton step: redundant rows) over the path up to n = 8, at two
    // inputs for n = 32; beyond, it costs seconds per pose.
    const std::vector<double> few{10 * kDeg, 25 * kDeg};
    if (n <= 32) dense = follow(f, Factorisation::Dense, n <= 8 ? inputs : few);
    // Both sparse back ends up to n = 64; at n = 256 the default one (choosing the independent rows by sparse
    // QR at assembly costs about a second there).
    std::vector<Factorisation> backends{Factorisation::EigenSparseLU, Factorisation::Klu};
    if (n > 64) backends = {Factorisation::Automatic};
    for (Factorisation how : backends) {
      SolveReport<double> rep;
      int sparse_poses = 0;
      const auto poses = follow(f, how, inputs, &rep, nullptr, &sparse_poses);
      BOOST_TEST_REQUIRE(rep.ok(), "n " << n << ": " << rep.detail);
      // Redundant constraints as in the gear train: one per mesh (the centre distance); the cams add none.
      BOOST_TEST(rep.equations == 7 * n);
      BOOST_TEST(rep.unknowns == 6 * n);
      BOOST_TEST(rep.rank == 6 * n);
      BOOST_TEST(rep.redundant() == n);
      // Every pose factored by the sparse LU (no fall-back to the dense decomposition).
      BOOST_TEST(sparse_poses == static_cast<int>(inputs.size()), "n " << n);
      const double disks_deg = gear_train_error_deg(n, poses), followers = follower_relative_error(f, n, poses);
      BOOST_TEST_MESSAGE("cam_gear_train " << n << " " << backend_name(how) << ": disks " << disks_deg
                                           << " deg, followers " << followers << " relative");
      BOOST_TEST(disks_deg < 1e-9, "n " << n);
      // 1e-9 deg on a lever of the cam's size.
      BOOST_TEST(followers < 1e-9 * kDeg, "n " << n);
      if (n <= 8) BOOST_TEST(max_difference(poses, dense) < 1e-12, "n " << n);
      if (n == 32) BOOST_TEST(max_difference(follow(f, how, few), dense) < 1e-12, "n " << n);
    }
  }
}

BOOST_AUTO_TEST_CASE(sweeps_on_the_sparse_path_keep_the_branch_through_change_points) {
  // A chain of 8 four-bars (24 unknowns: the sparse path) whose first bar is a parallelogram: at theta_0 = 90
  // and 270 deg its pins lie on the pivots' line and its crossed branch meets the parallelogram branch. The
  // continuation (continuation.hpp) must keep the parallelogram branch (theta_1 = theta_0) through both, on
  // the sparse path as on the dense one; a requested input on a change point gets status Singular (values
  // interpolated on the branch) or, polished by Newton, Converged.
  const int n = 8;
  const Fixture<double> f = four_bar_chain<double>(n, change_point_chain_bar<double>);
  BOOST_TEST_REQUIRE(f.mech.equation_count() == static_cast<int>(f.mech.unknowns.size()));  // square: det J_u's sign
  check_sweeps_through_change_points(f, [&](const VectorX<double>& q) {
    return chain_error_deg(n, {q}, change_point_chain_bar<double>);
  });
}

BOOST_AUTO_TEST_CASE(sweeps_on_the_sparse_path_keep_the_branch_of_a_redundant_train_through_change_points) {
  // The gear train of 8 stages (redundant: 35 equations, 27 unknowns) whose last disk drives a parallelogram:
  // both paths factor the LU of independent rows (chosen once) and track the sign of its determinant. Closed forms: phi_k = (-1)^k (r_0 / r_k) phi_0 (phi_8 = phi_0) and the rocker's angle = phi_8.
  const int n = 8;
  const Fixture<double> f = gear_train_with_parallelogram<double>(n);
  const int rocker = f.mech.find_variable("O.theta");
  BOOST_TEST_REQUIRE(rocker >= 0);
  // Landing on a change point once sent the sparse path to the other branch: a pose next to it that Newton
  // left at a residual of 64 eps had condition x residual above eps^(2/3) only by the sparse path's (larger)
  // condition estimate, so it was taken for singular and stepped over to a far pose that was singular too.
  // Newton now refines such a pose to round-off (solve_position, detail::worth_refining).
  check_sweeps_through_change_points(
      f, [&](const VectorX<double>& q) {
        return std::max(gear_train_error_deg(n, {q}), std::abs(wrap_angle(q(rocker) - q(n))) / kDeg);
      });
}

BOOST_AUTO_TEST_CASE(sparse_condition_reveals_the_singular_change_point) {
  // At theta_0 = 90 deg exactly the parallelogram bar of change_point_chain is at its change point: J_u is
  // singular (its smallest singular value is round-off). The continuation recognises such a pose by
  // condition x residual (continuation.hpp, singular_trial); a condition that stays small there lets it take
  // the singular pose for a regular one and predict from it (the sweep above then stops at 270 deg).
  const int n = 8;
  const Fixture<double> f = four_bar_chain<double>(n, change_point_chain_bar<double>);
  const std::vector<VectorX<double>> path = follow(f, Factorisation::Dense, inputs_deg(1, 90, 1));
  BOOST_TEST_REQUIRE(path.size() == 90u);
  const VectorX<double>& q = path.back();
  BOOST_TEST_REQUIRE(std::abs(q(0) - 90 * kDeg) < 1e-15);
  BOOST_TEST_REQUIRE(std::abs(q(1) - q(0)) < 1e-9 * kDeg);  // on the parallelogram branch, at the change point
  for (Factorisation how : {Factorisation::Dense, Factorisation::EigenSparseLU, Factorisation::Klu}) {
    SolveData<double> sd(f.mech, how);
    VectorX<double> q0 = f.guess;
    BOOST_TEST_REQUIRE(assemble(f.mech, q0, sd, f.held).ok());
    evaluate_and_factor(f.mech, q, sd, f.mech.equation_count());
    // eps^-1/3 = 1.7e5, the continuation's "outright" ill-conditioning; the dense LU says 1.5e12 here.
    BOOST_TEST(sd.condition > 1e10, backend_name(how) << ": condition " << sd.condition);
  }
}
