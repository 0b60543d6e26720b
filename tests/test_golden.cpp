// Golden reference data (tests/golden/*.csv, 50 significant digits, see tests/golden/README.md):
//  - the double solver reproduces every variable of every row to 1e-12 (radians; lengths relative to the
//    mechanism's length scale), the project's accuracy target;
//  - the MPFR reference code (rollkin/reference.hpp) still reproduces a few rows to 1e-40, so a change of
//    the solver, the contours or the fixtures that changes results shows up here.
// Regenerate (only after an intended change of the mechanisms; review the diff):
//   ROLLKIN_WRITE_GOLDEN=1 build/test_golden --run_test=write_golden_files
// This file compiles no solver in MPFR: the reference runs go through the library (src/reference.cpp).
#define BOOST_TEST_MODULE golden
#include <boost/test/unit_test.hpp>

#include "rollkin/samples/mechanisms.hpp"
#include "rollkin/io/units.hpp"
#include "rollkin/reference.hpp"
#include "rollkin/scalar_mpfr.hpp"
#include "rollkin/solve/mpfr50_instances.hpp"

#include <cstdlib>
#include <string>

using namespace rollkin;
using namespace rollkin::testing;

namespace {

const std::string golden_dir = std::string(ROLLKIN_SOURCE_DIR) + "/tests/golden/";
const std::string paper_file = golden_dir + "paper_fourbar_50digits.csv";
const std::string gears_file = golden_dir + "elliptical_gears_50digits.csv";

// Elliptical gears of the golden file: a = 2, e = 0.5, rolling; built in MPFR (exact sqrt(1 - e^2), so the
// redundant rolling row is consistent to 50 digits).
const double gears_a = 2, gears_e = 0.5;

std::vector<std::string> decimal_grid(int from, int to, int step) {
  std::vector<std::string> v;
  for (int d = from; d <= to; d += step) v.push_back(std::to_string(d));
  return v;
}
std::vector<std::string> paper_grid() { return decimal_grid(-50, 100, 5); }
std::vector<std::string> gears_grid() { return decimal_grid(-180, 540, 15); }

ReferenceSweep paper_reference(const std::vector<std::string>& inputs) {
  const auto f = paper_fourbar<double>();
  return reference_sweep_decimal(f.mech, f.guess, f.held, 0, inputs, 50);
}

ReferenceSweep gears_reference(const std::vector<std::string>& inputs) {
  const auto f = elliptical_gears<mpfr50>(mpfr50(gears_a), mpfr50(gears_e), true);
  std::vector<mpfr50> in;
  for (const auto& s : inputs) in.push_back(mpfr50(s) * pi<mpfr50>() / mpfr50(180));
  return reference_sweep_mp<mpfr50>(f.mech, f.guess, f.held, 0, in);
}

/// Double sweep at the table's inputs (degrees -> radians in double) against every variable of the table.
/// Returns the largest error in solver units (radians, lengths / length scale).
double double_vs_table(const Fixture<double>& f, const ReferenceTable& t) {
  const Mechanism<double>& m = f.mech;
  std::vector<double> inputs;
  for (const auto& row : t.rows) inputs.push_back(deg_to_rad(std::stod(row[0])));
  SolveData<double> sd(m);
  VectorX<double> q;
  const auto rep = assemble_fixture(f, q, sd);
  BOOST_TEST_REQUIRE(rep.ok());
  const auto r = sweep(m, sd, q, rep, 0, inputs);
  BOOST_TEST_REQUIRE(r.all_solved());
  double worst = 0;
  for (std::size_t k = 0; k < t.rows.size(); ++k) {
    BOOST_TEST_REQUIRE(t.rows[k][t.column("status")] == "ok");
    for (int i = 0; i < m.variable_count(); ++i) {
      const int col = t.column(m.variables[i].name);
      BOOST_TEST_REQUIRE(col >= 0, "column " << m.variables[i].name);
      const mpfr50 ref(t.rows[k][col]);
      const bool angle = m.variables[i].kind == ParamKind::Angle;
      const mpfr50 ref_solver = angle ? mpfr50(ref * pi<mpfr50>() / mpfr50(180)) : ref;
      const double err = to_double(abs(mpfr50(r.poses[k].q(i)) - ref_solver)) / m.variable_scale(i);
      worst = std::max(worst, err);
      BOOST_TEST(err < 1e-12, m.variables[i].name << " at input " << t.rows[k][0] << ": error " << err);
    }
  }
  return worst;
}

/// Rows of a fresh MPFR run against the same rows of the table, to 1e-40 (display units).
void mpfr_rerun_matches_table(const ReferenceSweep& fresh, const ReferenceTable& t, const std::vector<int>& rows,
                              const Mechanism<double>& m) {
  BOOST_TEST_REQUIRE(fresh.all_solved());
  mpfr50 worst(0);
  const mpfr50 tol("1e-40");
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const auto& row = t.rows[rows[k]];
    BOOST_TEST(mpfr50(fresh.poses[k].input) == mpfr50(row[0]));
    for (int i = 0; i < m.variable_count(); ++i) {
      const mpfr50 diff = abs(mpfr50(fresh.poses[k].q[i]) - mpfr50(row[t.column(m.variables[i].name)]));
      worst = std::max(worst, diff);
      BOOST_TEST(diff < tol, m.variables[i].name << " at input " << row[0] << ": " << diff.str(3));
    }
  }
  BOOST_TEST_MESSAGE("fresh MPFR run vs golden file: max difference " << worst.str(3));
}

}  // namespace

BOOST_AUTO_TEST_CASE(write_golden_files, *boost::unit_test::disabled()) {
  // Enabled only by --run_test=write_golden_files with ROLLKIN_WRITE_GOLDEN=1 (see the file comment).
  const char* env = std::getenv("ROLLKIN_WRITE_GOLDEN");
  BOOST_TEST_REQUIRE((env && std::string(env) == "1"), "set ROLLKIN_WRITE_GOLDEN=1 to regenerate the golden files");
  const auto paper = paper_reference(paper_grid());
  BOOST_TEST_REQUIRE(paper.all_solved());
  write_reference_csv(paper, paper_fourbar<double>().mech, paper_file);
  const auto gears = gears_reference(gears_grid());
  BOOST_TEST_REQUIRE(gears.all_solved());
  write_reference_csv(gears, elliptical_gears<double>(gears_a, gears_e, true).mech, gears_file);
}

BOOST_AUTO_TEST_CASE(paper_fourbar_double_matches_golden_to_1e_12) {
  const auto t = read_reference_csv(paper_file);
  BOOST_TEST_REQUIRE(t.rows.size() == paper_grid().size());
  const double worst = double_vs_table(paper_fourbar<double>(), t);
  BOOST_TEST_MESSAGE("paper fourbar: double vs 50-digit golden, max error " << worst << " (radians / length scale)");
}

BOOST_AUTO_TEST_CASE(elliptical_gears_double_matches_golden_to_1e_12) {
  const auto t = read_reference_csv(gears_file);
  BOOST_TEST_REQUIRE(t.rows.size() == gears_grid().size());
  const double worst = double_vs_table(elliptical_gears<double>(gears_a, gears_e, true), t);
  BOOST_TEST_MESSAGE("elliptical gears: double vs 50-digit golden, max error " << worst << " (radians)");
}

BOOST_AUTO_TEST_CASE(paper_fourbar_golden_still_matches_the_mpfr_code) {
  const auto t = read_reference_csv(paper_file);
  const std::vector<int> rows{0, 15, 30};  // -50, 25, 100 degrees
  std::vector<std::string> inputs;
  for (int r : rows) inputs.push_back(t.rows[r][0]);
  mpfr_rerun_matches_table(paper_reference(inputs), t, rows, paper_fourbar<double>().mech);
}

BOOST_AUTO_TEST_CASE(elliptical_gears_golden_still_matches_the_mpfr_code) {
  const auto t = read_reference_csv(gears_file);
  const std::vector<int> rows{0, 20, 48};  // -180, 120, 540 degrees
  std::vector<std::string> inputs;
  for (int r : rows) inputs.push_back(t.rows[r][0]);
  mpfr_rerun_matches_table(gears_reference(inputs), t, rows, elliptical_gears<double>(gears_a, gears_e, true).mech);
}

BOOST_AUTO_TEST_CASE(reference_api_rejects_bad_digits_and_reports_limits) {
  const auto f = paper_fourbar<double>();
  BOOST_CHECK_THROW(reference_sweep(f.mech, f.guess, f.held, 0, {0.0}, 40), std::invalid_argument);
  BOOST_CHECK_THROW(reference_sweep(f.mech, f.guess, f.held, 3, {0.0}, 50), std::invalid_argument);
  // 30 digits, through the double-input entry: past the dead point the pose is reported, not invented.
  const auto r = reference_sweep(f.mech, f.guess, f.held, 0, {deg_to_rad(10.0), deg_to_rad(-80.0)}, 30);
  BOOST_TEST(r.digits == 30);
  BOOST_TEST(r.assembly_status == SolveStatus::Converged);
  BOOST_TEST(r.poses[0].status == SolveStatus::Converged);
  BOOST_TEST(r.poses[0].q[1].size() >= 25u);  // x carries ~30 significant digits
  BOOST_TEST(r.poses[1].status == SolveStatus::DeadPoint);
  BOOST_TEST(r.limits.size() == 1u);
}
