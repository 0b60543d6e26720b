// Typed access to a parsed JSON document with error paths (internal to the readers under src/io/).
// Every accessor checks the value's type and throws InputError(file, JSON path, what was expected) when it
// does not fit; paths are written as in docs/scene_format.md ("pairs[2].contours[1]").
#pragma once

#include "rollkin/io/input_error.hpp"
#include "rollkin/io/format.hpp"
#include "rollkin/io/units.hpp"
#include "rollkin/se2.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace rollkin::io {

using json = nlohmann::ordered_json;

std::string join(const std::vector<std::string>& v, const std::string& sep = ", ");
/// "\"a\", \"b\"" or "(none)".
std::string quoted_list(const std::vector<std::string>& v);
/// path.key (or key at the root).
std::string child(const std::string& path, const std::string& key);
/// path[i].
std::string index(const std::string& path, std::size_t i);
/// "an object", "a number", ... for messages.
std::string kind_of(const json& j);
/// Shortest natural text of a number (as an ostream prints it).

/// The accessors, bound to the file named in messages.
class JsonAccess {
 public:
  explicit JsonAccess(std::string file) : file_(std::move(file)) {}

  const std::string& file() const { return file_; }

  [[noreturn]] void fail(const std::string& path, const std::string& message) const;

  /// Checks that j is an object with only the allowed keys.
  void object(const json& j, const std::string& path, const std::vector<std::string>& allowed) const;
  /// The value at key, or nullptr.
  static const json* get(const json& obj, const std::string& key);
  /// The value at key; a missing key is an error that says what it should hold.
  const json& require(const json& obj, const std::string& path, const std::string& key, const std::string& what) const;

  double number(const json& v, const std::string& path, const std::string& what) const;
  double number_or(const json& obj, const std::string& path, const std::string& key, double def,
                   const std::string& what) const;
  std::string string(const json& v, const std::string& path, const std::string& what) const;
  bool boolean(const json& v, const std::string& path, const std::string& what) const;
  /// An array; with size > 0, of exactly that many elements.
  const json& array(const json& v, const std::string& path, const std::string& what, std::size_t size = 0) const;
  /// A name: non-empty, without '.' (names are joined with '.' into variable and contour names).
  std::string name(const json& v, const std::string& path, const std::string& what) const;

  Vec2<double> point(const json& v, const std::string& path) const;
  std::vector<Vec2<double>> points(const json& v, const std::string& path) const;
  /// {"x", "y", "angle"}, all optional; the angle in the file's angle unit.
  SE2<double> frame(const json& v, const std::string& path, AngleUnit angle_unit) const;

 private:
  std::string file_;
};

}  // namespace rollkin::io
