// The run of one sweep, shared by the command line and the Python module (rollkin/output/sweep_run.hpp).
#include "rollkin/output/sweep_run.hpp"

#include "rollkin/output/sweep_file.hpp"
#include "rollkin/solve/continuation.hpp"

#include <utility>

namespace rollkin::output {
namespace {

/// The sweep to run: the scene's, with the request's overrides (their text as given), checked.
Sweep requested_sweep(const io::Scene& scene, const SweepRequest& r, const RequestNames& names) {
  std::optional<Sweep> s = io::requested_sweep(scene, r.from, r.to, r.step);
  if (!s) throw SweepRequestError(scene.file + " has no \"sweep\"; give " + names.range_list);
  if (r.from && !r.from_text.empty()) s->from_text = r.from_text;
  if (r.to && !r.to_text.empty()) s->to_text = r.to_text;
  if (r.step && !r.step_text.empty()) s->step_text = r.step_text;
  const std::string bad = check_sweep(*s);
  if (!bad.empty()) throw SweepRequestError(names.range + ": " + bad);
  return *s;
}

}  // namespace

SweepRun::SweepRun(std::shared_ptr<const io::Scene> scene, std::vector<io::InputFile> inputs,
                   const std::vector<OutputRequest>& outputs, const SweepRequest& request, const RequestNames& names)
    : scene_(std::move(scene)), outputs_(std::make_unique<io::OutputSet>(std::move(inputs))), files_(*outputs_) {
  for (const OutputRequest& o : outputs) {
    if (o.path.empty()) continue;
    if (o.format.empty()) given_[o.label] = outputs_->add(o.label, o.path);
    else files_.request(o.format, o.path, o.label);
  }
  sweep_ = requested_sweep(*scene_, request, names);
  inputs_ = io::bounded_inputs(*scene_, sweep_, request.max_steps, names.max_steps);
}

const std::vector<double>& SweepRun::values() {
  if (!values_) values_ = sweep_values(sweep_);
  return *values_;
}

SolveReport<double> SweepRun::try_assemble(SolveData<double>& sd, VectorX<double>& q) const {
  q = scene_->guess;
  return rollkin::assemble(scene_->mechanism, q, sd, scene_->held);
}

SolveReport<double> SweepRun::assemble(SolveData<double>& sd, VectorX<double>& q) const {
  const SolveReport<double> assembly = try_assemble(sd, q);
  if (assembly.status == SolveStatus::CannotAssemble) throw io::assembly_error(*scene_, assembly.detail);
  return assembly;
}

SweepResult<double> SweepRun::solve(SolveData<double>& sd, const VectorX<double>& q, const SolveReport<double>& assembly,
                                    const std::atomic<bool>* cancel, bool link_poses) const {
  ContinuationSettings<double> cfg;
  cfg.cancel = cancel;
  cfg.link_poses = link_poses;
  return rollkin::sweep(scene_->mechanism, sd, q, assembly, sweep_.driver, inputs_, cfg);
}

void SweepRun::solve_into(SolveData<double>& sd, const VectorX<double>& q, const SolveReport<double>& assembly,
                          io::SweepFile& file) const {
  io::sweep_to_file(scene_->mechanism, sd, q, assembly, sweep_.driver, inputs_, {}, file);
}

SweepSummary<double> SweepRun::summary(SolveData<double>& sd, const VectorX<double>& q, const SolveReport<double>& assembly) const {
  return sweep_summary(scene_->mechanism, sd, q, assembly, sweep_.driver, inputs_);
}

io::SweepOutput SweepRun::output(io::SweepRows rows, bool analysis) {
  return io::SweepOutput{*scene_, sweep_, rows, values(), analysis};
}

void SweepRun::write(const io::SweepOutput& out, const WriteOptions& options) {
  files_.write(out, options);
  outputs_->commit();
}

void SweepRun::set_output(const std::string& label, const std::function<std::string()>& make_text) {
  const auto it = given_.find(label);
  if (it != given_.end()) outputs_->set(it->second, make_text());
}

void SweepRun::omit_output(const std::string& label) {
  const auto it = given_.find(label);
  if (it != given_.end()) outputs_->omit(it->second);
}

void SweepRun::commit() { outputs_->commit(); }

}  // namespace rollkin::output
