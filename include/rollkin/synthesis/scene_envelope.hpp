// The envelope (synthesis/envelope.hpp) of a contour of a scene's link B under B's motion relative to link A
// along a solved sweep (docs/synthesis.md, "The envelope of a scene's contour").
//
// At each solved pose k of the sweep (input t_k) the relative pose of B in A, angle phi = phi_B - phi_A and
// origin d = R_A^T (o_B - o_A), and its rates from the velocity solution (qdot, kinematics.hpp link_twists):
//   phi' = omega_B - omega_A,     d' = R_A^T (o_B' - o_A') - phi_A' J d,     o' = v + omega J o (spatial twist)
// are interpolated between poses by cubic Hermite polynomials in t (value and rate at both ends; the angle
// unwrapped), which gives the engine the pose and its first two derivatives at any t in the sweep's range:
// the interpolation error is O(h^4) in the sweep's step h (1e-14 relative at 0.1 degree steps).
#pragma once

#include "rollkin/kinematics.hpp"
#include "rollkin/solve/sweep_result.hpp"
#include "rollkin/synthesis/envelope.hpp"

#include <optional>
#include <string>
#include <vector>

namespace rollkin::synthesis {

class SweepMotion {
 public:
  /// Needs every pose of `sweep` solved (has_pose) and at least 2 poses; throws std::invalid_argument otherwise.
  SweepMotion(const Mechanism<double>& m, const SweepResult<double>& sweep, int a, int b);

  MotionJet<double> operator()(double t) const;
  double t_begin() const { return t_.front(); }
  double t_end() const { return t_.back(); }
  /// The relative pose at the end equals the one at the start (angle modulo a turn) to 1e-9 of the scale.
  bool periodic() const { return periodic_; }

 private:
  std::vector<double> t_, phi_, dphi_;
  std::vector<Vec2<double>> d_, dd_;
  bool periodic_ = false;
};

/// The one check of an envelope request's numbers, shared by `rollkin synthesize envelope` (--start,
/// --tolerance) and Python's envelope(start=, tolerance=): "" when fine, else what is wrong and what is expected.
/// `start`: a contour parameter, finite; `tolerance`: a distance, finite and > 0.
std::string envelope_start_problem(double start);
std::string envelope_tolerance_problem(double tolerance);

/// The envelope problem of contour `contour` (on link b) under the sweep's motion relative to link a.
/// `u_start`: the contour parameter near the contact at the first pose; without it the root of the meshing
/// equation nearest (in B's frame) to the instant centre at the first pose, among 2000 points of the domain.
/// Throws std::invalid_argument for a start that envelope_start_problem refuses.
EnvelopeProblem<double> scene_envelope_problem(const Mechanism<double>& m, const SweepMotion& motion, int contour,
                                               const std::optional<double>& u_start);

}  // namespace rollkin::synthesis
