// What a solve tells its caller. A solve never throws or prints for a numerical outcome; it returns one of
// these and the caller (CLI, tests) decides what to say.
#pragma once

#include <ostream>
#include <string>

namespace rollkin {

enum class SolveStatus {
  Converged,        // pose found
  Singular,         // pose found (values follow the branch), but the Jacobian of the unknowns is singular there:
                    // branches meet; the values come from the regular poses on both sides (continuation.hpp)
  DeadPoint,        // motion limit: the Jacobian of the unknowns turns singular, the input cannot go on
  DomainExit,       // a contact parameter leaves its open contour's domain
  Corner,           // a contact reaches a corner of its contour (a tangent discontinuity: no contact beyond)
  NoConvergence,    // Newton did not converge (not identified as a limit)
  CannotAssemble,   // inconsistent constraints: least-squares residual stays above tolerance
  Underdetermined,  // more degrees of freedom than drivers: the pose is not fixed by the inputs
  NotReached        // a requested input beyond a limit met earlier in the sweep
};

inline const char* to_string(SolveStatus s) {
  switch (s) {
    case SolveStatus::Converged: return "ok";
    case SolveStatus::Singular: return "singular";
    case SolveStatus::DeadPoint: return "dead_point";
    case SolveStatus::DomainExit: return "domain_exit";
    case SolveStatus::Corner: return "corner";
    case SolveStatus::NoConvergence: return "no_convergence";
    case SolveStatus::CannotAssemble: return "cannot_assemble";
    case SolveStatus::Underdetermined: return "underdetermined";
    case SolveStatus::NotReached: return "not_reached";
  }
  return "?";
}

inline std::ostream& operator<<(std::ostream& os, SolveStatus s) { return os << to_string(s); }

template <class S> struct SolveReport {
  SolveStatus status = SolveStatus::NoConvergence;
  int iterations = 0;       // Newton steps taken
  int evaluations = 0;      // constraint evaluations, each with its Jacobian factorisation
  S residual = S(0);        // max-norm of the scaled residual at the returned pose; in a sweep, at the pose the
                            // closing step started from (continuation.hpp), which that Newton step only lowers
  S condition = S(0);       // condition estimate of the scaled Jacobian of the unknowns
  int rank = 0;             // numerical rank of the unknowns' Jacobian
  int equations = 0;        // number of constraint equations
  int unknowns = 0;
  // Where a limit lies (DeadPoint, DomainExit, Corner): the input value, and for DomainExit and Corner the pair
  // and contour, for Corner the index in Contour::corners().
  S limit_input = S(0);
  int pair = -1;
  int contour = -1;
  int corner = -1;
  std::string detail;       // one human-readable sentence

  /// Plainly solved: a regular pose.
  bool ok() const { return status == SolveStatus::Converged; }
  /// The pose's values are available (solved, or singular with values that follow the branch).
  bool has_pose() const { return status == SolveStatus::Converged || status == SolveStatus::Singular; }
  int redundant() const { return equations - rank; }
};

}  // namespace rollkin
