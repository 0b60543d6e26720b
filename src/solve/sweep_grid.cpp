// The input grid of a sweep (see include/rollkin/solve/sweep_grid.hpp).
#include "rollkin/solve/sweep_grid.hpp"
#include "rollkin/io/format.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace rollkin {

namespace {

using Wide = __int128;

/// Largest magnitude a scaled integer may have: F + k S lies between F and the end T, two such numbers, far
/// inside the 127 bits of Wide.
const Wide kWideLimit = static_cast<Wide>(1000000000000000000LL) * 1000000000000000000LL;  // 1e36

/// A decimal number: mantissa * 10^exponent.
struct Decimal {
  Wide mantissa = 0;
  int exponent = 0;
};

/// `text` as a plain decimal ([+-]digits[.digits][(e|E)[+-]digits]); nullopt for anything else (hex
/// floats, words) or more significant digits than kWideLimit holds.
std::optional<Decimal> parse_decimal(const std::string& text) {
  std::size_t i = 0;
  const bool negative = i < text.size() && text[i] == '-';
  if (i < text.size() && (text[i] == '-' || text[i] == '+')) ++i;
  Decimal d;
  bool digits = false, point = false;
  for (; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '.' && !point) {
      point = true;
      continue;
    }
    if (c < '0' || c > '9') break;
    digits = true;
    if (d.mantissa == 0 && c == '0') {  // leading zeros carry no digit
      if (point) --d.exponent;
      continue;
    }
    if (d.mantissa >= kWideLimit) return std::nullopt;
    d.mantissa = d.mantissa * 10 + (c - '0');
    if (point) --d.exponent;
  }
  if (!digits) return std::nullopt;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    int e = 0;
    const std::from_chars_result r = std::from_chars(text.data() + i + 1 + (text[i + 1] == '+'), text.data() + text.size(), e);
    if (r.ec != std::errc() || r.ptr != text.data() + text.size()) return std::nullopt;
    d.exponent += e;
    i = text.size();
  }
  if (i != text.size() || d.exponent < -400 || d.exponent > 400) return std::nullopt;
  if (negative) d.mantissa = -d.mantissa;
  return d;
}

/// The decimal value of one of the sweep's numbers: its text when given and plain, else the shortest text
/// of the double (std::to_chars).
std::optional<Decimal> decimal_of(const std::string& text, double v) {
  if (!text.empty())
    if (const std::optional<Decimal> d = parse_decimal(text)) return d;
  char buf[32];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, v);
  return parse_decimal(std::string(buf, r.ptr));
}

/// d scaled to the power of ten `exponent` (<= d.exponent): the integer d / 10^exponent, if it fits.
std::optional<Wide> scaled(const Decimal& d, int exponent) {
  Wide m = d.mantissa;
  for (int e = d.exponent; e > exponent; --e) {
    if (m >= kWideLimit || m <= -kWideLimit) return std::nullopt;
    m *= 10;
  }
  return m;
}

/// The double nearest to n * 10^exponent (correctly rounded).
double to_double(Wide n, int exponent) {
  static const double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                  1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  const Wide exact = static_cast<Wide>(1) << 53;
  if (n == 0) return 0.0;
  if (n <= exact && n >= -exact && exponent >= -22 && exponent <= 22) {
    // n and 10^|exponent| are both exact doubles: one IEEE multiplication or division rounds correctly.
    const double x = static_cast<double>(n);
    return exponent < 0 ? x / kPow10[-exponent] : x * kPow10[exponent];
  }
  std::string text;  // otherwise the decimal text, read by strtod (correctly rounded in glibc)
  const bool negative = n < 0;
  for (Wide a = negative ? -n : n; a > 0; a /= 10) text.push_back(static_cast<char>('0' + static_cast<int>(a % 10)));
  if (negative) text.push_back('-');
  std::reverse(text.begin(), text.end());
  text += "e" + std::to_string(exponent);
  return std::strtod(text.c_str(), nullptr);
}

/// The decimal grid: start F, step S (integers of the power of ten `exponent`) and the number of steps.
struct DecimalGrid {
  Wide from = 0, step = 0;
  int exponent = 0;
  long long steps = 0;
};

/// The sweep as a decimal grid; nullopt when a number is not a plain decimal or the common power of ten
/// makes the integers too large (numbers of very different magnitudes): the binary grid is used then.
std::optional<DecimalGrid> decimal_grid(const Sweep& s) {
  const std::optional<Decimal> f = decimal_of(s.from_text, s.from), t = decimal_of(s.to_text, s.to),
                               h = decimal_of(s.step_text, s.step);
  if (!f || !t || !h) return std::nullopt;
  DecimalGrid g;
  g.exponent = std::min({f->exponent, t->exponent, h->exponent});
  const std::optional<Wide> F = scaled(*f, g.exponent), T = scaled(*t, g.exponent), H = scaled(*h, g.exponent);
  if (!F || !T || !H || *H == 0) return std::nullopt;
  g.from = *F;
  g.step = *H;
  const Wide span = *T - *F;
  if (span != 0 && (span > 0) != (*H > 0)) return std::nullopt;  // check_sweep() refused it already
  const Wide steps = span / *H, rest = span - steps * *H;
  // `to` on the grid within 1e-9 of a step (as the binary grid allowed) counts as on it.
  const long double missing = static_cast<long double>(*H - rest) / static_cast<long double>(*H);
  g.steps = static_cast<long long>(steps) + (rest != 0 && missing <= 1e-9L ? 1 : 0);
  return g;
}

}  // namespace

std::string check_sweep(const Sweep& s) {
  if (!std::isfinite(s.from) || !std::isfinite(s.to) || !std::isfinite(s.step)) return "from, to and step must be finite numbers";
  if (s.step == 0) return "step must not be zero; expected a step with the sign of to - from";
  const double span = s.to - s.from;
  // The numbers are formatted only for a message (a sweep is checked for every run of a batch).
  const auto from_to = [&] { return "from " + io::format_number(s.from) + " to " + io::format_number(s.to); };
  if (span != 0 && (span > 0) != (s.step > 0))
    return "step " + io::format_number(s.step) + " has the wrong sign for a sweep " + from_to() + "; expected " +
           io::format_number(-s.step) + " (the step is signed: it has the sign of to - from, negative for a sweep " +
           "that decreases)";
  // The grid counts its values exactly (integers below 2^53); how many values a run may ask for is the
  // bounded-work rule's (io/work_bound.hpp: at most max_steps).
  if (span / s.step > 9e15)
    return "the sweep " + from_to() + " by " + io::format_number(s.step) +
           " has more than 9e15 values, more than a sweep can count; expected a larger step";
  return "";
}

std::vector<double> sweep_values(const Sweep& s) {
  const std::string bad = check_sweep(s);
  if (!bad.empty()) throw std::invalid_argument("sweep: " + bad);
  std::vector<double> out;
  if (const std::optional<DecimalGrid> g = decimal_grid(s)) {
    out.reserve(static_cast<std::size_t>(g->steps) + 1);
    for (long long k = 0; k <= g->steps; ++k) out.push_back(to_double(g->from + g->step * k, g->exponent));
    return out;
  }
  const double n = std::floor((s.to - s.from) / s.step + 1e-9);
  out.reserve(static_cast<std::size_t>(n) + 1);
  for (long k = 0; k <= static_cast<long>(n); ++k) out.push_back(s.from + s.step * static_cast<double>(k));
  return out;
}

std::vector<double> sweep_inputs(const Sweep& s) {
  std::vector<double> out = sweep_values(s);
  for (double& v : out) v *= s.unit;
  return out;
}

}  // namespace rollkin
