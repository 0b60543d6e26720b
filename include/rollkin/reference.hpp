// High-precision reference solutions: the same assembly and continuation code as the double solver, run in
// Boost.Multiprecision MPFR (30, 50 or 100 decimal digits), with the poses returned as decimal strings.
//
//   ReferenceSweep r = reference_sweep(mech, guess, held, driver, inputs, 50);
//   write_reference_csv(r, mech, "paper_fourbar_50digits.csv");
//
// The double entry points cast the mechanism with Mechanism::cast<T>(): every double number of the
// description (lengths, placements, guess) is taken exactly, so the reference is the exact solution of the
// mechanism *as described in double*, and comparing the double solver with it measures the solver's error
// alone (no 1e-16 description round-off on either side). A mechanism built directly in MPFR (exact
// irrational data, e.g. sqrt(1 - e^2)) goes through the template reference_sweep_mp().
//
// Tolerances derive from the MPFR epsilon (NewtonSettings<S> defaults: residual 64 eps, step eps^(3/4)).
// Only the consistency tolerance of least-squares solves (redundant constraints) is relaxed to 1e-13:
// an overconstrained mechanism described in double (e.g. twin ellipses whose semi-minor axis was rounded) is
// inconsistent at the 1e-16 level, which 50 digits would otherwise report as CannotAssemble; the
// least-squares residual of every pose is returned so such a reference is visibly limited by its input.
//
// The MPFR instantiations (30, 50, 100 digits) live in src/reference_mp30.cpp, reference_mp50.cpp and
// reference_mp100.cpp only: including this header does not compile the solver in MPFR.
#pragma once

#include "rollkin/kinematics.hpp"
#include "rollkin/solve/report.hpp"

#include <string>
#include <vector>

namespace rollkin {

/// One requested input of a reference sweep.
struct ReferencePose {
  SolveStatus status = SolveStatus::NotReached;
  std::string input;               // driver value in display units (degrees for angles), `digits` digits
  std::vector<std::string> q;      // every variable in display units (degrees for angles), `digits` digits
  std::vector<std::string> q_raw;  // every variable in solver units (radians for angles), `digits` digits
  std::string residual;            // max-norm of the scaled constraint residual at the pose (3 digits)
  int iterations = 0;
};

struct ReferenceSweep {
  int digits = 50;
  SolveStatus assembly_status = SolveStatus::NotReached;
  std::string assembly_detail;
  std::string assembly_residual;
  int rank = 0, equations = 0, unknowns = 0;
  std::vector<std::string> assembly_q_raw;  // assembled pose, solver units
  std::vector<std::string> variables;       // names, "<pair>.<var>"
  std::vector<ParamKind> kinds;
  std::vector<ReferencePose> poses;         // one per requested input, in the requested order
  std::vector<std::string> limits;          // limit reports met (status: detail, at input)
  bool all_solved() const {
    if (assembly_status != SolveStatus::Converged) return false;
    for (const auto& p : poses)
      if (p.status != SolveStatus::Converged) return false;
    return true;
  }
};

/// Options of a reference run. The defaults suit 50 digits; every tolerance not listed is eps-derived.
struct ReferenceOptions {
  /// Consistency tolerance of redundant (least-squares) constraints; see the header comment.
  double consistency_tolerance = 1e-13;
};

/// Assembles `mech` (cast to MPFR with `digits` = 30, 50 or 100 decimal digits) from `guess`, holding the
/// `held` variables at their guess values (as assemble()), and sweeps driver number `driver` (index into
/// mech.drivers) over `inputs` in solver units (radians for angles). Throws std::invalid_argument for
/// another digit count.
ReferenceSweep reference_sweep(const Mechanism<double>& mech, const VectorX<double>& guess, const std::vector<int>& held,
                               int driver, const std::vector<double>& inputs, int digits,
                               const ReferenceOptions& options = {});

/// Same, with the inputs as decimal strings in display units (degrees for an angle driver, scene units for a
/// length), parsed at full precision: "-50" is exactly -50 degrees, not the double nearest -50 pi/180.
ReferenceSweep reference_sweep_decimal(const Mechanism<double>& mech, const VectorX<double>& guess,
                                       const std::vector<int>& held, int driver,
                                       const std::vector<std::string>& inputs, int digits,
                                       const ReferenceOptions& options = {});

/// The generic core, for mechanisms built directly in MPFR. S must be one of mpfr_scalar<30>,
/// mpfr_scalar<50>, mpfr_scalar<100> (instantiated in src/reference.cpp; include rollkin/scalar_mpfr.hpp).
template <class S>
ReferenceSweep reference_sweep_mp(const Mechanism<S>& mech, const VectorX<S>& guess, const std::vector<int>& held,
                                  int driver, const std::vector<S>& inputs, const ReferenceOptions& options = {});

/// Writes one CSV row per requested input, columns as the CLI's CSV: the driver variable, every other
/// variable (display units: degrees for angles, scene units for lengths), the scaled residual and the
/// status ("ok", "dead_point", ...). Numbers are decimal strings with the sweep's significant digits; a pose
/// that was not solved has "nan" in its number columns. Header: the variable names (no unit suffixes).
/// Written atomically (io/atomic_file.hpp); throws std::runtime_error if the file cannot be written.
void write_reference_csv(const ReferenceSweep& ref, const Mechanism<double>& mech, const std::string& path);

/// The same CSV as text (for writing it with other outputs, all or nothing: io/output_set.hpp).
std::string reference_csv_text(const ReferenceSweep& ref, const Mechanism<double>& mech);

/// Reads a file written by write_reference_csv: the header's column names and the rows' fields as written.
/// Throws std::runtime_error if the file cannot be read or a row has the wrong number of fields.
struct ReferenceTable {
  std::vector<std::string> columns;             // driver, other variables..., residual, status
  std::vector<std::vector<std::string>> rows;
  int column(const std::string& name) const;    // index of a column, -1 if absent
};
ReferenceTable read_reference_csv(const std::string& path);

}  // namespace rollkin
