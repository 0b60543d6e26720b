// Loading is linear in the input's size, n log n at most (docs/reliability.md, "Input files are regular files,
// read in time linear in their size"): a scene whose input is 4n long loads in at most 5 times the time of
// one n long, for every reader: point files, SVG path data (smooth and all corners), SVG nested groups, DXF
// LWPOLYLINE, SPLINE and chains of LINE entities, inline NURBS, the scene's JSON itself (links and pairs), and
// the synthesis specs' law tables, segment lists and gear tables (with the law's continuity check); likewise
// the listing of a drawing's contours (io/contour_listing.hpp): a DXF MINSERT array of copies, a MINSERT column
// (every end at one x), an SVG document of many shapes.
// Before, a 16,000-point NURBS or DXF SPLINE took 11.6 CPU s (knot insertion over the whole control polygon
// for every knot, multiplicities counted over the whole knot vector), an SVG element under 10^5 nested groups
// 26 CPU s (a location text, counting lines from the file's start, built for every ancestor), and a scene of
// 10^4 four-bar loops 6.8 s (links and pairs looked up by name in lists, the spanning tree scanning every
// pair for every link): 16 times the cost for 4 times the input. `rollkin contours` on a 1 kB DXF with a
// 300 x 300 MINSERT took 26 s (every chain's "near" point checked against every other chain).
//
// The cost is the thread's CPU time, the least of seven loads, the small and the large input in turn (other
// processes only ever add to it), and only a ratio within one run is asserted, never a time. A linear load
// costs 4 times for 4 times the input, an n log n one 4.5 (n = 4000: 4 (1 + log 4 / log n)); allocation,
// page faults and caches add a little; a quadratic load costs 16 times. A ratio above 5 is measured again,
// up to three times in all, and the least one counts: noise does not repeat, a superlinear reader does.
#define BOOST_TEST_MODULE io_load_complexity
#include <boost/test/unit_test.hpp>

#include "test_support.hpp"

#include "rollkin/io/json/document.hpp"
#include "rollkin/io/contour_listing.hpp"
#include "rollkin/io/scene/reader.hpp"
#include "rollkin/synthesis/cam.hpp"
#include "rollkin/synthesis/gears.hpp"

#include <malloc.h>
#include <time.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>

namespace fs = std::filesystem;

namespace {

double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// Reads one input: its text and the file it stands for (relative files are read beside it).
using Loader = std::function<void(const std::string& text, const std::string& file)>;

void load_scene(const std::string& text, const std::string& file) { rollkin::io::parse_scene(text, file); }

/// The least CPU time of `loads` calls of load(0) (the small input) and load(1) (the large), in turn.
std::array<double, 2> load_costs(const std::function<void(std::size_t)>& load, int loads) {
  // Memory freed by one load stays in the heap for the next (no trimming, no mmap per large block): the
  // kernel's page faults on fresh memory are not counted in each load again.
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  std::array<double, 2> best{INFINITY, INFINITY};
  for (int k = 0; k < loads; ++k)
    for (std::size_t which = 0; which < 2; ++which) {
      const double t0 = thread_cpu_seconds();
      load(which);
      best[which] = std::min(best[which], thread_cpu_seconds() - t0);
    }
  return best;
}

/// A scene whose ground link carries `contour` (read when the scene loads; no pair uses it).
std::string scene_with(const std::string& contour) {
  return R"({"links": [{"name": "frame", "ground": true, "contours": [)" + contour + R"(]}, {"name": "arm"}],
  "pairs": [{"name": "O", "type": "revolute", "links": ["frame", "arm"], "variable": "phi", "value": 0}],
  "inputs": ["O.phi"]})";
}

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

/// Checks the cost ratio of load(1) (an input 4 times as large) to load(0) (see the comment at the top).
void check_ratio(const std::string& what, std::size_t n, const std::function<void(std::size_t)>& load) {
  const double bound = 5;
  double ratio = INFINITY;
  std::array<double, 2> least{};
  for (int attempt = 0; attempt < 3 && ratio > bound; ++attempt) {
    const std::array<double, 2> t = load_costs(load, 7);
    if (t[1] / t[0] < ratio) ratio = t[1] / t[0], least = t;
  }
  BOOST_TEST_MESSAGE(what << ": n = " << n << " loads in " << least[0] << " s, 4n in " << least[1] << " s: ratio " << ratio);
  BOOST_TEST(ratio <= bound, what << ": 4 times the input costs " << ratio << " times the CPU time (n = " << n << ": "
                                  << least[0] << " s, 4n: " << least[1] << " s); at most " << bound << " expected");
}

/// Loads the inputs made by make(n) and make(4 n) (a scene, unless `load` reads them otherwise) and checks the
/// cost ratio.
void check_linear(const std::string& what, std::size_t n, const std::function<std::string(std::size_t)>& make,
                  const Loader& load = load_scene) {
  const fs::path scene_file = rollkin::testing::scratch_dir("io_load_complexity") / "scene.json";
  const std::array<std::string, 2> scenes{make(n), make(4 * n)};
  check_ratio(what, n, [&](std::size_t which) { load(scenes[which], scene_file.string()); });
}

/// Lists the contours of the drawings made by make(n) and make(4 n) (files) and checks the cost ratio; each
/// listing must hold at least n (4 n) chains.
void check_listing_linear(const std::string& what, std::size_t n, const std::function<fs::path(std::size_t)>& make) {
  const std::array<fs::path, 2> files{make(n), make(4 * n)};
  for (std::size_t which = 0; which < 2; ++which)
    BOOST_TEST(rollkin::io::list_contours(files[which].string()).size() >= (which ? 4 * n : n));
  check_ratio(what, n, [&](std::size_t which) { rollkin::io::list_contours(files[which].string()); });
}

/// n control points on a spiral, as a list of [x, y] (JSON) or the DXF groups 10/20/30.
Eigen::Vector2d spiral(std::size_t i) {
  const double t = 0.01 * static_cast<double>(i), r = 100 + 0.01 * static_cast<double>(i);
  return {r * std::cos(t), r * std::sin(t)};
}

/// Clamped uniform cubic knots for n control points.
std::vector<double> clamped_knots(std::size_t n) {
  std::vector<double> k;
  for (int i = 0; i < 4; ++i) k.push_back(0);
  for (std::size_t i = 1; i + 3 < n; ++i) k.push_back(static_cast<double>(i));
  for (int i = 0; i < 4; ++i) k.push_back(static_cast<double>(n - 3));
  return k;
}

std::string inline_nurbs(std::size_t n) {
  std::ostringstream c;
  c << R"({"name": "c", "type": "nurbs", "degree": 3, "knots": [)";
  const std::vector<double> knots = clamped_knots(n);
  for (std::size_t i = 0; i < knots.size(); ++i) c << (i ? ", " : "") << number(knots[i]);
  c << R"(], "points": [)";
  for (std::size_t i = 0; i < n; ++i) c << (i ? ", [" : "[") << number(spiral(i).x()) << ", " << number(spiral(i).y()) << "]";
  c << "]}";
  return scene_with(c.str());
}

/// A DXF file holding one cubic SPLINE with n control points on layer CAM; the scene reads it.
std::string dxf_spline(std::size_t n) {
  const fs::path file = rollkin::testing::scratch_dir("io_load_complexity") / ("spline_" + std::to_string(n) + ".dxf");
  const std::vector<double> knots = clamped_knots(n);
  std::ostringstream d;
  d << "0\nSECTION\n2\nENTITIES\n0\nSPLINE\n5\n2F\n8\nCAM\n100\nAcDbSpline\n70\n8\n71\n3\n72\n" << knots.size()
    << "\n73\n" << n << "\n74\n0\n";
  for (double k : knots) d << "40\n" << number(k) << "\n";
  for (std::size_t i = 0; i < n; ++i) d << "10\n" << number(spiral(i).x()) << "\n20\n" << number(spiral(i).y()) << "\n30\n0.0\n";
  d << "0\nENDSEC\n0\nEOF\n";
  rollkin::testing::write_text(file, d.str());
  return scene_with(R"({"name": "c", "type": "dxf", "file": ")" + file.filename().string() + R"(", "layer": "CAM"})");
}

/// An SVG path under `depth` nested groups, or a path of `segments` smooth cubic pieces (an S wave).
std::string svg_scene(const std::string& name, const std::string& svg) {
  const fs::path file = rollkin::testing::scratch_dir("io_load_complexity") / name;
  rollkin::testing::write_text(file, svg);
  return scene_with(R"({"name": "c", "type": "svg", "file": ")" + name + R"(", "path": "p"})");
}

std::string nested_groups(std::size_t depth) {
  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\">\n";
  for (std::size_t i = 0; i < depth; ++i) svg += "<g transform=\"translate(1e-3 0)\">\n";
  svg += "<path id=\"p\" d=\"M 0 0 C 10 10 20 10 30 0\"/>\n";
  for (std::size_t i = 0; i < depth; ++i) svg += "</g>\n";
  return svg_scene("nested_" + std::to_string(depth) + ".svg", svg + "</svg>\n");
}

std::string long_path(std::size_t segments) {
  std::string d = "M 0 0 C 1 1 2 1 3 0";
  for (std::size_t i = 1; i < segments; ++i) d += i % 2 ? " s 2 -1 3 0" : " s 2 1 3 0";
  return svg_scene("path_" + std::to_string(segments) + ".svg",
                   "<svg xmlns=\"http://www.w3.org/2000/svg\"><path id=\"p\" d=\"" + d + "\"/></svg>\n");
}

/// A zigzag: every joint a corner (BezierPath looked each joint up in its corners linearly: 80,000 took 11 s).
std::string zigzag_path(std::size_t segments) {
  std::string d = "M 0 0";
  for (std::size_t i = 0; i < segments; ++i) d += i % 2 ? " l 1 1" : " l 1 -1";
  return svg_scene("zigzag_" + std::to_string(segments) + ".svg",
                   "<svg xmlns=\"http://www.w3.org/2000/svg\"><path id=\"p\" d=\"" + d + "\"/></svg>\n");
}

/// n samples on an open elliptic arc (0 to 1.9 pi). The curve, not the spiral: its segments shrink as n grows,
/// so the segments whose bounding boxes meet (the candidates of the validation's crossing test, which decides
/// each one) stay a few per segment. On the spiral the turns stay 2 pi apart while its samples spread, and the
/// candidates per segment grow with n: a property of that input, not of the reader.
std::string point_file(std::size_t n) {
  const fs::path file = rollkin::testing::scratch_dir("io_load_complexity") / ("points_" + std::to_string(n) + ".txt");
  std::ostringstream text;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 1.9 * M_PI * static_cast<double>(i) / static_cast<double>(n - 1);
    text << number(100 * std::cos(t)) << " " << number(60 * std::sin(t)) << "\n";
  }
  rollkin::testing::write_text(file, text.str());
  return scene_with(R"({"name": "c", "type": "samples", "file": ")" + file.filename().string() + R"("})");
}

/// A DXF file of ENTITIES `entities` (group lines) on layer CAM; the scene reads the layer.
std::string dxf_scene(const std::string& name, const std::string& entities) {
  const fs::path file = rollkin::testing::scratch_dir("io_load_complexity") / name;
  rollkin::testing::write_text(file, "0\nSECTION\n2\nENTITIES\n" + entities + "0\nENDSEC\n0\nEOF\n");
  return scene_with(R"({"name": "c", "type": "dxf", "file": ")" + name + R"(", "layer": "CAM"})");
}

/// One LWPOLYLINE of n vertices on the spiral, every other segment a bulge arc (bulge 0.01).
std::string dxf_lwpolyline(std::size_t n) {
  std::ostringstream d;
  d << "0\nLWPOLYLINE\n5\n2F\n8\nCAM\n100\nAcDbPolyline\n90\n" << n << "\n70\n0\n";
  for (std::size_t i = 0; i < n; ++i)
    d << "10\n" << number(spiral(i).x()) << "\n20\n" << number(spiral(i).y()) << "\n42\n" << (i % 2 ? "0.01" : "0") << "\n";
  return dxf_scene("lwpolyline_" + std::to_string(n) + ".dxf", d.str());
}

/// n LINE entities joining the spiral's points, in order along the chain (as a DXF contour's entities are listed).
std::string dxf_lines(std::size_t n) {
  std::ostringstream d;
  for (std::size_t i = 0; i < n; ++i)
    d << "0\nLINE\n5\n" << std::hex << (0x100 + i) << std::dec << "\n8\nCAM\n10\n" << number(spiral(i).x()) << "\n20\n"
      << number(spiral(i).y()) << "\n30\n0\n11\n" << number(spiral(i + 1).x()) << "\n21\n" << number(spiral(i + 1).y())
      << "\n31\n0\n";
  return dxf_scene("lines_" + std::to_string(n) + ".dxf", d.str());
}

/// A scene of n four-bar loops sharing the ground and the crank (2 n + 2 links, 3 n + 1 revolutes).
std::string four_bar_ladder(std::size_t n) {
  std::ostringstream links, pairs;
  links << R"({"name": "ground", "ground": true}, {"name": "crank"})";
  pairs << R"({"name": "O", "type": "revolute", "links": ["ground", "crank"], "variable": "phi", "value": 60})";
  for (std::size_t i = 0; i < n; ++i) {
    const std::string k = std::to_string(i);
    links << R"(, {"name": "coupler)" << k << R"("}, {"name": "rocker)" << k << R"("})";
    pairs << R"(, {"name": "A)" << k << R"(", "type": "revolute", "links": ["crank", "coupler)" << k
          << R"("], "at": [{"x": 1}, {}], "variable": "a", "value": 0})"
          << R"(, {"name": "B)" << k << R"(", "type": "revolute", "links": ["coupler)" << k << R"(", "rocker)" << k
          << R"("], "at": [{"x": 3}, {"x": 3}], "variable": "b", "value": 90})"
          << R"(, {"name": "P)" << k << R"(", "type": "revolute", "links": ["ground", "rocker)" << k << R"("], "at": [{"x": )"
          << number(3 + 1e-5 * static_cast<double>(i)) << R"(}, {}], "variable": "p", "value": 90})";
  }
  return R"({"links": [)" + links.str() + R"(], "pairs": [)" + pairs.str() + R"(], "inputs": ["O.phi"]})";
}

/// A cam spec (docs/synthesis.md) with `law` as its "law": read, and its law's continuity checked at every
/// join and its stroke measured, as `synthesize cam` does before it makes the profile.
void load_cam_spec(const std::string& text, const std::string& file) {
  const rollkin::synthesis::CamSpec spec = rollkin::synthesis::cam_spec_from_document(
      rollkin::io::parse_json_document(text, file), file, fs::path(file).parent_path().string());
  spec.law->check_continuity();
}

std::string cam_spec(const std::string& law) {
  return R"({"base_radius": 40, "follower": {"motion": "translating"}, "contact": {"roller_radius": 10}, "law": )" + law + "}";
}

/// A law table of n rows starting at -90 degrees (a header line naming the columns).
std::string law_table(std::size_t n) {
  const std::string name = "law_" + std::to_string(n) + ".txt";
  std::ostringstream text;
  text << "theta_deg,s_mm\n";
  for (std::size_t i = 0; i < n; ++i) {
    const double deg = -90 + 360.0 * static_cast<double>(i) / static_cast<double>(n);
    text << number(deg) << "," << number(5 * (1 - std::cos(deg * M_PI / 180)) + 0.1 * std::sin(3 * deg * M_PI / 180)) << "\n";
  }
  rollkin::testing::write_text(rollkin::testing::scratch_dir("io_load_complexity") / name, text.str());
  return cam_spec(R"({"file": ")" + name + R"("})");
}

/// n cycloidal segments, rises and returns in turn.
std::string law_segments(std::size_t n) {
  std::ostringstream law;
  law << "[";
  for (std::size_t i = 0; i < n; ++i)
    law << (i ? ", " : "") << R"({"to": )" << number(360.0 * static_cast<double>(i + 1) / static_cast<double>(n))
        << R"(, "kind": "cycloidal", "lift": )" << (i % 2 ? "-1" : "1") << "}";
  return cam_spec(law.str() + "]");
}

/// A gear spec whose transmission is a table of n + 1 rows (phi1 from -180 degrees over one turn).
std::string gear_table(std::size_t n) {
  const std::string name = "gear_" + std::to_string(n) + ".txt";
  std::ostringstream text;
  text << "phi1 phi2\n";
  for (std::size_t i = 0; i <= n; ++i) {
    const double deg = -180 + 360.0 * static_cast<double>(i) / static_cast<double>(n);
    text << number(deg) << " " << number(deg + 20 * std::sin(deg * M_PI / 180)) << "\n";
  }
  rollkin::testing::write_text(rollkin::testing::scratch_dir("io_load_complexity") / name, text.str());
  return R"({"centre_distance": 80, "transmission": {"file": ")" + name + R"("}})";
}

void load_gear_spec(const std::string& text, const std::string& file) {
  rollkin::synthesis::gear_spec_from_document(rollkin::io::parse_json_document(text, file), file,
                                              fs::path(file).parent_path().string());
}

/// A DXF drawing of one MINSERT of a block holding one LINE of length 0.5, in `columns` x `rows` copies spaced
/// 1 apart: as many chains on layer CAM.
fs::path dxf_minsert(const std::string& name, std::size_t columns, std::size_t rows) {
  const fs::path file = rollkin::testing::scratch_dir("io_load_complexity") / name;
  std::ostringstream d;
  d << "0\nSECTION\n2\nBLOCKS\n0\nBLOCK\n8\n0\n2\nTICK\n70\n0\n10\n0\n20\n0\n"
    << "0\nLINE\n5\n20\n8\n0\n10\n0\n20\n0\n11\n0.25\n21\n0.5\n0\nENDBLK\n8\n0\n0\nENDSEC\n"
    << "0\nSECTION\n2\nENTITIES\n0\nINSERT\n5\n30\n8\nCAM\n2\nTICK\n10\n0\n20\n0\n70\n" << columns << "\n71\n" << rows
    << "\n44\n1\n45\n1\n0\nENDSEC\n0\nEOF\n";
  rollkin::testing::write_text(file, d.str());
  return file;
}

/// A MINSERT grid of about n copies (a square of side sqrt(n)).
fs::path dxf_minsert_grid(std::size_t n) {
  const auto side = static_cast<std::size_t>(std::lround(std::sqrt(static_cast<double>(n))));
  return dxf_minsert("minsert_grid_" + std::to_string(n) + ".dxf", side, side);
}

/// A MINSERT column of n copies: every LINE end at x = 0 or 0.25 (ends compared by x alone: quadratic).
fs::path dxf_minsert_column(std::size_t n) { return dxf_minsert("minsert_column_" + std::to_string(n) + ".dxf", 1, n); }

/// An SVG document of n small closed paths (triangles) in a grid, without ids: each listed with "near".
fs::path svg_many_shapes(std::size_t n) {
  const fs::path file = rollkin::testing::scratch_dir("io_load_complexity") / ("shapes_" + std::to_string(n) + ".svg");
  const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(n))));
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\">\n";
  for (std::size_t i = 0; i < n; ++i)
    svg << "<path d=\"M " << 2 * (i % side) << " " << 2 * (i / side) << " l 1 0 l 0 1 z\"/>\n";
  svg << "</svg>\n";
  rollkin::testing::write_text(file, svg.str());
  return file;
}

}  // namespace

BOOST_AUTO_TEST_CASE(synthesis_tables_and_segment_lists_load_in_linear_time) {
  // Before (issue 37): every evaluation of a law searched its segments or rows linearly and the continuity
  // check evaluates every join, 10^5 rows took 6.3 s and 10^6 about ten minutes.
  check_linear("law table", 20000, law_table, load_cam_spec);
  check_linear("law segments", 5000, law_segments, load_cam_spec);
  check_linear("gear table", 20000, gear_table, load_gear_spec);
}

BOOST_AUTO_TEST_CASE(the_listing_of_a_minsert_grid_is_n_log_n) {
  check_listing_linear("DXF MINSERT grid listing", 2500, dxf_minsert_grid);
}

BOOST_AUTO_TEST_CASE(the_listing_of_a_minsert_column_is_n_log_n) {
  check_listing_linear("DXF MINSERT column listing", 2500, dxf_minsert_column);
}

BOOST_AUTO_TEST_CASE(the_listing_of_an_svg_document_of_many_shapes_is_n_log_n) {
  check_listing_linear("SVG listing", 1000, svg_many_shapes);
}

BOOST_AUTO_TEST_CASE(an_inline_nurbs_loads_in_linear_time) { check_linear("inline NURBS", 4000, inline_nurbs); }

BOOST_AUTO_TEST_CASE(a_dxf_spline_loads_in_linear_time) { check_linear("DXF SPLINE", 4000, dxf_spline); }

BOOST_AUTO_TEST_CASE(an_svg_element_under_deeply_nested_groups_loads_in_linear_time) {
  check_linear("SVG groups nested", 20000, nested_groups);
}

BOOST_AUTO_TEST_CASE(a_long_svg_path_loads_in_linear_time) { check_linear("SVG path", 2500, long_path); }

BOOST_AUTO_TEST_CASE(a_path_of_corners_loads_in_linear_time) { check_linear("SVG zigzag", 2500, zigzag_path); }

BOOST_AUTO_TEST_CASE(a_point_file_loads_in_linear_time) { check_linear("point file", 10000, point_file); }

BOOST_AUTO_TEST_CASE(a_dxf_lwpolyline_loads_in_linear_time) { check_linear("DXF LWPOLYLINE", 5000, dxf_lwpolyline); }

BOOST_AUTO_TEST_CASE(a_chain_of_dxf_lines_loads_in_linear_time) { check_linear("DXF LINE chain", 5000, dxf_lines); }

BOOST_AUTO_TEST_CASE(a_scene_of_many_loops_loads_in_linear_time) { check_linear("scene JSON", 250, four_bar_ladder); }
