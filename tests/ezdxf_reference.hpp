// What the DXF tests that compare with python3-ezdxf share: running a generator script (its standard output
// holds ezdxf's own world-coordinate points per entity), the entity each segment of a read contour belongs
// to, and the largest distance of an entity's ezdxf points from its segments.
#pragma once

#include "bezier_distance.hpp"

#include "rollkin/io/dxf/reader.hpp"

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace rollkin::testing {

/// One entity as ezdxf draws it: its label ("TYPE HANDLE[ in INSERT H ...]") and points on it.
struct RefEntity {
  std::string label;
  std::vector<Vec2<double>> points;
};

/// The standard output of `/usr/bin/python3 script args`; a test failure when it does not exit 0.
inline std::string ezdxf_script_output(const std::string& script, const std::string& args) {
  const std::string command = "/usr/bin/python3 " + script + " " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  BOOST_REQUIRE(pipe);
  std::string out;
  char buf[65536];
  for (std::size_t n; (n = fread(buf, 1, sizeof buf, pipe)) > 0;) out.append(buf, n);
  const int status = pclose(pipe);
  BOOST_REQUIRE_MESSAGE(status == 0, command + " failed (python3-ezdxf and python3-mpmath installed?): " + out.substr(0, 2000));
  return out;
}

/// The entity a segment belongs to: joint_entities names the one at its start, "A / B" at a join of two.
inline std::string owner(const io::DxfContour& c, std::size_t segment) {
  const std::string& j = c.joint_entities[segment];
  const std::size_t slash = j.find(" / ");
  return slash == std::string::npos ? j : j.substr(slash + 3);
}

/// The largest distance of e's ezdxf points from the segments of `path` (built from c) that belong to e,
/// relative to `size`; a test failure when no segment belongs to it.
inline double entity_distance(const io::DxfContour& c, const BezierPath<double>& path, const RefEntity& e, double size) {
  std::vector<std::size_t> segments;
  for (std::size_t i = 0; i < c.segments.size(); ++i)
    if (owner(c, i) == e.label) segments.push_back(i);
  BOOST_REQUIRE_MESSAGE(!segments.empty(), e.label << " has no segment in " << c.description);
  double worst = 0;
  for (const Vec2<double>& q : e.points) {
    double d = 1e300;
    for (std::size_t i : segments) d = std::min(d, distance_to_piece(path, i, q));
    worst = std::max(worst, d / size);
  }
  return worst;
}

}  // namespace rollkin::testing
