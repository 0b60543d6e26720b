// Small helpers shared by the test executables: scratch files, reading text back, catching input errors,
// comparing link poses.
#pragma once

#include <boost/test/unit_test.hpp>

#include "rollkin/io/input_error.hpp"
#include "rollkin/se2.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace rollkin::testing {

/// A per-test scratch directory under the build tree (created if needed).
inline std::filesystem::path scratch_dir(const std::string& test) {
  const auto dir = std::filesystem::path(ROLLKIN_BINARY_DIR) / "test_output" / test;
  std::filesystem::create_directories(dir);
  return dir;
}

/// Writes `text` to `path` (creating its directory) and returns the path as a string.
inline std::string write_text(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// True if `dir` (if it exists) holds no temporary output file: no name starting with '.', which is how
/// io::OutputSet names its temporaries (".NAME.XXXXXX", made by mkstemp).
inline bool no_temporaries_in(const std::filesystem::path& dir) {
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec))
    if (e.path().filename().string().rfind('.', 0) == 0) return false;
  return true;
}

/// The message of the InputError that `f()` throws, or "" if it throws none.
template <class F> std::string input_error_of(F&& f) {
  try {
    f();
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "";
}

/// True if `s` contains `part`; otherwise logs both, so a failing check shows the message it looked at.
inline bool contains(const std::string& s, const std::string& part) {
  if (s.find(part) != std::string::npos) return true;
  BOOST_TEST_MESSAGE("\"" << s << "\" does not contain \"" << part << "\"");
  return false;
}

/// The largest difference of `links` link poses a[i] and b[i]: of the rotations' cosines and sines, and of
/// the translations over `length` (the mechanism's length scale).
inline double link_pose_difference(const SE2<double>* a, const SE2<double>* b, std::size_t links, double length) {
  double worst = 0;
  for (std::size_t i = 0; i < links; ++i)
    worst = std::max({worst, std::abs(a[i].cos_angle() - b[i].cos_angle()), std::abs(a[i].sin_angle() - b[i].sin_angle()),
                      (a[i].translation() - b[i].translation()).cwiseAbs().maxCoeff() / length});
  return worst;
}

/// |a - b| for two angles in radians, whole turns apart counted as equal.
inline double angle_gap(double a, double b) { return std::abs(std::remainder(a - b, 2 * pi<double>())); }

}  // namespace rollkin::testing
