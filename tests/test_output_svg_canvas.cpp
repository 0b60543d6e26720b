// SVG writers: files are written, well-formed (parsed back with a minimal XML reader: balanced tags, quoted
// attributes), series names survive, point counts below the chart's resolution survive and above it are
// bounded by the pixel columns with the extremes kept, NaN breaks lines, the drawing fits its content, and
// atomic writes leave nothing behind on failure.
#define BOOST_TEST_MODULE io_svg
#include <boost/test/unit_test.hpp>

#include "test_support.hpp"

#include "rollkin/io/atomic_file.hpp"
#include "rollkin/output/svg_chart.hpp"
#include "rollkin/output/svg_drawing.hpp"
#include "rollkin/io/svg/markup.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace rollkin::io;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

fs::path out_dir() { return rollkin::testing::scratch_dir("io_svg"); }

std::string read_file(const fs::path& p) { return rollkin::testing::read_text(p); }

std::string unescape(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '&') {
      out += s[i];
      continue;
    }
    const std::size_t semi = s.find(';', i);
    BOOST_REQUIRE(semi != std::string::npos);
    const std::string ent = s.substr(i + 1, semi - i - 1);
    static const std::map<std::string, char> ents = {{"amp", '&'}, {"lt", '<'}, {"gt", '>'}, {"quot", '"'}, {"apos", '\''}};
    BOOST_REQUIRE_MESSAGE(ents.count(ent), "unknown entity &" << ent << ";");
    out += ents.at(ent);
    i = semi;
  }
  return out;
}

/// Minimal XML reader: elements with attributes and text, checks nesting and quoting.
struct Element {
  std::string name;
  std::map<std::string, std::string> attrs;
  std::string text;
  int parent = -1;
};

std::vector<Element> parse_xml(const std::string& doc) {
  std::vector<Element> els;
  std::vector<int> stack;
  std::size_t i = 0;
  bool root_closed = false;
  while (i < doc.size()) {
    const std::size_t lt = doc.find('<', i);
    const std::string text = doc.substr(i, lt == std::string::npos ? std::string::npos : lt - i);
    BOOST_REQUIRE_MESSAGE(text.find('>') == std::string::npos, "stray '>' in text: " << text);
    if (!stack.empty()) els[stack.back()].text += unescape(text);
    else BOOST_REQUIRE_MESSAGE(text.find_first_not_of(" \t\r\n") == std::string::npos, "text outside root: " << text);
    if (lt == std::string::npos) break;
    const std::size_t gt = doc.find('>', lt);
    BOOST_REQUIRE_MESSAGE(gt != std::string::npos, "unterminated tag");
    std::string tag = doc.substr(lt + 1, gt - lt - 1);
    i = gt + 1;
    BOOST_REQUIRE_MESSAGE(tag.find('<') == std::string::npos, "'<' inside tag: " << tag);
    if (tag.size() >= 2 && tag.front() == '?' && tag.back() == '?') continue;  // XML declaration
    if (tag.front() == '/') {
      BOOST_REQUIRE_MESSAGE(!stack.empty(), "closing tag without opening: " << tag);
      BOOST_REQUIRE_EQUAL(els[stack.back()].name, tag.substr(1));
      stack.pop_back();
      if (stack.empty()) root_closed = true;
      continue;
    }
    BOOST_REQUIRE_MESSAGE(!root_closed, "second root element");
    const bool self_closing = tag.back() == '/';
    if (self_closing) tag.pop_back();
    Element e;
    std::size_t k = tag.find_first_of(" \t\r\n");
    e.name = tag.substr(0, k);
    while (k != std::string::npos && k < tag.size()) {
      k = tag.find_first_not_of(" \t\r\n", k);
      if (k == std::string::npos) break;
      const std::size_t eq = tag.find('=', k);
      BOOST_REQUIRE_MESSAGE(eq != std::string::npos, "attribute without value in " << tag);
      const std::string key = tag.substr(k, eq - k);
      BOOST_REQUIRE_MESSAGE(eq + 1 < tag.size() && tag[eq + 1] == '"', "unquoted attribute " << key);
      const std::size_t close = tag.find('"', eq + 2);
      BOOST_REQUIRE_MESSAGE(close != std::string::npos, "unterminated attribute " << key);
      BOOST_REQUIRE_MESSAGE(!e.attrs.count(key), "duplicate attribute " << key);
      e.attrs[key] = unescape(tag.substr(eq + 2, close - eq - 2));
      k = close + 1;
    }
    e.parent = stack.empty() ? -1 : stack.back();
    BOOST_REQUIRE_MESSAGE(e.parent >= 0 || els.empty(), "second root element " << e.name);
    els.push_back(e);
    if (!self_closing) stack.push_back(static_cast<int>(els.size()) - 1);
  }
  BOOST_REQUIRE_MESSAGE(stack.empty(), "unclosed element " << (stack.empty() ? "" : els[stack.back()].name));
  BOOST_REQUIRE(!els.empty());
  BOOST_REQUIRE_EQUAL(els[0].name, "svg");
  return els;
}

std::vector<std::pair<double, double>> parse_points(const std::string& s) {
  std::vector<std::pair<double, double>> pts;
  std::istringstream in(s);
  std::string tok;
  while (in >> tok) {
    const std::size_t c = tok.find(',');
    BOOST_REQUIRE(c != std::string::npos);
    pts.emplace_back(std::stod(tok.substr(0, c)), std::stod(tok.substr(c + 1)));
  }
  return pts;
}

bool has_ancestor(const std::vector<Element>& els, int i, int anc) {
  for (int p = els[i].parent; p >= 0; p = els[p].parent)
    if (p == anc) return true;
  return false;
}

/// Indices of the <g class="series"> elements by data-name.
std::map<std::string, int> series_groups(const std::vector<Element>& els) {
  std::map<std::string, int> m;
  for (std::size_t i = 0; i < els.size(); ++i)
    if (els[i].name == "g" && els[i].attrs.count("class") && els[i].attrs.at("class") == "series")
      m[els[i].attrs.at("data-name")] = static_cast<int>(i);
  return m;
}

/// Point counts of the polylines under element g, in document order.
std::vector<std::size_t> polyline_sizes(const std::vector<Element>& els, int g, const char* name = "polyline") {
  std::vector<std::size_t> n;
  for (std::size_t i = 0; i < els.size(); ++i)
    if (els[i].name == name && has_ancestor(els, static_cast<int>(i), g))
      n.push_back(parse_points(els[i].attrs.at("points")).size());
  return n;
}

bool contains_text(const std::vector<Element>& els, const std::string& text) {
  for (const auto& e : els)
    if (e.name == "text" && e.text == text) return true;
  return false;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(ticks)

BOOST_AUTO_TEST_CASE(nice_tick_values) {
  Ticks t = nice_ticks(0.0, 1.0, 5);
  BOOST_TEST(t.step == 0.2);
  BOOST_TEST(t.values.size() == 6u);
  BOOST_TEST(t.lo == 0.0);
  BOOST_TEST(t.hi == 1.0, boost::test_tools::tolerance(1e-12));

  t = nice_ticks(-0.37, 2.1, 5);  // raw step 0.494 -> 0.5, widened to [-0.5, 2.5]
  BOOST_TEST(t.step == 0.5);
  BOOST_TEST(t.lo == -0.5);
  BOOST_TEST(t.hi == 2.5);
  BOOST_TEST(t.values.front() == -0.5);
  BOOST_TEST(t.values.back() == 2.5);

  t = nice_ticks(0.0, 360.0, 8);  // raw 45 -> 50
  BOOST_TEST(t.step == 50.0);
  BOOST_TEST(t.hi == 400.0);

  t = nice_ticks(0.013, 0.0145, 6);  // 2.5 steps at a small scale
  BOOST_TEST(t.step == 0.00025, boost::test_tools::tolerance(1e-9));
  for (double v : t.values) BOOST_TEST(std::abs(v / t.step - std::round(v / t.step)) < 1e-9);

  // Degenerate and non-finite ranges give usable ticks.
  t = nice_ticks(3.0, 3.0);
  BOOST_TEST(t.lo < 3.0);
  BOOST_TEST(t.hi > 3.0);
  BOOST_TEST(t.values.size() >= 2u);
  t = nice_ticks(kNaN, 1.0);
  BOOST_TEST(t.values.size() >= 2u);
  // Zero is exactly zero, never -0 or 1e-17.
  t = nice_ticks(-1.0, 1.0, 10);
  bool zero = false;
  for (double v : t.values) zero |= (v == 0.0 && !std::signbit(v));
  BOOST_TEST(zero);

  // Fixed range: kept as is; fixed step.
  t = ticks_in_range(0.0, 360.0, 4);
  BOOST_TEST(t.lo == 0.0);
  BOOST_TEST(t.hi == 360.0);
  BOOST_TEST(t.values.back() <= 360.0);
  t = ticks_with_step(0.0, 360.0, 90.0, false);
  BOOST_TEST(t.values.size() == 5u);
  BOOST_CHECK_THROW(ticks_with_step(0.0, 1.0, 0.0, false), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(tick_labels) {
  BOOST_TEST(format_tick(0.25, 0.25) == "0.25");
  BOOST_TEST(format_tick(-180.0, 45.0) == "-180");
  BOOST_TEST(format_tick(1.5, 0.5) == "1.5");
  BOOST_TEST(format_tick(-1e-17, 0.1) == "0.0");
  BOOST_TEST(format_tick(3.0, 0.5) == "3.0");
  BOOST_TEST(format_tick(0.0015, 0.0005) == "0.0015");
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(chart)

BOOST_AUTO_TEST_CASE(chart_written_and_well_formed) {
  SvgChart chart(640, 400);
  chart.set_title("Joint variables vs crank angle").set_x_label("theta2 [deg]").set_y_label("angle [deg]");
  std::vector<double> x, a, b, c;
  for (int i = 0; i <= 36; ++i) {
    x.push_back(10.0 * i);
    a.push_back(50 * std::sin(i * 0.17));
    b.push_back(-30 + 2.0 * i);
    c.push_back(120 * std::cos(i * 0.1));
  }
  chart.add_series("theta23", x, a);
  chart.add_series("theta34 <&> \"q\"", x, b, "#000000");
  ChartSeries s;
  s.name = "theta5";
  s.x = x;
  s.y = c;
  s.dash = "5 3";
  s.markers = true;
  chart.add_series(s);

  const fs::path file = out_dir() / "chart.svg";
  fs::remove(file);
  chart.write(file.string());
  BOOST_REQUIRE(fs::exists(file));
  BOOST_TEST(rollkin::testing::no_temporaries_in(file.parent_path()));
  const std::string doc = read_file(file);
  BOOST_TEST(doc == chart.to_svg());
  const auto els = parse_xml(doc);
  BOOST_TEST(els[0].attrs.at("width") == "640");
  BOOST_TEST(els[0].attrs.at("height") == "400");
  BOOST_TEST(els[0].attrs.at("xmlns") == "http://www.w3.org/2000/svg");

  const auto groups = series_groups(els);
  BOOST_REQUIRE_EQUAL(groups.size(), 3u);
  for (const std::string name : {"theta23", "theta34 <&> \"q\"", "theta5"}) {
    BOOST_TEST_CONTEXT(name) {
      BOOST_REQUIRE(groups.count(name));
      // One unbroken polyline with all 37 points (below the chart's resolution nothing is reduced), and the
      // name in the legend.
      const auto sizes = polyline_sizes(els, groups.at(name));
      BOOST_TEST(sizes.size() == 1u);
      if (!sizes.empty()) BOOST_TEST(sizes[0] == x.size());
      BOOST_TEST(contains_text(els, name));
    }
  }
  BOOST_TEST(contains_text(els, "Joint variables vs crank angle"));
  BOOST_TEST(contains_text(els, "theta2 [deg]"));
  BOOST_TEST(contains_text(els, "angle [deg]"));
  // Markers: one circle per point of theta5.
  std::size_t markers = 0;
  for (std::size_t i = 0; i < els.size(); ++i)
    if (els[i].name == "circle" && has_ancestor(els, static_cast<int>(i), groups.at("theta5"))) ++markers;
  BOOST_TEST(markers == x.size());
  // Default palette for series without a colour, explicit colour kept.
  BOOST_TEST(els[groups.at("theta23")].attrs.at("stroke") == palette_color(0));
  BOOST_TEST(els[groups.at("theta34 <&> \"q\"")].attrs.at("stroke") == "#000000");

  // All polyline points lie inside the picture (the range covers the data).
  for (const auto& e : els)
    if (e.name == "polyline")
      for (const auto& p : parse_points(e.attrs.at("points"))) {
        BOOST_TEST(p.first >= 0.0);
        BOOST_TEST(p.first <= 640.0);
        BOOST_TEST(p.second >= 0.0);
        BOOST_TEST(p.second <= 400.0);
      }
  // Tick labels for the automatic x axis 0..360 appear.
  const Ticks xt = chart.x_ticks();
  BOOST_TEST(xt.lo <= 0.0);
  BOOST_TEST(xt.hi >= 360.0);
  for (double v : xt.values) BOOST_TEST(contains_text(els, format_tick(v, xt.step)));
}

BOOST_AUTO_TEST_CASE(nan_breaks_lines) {
  std::vector<double> x, y;
  for (int i = 0; i < 14; ++i) {
    x.push_back(i);
    y.push_back(i * i * 0.1);
  }
  y[3] = kNaN;                                        // run 0..2 (3 points)
  y[7] = std::numeric_limits<double>::infinity();     // run 4..6 (3 points)
  x[8] = kNaN;                                        // (a non-finite x breaks too)
  y[10] = kNaN;                                       // 9 alone -> a dot; run 11..13 (3 points)
  SvgChart chart;
  chart.add_series("broken", x, y).set_legend(LegendPosition::Outside);
  const auto els = parse_xml(chart.to_svg());
  const auto groups = series_groups(els);
  BOOST_REQUIRE(groups.count("broken"));
  const auto sizes = polyline_sizes(els, groups.at("broken"));
  BOOST_TEST(sizes == (std::vector<std::size_t>{3, 3, 3}), boost::test_tools::per_element());
  std::size_t dots = 0;
  for (std::size_t i = 0; i < els.size(); ++i)
    if (els[i].name == "circle" && has_ancestor(els, static_cast<int>(i), groups.at("broken"))) ++dots;
  BOOST_TEST(dots == 1u);
  BOOST_TEST(chart.to_svg().find("nan") == std::string::npos);
  BOOST_TEST(chart.to_svg().find("inf") == std::string::npos);
  // The automatic y range ignores the non-finite values.
  BOOST_TEST(std::isfinite(chart.y_ticks().hi));
}

BOOST_AUTO_TEST_CASE(long_series_are_drawn_at_the_resolution_with_their_extremes) {
  // 200,001 points (a fine sweep) with narrow peaks: the chart draws at most 4 points per pixel column of its
  // plot area (output/decimate.hpp), and the drawn line still reaches the series' highest and lowest values and
  // starts and ends at its first and last points (pixels computed here from the plot area and the y ticks).
  const std::size_t n = 200001;
  std::vector<double> x(n), y(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = 360.0 * static_cast<double>(i) / static_cast<double>(n - 1);
    y[i] = 40 * std::sin(x[i] * 0.05) + (i == 12345 ? 75.0 : 0.0) - (i == 150000 ? 90.0 : 0.0);
  }
  SvgChart chart(640, 400);
  chart.add_series("fine", x, y).set_legend(LegendPosition::Outside);
  const std::string doc = chart.to_svg();
  BOOST_TEST(doc.size() < 200000u);
  const auto els = parse_xml(doc);
  const auto groups = series_groups(els);
  BOOST_REQUIRE(groups.count("fine"));
  std::vector<std::pair<double, double>> drawn;
  for (std::size_t i = 0; i < els.size(); ++i)
    if (els[i].name == "polyline" && has_ancestor(els, static_cast<int>(i), groups.at("fine")))
      for (const auto& p : parse_points(els[i].attrs.at("points"))) drawn.push_back(p);
  double left = 0, top = 0, pw = 0, ph = 0;
  for (const auto& e : els)
    if (e.name == "rect" && els[e.parent].name == "clipPath") {
      left = std::stod(e.attrs.at("x"));
      top = std::stod(e.attrs.at("y"));
      pw = std::stod(e.attrs.at("width"));
      ph = std::stod(e.attrs.at("height"));
    }
  BOOST_REQUIRE(pw > 0);
  BOOST_TEST(drawn.size() <= 4 * static_cast<std::size_t>(std::ceil(pw)));
  BOOST_TEST(drawn.size() >= static_cast<std::size_t>(pw));
  const Ticks xt = chart.x_ticks(), yt = chart.y_ticks();
  auto X = [&](double v) { return left + (v - xt.lo) / (xt.hi - xt.lo) * pw; };
  auto Y = [&](double v) { return top + ph - (v - yt.lo) / (yt.hi - yt.lo) * ph; };
  double highest = 1e300, lowest = -1e300;  // pixel y grows downwards
  for (const auto& p : drawn) {
    highest = std::min(highest, p.second);
    lowest = std::max(lowest, p.second);
  }
  BOOST_TEST(std::abs(highest - (Y(*std::max_element(y.begin(), y.end())))) <= 0.006);  // px, written with 2 decimals
  BOOST_TEST(std::abs(lowest - (Y(*std::min_element(y.begin(), y.end())))) <= 0.006);
  BOOST_TEST(std::abs(drawn.front().first - (X(x.front()))) <= 0.006);
  BOOST_TEST(std::abs(drawn.front().second - (Y(y.front()))) <= 0.006);
  BOOST_TEST(std::abs(drawn.back().first - (X(x.back()))) <= 0.006);
  BOOST_TEST(std::abs(drawn.back().second - (Y(y.back()))) <= 0.006);
}

BOOST_AUTO_TEST_CASE(fixed_ranges_steps_and_errors) {
  SvgChart chart;
  chart.set_x_range(0, 360).set_tick_steps(90, 0).set_legend(LegendPosition::None).set_grid(false);
  chart.add_series("s", {0, 180, 360}, {1, 2, 3});
  const Ticks xt = chart.x_ticks();
  BOOST_TEST(xt.values == (std::vector<double>{0, 90, 180, 270, 360}), boost::test_tools::per_element());
  const auto els = parse_xml(chart.to_svg());
  BOOST_TEST(contains_text(els, "270"));
  BOOST_TEST(!contains_text(els, "s"));  // no legend
  BOOST_CHECK_THROW(chart.add_series("bad", {1, 2}, {1}), std::invalid_argument);
  BOOST_CHECK_THROW(chart.set_y_range(2, 1), std::invalid_argument);  // reversed (equal ends are widened)
  // Empty chart still renders a valid document.
  BOOST_TEST(parse_xml(SvgChart().to_svg()).size() > 1u);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(drawing)

BOOST_AUTO_TEST_CASE(drawing_fits_content_and_counts_points) {
  SvgDrawing d(500, 400, 20);
  d.set_title("four-bar & disks");
  // A closed square, an open zig-zag with a NaN break, a circle, points and labels; world units with y up.
  const std::vector<Eigen::Vector2d> square = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  Stroke thick;
  thick.color = "#1f77b4";
  thick.width = 2.5;
  thick.opacity = 0.6;
  Fill fill;
  fill.color = "#aaccee";
  fill.opacity = 0.3;
  d.add_polyline(square, thick, true, fill);
  std::vector<Eigen::Vector2d> zig;
  for (int i = 0; i < 9; ++i) zig.emplace_back(-3 + 0.5 * i, (i % 2) ? 1.0 : -1.0);
  zig[4] = Eigen::Vector2d(kNaN, 0);
  d.add_polyline(zig);
  d.add_circle({7.99303, -0.26394}, 4.0, Stroke{"#d62728", 1.0, 1.0, "4 2"});
  d.add_point({0, 0}, "#000000", 3, Marker::Dot);
  d.add_point({7, -2}, "#000000", 4, Marker::Cross);
  d.add_point({3, 0}, "#2ca02c", 3, Marker::Square);
  d.add_point({1, 1}, "#2ca02c", 3, Marker::Circle);
  d.add_text({0, 0}, "O_A <pivot>");
  d.add_text({7, -2}, "O_B");

  // World box: x from -3 to 7.99303 + 4, y from -4.26394 to 3.73606.
  const Eigen::Vector4d box = d.content_box();
  BOOST_TEST(box[0] == -3.0);
  BOOST_TEST(box[2] == 11.99303, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(box[1] == -4.26394, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(box[3] == 3.73606, boost::test_tools::tolerance(1e-12));

  // y up: a higher world point is higher on the page (smaller pixel y); uniform scale.
  const Eigen::Vector2d p0 = d.to_pixel({0, 0}), p1 = d.to_pixel({1, 1});
  BOOST_TEST(p1.y() < p0.y());
  BOOST_TEST(p1.x() - p0.x() == p0.y() - p1.y(), boost::test_tools::tolerance(1e-9));
  // Fit: the box's corners are inside the margins and touch them in one direction.
  const Eigen::Vector2d lo = d.to_pixel({box[0], box[1]}), hi = d.to_pixel({box[2], box[3]});
  BOOST_TEST(lo.x() >= 20 - 1e-9);
  BOOST_TEST(hi.x() <= 480 + 1e-9);
  BOOST_TEST(hi.y() >= 20 - 1e-9);
  BOOST_TEST(lo.y() <= 380 + 1e-9);
  const bool touches_x = std::abs(lo.x() - 20) < 1e-6 && std::abs(hi.x() - 480) < 1e-6;
  const bool touches_y = std::abs(lo.y() - 380) < 1e-6;
  BOOST_TEST((touches_x || touches_y));

  const fs::path file = out_dir() / "drawing.svg";
  d.write(file.string());
  const auto els = parse_xml(read_file(file));
  std::vector<std::size_t> polygons, polylines;
  std::size_t circles = 0, rects = 0, paths = 0;
  for (const auto& e : els) {
    if (e.name == "polygon") polygons.push_back(parse_points(e.attrs.at("points")).size());
    if (e.name == "polyline") polylines.push_back(parse_points(e.attrs.at("points")).size());
    if (e.name == "circle") ++circles;
    if (e.name == "rect") ++rects;
    if (e.name == "path") ++paths;
    if (e.name == "polygon" || e.name == "polyline")
      for (const auto& p : parse_points(e.attrs.at("points"))) {
        BOOST_TEST(p.first >= 0.0);
        BOOST_TEST(p.first <= 500.0);
        BOOST_TEST(p.second >= 0.0);
        BOOST_TEST(p.second <= 400.0);
      }
  }
  BOOST_TEST(polygons == (std::vector<std::size_t>{4}), boost::test_tools::per_element());
  BOOST_TEST(polylines == (std::vector<std::size_t>{4, 4}), boost::test_tools::per_element());
  BOOST_TEST(circles == 3u);  // disk, dot marker, circle marker
  BOOST_TEST(rects == 2u);    // background, square marker
  BOOST_TEST(paths == 1u);    // cross marker
  BOOST_TEST(contains_text(els, "O_A <pivot>"));
  BOOST_TEST(contains_text(els, "O_B"));
  BOOST_TEST(contains_text(els, "four-bar & disks"));
  for (const auto& e : els)
    if (e.name == "polygon") {
      BOOST_TEST(e.attrs.at("stroke-opacity") == "0.6");
      BOOST_TEST(e.attrs.at("fill") == "#aaccee");
      BOOST_TEST(e.attrs.at("stroke-width") == "2.5");
    }
  // The disk's pixel radius is the world radius times the scale.
  for (const auto& e : els)
    if (e.name == "circle" && e.attrs.count("stroke-dasharray"))
      BOOST_TEST(std::stod(e.attrs.at("r")) == 4.0 * d.scale(), boost::test_tools::tolerance(1e-3));
}

BOOST_AUTO_TEST_CASE(closed_polyline_with_break_and_fixed_box) {
  SvgDrawing d(300, 300, 10);
  d.set_world_box(-1, -1, 1, 1).set_background("");
  d.add_polyline({{0, 0}, {1, 0}, {kNaN, kNaN}, {1, 1}, {0, 1}}, Stroke{}, true);
  d.add_point({5, 5});  // outside the fixed box: does not change the view
  BOOST_TEST(d.scale() == 140.0, boost::test_tools::tolerance(1e-12));
  const auto els = parse_xml(d.to_svg());
  std::vector<std::size_t> polylines;
  std::size_t polygons = 0, rects = 0;
  for (const auto& e : els) {
    if (e.name == "polyline") polylines.push_back(parse_points(e.attrs.at("points")).size());
    polygons += e.name == "polygon";
    rects += e.name == "rect";
  }
  BOOST_TEST(polylines == (std::vector<std::size_t>{2, 2}), boost::test_tools::per_element());
  BOOST_TEST(polygons == 0u);
  BOOST_TEST(rects == 0u);
  // Empty and single-point drawings are valid and finite.
  BOOST_TEST(parse_xml(SvgDrawing().to_svg()).size() > 1u);
  SvgDrawing one;
  one.add_point({3, 4});
  BOOST_TEST(std::isfinite(one.scale()));
  BOOST_TEST(one.to_pixel({3, 4}).x() == 400.0, boost::test_tools::tolerance(1e-9));
  BOOST_CHECK_THROW(d.set_world_box(1, 0, 0, 1), std::invalid_argument);    // reversed
  BOOST_CHECK_THROW(d.set_world_box(0, 0, kNaN, 1), std::invalid_argument);
}

// The box of a drawing whose only contour is a straight line parallel to an axis has zero height (or width):
// widened by 5% of the other extent on each side, so the line sets the scale and sits in the middle; a point
// by 10% of its largest coordinate (at least 1). Before, set_world_box refused it ("need finite xmin < xmax")
// and `rollkin solve --draw` failed.
BOOST_AUTO_TEST_CASE(degenerate_world_boxes_are_widened_relative_to_the_drawing) {
  SvgDrawing d(300, 300, 10);  // 280 x 280 px inside the margins
  d.set_world_box(0, 2, 10, 2);
  BOOST_TEST(d.scale() == 28.0, boost::test_tools::tolerance(1e-12));  // 280 px / 10 (x) < 280 px / 1 (y)
  BOOST_TEST((d.to_pixel({5, 2}) - Eigen::Vector2d(150, 150)).norm() < 1e-9);
  SvgDrawing v(300, 300, 10);
  v.set_world_box(3, -4, 3, 6);
  BOOST_TEST(v.scale() == 28.0, boost::test_tools::tolerance(1e-12));
  SvgDrawing p(300, 300, 10);
  p.set_world_box(3, 4, 3, 4);  // pad max(1, 0.4) = 1: a 2 x 2 box
  BOOST_TEST(p.scale() == 140.0, boost::test_tools::tolerance(1e-12));
  // The fitted box follows the same rule: a horizontal line drawn alone.
  SvgDrawing f(300, 300, 10);
  f.add_polyline({{0, 2}, {10, 2}});
  BOOST_TEST(f.scale() == 28.0, boost::test_tools::tolerance(1e-12));
  // A chart's fixed range of zero width is widened like a fitted one.
  SvgChart chart;
  BOOST_CHECK_NO_THROW(chart.set_x_range(5, 5));
  BOOST_CHECK_THROW(chart.set_x_range(6, 5), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(atomic_write)

BOOST_AUTO_TEST_CASE(missing_directory_leaves_no_file) {
  const fs::path dir = out_dir() / "does-not-exist";
  fs::remove_all(dir);
  const fs::path file = dir / "chart.svg";
  SvgChart chart;
  chart.add_series("a", {0, 1}, {0, 1});
  try {
    chart.write(file.string());
    BOOST_FAIL("write into a missing directory must throw");
  } catch (const std::runtime_error& e) {
    const std::string msg = e.what();
    BOOST_TEST_MESSAGE("error: " << msg);
    BOOST_TEST(msg.find(file.string()) != std::string::npos);
  }
  BOOST_TEST(!fs::exists(file));
  BOOST_TEST(rollkin::testing::no_temporaries_in(file.parent_path()));
  BOOST_TEST(!fs::exists(dir));

  SvgDrawing d;
  BOOST_CHECK_THROW(d.write(file.string()), std::runtime_error);
  BOOST_TEST(!fs::exists(dir));
}

BOOST_AUTO_TEST_CASE(replace_is_complete_and_failed_rename_keeps_target) {
  const fs::path file = out_dir() / "replace.svg";
  {
    std::ofstream(file) << "old content";
  }
  SvgDrawing d;
  d.add_polyline({{0, 0}, {1, 1}});
  d.write(file.string());
  BOOST_TEST(read_file(file) == d.to_svg());
  BOOST_TEST(rollkin::testing::no_temporaries_in(file.parent_path()));

  // Target is a non-empty directory: the temporary is written but the rename fails; nothing is left behind
  // and the directory is untouched.
  const fs::path dir = out_dir() / "is-a-directory.svg";
  fs::create_directories(dir / "inside");
  try {
    d.write(dir.string());
    BOOST_FAIL("rename over a directory must throw");
  } catch (const std::runtime_error& e) {
    BOOST_TEST(std::string(e.what()).find(dir.string()) != std::string::npos);
  }
  BOOST_TEST(fs::is_directory(dir / "inside"));
  BOOST_TEST(rollkin::testing::no_temporaries_in(dir.parent_path()));
  BOOST_CHECK_THROW(write_file_atomic("", "x"), std::runtime_error);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_CASE(charts_nested_in_one_document_clip_to_their_own_plot_area) {
  // Two charts stacked in one SVG (as the CLI's --plot does) must not share a clip-path id, or the second
  // chart's data would be clipped to the first chart's plot rectangle.
  auto clip_id = [](const std::string& svg) {
    const auto at = svg.find("clipPath id=\"");
    BOOST_TEST_REQUIRE(at != std::string::npos);
    const auto begin = at + 13;
    return svg.substr(begin, svg.find('"', begin) - begin);
  };
  SvgChart a, b;
  a.set_title("angles");
  b.set_title("lengths");
  a.add_series("s", {0.0, 1.0}, {0.0, 1.0});
  b.add_series("s", {0.0, 1.0}, {0.0, 1.0});
  const std::string sa = a.to_svg(), sb = b.to_svg();
  BOOST_TEST(clip_id(sa) != clip_id(sb));
  BOOST_TEST(sb.find("url(#" + clip_id(sb) + ")") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(control_characters_and_stray_bytes_stay_out_of_the_xml) {
  // XML 1.0 allows neither control characters (not even as &#1;) nor bytes that are not UTF-8: before,
  // a name holding them made the plot unreadable to XML parsers.
  BOOST_TEST(xml_escape("a\x01<b>\n&\"'\x7f") == "a\\x01&lt;b&gt;\\n&amp;&quot;&apos;\\x7f");
  BOOST_TEST(xml_escape("\xff\xc3(") == "\\xff\\xc3(");                     // invalid UTF-8
  BOOST_TEST(xml_escape("\xed\xa0\x80") == "\\xed\\xa0\\x80");               // a UTF-16 surrogate
  BOOST_TEST(xml_escape("\xef\xbf\xbf") == "\\xef\\xbf\\xbf");               // U+FFFF
  BOOST_TEST(xml_escape("\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80") == "\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80");  // e-acute, euro, emoji
}
