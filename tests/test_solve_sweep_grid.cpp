// The input grid of a sweep (solve/sweep_grid.hpp) is the decimal grid the user wrote (docs/scene_format.md, "Inputs
// and sweep"): value k is the double nearest to the decimal from + k step. The truth is independent of the code under
// test: the decimal text of each value written with integer arithmetic and read by strtod (correctly rounded).
#define BOOST_TEST_MODULE solve_sweep_grid
#include <boost/test/unit_test.hpp>

#include "rollkin/solve/sweep_grid.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>

using namespace rollkin;

namespace {

/// The double nearest to the decimal milli / 1000 (milli an integer), through its text.
double nearest_milli(long milli) {
  char buf[64];
  const long a = milli < 0 ? -milli : milli;
  std::snprintf(buf, sizeof buf, "%s%ld.%03ld", milli < 0 ? "-" : "", a / 1000, a % 1000);
  return std::strtod(buf, nullptr);
}

Sweep grid(double from, double to, double step) {
  Sweep s;
  s.from = from;
  s.to = to;
  s.step = step;
  return s;
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_grid_is_the_decimal_one) {
  // The example: from -50 by 0.001. The binary sum from + k step gives -49.999000000000002 for row 2
  // and, for row 1030, -48.971000000000004: not the double nearest to -48.971.
  const std::vector<double> v = sweep_values(grid(-50, -48, 0.001));
  BOOST_TEST_REQUIRE(v.size() == 2001u);
  BOOST_TEST(v[1] == -49.999);
  BOOST_TEST(v[1029] == -48.971);
  BOOST_TEST(-50 + 1029 * 0.001 != -48.971);  // what the binary grid gave
  for (long k = 0; k <= 2000; ++k) BOOST_TEST_CONTEXT("k " << k) { BOOST_TEST(v[k] == nearest_milli(-50000 + k)); }
}

BOOST_AUTO_TEST_CASE(the_options_text_is_read_as_written) {
  // The command line's text: 1e-3 and 0.001 are the same decimal; a step written with more digits than a
  // double's shortest form keeps them (0.00100000000000000002 is not 0.001 as a decimal, but its nearest
  // double is, and values far along the grid show the difference only as the decimal does).
  Sweep s = grid(-50, -48, 0.001);
  s.from_text = "-50";
  s.to_text = "-48.0";
  s.step_text = "1e-3";
  BOOST_TEST(sweep_values(s) == sweep_values(grid(-50, -48, 0.001)));
  s.from_text = "-5e1";
  s.step_text = "+0.0010";
  BOOST_TEST(sweep_values(s) == sweep_values(grid(-50, -48, 0.001)));
  // Text that is not a plain decimal (hex float): the double's shortest decimal is used.
  s.step_text = "0x1p-3";
  s.step = 0.125;
  const std::vector<double> eighths = sweep_values(s);
  BOOST_TEST_REQUIRE(eighths.size() == 17u);
  BOOST_TEST(eighths[3] == -49.625);
}

BOOST_AUTO_TEST_CASE(ends_and_directions) {
  // Downward, `to` included when on the grid; 0.1 steps from 0 to 1 (the binary sum gives 0.30000000000000004).
  const std::vector<double> down = sweep_values(grid(1, 0, -0.1));
  BOOST_TEST_REQUIRE(down.size() == 11u);
  BOOST_TEST(down[7] == 0.3);
  BOOST_TEST(down[10] == 0.0);
  const std::vector<double> up = sweep_values(grid(0, 1, 0.1));
  BOOST_TEST_REQUIRE(up.size() == 11u);
  BOOST_TEST(up[3] == 0.3);
  BOOST_TEST(up[10] == 1.0);
  // `to` off the grid: the last value is the last grid point before it.
  const std::vector<double> off = sweep_values(grid(0, 1.05, 0.1));
  BOOST_TEST(off.size() == 11u);
  BOOST_TEST(off.back() == 1.0);
  // A single value.
  BOOST_TEST(sweep_values(grid(3, 3, 1)).size() == 1u);
  // Large and small magnitudes together: 1e20 + k * 0.5 (integers beyond 2^53, decimal text path).
  const std::vector<double> big = sweep_values(grid(1e20, 1e20 + 1e6, 0.5e6));
  BOOST_TEST_REQUIRE(big.size() == 3u);
  BOOST_TEST(big[1] == std::strtod("100000000000000500000", nullptr));
  // Magnitudes too far apart for a common power of ten: the binary grid (still from, from + step, ...).
  const std::vector<double> apart = sweep_values(grid(1e300, 1e300, 1e-300));
  BOOST_TEST(apart.size() == 1u);
  BOOST_TEST(apart[0] == 1e300);
}

BOOST_AUTO_TEST_CASE(internal_units_scale_the_file_values) {
  Sweep s = grid(-50, -48, 0.001);
  s.unit = 3.141592653589793 / 180;
  const std::vector<double> in = sweep_inputs(s), file = sweep_values(s);
  BOOST_TEST_REQUIRE(in.size() == file.size());
  for (std::size_t k = 0; k < in.size(); ++k) BOOST_TEST(in[k] == file[k] * s.unit);
}

BOOST_AUTO_TEST_CASE(bad_sweeps_are_refused) {
  BOOST_CHECK_THROW(sweep_values(grid(0, 1, 0)), std::invalid_argument);
  BOOST_CHECK_THROW(sweep_values(grid(0, 1, -0.1)), std::invalid_argument);
  // More values than the grid counts exactly (9e15); how many a run may ask for is max_steps' (io/work_bound.hpp).
  BOOST_CHECK_THROW(sweep_values(grid(0, 1, 1e-16)), std::invalid_argument);
  BOOST_TEST(check_sweep(grid(0, 1, 1e-8)).empty());  // 1e8 values: no hidden cap of 1e7 any more
}
