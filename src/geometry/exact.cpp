// Exact predicates and exact tables (geometry/exact.hpp) in CGAL::Simple_cartesian over GMP rationals
// (Boost.Multiprecision mpq_rational): every double converts to it exactly, and +, -, * stay exact.
#include "rollkin/geometry/exact.hpp"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost_mp.h>

#include <boost/multiprecision/gmp.hpp>

#include <algorithm>

namespace rollkin::geometry {
namespace {

using Rational = boost::multiprecision::mpq_rational;
using Integer = boost::multiprecision::mpz_int;
using ExactKernel = CGAL::Simple_cartesian<Rational>;
using ExactPoint = ExactKernel::Point_2;

ExactPoint exact(const Vec2<double>& v) { return ExactPoint(Rational(v.x()), Rational(v.y())); }

/// Removes every factor `f` from `d`; returns how many there were.
unsigned strip_factor(Integer& d, unsigned f) {
  unsigned k = 0;
  while (d % f == 0) {
    d /= f;
    ++k;
  }
  return k;
}

/// n / (2^a 5^b) = n 2^(k-a) 5^(k-b) / 10^k with k = max(a, b): digits of the numerator, point k places
/// from the right. Denominators with other prime factors (not produced from doubles by +, -, *) are
/// written as a fraction "n/d".
std::string decimal(const Rational& q) {
  const Integer num = boost::multiprecision::numerator(q);
  Integer rest = boost::multiprecision::denominator(q);
  const unsigned twos = strip_factor(rest, 2), fives = strip_factor(rest, 5);
  if (rest != 1) return num.str() + "/" + boost::multiprecision::denominator(q).str();
  const unsigned k = std::max(twos, fives);
  const Integer scaled = abs(num) * boost::multiprecision::pow(Integer(2), k - twos) *
                         boost::multiprecision::pow(Integer(5), k - fives);
  std::string digits = scaled.str();
  if (digits.size() <= k) digits.insert(0, k + 1 - digits.size(), '0');
  std::string integer_part = digits.substr(0, digits.size() - k), fraction = digits.substr(digits.size() - k);
  fraction.erase(fraction.find_last_not_of('0') + 1);
  return (num < 0 ? "-" : "") + integer_part + (fraction.empty() ? "" : "." + fraction);
}

}  // namespace

int exact_orientation(const Vec2<double>& p, const Vec2<double>& q, const Vec2<double>& r) {
  return static_cast<int>(CGAL::orientation(exact(p), exact(q), exact(r)));
}

bool exactly_collinear(const Vec2<double>& p, const Vec2<double>& q, const Vec2<double>& r) {
  return CGAL::collinear(exact(p), exact(q), exact(r));
}

SegmentLocation locate_on_segment_exact(const Vec2<double>& p, const Vec2<double>& a, const Vec2<double>& b) {
  if (p == a) return SegmentLocation::AtStart;
  if (p == b) return SegmentLocation::AtEnd;
  const ExactPoint ep = exact(p), ea = exact(a), eb = exact(b);
  // Strictly between a and b on their line (CGAL::collinear_are_strictly_ordered_along_line).
  return CGAL::collinear(ea, ep, eb) && CGAL::collinear_are_strictly_ordered_along_line(ea, ep, eb)
             ? SegmentLocation::Inside
             : SegmentLocation::Off;
}

bool point_on_segment_exact(const Vec2<double>& p, const Vec2<double>& a, const Vec2<double>& b) {
  return locate_on_segment_exact(p, a, b) != SegmentLocation::Off;
}

PolylineLocation locate_on_polyline_exact(const Vec2<double>& p, const std::vector<Vec2<double>>& pts, bool closed) {
  using Kind = PolylineLocation::Kind;
  const std::size_t n = pts.size();
  for (std::size_t i = 0; i < n; ++i)
    if (pts[i] == p) return {Kind::AtSample, i};
  const std::size_t segments = n < 2 ? 0 : (closed ? n : n - 1);
  for (std::size_t i = 0; i < segments; ++i)
    if (locate_on_segment_exact(p, pts[i], pts[(i + 1) % n]) == SegmentLocation::Inside)
      return {Kind::InsideSegment, i};
  return {};
}

std::string exact_decimal(double x) { return decimal(Rational(x)); }

std::vector<std::string> exact_squared_chords(const std::vector<Vec2<double>>& pts, bool closed) {
  std::vector<std::string> table;
  const std::size_t n = pts.size();
  const std::size_t segments = n < 2 ? 0 : (closed ? n : n - 1);
  for (std::size_t i = 0; i < segments; ++i)
    table.push_back(decimal(CGAL::squared_distance(exact(pts[i]), exact(pts[(i + 1) % n]))));
  return table;
}

std::string exact_signed_area(const std::vector<Vec2<double>>& pts) {
  Rational twice = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Vec2<double>& p = pts[i];
    const Vec2<double>& q = pts[(i + 1) % pts.size()];
    twice += Rational(p.x()) * Rational(q.y()) - Rational(q.x()) * Rational(p.y());
  }
  return decimal(twice / 2);
}

}  // namespace rollkin::geometry
