// The paper example (examples/paper_fourbar.json) swept past its dead point: a sweep with both sides of the
// assembly input, a limit and rows not reached, for the tests of the sweep's outputs.
#pragma once

#include "rollkin/io/scene/reader.hpp"
#include "rollkin/solve/continuation.hpp"
#include "rollkin/solve/position.hpp"

#include <boost/test/unit_test.hpp>

#include <string>
#include <vector>

namespace rollkin::testing {

/// The paper example swept from -50 to `to` degrees by `step`, past its dead point (one limit, then
/// not_reached rows with NaN).
struct PaperSweep {
  io::Scene scene = io::load_scene(std::string(ROLLKIN_SOURCE_DIR) + "/examples/paper_fourbar.json");
  Sweep sw;
  std::vector<double> inputs, values;
  SweepResult<double> result;

  PaperSweep(double to, double step) : sw(*scene.sweep), result(solve(to, step)) {}

  /// The same sweep reported into `out` (sweep_into, continuation.hpp) from a fresh assembly.
  template <class Out> void sweep_again(Out& out) const {
    SolveData<double> sd(scene.mechanism);
    VectorX<double> q = scene.guess;
    const SolveReport<double> assembly = assemble(scene.mechanism, q, sd, scene.held);
    sweep_into(scene.mechanism, sd, q, assembly, sw.driver, inputs, {}, out);
  }
  /// The assembly's report (as sweep_again assembles).
  SolveReport<double> assembly() const { return result.assembly; }

 private:
  SweepResult<double> solve(double to, double step) {
    sw.from = -50;
    sw.to = to;
    sw.step = step;
    inputs = sweep_inputs(sw);
    values = sweep_values(sw);
    SolveData<double> sd(scene.mechanism);
    VectorX<double> q = scene.guess;
    const SolveReport<double> assembly = assemble(scene.mechanism, q, sd, scene.held);
    BOOST_TEST_REQUIRE(assembly.ok());
    SweepResult<double> r = sweep(scene.mechanism, sd, q, assembly, sw.driver, inputs);
    BOOST_TEST_REQUIRE(r.limits.size() == 1u);
    BOOST_TEST_REQUIRE(!r.has_pose(inputs.size() - 1));
    return r;
  }
};

}  // namespace rollkin::testing
