// The forces of a solved sweep (docs/forces.md): every solved pose's kinetostatics (analysis/forces.hpp) at the
// scene's speed, as the --forces columns of the result table, the statuses `separation` and `slip`, and the
// summary: separation speed per contact pair (located between poses), the largest friction a rolling pair
// needs, the peak drive effort and power, the massless links and the reactions redundant constraints leave
// open.
//
//   output::SweepForceReport f = output::sweep_forces(scene, sweep, rows, sd.kin.reference, speed);
//   io::SweepOutput out = run.output(rows);
//   out.forces = &f.table;  // the columns in the CSV and the charts
#pragma once

#include "rollkin/output/force_table.hpp"
#include "rollkin/io/scene/reader.hpp"
#include "rollkin/output/sweep_rows.hpp"

#include <string>
#include <vector>

namespace rollkin::output {

struct SweepForceReport {
  io::ForceTable table;
  std::vector<std::string> summary;   // lines for stdout
  std::vector<std::string> problems;  // lines for stderr: separation, slip, poses without forces, no Hertz contact
  bool separation_or_slip = false;    // some pose has status `separation` or `slip` (exit 1)
};

/// Thrown when a scene cannot give forces (no "dynamics", an input that is a contact parameter): the
/// command line's exit 2, with the scene's file in the message.
struct ForcesUnavailable : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// The forces of every solved row at input speed `speed` (internal units per second: rad/s, or scene lengths
/// per second) of the sweep `sweep` on `scene` (which must have dynamics). `reference`: the rolling pairs'
/// arc-length origins of the assembly (SolveData::kin.reference after assemble), used to solve the poses
/// between rows where a separation speed is located.
SweepForceReport sweep_forces(const io::Scene& scene, const Sweep& sweep, const io::SweepRows& rows,
                              const VectorX<double>& reference, double speed);

}  // namespace rollkin::output
