// DXF drawings as CAD programs write them (io/dxf/reader.hpp), against ezdxf: tests/data/dxf/ezdxf_cad.py writes
// drawings with several chains on one layer (entities out of order and reversed, extrusion -Z, an ELLIPSE with
// axis ratio > 1, a SPLINE with repeated control points, a zero-length LINE, a periodic SPLINE with n + 1
// knots, a TEXT, a VIEWPORT and a MULTILEADER, text after EOF) and INSERTs (rotation, negative and
// non-uniform scale, a base point, extrusion -Z, nesting, a MINSERT array), and prints ezdxf's world points on
// the entities of the chain each selector ("near", "handles", "layer") must pick. Every chain read by rollkin
// must consist of the same entities (as rollkin names them), be closed or open alike, and pass within 1e-12
// of the chain's size of every ezdxf point (to the segments of the entity the point belongs to). Selections
// that must be refused must name what the generator lists. Plus minimal texts: group 90 on a VIEWPORT and a
// MULTILEADER, text after EOF, extrusion 0.9999999999999998, a SPLINE normal (0, 0, 0), a near tie, a branch.
#define BOOST_TEST_MODULE io_dxf_cad
#include <boost/test/unit_test.hpp>

#include "ezdxf_reference.hpp"
#include "test_support.hpp"

#include "rollkin/io/contour_listing.hpp"
#include "rollkin/io/dxf/reader.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using rollkin::BezierPath;
using rollkin::io::DxfContour;
using rollkin::io::DxfSelection;
using rollkin::testing::contains;
using rollkin::testing::input_error_of;
using V = rollkin::Vec2<double>;

namespace {

const std::string kScript = std::string(ROLLKIN_SOURCE_DIR) + "/tests/data/dxf/ezdxf_cad.py";

using rollkin::testing::RefEntity;
struct RefCase {
  std::string file;
  DxfSelection selection;
  std::string select_text;
  bool closed = false;
  std::vector<RefEntity> entities;
  std::vector<std::string> errors;
};

DxfSelection parse_selection(const std::string& text) {
  std::istringstream s(text);
  std::string kind;
  s >> kind;
  DxfSelection sel;
  if (kind == "layer") s >> sel.layer;
  if (kind == "handles")
    for (std::string h; s >> h;) sel.handles.push_back(h);
  if (kind == "near") {
    double x, y;
    s >> x >> y;
    sel.near = V(x, y);
    std::string key;
    if (s >> key && key == "layer") s >> sel.layer;
  }
  return sel;
}

std::vector<RefCase> ezdxf_cases(const std::string& dir) {
  const std::string args = dir;
  const std::string out = rollkin::testing::ezdxf_script_output(kScript, args);
  std::vector<RefCase> cases;
  std::istringstream in(out);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string key;
    s >> key;
    const std::string rest = line.size() > key.size() + 1 ? line.substr(key.size() + 1) : "";
    if (key == "case") {
      cases.emplace_back();
      cases.back().file = rest;
    } else if (key == "select") {
      cases.back().select_text = rest;
      cases.back().selection = parse_selection(rest);
    } else if (key == "closed") {
      cases.back().closed = rest == "1";
    } else if (key == "entity") {
      cases.back().entities.push_back({rest, {}});
    } else if (key == "error") {
      cases.back().errors.push_back(rest);
    } else if (key == "p") {
      double x, y;
      s >> x >> y;
      cases.back().entities.back().points.emplace_back(x, y);
    }
  }
  return cases;
}

double compare(const RefCase& ref) {
  const DxfContour c = rollkin::io::read_dxf_contour(ref.file, ref.selection);
  if (ref.selection.handles.size() > 1) {  // the same chain, walked alike, whatever the order of the handles
    DxfSelection reversed = ref.selection;
    std::reverse(reversed.handles.begin(), reversed.handles.end());
    const DxfContour d = rollkin::io::read_dxf_contour(ref.file, reversed);
    BOOST_TEST(d.entities == c.entities);
    BOOST_TEST((d.segments.front().points == c.segments.front().points));
  }
  std::multiset<std::string> mine(c.entities.begin(), c.entities.end()), theirs;
  for (const RefEntity& e : ref.entities) theirs.insert(e.label);
  BOOST_TEST((mine == theirs), "entities read: " << c.description);
  BOOST_TEST(c.closed == ref.closed);
  V lo = ref.entities[0].points[0], hi = lo;
  for (const RefEntity& e : ref.entities)
    for (const V& p : e.points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double size = (hi - lo).norm();
  const BezierPath<double> path(c.segments, c.closed);
  double worst = 0;
  for (const RefEntity& e : ref.entities) {
    const double entity_worst = rollkin::testing::entity_distance(c, path, e, size);
    BOOST_TEST(entity_worst < 1e-12, e.label << ": ezdxf's points up to " << entity_worst << " x size off the contour");
    worst = std::max(worst, entity_worst);
  }
  return worst;
}

std::string minimal_dxf(const std::string& entities) { return "0\nSECTION\n2\nENTITIES\n" + entities + "0\nENDSEC\n0\nEOF\n"; }
const std::string kLine = "0\nLINE\n5\n2A\n8\nL\n10\n0\n20\n0\n11\n1\n21\n0\n";

}  // namespace

BOOST_AUTO_TEST_CASE(cad_drawings_read_as_ezdxf_draws_them) {
  const std::filesystem::path dir = rollkin::testing::scratch_dir("io_dxf_cad");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::vector<RefCase> cases = ezdxf_cases(dir.string());
  BOOST_TEST(cases.size() >= 20u);
  double worst = 0;
  for (const RefCase& ref : cases) {
    BOOST_TEST_CONTEXT(std::filesystem::path(ref.file).filename().string() << " " << ref.select_text) {
      if (!ref.errors.empty()) {
        const std::string message = input_error_of([&] { rollkin::io::read_dxf_contour(ref.file, ref.selection); });
        BOOST_TEST_MESSAGE(ref.select_text << ": " << message);
        for (const std::string& e : ref.errors) BOOST_TEST(contains(message, e), "\"" << e << "\" not in: " << message);
        continue;
      }
      const double w = compare(ref);
      std::printf("%-12s %-60s %zu entities, max distance / size = %.2e\n", std::filesystem::path(ref.file).filename().c_str(),
                  ref.select_text.substr(0, 60).c_str(), ref.entities.size(), w);
      worst = std::max(worst, w);
    }
  }
  std::printf("largest distance of an ezdxf point / chain size: %.2e\n", worst);
}

BOOST_AUTO_TEST_CASE(the_zero_length_line_is_dropped_and_noted) {
  const std::string text = minimal_dxf(kLine + "0\nLINE\n5\n2B\n8\nL\n10\n1\n20\n0\n11\n1\n21\n0\n" +
                                       "0\nLINE\n5\n2C\n8\nL\n10\n1\n20\n0\n11\n1\n21\n1\n");
  const DxfContour c = rollkin::io::parse_dxf_contour(text, DxfSelection{"L", ""});
  BOOST_TEST(c.entities.size() == 2u);
  BOOST_REQUIRE(c.notes.size() == 1u);
  BOOST_TEST(c.notes[0] == "LINE 2B has zero length: dropped");
  BOOST_TEST(contains(c.description, "LINE 2B has zero length: dropped"));
  // alone, it is an error
  BOOST_TEST(contains(input_error_of([&] { rollkin::io::parse_dxf_contour(text, DxfSelection{"", "2B"}); }), "LINE 2B has zero length"));
}

// A VIEWPORT's group 90 (status flags, 557152) and a MULTILEADER's (-1056964608) are not counts: the file was
// unreadable ("group 90 count 557152 is impossible"). A malformed number in an entity the selection does not
// consider is not checked either; in a considered one it is an error naming it.
BOOST_AUTO_TEST_CASE(only_what_is_used_is_checked) {
  const std::string viewport = "0\nVIEWPORT\n5\n3F\n8\nVIEWPORTS\n90\n557152\n";
  const std::string leader = "0\nMULTILEADER\n5\n3E\n8\nL\n90\n-1056964608\n90\n2147483647\n";
  const std::string bad = "0\nLINE\n5\n50\n8\nOTHER\n10\n1,5\n20\n0\n11\n1\n21\n0\n";
  const std::string text = minimal_dxf(viewport + leader + bad + kLine);
  const DxfContour c = rollkin::io::parse_dxf_contour(text, DxfSelection{"L", ""});
  BOOST_TEST(c.entities.size() == 1u);
  BOOST_TEST(contains(input_error_of([&] { rollkin::io::parse_dxf_contour(text, DxfSelection{"OTHER", ""}); }),
                      "LINE 50: group 10 value \"1,5\" is not a decimal number"));
  // Text after 0 EOF is not DXF: ignored, whatever it is.
  const std::string tail = minimal_dxf(kLine) + "garbage\nmore garbage\n0\nLINE\n";
  BOOST_TEST(rollkin::io::parse_dxf_contour(tail, DxfSelection{"L", ""}).segments.size() == 1u);
}

BOOST_AUTO_TEST_CASE(extrusion_round_off_and_spline_normal_zero) {
  const std::string arc = "0\nARC\n5\n6A\n8\nL\n10\n0\n20\n0\n40\n1\n50\n0\n51\n90\n210\n0\n220\n0\n230\n0.9999999999999998\n";
  const DxfContour c = rollkin::io::parse_dxf_contour(minimal_dxf(arc), DxfSelection{"L", ""});
  BOOST_TEST((c.segments.front().points.front() - V(1, 0)).norm() < 1e-15);
  BOOST_TEST((c.segments.back().points.back() - V(0, 1)).norm() < 1e-15);
  // a tilted one is printed exactly, never as (0, 0, 1)
  const std::string tilted = "0\nARC\n5\n6B\n8\nL\n10\n0\n20\n0\n40\n1\n50\n0\n51\n90\n210\n1e-11\n220\n0\n230\n0.9999999999999998\n";
  BOOST_TEST(contains(input_error_of([&] { rollkin::io::parse_dxf_contour(minimal_dxf(tilted), DxfSelection{"L", ""}); }),
                      "ARC 6B has extrusion direction (1e-11, 0, 0.9999999999999998)"));
  const std::string spline = "0\nSPLINE\n5\n6C\n8\nL\n210\n0\n220\n0\n230\n0\n70\n8\n71\n1\n72\n4\n73\n2\n40\n0\n40\n0\n40\n1\n40\n1\n"
                             "10\n0\n20\n0\n30\n0\n10\n3\n20\n4\n30\n0\n";
  const DxfContour s = rollkin::io::parse_dxf_contour(minimal_dxf(spline), DxfSelection{"L", ""});
  BOOST_TEST((s.segments.back().points.back() - V(3, 4)).norm() == 0);
}

BOOST_AUTO_TEST_CASE(a_spline_that_is_only_repeated_points_names_them) {
  const std::string spline = "0\nSPLINE\n5\n6D\n8\nL\n70\n8\n71\n1\n72\n4\n73\n2\n40\n0\n40\n0\n40\n1\n40\n1\n"
                             "10\n2\n20\n3\n30\n0\n10\n2\n20\n3\n30\n0\n";
  BOOST_TEST(contains(input_error_of([&] { rollkin::io::parse_dxf_contour(minimal_dxf(spline), DxfSelection{"L", ""}); }),
                      "SPLINE 6D has zero length: every span is a single point (repeated control points 0 = 1)"));
}

BOOST_AUTO_TEST_CASE(near_ties_branches_and_selector_errors) {
  // two parallel lines, the point midway: a tie naming both
  const std::string two = kLine + "0\nLINE\n5\n2B\n8\nL\n10\n0\n20\n2\n11\n1\n21\n2\n";
  DxfSelection midway;
  midway.near = V(0.5, 1);
  const std::string tie = input_error_of([&] { rollkin::io::parse_dxf_contour(minimal_dxf(two), midway); });
  BOOST_TEST(contains(tie, "two chains pass about equally near (0.5, 1)"));
  BOOST_TEST(contains(tie, "LINE 2A"));
  BOOST_TEST(contains(tie, "LINE 2B"));
  DxfSelection nearer;
  nearer.near = V(0.5, 1.2);
  BOOST_TEST(rollkin::io::parse_dxf_contour(minimal_dxf(two), nearer).entities.front() == "LINE 2B");
  // handles of two separate chains
  DxfSelection both;
  both.handles = {"2A", "2B"};
  BOOST_TEST(contains(input_error_of([&] { rollkin::io::parse_dxf_contour(minimal_dxf(two), both); }), "form 2 chains, not one"));
  // a branch inside the selected chain names the entities meeting there
  const std::string branch = kLine + "0\nLINE\n5\n2C\n8\nL\n10\n1\n20\n0\n11\n2\n21\n0\n0\nLINE\n5\n2D\n8\nL\n10\n1\n20\n0\n11\n1\n21\n1\n";
  const std::string b = input_error_of([&] { rollkin::io::parse_dxf_contour(minimal_dxf(branch), DxfSelection{"L", ""}); });
  BOOST_TEST(contains(b, "3 entity ends meet at (1, 0): LINE 2A (end), LINE 2C (start) and LINE 2D (start)"));
  // an INSERT of a block the file does not define
  const std::string insert = "0\nINSERT\n5\n70\n8\nL\n2\nNOPE\n10\n0\n20\n0\n";
  BOOST_TEST(contains(input_error_of([&] { rollkin::io::parse_dxf_contour(minimal_dxf(insert), DxfSelection{"L", ""}); }),
                      "INSERT 70 inserts block \"NOPE\", which the BLOCKS section does not define"));
}

// Blocks nested deeper than the bound (each inserting the next) are an error, not a stack overflow.
BOOST_AUTO_TEST_CASE(insert_depth_is_bounded) {
  std::string blocks = "0\nSECTION\n2\nBLOCKS\n";
  const int depth = rollkin::io::kDxfMaxInsertDepth + 5;
  for (int i = 0; i < depth; ++i) {
    blocks += "0\nBLOCK\n8\n0\n2\nB" + std::to_string(i) + "\n70\n0\n10\n0\n20\n0\n";
    if (i + 1 < depth) blocks += "0\nINSERT\n8\n0\n2\nB" + std::to_string(i + 1) + "\n10\n0\n20\n0\n";
    else blocks += "0\nLINE\n8\n0\n10\n0\n20\n0\n11\n1\n21\n0\n";
    blocks += "0\nENDBLK\n8\n0\n";
  }
  blocks += "0\nENDSEC\n";
  const std::string text = blocks + "0\nSECTION\n2\nENTITIES\n0\nINSERT\n5\n99\n8\nL\n2\nB0\n10\n0\n20\n0\n0\nENDSEC\n0\nEOF\n";
  const std::string m = input_error_of([&] { rollkin::io::parse_dxf_contour(text, DxfSelection{"L", ""}); });
  BOOST_TEST(contains(m, "INSERTs deep; at most 32 are read"));
  BOOST_TEST(contains(m, "in INSERT 99"));
  // a MINSERT of 32767 x 32767 copies of an empty block: refused at once, not looped over
  const std::string empty = "0\nSECTION\n2\nBLOCKS\n0\nBLOCK\n8\n0\n2\nE\n70\n0\n10\n0\n20\n0\n0\nENDBLK\n8\n0\n0\nENDSEC\n";
  const std::string grid = empty + "0\nSECTION\n2\nENTITIES\n0\nINSERT\n5\n98\n8\nL\n2\nE\n10\n0\n20\n0\n70\n32767\n71\n32767\n"
                           "44\n1\n45\n1\n0\nENDSEC\n0\nEOF\n";
  BOOST_TEST(contains(input_error_of([&] { rollkin::io::parse_dxf_contour(grid, DxfSelection{"L", ""}); }),
                      "INSERT 98 places more than 1000000 entities and copies"));
}

// The listing (io/contour_listing.hpp): every chain of every layer, each with the selector that picks exactly
// it, checked by reading the selector back: the same entities, the same segments.
BOOST_AUTO_TEST_CASE(listed_chains_are_selected_by_their_selectors) {
  const std::filesystem::path dir = rollkin::testing::scratch_dir("io_dxf_cad_listing");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  ezdxf_cases(dir.string());
  std::map<std::string, int> per_layer;
  std::size_t selectable = 0, near_selectors = 0, handle_selectors = 0, unreadable = 0;
  for (const std::string name : {"layers.dxf", "blocks.dxf", "tilt.dxf"}) {
    const std::string file = (dir / name).string();
    for (const rollkin::io::ListedChain& l : rollkin::io::list_dxf_contours(file)) {
      ++per_layer[name + " " + l.group];
      BOOST_TEST_CONTEXT(name << " " << l.group << " " << (l.entities.empty() ? std::string() : l.entities.front())) {
        BOOST_TEST(!l.entities.empty());
        if (!l.unreadable.empty()) {
          ++unreadable;
          BOOST_TEST(l.segments.empty());
        }
        if (l.selector.empty()) {  // every chain no selector picks says why
          BOOST_TEST(!l.no_selector.empty());
          continue;
        }
        ++selectable;
        const nlohmann::json j = nlohmann::json::parse(l.selector);
        BOOST_TEST(j.at("type") == "dxf");
        BOOST_TEST(j.at("file") == file);  // the path as given
        DxfSelection sel;
        if (j.contains("layer")) sel.layer = j.at("layer").get<std::string>();
        if (j.contains("near")) sel.near = V(j.at("near")[0].get<double>(), j.at("near")[1].get<double>()), ++near_selectors;
        if (j.contains("handles")) sel.handles = j.at("handles").get<std::vector<std::string>>(), ++handle_selectors;
        const DxfContour c = rollkin::io::read_dxf_contour(file, sel);
        BOOST_TEST(c.entities == l.entities, l.selector << " selects " << c.description);
        BOOST_REQUIRE(c.segments.size() == l.segments.size());
        for (std::size_t i = 0; i < c.segments.size(); ++i) BOOST_TEST((c.segments[i].points == l.segments[i].points));
        BOOST_TEST(c.closed == l.closed);
        BOOST_TEST(c.corners.size() == l.corners);
      }
    }
  }
  BOOST_TEST(per_layer["layers.dxf 0"] == 5);
  BOOST_TEST(per_layer["blocks.dxf GRID"] == 6);
  BOOST_TEST(per_layer["blocks.dxf LOOP"] == 1);  // the self-inserting block: listed with why, no selector
  BOOST_TEST(near_selectors == 11u);              // 5 on layer 0, 6 on GRID
  BOOST_TEST(handle_selectors == 1u);             // the LINE beside the unreadable tilted ARC
  BOOST_TEST(per_layer["tilt.dxf TILT"] == 2);    // the LINE, and the tilted ARC listed with why
  BOOST_TEST(unreadable == 7u);  // no chain: the self-inserting block and the 6 tilted entities of tilt.dxf
  std::printf("listing: %zu selectable chains (%zu by near, %zu by handles)\n", selectable, near_selectors, handle_selectors);
  // the CIRCLE (extrusion -Z, radius 15 around (100, -80)): its length and box
  for (const rollkin::io::ListedChain& l : rollkin::io::list_dxf_contours((dir / "layers.dxf").string()))
    if (l.entities.size() == 1 && l.entities[0].rfind("CIRCLE", 0) == 0) {
      BOOST_TEST(std::abs(l.length - 2 * M_PI * 15) <= 1e-12 * 2 * M_PI * 15);
      BOOST_TEST((l.min - V(85, -95)).norm() < 1e-12 * 30);  // the box's extremes are sampled points
      BOOST_TEST((l.max - V(115, -65)).norm() < 1e-12 * 30);
      BOOST_TEST(l.closed);
      BOOST_TEST(l.corners == 0u);
    }
}
