// Newton's refining step (solve/position.hpp, last case) and the dense path's factorisation of redundant systems
// (solve/solve_data.hpp, SolveData::factor): more rows than
// unknowns are solved by the LU of independent rows, chosen once by a rank-revealing QR and again where their
// pivot ratio grows 16-fold (at that pose) or their LU fails while the system keeps rank n (the COD takes that
// pose, new rows the next); a rank-deficient system by the COD. The Jacobian is set by hand on
// a real mechanism's solve data (disk_train(2): 8 rows, 6 unknowns) so that every case is known exactly: the
// solve of a consistent system must return the x it was built from.
#define BOOST_TEST_MODULE solve_position
#include <boost/test/unit_test.hpp>

#include "rollkin/samples/mechanisms.hpp"

#include <random>

using namespace rollkin;
using namespace rollkin::testing;

namespace {

/// Solve data of disk_train(2) (dense: 8 equations, 6 unknowns) whose scaled Jacobian of the unknowns is set
/// to a given 8 x 6 matrix.
struct HandJacobian {
  Fixture<double> f = disk_train<double>(2);
  SolveData<double> sd{f.mech, Factorisation::Dense};

  void set(const MatrixX<double>& a) {
    BOOST_TEST_REQUIRE(a.rows() == sd.rhs.size());
    BOOST_TEST_REQUIRE(a.cols() == static_cast<Eigen::Index>(sd.unknowns.size()));
    sd.kin.jacobian.setZero();
    for (Eigen::Index r = 0; r < a.rows(); ++r)
      for (Eigen::Index c = 0; c < a.cols(); ++c)
        sd.kin.jacobian(r, sd.unknowns[static_cast<std::size_t>(c)]) = a(r, c) / (sd.row_weight(r) * sd.col_scale(c));
  }
  /// Factors a, solves a x = a x_true and returns the largest error of x.
  double solve_error(const MatrixX<double>& a, const VectorX<double>& x_true) {
    set(a);
    sd.factor(static_cast<int>(a.rows()));
    const VectorX<double> b = a * x_true;
    VectorX<double> x;
    sd.solve(b, x);
    return (x - x_true).cwiseAbs().maxCoeff();
  }
};

/// An 8 x 6 matrix of rank 6: six random rows, then rows 6 and 7 combinations of rows 0-2 and 3-5.
MatrixX<double> redundant(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  MatrixX<double> a(8, 6);
  for (Eigen::Index r = 0; r < 6; ++r)
    for (Eigen::Index c = 0; c < 6; ++c) a(r, c) = u(rng);
  a.row(6) = 0.5 * a.row(0) - a.row(1) + 2 * a.row(2);
  a.row(7) = a.row(3) + a.row(4) - 0.25 * a.row(5);
  return a;
}

VectorX<double> unknowns_x(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  VectorX<double> x(6);
  for (Eigen::Index i = 0; i < 6; ++i) x(i) = u(rng);
  return x;
}

}  // namespace

BOOST_AUTO_TEST_CASE(redundant_rows_are_solved_by_an_lu_of_independent_rows) {
  std::mt19937 rng(11);
  HandJacobian h;
  const MatrixX<double> a = redundant(rng);
  const VectorX<double> x = unknowns_x(rng);
  BOOST_TEST(h.solve_error(a, x) < 1e-13);
  BOOST_TEST(h.sd.lu_active);  // not the COD
  BOOST_TEST(h.sd.rank == 6);
  BOOST_TEST(h.sd.determinant_sign() != 0);  // the continuation can track branches with it
  // The same rows serve the next pose: a nearby matrix is solved as exactly.
  MatrixX<double> near = a;
  near(0, 0) += 1e-3;
  near.row(6) = 0.5 * near.row(0) - near.row(1) + 2 * near.row(2);
  BOOST_TEST(h.solve_error(near, x) < 1e-13);
  BOOST_TEST(h.sd.lu_active);
}

BOOST_AUTO_TEST_CASE(rows_that_become_dependent_are_chosen_again) {
  std::mt19937 rng(12);
  HandJacobian h;
  const VectorX<double> x = unknowns_x(rng);
  MatrixX<double> a = redundant(rng);
  BOOST_TEST(h.solve_error(a, x) < 1e-13);
  // Rows 0-5 alone are now rank 5 (row 1 a copy of row 0); rows 6 and 7 are independent ones, and the
  // whole matrix keeps rank 6. Whichever six rows were chosen, at least one is not among any valid choice
  // unless the choice is made again.
  std::uniform_real_distribution<double> u(-1, 1);
  MatrixX<double> b = a;
  b.row(1) = b.row(0);
  for (Eigen::Index c = 0; c < 6; ++c) b(6, c) = u(rng);
  Eigen::ColPivHouseholderQR<MatrixX<double>> full(b);
  BOOST_TEST_REQUIRE(full.rank() == 6);
  // This pose: the chosen rows' LU is singular, so the COD solves it (rank 6, exactly) and asks for new rows.
  BOOST_TEST(h.solve_error(b, x) < 1e-12);
  BOOST_TEST(!h.sd.lu_active);
  BOOST_TEST(h.sd.rank == 6);
  // The next pose: new independent rows, an LU again.
  BOOST_TEST(h.solve_error(b, x) < 1e-12);
  BOOST_TEST(h.sd.lu_active);
  BOOST_TEST(h.sd.rank == 6);
}

BOOST_AUTO_TEST_CASE(rows_whose_pivot_ratio_grows_are_chosen_again) {
  HandJacobian h;
  std::mt19937 rng(13);
  const VectorX<double> x = unknowns_x(rng);
  // Start from the identity on rows 0-5 plus two redundant rows: rows 0-5 are the well-conditioned choice.
  MatrixX<double> a = MatrixX<double>::Zero(8, 6);
  a.topRows(6).setIdentity();
  a.row(6) = a.row(0) + a.row(1);
  a.row(7) = a.row(2) - a.row(3);
  BOOST_TEST(h.solve_error(a, x) < 1e-14);
  const double chosen_condition = h.sd.condition;
  // Row 0 shrinks to 1e-6 of its size: rows 0-5 now have pivot ratio 1e6, while rows 1-6 (row 6 = e0 + e1)
  // are still perfectly conditioned. The growth beyond 16-fold makes the solver choose again.
  a(0, 0) = 1e-6;
  a.row(6) = MatrixX<double>::Identity(6, 6).row(0) + a.row(1);
  a.row(7) = a.row(2) - a.row(3);
  BOOST_TEST(h.solve_error(a, x) < 1e-14);
  BOOST_TEST(h.sd.lu_active);
  BOOST_TEST(h.sd.condition < 16 * chosen_condition, "condition " << h.sd.condition << " against " << chosen_condition);
}

BOOST_AUTO_TEST_CASE(a_rank_deficient_system_takes_the_cod) {
  std::mt19937 rng(14);
  HandJacobian h;
  MatrixX<double> a = redundant(rng);
  a.row(5) = a.row(4);  // rank 5: rows 6 and 7 are combinations of the others
  a.row(7) = a.row(3) + a.row(4);
  h.set(a);
  h.sd.factor(8);
  BOOST_TEST(!h.sd.lu_active);
  BOOST_TEST(h.sd.rank == 5);
  BOOST_TEST(h.sd.determinant_sign() == 0);
  // The COD's step is the minimum-norm least-squares solution: for a consistent right-hand side it solves
  // the system and is orthogonal to the null space.
  const VectorX<double> b = a * unknowns_x(rng);
  VectorX<double> x;
  h.sd.solve(b, x);
  BOOST_TEST((a * x - b).cwiseAbs().maxCoeff() < 1e-12);
  const Eigen::FullPivLU<MatrixX<double>> lu(a);
  BOOST_TEST((lu.kernel().transpose() * x).cwiseAbs().maxCoeff() < 1e-12);
}

/// Moves the unknowns of q away from their solution along the right singular vector of the smallest singular
/// value of the scaled Jacobian of the unknowns (dense path), by the amount whose scaled residual is `target`:
/// the perturbation with the smallest residual for its size.
void perturb_along_weakest_direction(const Fixture<double>& f, VectorX<double>& q, double target) {
  SolveData<double> sd(f.mech, Factorisation::Dense);
  const int rows = f.mech.equation_count();
  evaluate_and_factor(f.mech, q, sd, rows);
  const auto n = static_cast<Eigen::Index>(sd.unknowns.size());
  MatrixX<double> ju(rows, n);
  for (Eigen::Index r = 0; r < rows; ++r)
    for (Eigen::Index c = 0; c < n; ++c) ju(r, c) = sd.scaled_jacobian(r, c);
  const Eigen::BDCSVD<MatrixX<double>> svd(ju, Eigen::ComputeThinV);
  const VectorX<double> weakest = svd.matrixV().col(n - 1);
  const double amount = target / (ju * weakest).cwiseAbs().maxCoeff();  // the scaled residual is max-norm
  for (Eigen::Index c = 0; c < n; ++c) q(sd.unknowns[static_cast<std::size_t>(c)]) += amount * weakest(c) * sd.col_scale(c);
}

BOOST_AUTO_TEST_CASE(newton_refines_a_converged_pose_whose_error_bound_is_not_yet_round_off) {
  // Newton stops at a scaled residual of 64 eps (1.4e-14). With condition kappa the unknowns are then only
  // known to kappa x 64 eps; solve_position takes one more step where that bound is above eps^(2/3) while
  // kappa x eps is below it (detail::worth_refining). four_bar_chain(128) at its assembly pose theta = 0,
  // known exactly (the fixture's guess: every rocker straight up), has condition about 1.5e4; moved along its
  // weakest direction to a residual of 1e-14, the unknowns are off by far more than round-off.
  const Fixture<double> chain = four_bar_chain<double>(128);
  VectorX<double> q = chain.guess;
  perturb_along_weakest_direction(chain, q, 1e-14);
  const double off_before = (q - chain.guess).cwiseAbs().maxCoeff();
  BOOST_TEST_REQUIRE(off_before > 1e-10);  // the case the residual tolerance alone would accept
  SolveData<double> sd(chain.mech);
  const SolveReport<double> rep = solve_position(chain.mech, q, sd);
  BOOST_TEST_REQUIRE(rep.ok());
  BOOST_TEST(rep.iterations == 1, "iterations " << rep.iterations);  // the refining step
  // Round-off limit: condition x eps = 3.3e-12.
  BOOST_TEST((q - chain.guess).cwiseAbs().maxCoeff() < 3e-12, "off by " << (q - chain.guess).cwiseAbs().maxCoeff()
                                                                        << " (before: " << off_before << ")");
  BOOST_TEST(sd.error_bound(rep.residual, rep.equations) <= tolerance<double>(2.0 / 3.0));

  // A well-conditioned mechanism pays nothing: the paper example, moved the same way, stops at once.
  const Fixture<double> paper = paper_fourbar<double>();
  SolveData<double> paper_sd(paper.mech);
  VectorX<double> p = paper.guess;
  BOOST_TEST_REQUIRE(assemble(paper.mech, p, paper_sd, paper.held).ok());
  perturb_along_weakest_direction(paper, p, 1e-14);
  const SolveReport<double> paper_rep = solve_position(paper.mech, p, paper_sd);
  BOOST_TEST_REQUIRE(paper_rep.ok());
  BOOST_TEST(paper_rep.iterations == 0);
}
