// Reading a gear spec (docs/synthesis.md, "Non-circular gears"): every problem an InputError naming the spec file and
// the JSON path.
#include "rollkin/io/format.hpp"
#include "rollkin/synthesis/spec_sizes.hpp"
#include "rollkin/io/input_file.hpp"
#include "rollkin/io/json/document.hpp"
#include "rollkin/io/point_file.hpp"
#include "rollkin/synthesis/gears.hpp"

#include "../io/json/access.hpp"

#include <cmath>
#include <filesystem>

namespace rollkin::synthesis {

GearSpec read_gear_spec(const std::string& path) {
  GearSpec spec = gear_spec_from_document(io::parse_json_document(io::read_input_file(path, "gear spec"), path, io::kMaxJsonDepth, "docs/synthesis.md"), path,
                                          std::filesystem::path(path).parent_path().string());
  spec.files_read.insert(spec.files_read.begin(), path);
  return spec;
}

namespace {

/// f' = 1 + g' > 0 at every row of a table and between rows: gear 2 turns one way as gear 1 does (pitch_radii of
/// synthesis.hpp needs it). Said with the table's rows, in the spec's angle unit ("f' must be positive" named none).
void check_speed_ratio(const GearSpec& spec, const std::vector<double>& p, const std::vector<std::size_t>& lines,
                       const std::string& file) {
  for (std::size_t i = 0; i + 1 < p.size(); ++i)
    for (const double at : {p[i], 0.5 * (p[i] + p[i + 1])}) {
      const double ratio = 1 + (*spec.table_excess)(at).v;
      if (ratio > 0) continue;
      throw io::InputError(file, "lines " + std::to_string(lines[i]) + "-" + std::to_string(lines[i + 1]),
                           "the speed ratio f' = d(phi2)/d(phi1) of the spline through the rows is " + io::format_number(ratio) +
                               " at phi1 = " + io::format_number(io::from_radians(at, spec.angle_unit)) + " " +
                               io::unit_label(spec.angle_unit) + "; expected f' > 0 everywhere (phi2 increasing with phi1: "
                               "gear 2 turns one way as gear 1 does); make phi2 increase more evenly between these rows");
    }
}

}  // namespace

GearSpec gear_spec_from_document(const nlohmann::ordered_json& root, const std::string& path, const std::string& dir) {
  using io::json;
  const io::JsonAccess js(path);
  GearSpec spec;
  spec.file = path;
  js.object(root, "", {"description", "units", "centre_distance", "transmission", "tolerance"});
  if (const json* u = io::JsonAccess::get(root, "units")) {
    js.object(*u, "units", {"length", "angle"});
    try {
      if (const json* l = io::JsonAccess::get(*u, "length"))
        spec.length = io::parse_length_unit(spec.length_label = js.string(*l, "units.length", "a length unit"));
      if (const json* a = io::JsonAccess::get(*u, "angle"))
        spec.angle_unit = io::parse_angle_unit(js.string(*a, "units.angle", "\"deg\" or \"rad\""));
    } catch (const std::invalid_argument& e) {
      js.fail("units", e.what());
    }
  }
  spec.centre_distance = js.number(js.require(root, "", "centre_distance", "the distance of the pivots (> 0)"),
                                   "centre_distance", "a length");
  if (!(spec.centre_distance > 0)) js.fail("centre_distance", "expected a distance > 0, got " + io::format_number(spec.centre_distance));
  if (const std::string bad = spec_size_problem(spec.centre_distance); !bad.empty()) js.fail("centre_distance", "the distance " + bad);
  const json& t = js.require(root, "", "transmission",
                             "{\"kind\": \"elliptical\", \"eccentricity\": e}, {\"kind\": \"sinusoidal\", \"k\": k} or {\"file\": \"f.txt\"}");
  if (io::JsonAccess::get(t, "file")) {
    js.object(t, "transmission", {"file"});
    spec.kind = "table";
    const std::string name = js.string(t["file"], "transmission.file", "the table's file name");
    const std::filesystem::path file = std::filesystem::path(dir) / name;
    spec.files_read.push_back(file.string());
    io::PointSamples rows;
    try {
      rows = io::read_table_file(file.string(), 5);
    } catch (const io::InputError& e) {  // the point file's words are about x y: say what the columns are here
      throw io::InputError(e.file(), e.location(), e.message() + " (a transmission table is read as a point file: two columns, phi1 "
                                                             "then phi2, and an optional header line naming them)");
    }
    std::vector<double> p, g;
    for (const auto& r : rows.points) {
      p.push_back(io::to_radians(r.x(), spec.angle_unit));
      g.push_back(io::to_radians(r.y(), spec.angle_unit) - p.back());
    }
    const double turn = 2 * pi<double>();
    if (std::abs(p.back() - p.front() - turn) > 1e-12 * turn)
      throw io::InputError(file.string(), "line " + std::to_string(rows.lines.back()),
                       "the table must cover one turn of phi1, its last row at the first phi1 + " +
                           io::format_number(io::from_radians(turn, spec.angle_unit)));
    spec.closure_error = g.back() - g.front();  // f(p + 2 pi) - f(p) - 2 pi
    g.back() = g.front();                       // the spline of g is periodic; the closure is reported
    try {
      spec.table_excess = MotionLaw<double>::from_table(p, g);
    } catch (const std::invalid_argument& e) {
      throw io::InputError(file.string(), "", e.what());
    }
    check_speed_ratio(spec, p, rows.lines, file.string());
  } else {
    const std::string kind = js.string(js.require(t, "transmission", "kind", "\"elliptical\" or \"sinusoidal\""),
                                       "transmission.kind", "\"elliptical\" or \"sinusoidal\"");
    spec.kind = kind;
    if (kind == "elliptical") {
      js.object(t, "transmission", {"kind", "eccentricity"});
      spec.parameter = js.number(js.require(t, "transmission", "eccentricity", "the ellipses' eccentricity in [0, 1)"),
                                 "transmission.eccentricity", "a number in [0, 1)");
      if (!(spec.parameter >= 0 && spec.parameter < 1)) js.fail("transmission.eccentricity", "expected a number in [0, 1), got " + io::format_number(spec.parameter));
    } else if (kind == "sinusoidal") {
      js.object(t, "transmission", {"kind", "k"});
      spec.parameter = js.number(js.require(t, "transmission", "k", "the amplitude k, |k| < 1"), "transmission.k", "a number");
      if (!(std::abs(spec.parameter) < 1)) js.fail("transmission.k", "expected |k| < 1 (f' = 1 + k cos p > 0), got " + io::format_number(spec.parameter));
    } else {
      js.fail("transmission.kind", "unknown kind \"" + kind + "\"; expected \"elliptical\" or \"sinusoidal\" (or give \"file\")");
    }
  }
  const double relative = js.number_or(root, "", "tolerance", 1e-9, "the largest deviation of gear 2's angle, as a fraction of a turn");
  if (!(relative > 0)) js.fail("tolerance", "expected a number > 0, got " + io::format_number(relative));
  spec.tolerance = relative * 2 * pi<double>();
  return spec;
}

}  // namespace rollkin::synthesis
