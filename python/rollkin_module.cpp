// The Python module `rollkin` (pybind11): scenes loaded from files or built as dicts, overridden by JSON path,
// solved over a sweep into NumPy columns (the same columns and values as `rollkin solve --csv`, both built by
// io::sweep_table), and batches of scenes solved on worker threads with the GIL released. API: docs/python.md.
//
// The module is built in parts: Python values <-> JSON (convert.cpp), scenes (scene_bindings.cpp), solving,
// files and the MPFR reference (solve_bindings.cpp); this file defines the module, its exceptions and the
// Scene class and lets each part add its functions and methods.
#include "bindings.hpp"

#include "rollkin/io/input_error.hpp"
#include "rollkin/io/output_set.hpp"

#include <exception>

using rollkin::io::InputError;
using rollkin::python::PyScene;

namespace {

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
    } catch (const rollkin::io::OutputError& e) {  // messages name files as the file system gave them: text_of
      PyErr_SetObject(output_error.ptr(), rollkin::python::text_of(e.what()).ptr());
    } catch (const InputError& e) {
      using rollkin::python::text_of;
      py::object error = py::reinterpret_borrow<py::object>(input_error)(text_of(e.what()));
      error.attr("file") = text_of(e.file());
      error.attr("location") = text_of(e.location());
      error.attr("message") = text_of(e.message());
      PyErr_SetObject(input_error.ptr(), error.ptr());
    }
  });

  py::class_<PyScene> scene(m, "Scene",
                            "A scene: a mechanism with its assembly pose and optional sweep, built from a JSON document.\n"
                            "Create it with load_scene(path) or scene(dict); it never changes (modified() returns a new one).\n"
                            "Scenes pickle (as their JSON document), so they can be sent to other processes (dask workers).");
  rollkin::python::bind_scenes(m, scene);
  rollkin::python::bind_solving(m, scene);
  rollkin::python::bind_synthesis(m);
  m.attr("__version__") = ROLLKIN_VERSION;
}
