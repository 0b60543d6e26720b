// The one number formatter of messages, reports and written files: format_number, printf's %g with a given
// number of significant digits (6 by default, which is also what std::ostream prints for a double), for text
// a person reads; format_double, the shortest text that reads back to the same double, for numbers a program
// reads again (CSV tables, point files, DXF, the coordinates a message quotes exactly).
#pragma once

#include <cstddef>
#include <string>

namespace rollkin::io {

/// v with `significant_digits` significant digits in the shortest of fixed and exponent form, trailing zeros
/// dropped (printf "%.*g"): format_number(0.1 + 0.2) == "0.3", format_number(1e-7) == "1e-07",
/// format_number(2.0 / 3, 3) == "0.667"; "inf", "-inf" and "nan" for the non-finite values.
std::string format_number(double v, int significant_digits = 6);

/// The shortest decimal text of v that reads back (strtod) to v exactly (std::to_chars); "nan", "inf",
/// "-inf" for non-finite values, "" for empty_cell(): format_double(0.1) == "0.1". append_double appends it to `out`.
std::string format_double(double v);
void append_double(std::string& out, double v);

/// The longest text format_double writes: the shortest round-trip form of a double takes at most 24 characters.
constexpr std::size_t kMaxDoubleText = 24;

/// A value that is not defined (a reaction that redundant constraints leave open, docs/forces.md): a NaN
/// with its own payload, which format_double writes as nothing (an empty CSV cell); a NaN from arithmetic stays
/// "nan" (NumPy reads both as NaN).
double empty_cell();
bool is_empty_cell(double v);

/// Writes format_double(v) at p, which must have room for kMaxDoubleText characters; returns one past its last
/// character (for writers that fill a buffer in place, io/csv.hpp).
char* put_double(char* p, double v);

}  // namespace rollkin::io
