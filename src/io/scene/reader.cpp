// Scene JSON reader (format: docs/scene_format.md). Strict: unknown keys, wrong types and dangling names
// are InputErrors naming the file, the JSON path and what is expected. The mechanism is built through
// MechanismBuilder; each contour kind has its reader under src/io/contours/ (src/io/scene/contours/registry.cpp).
#include "rollkin/io/scene/reader.hpp"

#include "contours/contour_reader.hpp"
#include "../json/access.hpp"

#include "rollkin/builder.hpp"
#include "rollkin/geometry/contact.hpp"
#include "rollkin/io/input_file.hpp"
#include "rollkin/io/json/document.hpp"

#include <array>
#include <cstring>
#include <filesystem>
#include <set>
#include <sstream>
#include <unordered_map>

namespace rollkin::io {
namespace {

namespace fs = std::filesystem;

constexpr int kContactSamples = 2000;

class SceneReader {
 public:
  /// `dir`: where relative contour files are looked up.
  SceneReader(std::string file, json document, fs::path dir) : file_(std::move(file)), js_(file_), dir_(std::move(dir)) {
    root_ = std::move(document);
    if (!root_.is_object()) fail("", "the scene must be a JSON object, got " + kind_of(root_));
  }

  Scene read() {
    Scene scene;
    scene.file = file_;
    js_.object(root_, "", {"units", "description", "links", "pairs", "inputs", "sweep"});
    read_units(scene);
    read_links(scene);
    read_pairs();
    build(scene);
    read_inputs(scene);
    build(scene);
    fill_guess(scene);
    locate_missing_contacts(scene);
    read_sweep(scene);
    return scene;
  }

 private:
  [[noreturn]] void fail(const std::string& path, const std::string& message) const { js_.fail(path, message); }

  /// The index `names` gives `name`, or -1.
  static int index_of(const std::unordered_map<std::string, int>& names, const std::string& name) {
    const auto it = names.find(name);
    return it == names.end() ? -1 : it->second;
  }

  // ---- sections -------------------------------------------------------------------------------------
  void read_units(Scene& scene) {
    const json* u = js_.get(root_, "units");
    if (!u) return;
    js_.object(*u, "units", {"length", "angle"});
    if (const json* l = js_.get(*u, "length")) {
      scene.length_unit = js_.string(*l, "units.length", "a length unit such as \"m\" or \"mm\"");
      try {
        scene.length = parse_length_unit(scene.length_unit);
      } catch (const std::invalid_argument& e) {
        fail("units.length", e.what());
      }
    }
    if (const json* a = js_.get(*u, "angle")) {
      const std::string s = js_.string(*a, "units.angle", "the angle unit \"deg\" or \"rad\"");
      try {
        angle_unit_ = parse_angle_unit(s);
      } catch (const std::invalid_argument& e) {
        fail("units.angle", e.what());
      }
    }
    scene.angle_unit = angle_unit_;
  }

  void read_links(Scene& scene) {
    const json& links = js_.array(js_.require(root_, "", "links", "the list of links"), "links", "the list of links");
    if (links.size() < 2) fail("links", "expected at least two links (a ground and a moving link), got " + std::to_string(links.size()));
    int ground = -1;
    for (std::size_t i = 0; i < links.size(); ++i) {
      const std::string path = index("links", i);
      const json& l = links[i];
      js_.object(l, path, {"name", "ground", "contours"});
      const std::string nm = js_.name(js_.require(l, path, "name", "the link's name"), child(path, "name"), "link name");
      if (link_by_name_.count(nm))
        fail(child(path, "name"), "duplicate link name \"" + nm + "\"; link names must be unique");
      bool is_ground = false;
      if (const json* g = js_.get(l, "ground"); g && js_.boolean(*g, child(path, "ground"), "whether this is the ground link")) {
        if (ground >= 0)
          fail(child(path, "ground"), "link \"" + nm + "\" is marked ground but \"" + builder_.description().links[ground].name +
                                          "\" already is; expected exactly one ground link");
        ground = static_cast<int>(i);
        is_ground = true;
      }
      const int link = builder_.link(nm, is_ground);
      link_by_name_.emplace(nm, link);
      if (const json* cs = js_.get(l, "contours")) {
        js_.array(*cs, child(path, "contours"), "the link's contours");
        std::set<std::string> names;
        for (std::size_t k = 0; k < cs->size(); ++k) read_contour((*cs)[k], index(child(path, "contours"), k), link, nm, names, scene);
      }
    }
    if (ground < 0) fail("links", "no ground link; mark exactly one link with \"ground\": true");
  }

  void read_contour(const json& c, const std::string& path, int link, const std::string& link_name,
                    std::set<std::string>& names, Scene& scene) {
    if (!c.is_object()) fail(path, "expected a contour object, got " + kind_of(c));
    const std::string type = js_.string(js_.require(c, path, "type", "the contour type"), child(path, "type"), "the contour type");
    const ContourReader reader = find_contour_reader(type);
    if (!reader) fail(child(path, "type"), "unknown contour type \"" + type + "\"; expected one of " + quoted_list(contour_types()));
    const ContourContext ctx(js_, dir_, angle_unit_, scene.length, scene.files_read, scene.notes);
    ContourShape shape = reader(c, path, ctx);
    const std::string nm = js_.name(js_.require(c, path, "name", "the contour's name"), child(path, "name"), "contour name");
    if (!names.insert(nm).second) fail(child(path, "name"), "duplicate contour name \"" + nm + "\" on link \"" + link_name + "\"");
    SE2<double> at;
    if (const json* a = js_.get(c, "at")) at = js_.frame(*a, child(path, "at"), angle_unit_);
    const int contour = builder_.contour(link, nm, std::move(shape.shape), at, shape.reversed, std::move(shape.corner_labels));
    contour_by_name_.emplace(builder_.description().contours[static_cast<std::size_t>(contour)].name(), contour);
  }

  /// One link of a revolute or prismatic pair, by name.
  int pair_link(const json& v, const std::string& path) const {
    const Mechanism<double>& m = builder_.description();
    const std::string ln = js_.string(v, path, "a link name");
    const int idx = index_of(link_by_name_, ln);
    if (idx < 0) {
      std::vector<std::string> names;
      for (const auto& l : m.links) names.push_back(l.name);
      fail(path, "unknown link \"" + ln + "\"; existing links: " + quoted_list(names));
    }
    return idx;
  }

  /// One contour of a cam or rolling pair, by its full name "link.contour".
  int pair_contour(const json& v, const std::string& path) const {
    const Mechanism<double>& m = builder_.description();
    const std::string cn = js_.string(v, path, "a contour reference \"link.contour\"");
    const int idx = index_of(contour_by_name_, cn);
    if (idx < 0) {
      std::vector<std::string> names;
      for (const auto& c : m.contours) names.push_back(c.name());
      fail(path, "unknown contour \"" + cn + "\"; expected \"link.contour\", existing contours: " + quoted_list(names));
    }
    return idx;
  }

  void read_joint(const json& p, const std::string& path, const std::string& name, PairKind kind) {
    js_.object(p, path, {"name", "type", "links", "at", "variable", "value"});
    const std::string lp = child(path, "links");
    const json& links = js_.array(js_.require(p, path, "links", "the two links [A, B]"), lp, "two link names [A, B]", 2);
    const int a = pair_link(links[0], index(lp, 0)), b = pair_link(links[1], index(lp, 1));
    if (a == b) fail(lp, "a pair must join two different links");
    SE2<double> frame_a, frame_b;
    if (const json* at = js_.get(p, "at")) {
      js_.array(*at, child(path, "at"), "the joint frames [frame in A, frame in B]", 2);
      frame_a = js_.frame((*at)[0], index(child(path, "at"), 0), angle_unit_);
      frame_b = js_.frame((*at)[1], index(child(path, "at"), 1), angle_unit_);
    }
    std::string var = kind == PairKind::Revolute ? "angle" : "s";
    if (const json* v = js_.get(p, "variable")) var = js_.name(*v, child(path, "variable"), "variable name");
    PairInput in;
    in.values[0] = js_.get(p, "value") ? js_.number(p["value"], child(path, "value"), "the variable's value") : 0.0;
    in.has_values = true;
    if (kind == PairKind::Revolute) builder_.revolute(name, a, b, frame_a, frame_b, var);
    else builder_.prismatic(name, a, b, frame_a, frame_b, var);
    inputs_.push_back(in);
  }

  void read_contact(const json& p, const std::string& path, const std::string& name, PairKind kind) {
    js_.object(p, path, {"name", "type", "contours", "variables", "values", "hold"});
    const std::string cp = child(path, "contours");
    const json& cs = js_.array(js_.require(p, path, "contours", "the two contours [\"link.contour\", \"link.contour\"]"), cp,
                               "two contour references [\"link.contour\", \"link.contour\"]", 2);
    const int a = pair_contour(cs[0], index(cp, 0)), b = pair_contour(cs[1], index(cp, 1));
    const Mechanism<double>& m = builder_.description();
    if (m.contours[a].link() == m.contours[b].link())
      fail(cp, "both contours are on link \"" + m.links[m.contours[a].link()].name + "\"; a pair must join two different links");
    std::array<std::string, 2> vars = {"u", "v"};
    if (const json* v = js_.get(p, "variables")) {
      js_.array(*v, child(path, "variables"), "two variable names [u, v]", 2);
      for (int j = 0; j < 2; ++j) vars[j] = js_.name((*v)[j], index(child(path, "variables"), j), "variable name");
      if (vars[0] == vars[1]) fail(child(path, "variables"), "the two variables must have different names");
    }
    PairInput in;
    if (const json* v = js_.get(p, "values")) {
      js_.array(*v, child(path, "values"), "two values [u0, v0]", 2);
      for (int j = 0; j < 2; ++j) in.values[j] = js_.number((*v)[j], index(child(path, "values"), j), "a contact parameter value");
      in.has_values = true;
    }
    if (const json* h = js_.get(p, "hold")) {
      js_.array(*h, child(path, "hold"), "two flags [hold u, hold v]", 2);
      for (int j = 0; j < 2; ++j)
        in.hold[j] = js_.boolean((*h)[j], index(child(path, "hold"), j), "whether to hold the variable during assembly");
      if ((in.hold[0] || in.hold[1]) && !in.has_values)
        fail(child(path, "hold"), "\"hold\" needs \"values\": a held variable keeps its given value during "
                                  "assembly; give \"values\": [u0, v0] or drop \"hold\"");
    }
    builder_.contact(name, kind == PairKind::Rolling, a, b, vars[0], vars[1]);
    inputs_.push_back(in);
  }

  void read_pairs() {
    const json& pairs = js_.array(js_.require(root_, "", "pairs", "the list of pairs"), "pairs", "the list of pairs");
    if (pairs.empty()) fail("pairs", "expected at least one pair");
    static const std::vector<std::string> types = {"revolute", "prismatic", "cam", "rolling"};
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      const std::string path = index("pairs", k);
      const json& p = pairs[k];
      if (!p.is_object()) fail(path, "expected a pair object, got " + kind_of(p));
      const std::string type = js_.string(js_.require(p, path, "type", "the pair type"), child(path, "type"), "the pair type");
      PairKind kind = PairKind::Revolute;
      if (type == "revolute") kind = PairKind::Revolute;
      else if (type == "prismatic") kind = PairKind::Prismatic;
      else if (type == "cam") kind = PairKind::Cam;
      else if (type == "rolling") kind = PairKind::Rolling;
      else fail(child(path, "type"), "unknown pair type \"" + type + "\"; expected one of " + quoted_list(types));
      const std::string name = js_.name(js_.require(p, path, "name", "the pair's name"), child(path, "name"), "pair name");
      if (pair_by_name_.count(name))
        fail(child(path, "name"), "duplicate pair name \"" + name + "\"; pair names must be unique");
      if (is_contact(kind)) read_contact(p, path, name, kind);
      else read_joint(p, path, name, kind);
      pair_by_name_.emplace(name, static_cast<int>(k));
    }
  }

  void build(Scene& scene) const {
    try {
      scene.mechanism = builder_.build();
    } catch (const std::invalid_argument& e) {
      fail("pairs", std::string(e.what()) + "; expected every link to be connected to the ground through pairs");
    }
  }

  static std::vector<std::string> variable_names(const Mechanism<double>& m) {
    std::vector<std::string> names;
    for (const auto& v : m.variables) names.push_back(v.name);
    return names;
  }

  void read_inputs(Scene& scene) {
    const Mechanism<double>& m = scene.mechanism;
    const json& in = js_.array(js_.require(root_, "", "inputs", "the list of driver variables, e.g. [\"O_A.theta2\"]"), "inputs",
                               "a list of driver variable names");
    if (in.empty()) fail("inputs", "expected at least one input variable; existing variables: " + quoted_list(variable_names(m)));
    std::unordered_map<std::string, int> variable_by_name;
    for (std::size_t i = 0; i < m.variables.size(); ++i) variable_by_name.emplace(m.variables[i].name, static_cast<int>(i));
    std::vector<bool> listed(m.variables.size(), false);
    for (std::size_t i = 0; i < in.size(); ++i) {
      const std::string path = index("inputs", i);
      const std::string v = js_.string(in[i], path, "a variable name \"<pair>.<var>\"");
      const int idx = index_of(variable_by_name, v);
      if (idx < 0) fail(path, "unknown variable \"" + v + "\"; existing variables: " + quoted_list(variable_names(m)));
      if (listed[static_cast<std::size_t>(idx)]) fail(path, "input \"" + v + "\" is listed twice");
      listed[static_cast<std::size_t>(idx)] = true;
      builder_.driver_variable(idx);
      scene.inputs.push_back(v);
    }
  }

  void fill_guess(Scene& scene) const {
    const Mechanism<double>& m = scene.mechanism;
    scene.guess = VectorX<double>::Zero(m.variable_count());
    std::vector<bool> driven(m.variables.size(), false);
    for (int d : m.drivers) driven[static_cast<std::size_t>(d)] = true;
    for (std::size_t k = 0; k < m.pairs.size(); ++k) {
      const Pair<double>& p = m.pairs[k];
      for (int j = 0; j < p.variable_count(); ++j) {
        const int i = p.first_variable + j;
        scene.guess(i) = inputs_[k].values[j] * scene.unit_of(i);
        if (inputs_[k].hold[j] && !driven[static_cast<std::size_t>(i)]) scene.held.push_back(i);
      }
    }
  }

  /// Contact pairs without "values": closest points of the two contours sampled in world coordinates at
  /// the assembly guess (geometry::locate_contact). Needs the poses of both links without this pair: it
  /// must not be on the spanning tree (a chord closing a loop), and the pairs on the tree must have their values.
  void locate_missing_contacts(Scene& scene) const {
    const Mechanism<double>& m = scene.mechanism;
    std::vector<int> missing;
    for (std::size_t k = 0; k < m.pairs.size(); ++k)
      if (!inputs_[k].has_values) missing.push_back(static_cast<int>(k));
    if (missing.empty()) return;
    std::vector<int> places(m.pairs.size(), -1);  // the link a pair on the spanning tree places, by pair
    for (std::size_t l = 0; l < m.links.size(); ++l)
      if (static_cast<int>(l) != m.ground && places[static_cast<std::size_t>(m.tree[l].edge.pair)] < 0)
        places[static_cast<std::size_t>(m.tree[l].edge.pair)] = static_cast<int>(l);
    for (int k : missing)
      if (const int l = places[static_cast<std::size_t>(k)]; l >= 0)
        fail(index("pairs", k), "\"values\" required: link \"" + m.links[l].name + "\" is placed through pair \"" +
                                    m.pairs[k].name + "\", so its contact cannot be located from the other pairs; give "
                                    "\"values\": [u0, v0] (contact parameters at the assembly pose)");
    KinematicsData<double> kin(m);
    evaluate_pairs<double>(m, scene.guess, nullptr, 1, kin);
    const std::vector<SE2<double>> pose = link_poses(m, kin);
    for (int k : missing) {
      const Pair<double>& p = m.pairs[k];
      const Contour<double>& a = m.contours[p.contour_a];
      const Contour<double>& b = m.contours[p.contour_b];
      std::array<double, 2> u;
      try {
        u = geometry::locate_contact(a, pose[a.link()], b, pose[b.link()], kContactSamples);
      } catch (const std::exception& e) {
        fail(index("pairs", k), std::string("cannot locate the initial contact: ") + e.what() + "; give \"values\"");
      }
      for (int j = 0; j < 2; ++j) scene.guess(p.first_variable + j) = u[j];
    }
  }

  void read_sweep(Scene& scene) const {
    const Mechanism<double>& m = scene.mechanism;
    const json* s = js_.get(root_, "sweep");
    if (!s) return;
    js_.object(*s, "sweep", {"input", "from", "to", "step"});
    Sweep sw;
    sw.input = scene.inputs.front();
    if (const json* in = js_.get(*s, "input")) {
      sw.input = js_.string(*in, "sweep.input", "one of the inputs");
      bool found = false;
      for (const auto& i : scene.inputs) found = found || i == sw.input;
      if (!found) fail("sweep.input", "\"" + sw.input + "\" is not one of the inputs; expected one of " + quoted_list(scene.inputs));
    }
    for (std::size_t d = 0; d < scene.inputs.size(); ++d)
      if (scene.inputs[d] == sw.input) sw.driver = static_cast<int>(d);
    sw.variable = m.drivers[sw.driver];
    sw.unit = scene.unit_of(sw.variable);
    sw.from = js_.number(js_.require(*s, "sweep", "from", "the first input value"), "sweep.from", "the first input value");
    sw.to = js_.number(js_.require(*s, "sweep", "to", "the last input value"), "sweep.to", "the last input value");
    sw.step = js_.number(js_.require(*s, "sweep", "step", "the input step"), "sweep.step", "the input step");
    const std::string bad = check_sweep(sw);
    if (!bad.empty()) fail("sweep.step", bad);
    scene.sweep = sw;
  }

  /// A pair's values and hold flags as given, until the variables are numbered.
  struct PairInput {
    std::array<double, 2> values{0, 0};
    std::array<bool, 2> hold{false, false};
    bool has_values = false;
  };

  std::string file_;
  JsonAccess js_;
  fs::path dir_;
  json root_;
  AngleUnit angle_unit_ = AngleUnit::Degree;
  MechanismBuilder<double> builder_;
  std::vector<PairInput> inputs_;
  // Names to indices in builder_'s mechanism, so that reading is linear in the scene's size (Mechanism's
  // find_* scan their lists: a look-up per pair was quadratic in the pairs).
  std::unordered_map<std::string, int> link_by_name_, contour_by_name_, pair_by_name_;
};

}  // namespace

double Scene::unit_of(int variable) const {
  return mechanism.variables[variable].kind == ParamKind::Angle ? radians_per<double>(angle_unit) : 1.0;
}

std::string Scene::unit_label(int variable) const {
  switch (mechanism.variables[variable].kind) {
    case ParamKind::Angle: return io::unit_label(angle_unit);
    case ParamKind::Length: return length_unit;
    case ParamKind::Unitless: return "";
  }
  return "";
}

std::optional<Sweep> requested_sweep(const Scene& scene, std::optional<double> from, std::optional<double> to,
                                     std::optional<double> step) {
  Sweep s;
  if (scene.sweep) {
    s = *scene.sweep;
  } else {
    if (!from || !to || !step) return std::nullopt;
    s.input = scene.inputs.front();
    s.driver = 0;
    s.variable = scene.mechanism.drivers[0];
    s.unit = scene.unit_of(s.variable);
  }
  if (from) s.from = *from, s.from_text.clear();
  if (to) s.to = *to, s.to_text.clear();
  if (step) s.step = *step, s.step_text.clear();
  return s;
}

InputError assembly_error(const Scene& scene, const std::string& detail) {
  return InputError(scene.file, "pairs",
                    "the mechanism cannot be assembled: " + detail +
                        "; expected pair frames, contour sizes and \"values\" that let every loop close");
}

Scene build_scene(const nlohmann::ordered_json& document, const std::string& file, const std::optional<std::string>& dir) {
  return SceneReader(file, document, dir ? fs::path(*dir) : fs::path(file).parent_path()).read();
}

Scene parse_scene(const std::string& text, const std::string& file) { return build_scene(parse_json_document(text, file), file); }

nlohmann::ordered_json read_scene_document(const std::string& path) {
  return parse_json_document(read_input_file(path, "the scene file"), path);
}

Scene load_scene(const std::string& path) { return build_scene(read_scene_document(path), path); }

}  // namespace rollkin::io
