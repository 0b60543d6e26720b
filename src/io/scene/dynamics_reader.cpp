// The scene's "dynamics" object (docs/forces.md, "Scene"): strict like the rest of the scene reader. Unknown
// keys, links, pairs, values out of range and springs or loads that cannot act are InputErrors at their
// JSON path.
#include "dynamics_reader.hpp"

#include "rollkin/io/speed.hpp"

#include <cmath>
#include <stdexcept>

namespace rollkin::io {

SpeedUnit parse_speed_unit(const std::string& text, bool angular, LengthUnit scene_length) {
  if (angular) {
    if (text == "rpm") return {text, 2 * M_PI / 60, true};
    if (text == "rad/s") return {text, 1, true};
    if (text == "deg/s") return {text, deg_to_rad(1.0), true};
    throw std::invalid_argument("unknown speed unit \"" + text + "\" for an angle input; expected \"rpm\", \"rad/s\" or \"deg/s\"");
  }
  const std::string suffix = "/s";
  if (text.size() > suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0) {
    try {
      const LengthUnit u = parse_length_unit(text.substr(0, text.size() - suffix.size()));
      return {text, length_factor(u, scene_length), false};
    } catch (const std::invalid_argument&) {
    }
  }
  throw std::invalid_argument("unknown speed unit \"" + text + "\" for a length input; expected a length unit per second, e.g. \"" +
                              std::string(scene_length == LengthUnit::Unitless ? "m" : unit_label(scene_length)) + "/s\"");
}

double parse_speed(const std::string& text, bool angular, LengthUnit scene_length, const SpeedUnit& default_unit,
                   SpeedUnit& unit) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    throw std::invalid_argument("'" + text + "' is not a speed; expected a number and a unit, e.g. 500rpm");
  }
  if (!std::isfinite(value)) throw std::invalid_argument("'" + text + "' is not a finite speed");
  std::string rest = text.substr(used);
  while (!rest.empty() && rest.front() == ' ') rest.erase(rest.begin());
  unit = rest.empty() ? default_unit : parse_speed_unit(rest, angular, scene_length);
  return value;
}

namespace {

class DynamicsReader {
 public:
  DynamicsReader(const JsonAccess& js, Scene& scene) : js_(js), scene_(scene), m_(scene.mechanism) {}

  void read(const json& d) {
    js_.object(d, "dynamics", {"speed", "gravity", "links", "springs", "loads", "friction", "contact"});
    Dynamics<double> dyn(m_.links.size(), m_.pairs.size());
    dyn.metres_per_length = metres_per(scene_.length);
    read_speed(js_.require(d, "dynamics", "speed", "the input's constant speed, e.g. {\"value\": 500, \"unit\": \"rpm\"}"), dyn);
    if (const json* g = js_.get(d, "gravity")) dyn.gravity = js_.point(*g, "dynamics.gravity");
    if (const json* l = js_.get(d, "links")) read_links(*l, dyn);
    if (const json* s = js_.get(d, "springs")) read_springs(*s, dyn);
    if (const json* l = js_.get(d, "loads")) read_loads(*l, dyn);
    if (const json* f = js_.get(d, "friction")) read_friction(*f, dyn);
    if (const json* c = js_.get(d, "contact")) read_contact(*c, dyn);
    scene_.dynamics = std::move(dyn);
  }

 private:
  [[noreturn]] void fail(const std::string& path, const std::string& message) const { js_.fail(path, message); }

  /// A positive number.
  double positive(const json& v, const std::string& path, const std::string& what) const {
    const double x = js_.number(v, path, what);
    if (!(x > 0)) fail(path, what + " must be positive, got " + format_number(x));
    return x;
  }

  /// A moving link by name (the ground takes no equation: nothing on it moves anything).
  int moving_link(const json& v, const std::string& path, bool ground_allowed = false) const {
    const std::string name = js_.string(v, path, "a link name");
    const int link = m_.find_link(name);
    if (link < 0) {
      std::vector<std::string> names;
      for (const auto& l : m_.links) names.push_back(l.name);
      fail(path, "unknown link \"" + name + "\"; existing links: " + quoted_list(names));
    }
    if (link == m_.ground && !ground_allowed)
      fail(path, "link \"" + name + "\" is the ground: it does not move, so nothing on it enters the forces; give a moving link");
    return link;
  }

  /// A cam or rolling pair by name (friction and contact materials belong to contacts).
  int contact_pair(const std::string& name, const std::string& path) const {
    const int k = m_.find_pair(name);
    if (k < 0) {
      std::vector<std::string> names;
      for (const auto& p : m_.pairs)
        if (p.traits().has_contours) names.push_back(p.name);
      fail(path, "unknown pair \"" + name + "\"; the cam and rolling pairs are " + quoted_list(names));
    }
    if (!m_.pairs[static_cast<std::size_t>(k)].traits().has_contours)
      fail(path, "pair \"" + name + "\" is a " + to_string(m_.pairs[static_cast<std::size_t>(k)].kind) +
                     " pair; friction and contact materials are given for cam and rolling pairs only");
    return k;
  }

  void read_speed(const json& s, Dynamics<double>& dyn) {
    const std::string path = "dynamics.speed";
    js_.object(s, path, {"value", "unit"});
    const double value = js_.number(js_.require(s, path, "value", "the speed's number"), child(path, "value"), "the speed");
    const std::string unit = js_.string(js_.require(s, path, "unit", "the speed's unit"), child(path, "unit"), "a speed unit");
    const int input = scene_.sweep ? scene_.sweep->variable : m_.drivers.front();
    const bool angular = m_.variables[static_cast<std::size_t>(input)].kind != ParamKind::Length;
    try {
      scene_.speed_unit = parse_speed_unit(unit, angular, scene_.length);
    } catch (const std::invalid_argument& e) {
      fail(child(path, "unit"), std::string(e.what()) + " (the speed of input '" + m_.variables[static_cast<std::size_t>(input)].name + "')");
    }
    dyn.speed = value * scene_.speed_unit.per_second;
  }

  void read_links(const json& links, Dynamics<double>& dyn) {
    if (!links.is_object()) fail("dynamics.links", "expected an object {\"<link>\": {\"mass\", \"centre_of_mass\", \"inertia\"}}, got " + kind_of(links));
    for (const auto& [name, body] : links.items()) {
      const std::string path = child("dynamics.links", name);
      const int link = moving_link(json(name), path);
      js_.object(body, path, {"mass", "centre_of_mass", "inertia"});
      LinkMass<double>& lm = dyn.links[static_cast<std::size_t>(link)];
      lm.mass = positive(js_.require(body, path, "mass", "the link's mass in kg"), child(path, "mass"), "the mass (kg)");
      lm.inertia = positive(js_.require(body, path, "inertia", "the moment of inertia about the centre of mass, kg * length^2"),
                            child(path, "inertia"), "the moment of inertia (kg * length^2)");
      if (const json* c = js_.get(body, "centre_of_mass")) lm.centre = js_.point(*c, child(path, "centre_of_mass"));
    }
  }

  /// ["link", [x, y]]: a point of a link in its frame.
  std::pair<int, Vec2<double>> attachment(const json& v, const std::string& path) const {
    js_.array(v, path, "[\"link\", [x, y]]: a link and a point in its frame", 2);
    return {moving_link(v[0], index(path, 0), true), js_.point(v[1], index(path, 1))};
  }

  void read_springs(const json& springs, Dynamics<double>& dyn) {
    js_.array(springs, "dynamics.springs", "a list of springs");
    for (std::size_t i = 0; i < springs.size(); ++i) {
      const std::string path = index("dynamics.springs", i);
      const json& s = springs[i];
      js_.object(s, path, {"name", "from", "to", "rate", "free_length"});
      Spring<double> sp;
      sp.name = js_.get(s, "name") ? js_.string(s["name"], child(path, "name"), "the spring's name") : "spring " + std::to_string(i);
      std::tie(sp.link_a, sp.at_a) = attachment(js_.require(s, path, "from", "[\"link\", [x, y]]"), child(path, "from"));
      std::tie(sp.link_b, sp.at_b) = attachment(js_.require(s, path, "to", "[\"link\", [x, y]]"), child(path, "to"));
      if (sp.link_a == sp.link_b)
        fail(path, "both ends of the spring are on link \"" + m_.links[static_cast<std::size_t>(sp.link_a)].name +
                       "\": a spring within one link exerts no net force; join two links");
      sp.rate = positive(js_.require(s, path, "rate", "the spring rate in N / length"), child(path, "rate"), "the rate (N / length)");
      sp.free_length = js_.number(js_.require(s, path, "free_length", "the free length"), child(path, "free_length"), "the free length");
      if (sp.free_length < 0) fail(child(path, "free_length"), "the free length must not be negative, got " + format_number(sp.free_length));
      dyn.springs.push_back(sp);
    }
  }

  void read_loads(const json& loads, Dynamics<double>& dyn) {
    js_.array(loads, "dynamics.loads", "a list of loads");
    for (std::size_t i = 0; i < loads.size(); ++i) {
      const std::string path = index("dynamics.loads", i);
      const json& l = loads[i];
      js_.object(l, path, {"link", "at", "force", "torque"});
      Load<double> load;
      load.link = moving_link(js_.require(l, path, "link", "the loaded link"), child(path, "link"));
      if (!js_.get(l, "force") && !js_.get(l, "torque"))
        fail(path, "a load needs a \"force\" [Fx, Fy] (N, world axes, at \"at\") or a \"torque\" (N * length, counter-clockwise)");
      if (const json* f = js_.get(l, "force")) load.force = js_.point(*f, child(path, "force"));
      if (const json* a = js_.get(l, "at")) {
        if (!js_.get(l, "force")) fail(child(path, "at"), "\"at\" places a force; this load has none");
        load.at = js_.point(*a, child(path, "at"));
      }
      if (const json* t = js_.get(l, "torque")) load.torque = js_.number(*t, child(path, "torque"), "the torque (N * length)");
      dyn.loads.push_back(load);
    }
  }

  void read_friction(const json& f, Dynamics<double>& dyn) {
    if (!f.is_object()) fail("dynamics.friction", "expected an object {\"<pair>\": coefficient}, got " + kind_of(f));
    for (const auto& [name, mu] : f.items()) {
      const std::string path = child("dynamics.friction", name);
      const int k = contact_pair(name, path);
      const double c = js_.number(mu, path, "the Coulomb friction coefficient");
      if (!(c >= 0)) fail(path, "the friction coefficient must not be negative, got " + format_number(c));
      dyn.friction[static_cast<std::size_t>(k)] = c;
    }
  }

  void read_contact(const json& c, Dynamics<double>& dyn) {
    if (!c.is_object()) fail("dynamics.contact", "expected an object {\"<pair>\": {\"width\", \"E\", \"poisson\"}}, got " + kind_of(c));
    for (const auto& [name, v] : c.items()) {
      const std::string path = child("dynamics.contact", name);
      const int k = contact_pair(name, path);
      js_.object(v, path, {"width", "E", "poisson"});
      ContactMaterial<double>& cm = dyn.contact[static_cast<std::size_t>(k)];
      cm.given = true;
      cm.width = positive(js_.require(v, path, "width", "the face width"), child(path, "width"), "the face width");
      const json& e = js_.array(js_.require(v, path, "E", "[E1, E2]: Young's moduli in N / length^2"), child(path, "E"),
                                "[E1, E2]: Young's moduli of the first and second contour's body", 2);
      const json& nu = js_.array(js_.require(v, path, "poisson", "[nu1, nu2]"), child(path, "poisson"),
                                 "[nu1, nu2]: Poisson's ratios of the first and second contour's body", 2);
      for (std::size_t j = 0; j < 2; ++j) {
        cm.modulus[j] = positive(e[j], index(child(path, "E"), j), "Young's modulus (N / length^2)");
        cm.poisson[j] = js_.number(nu[j], index(child(path, "poisson"), j), "Poisson's ratio");
        if (!(cm.poisson[j] >= 0 && cm.poisson[j] < 0.5))
          fail(index(child(path, "poisson"), j), "Poisson's ratio must lie in [0, 0.5), got " + format_number(cm.poisson[j]));
      }
    }
  }

  const JsonAccess& js_;
  Scene& scene_;
  const Mechanism<double>& m_;
};

}  // namespace

void read_dynamics(const json& dynamics, const JsonAccess& js, Scene& scene) { DynamicsReader(js, scene).read(dynamics); }

}  // namespace rollkin::io
