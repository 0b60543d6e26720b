// The one number formatter (include/rollkin/io/format.hpp).
#include "rollkin/io/format.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>

namespace rollkin::io {

std::string format_number(double v, int significant_digits) {
  char buf[64];  // %.*g of a double: at most 17 significant digits, sign, point and a 4-character exponent
  std::snprintf(buf, sizeof buf, "%.*g", significant_digits, v);
  return buf;
}

namespace {
/// The bits of empty_cell(): a quiet NaN whose payload spells no arithmetic result.
constexpr std::uint64_t kEmptyCellBits = 0x7ff80000e3b7c311ULL;
}  // namespace

double empty_cell() {
  double v;
  std::memcpy(&v, &kEmptyCellBits, sizeof v);
  return v;
}

bool is_empty_cell(double v) {
  std::uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  return bits == kEmptyCellBits;
}

char* put_double(char* p, double v) {
  if (std::isnan(v)) return is_empty_cell(v) ? p : std::copy_n("nan", 3, p);
  if (std::isinf(v)) return v > 0 ? std::copy_n("inf", 3, p) : std::copy_n("-inf", 4, p);
  return std::to_chars(p, p + kMaxDoubleText, v).ptr;
}

void append_double(std::string& out, double v) {
  char buf[kMaxDoubleText];
  out.append(buf, put_double(buf, v));
}

std::string format_double(double v) {
  std::string out;
  append_double(out, v);
  return out;
}

}  // namespace rollkin::io
