// The closed set of pair kinds and what each one does, one row of a table per kind (docs/method.md sections
// 1-3). Consumers ask a pair what it does (pair.traits().has_contours, .constrains_sliding, .turns, ...) and
// never which kind it is: adding a kind is one row here and its evaluation in pair.hpp (evaluate_pair,
// pair_transform, pair_turn), which visit the kind statically. tests/test_pair_contract.cpp checks every row
// against the evaluation.
#pragma once

#include "rollkin/profile/jet.hpp"

#include <optional>
#include <string>
#include <vector>

namespace rollkin {

enum class PairKind { Revolute, Prismatic, Cam, Rolling };

/// What a pair kind does. The questions, and who asks them:
struct PairTraits {
  PairKind kind;
  /// The scene's "type" (docs/scene_format.md, "pairs") and the name in messages.
  const char* name;
  /// Variables of the pair in q: columns of the Jacobian, twists evaluate_pair fills (1 or 2).
  int variable_count;
  /// The variables are contact parameters u on contour_a and v on contour_b (eq. 1): the contact geometry
  /// (PairState::contact) is evaluated, contour indices are read, the contact analysis, design check,
  /// contact limits and interference look at it. Otherwise contour_a/contour_b are never read.
  bool has_contours;
  /// Placed by the joint frames frame_a, frame_b in its links (drawn as a pivot or joint); otherwise those
  /// frames are the identity and never read.
  bool has_joint_frames;
  /// Adds the rolling row s_A(u0 -> u) + s_B(v0 -> v) = 0 (eqs. 3-4): the contact does not slip, so there is
  /// no sliding velocity to chart. Only kinds with contours.
  bool constrains_sliding;
  /// Its variable is the relative angle about the joint frames' common origin: link B turns about a point
  /// fixed in both links (that point is the pair's instant centre; the angle adds up without atan2).
  bool turns;
  /// Its variable is the displacement along frame A's x axis (a stroke, a length): no relative turning.
  bool slides;
  /// Relative freedoms of link B on link A that the pair leaves (the rank of its twists subject to its own
  /// rows); it removes 3 - freedoms, the reaction components it carries (docs/method.md section 3, DOF count).
  int freedoms;
  /// Names of the variables when the scene or the builder gives none (the unused second one empty).
  const char* default_variables[2];

  /// Constraints the pair imposes on the relative motion of its links (reaction components).
  int constraint_count() const { return 3 - freedoms; }
  /// How the pair's variable j is reported, when it is not a contact parameter (those follow their contour).
  ParamKind joint_variable_kind() const { return slides ? ParamKind::Length : ParamKind::Angle; }
};

/// One row per kind, in the order of PairKind (checked below).
inline constexpr PairTraits kPairTraits[] = {
    // kind              name        vars contours frames no-slip turns  slides free variables
    {PairKind::Revolute, "revolute", 1, false, true, false, true, false, 1, {"angle", ""}},
    {PairKind::Prismatic, "prismatic", 1, false, true, false, false, true, 1, {"s", ""}},
    {PairKind::Cam, "cam", 2, true, false, false, false, false, 2, {"u", "v"}},
    {PairKind::Rolling, "rolling", 2, true, false, true, false, false, 1, {"u", "v"}},
};

namespace detail {
constexpr bool pair_table_in_enum_order() {
  for (std::size_t k = 0; k < sizeof kPairTraits / sizeof *kPairTraits; ++k)
    if (static_cast<std::size_t>(kPairTraits[k].kind) != k) return false;
  return true;
}
static_assert(pair_table_in_enum_order(), "kPairTraits: one row per PairKind, in the enum's order");
}  // namespace detail

inline const PairTraits& traits(PairKind k) { return kPairTraits[static_cast<std::size_t>(k)]; }
inline const char* to_string(PairKind k) { return traits(k).name; }

/// Every kind, in table order.
inline std::vector<PairKind> pair_kinds() {
  std::vector<PairKind> out;
  for (const PairTraits& t : kPairTraits) out.push_back(t.kind);
  return out;
}
/// The kind whose name (scene "type") is `name`; nullopt for any other.
inline std::optional<PairKind> pair_kind_named(const std::string& name) {
  for (const PairTraits& t : kPairTraits)
    if (name == t.name) return t.kind;
  return std::nullopt;
}
/// The names of every kind, in table order (for the "unknown pair type" message).
inline std::vector<std::string> pair_kind_names() {
  std::vector<std::string> out;
  for (const PairTraits& t : kPairTraits) out.push_back(t.name);
  return out;
}

}  // namespace rollkin
