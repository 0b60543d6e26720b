// Reading a cam spec (docs/synthesis.md, "The cam spec"): a JSON object checked key by key, every problem an
// InputError naming the spec file and the JSON path, what is wrong and what is expected.
#include "rollkin/io/csv.hpp"
#include "rollkin/io/format.hpp"
#include "rollkin/synthesis/spec_sizes.hpp"
#include "rollkin/io/input_file.hpp"
#include "rollkin/io/json/document.hpp"
#include "rollkin/io/point_file.hpp"
#include "rollkin/io/scene/reader.hpp"
#include "rollkin/synthesis/cam.hpp"

#include "../io/json/access.hpp"

#include <cmath>
#include <filesystem>
#include <limits>

namespace rollkin::synthesis {
namespace {

using io::json;
namespace fs = std::filesystem;

class CamSpecReader {
 public:
  CamSpecReader(const json& root, const std::string& file, std::string dir) : root_(root), js_(file), dir_(std::move(dir)) {}

  CamSpec read() {
    CamSpec spec;
    spec.file = js_.file();
    spec.files_read.push_back(js_.file());
    js_.object(root_, "", {"description", "units", "base_radius", "rotation", "follower", "contact", "law", "tolerance"});
    read_units(spec);
    spec.base_radius = positive(js_.require(root_, "", "base_radius", "the base circle's radius (a length > 0)"),
                                "base_radius", "the base circle's radius");
    if (const json* r = io::JsonAccess::get(root_, "rotation")) {
      const std::string dir = js_.string(*r, "rotation", "\"ccw\" or \"cw\"");
      if (dir != "ccw" && dir != "cw") js_.fail("rotation", "unknown rotation \"" + dir + "\"; expected \"ccw\" or \"cw\"");
      spec.rotation = dir == "ccw" ? 1 : -1;
    }
    read_contact(spec);
    read_follower(spec);
    read_law(spec);
    spec.stroke = spec.law->stroke();
    if (!(spec.stroke > 0)) js_.fail("law", "the law never moves the follower (its stroke is 0)");
    const double relative = js_.number_or(root_, "", "tolerance", 1e-9, "the largest deviation allowed, as a fraction of the stroke");
    if (!(relative > 0)) js_.fail("tolerance", "expected a fraction of the stroke > 0, got " + io::format_number(relative));
    spec.tolerance = relative * spec.stroke;
    return spec;
  }

 private:
  double positive(const json& v, const std::string& path, const std::string& what) const {
    const double x = js_.number(v, path, what);
    if (!(x > 0)) js_.fail(path, what + " must be > 0, got " + io::format_number(x));
    return sized(x, path, what);
  }
  /// A length (or lift) the synthesis can compute with (synthesis::kSpecSizes; docs/synthesis.md).
  double sized(double x, const std::string& path, const std::string& what) const {
    const std::string bad = spec_size_problem(x);
    if (!bad.empty()) js_.fail(path, what + " " + bad);
    return x;
  }
  double angle(const json& v, const std::string& path, const std::string& what, const CamSpec& spec) const {
    return io::to_radians(js_.number(v, path, what), spec.angle_unit);
  }

  void read_units(CamSpec& spec) {
    const json* u = io::JsonAccess::get(root_, "units");
    if (!u) return;
    js_.object(*u, "units", {"length", "angle"});
    if (const json* l = io::JsonAccess::get(*u, "length")) {
      spec.length_label = js_.string(*l, "units.length", "a length unit such as \"mm\"");
      try {
        spec.length = io::parse_length_unit(spec.length_label);
      } catch (const std::invalid_argument& e) {
        js_.fail("units.length", e.what());
      }
    }
    if (const json* a = io::JsonAccess::get(*u, "angle")) {
      try {
        spec.angle_unit = io::parse_angle_unit(js_.string(*a, "units.angle", "\"deg\" or \"rad\""));
      } catch (const std::invalid_argument& e) {
        js_.fail("units.angle", e.what());
      }
    }
  }

  void read_contact(CamSpec& spec) {
    const json& c = js_.require(root_, "", "contact", "{\"roller_radius\": r}, {\"flat\": true} or {\"contour\": {...}}");
    js_.object(c, "contact", {"roller_radius", "flat", "contour"});
    const json* roller = io::JsonAccess::get(c, "roller_radius");
    const json* flat = io::JsonAccess::get(c, "flat");
    const json* contour = io::JsonAccess::get(c, "contour");
    if ((roller != nullptr) + (flat != nullptr) + (contour != nullptr) != 1)
      js_.fail("contact", "give exactly one of \"roller_radius\" (a roller), \"flat\": true (a flat face) and \"contour\" (any contour)");
    if (contour) {
      read_follower_contour(spec, *contour);
      return;
    }
    if (roller) {
      spec.contact = FollowerContact::Roller;
      spec.roller_radius = positive(*roller, "contact.roller_radius", "the roller's radius");
    } else {
      if (!js_.boolean(*flat, "contact.flat", "true")) js_.fail("contact.flat", "expected true (a flat face); for a roller give \"roller_radius\"");
      spec.contact = FollowerContact::Flat;
    }
  }

  /// A contour of the scene format (docs/scene_format.md) read as the one contour of a one-link scene in the spec's
  /// units, files relative to the spec; its errors are reported at contact.contour.
  void read_follower_contour(CamSpec& spec, const json& contour) {
    if (!contour.is_object()) js_.fail("contact.contour", "expected a contour object such as {\"type\": \"circle\", \"radius\": 10}");
    json dict = contour;
    if (!dict.contains("name")) dict["name"] = "contour";
    json units = json::object();
    if (!spec.length_label.empty()) units["length"] = spec.length_label;
    units["angle"] = spec.angle_unit == io::AngleUnit::Degree ? "deg" : "rad";
    const json scene = {{"units", units},
                        {"links", json::array({{{"name", "frame"}, {"ground", true}}, {{"name", "follower"}, {"contours", json::array({dict})}}})},
                        {"pairs", json::array({{{"name", "p"}, {"type", "revolute"}, {"links", {"frame", "follower"}}}})},
                        {"inputs", json::array({"p.angle"})}};
    const std::string prefix = "links[1].contours[0]";
    try {
      spec.follower_shape = std::make_shared<const io::Scene>(io::build_scene(scene, js_.file(), dir_));
    } catch (const io::InputError& e) {
      std::string location = e.location();
      if (location.compare(0, prefix.size(), prefix) == 0) location = "contact.contour" + location.substr(prefix.size());
      throw io::InputError(e.file(), location, e.message());
    }
    for (const std::string& f : spec.follower_shape->files_read) spec.files_read.push_back(f);
    spec.follower_contour = dict;
    spec.contact = FollowerContact::Contour;
  }

  void read_follower(CamSpec& spec) {
    const json& f = js_.require(root_, "", "follower", "{\"motion\": \"translating\", ...} or {\"motion\": \"oscillating\", ...}");
    const std::string motion = js_.string(js_.require(f, "follower", "motion", "\"translating\" or \"oscillating\""),
                                          "follower.motion", "\"translating\" or \"oscillating\"");
    if (motion == "translating") {
      js_.object(f, "follower", {"motion", "offset"});
      spec.motion = FollowerMotion::Translating;
      spec.offset = sized(js_.number_or(f, "follower", "offset", 0, "the guide's offset from the cam centre (a length)"),
                          "follower.offset", "the guide's offset");
      const double prime = spec.base_radius + spec.roller_radius;
      if (spec.contact == FollowerContact::Roller && !(std::abs(spec.offset) < prime))
        js_.fail("follower.offset", "|offset| " + io::format_number(std::abs(spec.offset)) + " must be less than base_radius + roller_radius = " +
                                        io::format_number(prime) + " (the roller could not touch the base circle)");
    } else if (motion == "oscillating") {
      js_.object(f, "follower", {"motion", "pivot", "arm", "start_angle"});
      spec.motion = FollowerMotion::Oscillating;
      if (spec.contact == FollowerContact::Flat)
        js_.fail("contact.flat", "a flat face is a kind for translating followers; on an oscillating arm give it as a contour, e.g. \"contour\": {\"type\": \"line\", \"from\": 0, \"to\": 100, \"at\": {...}}");
      spec.pivot = js_.point(js_.require(f, "follower", "pivot", "the pivot [x, y]"), "follower.pivot");
      sized(spec.pivot.x(), "follower.pivot[0]", "the pivot's x");
      sized(spec.pivot.y(), "follower.pivot[1]", "the pivot's y");
      spec.arm = positive(js_.require(f, "follower", "arm", "the arm's length (> 0)"), "follower.arm", "the arm's length");
      // An arm turning about the cam centre keeps its roller at one distance from it: no cam can move it (the
      // analysis then found a 360 degree deviation). Bad geometry, said as such.
      if (!(spec.pivot.norm() > 1e-9 * (spec.base_radius + spec.arm)))
        js_.fail("follower.pivot", "the pivot is at the cam centre (0, 0): the arm would turn about the cam's own axis, keeping the "
                                   "follower at one distance from it, so no cam can move it; expected a pivot away from the cam "
                                   "centre, usually beyond base_radius + roller_radius");
      if (const json* a0 = io::JsonAccess::get(f, "start_angle")) {
        spec.start_angle = angle(*a0, "follower.start_angle", "the arm's angle", spec);
        if (spec.contact == FollowerContact::Roller) check_oscillating_start(spec);
      } else if (spec.contact == FollowerContact::Roller) {
        spec.start_angle = start_on_prime_circle(spec);
      } else {
        js_.fail("follower", "an oscillating follower with a \"contour\" needs \"start_angle\" (the arm's angle at the law's zero)");
      }
    } else {
      js_.fail("follower.motion", "unknown motion \"" + motion + "\"; expected \"translating\" or \"oscillating\"");
    }
  }

  /// Without "start_angle": the arm's angle that puts the roller's centre on the prime circle, of the two the one
  /// nearer the direction from the pivot to the cam centre.
  double start_on_prime_circle(const CamSpec& spec) const {
    const double rho = spec.base_radius + spec.roller_radius, p = spec.pivot.norm();
    const double c = p > 0 ? (rho * rho - p * p - spec.arm * spec.arm) / (2 * spec.arm * p) : 2;
    if (!(std::abs(c) <= 1))
      js_.fail("follower", "no arm angle puts the roller's centre on the prime circle (radius base_radius + roller_radius = " +
                               io::format_number(rho) + ") with this pivot and arm");
    const double base = std::atan2(spec.pivot.y(), spec.pivot.x()), d = std::acos(c);
    const double toward = std::atan2(-spec.pivot.y(), -spec.pivot.x());
    auto gap = [&](double a) { return std::abs(std::remainder(a - toward, 2 * pi<double>())); };
    return gap(base - d) <= gap(base + d) ? base - d : base + d;
  }

  /// The roller's centre at the law's zero must lie on the prime circle |P + L u(a0)| = Rb + r; the message
  /// gives the start angles that would put it there (cos(a0 - atan2 P) = (rho^2 - |P|^2 - L^2) / (2 L |P|)).
  void check_oscillating_start(const CamSpec& spec) const {
    const Vec2<double> u(std::cos(spec.start_angle), std::sin(spec.start_angle));
    const double rho = spec.base_radius + spec.roller_radius;
    const double at = (spec.pivot + spec.arm * u).norm();
    if (std::abs(at - rho) <= 1e-9 * rho) return;
    std::string hint;
    const double p = spec.pivot.norm();
    const double c = (rho * rho - p * p - spec.arm * spec.arm) / (2 * spec.arm * p);
    if (p > 0 && std::abs(c) <= 1) {
      const double base = std::atan2(spec.pivot.y(), spec.pivot.x()), d = std::acos(c);
      hint = "; start_angle " + io::format_number(io::from_radians(base - d, spec.angle_unit)) + " or " +
             io::format_number(io::from_radians(base + d, spec.angle_unit)) + " puts it there";
    } else {
      hint = "; no start angle puts it there with this pivot and arm";
    }
    js_.fail("follower.start_angle", "the roller's centre is " + io::format_number(at) + " from the cam centre, not base_radius + roller_radius = " +
                                         io::format_number(rho) + hint);
  }

  void read_law(CamSpec& spec) {
    const json& law = js_.require(root_, "", "law", "a list of segments or {\"file\": \"law.csv\"}");
    const double lift_unit = spec.motion == FollowerMotion::Oscillating ? io::radians_per<double>(spec.angle_unit) : 1.0;
    try {
      if (law.is_object()) {
        js_.object(law, "law", {"file"});
        read_law_file(spec, js_.string(js_.require(law, "law", "file", "the law file's name"), "law.file", "a file name"), lift_unit);
        return;
      }
      js_.array(law, "law", "a list of segments {\"to\", \"kind\", \"lift\"}");
      std::vector<LawSegment<double>> segments;
      double start = 0;
      for (std::size_t k = 0; k < law.size(); ++k) {
        const std::string path = io::index("law", k);
        js_.object(law[k], path, {"to", "kind", "lift"});
        const double to = angle(js_.require(law[k], path, "to", "the cam angle where the segment ends"), io::child(path, "to"),
                                "the cam angle where the segment ends", spec);
        const std::string kind_name = js_.string(js_.require(law[k], path, "kind", "the segment's kind"), io::child(path, "kind"), "a kind");
        RiseKind kind;
        try {
          kind = rise_kind(kind_name);
        } catch (const std::invalid_argument& e) {
          js_.fail(io::child(path, "kind"), e.what());
        }
        const double lift = sized(js_.number_or(law[k], path, "lift", 0, "the segment's lift (negative for a return)"),
                                  io::child(path, "lift"), "the lift") * lift_unit;
        if (!(to > start)) js_.fail(io::child(path, "to"), "expected a cam angle after the segment's start " + io::format_number(io::from_radians(start, spec.angle_unit)));
        if (kind == RiseKind::Dwell && lift != 0) js_.fail(io::child(path, "lift"), "a dwell has no lift");
        if (kind != RiseKind::Dwell && lift == 0) js_.fail(path, "a \"" + kind_name + "\" segment needs a nonzero \"lift\"");
        segments.push_back({start, to, lift, kind});
        start = to;
      }
      check_law_closes(segments, spec);
      spec.law = MotionLaw<double>::from_segments(segments);
    } catch (const std::invalid_argument& e) {
      js_.fail("law", e.what());
    }
  }

  /// The law ends after one turn and its lifts add up to zero (the follower comes back), said in the spec's units
  /// with the numbers that show the difference; the same tolerances as MotionLaw::from_segments (round-off of a
  /// turn; 64 eps of the largest displacement).
  void check_law_closes(const std::vector<LawSegment<double>>& segments, const CamSpec& spec) const {
    if (segments.empty()) return;
    const double turn = 2 * pi<double>();
    if (std::abs(segments.back().end - turn) > 64 * std::numeric_limits<double>::epsilon() * turn)
      js_.fail(io::child(io::index("law", segments.size() - 1), "to"),
               "the law ends at " + io::format_double(io::from_radians(segments.back().end, spec.angle_unit)) + " " +
                   io::unit_label(spec.angle_unit) + ", not after one turn; expected " +
                   io::format_double(io::from_radians(turn, spec.angle_unit)) + " " + io::unit_label(spec.angle_unit));
    const double unit = spec.motion == FollowerMotion::Oscillating ? io::radians_per<double>(spec.angle_unit) : 1.0;
    double sum = 0, largest = 0;
    std::string terms;
    for (const auto& g : segments) {
      if (g.lift == 0) continue;
      sum += g.lift;
      largest = std::max(largest, std::abs(sum));
      terms += (terms.empty() ? "" : g.lift < 0 ? " - " : " + ") + io::format_double(std::abs(g.lift / unit) * (terms.empty() && g.lift < 0 ? -1 : 1));
    }
    if (std::abs(sum) > 64 * std::numeric_limits<double>::epsilon() * largest)
      js_.fail("law", "the lifts add up to " + terms + " = " + io::format_double(sum / unit) + ", not 0: the follower would not come "
                      "back after one turn; make the returns' lifts add up to the rises' exactly");
  }

  void read_law_file(CamSpec& spec, const std::string& name, double lift_unit) {
    const fs::path path = fs::path(dir_) / name;
    spec.files_read.push_back(path.string());
    io::PointSamples rows;
    try {
      rows = io::read_table_file(path.string(), 4);
    } catch (const io::InputError& e) {  // the point file's words are about x y: say what the columns are here
      throw io::InputError(e.file(), e.location(), e.message() + " (a law file is read as a point file: two columns, the cam angle then "
                                                             "the follower's displacement, and an optional header line naming them)");
    }
    std::vector<double> theta, s;
    for (const auto& p : rows.points) {
      theta.push_back(io::to_radians(p.x(), spec.angle_unit));
      s.push_back(p.y() * lift_unit);
    }
    try {
      spec.law = MotionLaw<double>::from_table(theta, s);
    } catch (const std::invalid_argument& e) {
      throw io::InputError(path.string(), "", e.what());
    }
  }

  const json& root_;
  io::JsonAccess js_;
  std::string dir_;
};

}  // namespace

CamSpec read_cam_spec(const std::string& path) {
  const std::string text = io::read_input_file(path, "cam spec");
  const json root = io::parse_json_document(text, path, io::kMaxJsonDepth, "docs/synthesis.md");
  return CamSpecReader(root, path, fs::path(path).parent_path().string()).read();
}

CamSpec cam_spec_from_document(const nlohmann::ordered_json& document, const std::string& file, const std::string& dir) {
  CamSpec spec = CamSpecReader(document, file, dir).read();
  spec.files_read.erase(spec.files_read.begin());  // no spec file was read
  return spec;
}

}  // namespace rollkin::synthesis
