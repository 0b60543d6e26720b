// The contract of every contour file format (io/contour_formats.hpp), one loop over the table: each format's
// lister lists the fixtures of that format, and every selector it prints, put into a scene, is read by the
// scene's contour reader of the format's "type" into a contour of the listed length, closed or open as listed,
// with the listed corners, inside the listed bounding box and reaching its sides. The table's own rules:
// extensions lower case with the dot, each in one format, found ignoring case; the help text names every format.
// A format without a fixture here fails the test, naming it.
#define BOOST_TEST_MODULE io_contour_formats
#include <boost/test/unit_test.hpp>

#include "rollkin/io/contour_formats.hpp"
#include "rollkin/io/scene/reader.hpp"
#include "test_support.hpp"

#include <nlohmann/json.hpp>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>

using namespace rollkin;
using namespace rollkin::testing;
namespace fs = std::filesystem;

namespace {

const fs::path kSource = ROLLKIN_SOURCE_DIR;

/// The files each format is checked on: the repository's fixtures, and files written here for cases they lack.
std::vector<std::string> fixtures(const std::string& type) {
  const fs::path dir = scratch_dir("io_contour_formats");
  if (type == "dxf")
    return {(kSource / "tests/data/dxf/curves.dxf").string(), (kSource / "tests/data/dxf/chain_mm.dxf").string(),
            (kSource / "shapes/cam_profile.dxf").string()};
  if (type == "svg") return {(kSource / "tests/data/svg/clones.svg").string(), (kSource / "tests/data/svg/inkscape_mm.svg").string()};
  if (type == "samples") {
    // An open file, and a closed one (its last point repeats its first) with a header and an upper-case extension.
    std::string closed = "x, y\n";
    for (int k = 0; k <= 24; ++k) {
      const double t = 2 * pi<double>() * (k % 24) / 24;
      closed += std::to_string(3 * std::cos(t)) + ", " + std::to_string(1.5 * std::sin(t)) + "\n";
    }
    return {(kSource / "shapes/parabola_n0025.txt").string(), write_text(dir / "ellipse.CSV", closed)};
  }
  return {};
}

/// The contour a selector selects, read through the scene reader (on a ground link, with a slider to solve).
Contour<double> read_selected(const std::string& selector) {
  nlohmann::ordered_json contour = nlohmann::ordered_json::parse(selector);
  contour["name"] = "c";
  const nlohmann::ordered_json scene = {
      {"links", {{{"name", "ground"}, {"ground", true}, {"contours", {contour}}}, {{"name", "slider"}}}},
      {"pairs", {{{"name", "S"}, {"type", "prismatic"}, {"links", {"ground", "slider"}}, {"variable", "s"}, {"value", 0}}}},
      {"inputs", {"S.s"}}};
  const io::Scene s = io::build_scene(scene, "<selected>", std::string("."));
  return s.mechanism.contours.at(0);
}

/// The contour's extent along each axis from dense samples and its corners (where a polygon's extremes are):
/// the listed box must hold it and be reached by it.
void sampled_box(const Contour<double>& c, Vec2<double>& lo, Vec2<double>& hi) {
  const Domain<double> d = c.domain();
  lo = hi = c.jet(d.lo, 0).p;
  auto add = [&](double u) {
    const Vec2<double> p = c.jet(u, 0).p;
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  };
  const int n = 20000;
  for (int i = 0; i <= n; ++i) add(d.lo + d.period() * i / n);
  for (const ContourCorner<double>& k : c.corners()) add(k.u);
}

}  // namespace

BOOST_AUTO_TEST_CASE(every_format_is_found_by_its_extensions_and_named_in_the_help) {
  std::map<std::string, std::string> owner;
  const std::string help = io::contour_file_formats_help();
  BOOST_TEST(!io::contour_file_formats().empty());
  for (const io::ContourFileFormat& f : io::contour_file_formats()) {
    BOOST_TEST_CONTEXT(f.name) {
      BOOST_TEST((f.type && f.name && f.description && f.list));
      BOOST_TEST(!f.extensions.empty());
      BOOST_TEST(contains(help, f.name));
      for (const std::string& e : f.extensions) {
        BOOST_TEST((e.size() >= 2 && e[0] == '.'));
        for (char ch : e) BOOST_TEST(ch == std::tolower(static_cast<unsigned char>(ch)));
        BOOST_TEST(owner.emplace(e, f.name).second, e << " belongs to two formats");
        std::string upper = e;
        for (char& ch : upper) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
        BOOST_TEST(io::contour_file_format_of("dir.x/part" + upper) == &f);
        BOOST_TEST(contains(io::contour_file_extensions(), e));
      }
    }
  }
  BOOST_TEST(io::contour_file_format_of("notes.odt") == nullptr);
  BOOST_TEST(contains(input_error_of([] { io::list_contours("notes.odt"); }), io::contour_file_extensions()));
}

BOOST_AUTO_TEST_CASE(every_listed_selector_reads_the_listed_chain) {
  for (const io::ContourFileFormat& f : io::contour_file_formats()) {
    const std::vector<std::string> files = fixtures(f.type);
    BOOST_TEST(!files.empty(), "no fixture for the contour file format " << f.name << " (type " << f.type << "): add one here");
    for (const std::string& file : files) {
      const std::vector<io::ListedChain> chains = io::list_contours(file);
      BOOST_TEST(!chains.empty(), file);
      for (std::size_t k = 0; k < chains.size(); ++k) {
        const io::ListedChain& c = chains[k];
        if (c.selector.empty()) continue;  // a chain no selector picks alone (a branch; the DXF listing says why)
        BOOST_TEST_CONTEXT(file << ", chain " << k + 1 << ": " << c.selector) {
          BOOST_TEST(nlohmann::json::parse(c.selector).at("type") == f.type);
          const Contour<double> read = read_selected(c.selector);
          const Domain<double> d = read.domain();
          BOOST_TEST(d.closed == c.closed);
          BOOST_TEST(std::abs(read.arc_length(d.lo, d.hi) - c.length) <= 1e-9 * c.length);
          BOOST_TEST(read.corners().size() == c.corners);
          Vec2<double> lo, hi;
          sampled_box(read, lo, hi);
          const double size = (c.max - c.min).norm(), slack = 1e-9 * size, reach = 1e-6 * size;
          for (int i = 0; i < 2; ++i) {
            BOOST_TEST(lo(i) >= c.min(i) - slack);
            BOOST_TEST(hi(i) <= c.max(i) + slack);
            BOOST_TEST(lo(i) <= c.min(i) + reach);
            BOOST_TEST(hi(i) >= c.max(i) - reach);
          }
        }
      }
    }
  }
}
