// Solving in the Python module: Scene.solve, write, centrodes, reference and solve_many, each sweep solved on
// worker threads with the GIL released.
//
// Threads: every solve, one scene or many, runs on worker threads (interruptible, bindings.hpp); the calling
// thread waits with the GIL released and, every kPollInterval, takes the GIL to run Python's signal handlers
// (PyErr_CheckSignals). A Ctrl-C there raises the cancellation flag that sweep() polls between poses
// (ContinuationSettings::cancel) and KeyboardInterrupt propagates; an assembly under way ends on its worker.
//
// Every call runs the library's output::SweepRun, as the CLI's commands do: the request checked and bounded,
// the files (Scene.write, Scene.centrodes(dxf=)) checked before solving (an output that is one of the scene's
// input files is refused) and written all or nothing.
#include "bindings.hpp"

#include "rollkin/analysis/centrodes.hpp"
#include "rollkin/io/input_error.hpp"
#include "rollkin/io/output_set.hpp"
#include "rollkin/output/sweep_table.hpp"
#include "rollkin/io/work_bound.hpp"
#include "rollkin/output/centrode_files.hpp"
#include "rollkin/output/sweep_files.hpp"
#include "rollkin/output/sweep_run.hpp"
#include "rollkin/solve/batch.hpp"
#include "rollkin/solve/continuation.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <functional>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace rollkin::python {
namespace {

// ---- solving ---------------------------------------------------------------------------------------------

/// What to solve: the sweep's overrides (None: the scene's own "sweep") and its bound, and the extra columns.
struct Request {
  rollkin::output::SweepRequest sweep;
  bool analysis = false, rates = false;
};

/// The keywords in the library's messages about a request.
const rollkin::output::RequestNames kKeywordNames{"start/stop/step", "start, stop and step", "max_steps"};

/// The files a scene read (never written over): its scene file (load_scene's path, scene()'s name=, kept by
/// modified() and pickling) and its contour files.
std::vector<rollkin::io::InputFile> input_files(const PyScene& s) {
  std::vector<rollkin::io::InputFile> inputs;
  if (!s.source.empty()) inputs.push_back({s.source, "the scene's input file '" + s.source + "'"});
  for (const std::string& f : s.scene->files_read)
    inputs.push_back({f, "the input file '" + f + "' (a contour file the scene read)"});
  return inputs;
}

/// The library's run of `s` (output::SweepRun: `outputs` checked against the scene's files, the sweep with the
/// request's overrides checked and bounded, as the CLI's), its refusals of the request as ValueError.
rollkin::output::SweepRun start_run(const PyScene& s, const Request& r,
                                    const std::vector<rollkin::output::OutputRequest>& outputs = {}) {
  try {
    return rollkin::output::SweepRun(s.scene, input_files(s), outputs, r.sweep, kKeywordNames);
  } catch (const rollkin::output::SweepRequestError& e) {
    throw py::value_error(e.what());
  } catch (const rollkin::io::WorkLimitError& e) {
    throw py::value_error(s.scene->file + ": " + e.what());
  }
}

/// One scene to solve and, once solved, its table (and, for writing files from it, its sweep result).
struct Job {
  rollkin::output::SweepRun run;
  rollkin::SolveReport<double> assembly;
  rollkin::io::SweepColumns table;
  std::exception_ptr error;
  bool keep_result = false;    // keep `result` (Scene.write, Scene.centrodes)
  std::optional<rollkin::SweepResult<double>> result;
};

/// Assembles and sweeps one scene and builds its table (on a worker thread: no Python here). Exceptions are
/// kept in job.error.
void run(Job& job, const Request& r, const std::atomic<bool>& cancel) {
  try {
    rollkin::SolveData<double> sd(job.run.mechanism());
    rollkin::VectorX<double> q;
    if (cancel) return;
    job.assembly = job.run.try_assemble(sd, q);
    if (cancel) return;
    // A table alone (solve, solve_many) reads the link poses the sweep keeps (ContinuationSettings::
    // link_poses: equal to round-off to the tree's pairs evaluated again); the files of write() are the CLI's,
    // byte for byte, so their table evaluates them as the CLI does.
    job.result = job.run.solve(sd, q, job.assembly, &cancel, !job.keep_result);
    if (cancel) return;
    job.table = rollkin::io::sweep_columns(job.run.output(*job.result, r.analysis), r.rates);
    if (!job.keep_result) job.result.reset();
  } catch (...) {
    job.error = std::current_exception();
  }
}

/// Solves every job on up to `threads` worker threads (0: one per core; rollkin::run_batch), the calling thread
/// checking for Ctrl-C (interruptible): a KeyboardInterrupt cancels the workers (between poses) and propagates;
/// an assembly under way ends on its worker, its result dropped.
void run_all(const std::shared_ptr<std::vector<Job>>& jobs, const Request& r, int threads) {
  if (threads < 0) throw py::value_error("threads must be >= 0 (0: one per core), got " + std::to_string(threads));
  interruptible<bool>([jobs, r, threads](const std::atomic<bool>& stop) {
    rollkin::run_batch(
        jobs->size(), threads, [&](std::size_t k, const std::atomic<bool>& cancel) { run((*jobs)[k], r, cancel); },
        [&] { return stop.load(); }, kPollInterval);
    return true;
  });
}

/// The column names of the tables as Python str, made once for every table with the same names (the
/// variants of a batch): each name is encoded once per call, not once per table.
class ColumnKeys {
 public:
  const std::vector<py::str>& of(const std::vector<std::string>& names) {
    if (names != names_) {
      names_ = names;
      keys_.clear();
      for (const std::string& n : names) keys_.emplace_back(n);
    }
    return keys_;
  }

 private:
  std::vector<std::string> names_;
  std::vector<py::str> keys_;
};

/// Every column of `t` as a float64 array over the table's block, as it is (no copy): one capsule owns the
/// block and each array holds a reference to it, so the block lives while any of its arrays does. Made with
/// NumPy's C API (PyArray_NewFromDescr, as pybind11's array does, without its shape and strides vectors).
void add_columns(rollkin::io::SweepColumns& t, const std::vector<py::str>& keys, py::dict& out) {
  if (!t.values) return;  // no table (never built)
  const std::size_t rows = t.rows();
  double* const block = t.values.get();
  const py::capsule owner(block, [](void* p) { delete[] static_cast<double*>(p); });
  t.values.release();  // the capsule owns the block now
  auto& api = py::detail::npy_api::get();
  const py::dtype f8 = py::dtype::of<double>();
  Py_intptr_t shape = static_cast<Py_intptr_t>(rows), stride = sizeof(double);
  for (std::size_t c = 0; c < keys.size(); ++c) {
    const auto array = py::reinterpret_steal<py::object>(
        api.PyArray_NewFromDescr_(api.PyArray_Type_, f8.inc_ref().ptr(), 1, &shape, &stride, block + c * rows,
                                  py::detail::npy_api::NPY_ARRAY_WRITEABLE_, nullptr));
    if (!array) throw py::error_already_set();
    if (api.PyArray_SetBaseObject_(array.ptr(), owner.inc_ref().ptr()) != 0) throw py::error_already_set();
    if (PyDict_SetItem(out.ptr(), keys[c].ptr(), array.ptr()) != 0) throw py::error_already_set();
  }
}

/// The statuses as a NumPy array of str (dtype <U width of the longest present): each distinct status's
/// name is encoded once and copied into the rows of the array's UCS-4 buffer.
py::array status_array(const std::vector<rollkin::SolveStatus>& status) {
  std::vector<std::u32string> name;  // by code, "" for a status not present
  std::size_t width = 1;
  for (const rollkin::SolveStatus s : status) {
    const auto code = static_cast<std::size_t>(s);
    if (code >= name.size()) name.resize(code + 1);
    if (!name[code].empty()) continue;
    for (const char* c = rollkin::to_string(s); *c; ++c) name[code] += static_cast<char32_t>(static_cast<unsigned char>(*c));
    width = std::max(width, name[code].size());
  }
  for (std::u32string& n : name) n.resize(width, U'\0');
  py::array out(py::dtype("<U" + std::to_string(width)), py::array::ShapeContainer{static_cast<py::ssize_t>(status.size())});
  auto* chars = static_cast<char32_t*>(out.mutable_data());
  for (const rollkin::SolveStatus s : status) {
    std::memcpy(chars, name[static_cast<std::size_t>(s)].data(), width * sizeof(char32_t));
    chars += width;
  }
  return out;
}

/// A solved job as a dict: column name -> float64 array, "status" -> array of str; a scene that cannot be
/// assembled also "error": the InputError message Scene.solve would raise for it. The columns' block moves
/// into the arrays: the job's table has no values afterwards.
py::dict to_dict(Job& job, ColumnKeys& keys) {
  rollkin::io::SweepColumns& t = job.table;
  py::dict out;
  add_columns(t, keys.of(t.names), out);
  out["status"] = status_array(t.status);
  if (job.assembly.status == rollkin::SolveStatus::CannotAssemble)
    out["error"] = rollkin::io::assembly_error(job.run.scene(), job.assembly.detail).what();
  return out;
}

/// Solves one prepared run on a worker thread; an assembly that fails is an InputError, as in the CLI.
Job solved(rollkin::output::SweepRun run, const Request& r, bool keep_result) {
  auto jobs = std::make_shared<std::vector<Job>>();
  jobs->push_back(Job{std::move(run)});
  Job& job = jobs->front();
  job.keep_result = keep_result;
  run_all(jobs, r, 1);
  if (job.error) std::rethrow_exception(job.error);
  if (job.assembly.status == rollkin::SolveStatus::CannotAssemble)
    throw rollkin::io::assembly_error(job.run.scene(), job.assembly.detail);
  return std::move(job);
}

py::dict solve(const PyScene& s, const Request& r) {
  Job job = solved(start_run(s, r), r, false);
  ColumnKeys keys;
  return to_dict(job, keys);
}

// ---- files -----------------------------------------------------------------------------------------------

/// Checks every requested path (format keyword, path or None: output::sweep_formats()) before solving,
/// solves, and writes every file or none, as `rollkin solve` does.
py::dict write(const PyScene& s, const Request& r, const std::vector<std::pair<std::string, py::object>>& files) {
  std::vector<rollkin::output::OutputRequest> outputs;
  for (const auto& [format, path] : files)
    if (!path.is_none()) outputs.push_back({format, path_argument(path, format.c_str()), format});
  Job job = solved(start_run(s, r, outputs), r, true);
  job.run.write(job.run.output(*job.result, r.analysis), rollkin::output::WriteOptions{r.rates, 1});
  ColumnKeys keys;
  return to_dict(job, keys);
}

// ---- centrodes and the MPFR reference ----------------------------------------------------------------------

int link_named(const rollkin::io::Scene& scene, const std::string& name) {
  const int i = scene.mechanism.find_link(name);
  if (i >= 0) return i;
  std::string names;
  for (const rollkin::Link& l : scene.mechanism.links) names += (names.empty() ? "\"" : ", \"") + l.name + "\"";
  throw py::value_error("no link \"" + name + "\" in " + scene.file + "; its links are " + names);
}

/// The instant centres of link b relative to link a over the sweep, as arrays (analysis/centrodes.hpp), optionally
/// also written as DXF splines (the CLI's `centrodes --dxf`).
py::dict centrodes(const PyScene& s, const std::string& link_a, const std::string& link_b, const Request& r,
                   const py::object& dxf) {
  const int a = link_named(*s.scene, link_a), b = link_named(*s.scene, link_b);
  if (a == b) throw py::value_error("centrodes(): give two different links, got \"" + link_a + "\" twice");
  const std::string dxf_path = dxf.is_none() ? std::string() : path_argument(dxf, "dxf");
  Job job = solved(start_run(s, r, {{"dxf", dxf_path, ""}}), r, true);
  const rollkin::Mechanism<double>& m = s.scene->mechanism;
  rollkin::KinematicsData<double> kin(m);
  const auto centres = rollkin::centrodes(m, kin, *job.result, a, b);
  const rollkin::io::SweepOutput solved_sweep = job.run.output(*job.result);
  if (!dxf_path.empty()) {  // a centrode that is one point (a revolute joins the links) has no curve: no DXF, a warning
    const std::string single_point = rollkin::output::centrode_single_point(solved_sweep, centres, a, b);
    if (single_point.empty()) job.run.set_output("dxf", [&] { return rollkin::output::centrode_dxf(solved_sweep, centres, a, b); });
    else job.run.omit_output("dxf");
    job.run.commit();
    const std::string why = single_point + "; dxf not written: a point has no curve to draw as a spline";
    if (!single_point.empty() && PyErr_WarnEx(PyExc_RuntimeWarning, why.c_str(), 1) != 0) throw py::error_already_set();
  }
  const py::ssize_t n = static_cast<py::ssize_t>(centres.size());
  py::array_t<double> input(n), ax(n), ay(n), bx(n), by(n), wx(n), wy(n);
  py::array_t<bool> finite(n);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (py::ssize_t k = 0; k < n; ++k) {
    const auto& c = centres[static_cast<std::size_t>(k)];
    input.mutable_at(k) = solved_sweep.inputs[static_cast<std::size_t>(k)];
    finite.mutable_at(k) = c.finite;
    ax.mutable_at(k) = c.finite ? c.in_a.x() : nan;
    ay.mutable_at(k) = c.finite ? c.in_a.y() : nan;
    bx.mutable_at(k) = c.finite ? c.in_b.x() : nan;
    by.mutable_at(k) = c.finite ? c.in_b.y() : nan;
    wx.mutable_at(k) = c.finite ? c.world.x() : nan;
    wy.mutable_at(k) = c.finite ? c.world.y() : nan;
  }
  py::dict out;
  out[py::str(job.table.names.front())] = input;  // the input column's name
  out["a"] = py::module_::import("numpy").attr("column_stack")(py::make_tuple(ax, ay));
  out["b"] = py::module_::import("numpy").attr("column_stack")(py::make_tuple(bx, by));
  out["world"] = py::module_::import("numpy").attr("column_stack")(py::make_tuple(wx, wy));
  out["finite"] = finite;
  out["status"] = status_array(job.table.status);
  return out;
}

/// The sweep solved in MPFR (io::scene_reference) as float64 arrays: the columns of `rollkin reference --csv`
/// (display units), each value the decimal result correctly rounded to the nearest double.
py::dict reference(const PyScene& s, const Request& r, int digits) {
  if (digits != 30 && digits != 50 && digits != 100)
    throw py::value_error("reference(): digits must be 30, 50 or 100, got " + std::to_string(digits));
  const rollkin::output::SweepRun run = start_run(s, r);
  const rollkin::ReferenceSweep ref = interruptible<rollkin::ReferenceSweep>(
      [scene = s.scene, sweep = run.sweep(), digits](const std::atomic<bool>&) {
        return rollkin::io::scene_reference(*scene, sweep, digits);
      });
  if (ref.assembly_status == rollkin::SolveStatus::CannotAssemble)
    throw rollkin::io::assembly_error(*s.scene, ref.assembly_detail);
  const rollkin::Mechanism<double>& m = s.scene->mechanism;
  const int input = m.drivers[static_cast<std::size_t>(run.sweep().driver)];
  const py::ssize_t n = static_cast<py::ssize_t>(ref.poses.size());
  auto column = [&](auto field) {
    py::array_t<double> a(n);
    for (py::ssize_t k = 0; k < n; ++k) a.mutable_at(k) = std::strtod(field(ref.poses[static_cast<std::size_t>(k)]).c_str(), nullptr);
    return a;
  };
  auto solved_value = [](const rollkin::ReferencePose& p, const std::string& v) {
    const bool ok = p.status == rollkin::SolveStatus::Converged || p.status == rollkin::SolveStatus::Singular;
    return ok ? v : std::string("nan");
  };
  py::dict out;
  out[py::str(ref.variables[static_cast<std::size_t>(input)])] = column([](const rollkin::ReferencePose& p) { return p.input; });
  for (int i = 0; i < m.variable_count(); ++i)
    if (i != input)
      out[py::str(ref.variables[static_cast<std::size_t>(i)])] =
          column([&](const rollkin::ReferencePose& p) { return solved_value(p, p.q[static_cast<std::size_t>(i)]); });
  out["residual"] = column([&](const rollkin::ReferencePose& p) { return solved_value(p, p.residual); });
  std::vector<std::string> status;
  for (const auto& p : ref.poses) status.emplace_back(rollkin::to_string(p.status));
  out["status"] = str_array(status);
  return out;
}

py::list solve_many(const std::vector<PyScene>& scenes, const Request& r, int threads) {
  auto jobs = std::make_shared<std::vector<Job>>();
  jobs->reserve(scenes.size());
  for (const PyScene& s : scenes) jobs->push_back(Job{start_run(s, r)});
  run_all(jobs, r, threads);
  for (const Job& j : *jobs)
    if (j.error) std::rethrow_exception(j.error);
  py::list out(jobs->size());
  ColumnKeys keys;
  for (std::size_t k = 0; k < jobs->size(); ++k) out[k] = to_dict((*jobs)[k], keys);
  return out;
}

/// The request of a call; max_steps checked by the rule the CLI's --max-steps follows (io/work_bound.hpp).
Request request(std::optional<double> start, std::optional<double> stop, std::optional<double> step, bool analysis,
                bool rates, double max_steps) {
  const std::string bad = rollkin::io::max_steps_problem(max_steps);
  if (!bad.empty()) throw py::value_error("max_steps: " + bad);
  Request r;
  r.sweep.from = start;
  r.sweep.to = stop;
  r.sweep.step = step;
  r.sweep.max_steps = max_steps;
  r.analysis = analysis;
  r.rates = rates;
  return r;
}

// ---- docstrings ------------------------------------------------------------------------------------------

const char* const kSolveDoc = R"(Sweeps the scene's input and returns its table.

start, stop, step: the sweep of the scene's input in the file's units (degrees for an angle in a "deg" scene);
each None keeps the scene's "sweep" (a scene without one needs all three).
analysis=True adds the contact analysis columns (as --analysis), rates=True the rate columns (as --rates).
max_steps bounds the work like the CLI's --max-steps: a finite number >= 1 (ValueError otherwise); a sweep
estimated to need more continuation sub-steps, or of more values, raises ValueError (docs/reliability.md).

Returns a dict: CSV column name -> numpy float64 array (one value per input value, NaN where the pose was not
solved), and "status" -> numpy array of str ("ok", "singular", "dead_point", "domain_exit", "corner",
"no_convergence", "not_reached"); the same columns, in the same order, and the same values as
`rollkin solve SCENE --from START --to STOP --step STEP --csv`.
Raises InputError when the mechanism cannot be assembled (the CLI's exit 2), ValueError for a bad sweep.
The GIL is released while solving; Ctrl-C raises KeyboardInterrupt within about 50 ms of the next pose.)";

const char* const kSolveManyDoc = R"(Solves several scenes over the same sweep, on worker threads.

scenes: a list of Scene; start, stop, step, analysis, rates, max_steps: as Scene.solve (None keeps each
scene's own "sweep"). threads: the number of worker threads, 0 for one per core.
Returns a list of dicts, one per scene in order, each as Scene.solve returns it. A scene that cannot be
assembled does not stop the batch: its dict has NaN values and the status "cannot_assemble" in every row
and "error": the InputError message Scene.solve would raise for it. The GIL is released while solving; Ctrl-C
cancels the workers between poses and raises KeyboardInterrupt within a second.)";

const char* const kWriteDoc = R"(Solves like solve() and writes the CLI's output files from the result.

csv, plot, draw, animate: paths (None: not written) of the files `rollkin solve --csv --plot --draw --animate`
writes: the table, the charts (with analysis=True also the analysis charts), the drawing of the mechanism and
the self-contained HTML animation. Every path is checked before solving; a path that is one of the scene's
input files, a missing directory or a directory raises OutputError (an OSError) and nothing is written. The
files are written all or nothing, each through a temporary in its own directory. Returns the table as solve().)";

const char* const kCentrodesDoc = R"(The centrodes of link_b's motion relative to link_a over the sweep.

Returns a dict: the input column (as in solve()), "a" and "b": (n, 2) arrays of the instant centre in link_a's
frame (the fixed centrode when link_a is the ground) and in link_b's frame (the moving centrode), "world": in
the world frame, "finite": False where the centre is at infinity (pure relative translation) or the pose was not
solved (NaN rows), "status" as in solve(). dxf: a path for both centrodes as DXF splines (as the CLI's
`rollkin centrodes --dxf`), written only after the sweep succeeded, never over an input file.)";

const char* const kReferenceDoc = R"(The same assembly and sweep solved in MPFR with `digits` decimal digits (30, 50, 100).

Returns a dict of float64 arrays with the columns of `rollkin reference --csv` (the input, every other
variable in the file's units, "residual") and "status": each value is the high-precision result rounded once
to the nearest double, so solve()'s columns can be compared with it to measure the double solver's error.
The MPFR run takes milliseconds per pose; it holds no GIL, and Ctrl-C returns from it at once (KeyboardInterrupt)
while the MPFR sweep under way ends on its worker thread.)";

}  // namespace

void bind_solving(py::module_& m, py::class_<PyScene>& scene) {
  scene
      .def("solve",
           [](const PyScene& s, std::optional<double> start, std::optional<double> stop, std::optional<double> step,
              bool analysis, bool rates, double max_steps) {
             return solve(s, request(start, stop, step, analysis, rates, max_steps));
           },
           py::arg("start") = py::none(), py::arg("stop") = py::none(), py::arg("step") = py::none(), py::kw_only(),
           py::arg("analysis") = false, py::arg("rates") = false, py::arg("max_steps") = rollkin::io::kDefaultMaxSteps, kSolveDoc)
      .def("write",
           [](const PyScene& s, std::optional<double> start, std::optional<double> stop, std::optional<double> step,
              const py::object& csv, const py::object& plot, const py::object& draw, const py::object& animate,
              bool analysis, bool rates, double max_steps) {
             return write(s, request(start, stop, step, analysis, rates, max_steps),
                          {{"csv", csv}, {"plot", plot}, {"draw", draw}, {"animate", animate}});
           },
           py::arg("start") = py::none(), py::arg("stop") = py::none(), py::arg("step") = py::none(), py::kw_only(),
           py::arg("csv") = py::none(), py::arg("plot") = py::none(), py::arg("draw") = py::none(),
           py::arg("animate") = py::none(), py::arg("analysis") = false, py::arg("rates") = false,
           py::arg("max_steps") = rollkin::io::kDefaultMaxSteps, kWriteDoc)
      .def("centrodes",
           [](const PyScene& s, const std::string& a, const std::string& b, std::optional<double> start,
              std::optional<double> stop, std::optional<double> step, const py::object& dxf, double max_steps) {
             return centrodes(s, a, b, request(start, stop, step, false, false, max_steps), dxf);
           },
           py::arg("link_a"), py::arg("link_b"), py::arg("start") = py::none(), py::arg("stop") = py::none(),
           py::arg("step") = py::none(), py::kw_only(), py::arg("dxf") = py::none(), py::arg("max_steps") = rollkin::io::kDefaultMaxSteps,
           kCentrodesDoc)
      .def("reference",
           [](const PyScene& s, std::optional<double> start, std::optional<double> stop, std::optional<double> step,
              int digits, double max_steps) {
             return reference(s, request(start, stop, step, false, false, max_steps), digits);
           },
           py::arg("start") = py::none(), py::arg("stop") = py::none(), py::arg("step") = py::none(), py::kw_only(),
           py::arg("digits") = 50, py::arg("max_steps") = rollkin::io::kDefaultMaxSteps, kReferenceDoc);

  m.def("solve_many",
        [](const std::vector<PyScene>& scenes, std::optional<double> start, std::optional<double> stop,
           std::optional<double> step, int threads, bool analysis, bool rates, double max_steps) {
          return solve_many(scenes, request(start, stop, step, analysis, rates, max_steps), threads);
        },
        py::arg("scenes"), py::arg("start") = py::none(), py::arg("stop") = py::none(), py::arg("step") = py::none(),
        py::arg("threads") = 0, py::kw_only(), py::arg("analysis") = false, py::arg("rates") = false,
        py::arg("max_steps") = rollkin::io::kDefaultMaxSteps, kSolveManyDoc);
  m.def("_sweep_seconds",
        [](const PyScene& s, std::optional<double> start, std::optional<double> stop, std::optional<double> step,
           bool table) {
          // Benchmark hook (bench/python_bench.py): wall time of the C++ loop, assembly and sweep, with no NumPy:
          // without the table (the bare solve) or with it (io::sweep_columns, the table solve() returns, made
          // and dropped), for the overhead of Python and dask per variant against it.
          rollkin::output::SweepRun run = start_run(s, request(start, stop, step, false, false, rollkin::io::kDefaultMaxSteps));
          py::gil_scoped_release nogil;
          const auto t0 = std::chrono::steady_clock::now();
          rollkin::SolveData<double> sd(run.mechanism());
          rollkin::VectorX<double> q;
          const auto assembly = run.try_assemble(sd, q);
          const auto result = run.solve(sd, q, assembly, nullptr, table);
          if (table) {
            [[maybe_unused]] const auto columns = rollkin::io::sweep_columns(run.output(result), false);
          }
          const std::chrono::duration<double> t = std::chrono::steady_clock::now() - t0;
          return t.count();
        },
        py::arg("scene"), py::arg("start") = py::none(), py::arg("stop") = py::none(), py::arg("step") = py::none(),
        py::arg("table") = false);
}

}  // namespace rollkin::python
