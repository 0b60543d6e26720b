// The DXF reader (io/dxf/reader.hpp) against ezdxf on random valid drawings: tests/data/dxf/ezdxf_random.py writes
// seeded drawings with python3-ezdxf (lines and arcs either way, partial ellipses, LWPOLYLINEs and 2D
// POLYLINEs with bulges 0 and +-1e-18 .. 1e3, rational splines with random weights and knots, extrusion +Z
// and -Z, 1 to 4 chains on their own layers, some a closed CIRCLE, ELLIPSE or LWPOLYLINE alone, scales 1e-2
// .. 1e4; a quarter of the chains in blocks placed by INSERTs with rotation, negative and non-uniform scale,
// extrusion +-Z, some nested; ELLIPSEs with axis ratio > 1; MULTILEADERs, TEXT, VIEWPORTs, text after EOF;
// modelspace entities in random order) and prints ezdxf's own world-coordinate points on each entity (through
// INSERTs: mapped by ezdxf's Insert.matrix44()). Every chain read by rollkin must
//   - consist of the same entities in the same order (the walk from the free end of the chain's entity first
//     in the file),
//   - start where the generator says, within 1e-12 of the chain's size,
//   - pass within 1e-12 of the chain's size of every ezdxf point (to the segments of the entity the point
//     belongs to),
//   - have the length of ezdxf's points joined up, to 1e-2 (that polygon's chord error is below 1e-3): a
//     gross check that no piece is drawn twice and no arc taken the other way round;
//   - read a polyline of arcs of one circle as one arc: no joint at its inner vertices; and keep tangent arcs
//     of different circles apart (unequal radii, radii 1e-6 apart, an S of equal radii): their ezdxf points
//     lie on the drawn circles, not on one circle through the vertices (docs/reliability.md, "CAD readers
//     (issue 37)").
// Cases: ROLLKIN_DXF_CASES (default 300) drawings from seed ROLLKIN_DXF_SEED (default 1); the longer run is
// described in docs/reliability.md.
#define BOOST_TEST_MODULE io_dxf_differential
#include <boost/test/unit_test.hpp>

#include "ezdxf_reference.hpp"
#include "test_support.hpp"

#include "rollkin/io/dxf/reader.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using rollkin::BezierPath;
using rollkin::io::DxfContour;
using rollkin::io::DxfSelection;
using V = rollkin::Vec2<double>;

namespace {

const std::string kScript = std::string(ROLLKIN_SOURCE_DIR) + "/tests/data/dxf/ezdxf_random.py";

using rollkin::testing::RefEntity;
struct RefChain {
  std::string file, layer;
  std::vector<RefEntity> entities;
  std::optional<V> start;  // where the chain starts, when not at its first entity's first point
  std::vector<std::pair<std::size_t, V>> one_arc;  // (entity, inner vertex) of polylines of one circle's arcs
};

int env_or(const char* name, int fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::atoi(v) : fallback;
}

/// Runs ezdxf_random.py and parses its blocks (see the script's docstring).
std::vector<RefChain> ezdxf_chains(const std::string& dir, int seed, int count) {
  const std::string args = dir + " " + std::to_string(seed) + " " + std::to_string(count);
  const std::string out = rollkin::testing::ezdxf_script_output(kScript, args);
  std::vector<RefChain> chains;
  std::istringstream in(out);
  std::string line, file;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string key;
    s >> key;
    if (key == "case") {
      s >> file;
    } else if (key == "layer") {
      chains.push_back({file, "", {}, std::nullopt, {}});
      s >> chains.back().layer;
    } else if (key == "entity") {
      chains.back().entities.push_back({line.substr(7), {}});  // "TYPE HANDLE[ in INSERT H[ in INSERT H2]]"
    } else if (key == "start") {
      double x, y;
      s >> x >> y;
      chains.back().start = V(x, y);
    } else if (key == "onearc") {
      double x, y;
      s >> x >> y;
      chains.back().one_arc.emplace_back(chains.back().entities.size() - 1, V(x, y));
    } else if (key == "p") {
      double x, y;
      s >> x >> y;
      chains.back().entities.back().points.emplace_back(x, y);
    }
  }
  return chains;
}

struct Worst {
  double distance = 0, length = 0;
  std::string where;
  std::size_t one_arc_vertices = 0;  // inner vertices of polylines read as one arc, checked
};

/// Compares one chain; returns its largest relative distance and length difference.
void compare(const RefChain& ref, Worst& worst) {
  BOOST_TEST_CONTEXT(ref.file << " layer " << ref.layer) {
    const DxfContour c = rollkin::io::read_dxf_contour(ref.file, DxfSelection{ref.layer, ""});
    BOOST_REQUIRE_EQUAL(c.entities.size(), ref.entities.size());
    V lo = ref.entities[0].points[0], hi = lo;
    double polygon = 0;
    for (const RefEntity& e : ref.entities)
      for (std::size_t i = 0; i < e.points.size(); ++i) {
        lo = lo.cwiseMin(e.points[i]), hi = hi.cwiseMax(e.points[i]);
        if (i > 0) polygon += (e.points[i] - e.points[i - 1]).norm();
      }
    const double size = (hi - lo).norm();
    const BezierPath<double> path(c.segments, c.closed);
    BOOST_TEST((c.segments.front().points.front() - ref.start.value_or(ref.entities[0].points[0])).norm() <= 1e-12 * size);
    for (std::size_t k = 0; k < ref.entities.size(); ++k) {
      const RefEntity& e = ref.entities[k];
      BOOST_TEST(c.entities[k] == e.label);
      const double entity_worst = rollkin::testing::entity_distance(c, path, e, size);
      BOOST_TEST(entity_worst < 1e-12, e.label << ": ezdxf's points up to " << entity_worst << " x size off the contour");
      if (entity_worst > worst.distance) worst.distance = entity_worst, worst.where = ref.file + " " + e.label;
    }
    for (const auto& [k, vertex] : ref.one_arc) {  // no joint of the entity's segments at an inner vertex
      bool first = true;
      for (std::size_t i = 0; i < c.segments.size(); ++i) {
        if (rollkin::testing::owner(c, i) != ref.entities[k].label) continue;
        const V start = c.segments[i].points.front();
        BOOST_TEST((first || (start - vertex).norm() > 1e-9 * size),
                   ref.entities[k].label << ": arcs of one circle not read as one arc: a joint at " << vertex.x() << ", " << vertex.y());
        first = false;
      }
    }
    worst.one_arc_vertices += ref.one_arc.size();
    const double length = std::abs(path.total_length() - polygon) / path.total_length();
    BOOST_TEST(length < 1e-2, "length " << path.total_length() << ", ezdxf's polygon " << polygon);
    worst.length = std::max(worst.length, length);
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(random_ezdxf_drawings_read_as_ezdxf_draws_them) {
  const int seed = env_or("ROLLKIN_DXF_SEED", 1), count = env_or("ROLLKIN_DXF_CASES", 300);
  const std::filesystem::path dir = rollkin::testing::scratch_dir("io_dxf_differential") / ("seed_" + std::to_string(seed));
  std::filesystem::remove_all(dir);
  const std::vector<RefChain> chains = ezdxf_chains(dir.string(), seed, count);
  std::map<std::string, int> types;
  Worst worst;
  int placed = 0, backwards = 0;
  for (const RefChain& chain : chains) {
    compare(chain, worst);
    for (const RefEntity& e : chain.entities) {
      ++types[e.label.substr(0, e.label.find(' '))];
      placed += e.label.find(" in INSERT ") != std::string::npos;
    }
    backwards += chain.start.has_value();
  }
  std::printf("%d drawings (seed %d), %zu chains (%d walked from their last entity in the file):", count, seed, chains.size(), backwards);
  for (const auto& [type, n] : types) std::printf(" %d %s", n, type.c_str());
  std::printf(" (%d placed by INSERTs)", placed);
  std::printf("\nlargest distance of an ezdxf point / chain size %.2e (%s); largest length difference to ezdxf's polygon %.2e;"
              " %zu inner vertices of one-circle polylines without a joint\n",
              worst.distance, worst.where.c_str(), worst.length, worst.one_arc_vertices);
  BOOST_TEST(worst.one_arc_vertices > 0u);
  BOOST_TEST(chains.size() >= static_cast<std::size_t>(count));
}
