#include "rollkin/io/point_file.hpp"

#include "rollkin/io/format.hpp"
#include "rollkin/io/input_file.hpp"
#include "rollkin/io/output_set.hpp"

#include <charconv>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <iterator>
#include <sstream>
#include <stdexcept>

namespace rollkin::io {
namespace {

bool is_separator(char c) { return c == ' ' || c == '\t' || c == ',' || c == ';' || c == '\r' || c == '\f' || c == '\v'; }

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_separator(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_separator(line[i])) ++i;
    if (i > start) fields.push_back(line.substr(start, i - start));
  }
  return fields;
}

/// The whole field as a number (a leading '+' allowed); false if it is not one. nan/inf parse as numbers
/// so that they can be reported as non-finite rather than as text.
bool parse_number(const std::string& field, double& value) {
  const char* first = field.data();
  const char* last = first + field.size();
  if (first != last && *first == '+') ++first;
  const auto [end, ec] = std::from_chars(first, last, value);
  return ec == std::errc() && end == last;
}

std::string trimmed(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t\r\f\v");
  if (a == std::string::npos) return "";
  const std::size_t b = s.find_last_not_of(" \t\r\f\v");
  return s.substr(a, b - a + 1);
}

/// A message if `text` looks like two numbers written with decimal commas ("1,5 2,25", "1,5;2,25"),
/// which the separators would otherwise split into three or four columns; "" otherwise.
std::string decimal_commas(const std::string& text) {
  bool digit_comma_digit = false;
  for (std::size_t i = 1; i + 1 < text.size(); ++i)
    digit_comma_digit = digit_comma_digit || (text[i] == ',' && std::isdigit(static_cast<unsigned char>(text[i - 1])) &&
                                              std::isdigit(static_cast<unsigned char>(text[i + 1])));
  if (!digit_comma_digit) return "";
  std::string pointed;
  std::vector<std::string> fields;  // split on blanks and ';' only, ',' read as a decimal point
  for (char c : text) pointed += c == ',' ? '.' : c == ';' ? ' ' : c;
  std::istringstream in(pointed);
  for (std::string f; in >> f;) fields.push_back(f);
  double a = 0, b = 0;
  if (fields.size() != 2 || !parse_number(fields[0], a) || !parse_number(fields[1], b)) return "";
  return "\"" + excerpt(trimmed(text)) + "\" looks like two numbers written with decimal commas; write decimal " +
         "points (\"" + fields[0] + " " + fields[1] + "\"): ',' separates the columns";
}

/// The column names of a header line's fields: quotes and case dropped, a unit in brackets after a name
/// ("x (mm)") not counted as a name of its own.
std::vector<std::string> header_names(const std::vector<std::string>& fields) {
  std::vector<std::string> names;
  for (std::string f : fields) {
    f.erase(std::remove_if(f.begin(), f.end(), [](char c) { return c == '"' || c == '\''; }), f.end());
    std::transform(f.begin(), f.end(), f.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (f.empty() || f.front() == '(' || f.front() == '[') continue;  // a unit of the previous name
    names.push_back(f);
  }
  return names;
}

/// Whether the names are x then y: "x y", "x,y", "\"X\";\"Y\"", "x_mm y_mm", "x (mm), y (mm)" (a unit in
/// brackets or after '_' allowed). For a contour anything else (e.g. "theta r": polar samples) would be read
/// as x y silently wrong, so it is refused.
bool names_x_and_y(const std::vector<std::string>& names) {
  auto names_axis = [](const std::string& f, char axis) {
    return f[0] == axis && (f.size() == 1 || f[1] == '_' || f[1] == '(' || f[1] == '[');
  };
  return names.size() == 2 && names_axis(names[0], 'x') && names_axis(names[1], 'y');
}

/// What is wrong with a header line (fields, none a number in the first place) for `columns`; "" when it is
/// a header the file may have (header_rule in point_file.hpp).
std::string header_problem(const std::vector<std::string>& fields, HeaderNames columns) {
  const std::vector<std::string> names = header_names(fields);
  if (columns == HeaderNames::XAndY)
    return names_x_and_y(names) ? "" : "does not name the columns x and y; a point file holds the coordinates x y of a planar "
                                       "contour, so a header line must name x then y (e.g. \"x,y\" or \"x_mm y_mm\")";
  double ignored = 0;
  for (const std::string& f : fields)
    if (parse_number(f, ignored)) return "mixes names and numbers; a header line names the two columns (e.g. \"theta_deg,s_mm\")";
  if (names.size() != 2)
    return "names " + std::to_string(names.size()) + " columns; the table has two (e.g. \"theta_deg,s_mm\")";
  return "";
}

class PointParser {
 public:
  PointParser(const std::string& source, double scale, HeaderNames columns) : source_(source), scale_(scale), columns_(columns) {}

  void line(std::string text, std::size_t number) {
    const std::size_t hash = text.find('#');
    if (hash != std::string::npos) text.erase(hash);
    const std::vector<std::string> fields = split_fields(text);
    if (fields.empty()) return;
    const bool first_content = !seen_content_;
    seen_content_ = true;
    double x = 0, y = 0;
    const bool x_ok = parse_number(fields[0], x);
    const auto shown = [&] { return "\"" + excerpt(trimmed(text)) + "\""; };  // for messages only
    if (first_content && !x_ok) {  // the header line
      if (const std::string why = header_problem(fields, columns_); !why.empty()) fail(number, "header " + shown() + " " + why);
      return;
    }
    const std::string expected = "expected two numbers \"x y\", got ";
    if (const std::string why = decimal_commas(text); !why.empty()) fail(number, why);
    if (!x_ok || (fields.size() > 1 && !parse_number(fields[1], y)))
      fail(number, expected + shown() + " (" + excerpt(x_ok ? fields[1] : fields[0]) + " is not a number)");
    if (fields.size() == 1) fail(number, expected + "only one number in " + shown());
    if (fields.size() > 2)
      fail(number, expected + (fields.size() == 3 ? "a third column" : std::to_string(fields.size()) + " columns") +
                       " in " + shown() + "; a point file holds the two coordinates x y of a planar contour: keep " +
                       "the x and y columns only (e.g. awk '{print $1, $2}')");
    if (!std::isfinite(x) || !std::isfinite(y)) fail(number, expected + shown() + " (not a finite number)");
    points_.emplace_back(x * scale_, y * scale_);
    lines_.push_back(number);
    last_line_ = number;
  }

  PointSamples finish(std::size_t min_points) {
    if (points_.empty())
      throw InputError(source_, "", "no points (the file is empty or holds only comments/header); expected lines \"x y\"");
    if (points_.size() < min_points)
      throw InputError(source_, std::to_string(last_line_),
                       "only " + std::to_string(points_.size()) + " point" + (points_.size() == 1 ? "" : "s") +
                           " in the file, at least " + std::to_string(min_points) + " needed");
    return PointSamples{std::move(points_), std::move(lines_)};
  }

 private:
  [[noreturn]] void fail(std::size_t line, const std::string& message) const {
    throw InputError(source_, std::to_string(line), message);
  }

  const std::string& source_;
  double scale_;
  HeaderNames columns_;
  bool seen_content_ = false;
  std::size_t last_line_ = 0;
  std::vector<Vec2<double>> points_;
  std::vector<std::size_t> lines_;
};

/// Whole-file problems that would otherwise show as a confusing message about one line: UTF-16/32 text,
/// NUL bytes, line ends that are a bare CR. Throws InputError saying which and what to do.
void check_encoding(const std::string& text, const std::string& source) {
  const auto starts = [&](const char* bom, std::size_t n) { return text.compare(0, n, bom, n) == 0; };
  const std::string save_as = "; save it as plain text (ASCII or UTF-8), e.g. iconv -f UTF-16 -t UTF-8 FILE > NEW";
  if (starts("\xFF\xFE", 2) || starts("\xFE\xFF", 2))
    throw InputError(source, "", std::string("the file is UTF-16 text (byte order mark ") +
                                     (text[0] == '\xFF' ? "FF FE" : "FE FF") + ")" + save_as);
  const std::size_t nul = text.find('\0');
  if (nul != std::string::npos) {
    const std::size_t line = 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + nul, '\n'));
    throw InputError(source, std::to_string(line), "the file holds NUL bytes (it is UTF-16/UTF-32 text or a binary file)" + save_as);
  }
  for (std::size_t cr = text.find('\r'); cr != std::string::npos; cr = text.find('\r', cr + 1))
    if (cr + 1 < text.size() && text[cr + 1] != '\n') {
      const std::size_t line = 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + cr, '\n'));
      throw InputError(source, std::to_string(line),
                       std::string("line ends are a bare CR (classic Mac OS line ends)") +
                           (line == 1 ? ", so the whole file reads as one line" : "") +
                           "; expected LF or CR LF line ends: convert them, e.g. tr '\\r' '\\n' < FILE > NEW");
    }
}

PointSamples parse_text(const std::string& text, const std::string& source, std::size_t min_points, double scale,
                        HeaderNames columns) {
  if (!std::isfinite(scale) || !(scale > 0))
    throw InputError(source, "", "scale factor must be a positive finite number, got " + std::to_string(scale));
  check_encoding(text, source);
  PointParser parser(source, scale, columns);
  std::size_t start = text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;  // UTF-8 byte order mark
  for (std::size_t number = 1; start < text.size(); ++number) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    parser.line(text.substr(start, end - start), number);
    start = end + 1;
  }
  return parser.finish(min_points);
}

}  // namespace

PointSamples read_point_samples(const std::string& path, std::size_t min_points, double scale, HeaderNames columns) {
  return parse_text(io::read_input_file(path, "the point file"), path, min_points, scale, columns);
}

PointSamples read_table_file(const std::string& path, std::size_t min_rows) {
  return read_point_samples(path, min_rows, 1.0, HeaderNames::AnyTwo);
}

std::vector<Vec2<double>> read_point_file(const std::string& path, std::size_t min_points, double scale) {
  return read_point_samples(path, min_points, scale, HeaderNames::XAndY).points;
}

std::vector<Vec2<double>> parse_point_text(const std::string& text, const std::string& source, std::size_t min_points,
                                           double scale, HeaderNames columns) {
  return parse_text(text, source, min_points, scale, columns).points;
}

// ---- writing ----------------------------------------------------------------------------------------------

PointFileText& PointFileText::comment(const std::string& text) {
  std::size_t start = 0;
  for (;;) {
    const std::size_t end = text.find('\n', start);
    const std::string_view line = std::string_view(text).substr(start, end == std::string::npos ? end : end - start);
    text_ += "# " + excerpt(line, std::string::npos) + "\n";
    if (end == std::string::npos) return *this;
    start = end + 1;
  }
}

PointFileText& PointFileText::header() {
  if (has_point_) throw std::logic_error("PointFileText::header: the header line \"x y\" must come before the first point");
  text_ += "x y\n";
  return *this;
}

PointFileText& PointFileText::point(const Vec2<double>& p) {
  if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
    throw InternalError("a point to write (" + format_double(p.x()) + ", " + format_double(p.y()) +
                        ") is not finite; a point file holds finite coordinates only");
  append_double(text_, p.x());
  text_ += ' ';
  append_double(text_, p.y());
  text_ += '\n';
  has_point_ = true;
  return *this;
}

PointFileText& PointFileText::points(const std::vector<Vec2<double>>& ps) {
  for (const Vec2<double>& p : ps) point(p);
  return *this;
}

std::string point_file_text(const std::string& what, const std::vector<Vec2<double>>& points) {
  return PointFileText().comment(what).points(points).text();
}

}  // namespace rollkin::io
