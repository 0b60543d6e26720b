// The dynamics of a mechanism: masses, springs, loads, friction and contact materials (the scene's
// "dynamics" object, docs/forces.md). The description side beside Mechanism<S> (mechanism.hpp): fixed per
// mechanism, no solve state; analysis/forces.hpp computes the forces of a solved pose from it.
//
// Units (docs/forces.md, "Units"): mass kg, time s, force N; lengths in the scene's unit; derived units
// follow (inertia kg * length^2, spring rate N / length, torque N * length, Young's modulus N / length^2).
#pragma once

#include "rollkin/se2.hpp"

#include <array>
#include <string>
#include <vector>

namespace rollkin {

/// Mass properties of one link, in its own frame: mass in kg (0: massless), the centre of mass in scene
/// units, the moment of inertia about the centre of mass in kg * length^2.
template <class S> struct LinkMass {
  S mass = S(0);
  Vec2<S> centre = Vec2<S>::Zero();
  S inertia = S(0);
  template <class T> LinkMass<T> cast() const { return {scalar_cast<T>(mass), centre.template cast<T>(), scalar_cast<T>(inertia)}; }
};

/// A linear spring between a point of link_a and a point of link_b (each in its link's frame): tension
/// rate (L - free_length), pulling the two points together when positive. Rate in N / length.
template <class S> struct Spring {
  std::string name;
  int link_a = -1, link_b = -1;
  Vec2<S> at_a = Vec2<S>::Zero(), at_b = Vec2<S>::Zero();
  S rate = S(0), free_length = S(0);
  template <class T> Spring<T> cast() const {
    return {name, link_a, link_b, at_a.template cast<T>(), at_b.template cast<T>(), scalar_cast<T>(rate), scalar_cast<T>(free_length)};
  }
};

/// A constant load on a link: a force in world axes (N) at a point of the link (its frame), and a torque
/// (N * length, counter-clockwise positive).
template <class S> struct Load {
  int link = -1;
  Vec2<S> at = Vec2<S>::Zero(), force = Vec2<S>::Zero();
  S torque = S(0);
  template <class T> Load<T> cast() const { return {link, at.template cast<T>(), force.template cast<T>(), scalar_cast<T>(torque)}; }
};

/// The materials and face width of a cam or rolling pair, for the Hertz line contact (analysis/hertz.hpp).
template <class S> struct ContactMaterial {
  bool given = false;
  S width = S(0);                         // face width, scene units
  std::array<S, 2> modulus{S(0), S(0)};   // Young's modulus of the first and second contour's body, N / length^2
  std::array<S, 2> poisson{S(0), S(0)};   // Poisson's ratio of each
  template <class T> ContactMaterial<T> cast() const {
    return {given, scalar_cast<T>(width), {scalar_cast<T>(modulus[0]), scalar_cast<T>(modulus[1])},
            {scalar_cast<T>(poisson[0]), scalar_cast<T>(poisson[1])}};
  }
};

/// The dynamics of a mechanism (the scene's "dynamics" object, docs/forces.md): the description side, fixed
/// per mechanism, beside Mechanism<S>.
template <class S> struct Dynamics {
  std::vector<LinkMass<S>> links;          // per link of the mechanism (the ground's unused)
  Vec2<S> gravity = Vec2<S>::Zero();       // scene length units per s^2
  std::vector<Spring<S>> springs;
  std::vector<Load<S>> loads;
  std::vector<S> friction;                 // per pair: Coulomb coefficient of a cam or rolling pair; -1: none given
  std::vector<ContactMaterial<S>> contact; // per pair
  S metres_per_length = S(1);              // l: the scene's length unit in metres
  S speed = S(0);                          // the swept input's speed: rad/s, or scene length units per s

  explicit Dynamics(std::size_t links_count = 0, std::size_t pairs = 0)
      : links(links_count), friction(pairs, S(-1)), contact(pairs) {}

  template <class T> Dynamics<T> cast() const {
    Dynamics<T> d(links.size(), friction.size());
    for (std::size_t i = 0; i < links.size(); ++i) d.links[i] = links[i].template cast<T>();
    d.gravity = gravity.template cast<T>();
    for (const auto& s : springs) d.springs.push_back(s.template cast<T>());
    for (const auto& l : loads) d.loads.push_back(l.template cast<T>());
    for (std::size_t k = 0; k < friction.size(); ++k) d.friction[k] = scalar_cast<T>(friction[k]);
    for (std::size_t k = 0; k < contact.size(); ++k) d.contact[k] = contact[k].template cast<T>();
    d.metres_per_length = scalar_cast<T>(metres_per_length);
    d.speed = scalar_cast<T>(speed);
    return d;
  }
};

}  // namespace rollkin
