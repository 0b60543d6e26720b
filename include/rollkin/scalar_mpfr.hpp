// Boost.Multiprecision MPFR as a first-class rollkin scalar (see scalar.hpp for the rules templates follow).
//
//   rollkin::mpfr50            50 decimal digits, expression templates off
//   rollkin::mpfr_scalar<D>    D decimal digits, expression templates off
//
// Expression templates are off on purpose: Eigen and the scalar-generic code in rollkin store intermediate
// results in `auto` and `S` variables, which with expression templates would hold dangling references.
//
// Eigen integration comes from <boost/multiprecision/eigen.hpp> (NumTraits, ScalarBinaryOpTraits with the
// built-in arithmetic types). Boost 1.74's generic NumTraits::lowest() returns numeric_limits::min() (the
// smallest *positive* value), which breaks e.g. Eigen::AlignedBox::setEmpty(); the more specialised
// NumTraits below fixes that for the MPFR backends and keeps everything else identical.
// Checked with Eigen 3.4 (tests/test_scalar_mpfr.cpp): PartialPivLU, ColPivHouseholderQR,
// CompleteOrthogonalDecomposition and JacobiSVD compile and solve to working precision.
//
// Include this header, not <boost/multiprecision/eigen.hpp> alone, wherever MPFR numbers meet Eigen, so that
// every translation unit sees the same NumTraits (one definition rule).
//
// Linking: MPFR and GMP (the rollkin::rollkin target carries them in its link interface).
#pragma once

#include <boost/multiprecision/eigen.hpp>
#include <boost/multiprecision/mpfr.hpp>

#include <Eigen/Core>

#include <limits>

#include "rollkin/scalar.hpp"

namespace rollkin {

/// MPFR float with a fixed number of decimal digits and no expression templates.
template <unsigned Digits10>
using mpfr_scalar = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<Digits10>,
                                                  boost::multiprecision::et_off>;

/// The project's high-precision reference scalar: 50 decimal digits.
using mpfr50 = mpfr_scalar<50>;

}  // namespace rollkin

namespace Eigen {

/// NumTraits for fixed-precision MPFR numbers (more specialised than Boost's generic one).
template <unsigned Digits10, boost::multiprecision::mpfr_allocation_type Alloc,
          boost::multiprecision::expression_template_option ET>
struct NumTraits<boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<Digits10, Alloc>, ET>>
    : GenericNumTraits<boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<Digits10, Alloc>, ET>> {
  using self_type = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<Digits10, Alloc>, ET>;
  using Real = self_type;
  using NonInteger = self_type;
  using Literal = double;
  using Nested = self_type;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 1,
    AddCost = 4,
    MulCost = 8
  };
  static Real epsilon() { return std::numeric_limits<Real>::epsilon(); }
  static Real dummy_precision() { return Real(1000) * epsilon(); }
  static Real highest() { return (std::numeric_limits<Real>::max)(); }
  static Real lowest() { return -(std::numeric_limits<Real>::max)(); }
  static int digits10() { return std::numeric_limits<Real>::digits10; }
  static int digits() { return std::numeric_limits<Real>::digits; }
  static Real infinity() { return std::numeric_limits<Real>::infinity(); }
  static Real quiet_NaN() { return std::numeric_limits<Real>::quiet_NaN(); }
};

}  // namespace Eigen
