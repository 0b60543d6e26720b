// The sweep of a synthesis round trip by the path of `rollkin solve` (include/rollkin/synthesis/round_trip.hpp).
#include "rollkin/synthesis/round_trip.hpp"

#include "rollkin/solve/continuation.hpp"

namespace rollkin::synthesis {
namespace {

/// "N singular poses (at cam angle 12.5, 13.5, 14.5, ... deg)": the inputs of the poses with `status`, the first
/// few of them.
std::string poses_with(const RoundTripSweep& r, SolveStatus status, const RoundTripInput& input) {
  std::size_t count = 0;
  std::string at;
  for (std::size_t k = 0; k < r.result.size(); ++k) {
    if (r.result.status(k) != status) continue;
    if (++count <= 3) at += (at.empty() ? "" : ", ") + input.value(r.result.input(k));
  }
  if (count == 0) return "";
  return std::to_string(count) + " " + to_string(status) + " pose" + (count == 1 ? "" : "s") + " (at " + input.name + " " + at +
         (count > 3 ? ", ..." : "") + input.unit + ")";
}

}  // namespace

std::vector<double> round_trip_inputs(std::size_t poses, int direction) {
  std::vector<double> inputs;
  for (std::size_t k = 0; k <= poses; ++k) inputs.push_back(direction * 2 * pi<double>() * double(k) / double(poses));
  return inputs;
}

RoundTripSweep round_trip_sweep(const io::Scene& scene, const std::vector<double>& inputs, const RoundTripInput& input) {
  const Mechanism<double>& m = scene.mechanism;
  SolveData<double> sd(m);
  VectorX<double> q = scene.guess;
  const SolveReport<double> assembly = assemble(m, q, sd, scene.held);
  if (assembly.status == SolveStatus::CannotAssemble) throw io::assembly_error(scene, assembly.detail);
  RoundTripSweep r;
  r.result = sweep(m, sd, q, assembly, scene.sweep->driver, inputs, ContinuationSettings<double>{});
  r.summary = summarise(r.result);
  for (const auto& l : r.result.limits)
    r.problems.push_back("the sweep stopped at " + input.name + " " + input.value(l.limit_input) + input.unit + ": " + l.detail);
  for (SolveStatus s : {SolveStatus::Singular, SolveStatus::DeadPoint, SolveStatus::DomainExit, SolveStatus::Corner,
                        SolveStatus::NoConvergence, SolveStatus::Underdetermined, SolveStatus::NotReached})
    if (std::string line = poses_with(r, s, input); !line.empty()) r.problems.push_back(line);
  return r;
}

}  // namespace rollkin::synthesis
