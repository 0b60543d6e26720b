// The sweep of a synthesis round trip (docs/synthesis.md, "`rollkin synthesize cam SPEC.json --out PREFIX`" and "Non-circular gears"): the scene a synthesis wrote is
// assembled and swept by the library's own path, the one `rollkin solve` takes (assemble, rollkin::sweep with
// the default ContinuationSettings, summarise), so a pose has one status whichever command solves it: a pose
// is solved when its status is `ok` (Converged); a `singular` pose, a limit or a pose not reached is a problem
// of the round trip, named with its input (docs/reliability.md, "Synthesis (issue 37)").
#pragma once

#include "rollkin/io/scene/reader.hpp"
#include "rollkin/solve/sweep_result.hpp"
#include "rollkin/solve/sweep_summary.hpp"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace rollkin::synthesis {

struct RoundTripSweep {
  SweepResult<double> result;    // every pose, as rollkin::sweep gives it
  SweepSummary<double> summary;  // summarise(result): the statuses `rollkin solve` reports
  std::vector<std::string> problems;  // one line per limit and per kind of pose not solved, with its inputs
};

/// `poses` + 1 equally spaced inputs over one turn of the scene's swept input (radians), signed by `direction`
/// (+1 or -1): a prime `poses` puts them between the samples of a synthesised contour.
std::vector<double> round_trip_inputs(std::size_t poses, int direction = 1);

/// How the problems' lines name the swept input: "cam angle" 12.5 " deg".
struct RoundTripInput {
  std::string name;                               // e.g. "cam angle", "gear1.phi"
  std::function<std::string(double)> value;      // an input (radians) in the spec's unit, as text
  std::string unit;                               // e.g. " deg" ("" for none)
};

/// Assembles `scene` (io::assembly_error when it cannot) and sweeps its driver over `inputs`.
RoundTripSweep round_trip_sweep(const io::Scene& scene, const std::vector<double>& inputs, const RoundTripInput& input);

}  // namespace rollkin::synthesis
