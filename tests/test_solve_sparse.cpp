// The sparse path of the position solver (solve/sparse_lu.hpp) on generated mechanisms of n loops
// (tests/mechanisms.hpp: disk_train, four_bar_chain) up to n = 256: results equal the closed forms and the
// dense solver's; redundant constraints found as by the dense path; inconsistent and underdetermined
// mechanisms reported as before; the determinant sign that the continuation tracks branches with is the
// dense path's; a scalar without a sparse back end (MPFR) falls back to the dense path.
#define BOOST_TEST_MODULE solve_sparse
#include <boost/test/unit_test.hpp>

#include "mechanisms.hpp"
#include "rollkin/scalar_mpfr.hpp"

#include <cmath>

using namespace rollkin;
using namespace rollkin::testing;

namespace {

const double kDeg = pi<double>() / 180;

/// Solves the poses of a fixture for the inputs (radians, in small steps from the assembly pose's), each Newton
/// run started from the previous pose moved along its velocity.
/// Returns the poses; each report must be ok. signs receives the determinant sign at each pose.
std::vector<VectorX<double>> follow(const Fixture<double>& f, Factorisation how, const std::vector<double>& inputs,
                                    SolveReport<double>* assembly = nullptr, std::vector<int>* signs = nullptr) {
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
  }
  return out;
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

/// Gear train: phi_k = (-1)^k (r_0 / r_k) phi_0 (tests/mechanisms.hpp).
double gear_train_error_deg(int n, const std::vector<VectorX<double>>& poses) {
  double worst = 0;
  for (const auto& q : poses)
    for (int k = 0; k <= n; ++k) {
      const double expected = (k % 2 ? -1 : 1) * disk_train_radius<double>(0) / disk_train_radius<double>(k) * q(0);
      worst = std::max(worst, std::abs(q(k) - expected) / kDeg);
    }
  return worst;
}

/// Four-bar chain: rocker k+1's angle from rocker k's by intersecting the circle of radius `coupler` about
/// pin A_k with the circle of radius c about pivot k+1 (the intersection above the pivots' line, the
/// assembled branch): an independent closed form, each bar's output from the solved input.
double chain_error_deg(int n, const std::vector<VectorX<double>>& poses) {
  double worst = 0;
  for (const auto& q : poses) {
    for (int k = 0; k < n; ++k) {
      double theta = q(k);  // bar by bar: round-off is not amplified along 256 bars
      const ChainBar<double> bar = four_bar_chain_bar<double>(k);
      const Vec2<double> pin(4.0 * k - bar.a * std::sin(theta), bar.a * std::cos(theta));
      const Vec2<double> pivot(4.0 * (k + 1), 0);
      const Vec2<double> d = pivot - pin;
      const double dist = d.norm();
      const double along = (bar.coupler * bar.coupler - bar.c * bar.c + dist * dist) / (2 * dist);
      const double h = std::sqrt(bar.coupler * bar.coupler - along * along);
      const Vec2<double> mid = pin + along / dist * d, normal(-d.y() / dist, d.x() / dist);
      const Vec2<double> b1 = mid + h * normal, b2 = mid - h * normal;
      const Vec2<double> b = b1.y() > b2.y() ? b1 : b2;
      // pin B at (0, c) in the rocker's frame: B = pivot + c (-sin theta, cos theta)
      theta = std::atan2(-(b.x() - pivot.x()), b.y() - pivot.y());
      worst = std::max(worst, std::abs(q(k + 1) - theta) / kDeg);
    }
  }
  return worst;
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
