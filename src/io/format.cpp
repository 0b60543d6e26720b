// The one number formatter (include/rollkin/io/format.hpp).
#include "rollkin/io/format.hpp"

#include <cstdio>

namespace rollkin::io {

std::string format_number(double v, int significant_digits) {
  char buf[64];  // %.*g of a double: at most 17 significant digits, sign, point and a 4-character exponent
  std::snprintf(buf, sizeof buf, "%.*g", significant_digits, v);
  return buf;
}

}  // namespace rollkin::io
