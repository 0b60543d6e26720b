// The Python module `rollkin` (pybind11): scenes loaded from files or built as dicts, overridden by JSON path,
// solved over a sweep into NumPy columns (the same columns and values as `rollkin solve --csv`, both built by
// io::sweep_table), and batches of scenes solved on worker threads with the GIL released. API: docs/python.md.
//
// Threads: every solve, one scene or many, runs on worker threads; the calling thread waits with the GIL
// released and, every kPollInterval, takes the GIL to run Python's signal handlers (PyErr_CheckSignals). A
// Ctrl-C there raises the cancellation flag that sweep() polls between poses (ContinuationSettings::cancel),
// the workers are joined and KeyboardInterrupt propagates.
//
// Files (Scene.write, Scene.centrodes(dxf=)) go through io::OutputSet like the CLI's: every path is checked
// before solving, an output that is one of the scene's input files is refused, and all are written or none.
#include "json_access.hpp"  // child(), index(), kind_of() of the scene reader's messages (src/io)

#include "animation.hpp"     // the CLI's writers (src/cli, library rollkin_outputs): plots, drawing, animation
#include "output.hpp"

#include "rollkin/centrodes.hpp"
#include "rollkin/io/input_error.hpp"
#include "rollkin/io/json_document.hpp"
#include "rollkin/io/output_set.hpp"
#include "rollkin/io/scene.hpp"
#include "rollkin/io/sweep_table.hpp"
#include "rollkin/solve/batch.hpp"
#include "rollkin/solve/continuation.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <exception>
#include <filesystem>
#include <functional>
#include <limits>
#include <cstdlib>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace py = pybind11;
using rollkin::InputError;
using rollkin::io::json;

namespace {

constexpr std::chrono::milliseconds kPollInterval{50};  // how often a waiting solve checks for Ctrl-C

// ---- Python values <-> JSON ------------------------------------------------------------------------------

/// A float NumPy array of 1 or 2 dimensions as JSON numbers (nested lists), read straight from its buffer:
/// a large contour array goes into the document without a Python list in between. Non-finite values are an
/// InputError at the element's JSON path.
json float_array_json(py::handle v, const std::string& path, const std::string& file) {
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(v);
  if (!a || a.ndim() < 1 || a.ndim() > 2)
    throw InputError(file, path, "a float array of " + std::to_string(a ? a.ndim() : 0) +
                                     " dimensions; expected a vector or an (n, k) array");
  const py::ssize_t rows = a.shape(0), cols = a.ndim() == 2 ? a.shape(1) : 1;
  const double* data = a.data();
  auto number = [&](py::ssize_t i, py::ssize_t j) -> json {
    const double d = data[i * cols + j];
    if (std::isfinite(d)) return d;
    const std::string at = a.ndim() == 2 ? rollkin::io::index(rollkin::io::index(path, static_cast<std::size_t>(i)), static_cast<std::size_t>(j))
                                            : rollkin::io::index(path, static_cast<std::size_t>(i));
    throw InputError(file, at, "the number " + std::string(py::str(py::float_(d))) + " is not finite; expected a finite number");
  };
  json out = json::array();
  out.get_ref<json::array_t&>().reserve(static_cast<std::size_t>(rows));
  for (py::ssize_t i = 0; i < rows; ++i) {
    if (a.ndim() == 1) {
      out.push_back(number(i, 0));
      continue;
    }
    json row = json::array();
    for (py::ssize_t j = 0; j < cols; ++j) row.push_back(number(i, j));
    out.push_back(std::move(row));
  }
  return out;
}

/// A Python value as JSON (dict, list/tuple, str, int, float, bool, None; NumPy arrays and scalars through
/// their tolist()). What JSON cannot hold (NaN, infinities, other types, nesting deeper than the scene reader
/// allows) is an InputError naming `file` and the value's JSON path.
json to_json(py::handle v, const std::string& path, const std::string& file, std::size_t depth = 1) {
  if (depth > rollkin::io::kMaxJsonDepth)
    throw InputError(file, path, "nested deeper than " + std::to_string(rollkin::io::kMaxJsonDepth) + " levels");
  if (v.is_none()) return nullptr;
  if (py::isinstance<py::bool_>(v)) return v.cast<bool>();
  if (py::isinstance<py::int_>(v)) {
    int overflow = 0;
    const long long i = PyLong_AsLongLongAndOverflow(v.ptr(), &overflow);
    if (!overflow) return i;
    return to_json(py::float_(py::reinterpret_borrow<py::object>(v)), path, file, depth);
  }
  if (py::isinstance<py::float_>(v)) {
    const double d = v.cast<double>();
    if (!std::isfinite(d)) throw InputError(file, path, "the number " + std::string(py::str(v)) + " is not finite; expected a finite number");
    return d;
  }
  if (py::isinstance<py::str>(v)) return v.cast<std::string>();
  if (py::isinstance<py::dict>(v)) {
    json out = json::object();
    for (auto item : py::reinterpret_borrow<py::dict>(v)) {
      if (!py::isinstance<py::str>(item.first))
        throw InputError(file, path, "a key " + std::string(py::repr(item.first)) + " that is not a string; JSON keys are strings");
      const std::string key = item.first.cast<std::string>();
      out[key] = to_json(item.second, rollkin::io::child(path, key), file, depth + 1);
    }
    return out;
  }
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
    json out = json::array();
    std::size_t i = 0;
    for (auto item : v) out.push_back(to_json(item, rollkin::io::index(path, i++), file, depth + 1));
    return out;
  }
  if (py::isinstance<py::array>(v) && py::array::ensure(v).dtype().kind() == 'f') return float_array_json(v, path, file);
  if (py::hasattr(v, "tolist") && py::hasattr(v, "dtype")) return to_json(v.attr("tolist")(), path, file, depth);
  throw InputError(file, path, "a Python " + std::string(py::str(v.get_type().attr("__name__"))) +
                                   " cannot be a scene value; expected a dict, list, str, number, bool or None");
}

/// A JSON value as Python objects (dict, list, str, int, float, bool, None).
py::object to_python(const json& j) {
  switch (j.type()) {
    case json::value_t::null: return py::none();
    case json::value_t::boolean: return py::bool_(j.get<bool>());
    case json::value_t::number_integer: return py::int_(j.get<long long>());
    case json::value_t::number_unsigned: return py::int_(j.get<unsigned long long>());
    case json::value_t::number_float: return py::float_(j.get<double>());
    case json::value_t::string: return py::str(j.get<std::string>());
    case json::value_t::array: {
      py::list out;
      for (const json& e : j) out.append(to_python(e));
      return std::move(out);
    }
    case json::value_t::object: {
      py::dict out;
      for (auto it = j.begin(); it != j.end(); ++it) out[py::str(it.key())] = to_python(it.value());
      return std::move(out);
    }
    default: return py::none();
  }
}

/// A path given to Python (str or os.PathLike) as text.
std::string path_text(const py::object& path) { return py::str(py::module_::import("os").attr("fspath")(path)); }

// ---- scenes ----------------------------------------------------------------------------------------------

/// A scene as Python sees it: the built scene and the JSON document it was built from (overrides edit a copy
/// of the document and build a new scene). Immutable, so batches share it between threads.
struct PyScene {
  std::shared_ptr<const rollkin::io::Scene> scene;
  std::shared_ptr<const json> document;
  std::string file;  // names the source in messages
  std::string dir;   // relative contour files are resolved against it
  std::string source;  // the scene file the document was read from ("" for a dict): never written over
};

/// `dir` is made absolute ("" is the working directory), so that a scene sent to another process (pickle, e.g.
/// to dask workers) finds its contour files wherever that process runs.
PyScene build(json document, const std::string& file, const std::string& dir, const std::string& source = {}) {
  const std::string where = (dir.empty() ? std::filesystem::current_path() : std::filesystem::absolute(dir)).string();
  auto scene = std::make_shared<const rollkin::io::Scene>(rollkin::io::build_scene(document, file, where));
  const std::string absolute_source = source.empty() ? source : std::filesystem::absolute(source).string();
  return PyScene{std::move(scene), std::make_shared<const json>(std::move(document)), file, where, absolute_source};
}

/// Pickling: the document as JSON text, the name and the directory; unpickling builds the scene again.
py::tuple scene_state(const PyScene& s) { return py::make_tuple(s.document->dump(), s.file, s.dir, s.source); }

PyScene scene_from_state(const py::tuple& t) {
  if (t.size() != 4) throw py::value_error("rollkin.Scene: a pickled state is (document, file, dir, source)");
  const std::string file = t[1].cast<std::string>();
  return build(rollkin::io::parse_json_document(t[0].cast<std::string>(), file), file, t[2].cast<std::string>(),
               t[3].cast<std::string>());
}

PyScene load_scene(const py::object& path) {
  const std::string file = path_text(path);
  return build(rollkin::io::read_scene_document(file), file, std::filesystem::path(file).parent_path().string(), file);
}

PyScene scene_from_dict(const py::dict& document, const py::object& base_dir, const std::string& name) {
  const std::string dir = base_dir.is_none() ? std::string() : path_text(base_dir);
  return build(to_json(document, "", name), name, dir);
}

/// The scene with each (JSON path, value) of `overrides` set in a copy of its document, then built and
/// checked like a file; messages name the file as "<file> (modified)".
PyScene modified(const PyScene& s, const py::dict& overrides) {
  const std::string suffix = " (modified)";
  const bool already = s.file.size() >= suffix.size() && s.file.compare(s.file.size() - suffix.size(), suffix.size(), suffix) == 0;
  const std::string file = already ? s.file : s.file + suffix;
  json document = *s.document;
  for (auto item : overrides) {
    if (!py::isinstance<py::str>(item.first))
      throw py::type_error("modified(): override keys are JSON paths (str) such as \"links[1].contours[0].a\", got " +
                           std::string(py::repr(item.first)));
    const std::string path = item.first.cast<std::string>();
    rollkin::io::set_at_path(document, path, to_json(item.second, path, file), file);
  }
  return build(std::move(document), file, s.dir, s.source);
}

/// An (n, 2) float64 array of points, checked: the shape and every value finite (ValueError naming the row).
using PointArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

void check_points(const PointArray& xy, const char* function, const char* argument) {
  const std::string what = std::string(function) + "(): " + argument;
  if (xy.ndim() != 2 || xy.shape(1) != 2)
    throw py::value_error(what + " must have shape (n, 2) (one row x, y per point), got " +
                          std::string(py::str(py::tuple(py::cast(std::vector<py::ssize_t>(xy.shape(), xy.shape() + xy.ndim()))))));
  auto a = xy.unchecked<2>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i)
    if (!std::isfinite(a(i, 0)) || !std::isfinite(a(i, 1)))
      throw py::value_error(what + ": row " + std::to_string(i) + " is not finite (" + std::string(py::str(py::float_(a(i, 0)))) +
                            ", " + std::string(py::str(py::float_(a(i, 1)))) + ")");
}

/// A contour dict of `type` with the given keys; `options` adds the contour's other keys.
py::dict contour_dict(const std::string& name, const char* type, const py::kwargs& options) {
  py::dict contour;
  contour["name"] = name;
  contour["type"] = type;
  for (auto item : options) contour[item.first] = item.second;
  return contour;
}

/// The array itself goes into the dict (no copy when the caller's array is already contiguous float64); the
/// scene's document takes one copy when the scene is built.
py::dict samples(const PointArray& xy, const std::string& name, const py::kwargs& options) {
  check_points(xy, "samples", "xy");
  py::dict contour = contour_dict(name, "samples", options);
  contour["points"] = xy;
  return contour;
}

/// A clamped uniform knot vector for n control points of degree p: p + 1 zeros, the interior knots 1 .. n - p - 1,
/// p + 1 values n - p (docs/scene_format.md, nurbs contours: any non-decreasing scale works).
py::array_t<double> clamped_uniform_knots(py::ssize_t n, int p) {
  py::array_t<double> knots(n + p + 1);
  double* k = knots.mutable_data();
  for (py::ssize_t i = 0; i < n + p + 1; ++i) k[i] = static_cast<double>(std::clamp<py::ssize_t>(i - p, 0, n - p));
  return knots;
}

py::dict nurbs(const PointArray& points, int degree, const py::object& knots, const py::object& weights,
               const std::string& name, const py::kwargs& options) {
  check_points(points, "nurbs", "points");
  if (degree < 1) throw py::value_error("nurbs(): degree must be >= 1, got " + std::to_string(degree));
  const py::ssize_t n = points.shape(0);
  if (n < degree + 1)
    throw py::value_error("nurbs(): " + std::to_string(n) + " control points given; degree " + std::to_string(degree) +
                          " needs at least degree + 1 = " + std::to_string(degree + 1));
  py::dict contour = contour_dict(name, "nurbs", options);
  contour["degree"] = degree;
  contour["points"] = points;
  contour["knots"] = knots.is_none() ? py::object(clamped_uniform_knots(n, degree)) : knots;
  if (!weights.is_none()) contour["weights"] = weights;
  return contour;
}

// ---- solving ---------------------------------------------------------------------------------------------

/// What to solve: the sweep's overrides (None: the scene's own "sweep") and the extra columns.
struct Request {
  std::optional<double> start, stop, step;
  bool analysis = false, rates = false;
  double max_steps = 1e7;
};

/// One scene to solve and, once solved, its table (and, for writing files from it, its sweep result).
struct Job {
  std::shared_ptr<const rollkin::io::Scene> scene;
  rollkin::io::Sweep sweep;
  std::vector<double> inputs;  // internal units
  rollkin::SolveReport<double> assembly;
  rollkin::io::SweepTable table;
  std::exception_ptr error;
  bool keep_result = false;    // keep `result` and `analysis` (Scene.write, Scene.centrodes)
  std::optional<rollkin::SweepResult<double>> result;
  rollkin::io::SweepAnalysis analysis;
  std::vector<double> values;  // the inputs in file units (the table's input column)
};

/// The sweep of `s` with the request's overrides, checked and bounded like the CLI's (ValueError otherwise).
Job prepare(const PyScene& s, const Request& r) {
  const rollkin::io::Scene& scene = *s.scene;
  Job job;
  job.scene = s.scene;
  const std::optional<rollkin::io::Sweep> requested = rollkin::io::requested_sweep(scene, r.start, r.stop, r.step);
  if (!requested) throw py::value_error(scene.file + " has no \"sweep\"; give start, stop and step");
  rollkin::io::Sweep& sw = job.sweep;
  sw = *requested;
  const std::string bad = rollkin::io::check_sweep(sw);
  if (!bad.empty()) throw py::value_error("start/stop/step: " + bad);
  job.inputs = rollkin::io::sweep_inputs(sw);
  const double estimate = rollkin::estimate_substeps(scene.mechanism, scene.guess, sw.driver, job.inputs);
  if (estimate > r.max_steps) {
    std::ostringstream os;
    os << scene.file << ": the sweep of " << sw.input << " from " << sw.from << " to " << sw.to << " needs an estimated "
       << estimate << " continuation sub-steps, above max_steps = " << r.max_steps
       << "; ask for a smaller range, a larger step, or raise max_steps";
    throw py::value_error(os.str());
  }
  return job;
}

/// What the CLI's writers take: the solved sweep of a job (job.result set).
rollkin::io::SweepOutput output_of(const Job& job, const Request& r) {
  return {*job.scene, job.sweep, *job.result, job.values, r.analysis ? &job.analysis : nullptr};
}

/// Assembles and sweeps one scene (on a worker thread: no Python here). Exceptions are kept in job.error.
void run(Job& job, const Request& r, const std::atomic<bool>& cancel) {
  try {
    const rollkin::io::Scene& scene = *job.scene;
    const rollkin::Mechanism<double>& m = scene.mechanism;
    rollkin::SolveData<double> sd(m);
    rollkin::VectorX<double> q = scene.guess;
    job.assembly = rollkin::assemble(m, q, sd, scene.held);
    rollkin::ContinuationSettings<double> cfg;
    cfg.cancel = &cancel;
    job.result = rollkin::sweep(m, sd, q, job.assembly, job.sweep.driver, job.inputs, cfg);
    if (cancel) return;
    job.values = rollkin::io::sweep_values(job.sweep);
    if (r.analysis) job.analysis = rollkin::io::analyse_sweep(m, *job.result);
    job.table = rollkin::io::sweep_table(output_of(job, r), r.rates);
    if (!job.keep_result) job.result.reset();
  } catch (...) {
    job.error = std::current_exception();
  }
}

/// Solves every job on up to `threads` worker threads (0: one per core; rollkin::run_batch) with the GIL
/// released, the calling thread checking for Ctrl-C every kPollInterval. A signal handler's exception
/// (KeyboardInterrupt) cancels the workers (between poses), waits for them and propagates.
void run_all(std::vector<Job>& jobs, const Request& r, int threads) {
  if (threads < 0) throw py::value_error("threads must be >= 0 (0: one per core), got " + std::to_string(threads));
  bool interrupted = false;
  {
    py::gil_scoped_release nogil;
    rollkin::run_batch(
        jobs.size(), threads, [&](std::size_t k, const std::atomic<bool>& cancel) { run(jobs[k], r, cancel); },
        [&] {
          py::gil_scoped_acquire gil;
          interrupted = PyErr_CheckSignals() != 0;
          return interrupted;
        },
        kPollInterval);
  }
  if (interrupted) throw py::error_already_set();
}

/// Texts as a NumPy array of str (dtype <U width of the longest), its UCS-4 buffer filled here: no Python
/// string per row.
template <class Texts> py::array str_array(const Texts& texts) {
  std::size_t width = 1;
  for (const std::string& t : texts) width = std::max(width, t.size());
  py::array out = py::module_::import("numpy").attr("empty")(std::size(texts), py::arg("dtype") = "<U" + std::to_string(width));
  auto* chars = static_cast<char32_t*>(out.mutable_data());
  std::fill(chars, chars + std::size(texts) * width, U'\0');
  std::size_t row = 0;
  for (const std::string& t : texts) {
    for (std::size_t i = 0; i < t.size(); ++i) chars[row * width + i] = static_cast<unsigned char>(t[i]);
    ++row;
  }
  return out;
}

/// A solved job as a dict: column name -> float64 array, "status" -> array of str; a scene that cannot be
/// assembled also "error": the InputError message Scene.solve would raise for it.
py::dict to_dict(const Job& job) {
  const rollkin::io::SweepTable& t = job.table;
  py::dict out;
  for (std::size_t c = 0; c < t.names.size(); ++c) {
    py::array_t<double> a(static_cast<py::ssize_t>(t.rows()));
    if (t.rows()) std::memcpy(a.mutable_data(), t.columns[c].data(), t.rows() * sizeof(double));
    out[py::str(t.names[c])] = std::move(a);
  }
  out[py::str(t.status_name)] = str_array(t.status);
  if (job.assembly.status == rollkin::SolveStatus::CannotAssemble)
    out["error"] = rollkin::io::assembly_error(*job.scene, job.assembly.detail).what();
  return out;
}

/// Solves one scene on a worker thread; an assembly that fails is an InputError, as in the CLI.
Job solved(const PyScene& s, const Request& r, bool keep_result) {
  std::vector<Job> jobs{prepare(s, r)};
  jobs[0].keep_result = keep_result;
  run_all(jobs, r, 1);
  if (jobs[0].error) std::rethrow_exception(jobs[0].error);
  if (jobs[0].assembly.status == rollkin::SolveStatus::CannotAssemble)
    throw rollkin::io::assembly_error(*s.scene, jobs[0].assembly.detail);
  return std::move(jobs[0]);
}

py::dict solve(const PyScene& s, const Request& r) { return to_dict(solved(s, r, false)); }

// ---- files -----------------------------------------------------------------------------------------------

/// The files a scene read (never written over) as an OutputSet's inputs.
rollkin::io::OutputSet output_set(const PyScene& s) {
  std::vector<std::string> inputs;
  if (!s.source.empty()) inputs.push_back(s.source);
  inputs.insert(inputs.end(), s.scene->files_read.begin(), s.scene->files_read.end());
  return rollkin::io::OutputSet(std::move(inputs));
}

/// An output file requested by keyword: its label in messages, its path (None: not written) and its text.
struct FileRequest {
  const char* label;
  py::object path;
  std::function<std::string(const rollkin::io::SweepOutput&)> text;
};

/// Checks every requested path (before solving), solves, and writes every file or none.
py::dict write(const PyScene& s, const Request& r, const std::vector<FileRequest>& files) {
  rollkin::io::OutputSet outputs = output_set(s);
  std::vector<std::pair<std::size_t, const FileRequest*>> given;
  for (const FileRequest& f : files)
    if (!f.path.is_none()) given.emplace_back(outputs.add(f.label, path_text(f.path)), &f);
  const Job job = solved(s, r, true);
  const rollkin::io::SweepOutput out = output_of(job, r);
  for (const auto& [index, f] : given) outputs.set(index, f->text(out));
  outputs.commit();
  return to_dict(job);
}

// ---- centrodes and the MPFR reference ----------------------------------------------------------------------

int link_named(const rollkin::io::Scene& scene, const std::string& name) {
  const int i = scene.mechanism.find_link(name);
  if (i >= 0) return i;
  std::string names;
  for (const rollkin::Link& l : scene.mechanism.links) names += (names.empty() ? "\"" : ", \"") + l.name + "\"";
  throw py::value_error("no link \"" + name + "\" in " + scene.file + "; its links are " + names);
}

/// The instant centres of link b relative to link a over the sweep, as arrays (centrodes.hpp), optionally
/// also written as DXF splines (the CLI's `centrodes --dxf`).
py::dict centrodes(const PyScene& s, const std::string& link_a, const std::string& link_b, const Request& r,
                   const py::object& dxf) {
  const int a = link_named(*s.scene, link_a), b = link_named(*s.scene, link_b);
  if (a == b) throw py::value_error("centrodes(): give two different links, got \"" + link_a + "\" twice");
  rollkin::io::OutputSet outputs = output_set(s);
  const std::optional<std::size_t> dxf_index =
      dxf.is_none() ? std::nullopt : std::optional<std::size_t>(outputs.add("dxf", path_text(dxf)));
  const Job job = solved(s, r, true);
  const rollkin::Mechanism<double>& m = s.scene->mechanism;
  rollkin::KinematicsData<double> kin(m);
  const auto centres = rollkin::centrodes(m, kin, *job.result, a, b);
  if (dxf_index) {
    outputs.set(*dxf_index, rollkin::cli::centrode_dxf(output_of(job, r), centres, a, b));
    outputs.commit();
  }
  const py::ssize_t n = static_cast<py::ssize_t>(centres.size());
  py::array_t<double> input(n), ax(n), ay(n), bx(n), by(n), wx(n), wy(n);
  py::array_t<bool> finite(n);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (py::ssize_t k = 0; k < n; ++k) {
    const auto& c = centres[static_cast<std::size_t>(k)];
    input.mutable_at(k) = job.values[static_cast<std::size_t>(k)];
    finite.mutable_at(k) = c.finite;
    ax.mutable_at(k) = c.finite ? c.in_a.x() : nan;
    ay.mutable_at(k) = c.finite ? c.in_a.y() : nan;
    bx.mutable_at(k) = c.finite ? c.in_b.x() : nan;
    by.mutable_at(k) = c.finite ? c.in_b.y() : nan;
    wx.mutable_at(k) = c.finite ? c.world.x() : nan;
    wy.mutable_at(k) = c.finite ? c.world.y() : nan;
  }
  py::dict out;
  out[py::str(job.table.names.front())] = input;
  out["a"] = py::module_::import("numpy").attr("column_stack")(py::make_tuple(ax, ay));
  out["b"] = py::module_::import("numpy").attr("column_stack")(py::make_tuple(bx, by));
  out["world"] = py::module_::import("numpy").attr("column_stack")(py::make_tuple(wx, wy));
  out["finite"] = finite;
  out[py::str(job.table.status_name)] = to_dict(job)[py::str(job.table.status_name)];
  return out;
}

/// The sweep solved in MPFR (io::scene_reference) as float64 arrays: the columns of `rollkin reference --csv`
/// (display units), each value the decimal result correctly rounded to the nearest double.
py::dict reference(const PyScene& s, const Request& r, int digits) {
  if (digits != 30 && digits != 50 && digits != 100)
    throw py::value_error("reference(): digits must be 30, 50 or 100, got " + std::to_string(digits));
  const Job job = prepare(s, r);
  rollkin::ReferenceSweep ref;
  {
    py::gil_scoped_release nogil;
    ref = rollkin::io::scene_reference(*s.scene, job.sweep, digits);
  }
  if (ref.assembly_status == rollkin::SolveStatus::CannotAssemble)
    throw rollkin::io::assembly_error(*s.scene, ref.assembly_detail);
  const rollkin::Mechanism<double>& m = s.scene->mechanism;
  const int input = m.drivers[static_cast<std::size_t>(job.sweep.driver)];
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
  std::vector<Job> jobs;
  for (const PyScene& s : scenes) jobs.push_back(prepare(s, r));
  run_all(jobs, r, threads);
  for (const Job& j : jobs)
    if (j.error) std::rethrow_exception(j.error);
  py::list out;
  for (const Job& j : jobs) out.append(to_dict(j));
  return out;
}

Request request(std::optional<double> start, std::optional<double> stop, std::optional<double> step, bool analysis,
                bool rates, double max_steps) {
  return Request{start, stop, step, analysis, rates, max_steps};
}

py::object sweep_dict(const PyScene& s) {
  if (!s.scene->sweep) return py::none();
  const rollkin::io::Sweep& sw = *s.scene->sweep;
  py::dict d;
  d["input"] = sw.input;
  d["from"] = sw.from;
  d["to"] = sw.to;
  d["step"] = sw.step;
  return std::move(d);
}

// ---- docstrings ------------------------------------------------------------------------------------------

const char* const kModuleDoc = R"(rollkin: kinematic analysis of planar mechanisms with rolling pairs.

Scenes are the JSON files of the command-line tool (docs/scene_format.md), loaded with load_scene() or given
as a dict with scene(). Scene.solve() sweeps the input and returns the columns of
`rollkin solve SCENE --from --to --step --csv` as a dict of NumPy arrays; Scene.modified() overrides values by
JSON path; solve_many() solves a batch on worker threads with the GIL released (Ctrl-C cancels it).
Bad input raises rollkin.InputError (a ValueError) with the command-line tool's message. See docs/python.md.

    import rollkin
    sc = rollkin.load_scene("examples/paper_fourbar.json")
    t = sc.solve(-50, 100, 1)            # t["B.theta4"], t["status"], ...
    v = sc.modified({"links[1].contours[0].a": 0.6})
    ts = rollkin.solve_many([sc, v], -50, 100, 1, threads=0)
)";

const char* const kSolveDoc = R"(Sweeps the scene's input and returns its table.

start, stop, step: the sweep of the scene's input in the file's units (degrees for an angle in a "deg" scene);
each None keeps the scene's "sweep" (a scene without one needs all three).
analysis=True adds the contact analysis columns (as --analysis), rates=True the rate columns (as --rates).
max_steps bounds the work like the CLI's --max-steps (ValueError above it).

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
The MPFR run takes milliseconds per pose; it holds no GIL but cannot be interrupted before it ends.)";

}  // namespace

PYBIND11_MODULE(rollkin, m) {
  m.doc() = kModuleDoc;

  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  input_error.attr("__doc__") =
      "Bad input (a scene, a contour file, an override): a ValueError whose message names the file, the location\n"
      "(JSON path, line) and what is wrong and expected, as the command-line tool prints it. Attributes: file,\n"
      "location (e.g. the JSON path \"links[1].contours[0].a\"), message.";
  static py::exception<rollkin::io::OutputError> output_error(m, "OutputError", PyExc_OSError);
  output_error.attr("__doc__") =
      "An output file that cannot or must not be written (an OSError): a missing directory, a directory, one of\n"
      "the scene's input files. Raised before anything is solved or written; no file is changed.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const rollkin::io::OutputError& e) {
      PyErr_SetString(output_error.ptr(), e.what());
    } catch (const InputError& e) {
      py::object error = py::reinterpret_borrow<py::object>(input_error)(e.what());
      error.attr("file") = e.file();
      error.attr("location") = e.location();
      error.attr("message") = e.message();
      PyErr_SetObject(input_error.ptr(), error.ptr());
    }
  });

  py::class_<PyScene>(m, "Scene",
                      "A scene: a mechanism with its assembly pose and optional sweep, built from a JSON document.\n"
                      "Create it with load_scene(path) or scene(dict); it never changes (modified() returns a new one).\n"
                      "Scenes pickle (as their JSON document), so they can be sent to other processes (dask workers).")
      .def("solve",
           [](const PyScene& s, std::optional<double> start, std::optional<double> stop, std::optional<double> step,
              bool analysis, bool rates, double max_steps) {
             return solve(s, request(start, stop, step, analysis, rates, max_steps));
           },
           py::arg("start") = py::none(), py::arg("stop") = py::none(), py::arg("step") = py::none(), py::kw_only(),
           py::arg("analysis") = false, py::arg("rates") = false, py::arg("max_steps") = 1e7, kSolveDoc)
      .def("write",
           [](const PyScene& s, std::optional<double> start, std::optional<double> stop, std::optional<double> step,
              const py::object& csv, const py::object& plot, const py::object& draw, const py::object& animate,
              bool analysis, bool rates, double max_steps) {
             namespace cli = rollkin::cli;
             return write(s, request(start, stop, step, analysis, rates, max_steps),
                          {{"csv", csv, [rates](const rollkin::io::SweepOutput& o) { return cli::csv_text(o, rates); }},
                           {"plot", plot, &cli::plot_svg},
                           {"draw", draw, &cli::draw_svg},
                           {"animate", animate, &cli::animation_html}});
           },
           py::arg("start") = py::none(), py::arg("stop") = py::none(), py::arg("step") = py::none(), py::kw_only(),
           py::arg("csv") = py::none(), py::arg("plot") = py::none(), py::arg("draw") = py::none(),
           py::arg("animate") = py::none(), py::arg("analysis") = false, py::arg("rates") = false,
           py::arg("max_steps") = 1e7, kWriteDoc)
      .def("centrodes",
           [](const PyScene& s, const std::string& a, const std::string& b, std::optional<double> start,
              std::optional<double> stop, std::optional<double> step, const py::object& dxf, double max_steps) {
             return centrodes(s, a, b, request(start, stop, step, false, false, max_steps), dxf);
           },
           py::arg("link_a"), py::arg("link_b"), py::arg("start") = py::none(), py::arg("stop") = py::none(),
           py::arg("step") = py::none(), py::kw_only(), py::arg("dxf") = py::none(), py::arg("max_steps") = 1e7,
           kCentrodesDoc)
      .def("reference",
           [](const PyScene& s, std::optional<double> start, std::optional<double> stop, std::optional<double> step,
              int digits, double max_steps) {
             return reference(s, request(start, stop, step, false, false, max_steps), digits);
           },
           py::arg("start") = py::none(), py::arg("stop") = py::none(), py::arg("step") = py::none(), py::kw_only(),
           py::arg("digits") = 50, py::arg("max_steps") = 1e7, kReferenceDoc)
      .def("modified", &modified, py::arg("overrides"),
           "A new scene with each value of `overrides` ({JSON path: value}, e.g. {\"links[1].contours[0].a\": 0.6})\n"
           "set in a copy of this scene's document, then checked like a scene file: a path that does not exist or a\n"
           "bad value raises InputError naming the path. Messages name the file as \"<file> (modified)\"; relative\n"
           "contour files are still found next to the original file.")
      .def("document", [](const PyScene& s) { return to_python(*s.document); },
           "The scene's JSON document as Python objects (dicts, lists, numbers, strings): edit it and pass it to\n"
           "rollkin.scene() for changes beyond modified().")
      .def_property_readonly("file", [](const PyScene& s) { return s.file; }, "The source named in messages.")
      .def_property_readonly("inputs", [](const PyScene& s) { return s.scene->inputs; },
                             "The full names of the inputs (drivers), e.g. [\"O_A.theta2\"].")
      .def_property_readonly("sweep", &sweep_dict,
                             "The scene's own sweep as {\"input\", \"from\", \"to\", \"step\"} (file units), or None.")
      .def(py::pickle(&scene_state, &scene_from_state))
      .def("__repr__", [](const PyScene& s) { return "<rollkin.Scene " + s.file + ">"; });

  m.def("load_scene", &load_scene, py::arg("path"),
        "Reads a scene file (JSON, docs/scene_format.md) and checks it. Raises InputError with the command-line\n"
        "tool's message (file, JSON path, what is wrong and expected).");
  m.def("scene", &scene_from_dict, py::arg("document"), py::arg("base_dir") = py::none(), py::arg("name") = "<dict>",
        "A scene from its JSON document given as a dict (the content of a scene file). Relative contour files are\n"
        "resolved against base_dir (default: the current directory); `name` names the scene in messages.\n"
        "Raises InputError naming the JSON path of a bad value (NaN and infinities are not JSON numbers).");
  m.def("samples", &samples, py::arg("xy"), py::arg("name") = "samples",
        "A sampled contour (type \"samples\", docs/scene_format.md) from an (n, 2) array of x, y rows, as the dict\n"
        "a scene's contour list takes; keyword arguments add the contour's other keys (closed, smoothing, scale,\n"
        "parameter, at, material). xy is read as contiguous float64; a non-finite value raises ValueError.\n"
        "    contour = rollkin.samples(np.c_[x, y], name=\"profile\", closed=True)");
  m.def("nurbs", &nurbs, py::arg("points"), py::arg("degree") = 3, py::arg("knots") = py::none(),
        py::arg("weights") = py::none(), py::arg("name") = "nurbs",
        "A NURBS contour (type \"nurbs\", docs/scene_format.md) from an (n, 2) array of control points, as the dict a\n"
        "scene's contour list takes. knots: n + degree + 1 non-decreasing values (default: clamped and uniform, the\n"
        "curve from the first control point to the last); weights: one positive weight per point (default: a\n"
        "polynomial B-spline). Keyword arguments add the contour's other keys (closed, parameter, at, material).\n"
        "The knots and weights are checked when the scene is built (InputError at their JSON path).\n"
        "    cam = rollkin.nurbs(np.c_[x, y], degree=3, name=\"cam\")");
  m.def("solve_many",
        [](const std::vector<PyScene>& scenes, std::optional<double> start, std::optional<double> stop,
           std::optional<double> step, int threads, bool analysis, bool rates, double max_steps) {
          return solve_many(scenes, request(start, stop, step, analysis, rates, max_steps), threads);
        },
        py::arg("scenes"), py::arg("start") = py::none(), py::arg("stop") = py::none(), py::arg("step") = py::none(),
        py::arg("threads") = 0, py::kw_only(), py::arg("analysis") = false, py::arg("rates") = false,
        py::arg("max_steps") = 1e7, kSolveManyDoc);
  m.def("_sweep_seconds",
        [](const PyScene& s, std::optional<double> start, std::optional<double> stop, std::optional<double> step) {
          // Benchmark hook (bench/python_bench.py): wall time of the bare C++ loop, assembly and sweep, with no
          // table and no NumPy, for the overhead of Python and dask per variant against it.
          Job job = prepare(s, request(start, stop, step, false, false, 1e7));
          py::gil_scoped_release nogil;
          const auto t0 = std::chrono::steady_clock::now();
          const rollkin::Mechanism<double>& m = job.scene->mechanism;
          rollkin::SolveData<double> sd(m);
          rollkin::VectorX<double> q = job.scene->guess;
          const auto assembly = rollkin::assemble(m, q, sd, job.scene->held);
          [[maybe_unused]] const auto result = rollkin::sweep(m, sd, q, assembly, job.sweep.driver, job.inputs);
          const std::chrono::duration<double> t = std::chrono::steady_clock::now() - t0;
          return t.count();
        },
        py::arg("scene"), py::arg("start") = py::none(), py::arg("stop") = py::none(), py::arg("step") = py::none());
  m.attr("__version__") = ROLLKIN_VERSION;
}
