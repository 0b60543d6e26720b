// Describing a mechanism in code: links, contours and pairs by name, then build() numbers the variables
// and finds the loops. The scene reader (src/io/scene/reader.cpp) builds through it from JSON.
#pragma once

#include "rollkin/mechanism.hpp"

namespace rollkin {

template <class S> class MechanismBuilder {
 public:
  int link(const std::string& name, bool ground = false) {
    m_.links.push_back(Link{name});
    if (ground) m_.ground = static_cast<int>(m_.links.size()) - 1;
    return static_cast<int>(m_.links.size()) - 1;
  }
  /// A contour on `link`, named "<link>.<name>"; reversed = material on the right of the profile's direction;
  /// corner_labels describe the profile's corners for messages (Contour).
  int contour(int link, const std::string& name, ProfileShape<S> shape, const SE2<S>& placement = SE2<S>(),
              bool reversed = false, std::vector<std::string> corner_labels = {}) {
    m_.contours.emplace_back(m_.links.at(link).name + "." + name, link, std::move(shape), placement, reversed,
                             std::move(corner_labels));
    return static_cast<int>(m_.contours.size()) - 1;
  }
  int revolute(const std::string& name, int a, int b, const SE2<S>& frame_a = SE2<S>(), const SE2<S>& frame_b = SE2<S>(),
               const std::string& var = "angle") {
    return joint(name, PairKind::Revolute, a, b, frame_a, frame_b, var);
  }
  int prismatic(const std::string& name, int a, int b, const SE2<S>& frame_a = SE2<S>(), const SE2<S>& frame_b = SE2<S>(),
                const std::string& var = "s") {
    return joint(name, PairKind::Prismatic, a, b, frame_a, frame_b, var);
  }
  /// Cam (slipping) or rolling contact between two contours, from contour A's link to contour B's link.
  int contact(const std::string& name, bool rolling, int contour_a, int contour_b, const std::string& var_a = "u",
              const std::string& var_b = "v") {
    Pair<S> p;
    p.name = name;
    p.kind = rolling ? PairKind::Rolling : PairKind::Cam;
    p.contour_a = contour_a;
    p.contour_b = contour_b;
    p.link_a = m_.contours.at(contour_a).link();
    p.link_b = m_.contours.at(contour_b).link();
    p.variables = {var_a, var_b};
    m_.pairs.push_back(p);
    return static_cast<int>(m_.pairs.size()) - 1;
  }
  /// The pair's variable number j (0 or 1) in q.
  int variable(int pair, int j = 0) const {
    int index = 0;
    for (int k = 0; k < pair; ++k) index += m_.pairs[k].variable_count();
    return index + j;
  }
  void driver(int pair, int j = 0) { m_.drivers.push_back(variable(pair, j)); }
  /// A driver given by its variable number in q (as numbered by build()).
  void driver_variable(int variable) { m_.drivers.push_back(variable); }

  /// The description so far (links, contours, pairs, drivers; not finalized), for look-ups by name.
  const Mechanism<S>& description() const { return m_; }

  /// The finalized mechanism. Throws std::invalid_argument if a link cannot be reached from the ground.
  Mechanism<S> build() const {
    Mechanism<S> m = m_;
    m.finalize();
    return m;
  }

 private:
  int joint(const std::string& name, PairKind kind, int a, int b, const SE2<S>& fa, const SE2<S>& fb, const std::string& var) {
    Pair<S> p;
    p.name = name;
    p.kind = kind;
    p.link_a = a;
    p.link_b = b;
    p.frame_a = fa;
    p.frame_b = fb;
    p.variables = {var, ""};
    m_.pairs.push_back(p);
    return static_cast<int>(m_.pairs.size()) - 1;
  }

  Mechanism<S> m_;
};

}  // namespace rollkin
