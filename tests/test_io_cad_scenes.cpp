// Whole scenes whose contours come from CAD files (DXF, SVG) or inline NURBS, solved and compared with the
// analytic scene they draw and with closed forms: the paper's parabola as a 2-span quadratic SPLINE in
// millimetres (same joint angles as examples/paper_fourbar.json to 1e-9 deg), a disk of two bulge arcs rolling
// on a LINE (the cycloid: disk angle = -travel / r), an SVG circle inside transformed groups (same as the
// analytic cycloid scene), and an exact rational NURBS circle rolling inside a ring (the hypocycloid: planet
// angle -3 phi, relative to the arm -4 phi). The DXF fixtures are written by ezdxf
// (tests/data/dxf/make_fixtures.py, scenes_mm.dxf).
#define BOOST_TEST_MODULE io_cad_scenes
#include <boost/test/unit_test.hpp>

#include "test_support.hpp"

#include "rollkin/io/scene/reader.hpp"
#include "rollkin/solve/continuation.hpp"
#include "rollkin/solve/position.hpp"

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

using namespace rollkin;
using namespace rollkin::testing;

namespace {

namespace fs = std::filesystem;

const std::string kExamples = std::string(ROLLKIN_SOURCE_DIR) + "/examples/";
const std::string kDxf = std::string(ROLLKIN_SOURCE_DIR) + "/tests/data/dxf/";

std::string number(double x) {
  std::ostringstream os;
  os.precision(17);
  os << x;
  return os.str();
}

/// `text` with `from` replaced by `to` (which must occur).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  BOOST_REQUIRE_MESSAGE(at != std::string::npos, "test setup: \"" << from << "\" not found");
  return text.replace(at, from.size(), to);
}

io::Scene scene_from(const std::string& name, const std::string& text) {
  return io::load_scene(write_text(scratch_dir("io_cad_scenes") / name, text));
}

/// The scene's own sweep from its assembly, limits allowed.
SweepResult<double> swept(const io::Scene& s) {
  BOOST_REQUIRE(s.sweep.has_value());
  const Mechanism<double>& m = s.mechanism;
  SolveData<double> sd(m);
  VectorX<double> q = s.guess;
  const SolveReport<double> rep = assemble(m, q, sd, s.held);
  BOOST_REQUIRE_MESSAGE(rep.ok(), "assembly: " << to_string(rep.status));
  return sweep(m, sd, q, rep, s.sweep->driver, sweep_inputs(*s.sweep));
}

/// The scene's own sweep, solved; every pose must be ok.
SweepResult<double> solved(const io::Scene& s) {
  SweepResult<double> r = swept(s);
  BOOST_REQUIRE(r.all_solved());
  return r;
}

/// Largest difference (radians) of the named angle variables between two solved sweeps of the same inputs.
double worst_angle_difference(const io::Scene& a, const SweepResult<double>& ra, const io::Scene& b,
                              const SweepResult<double>& rb, const std::vector<std::string>& names) {
  BOOST_REQUIRE_EQUAL(ra.poses.size(), rb.poses.size());
  double worst = 0;
  for (const std::string& n : names) {
    const int ia = a.mechanism.find_variable(n), ib = b.mechanism.find_variable(n);
    BOOST_REQUIRE_MESSAGE(ia >= 0 && ib >= 0, "variable " << n);
    for (std::size_t k = 0; k < ra.poses.size(); ++k) {
      BOOST_REQUIRE_EQUAL(ra.poses[k].input, rb.poses[k].input);
      worst = std::max(worst, std::abs(ra.poses[k].q(ia) - rb.poses[k].q(ib)));
    }
  }
  return worst;
}

const double kDeg = M_PI / 180;

/// The paper example with its parabola read from layer `layer` of DXF `file` (with the arc-length parameter,
/// the contact held at the vertex: arc length sqrt(5) + asinh(2) / 2 from (-2, 2)), written as `scene_name`:
/// the worst difference of its coupler and rocker angles from the analytic example's over the 151 poses.
double paper_from_dxf(const std::string& file, const std::string& layer, const std::string& scene_name) {
  const std::string analytic_text = read_text(kExamples + "paper_fourbar.json");
  const double vertex = std::sqrt(5.0) + std::asinh(2.0) / 2;
  std::string text = replaced(analytic_text,
                              "\"type\": \"parabola\", \"a\": 0.5, \"x_range\": [-2, 2],",
                              "\"type\": \"dxf\", \"file\": \"" + kDxf + file + "\", \"layer\": \"" + layer + "\", "
                              "\"parameter\": \"arc_length\",");
  text = replaced(text, "\"material\": \"inside\"", "\"material\": \"left\"");
  text = replaced(text, "\"values\": [0, 180]", "\"values\": [" + number(vertex) + ", 180]");
  const io::Scene analytic = io::load_scene(kExamples + "paper_fourbar.json");
  const io::Scene dxf = scene_from(scene_name, text);
  BOOST_TEST(dxf.files_read.back() == kDxf + file);
  const auto ra = solved(analytic), rd = solved(dxf);
  BOOST_TEST(ra.poses.size() == 151u);
  return worst_angle_difference(analytic, ra, dxf, rd, {"A.theta23", "B.theta34", "B.theta4", "O_B.theta5"});
}

}  // namespace

// (a) The paper's parabola y = 0.5 x^2, x in [-2, 2] m, drawn in mm as a 2-span quadratic SPLINE ($INSUNITS 4),
// converted to the scene's metres, with the arc-length parameter: the contact is held at the vertex, at arc
// length sqrt(5) + asinh(2) / 2 from (-2, 2) (the integral of sqrt(1 + x^2) over [-2, 0]).
BOOST_AUTO_TEST_CASE(paper_parabola_as_mm_spline_gives_the_papers_angles) {
  const double worst = paper_from_dxf("scenes_mm.dxf", "PARABOLA_MM", "paper_dxf.json");
  BOOST_TEST_MESSAGE("paper parabola from DXF: worst angle difference " << worst / kDeg << " deg");
  BOOST_TEST(worst < 1e-9 * kDeg);
}

// (b) A disk of radius 1000 mm made of two bulge arcs (closed LWPOLYLINE) rolling on a LINE, in a scene in
// metres: the cycloid, disk angle = -travel / r with r = 1 m.
BOOST_AUTO_TEST_CASE(two_bulge_disk_rolling_on_a_dxf_line_is_the_cycloid) {
  std::string text = read_text(kExamples + "cycloid.json");
  text = replaced(text, "\"type\": \"line\", \"from\": -10, \"to\": 10,",
                  "\"type\": \"dxf\", \"file\": \"" + kDxf + "scenes_mm.dxf\", \"layer\": \"TRACK_MM\", \"parameter\": \"arc_length\",");
  text = replaced(text, "\"type\": \"circle\", \"radius\": 1}",
                  "\"type\": \"dxf\", \"file\": \"" + kDxf + "scenes_mm.dxf\", \"layer\": \"DISK_MM\", \"parameter\": \"arc_length\"}");
  // Contact guesses: the disk's bottom (0, -1) is 3/4 of its circumference from (1, 0); the track's origin
  // is 10 m from its start.
  text = replaced(text, "\"values\": [-90, 0]", "\"values\": [" + number(1.5 * M_PI) + ", 10]");
  const io::Scene s = scene_from("cycloid_dxf.json", text);
  const auto r = solved(s);
  const int travel = s.mechanism.find_variable("S.s"), turn = s.mechanism.find_variable("H.psi");
  BOOST_REQUIRE(travel >= 0 && turn >= 0);
  // The disk's angle at the start depends on which rim point the assembly put in contact (the guesses are
  // not held); the closed form is about its change: psi - psi_0 = -(s - s_0) / r.
  BOOST_REQUIRE(r.poses.front().input == 0.0);
  const double psi0 = r.poses.front().q(turn);
  double worst = 0;
  for (const auto& p : r.poses) worst = std::max(worst, std::abs((p.q(turn) - psi0) - (-p.q(travel) / 1.0)));
  BOOST_TEST_MESSAGE("cycloid from DXF: worst |psi + s / r| " << worst << " rad");
  BOOST_TEST(r.poses.size() == 21u);
  BOOST_TEST(worst < 1e-9 * kDeg);
}

// (a') The paper's parabola inside a block, placed by an INSERT rotated by 33 degrees and mirrored (x scale -1)
// with a base point (blocks_mm.dxf: the block holds the parabola mapped back), selected by the INSERT's layer:
// the paper's angles to 1e-9 deg, as (a).
BOOST_AUTO_TEST_CASE(paper_parabola_inside_a_rotated_mirrored_insert_gives_the_papers_angles) {
  const double worst = paper_from_dxf("blocks_mm.dxf", "PARABOLA_INS", "paper_insert.json");
  BOOST_TEST_MESSAGE("paper parabola in a rotated, mirrored INSERT: worst angle difference " << worst / kDeg << " deg");
  BOOST_TEST(worst < 1e-9 * kDeg);
}

// (b') The cycloid from one layer that holds everything (blocks_mm.dxf, layer 0): the rim of a wheel block
// (two ARCs, radius 1000 mm, with a hub circle and centre marks beside it) inserted rotated and mirrored, and
// the track LINE through it, each picked by "near" a point beside it. Closed form as (b): psi - psi_0 = -s / r.
// The rim's chain starts at the first ARC's start, block angle 0, which the INSERT puts at 213 degrees, and
// runs clockwise (mirrored); with its material inside it is taken the other way round from there, so the
// bottom of the disk (the contact guess) is 57 degrees of arc (r = 1 m) along it.
BOOST_AUTO_TEST_CASE(disk_and_track_picked_by_near_from_a_shared_layer_roll_as_the_cycloid) {
  std::string text = read_text(kExamples + "cycloid.json");
  text = replaced(text, "\"type\": \"line\", \"from\": -10, \"to\": 10,",
                  "\"type\": \"dxf\", \"file\": \"" + kDxf + "blocks_mm.dxf\", \"layer\": \"0\", \"near\": [5000, 3], "
                  "\"parameter\": \"arc_length\",");
  text = replaced(text, "\"type\": \"circle\", \"radius\": 1}",
                  "\"type\": \"dxf\", \"file\": \"" + kDxf + "blocks_mm.dxf\", \"layer\": \"0\", \"near\": [0, 1001], "
                  "\"parameter\": \"arc_length\"}");
  text = replaced(text, "\"values\": [-90, 0]", "\"values\": [" + number(57 * kDeg) + ", 10]");
  const io::Scene s = scene_from("cycloid_near.json", text);
  const auto r = solved(s);
  const int travel = s.mechanism.find_variable("S.s"), turn = s.mechanism.find_variable("H.psi");
  BOOST_REQUIRE(travel >= 0 && turn >= 0);
  BOOST_REQUIRE(r.poses.front().input == 0.0);
  const double psi0 = r.poses.front().q(turn);
  double worst = 0;
  for (const auto& p : r.poses) worst = std::max(worst, std::abs((p.q(turn) - psi0) - (-p.q(travel) / 1.0)));
  BOOST_TEST_MESSAGE("cycloid from a shared layer by near: worst |psi + s / r| " << worst << " rad");
  BOOST_TEST(r.poses.size() == 21u);
  BOOST_TEST(worst < 1e-9 * kDeg);
  // without "near" the layer is refused, listing its chains (rim, hub, two centre marks, track)
  const std::string whole = replaced(text, "\"near\": [0, 1001], ", "");
  const std::string msg = input_error_of([&] { scene_from("cycloid_layer.json", whole); });
  BOOST_TEST(contains(msg, "form 5 chains"));
  BOOST_TEST(contains(msg, "in INSERT"));
}

// (c) The cycloid's disk drawn as an SVG <circle> inside nested transformed groups, in a mm document, for a
// scene in cm: the same disk angles as the analytic scene (radius 1 cm) and the closed form.
BOOST_AUTO_TEST_CASE(svg_circle_in_transformed_groups_matches_the_analytic_cycloid) {
  // Centre: scale(2) then rotate(30) keep (0, 0); translate(50 50) moves it to (50, 50) mm, flipped (50, -50)
  // mm = (5, -5) cm, put back on the link's origin by "at". Radius 2 * 5 mm = 1 cm.
  // The same disk drawn as a drawing holds it: a <use> clone of a circle in <defs>; in a group with its hub
  // (radius 2 mm) selected by "subpath" and by "near" (in the contour's coordinates: cm, y up, before "at"); as
  // the second subpath of a compound path (the hub first); inside Illustrator's <switch>.
  struct Variant {
    std::string name, drawing, selector;
  };
  const std::string hub = "<circle cx=\"0\" cy=\"0\" r=\"1\"/>";
  const std::vector<Variant> variants = {
      {"circle", "<circle id=\"disk\" cx=\"0\" cy=\"0\" r=\"5\"/>", "\"path\": \"disk\""},
      {"use", "<defs><circle id=\"proto\" r=\"5\"/></defs><use id=\"disk\" href=\"#proto\"/>", "\"path\": \"disk\""},
      {"group_subpath", "<g id=\"part\">" + hub + "<circle cx=\"0\" cy=\"0\" r=\"5\"/></g>", "\"path\": \"part\", \"subpath\": 2"},
      {"group_near", "<g id=\"part\">" + hub + "<circle cx=\"0\" cy=\"0\" r=\"5\"/></g>", "\"near\": [5.6, -4.3]"},
      {"compound", "<path id=\"part\" d=\"M 1 0 A 1 1 0 0 1 -1 0 A 1 1 0 0 1 1 0 Z M 5 0 A 5 5 0 0 1 -5 0 A 5 5 0 0 1 5 0 Z\"/>",
       "\"path\": \"part\", \"subpath\": 2"},
      {"switch", "<switch><foreignObject requiredExtensions=\"http://ns.adobe.com/AdobeIllustrator/10.0/\"/>"
                 "<g><circle id=\"disk\" cx=\"0\" cy=\"0\" r=\"5\"/></g></switch>", "\"path\": \"disk\""}};
  std::string analytic_text = replaced(read_text(kExamples + "cycloid.json"), "\"length\": \"m\"", "\"length\": \"cm\"");
  const io::Scene analytic = scene_from("cycloid_cm.json", analytic_text);
  const auto ra = solved(analytic);
  const int turn_a = analytic.mechanism.find_variable("H.psi");
  for (const Variant& v : variants) {
    BOOST_TEST_CONTEXT(v.name) {
      const std::string svg =
          "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100mm\" height=\"100mm\" viewBox=\"0 0 100 100\">\n"
          "  <g transform=\"translate(50 50) rotate(30)\">\n"
          "    <g transform=\"scale(2)\">" + v.drawing + "</g>\n"
          "  </g>\n"
          "</svg>\n";
      const std::string svg_file = write_text(scratch_dir("io_cad_scenes") / ("disk_" + v.name + ".svg"), svg);
      const std::string text = replaced(analytic_text, "\"type\": \"circle\", \"radius\": 1}",
                                        "\"type\": \"svg\", \"file\": \"" + svg_file + "\", " + v.selector +
                                            ", \"at\": {\"x\": -5, \"y\": 5}}");
      const io::Scene s = scene_from("cycloid_svg_" + v.name + ".json", text);
      const auto rs = solved(s);
      const int travel = s.mechanism.find_variable("S.s"), turn = s.mechanism.find_variable("H.psi");
      // Disk angles counted from the first pose (s = 0): the SVG circle's start point is rotated by the groups,
      // so the rim point the assembly puts in contact, and with it the initial psi, may differ.
      const double psi0 = rs.poses.front().q(turn), psi0_a = ra.poses.front().q(turn_a);
      double worst = 0, closed_form = 0;
      BOOST_REQUIRE_EQUAL(rs.poses.size(), ra.poses.size());
      for (std::size_t k = 0; k < rs.poses.size(); ++k) {
        const double dpsi = rs.poses[k].q(turn) - psi0;
        worst = std::max(worst, std::abs(dpsi - (ra.poses[k].q(turn_a) - psi0_a)));
        closed_form = std::max(closed_form, std::abs(dpsi + rs.poses[k].q(travel)));
      }
      BOOST_TEST_MESSAGE("cycloid from SVG (" << v.name << "): vs analytic " << worst << " rad, vs closed form "
                                              << closed_form << " rad");
      BOOST_TEST(worst < 1e-9 * kDeg);
      BOOST_TEST(closed_form < 1e-9 * kDeg);
    }
  }
}

// A straight run drawn through many collinear vertices of different spacing is one line: a disk rolls along
// it on the native parameter, every pose ok, as on an analytic line (the cycloid: disk angle = -travel / r).
// Before, the parameter's speed jumped at every vertex (2.5 and 7.5 mm pieces in turn) and the sweep stopped
// with no_convergence after 1.14 m (300,000 such vertices: `singular` poses). For every reader that builds a
// path: the DXF LWPOLYLINE of 2001 vertices (straight_mm.dxf, RUN) and the same run as an SVG path.
BOOST_AUTO_TEST_CASE(a_straight_run_of_collinear_vertices_is_one_line_for_every_reader) {
  const std::string middle = read_text(kDxf + "straight_mm.RUN.txt");
  BOOST_REQUIRE(contains(middle, "# vertices 2001") && contains(middle, "# middle_vertex 1000"));
  std::string d = "M -5000 0";
  for (int k = 0; k < 2000; ++k) d += " L " + number(-5000 + 5 * k + (k % 2 ? 5 : 2.5)) + " 0";  // 2.5, 7.5 mm in turn
  const std::string svg_file = write_text(scratch_dir("io_cad_scenes") / "run.svg",
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"10000mm\" height=\"20mm\" viewBox=\"0 0 10000 20\">\n"
      "  <path id=\"run\" d=\"" + d + "\"/>\n</svg>\n");
  const std::string tracks[] = {"\"type\": \"dxf\", \"file\": \"" + kDxf + "straight_mm.dxf\", \"layer\": \"RUN\",",
                                "\"type\": \"svg\", \"file\": \"" + svg_file + "\", \"path\": \"run\","};
  for (const std::string& track : tracks) {
    BOOST_TEST_CONTEXT(track) {
      std::string text = replaced(read_text(kExamples + "cycloid.json"), "\"type\": \"line\", \"from\": -10, \"to\": 10,", track);
      // One line piece, reversed by "material": "right": its middle at -0.5. Three quarters of a turn (4.7 m).
      text = replaced(text, "\"values\": [-90, 0]", "\"values\": [-90, -0.5]");
      text = replaced(text, "\"to\": 6.283185307179586", "\"to\": " + number(1.5 * M_PI));
      const io::Scene s = scene_from("straight_run.json", text);
      const Domain<double> domain = s.mechanism.contours[s.mechanism.find_contour("ground.track")].domain();
      BOOST_TEST(domain.hi - domain.lo == 1.0);
      const SweepResult<double> r = solved(s);
      const int travel = s.mechanism.find_variable("S.s"), turn = s.mechanism.find_variable("H.psi");
      double closed_form = 0;
      for (const auto& pose : r.poses) closed_form = std::max(closed_form, std::abs(pose.q(turn) + pose.q(travel)));
      BOOST_TEST_MESSAGE("straight run: " << r.poses.size() << " poses, |psi + s / r| up to " << closed_form);
      BOOST_TEST(r.poses.size() == 16u);
      BOOST_TEST(closed_form < 1e-12);
    }
  }
}

// A run whose every joint is within round-off of its neighbours' line but which bends away from its chord
// (y = 1e-16 (x - 500)^2 through 1001 vertices: 2.5e-11 off the chord, more than its round-off) is not one
// line: its pieces stay as drawn.
BOOST_AUTO_TEST_CASE(a_run_that_bends_off_its_chord_keeps_its_pieces) {
  std::string d = "M 0 0";
  for (int k = 0; k <= 1000; ++k) d += (k ? " L " : " M ") + number(k) + " " + number(1e-16 * (k - 500.0) * (k - 500.0));
  d = d.substr(std::string("M 0 0 ").size());
  const std::string svg_file = write_text(scratch_dir("io_cad_scenes") / "bend.svg",
      "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 1000 10\">\n  <path id=\"bend\" d=\"" + d + "\"/>\n</svg>\n");
  std::string text = replaced(read_text(kExamples + "cycloid.json"), "\"type\": \"line\", \"from\": -10, \"to\": 10,",
                              "\"type\": \"svg\", \"file\": \"" + svg_file + "\", \"path\": \"bend\",");
  const io::Scene s = scene_from("bend.json", text);
  const Domain<double> domain = s.mechanism.contours[s.mechanism.find_contour("ground.track")].domain();
  BOOST_TEST(domain.hi - domain.lo == 1000.0);
}

// The same for arcs of one circle: a disk of radius 10 on an arm about the centre of a track of radius 500
// drawn as 1,200 LWPOLYLINE arcs of 0.05 and 0.15 degrees in turn rolls over it (one arc of two pieces), every
// pose ok, turning as the epicycloid's planet: psi - psi0 = (R / r) (phi - phi0) relative to the arm. Before, the
// sweep stopped at its first step with no_convergence.
BOOST_AUTO_TEST_CASE(a_run_of_arcs_of_one_circle_is_one_arc_for_a_rolling_disk) {
  const double R = 500, r = 10, to_rad = M_PI / 180;
  std::string groups = "0\nLWPOLYLINE\n5\n7C\n8\nT\n90\n1201\n70\n0\n";
  double a = 150;
  for (int k = 0; k <= 1200; ++k) {
    const double next = a - (k % 2 ? 0.15 : 0.05);
    groups += "10\n" + number(R * std::cos(a * to_rad)) + "\n20\n" + number(R * std::sin(a * to_rad)) + "\n42\n" +
              number(k < 1200 ? std::tan((next - a) * to_rad / 4) : 0.0) + "\n";
    a = next;
  }
  const std::string dxf = write_text(scratch_dir("io_cad_scenes") / "one_circle.dxf",
                                     "0\nSECTION\n2\nENTITIES\n" + groups + "0\nENDSEC\n0\nEOF\n");
  const std::string text =
      "{\"units\": {\"length\": \"mm\", \"angle\": \"deg\"},\n"
      " \"links\": [{\"name\": \"ground\", \"ground\": true, \"contours\": [{\"name\": \"track\", \"type\": \"dxf\", \"file\": \"" + dxf +
      "\", \"layer\": \"T\", \"material\": \"right\"}]},\n"
      "   {\"name\": \"arm\"}, {\"name\": \"disk\", \"contours\": [{\"name\": \"rim\", \"type\": \"circle\", \"radius\": 10}]}],\n"
      " \"pairs\": [{\"name\": \"A\", \"type\": \"revolute\", \"links\": [\"ground\", \"arm\"], \"variable\": \"phi\", \"value\": 90},\n"
      "   {\"name\": \"H\", \"type\": \"revolute\", \"links\": [\"arm\", \"disk\"], \"at\": [{\"x\": 510}, {}], \"variable\": \"psi\", \"value\": 0},\n"
      "   {\"name\": \"C\", \"type\": \"rolling\", \"contours\": [\"disk.rim\", \"ground.track\"], \"variables\": [\"u\", \"x\"], \"values\": [-90, -1]}],\n"
      " \"inputs\": [\"A.phi\"], \"sweep\": {\"from\": 90, \"to\": 60, \"step\": -0.5}}\n";
  const io::Scene s = scene_from("one_circle.json", text);
  const Domain<double> domain = s.mechanism.contours[s.mechanism.find_contour("ground.track")].domain();
  BOOST_TEST(domain.hi - domain.lo == 2.0);
  const SweepResult<double> result = solved(s);
  const int phi = s.mechanism.find_variable("A.phi"), psi = s.mechanism.find_variable("H.psi");
  const double phi0 = result.poses.front().q(phi), psi0 = result.poses.front().q(psi);
  double worst = 0;
  for (const auto& pose : result.poses)
    worst = std::max(worst, std::abs((pose.q(psi) - psi0) - R / r * (pose.q(phi) - phi0)));
  BOOST_TEST_MESSAGE("arcs of one circle: " << result.poses.size() << " poses, |psi - psi0 - (R/r)(phi - phi0)| up to " << worst);
  BOOST_TEST(result.poses.size() == 61u);
  BOOST_TEST(worst < 1e-11);
}

// (d) The planet of examples/hypocycloid.json as an exact rational quadratic NURBS circle (9 control points,
// weights 1 and sqrt(2)/2): the planet turns -3 phi absolutely, -4 phi relative to the arm (r = 1, R = 4).
BOOST_AUTO_TEST_CASE(nurbs_circle_rolling_in_a_ring_is_the_hypocycloid) {
  const std::string nurbs =
      "\"type\": \"nurbs\", \"degree\": 2, \"knots\": [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1], "
      "\"points\": [[1, 0], [1, 1], [0, 1], [-1, 1], [-1, 0], [-1, -1], [0, -1], [1, -1], [1, 0]], "
      "\"weights\": [1, " + number(std::sqrt(0.5)) + ", 1, " + number(std::sqrt(0.5)) + ", 1, " + number(std::sqrt(0.5)) +
      ", 1, " + number(std::sqrt(0.5)) + ", 1], \"closed\": true, \"parameter\": \"arc_length\"}";
  const std::string analytic_text = read_text(kExamples + "hypocycloid.json");
  const std::string text = replaced(analytic_text, "\"type\": \"circle\", \"radius\": 1}", nurbs);
  const io::Scene analytic = io::load_scene(kExamples + "hypocycloid.json");
  const io::Scene s = scene_from("hypocycloid_nurbs.json", text);
  const auto ra = solved(analytic), rs = solved(s);
  const int phi = s.mechanism.find_variable("O.phi"), psi = s.mechanism.find_variable("P.psi");
  BOOST_REQUIRE(phi >= 0 && psi >= 0);
  double closed_form = 0;
  for (const auto& p : rs.poses) closed_form = std::max(closed_form, std::abs(p.q(psi) - (-4 * p.q(phi))));
  const double worst = worst_angle_difference(analytic, ra, s, rs, {"P.psi"});
  BOOST_TEST_MESSAGE("hypocycloid with a NURBS planet: vs closed form " << closed_form << " rad, vs analytic " << worst);
  BOOST_TEST(rs.poses.size() == 73u);
  BOOST_TEST(closed_form < 1e-9 * kDeg);
  BOOST_TEST(worst < 1e-9 * kDeg);
}

// ---- corners: a contact stops where its contour's tangent jumps ---------------------------------------------

namespace {

/// Checks a sweep of the cycloid scene (disk r = 1, centre at x = s) whose contact must stop at a corner at
/// s = corner_input: every pose before it ok with the rolling closed form psi - psi_0 = -s, the first pose
/// beyond it `corner`, the rest not reached, and the limit located to 1e-6. Returns the limit.
SolveReport<double> check_stops_at_corner(const io::Scene& s, const SweepResult<double>& r, double corner_input) {
  const int travel = s.mechanism.find_variable("S.s"), turn = s.mechanism.find_variable("H.psi");
  BOOST_REQUIRE(r.assembly.ok());
  BOOST_REQUIRE_EQUAL(r.limits.size(), 1u);
  const SolveReport<double>& limit = r.limits.front();
  BOOST_TEST_MESSAGE(limit.detail);
  BOOST_TEST(limit.status == SolveStatus::Corner);
  BOOST_TEST(std::abs(limit.limit_input - corner_input) < 1e-6);
  const double psi0 = r.poses.front().q(turn);
  bool beyond = false;
  for (const auto& p : r.poses) {
    const bool before = std::abs(p.input) < std::abs(corner_input);
    if (before) {
      BOOST_TEST(p.report.ok());
      BOOST_TEST(std::abs((p.q(turn) - psi0) + p.q(travel)) < 1e-9 * kDeg);
    } else {
      BOOST_TEST(p.report.status == (beyond ? SolveStatus::NotReached : SolveStatus::Corner));
      beyond = true;
    }
  }
  BOOST_TEST(beyond);
  return limit;
}

}  // namespace

// A disk rolling on an LWPOLYLINE that is flat up to x = 3 m and then falls at 45 degrees (a table's edge,
// drawn in mm by ezdxf): the contact reaches the vertex at s = 3 m and the sweep stops there with status
// corner, naming the polyline by its handle; with the arc-length and the native parameter.
BOOST_AUTO_TEST_CASE(a_disk_rolling_over_a_dxf_polyline_corner_stops_there_with_status_corner) {
  const std::string handle = read_text(kDxf + "scenes_mm.TABLE_MM.txt");
  const std::string key = "# entities ";
  const std::string entity = handle.substr(handle.find(key) + key.size(), handle.find('\n', handle.find(key)) - handle.find(key) - key.size());
  for (const std::string parameter : {"arc_length", "native"}) {
    BOOST_TEST_CONTEXT("parameter " << parameter) {
      const std::string text = replaced(read_text(kExamples + "cycloid.json"), "\"type\": \"line\", \"from\": -10, \"to\": 10,",
                                        "\"type\": \"dxf\", \"file\": \"" + kDxf + "scenes_mm.dxf\", \"layer\": \"TABLE_MM\", "
                                        "\"parameter\": \"" + parameter + "\",");
      const io::Scene s = scene_from("table_" + parameter + ".json", text);
      const Contour<double>& track = s.mechanism.contours[s.mechanism.find_contour("ground.track")];
      BOOST_REQUIRE_EQUAL(track.corners().size(), 1u);
      BOOST_TEST((track.corners()[0].point - Vec2<double>(3, 0)).norm() < 1e-15);
      const SolveReport<double> limit = check_stops_at_corner(s, swept(s), 3.0);
      BOOST_TEST(limit.contour == s.mechanism.find_contour("ground.track"));
      BOOST_TEST(contains(limit.detail, entity));
      BOOST_TEST(contains(limit.detail, "(3000, 0) mm"));
    }
  }
}

// A closed "D" (a half disk: a semicircle of radius 1 below a diameter) as one rational quadratic NURBS, rolled
// on its round side from its lowest point: each end of the diameter is a corner (90 degrees), reached after a
// quarter of the circumference in either direction, s = +-pi/2. One of them is the closing joint, where the
// parameter wraps.
BOOST_AUTO_TEST_CASE(a_half_disk_rolls_until_either_corner_of_its_diameter) {
  const std::string w = number(std::sqrt(0.5));
  const std::string half_disk =
      "\"type\": \"nurbs\", \"degree\": 2, \"knots\": [0, 0, 0, 1, 1, 2, 2, 3, 3, 3], "
      "\"points\": [[-1, 0], [-1, -1], [0, -1], [1, -1], [1, 0], [0, 0], [-1, 0]], "
      "\"weights\": [1, " + w + ", 1, " + w + ", 1, 1, 1], \"closed\": true, \"parameter\": \"arc_length\"}";
  std::string text = replaced(read_text(kExamples + "cycloid.json"), "\"type\": \"circle\", \"radius\": 1}", half_disk);
  text = replaced(text, "\"values\": [-90, 0]", "\"values\": [" + number(M_PI / 2) + ", 0]");
  text = replaced(text, "\"sweep\": {\"from\": 0, \"to\": 6.283185307179586, \"step\": 0.3141592653589793}",
                  "\"sweep\": {\"from\": 0, \"to\": 3, \"step\": 0.25}");
  for (const double sign : {1.0, -1.0}) {
    BOOST_TEST_CONTEXT("direction " << sign) {
      const std::string t = sign > 0 ? text : replaced(text, "\"to\": 3, \"step\": 0.25", "\"to\": -3, \"step\": -0.25");
      const io::Scene s = scene_from("half_disk.json", t);
      const Contour<double>& rim = s.mechanism.contours[s.mechanism.find_contour("disk.rim")];
      BOOST_REQUIRE_EQUAL(rim.corners().size(), 2u);
      const SolveReport<double> limit = check_stops_at_corner(s, swept(s), sign * M_PI / 2);
      BOOST_TEST(limit.contour == s.mechanism.find_contour("disk.rim"));
      BOOST_TEST(contains(limit.detail, "NURBS knot u = "));
    }
  }
}

// A tangent joint whose curvature jumps (line into arc) is no corner: the contact rolls through it, and
// --verbose (Scene::notes) says where the curvature jumps.
BOOST_AUTO_TEST_CASE(a_line_into_arc_join_rolls_through_and_its_curvature_jump_is_noted) {
  // The track: flat to x = 2, then a convex quarter arc of radius 5 falling away (centre (2, -5)), drawn as
  // a NURBS of degree 2: the line as a quadratic with its middle point between its ends.
  const std::string w = number(std::sqrt(0.5));
  const std::string track =
      "\"type\": \"nurbs\", \"degree\": 2, \"knots\": [0, 0, 0, 1, 1, 2, 2, 2], "
      "\"points\": [[-10, 0], [-4, 0], [2, 0], [7, 0], [7, -5]], \"weights\": [1, 1, 1, " + w + ", 1], "
      "\"parameter\": \"arc_length\",";
  std::string text = replaced(read_text(kExamples + "cycloid.json"), "\"type\": \"line\", \"from\": -10, \"to\": 10,", track);
  text = replaced(text, "\"values\": [-90, 0]", "\"values\": [-90, -10]");
  const io::Scene s = scene_from("line_into_arc.json", text);
  BOOST_TEST(s.mechanism.contours[s.mechanism.find_contour("ground.track")].corners().empty());
  bool noted = false;
  for (const std::string& n : s.notes) noted = noted || (contains(n, "curvature jumps from 0 to") && contains(n, "rolls through"));
  BOOST_TEST(noted);
}

BOOST_AUTO_TEST_CASE(dxf_selection_and_reader_errors_name_the_json_path) {
  const std::string base = read_text(kExamples + "cycloid.json");
  auto with = [&](const std::string& contour) { return replaced(base, "\"type\": \"circle\", \"radius\": 1}", contour); };
  const std::string file = "\"file\": \"" + kDxf + "scenes_mm.dxf\"";
  std::string msg = input_error_of([&] { scene_from("both.json", with("\"type\": \"dxf\", " + file + ", \"layer\": \"A\", \"handle\": \"2F\"}")); });
  BOOST_TEST(contains(msg, "links[2].contours[0].handle"));
  BOOST_TEST(contains(msg, "give one selector"));
  msg = input_error_of([&] { scene_from("none.json", with("\"type\": \"dxf\", " + file + "}")); });
  BOOST_TEST(contains(msg, "\"layer\", \"near\", \"handle\" or \"handles\""));
  msg = input_error_of([&] { scene_from("near.json", with("\"type\": \"dxf\", " + file + ", \"near\": [1]}")); });
  BOOST_TEST(contains(msg, "links[2].contours[0].near"));
  msg = input_error_of([&] { scene_from("handles.json", with("\"type\": \"dxf\", " + file + ", \"handles\": []}")); });
  BOOST_TEST(contains(msg, "links[2].contours[0].handles"));
  msg = input_error_of([&] { scene_from("nolayer.json", with("\"type\": \"dxf\", " + file + ", \"layer\": \"NO_SUCH\"}")); });
  BOOST_TEST_MESSAGE(msg);
  BOOST_TEST(contains(msg, "links[2].contours[0].file"));
  BOOST_TEST(contains(msg, "scenes_mm.dxf"));
  msg = input_error_of([&] { scene_from("gap.json", with("\"type\": \"dxf\", \"file\": \"" + kDxf + "errors.dxf\", \"layer\": \"GAP\"}")); });
  BOOST_TEST(contains(msg, "links[2].contours[0].file"));
  BOOST_TEST(contains(msg, "form 2 chains"));
}

BOOST_AUTO_TEST_CASE(svg_selection_errors_name_the_json_path) {
  const std::string base = read_text(kExamples + "cycloid.json");
  auto with = [&](const std::string& contour) { return replaced(base, "\"type\": \"circle\", \"radius\": 1}", contour); };
  const std::string svg = write_text(scratch_dir("io_cad_scenes") / "holes.svg",
      "<svg xmlns=\"http://www.w3.org/2000/svg\">\n<path id=\"plate\" d=\"M 0 0 h 4 v 4 h -4 z M 1 1 h 1 v 1 h -1 z\"/>\n</svg>\n");
  const std::string file = "\"type\": \"svg\", \"file\": \"" + svg + "\"";
  std::string msg = input_error_of([&] { scene_from("zero.json", with(file + ", \"path\": \"plate\", \"subpath\": 0}")); });
  BOOST_TEST(contains(msg, "links[2].contours[0].subpath: expected a whole number from 1 (subpaths count from 1), got 0"));
  msg = input_error_of([&] { scene_from("half.json", with(file + ", \"path\": \"plate\", \"subpath\": 1.5}")); });
  BOOST_TEST(contains(msg, "links[2].contours[0].subpath: expected a whole number from 1"));
  msg = input_error_of([&] { scene_from("both.json", with(file + ", \"subpath\": 1, \"near\": [0, 0]}")); });
  BOOST_TEST(contains(msg, "links[2].contours[0].subpath: give \"subpath\" or \"near\", not both"));
  msg = input_error_of([&] { scene_from("none.json", with(file + ", \"path\": \"plate\"}")); });
  BOOST_TEST(contains(msg, "links[2].contours[0].file"));
  BOOST_TEST(contains(msg, "the element draws 2 subpath(s): 1: line 2, path \"plate\", subpath 1 (closed, from (0, 0)); 2: "
                           "line 2, path \"plate\", subpath 2 (closed, from (1, -1)); select one with \"subpath\": k (1 to 2)"));
  msg = input_error_of([&] { scene_from("three.json", with(file + ", \"path\": \"plate\", \"subpath\": 3}")); });
  BOOST_TEST(contains(msg, "subpath 3 does not exist"));
  msg = input_error_of([&] { scene_from("nothing.json", with(file + "}")); });
  BOOST_TEST(contains(msg, "links[2].contours[0]: missing key \"path\""));
  msg = input_error_of([&] { scene_from("badnear.json", with(file + ", \"near\": [1]}")); });
  BOOST_TEST(contains(msg, "links[2].contours[0].near"));
}

BOOST_AUTO_TEST_CASE(invalid_nurbs_is_an_error_naming_the_json_path) {
  const std::string base = read_text(kExamples + "cycloid.json");
  auto with = [&](const std::string& contour) { return replaced(base, "\"type\": \"circle\", \"radius\": 1}", contour); };
  // 4 points of degree 2 need 7 knots.
  std::string msg = input_error_of([&] {
    scene_from("knots.json", with("\"type\": \"nurbs\", \"degree\": 2, \"knots\": [0, 0, 0, 1, 1, 1], "
                                  "\"points\": [[0, 0], [1, 1], [2, 0], [3, 1]]}"));
  });
  BOOST_TEST(contains(msg, "links[2].contours[0].knots"));
  BOOST_TEST(contains(msg, "7"));
  msg = input_error_of([&] {
    scene_from("weight.json", with("\"type\": \"nurbs\", \"degree\": 1, \"knots\": [0, 0, 1, 1], "
                                   "\"points\": [[0, 0], [1, 1]], \"weights\": [1, -1]}"));
  });
  BOOST_TEST(contains(msg, "links[2].contours[0].weights"));
  // "closed" for a curve that does not return to its start.
  msg = input_error_of([&] {
    scene_from("open.json", with("\"type\": \"nurbs\", \"degree\": 2, \"knots\": [0, 0, 0, 1, 1, 1], "
                                 "\"points\": [[0, 0], [1, 1], [2, 0]], \"closed\": true}"));
  });
  BOOST_TEST(contains(msg, "links[2].contours[0].closed"));
  BOOST_TEST(contains(msg, "not its start"));
}

// The disk selected by its handle (as ezdxf wrote it, from the fixture's answer file) and doubled by "scale"
// after the mm -> m conversion: r = 2 m, so psi - psi_0 = -(s - s_0) / 2.
BOOST_AUTO_TEST_CASE(dxf_disk_by_handle_with_scale_rolls_with_the_scaled_radius) {
  const std::string answer = read_text(kDxf + "scenes_mm.DISK_MM.txt");
  const std::string key = "# entities LWPOLYLINE ";
  const std::size_t at = answer.find(key);
  BOOST_REQUIRE(at != std::string::npos);
  const std::string handle = answer.substr(at + key.size(), answer.find('\n', at) - at - key.size());
  std::string text = read_text(kExamples + "cycloid.json");
  text = replaced(text, "\"at\": [{\"y\": 1}, {}]", "\"at\": [{\"y\": 2}, {}]");
  text = replaced(text, "\"type\": \"circle\", \"radius\": 1}",
                  "\"type\": \"dxf\", \"file\": \"" + kDxf + "scenes_mm.dxf\", \"handle\": \"" + handle + "\", \"scale\": 2}");
  const io::Scene s = scene_from("cycloid_dxf_handle.json", text);
  const auto r = solved(s);
  const int travel = s.mechanism.find_variable("S.s"), turn = s.mechanism.find_variable("H.psi");
  const double psi0 = r.poses.front().q(turn);
  double worst = 0;
  for (const auto& p : r.poses) worst = std::max(worst, std::abs((p.q(turn) - psi0) + p.q(travel) / 2));
  BOOST_TEST_MESSAGE("DXF disk by handle, scale 2: worst " << worst << " rad");
  BOOST_TEST(worst < 1e-9 * kDeg);
}

BOOST_AUTO_TEST_CASE(svg_id_is_an_alias_of_path_but_not_both) {
  const std::string svg_file = write_text(scratch_dir("io_cad_scenes") / "disk_alias.svg",
                                          "<svg xmlns=\"http://www.w3.org/2000/svg\"><circle id=\"d\" r=\"1\"/></svg>\n");
  const std::string base = read_text(kExamples + "cycloid.json");
  auto with = [&](const std::string& keys) {
    return replaced(base, "\"type\": \"circle\", \"radius\": 1}", "\"type\": \"svg\", \"file\": \"" + svg_file + "\", " + keys + "}");
  };
  const io::Scene s = scene_from("alias.json", with("\"id\": \"d\""));
  BOOST_TEST(s.files_read.back() == svg_file);
  const std::string msg = input_error_of([&] { scene_from("alias_both.json", with("\"id\": \"d\", \"path\": \"d\"")); });
  BOOST_TEST(contains(msg, "links[2].contours[0].id"));
  BOOST_TEST(contains(msg, "both"));
}

// Without units.length in the scene the file's numbers are taken as they are (no conversion): the mm disk
// of the DXF has radius 1000 and the mm SVG circle radius 10, so psi - psi_0 = -(s - s_0) / r with those r.
BOOST_AUTO_TEST_CASE(without_scene_units_file_numbers_are_kept) {
  const std::string svg_file = write_text(scratch_dir("io_cad_scenes") / "disk_mm.svg",
                                          "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100mm\" height=\"100mm\" "
                                          "viewBox=\"0 0 100 100\"><circle id=\"d\" r=\"10\"/></svg>\n");
  const std::string base = replaced(read_text(kExamples + "cycloid.json"), "\"length\": \"m\", ", "");
  const std::vector<std::pair<std::string, double>> cases = {
      {"\"type\": \"dxf\", \"file\": \"" + kDxf + "scenes_mm.dxf\", \"layer\": \"DISK_MM\", \"parameter\": \"arc_length\"}", 1000.0},
      {"\"type\": \"svg\", \"file\": \"" + svg_file + "\", \"path\": \"d\"}", 10.0}};
  for (const auto& [contour, r] : cases) {
    std::string text = replaced(base, "\"at\": [{\"y\": 1}, {}]", "\"at\": [{\"y\": " + number(r) + "}, {}]");
    text = replaced(text, "\"type\": \"circle\", \"radius\": 1}", contour);
    // Contact guesses for the large disk: its bottom is 3/4 of the circumference from (r, 0).
    if (r > 100) text = replaced(text, "\"values\": [-90, 0]", "\"values\": [" + number(1.5 * M_PI * r) + ", 10]");
    const io::Scene s = scene_from("unitless.json", text);
    BOOST_TEST((s.length == io::LengthUnit::Unitless));
    const auto res = solved(s);
    const int travel = s.mechanism.find_variable("S.s"), turn = s.mechanism.find_variable("H.psi");
    const double psi0 = res.poses.front().q(turn);
    double worst = 0;
    for (const auto& p : res.poses) worst = std::max(worst, std::abs((p.q(turn) - psi0) + p.q(travel) / r));
    BOOST_TEST(worst < 1e-9 * kDeg, contour << ": worst " << worst);
  }
}
