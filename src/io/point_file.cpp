#include "rollkin/io/point_file.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

namespace rollkin {
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

class PointParser {
 public:
  PointParser(const std::string& source, double scale) : source_(source), scale_(scale) {}

  void line(std::string text, std::size_t number) {
    const std::size_t hash = text.find('#');
    if (hash != std::string::npos) text.erase(hash);
    const std::vector<std::string> fields = split_fields(text);
    if (fields.empty()) return;
    const bool first_content = !seen_content_;
    seen_content_ = true;
    double x = 0, y = 0;
    const bool x_ok = parse_number(fields[0], x);
    if (first_content && !x_ok) return;  // the header line
    const std::string shown = "\"" + trimmed(text) + "\"";
    const std::string expected = "expected two numbers \"x y\", got ";
    if (!x_ok || (fields.size() > 1 && !parse_number(fields[1], y)))
      fail(number, expected + shown + " (" + (x_ok ? fields[1] : fields[0]) + " is not a number)");
    if (fields.size() == 1) fail(number, expected + "only one number in " + shown);
    if (fields.size() > 2) fail(number, expected + "a third column in " + shown);
    if (!std::isfinite(x) || !std::isfinite(y)) fail(number, expected + shown + " (not a finite number)");
    points_.emplace_back(x * scale_, y * scale_);
    last_line_ = number;
  }

  std::vector<Vec2<double>> finish(std::size_t min_points) {
    if (points_.empty())
      throw InputError(source_, "", "no points (the file is empty or holds only comments/header); expected lines \"x y\"");
    if (points_.size() < min_points)
      throw InputError(source_, std::to_string(last_line_),
                       "only " + std::to_string(points_.size()) + " point" + (points_.size() == 1 ? "" : "s") +
                           " in the file, at least " + std::to_string(min_points) + " needed");
    return std::move(points_);
  }

 private:
  [[noreturn]] void fail(std::size_t line, const std::string& message) const {
    throw InputError(source_, std::to_string(line), message);
  }

  const std::string& source_;
  double scale_;
  bool seen_content_ = false;
  std::size_t last_line_ = 0;
  std::vector<Vec2<double>> points_;
};

std::vector<Vec2<double>> parse_stream(std::istream& in, const std::string& source, std::size_t min_points,
                                       double scale) {
  if (!std::isfinite(scale) || !(scale > 0))
    throw InputError(source, "", "scale factor must be a positive finite number, got " + std::to_string(scale));
  PointParser parser(source, scale);
  std::string text;
  for (std::size_t number = 1; std::getline(in, text); ++number) {
    if (number == 1 && text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);  // UTF-8 byte order mark
    parser.line(text, number);
  }
  return parser.finish(min_points);
}

}  // namespace

std::vector<Vec2<double>> read_point_file(const std::string& path, std::size_t min_points, double scale) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "", std::string("cannot open the point file: ") + std::strerror(errno));
  return parse_stream(in, path, min_points, scale);
}

std::vector<Vec2<double>> parse_point_text(const std::string& text, const std::string& source, std::size_t min_points,
                                           double scale) {
  std::istringstream in(text);
  return parse_stream(in, source, min_points, scale);
}

}  // namespace rollkin
