// Hidden SVG elements (docs/reliability.md, "CAD readers (issue 37)"): an element with display="none"
// (attribute or style, on itself, a group, an Inkscape layer, a <use>, or the element a <use> clones) or with
// visibility="hidden"/"collapse" (inherited, overridable) is not drawn: "near", "subpath" and the only-one
// choice pass it over, `rollkin contours` marks it hidden, and only an id at or above the element that hides
// it selects it. Before, a path with display="none" was picked by "near" and a disk rolled on it, 7/7 poses ok.
//   (a) generated documents against svgelements (python3-svgelements skips display="none" as SVG does): the
//       shapes rollkin draws are svgelements' shapes, point for point;
//   (b) the contract over every way of selecting: id, near, subpath (with and without an id), the only one,
//       <use> clones, visibility, the listing's selectors read back, errors.
#define BOOST_TEST_MODULE io_svg_hidden
#include <boost/test/unit_test.hpp>

#include "test_support.hpp"

#include "rollkin/io/contour_listing.hpp"
#include "rollkin/io/svg/reader.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <random>
#include <sstream>

using rollkin::io::read_svg_shape_from_text;
using rollkin::io::read_svg_shapes_from_text;
using rollkin::io::SvgReadOptions;
using rollkin::io::SvgShape;
using rollkin::testing::contains;
using V = rollkin::Vec2<double>;
namespace fs = std::filesystem;

namespace {

std::string doc(const std::string& body) {
  return "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" "
         "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\">\n" + body + "\n</svg>\n";
}

std::string error_of(const std::string& svg, const std::string& id, const SvgReadOptions& o = {}) {
  return rollkin::testing::input_error_of([&] { read_svg_shape_from_text(svg, id, o, "drawing.svg"); });
}

SvgReadOptions near(double x, double y) {
  SvgReadOptions o;
  o.near = V(x, y);
  return o;
}

SvgReadOptions subpath(std::size_t k) {
  SvgReadOptions o;
  o.subpath = k;
  return o;
}

/// The first point of the shape read, in the file's coordinates (y down).
V start_of(const SvgShape& s) { return V(s.segments.front().points.front().x(), -s.segments.front().points.front().y()); }

// ---- (a) against svgelements ----------------------------------------------------------------------------

/// One generated document: layers (some hidden in one of the ways editors write it), shapes in them (some
/// hidden), <use> clones of earlier shapes (some hidden, some of hidden shapes). Polygons of lines only: the
/// comparison is of vertices. svgelements' limits (test_io_svg_reader.cpp) are kept out: every <use> clones
/// an element written before it, no clone of a clone, no x/y on a <use> of a group.
std::string random_document(std::mt19937_64& rng, int& shapes) {
  std::uniform_real_distribution<double> u(0, 1);
  const auto hide = [&](double p) -> std::string {
    if (u(rng) >= p) return u(rng) < 0.3 ? " style=\"display:inline\"" : "";
    const double w = u(rng);
    return w < 0.4 ? " display=\"none\"" : w < 0.8 ? " style=\"display:none\"" : " style=\"fill:red ; display : none\"";
  };
  std::ostringstream body;
  std::vector<std::string> ids;
  shapes = 0;
  const int layers = 1 + static_cast<int>(u(rng) * 4);
  for (int l = 0; l < layers; ++l) {
    body << "<g inkscape:groupmode=\"layer\" inkscape:label=\"L" << l << "\"" << hide(0.3) << ">\n";
    const int count = 1 + static_cast<int>(u(rng) * 4);
    for (int k = 0; k < count; ++k) {
      const std::string id = "s" + std::to_string(shapes++);
      const double x = 100 * u(rng), y = 100 * u(rng), w = 1 + 10 * u(rng), h = 1 + 10 * u(rng);
      const double kind = u(rng);
      body << "  ";
      if (kind < 0.3) body << "<rect id=\"" << id << "\" x=\"" << x << "\" y=\"" << y << "\" width=\"" << w << "\" height=\"" << h << "\"" << hide(0.25) << "/>\n";
      else if (kind < 0.6) body << "<polygon id=\"" << id << "\" points=\"" << x << "," << y << " " << x + w << "," << y << " " << x << "," << y + h << "\"" << hide(0.25) << "/>\n";
      else if (kind < 0.8) body << "<path id=\"" << id << "\" d=\"M " << x << " " << y << " l " << w << " " << h << " l " << -w << " 0 z\"" << hide(0.25) << "/>\n";
      else body << "<g" << hide(0.4) << "><line id=\"" << id << "\" x1=\"" << x << "\" y1=\"" << y << "\" x2=\"" << x + w << "\" y2=\"" << y + h << "\"/></g>\n";
      ids.push_back(id);
    }
    body << "</g>\n";
  }
  const int clones = static_cast<int>(u(rng) * 4);
  for (int c = 0; c < clones; ++c)
    body << "<use xlink:href=\"#" << ids[static_cast<std::size_t>(u(rng) * static_cast<double>(ids.size()))] << "\" transform=\"translate("
         << 200 + 50 * c << " 7)\"" << hide(0.25) << "/>\n";
  return doc(body.str());
}

/// svgelements' vertices of every subpath the document draws (tests/data/svg/svgelements_points.py, "*"): the
/// start of every line, in document order, one list per subpath.
std::vector<std::vector<V>> svgelements_vertices(const fs::path& file) {
  const std::string command = "/usr/bin/python3 " + std::string(ROLLKIN_SOURCE_DIR) + "/tests/data/svg/svgelements_points.py " +
                              file.string() + " '*' 96 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  BOOST_REQUIRE(pipe != nullptr);
  std::string out;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
  BOOST_REQUIRE_MESSAGE(pclose(pipe) == 0, command + " failed (python3-svgelements installed?): " + out);
  std::vector<std::vector<V>> subpaths;
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string kind;
    words >> kind;
    if (kind == "P" || kind == "M") subpaths.emplace_back();
    if (kind != "L") continue;
    double x, y;
    words >> x >> y;
    BOOST_REQUIRE(!subpaths.empty());
    subpaths.back().emplace_back(x, y);
  }
  return subpaths;
}

}  // namespace

BOOST_AUTO_TEST_CASE(generated_documents_draw_what_svgelements_draws) {
  std::mt19937_64 rng(20261128);
  const fs::path dir = rollkin::testing::scratch_dir("io_svg_hidden");
  fs::create_directories(dir);
  std::size_t drawn = 0, hidden = 0;
  for (int k = 0; k < 60; ++k) {
    int shapes = 0;
    const std::string text = random_document(rng, shapes);
    const fs::path file = dir / ("random_" + std::to_string(k) + ".svg");
    rollkin::testing::write_text(file, text);
    SvgReadOptions o;
    o.flip_y = false;
    std::vector<SvgShape> mine;
    for (SvgShape& s : read_svg_shapes_from_text(text, "", o, file.string())) {
      if (s.hidden.empty()) mine.push_back(std::move(s));
      else ++hidden;
    }
    const std::vector<std::vector<V>> ref = svgelements_vertices(file);
    BOOST_TEST_CONTEXT(file.string()) {
      BOOST_REQUIRE_EQUAL(mine.size(), ref.size());
      for (std::size_t i = 0; i < mine.size(); ++i) {
        BOOST_REQUIRE_EQUAL(mine[i].segments.size(), ref[i].size());
        for (std::size_t j = 0; j < ref[i].size(); ++j)
          BOOST_TEST((mine[i].segments[j].points.front() - ref[i][j]).norm() <= 1e-12 * (1 + ref[i][j].norm()),
                     mine[i].location << " vertex " << j);
      }
    }
    drawn += mine.size();
  }
  BOOST_TEST_MESSAGE("60 generated documents: " << drawn << " shapes drawn as svgelements draws them, " << hidden << " hidden");
  BOOST_TEST(hidden > 20u);
  BOOST_TEST(drawn > 100u);
}

// ---- (b) the contract over every way of selecting -------------------------------------------------------

// Squares of side 2 at y 0..2 (scene y -2..0): visible at x = 0 ("shown") and x = 15 ("back"), between them
// one hidden in each way; clones of a hidden path and a hidden clone of "shown"; a group of one shown and one
// hidden path.
const std::string kHidden = doc(
    "<path id=\"shown\" d=\"M 0 0 h 2 v 2 h -2 z\"/>\n"
    "<path id=\"attr\" display=\"none\" d=\"M 3 0 h 2 v 2 h -2 z\"/>\n"
    "<path id=\"css\" style=\"fill:none;display:none\" d=\"M 6 0 h 2 v 2 h -2 z\"/>\n"
    "<g id=\"layer\" inkscape:groupmode=\"layer\" style=\"display:none\"><path d=\"M 9 0 h 2 v 2 h -2 z\"/></g>\n"
    "<g id=\"ghosts\" visibility=\"hidden\"><path id=\"vis\" d=\"M 12 0 h 2 v 2 h -2 z\"/>"
    "<path id=\"back\" visibility=\"visible\" d=\"M 15 0 h 2 v 2 h -2 z\"/></g>\n"
    "<use id=\"clone_of_hidden\" xlink:href=\"#attr\" transform=\"translate(0 10)\"/>\n"
    "<use id=\"hidden_clone\" display=\"none\" xlink:href=\"#shown\" transform=\"translate(0 20)\"/>\n"
    "<g id=\"mixed\"><path id=\"m1\" d=\"M 0 30 h 1 v 1 z\"/><path id=\"m2\" style=\"display: none !important\" d=\"M 5 30 h 1 v 1 z\"/></g>\n");

BOOST_AUTO_TEST_CASE(near_passes_over_hidden_elements) {
  // Every point is nearer to a hidden square than to a shown one; near picks the nearer shown one.
  for (const double x : {2.5, 4.0, 7.0, 8.0, 9.5, 10.0, 12.5, 13.0, 14.5}) {
    const SvgShape s = read_svg_shape_from_text(kHidden, "", near(x, -1));
    BOOST_TEST(s.hidden.empty());
    BOOST_TEST(s.id == (x < 8.5 ? "shown" : "back"), "near x = " << x << " picked " << s.location);
  }
  // through a group: the shown member, however near the hidden one
  BOOST_TEST(read_svg_shape_from_text(kHidden, "mixed", near(5.5, -30.5)).id == "m1");
  // under a group named by id, an element it hides itself is shown (the id names the group)
  BOOST_TEST(read_svg_shape_from_text(kHidden, "ghosts", near(12.5, -1)).id == "vis");
}

BOOST_AUTO_TEST_CASE(subpath_and_the_only_one_count_what_is_drawn) {
  // the document draws shown, back, m1 (in that order): hidden ones take no number
  BOOST_TEST(read_svg_shape_from_text(kHidden, "", subpath(2)).id == "back");
  BOOST_TEST(read_svg_shape_from_text(kHidden, "", subpath(3)).id == "m1");
  BOOST_TEST(contains(error_of(kHidden, "", subpath(4)), "subpath 4 does not exist (subpaths count from 1): the document draws 3 subpath(s)"));
  // "mixed" draws one shape: no choice needed; "ghosts" named by id draws both of its paths
  BOOST_TEST(read_svg_shape_from_text(kHidden, "mixed").id == "m1");
  BOOST_TEST(read_svg_shape_from_text(kHidden, "ghosts", subpath(1)).id == "vis");
  BOOST_TEST(read_svg_shape_from_text(kHidden, "ghosts", subpath(2)).id == "back");
}

BOOST_AUTO_TEST_CASE(an_id_selects_a_hidden_element) {
  for (const char* id : {"attr", "css", "vis", "m2"}) {
    const SvgShape s = read_svg_shape_from_text(kHidden, id);
    BOOST_TEST(s.id == id);
    BOOST_TEST(s.hidden.empty());
  }
  BOOST_TEST(start_of(read_svg_shape_from_text(kHidden, "layer")) == V(9, 0));  // the hidden layer, by its id
  BOOST_TEST(start_of(read_svg_shape_from_text(kHidden, "hidden_clone")) == V(0, 20));  // the hidden <use>, by its id
  // a clone of a hidden element is hidden inside the clone: no id of the clone shows it
  const std::string m = error_of(kHidden, "clone_of_hidden");
  BOOST_TEST(contains(m, "the element draws 1 subpath(s), every one hidden: line 4, path \"attr\" (drawn by line 8, use "
                         "\"clone_of_hidden\") (display=\"none\" on line 4, path \"attr\")"));
  // visibility set back to visible inside a hidden group, and a symbol's visibility
  const std::string symbols = doc(
      "<symbol id=\"sym\" visibility=\"hidden\"><path id=\"inner\" d=\"M 0 0 h 1 v 1 z\"/></symbol>\n"
      "<use id=\"u\" xlink:href=\"#sym\"/>\n"
      "<g visibility=\"collapse\"><g visibility=\"inherit\"><rect id=\"r\" visibility=\"visible\" x=\"5\" y=\"0\" width=\"1\" height=\"1\"/></g></g>\n");
  const std::vector<SvgShape> all = read_svg_shapes_from_text(symbols, "");
  BOOST_REQUIRE_EQUAL(all.size(), 2u);
  BOOST_TEST(all[0].hidden == "visibility=\"hidden\" on line 3, symbol \"sym\"");
  BOOST_TEST(all[1].hidden.empty());
  BOOST_TEST(read_svg_shape_from_text(symbols, "", near(0.5, -0.5)).id == "r");
}

BOOST_AUTO_TEST_CASE(the_listing_marks_hidden_elements_and_its_selectors_read_back) {
  const fs::path file = rollkin::testing::scratch_dir("io_svg_hidden") / "hidden.svg";
  fs::create_directories(file.parent_path());
  rollkin::testing::write_text(file, kHidden);
  const std::vector<rollkin::io::ListedChain> listed = rollkin::io::list_svg_contours(file.string());
  BOOST_REQUIRE_EQUAL(listed.size(), 10u);
  const std::vector<bool> hidden{false, true, true, true, true, false, true, true, false, true};
  const std::vector<std::string> by{"shown", "attr", "css", "layer", "vis", "back", "", "hidden_clone", "m1", "m2"};
  for (std::size_t k = 0; k < listed.size(); ++k) {
    const rollkin::io::ListedChain& c = listed[k];
    BOOST_TEST_CONTEXT(k << ": " << c.group) {
      BOOST_TEST(c.hidden.empty() == !hidden[k]);
      if (c.selector.empty()) {
        BOOST_TEST(by[k].empty());
        BOOST_TEST(contains(c.no_selector, "it is hidden (display=\"none\" on line 4, path \"attr\")"));
        continue;
      }
      const nlohmann::json j = nlohmann::json::parse(c.selector);
      BOOST_TEST(j.value("path", std::string()) == by[k]);
      SvgReadOptions o;
      if (j.contains("subpath")) o.subpath = j["subpath"].get<std::size_t>();
      const SvgShape s = rollkin::io::read_svg_shape(file.string(), j.value("path", std::string()), o);
      BOOST_TEST(s.hidden.empty());
      BOOST_TEST(s.segments.size() == c.segments.size());
      BOOST_TEST(s.segments.front().points.front() == c.segments.front().points.front());
    }
  }
  // the JSON listing: hidden, and null with a reason where there is no selector
  const nlohmann::json all = nlohmann::json::parse(rollkin::io::contours_json(listed));
  BOOST_TEST(all[1]["hidden"] == "display=\"none\" on line 4, path \"attr\"");
  BOOST_TEST(all[6]["selector"].is_null());
  BOOST_TEST(contains(all[6]["no_selector"].get<std::string>(), "give it an id"));
  BOOST_TEST(!all[0].contains("hidden"));
}

BOOST_AUTO_TEST_CASE(what_rollkin_cannot_apply_is_an_error) {
  const std::string sheet = doc("<style>.h { display: none }</style><path id=\"p\" class=\"h\" d=\"M 0 0 h 1 v 1 z\"/>");
  BOOST_TEST(contains(error_of(sheet, "p"), "the document's <style> sheet sets \"display: none\", which rollkin does not apply"));
  const std::string shown = doc("<style>path { visibility: visible }</style><path id=\"p\" d=\"M 0 0 h 1 v 1 z\"/>");
  BOOST_TEST(contains(error_of(shown, "p"), "sets \"visibility: visible\""));
  const std::string typo = doc("<path id=\"p\" visibility=\"hiden\" d=\"M 0 0 h 1 v 1 z\"/>");
  BOOST_TEST(contains(error_of(typo, "p"), "line 3, path \"p\": has visibility=\"hiden\"; visibility is visible, hidden, collapse or inherit"));
  const std::string none = doc("<g display=\"none\"><path d=\"M 0 0 h 1 v 1 z\"/></g>");
  BOOST_TEST(contains(error_of(none, "", near(0, 0)), "the document draws 1 subpath(s), every one hidden: line 3, <path> "
                                                       "(display=\"none\" on line 3, <g>)"));
  // a sheet that hides nothing is read
  const std::string harmless = doc("<style>path { fill: none; display: inline }</style><path id=\"p\" d=\"M 0 0 h 1 v 1 z\"/>");
  BOOST_TEST(read_svg_shape_from_text(harmless, "p").segments.size() == 3u);
}
