// Typed JSON access with error paths (see json/access.hpp).
#include "access.hpp"

#include <cmath>
#include <sstream>

namespace rollkin::io {

std::string join(const std::vector<std::string>& v, const std::string& sep) {
  std::string out;
  for (std::size_t i = 0; i < v.size(); ++i) out += (i ? sep : "") + v[i];
  return out;
}

std::string quoted_list(const std::vector<std::string>& v) {
  std::vector<std::string> q;
  for (const auto& s : v) q.push_back("\"" + s + "\"");
  return q.empty() ? "(none)" : join(q);
}

std::string child(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }
std::string index(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }

std::string kind_of(const json& j) {
  switch (j.type()) {
    case json::value_t::null: return "null";
    case json::value_t::object: return "an object";
    case json::value_t::array: return "an array";
    case json::value_t::string: return "a string";
    case json::value_t::boolean: return "a boolean";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float: return "a number";
    default: return "an unsupported value";
  }
}

void JsonAccess::fail(const std::string& path, const std::string& message) const { throw InputError(file_, path, message); }

void JsonAccess::object(const json& j, const std::string& path, const std::vector<std::string>& allowed) const {
  if (!j.is_object()) fail(path, "expected an object with keys " + quoted_list(allowed) + ", got " + kind_of(j));
  for (auto it = j.begin(); it != j.end(); ++it) {
    bool ok = false;
    for (const auto& a : allowed) ok = ok || a == it.key();
    if (!ok) fail(child(path, it.key()), "unknown key \"" + it.key() + "\"; allowed keys here: " + quoted_list(allowed));
  }
}

const json* JsonAccess::get(const json& obj, const std::string& key) {
  auto it = obj.find(key);
  return it == obj.end() ? nullptr : &*it;
}

const json& JsonAccess::require(const json& obj, const std::string& path, const std::string& key,
                                const std::string& what) const {
  const json* v = get(obj, key);
  if (!v) fail(path, "missing key \"" + key + "\" (" + what + ")");
  return *v;
}

double JsonAccess::number(const json& v, const std::string& path, const std::string& what) const {
  if (!v.is_number()) fail(path, "expected " + what + " (a number), got " + kind_of(v));
  const double x = v.get<double>();
  if (!std::isfinite(x)) fail(path, "expected " + what + " (a finite number)");
  return x;
}

double JsonAccess::number_or(const json& obj, const std::string& path, const std::string& key, double def,
                             const std::string& what) const {
  const json* v = get(obj, key);
  return v ? number(*v, child(path, key), what) : def;
}

std::string JsonAccess::string(const json& v, const std::string& path, const std::string& what) const {
  if (!v.is_string()) fail(path, "expected " + what + " (a string), got " + kind_of(v));
  return v.get<std::string>();
}

bool JsonAccess::boolean(const json& v, const std::string& path, const std::string& what) const {
  if (!v.is_boolean()) fail(path, "expected " + what + " (true or false), got " + kind_of(v));
  return v.get<bool>();
}

const json& JsonAccess::array(const json& v, const std::string& path, const std::string& what, std::size_t size) const {
  if (!v.is_array()) fail(path, "expected " + what + " (an array), got " + kind_of(v));
  if (size && v.size() != size)
    fail(path, "expected " + what + ": an array of " + std::to_string(size) + " elements, got " + std::to_string(v.size()));
  return v;
}

std::string JsonAccess::name(const json& v, const std::string& path, const std::string& what) const {
  const std::string s = string(v, path, what);
  if (s.empty()) fail(path, "expected " + what + ": a non-empty name");
  if (s.find('.') != std::string::npos)
    fail(path, "the " + what + " \"" + s + "\" contains '.'; names are joined with '.' and may not contain it");
  return s;
}

Vec2<double> JsonAccess::point(const json& v, const std::string& path) const {
  array(v, path, "a point [x, y]", 2);
  return Vec2<double>(number(v[0], index(path, 0), "x"), number(v[1], index(path, 1), "y"));
}

std::vector<Vec2<double>> JsonAccess::points(const json& v, const std::string& path) const {
  array(v, path, "a list of points [[x, y], ...]");
  std::vector<Vec2<double>> out;
  for (std::size_t i = 0; i < v.size(); ++i) out.push_back(point(v[i], index(path, i)));
  return out;
}

SE2<double> JsonAccess::frame(const json& v, const std::string& path, AngleUnit angle_unit) const {
  const bool degrees = angle_unit == AngleUnit::Degree;
  object(v, path, {"x", "y", "angle"});
  const double x = number_or(v, path, "x", 0, "an x coordinate");
  const double y = number_or(v, path, "y", 0, "a y coordinate");
  const double a = number_or(v, path, "angle", 0, std::string("an angle in ") + (degrees ? "degrees" : "radians"));
  return SE2<double>(to_radians(a, angle_unit), Vec2<double>(x, y));
}

}  // namespace rollkin::io
