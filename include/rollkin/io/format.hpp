// The one number formatter of messages, reports and written files: printf's %g with a given number of
// significant digits (6 by default, which is also what std::ostream prints for a double).
#pragma once

#include <string>

namespace rollkin::io {

/// v with `significant_digits` significant digits in the shortest of fixed and exponent form, trailing zeros
/// dropped (printf "%.*g"): format_number(0.1 + 0.2) == "0.3", format_number(1e-7) == "1e-07",
/// format_number(2.0 / 3, 3) == "0.667"; "inf", "-inf" and "nan" for the non-finite values.
std::string format_number(double v, int significant_digits = 6);

}  // namespace rollkin::io
