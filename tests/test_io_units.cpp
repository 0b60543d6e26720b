#define BOOST_TEST_MODULE io_units
#include <boost/test/unit_test.hpp>

#include "rollkin/io/format.hpp"
#include "rollkin/io/units.hpp"
#include "rollkin/scalar_mpfr.hpp"

#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>

using namespace rollkin;
using io::AngleUnit;
using io::LengthUnit;

namespace {

const double kEps = std::numeric_limits<double>::epsilon();

}  // namespace

// Truth: the definitions 1 in = 25.4 mm, 1 ft = 12 in, 1 pt = 1/72 in, 1 pc = 12 pt, 1 px = 1/96 in.
BOOST_AUTO_TEST_CASE(length_factors_follow_the_unit_definitions) {
  const auto tol = boost::test_tools::tolerance(4 * kEps);
  BOOST_TEST(io::length_factor(LengthUnit::Inch, LengthUnit::Millimetre) == 25.4, tol);
  BOOST_TEST(io::length_factor(LengthUnit::Millimetre, LengthUnit::Inch) == 1 / 25.4, tol);
  BOOST_TEST(io::length_factor(LengthUnit::Foot, LengthUnit::Inch) == 12.0, tol);
  BOOST_TEST(io::length_factor(LengthUnit::Metre, LengthUnit::Centimetre) == 100.0, tol);
  BOOST_TEST(io::length_factor(LengthUnit::Centimetre, LengthUnit::Millimetre) == 10.0, tol);
  BOOST_TEST(io::length_factor(LengthUnit::Pixel, LengthUnit::Inch) == 1.0 / 96, tol);
  BOOST_TEST(io::length_factor(LengthUnit::Point, LengthUnit::Inch) == 1.0 / 72, tol);
  BOOST_TEST(io::length_factor(LengthUnit::Pica, LengthUnit::Point) == 12.0, tol);
  BOOST_TEST(io::length_factor(LengthUnit::Pixel, LengthUnit::Millimetre) == 25.4 / 96, tol);
  BOOST_TEST(io::length_factor(LengthUnit::Foot, LengthUnit::Metre) == 0.3048, tol);
  // Unitless on either side: numbers are taken as they are.
  BOOST_TEST(io::length_factor(LengthUnit::Unitless, LengthUnit::Millimetre) == 1.0);
  BOOST_TEST(io::length_factor(LengthUnit::Inch, LengthUnit::Unitless) == 1.0);
  BOOST_TEST(io::length_factor(LengthUnit::Millimetre, LengthUnit::Millimetre) == 1.0);
}

BOOST_AUTO_TEST_CASE(length_units_parse_and_name_the_accepted_spellings) {
  for (LengthUnit u : io::scene_length_units()) BOOST_TEST((io::parse_length_unit(io::unit_label(u)) == u));
  BOOST_CHECK_THROW(io::parse_length_unit("px"), std::invalid_argument);  // not a scene unit
  BOOST_TEST((io::parse_length_unit("px", {LengthUnit::Millimetre, LengthUnit::Pixel}) == LengthUnit::Pixel));
  std::string msg;
  try {
    io::parse_length_unit("MM");
  } catch (const std::invalid_argument& e) {
    msg = e.what();
  }
  BOOST_TEST(msg == "unknown length unit \"MM\"; expected one of \"m\", \"cm\", \"mm\", \"in\", \"ft\"");
  BOOST_TEST((io::parse_angle_unit("deg") == AngleUnit::Degree));
  BOOST_TEST((io::parse_angle_unit("rad") == AngleUnit::Radian));
  BOOST_CHECK_THROW(io::parse_angle_unit("grad"), std::invalid_argument);
}

// Angles against values known independently: 180 deg = pi, 90 deg = pi/2, and the MPFR constant at 50 digits.
BOOST_AUTO_TEST_CASE(angle_conversions_in_double_and_mpfr) {
  const double pi_d = 3.14159265358979323846;
  BOOST_TEST(io::to_radians(180.0, AngleUnit::Degree) == pi_d, boost::test_tools::tolerance(2 * kEps));
  BOOST_TEST(io::from_radians(pi_d / 2, AngleUnit::Degree) == 90.0, boost::test_tools::tolerance(2 * kEps));
  BOOST_TEST(io::to_radians(0.25, AngleUnit::Radian) == 0.25);
  BOOST_TEST(io::radians_per<double>(AngleUnit::Radian) == 1.0);
  using M = mpfr_scalar<50>;
  const M pi_50("3.1415926535897932384626433832795028841971693993751058");
  const M eps = std::numeric_limits<M>::epsilon();
  BOOST_TEST(abs(io::to_radians(M(180), AngleUnit::Degree) - pi_50) < 4 * eps * pi_50);
  BOOST_TEST(abs(io::from_radians(pi_50 / 4, AngleUnit::Degree) - M(45)) < 4 * eps * M(45));
  BOOST_TEST(abs(io::radians_per<M>(AngleUnit::Degree) * M(180) - pi_50) < 4 * eps * pi_50);
}

// The one number formatter (io/format.hpp) against std::ostream at the same precision (the formatting every
// message used before it): 4 to 17 significant digits, seeded random doubles over 600 orders of magnitude,
// both signs, zeros, subnormals, the extremes and the non-finite values.
BOOST_AUTO_TEST_CASE(format_number_prints_what_an_ostream_prints_at_that_precision) {
  std::mt19937_64 rng(20261125);
  std::uniform_real_distribution<double> mantissa(-10, 10);
  std::uniform_int_distribution<int> exponent(-300, 300);
  std::vector<double> values = {0.0, -0.0, 1.0, 0.1 + 0.2, 1e-7, 123456789.0, std::numeric_limits<double>::min() / 8,
                                std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest(),
                                std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                                std::numeric_limits<double>::quiet_NaN()};
  for (int i = 0; i < 2000; ++i) values.push_back(std::ldexp(mantissa(rng), exponent(rng) * 3));
  for (int digits : {4, 6, 8, 10, 12, 17})
    for (double v : values) {
      std::ostringstream os;
      os.precision(digits);
      os << v;
      BOOST_TEST(io::format_number(v, digits) == os.str(), "value " << v << ", " << digits << " digits");
    }
  BOOST_TEST(io::format_number(2.0 / 3) == "0.666667");  // 6 digits by default
  BOOST_TEST(io::format_number(1e-7) == "1e-07");
}
