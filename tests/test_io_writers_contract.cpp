// The writers' contract (docs/reliability.md, "Outputs, signals and messages (issue 37)"): every file rollkin
// writes is read back by rollkin's own reader, for ordinary and extreme inputs. A file rollkin wrote that its
// reader refuses is a defect of rollkin (io::InternalError), never the user's bad input.
//
// Writers, each with the reader the run itself uses:
//   point files (io::point_file_text)                      -> io::parse_point_text: the same doubles, bit for bit;
//   DXF SPLINEs (io::dxf_text of spline_of, polyline_spline) -> io::parse_dxf_contour: the same control points;
//   synthesize cam's four files (output::cam_files)     -> read_point_file, read_dxf_contour (layer CAM),
//                                                             read_svg_path ("cam"), io::load_scene;
//   synthesize gears' four files (output::gear_files)   -> read_point_file x 2, read_dxf_contour (GEAR1, GEAR2),
//                                                             io::load_scene.
// Inputs: sizes from 1e-300 to 1e300, far from the origin (1e12 + a unit circle), signed zeros, the smallest
// normal numbers, 3 to 10^5 points; specs scaled by 1e-6 to 1e6 and specs of absurd sizes (1e300). For a spec a
// run may refuse the input (io::InputError: bad input, exit 2); once files are made, they must read back.
// Found on its first run: libdxflib's writer printed reals as "%.16f", so a contour of size 1e-20 was written as
// zeros (the DXF writer now writes the shortest exact decimal).
#define BOOST_TEST_MODULE io_writers_contract
#include <boost/test/unit_test.hpp>

#include "test_support.hpp"

#include "rollkin/io/dxf/reader.hpp"
#include "rollkin/io/dxf/writer.hpp"
#include "rollkin/io/format.hpp"
#include "rollkin/io/json/document.hpp"
#include "rollkin/io/output_set.hpp"
#include "rollkin/io/point_file.hpp"
#include "rollkin/io/scene/reader.hpp"
#include "rollkin/io/svg/reader.hpp"
#include "rollkin/output/synthesis_files.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace rollkin;
using V = Vec2<double>;
namespace fs = std::filesystem;

/// n points of an ellipse-like closed curve of size `size` about `centre`, seeded noise of 1e-3 of the size.
std::vector<V> curve(std::size_t n, double size, const V& centre, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> noise(-1e-3, 1e-3);
  std::vector<V> out;
  for (std::size_t k = 0; k < n; ++k) {
    const double t = 2 * pi<double>() * double(k) / double(n);
    out.push_back(centre + size * V((1 + noise(rng)) * std::cos(t), (0.6 + noise(rng)) * std::sin(t)));
  }
  return out;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

struct Case {
  std::string name;
  std::vector<V> points;
};

/// Ordinary and extreme point sets.
std::vector<Case> point_sets() {
  std::vector<Case> cases;
  for (const double size : {1e-300, 1e-150, 1e-20, 1e-6, 1.0, 1e6, 1e150, 1e300})
    cases.push_back({"size " + std::to_string(size), curve(200, size, V(0, 0), 7)});
  cases.push_back({"1e12 from the origin", curve(200, 1.0, V(1e12, -1e12), 8)});
  cases.push_back({"10^5 points", curve(100000, 3.0, V(0, 0), 9)});
  cases.push_back({"three points", {V(0, 0), V(1, 0), V(0, 1)}});
  const double tiny = std::numeric_limits<double>::min(), huge = std::numeric_limits<double>::max() / 4;
  cases.push_back({"signed zeros and extremes", {V(-0.0, 0.0), V(tiny, -tiny), V(huge, 0), V(0, -huge), V(1.0 / 3, 2.0 / 3)}});
  return cases;
}

}  // namespace

BOOST_AUTO_TEST_CASE(point_files_read_back_bit_for_bit) {
  for (const Case& c : point_sets()) {
    BOOST_TEST_CONTEXT(c.name) {
      const std::string text = io::point_file_text("contract\nsecond comment line", c.points);
      std::vector<V> back;
      BOOST_REQUIRE_NO_THROW(back = io::parse_point_text(text, "contract.txt", 1));
      BOOST_REQUIRE_EQUAL(back.size(), c.points.size());
      std::size_t differ = 0;
      for (std::size_t k = 0; k < back.size(); ++k)
        differ += !same_bits(back[k].x(), c.points[k].x()) || !same_bits(back[k].y(), c.points[k].y());
      BOOST_TEST(differ == 0u);
    }
  }
}

BOOST_AUTO_TEST_CASE(a_point_that_a_point_file_cannot_hold_is_an_internal_error) {
  for (const double bad : {std::nan(""), std::numeric_limits<double>::infinity()})
    BOOST_CHECK_THROW(io::point_file_text("x", {V(0, 0), V(bad, 1)}), io::InternalError);
}

BOOST_AUTO_TEST_CASE(dxf_splines_read_back_with_their_control_points) {
  for (const Case& c : point_sets()) {
    if (c.points.size() < 4 || c.points.size() > 1000) continue;  // a spline needs four; 10^5 is the point files'
    double size = 0;
    for (const V& p : c.points) size = std::max(size, p.norm());
    if (size < 1e-100 || size > 1e100) continue;  // the sampled spline squares its chords (the specs' range)
    for (const bool closed : {true, false}) {
      BOOST_TEST_CONTEXT(c.name << (closed ? ", closed" : ", open")) {
        SplineOptions<double> options;
        options.closed = closed;
        const io::DxfSpline written = io::spline_of(SampledProfile<double>(c.points, options), "CONTRACT");
        const std::string text = io::dxf_text({written}, "mm");
        io::DxfContour back;
        BOOST_REQUIRE_NO_THROW(back = io::parse_dxf_contour(text, {"CONTRACT", ""}, "contract.dxf"));
        BOOST_TEST(back.closed == closed);
        // Every written control point is the first point of a read-back Bezier segment (or its end), exactly.
        BOOST_TEST_REQUIRE(back.segments.size() * 3 + 1 == written.control.size());
        double worst = 0;
        for (std::size_t k = 0; k < back.segments.size(); ++k)
          for (std::size_t j = 0; j < 4; ++j)
            worst = std::max(worst, (back.segments[k].points[j] - written.control[3 * k + j]).norm());
        BOOST_TEST(worst <= 1e-15 * size);
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(dxf_polylines_read_back_exactly) {
  const std::vector<V> q{{1e-90, 0}, {1e90, 1e-90}, {-0.0, 2.5e89}};  // digits a "%.16f" writer lost
  const io::DxfContour back = io::parse_dxf_contour(io::dxf_text({io::polyline_spline(q, "P")}, ""), {"P", ""}, "p.dxf");
  BOOST_TEST_REQUIRE(back.segments.size() == 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    BOOST_TEST(same_bits(back.segments[k].points.front().x(), q[k].x()));
    BOOST_TEST(same_bits(back.segments[k].points.back().y(), q[k + 1].y()));
  }
}

namespace {

/// The four files of a cam spec written to `dir` and read back by the readers the run uses; "" when they all
/// read, else what failed. A spec the run refuses as bad input gives "refused: <message>".
std::string cam_round_trip(const std::string& spec_text, const fs::path& dir) {
  synthesis::CamSpec spec;
  synthesis::CamProfile profile;
  try {
    spec = synthesis::cam_spec_from_document(io::parse_json_document(spec_text, "contract.json"), "contract.json", dir.string());
    profile = synthesis::synthesise_cam(spec);
  } catch (const io::InputError& e) {
    return std::string("refused: ") + e.what();
  }
  if (!profile.envelope.defects.empty()) return "refused: undercut";  // nothing is written
  const output::CamFiles files = output::cam_files(spec, profile, "c.txt");
  testing::write_text(dir / "c.txt", files.profile);
  testing::write_text(dir / "c.dxf", files.dxf);
  testing::write_text(dir / "c.svg", files.svg);
  testing::write_text(dir / "c.json", files.scene);
  try {
    const std::vector<V> points = io::read_point_file((dir / "c.txt").string(), 4);
    if (points.size() != profile.points.size()) return "the point file holds " + std::to_string(points.size()) + " points";
    (void)io::read_dxf_contour((dir / "c.dxf").string(), {"CAM", ""});
    (void)io::read_svg_path((dir / "c.svg").string(), "cam");
    (void)io::load_scene((dir / "c.json").string());
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

std::string cam_spec(double scale, double lift, const std::string& follower, const std::string& contact) {
  auto n = [](double v) { return io::format_number(v, 17); };
  return R"({"units": {"length": "mm", "angle": "deg"}, "base_radius": )" + n(40 * scale) + R"(, "follower": )" + follower +
         R"(, "contact": )" + contact + R"(, "law": [{"to": 90, "lift": )" + n(lift) +
         R"(, "kind": "cycloidal"}, {"to": 180, "kind": "dwell"}, {"to": 270, "lift": )" + n(-lift) +
         R"(, "kind": "cycloidal"}, {"to": 360, "kind": "dwell"}]})";
}

}  // namespace

BOOST_AUTO_TEST_CASE(synthesize_cam_files_read_back_at_every_scale) {
  const fs::path dir = testing::scratch_dir("writers_contract_cam");
  for (const double scale : {1e-90, 1e-6, 1.0, 1e6, 1e90}) {
    auto n = [&](double v) { return io::format_number(v * scale, 17); };
    const std::vector<std::pair<std::string, std::string>> kinds{
        {R"({"motion": "translating", "offset": )" + n(12) + "}", R"({"roller_radius": )" + n(10) + "}"},
        {R"({"motion": "translating"})", R"({"flat": true})"},
        {R"({"motion": "oscillating", "pivot": [)" + n(90) + ", 0], \"arm\": " + n(70) + "}",
         R"({"roller_radius": )" + n(10) + "}"}};
    for (const auto& [follower, contact] : kinds) {
      const double lift = follower.find("oscillating") != std::string::npos ? 20 : 15 * scale;
      const std::string spec = cam_spec(scale, lift, follower, contact);
      BOOST_TEST_CONTEXT(spec) { BOOST_TEST(cam_round_trip(spec, dir) == ""); }
    }
  }
}

BOOST_AUTO_TEST_CASE(synthesize_cam_files_of_absurd_sizes_are_refused_or_read_back) {
  const fs::path dir = testing::scratch_dir("writers_contract_cam_extreme");
  const std::string roller = R"({"motion": "translating", "offset": 12})", r10 = R"({"roller_radius": 10})";
  for (const std::string& spec : {cam_spec(1, 1e300, roller, r10), cam_spec(1e298, 15, roller, r10),
                                  cam_spec(1, 1e-300, roller, r10), cam_spec(1e-300, 1e-300, roller, R"({"roller_radius": 1e-300})")}) {
    BOOST_TEST_CONTEXT(spec) {
      const std::string outcome = cam_round_trip(spec, dir);
      BOOST_TEST((outcome.empty() || outcome.rfind("refused: ", 0) == 0), outcome);
    }
  }
}

namespace {

std::string gear_round_trip(const std::string& spec_text, const fs::path& dir) {
  synthesis::GearSpec spec;
  synthesis::GearDesign design;
  try {
    spec = synthesis::gear_spec_from_document(io::parse_json_document(spec_text, "contract.json"), "contract.json", dir.string());
    design = synthesis::synthesise_gears(spec);
  } catch (const io::InputError& e) {
    return std::string("refused: ") + e.what();
  }
  const output::GearFiles files = output::gear_files(spec, design, "g.1.txt", "g.2.txt");
  testing::write_text(dir / "g.1.txt", files.gear1);
  testing::write_text(dir / "g.2.txt", files.gear2);
  testing::write_text(dir / "g.dxf", files.dxf);
  testing::write_text(dir / "g.json", files.scene);
  try {
    (void)io::read_point_file((dir / "g.1.txt").string(), 4);
    (void)io::read_point_file((dir / "g.2.txt").string(), 4);
    (void)io::read_dxf_contour((dir / "g.dxf").string(), {"GEAR1", ""});
    (void)io::read_dxf_contour((dir / "g.dxf").string(), {"GEAR2", ""});
    (void)io::load_scene((dir / "g.json").string());
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace

BOOST_AUTO_TEST_CASE(synthesize_gears_files_read_back_or_the_spec_is_refused) {
  const fs::path dir = testing::scratch_dir("writers_contract_gears");
  for (const double distance : {1e-6, 80.0, 1e6})
    for (const std::string& transmission : {std::string(R"({"kind": "elliptical", "eccentricity": 0.5})"),
                                            std::string(R"({"kind": "sinusoidal", "k": 0.3})")}) {
      const std::string spec = R"({"units": {"length": "mm", "angle": "deg"}, "centre_distance": )" + io::format_number(distance, 17) +
                               R"(, "transmission": )" + transmission + "}";
      BOOST_TEST_CONTEXT(spec) { BOOST_TEST(gear_round_trip(spec, dir) == ""); }
    }
  for (const double distance : {1e300, 1e-300}) {
    const std::string spec = R"({"units": {"length": "mm", "angle": "deg"}, "centre_distance": )" + io::format_number(distance, 17) +
                             R"(, "transmission": {"kind": "elliptical", "eccentricity": 0.5}})";
    BOOST_TEST_CONTEXT(spec) {
      const std::string outcome = gear_round_trip(spec, dir);
      BOOST_TEST((outcome.empty() || outcome.rfind("refused: ", 0) == 0), outcome);
    }
  }
}
