#define BOOST_TEST_MODULE io_scene
#include <boost/test/unit_test.hpp>

#include "test_support.hpp"

#include "rollkin/io/units.hpp"
#include "rollkin/io/scene/reader.hpp"
#include "rollkin/solve/continuation.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using rollkin::io::InputError;
using rollkin::deg_to_rad;
using rollkin::io::Scene;
using rollkin::io::load_scene;

namespace {

namespace fs = std::filesystem;

const std::string kExamples = std::string(ROLLKIN_SOURCE_DIR) + "/examples/";

using namespace rollkin::testing;

fs::path temp_dir() { return scratch_dir("io_scene"); }

std::string write_temp(const std::string& name, const std::string& text) { return write_text(temp_dir() / name, text); }

/// The paper example's text with `from` replaced by `to` (which must occur).
std::string paper_with(const std::string& from, const std::string& to) {
  std::string text = read_text(kExamples + "paper_fourbar.json");
  const std::size_t at = text.find(from);
  BOOST_REQUIRE_MESSAGE(at != std::string::npos, "test setup: \"" << from << "\" not in the paper example");
  return text.replace(at, from.size(), to);
}

/// The InputError message for loading `text` saved as `name`, or "" if it loads.
std::string error_for(const std::string& name, const std::string& text) {
  return input_error_of([&] { load_scene(write_temp(name, text)); });
}

/// Every error names the file, the JSON path and what was expected.
void expect_error(const std::string& name, const std::string& text, const std::string& path, const std::string& expected) {
  const std::string msg = error_for(name, text);
  BOOST_TEST_CONTEXT(name) {
    BOOST_TEST(!msg.empty());
    BOOST_TEST(contains(msg, name));
    BOOST_TEST(contains(msg, path));
    BOOST_TEST(contains(msg, expected));
  }
}

}  // namespace

// ---- examples -------------------------------------------------------------------------------------------

BOOST_AUTO_TEST_CASE(paper_example_loads_as_specified) {
  const Scene s = load_scene(kExamples + "paper_fourbar.json");
  const auto& m = s.mechanism;
  BOOST_TEST(m.links.size() == 4u);
  BOOST_TEST(m.links[m.ground].name == "link1");
  std::vector<std::string> names;
  for (const auto& v : m.variables) names.push_back(v.name);
  const std::vector<std::string> expected{"O_A.theta2", "A.x", "A.theta23", "B.theta34", "B.theta4", "O_B.theta5"};
  BOOST_TEST(names == expected, boost::test_tools::per_element());
  BOOST_TEST(m.drivers == std::vector<int>{0}, boost::test_tools::per_element());
  BOOST_TEST(s.held == (std::vector<int>{1, 2}), boost::test_tools::per_element());
  BOOST_TEST(s.guess(2) == deg_to_rad(180.0));
  BOOST_TEST(s.guess(5) == deg_to_rad(60.0));
  BOOST_TEST(m.contours[0].name() == "link2.parabola");
  BOOST_TEST(!m.contours[0].reversed());  // "inside" the cup = the natural left side for a > 0
  BOOST_TEST(m.pairs[3].frame_a.translation().x() == 7.0);
  BOOST_TEST(m.pairs[3].frame_a.translation().y() == -2.0);
  BOOST_REQUIRE(s.sweep.has_value());
  BOOST_TEST(s.sweep->input == "O_A.theta2");
  const std::vector<double> in = rollkin::sweep_inputs(*s.sweep);
  BOOST_TEST(in.size() == 151u);
  BOOST_TEST(in.front() == deg_to_rad(-50.0), boost::test_tools::tolerance(1e-15));
  BOOST_TEST(in.back() == deg_to_rad(100.0), boost::test_tools::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(paper_example_assembles_at_the_reference_pose) {
  const Scene s = load_scene(kExamples + "paper_fourbar.json");
  rollkin::SolveData<double> sd(s.mechanism);
  rollkin::VectorX<double> q = s.guess;
  const auto rep = rollkin::assemble(s.mechanism, q, sd, s.held);
  BOOST_TEST(rep.ok());
  const auto poses = rollkin::link_poses(s.mechanism, sd.kin);
  BOOST_TEST(poses[2].translation().x() == 3.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(std::abs(poses[2].translation().y()) < 1e-12);
  // Disk 4's centre: the upper point 5 from (3, 0) and 2 from O_B, about (7.99303, -0.26394).
  const auto c4 = poses[3].act(rollkin::Vec2<double>(2, 0));
  BOOST_TEST(c4.x() == 7.99303, boost::test_tools::tolerance(1e-5));
  BOOST_TEST(c4.y() == -0.26394, boost::test_tools::tolerance(1e-4));
}

BOOST_AUTO_TEST_CASE(other_examples_load) {
  const Scene h = load_scene(kExamples + "hypocycloid.json");
  BOOST_TEST(h.mechanism.contours[0].reversed());  // ring: material outside
  BOOST_TEST(!h.mechanism.contours[1].reversed());
  const Scene g = load_scene(kExamples + "elliptical_gears.json");
  BOOST_TEST(g.mechanism.rolling_pairs.size() == 1u);
  BOOST_TEST(g.held == std::vector<int>{2}, boost::test_tools::per_element());
  const Scene c = load_scene(kExamples + "elliptical_gears_cam.json");
  BOOST_TEST(c.mechanism.rolling_pairs.empty());
  const Scene o = load_scene(kExamples + "paper_fourbar_osculating.json");
  BOOST_TEST(o.mechanism.contours[0].reversed());  // material outside the cup
}

// ---- sweep ------------------------------------------------------------------------------------------------

BOOST_AUTO_TEST_CASE(sweep_inputs_include_the_end_on_the_grid) {
  rollkin::Sweep s;
  s.from = 0;
  s.to = 1;
  s.step = 0.1;
  BOOST_TEST(rollkin::sweep_inputs(s).size() == 11u);
  s.to = 1.05;
  BOOST_TEST(rollkin::sweep_inputs(s).size() == 11u);
  s.from = 10;
  s.to = 0;
  s.step = -2.5;
  const auto down = rollkin::sweep_inputs(s);
  BOOST_TEST(down.size() == 5u);
  BOOST_TEST(down.back() == 0.0);
  s.step = 2.5;
  BOOST_CHECK_THROW(rollkin::sweep_inputs(s), std::invalid_argument);
  s.step = 0;
  BOOST_CHECK_THROW(rollkin::sweep_inputs(s), std::invalid_argument);
  s.from = s.to = 3;
  s.step = 1;
  BOOST_TEST(rollkin::sweep_inputs(s).size() == 1u);
  s.unit = deg_to_rad(1.0);
  BOOST_TEST(rollkin::sweep_inputs(s).front() == deg_to_rad(3.0), boost::test_tools::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(radians_file_keeps_angles) {
  std::string text = paper_with("\"angle\": \"deg\"", "\"angle\": \"rad\"");
  const Scene s = load_scene(write_temp("rad.json", text));
  BOOST_TEST((s.angle_unit == rollkin::io::AngleUnit::Radian));
  BOOST_TEST(s.guess(2) == 180.0);  // taken as radians, as written
  BOOST_TEST(s.unit_of(2) == 1.0);
  BOOST_TEST(s.unit_label(2) == "rad");
  BOOST_TEST(s.unit_label(1) == "m");
}

// ---- errors -------------------------------------------------------------------------------------------------

BOOST_AUTO_TEST_CASE(malformed_json_gives_line_and_column) {
  const std::string msg = error_for("malformed.json", "{\n  \"links\": [\n    {\"name\": \"a\" \"ground\": true}\n  ]\n}\n");
  BOOST_TEST(contains(msg, "malformed.json:3:"));
  BOOST_TEST(contains(msg, "malformed JSON"));
}

BOOST_AUTO_TEST_CASE(unknown_keys_list_the_allowed_ones) {
  expect_error("top_key.json", paper_with("\"inputs\"", "\"input\""), "input", "allowed keys here");
  expect_error("contour_key.json", paper_with("\"radius\": 1}", "\"radius\": 1, \"radiuss\": 2}"),
               "links[2].contours[0].radiuss", "\"radius\", \"arc\"");
  expect_error("pair_key.json", paper_with("\"variable\": \"theta5\"", "\"variable\": \"theta5\", \"vlaue\": 1"),
               "pairs[3].vlaue", "\"value\"");
}

BOOST_AUTO_TEST_CASE(wrong_types) {
  expect_error("radius_type.json", paper_with("\"radius\": 1}", "\"radius\": \"1\"}"), "links[2].contours[0].radius",
               "(a number), got a string");
  expect_error("hold_type.json", paper_with("\"hold\": [true, true]", "\"hold\": [true, 1]"), "pairs[1].hold[1]",
               "true or false");
  expect_error("ground_type.json", paper_with("\"ground\": true", "\"ground\": \"yes\""), "links[0].ground",
               "(true or false), got a string");
  expect_error("at_type.json", paper_with("\"at\": [{\"x\": 7, \"y\": -2}, {}]", "\"at\": {\"x\": 7, \"y\": -2}"),
               "pairs[3].at", "(an array), got an object");
}

BOOST_AUTO_TEST_CASE(unknown_types_list_the_allowed_ones) {
  expect_error("pair_type.json", paper_with("\"type\": \"rolling\"", "\"type\": \"rollin\""), "pairs[1].type",
               "\"revolute\", \"prismatic\", \"cam\", \"rolling\"");
  expect_error("contour_type.json", paper_with("\"type\": \"circle\"", "\"type\": \"cirlce\""),
               "links[2].contours[0].type", "\"line\", \"circle\", \"parabola\", \"ellipse\", \"samples\", \"bezier\", \"svg\", \"dxf\", \"nurbs\"");
  expect_error("angle_unit.json", paper_with("\"angle\": \"deg\"", "\"angle\": \"grad\""), "units.angle", "\"deg\" or \"rad\"");
  expect_error("material.json", paper_with("\"material\": \"inside\"", "\"material\": \"inner\""),
               "links[1].contours[0].material", "\"left\", \"right\", \"inside\", \"outside\"");
}

BOOST_AUTO_TEST_CASE(unknown_references_list_existing_names) {
  expect_error("link_ref.json", paper_with("\"links\": [\"link1\", \"link4\"]", "\"links\": [\"link1\", \"link5\"]"),
               "pairs[3].links[1]", "existing links: \"link1\", \"link2\", \"link3\", \"link4\"");
  expect_error("contour_ref.json", paper_with("[\"link3.rim\", \"link4.rim\"]", "[\"link3.rim\", \"link4.rimm\"]"),
               "pairs[2].contours[1]", "existing contours: \"link2.parabola\", \"link3.rim\", \"link4.rim\"");
  expect_error("input_ref.json", paper_with("\"inputs\": [\"O_A.theta2\"]", "\"inputs\": [\"O_A.theta\"]"), "inputs[0]",
               "existing variables: \"O_A.theta2\"");
  expect_error("sweep_input.json", paper_with("\"input\": \"O_A.theta2\"", "\"input\": \"O_B.theta5\""), "sweep.input",
               "one of \"O_A.theta2\"");
}

BOOST_AUTO_TEST_CASE(missing_contour_file) {
  const std::string msg = error_for("missing_file.json",
                                    paper_with("{\"name\": \"rim\", \"type\": \"circle\", \"radius\": 1}",
                                               "{\"name\": \"rim\", \"type\": \"samples\", \"file\": \"../shapes/none.txt\"}"));
  BOOST_TEST(contains(msg, "missing_file.json"));
  BOOST_TEST(contains(msg, "links[2].contours[0].file"));
  BOOST_TEST(contains(msg, "none.txt"));
  BOOST_TEST(contains(msg, "cannot open"));
}

BOOST_AUTO_TEST_CASE(short_and_degenerate_contours) {
  expect_error("three_samples.json",
               paper_with("\"type\": \"circle\", \"radius\": 1}",
                          "\"type\": \"samples\", \"points\": [[1, 0], [0, 1], [-1, 0]], \"closed\": true}"),
               "links[2].contours[0].points", "at least 4");
  write_temp("three.txt", "0 0\n1 0\n2 1\n");
  expect_error("three_samples_file.json",
               paper_with("\"type\": \"circle\", \"radius\": 1}", "\"type\": \"samples\", \"file\": \"three.txt\"}"),
               "three.txt", "at least 4");
  expect_error("zero_range.json", paper_with("\"x_range\": [-2, 2]", "\"x_range\": [1, 1]"), "links[1].contours[0].x_range",
               "contour too short");
  expect_error("radius.json", paper_with("\"radius\": 4", "\"radius\": -4"), "links[3].contours[0].radius", "radius > 0");
  expect_error("bowtie.json",
               paper_with("\"type\": \"circle\", \"radius\": 1}",
                          "\"type\": \"samples\", \"points\": [[0, 0], [1, 1], [1, 0], [0, 1]], \"closed\": true}"),
               "links[2].contours[0]", "invalid sampled contour");
}

BOOST_AUTO_TEST_CASE(bad_sweeps) {
  expect_error("step_zero.json", paper_with("\"step\": 1", "\"step\": 0"), "sweep.step", "sign of to - from");
  expect_error("step_sign.json", paper_with("\"step\": 1", "\"step\": -1"), "sweep.step", "wrong sign");
}

BOOST_AUTO_TEST_CASE(links_not_connected) {
  std::string text = paper_with("{\"name\": \"link4\",", "{\"name\": \"link5\"},\n    {\"name\": \"link4\",");
  expect_error("unconnected.json", text, "pairs", "'link5' is not connected to the ground");
}

BOOST_AUTO_TEST_CASE(duplicate_names) {
  expect_error("dup_link.json", paper_with("{\"name\": \"link3\",", "{\"name\": \"link2\","), "links[2].name",
               "duplicate link name \"link2\"");
  expect_error("dup_pair.json", paper_with("{\"name\": \"B\",", "{\"name\": \"A\","), "pairs[2].name",
               "duplicate pair name \"A\"");
  expect_error("dup_key.json", paper_with("\"radius\": 1}", "\"radius\": 1, \"radius\": 2}"), "links[2].contours[0].radius",
               "duplicate key \"radius\"");
  expect_error("dup_ground.json", paper_with("{\"name\": \"link2\",", "{\"name\": \"link2\", \"ground\": true,"),
               "links[1].ground", "exactly one ground link");
}

// ---- material sides and contact location ------------------------------------------------------------------

BOOST_AUTO_TEST_CASE(material_side_of_closed_samples_follows_their_orientation) {
  const std::string ccw = "[[1, 0], [0, 1], [-1, 0], [0, -1], [0.7, -0.7]]";
  const std::string cw = "[[0.7, -0.7], [0, -1], [-1, 0], [0, 1], [1, 0]]";
  for (const auto& [pts, reversed] : {std::pair{ccw, false}, std::pair{cw, true}}) {
    const Scene s = load_scene(write_temp("samples_side.json",
                                          paper_with("\"type\": \"circle\", \"radius\": 1}",
                                                     "\"type\": \"samples\", \"points\": " + pts + ", \"closed\": true}")));
    BOOST_TEST(s.mechanism.contours[1].reversed() == reversed);
  }
  const Scene p = load_scene(write_temp("parabola_down.json", paper_with("\"a\": 0.5", "\"a\": -0.5")));
  BOOST_TEST(p.mechanism.contours[0].reversed());  // a < 0: the focus side is the right of x increasing
}

BOOST_AUTO_TEST_CASE(contact_located_when_values_are_omitted) {
  std::string text = read_text(kExamples + "elliptical_gears.json");
  const std::string values = ", \"values\": [0, 180], \"hold\": [true, false]";
  text.replace(text.find(values), values.size(), "");
  const Scene s = load_scene(write_temp("gears_no_values.json", text));
  BOOST_TEST(s.guess(2) == 0.0, boost::test_tools::tolerance(1e-2));
  BOOST_TEST(std::abs(rollkin::wrap_angle(s.guess(3) - rollkin::pi<double>())) < 1e-2);
  // A contact pair on the spanning tree cannot be located: "values" required.
  expect_error("paper_no_values.json", paper_with(", \"values\": [0, 180], \"hold\": [true, true]", ""), "pairs[1]",
               "\"values\" required");
}

// ---- bad sample files through the scene (CGAL validation at the input boundary) ---------------------------

BOOST_AUTO_TEST_CASE(duplicate_and_self_intersecting_samples_name_the_file_and_samples) {
  // Disk 3 of the paper example as 64 samples of the unit circle, then spoiled two ways.
  auto circle = [](int n, int duplicate_at, bool figure_eight) {
    std::ostringstream os;
    os.precision(17);
    for (int k = 0; k < n; ++k) {
      const double t = 2 * 3.141592653589793 * k / n;
      if (figure_eight) os << std::sin(t) << " " << std::sin(2 * t) / 2 << "\n";  // lemniscate: crosses at 0
      else os << std::cos(t) << " " << std::sin(t) << "\n";
      if (k == duplicate_at) os << std::cos(t) << " " << std::sin(t) << "\n";
    }
    return os.str();
  };
  auto scene_with = [](const std::string& file) {
    return paper_with("{\"name\": \"rim\", \"type\": \"circle\", \"radius\": 1}",
                      "{\"name\": \"rim\", \"type\": \"samples\", \"file\": \"" + file + "\", \"closed\": true}");
  };
  write_temp("disk_duplicate.txt", circle(64, 10, false));
  const std::string dup = error_for("dup_samples.json", scene_with("disk_duplicate.txt"));
  BOOST_TEST(contains(dup, "disk_duplicate.txt"));
  // Named by the lines of the point file (the 11th and 12th lines), not by 0-based sample indices.
  BOOST_TEST(contains(dup, "the points on lines 11 and 12 coincide"));
  write_temp("disk_eight.txt", circle(64, -1, true));
  const std::string eight = error_for("eight_samples.json", scene_with("disk_eight.txt"));
  BOOST_TEST(contains(eight, "disk_eight.txt"));
  BOOST_TEST(contains(eight, "cross"));
}

// ---- units.length ------------------------------------------------------------------------------------------

BOOST_AUTO_TEST_CASE(length_unit_is_a_real_unit) {
  using rollkin::io::LengthUnit;
  const Scene mm = load_scene(write_temp("mm.json", paper_with("\"length\": \"m\"", "\"length\": \"mm\"")));
  BOOST_TEST((mm.length == LengthUnit::Millimetre));
  BOOST_TEST(mm.unit_label(1) == "mm");
  const Scene inch = load_scene(write_temp("in.json", paper_with("\"length\": \"m\"", "\"length\": \"in\"")));
  BOOST_TEST((inch.length == LengthUnit::Inch));
  // Without units.length the numbers are taken as they are; outputs keep the "m" label.
  const Scene none = load_scene(write_temp("no_units.json", paper_with("\"length\": \"m\", ", "")));
  BOOST_TEST((none.length == LengthUnit::Unitless));
  BOOST_TEST(none.unit_label(1) == "m");
}

BOOST_AUTO_TEST_CASE(unknown_length_unit_names_the_accepted_ones) {
  expect_error("furlong.json", paper_with("\"length\": \"m\"", "\"length\": \"furlong\""), "units.length",
               "unknown length unit \"furlong\"; expected one of \"m\", \"cm\", \"mm\", \"in\", \"ft\"");
  expect_error("metre.json", paper_with("\"length\": \"m\"", "\"length\": \"metre\""), "units.length", "\"mm\", \"in\"");
  expect_error("length_type.json", paper_with("\"length\": \"m\"", "\"length\": 1"), "units.length", "(a string), got a number");
}

BOOST_AUTO_TEST_CASE(closed_point_file_repeating_its_first_point_to_round_off_is_the_same_contour) {
  // 64 samples of the unit circle; the same with the first point repeated at the end, exactly and to
  // round-off (1e-13, far below the 1e-9 coincidence tolerance). The repeat must be dropped: the contours
  // must be the same spline (a kept repeat is a 1e-13 segment that bends the spline near the closure).
  auto circle = [](const std::string& repeat) {
    std::ostringstream os;
    os.precision(17);
    for (int k = 0; k < 64; ++k) os << std::cos(2 * 3.141592653589793 * k / 64) << " " << std::sin(2 * 3.141592653589793 * k / 64) << "\n";
    return os.str() + repeat;
  };
  auto contour_of = [](const std::string& file, const std::string& text) {
    write_temp(file, text);
    const Scene s = load_scene(write_temp(file + ".json", paper_with("{\"name\": \"rim\", \"type\": \"circle\", \"radius\": 1}",
                                                                     "{\"name\": \"rim\", \"type\": \"samples\", \"file\": \"" + file + "\", \"closed\": true}")));
    return s.mechanism.contours[s.mechanism.find_contour("link3.rim")];
  };
  const auto plain = contour_of("disk64.txt", circle(""));
  for (const std::string repeat : {"1 0\n", "1.0000000000001 1e-14\n"}) {
    const auto repeated = contour_of("disk64_repeat.txt", circle(repeat));
    BOOST_TEST_CONTEXT("repeat " << repeat) {
      BOOST_TEST(repeated.domain().hi == plain.domain().hi, boost::test_tools::tolerance(1e-12));
      double worst = 0;
      for (int i = 0; i < 640; ++i) {
        const double u = plain.domain().sample(i, 640);
        // kappa = (x' y'' - y' x'') / |p'|^3
        auto kappa = [u](const auto& c) {
          const auto j = c.jet(u, 2);
          return (j.d1.x() * j.d2.y() - j.d1.y() * j.d2.x()) / std::pow(j.d1.norm(), 3);
        };
        worst = std::max(worst, std::abs(kappa(repeated) - kappa(plain)));
      }
      BOOST_TEST(worst < 1e-6);  // curvature of the unit circle is 1
    }
  }
  // A point file line is named in the error about it: an open contour folding back.
  write_temp("fold.txt", "# header comment\nx y\n0 0\n1 0\n2 0\n1 0\n3 1\n");
  const std::string fold = error_for("fold.json", paper_with("{\"name\": \"rim\", \"type\": \"circle\", \"radius\": 1}",
                                                             "{\"name\": \"rim\", \"type\": \"samples\", \"file\": \"fold.txt\"}"));
  BOOST_TEST(contains(fold, "fold.txt"));
  BOOST_TEST(contains(fold, "line 5"));
}

BOOST_AUTO_TEST_CASE(hold_needs_values) {
  // Before: accepted, then "the loops cannot be closed" at assembly.
  expect_error("hold_no_values.json", paper_with("\"values\": [-3, 117]", "\"hold\": [true, false]"), "pairs[2].hold",
               "\"hold\" needs \"values\"");
  expect_error("hold_no_values2.json", paper_with("\"values\": [-3, 117]", "\"hold\": [false, true]"), "pairs[2].hold",
               "give \"values\": [u0, v0] or drop \"hold\"");
  BOOST_CHECK_NO_THROW(load_scene(write_temp("hold_false.json", paper_with("\"values\": [-3, 117]", "\"hold\": [false, false]"))));
}

BOOST_AUTO_TEST_CASE(json_errors_carry_line_column_and_full_path) {
  const std::string big = error_for("big.json", paper_with("\"radius\": 4,", "\"radius\": 1e400,"));
  BOOST_TEST(contains(big, "big.json:10:84: number 1e400 at links[3].contours[0].radius is out of the range of a double"));
  const std::string dup = error_for("dupkey.json", paper_with("\"radius\": 4,", "\"radius\": 4, \"radius\": 5,"));
  BOOST_TEST(contains(dup, "dupkey.json:10:90: duplicate key \"radius\" at links[3].contours[0].radius"));
  const std::size_t n = 1000000;
  const std::string deep = error_for("deep.json", paper_with("\"radius\": 4,", "\"radius\": 4, \"x\": " + std::string(n, '[') + std::string(n, ']') + ","));
  BOOST_TEST(contains(deep, "deep.json:10:"));
  BOOST_TEST(contains(deep, "nested deeper than 256 levels at links[3].contours[0].x[0][0]"));
}

// ---- scenes from a JSON document (build_scene): the Python module's scene(dict) and Scene.modified --------

BOOST_AUTO_TEST_CASE(build_scene_resolves_contour_files_against_the_given_directory) {
  const std::string file = kExamples + "dxf_cam.json";  // its cam is the DXF file "../shapes/cam_profile.dxf"
  const Scene from_file = load_scene(file);
  const nlohmann::ordered_json doc = rollkin::io::read_scene_document(file);
  const Scene built = rollkin::io::build_scene(doc, "in memory", kExamples);
  BOOST_TEST(built.file == "in memory");
  BOOST_TEST(built.files_read == from_file.files_read, boost::test_tools::per_element());
  BOOST_TEST(built.guess == from_file.guess);
  BOOST_TEST(built.mechanism.variable_count() == from_file.mechanism.variable_count());
  // Without a directory, relative files are looked up next to `file` (here: a directory that does not
  // exist), and the error names the file given and the JSON path of the contour file.
  const std::string msg = input_error_of([&] { rollkin::io::build_scene(doc, "no/such/dir/in memory"); });
  BOOST_TEST(contains(msg, "no/such/dir/in memory:links["));
  BOOST_TEST(contains(msg, "].file"));
  BOOST_TEST(contains(msg, "cam_profile.dxf"));
}

BOOST_AUTO_TEST_CASE(build_scene_checks_a_document_like_a_file) {
  nlohmann::ordered_json doc = rollkin::io::read_scene_document(kExamples + "paper_fourbar.json");
  rollkin::io::set_at_path(doc, "links[1].contours[0].a", "wide", "paper (modified)");
  const std::string msg = input_error_of([&] { rollkin::io::build_scene(doc, "paper (modified)"); });
  BOOST_TEST(contains(msg, "paper (modified):links[1].contours[0].a: expected"));
  BOOST_TEST(input_error_of([] { rollkin::io::build_scene(nlohmann::ordered_json::array(), "doc"); }) ==
             "doc: the scene must be a JSON object, got an array");
  // The same document as text and as a document give the same scene.
  rollkin::io::set_at_path(doc, "links[1].contours[0].a", 0.625, "paper (modified)");
  const Scene a = rollkin::io::build_scene(doc, "x.json");
  const Scene b = rollkin::io::parse_scene(doc.dump(), "x.json");
  BOOST_TEST(a.guess == b.guess);
  BOOST_TEST(a.mechanism.contours[0].jet(0.3, 2).p == b.mechanism.contours[0].jet(0.3, 2).p);
}

BOOST_AUTO_TEST_CASE(requested_sweep_is_the_scenes_with_the_values_given) {
  const Scene paper = load_scene(kExamples + "paper_fourbar.json");  // sweep O_A.theta2 from -50 to 100 step 1
  const auto same = rollkin::io::requested_sweep(paper, std::nullopt, std::nullopt, std::nullopt);
  BOOST_REQUIRE(same.has_value());
  BOOST_TEST(same->input == "O_A.theta2");
  BOOST_TEST(same->from == -50.0);
  BOOST_TEST(same->to == 100.0);
  BOOST_TEST(same->step == 1.0);
  const auto moved = rollkin::io::requested_sweep(paper, 10.0, std::nullopt, 0.5);
  BOOST_TEST(moved->from == 10.0);
  BOOST_TEST(moved->to == 100.0);
  BOOST_TEST(moved->step == 0.5);
  BOOST_TEST(moved->variable == same->variable);
  // Without a "sweep", the first input is swept, and only when all three values are given.
  const Scene bare = load_scene(write_temp("no_sweep.json",
                                           paper_with(",\n  \"sweep\": {\"input\": \"O_A.theta2\", \"from\": -50, \"to\": 100, \"step\": 1}", "")));
  BOOST_REQUIRE(!bare.sweep.has_value());
  BOOST_TEST(!rollkin::io::requested_sweep(bare, 0.0, 10.0, std::nullopt).has_value());
  const auto given = rollkin::io::requested_sweep(bare, 0.0, 10.0, 2.0);
  BOOST_REQUIRE(given.has_value());
  BOOST_TEST(given->input == "O_A.theta2");
  BOOST_TEST(given->variable == bare.mechanism.drivers[0]);
  BOOST_TEST(std::abs(given->unit - std::acos(-1.0) / 180) <= 1e-16);
  BOOST_TEST(given->from == 0.0);
  BOOST_TEST(given->to == 10.0);
}
