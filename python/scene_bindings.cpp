// Scenes in the Python module: loaded from a file or built from a dict, pickled as their JSON document,
// modified by JSON path, the contour dicts samples() and nurbs() build from NumPy arrays, and the listing of a
// drawing's contours (contours(), as `rollkin contours --json`).
#include "bindings.hpp"

#include "rollkin/io/contour_formats.hpp"
#include "rollkin/io/contour_listing.hpp"
#include "rollkin/io/json/document.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <utility>
#include <vector>

namespace rollkin::python {
namespace {

/// Builds a scene from the document `read` returns, on a worker thread that Ctrl-C interrupts (interruptible:
/// reading a file and building a scene can take long). `dir` is made absolute ("" is the working directory),
/// so that a scene sent to another process (pickle, e.g. to dask workers) finds its contour files wherever
/// that process runs; `source`, the file the document was read from or that name= names, is never written over
/// (Scene.write, centrodes(dxf=)).
PyScene build(std::function<json()> read, const std::string& file, const std::string& dir, const std::string& source = {}) {
  return interruptible<PyScene>([read = std::move(read), file, dir, source](const std::atomic<bool>&) {
    const std::string where = (dir.empty() ? std::filesystem::current_path() : std::filesystem::absolute(dir)).string();
    json document = read();
    auto scene = std::make_shared<const rollkin::io::Scene>(rollkin::io::build_scene(document, file, where));
    const std::string absolute_source = source.empty() ? source : std::filesystem::absolute(source).string();
    return PyScene{std::move(scene), std::make_shared<const json>(std::move(document)), file, where, absolute_source};
  });
}

/// A document already in memory as build()'s reader (moved out once).
std::function<json()> given(json document) {
  auto held = std::make_shared<json>(std::move(document));
  return [held] { return std::move(*held); };
}

/// Pickling: the document as JSON text, the name and the directory; unpickling builds the scene again.
py::tuple scene_state(const PyScene& s) { return py::make_tuple(s.document->dump(), text_of(s.file), text_of(s.dir), text_of(s.source)); }

PyScene scene_from_state(const py::tuple& t) {
  if (t.size() != 4) throw py::value_error("rollkin.Scene: a pickled state is (document, file, dir, source)");
  const std::string file = path_argument(t[1], "file"), dir = path_argument(t[2], "dir");
  const std::string source = py::len(t[3]) == 0 ? std::string() : path_argument(t[3], "source");
  return build(given(rollkin::io::parse_json_document(t[0].cast<std::string>(), file)), file, dir, source);
}

PyScene load_scene(const py::object& path) {
  const std::string file = path_argument(path, "path");
  return build([file] { return rollkin::io::read_scene_document(file); }, file,
               std::filesystem::path(file).parent_path().string(), file);
}

/// A scene from a dict. `name`, when given, names the scene in messages and is protected as its file: a dict
/// made from a scene file's document (sc.document()) is never written over through it.
PyScene scene_from_dict(const py::dict& document, const py::object& base_dir, const py::object& name) {
  const std::string dir = base_dir.is_none() ? std::string() : path_argument(base_dir, "base_dir");
  const std::string file = name.is_none() ? std::string("<dict>") : path_argument(name, "name");
  return build(given(to_json(document, "", file)), file, dir, name.is_none() ? std::string() : file);
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
    const std::string path = json_text(item.first, "", file);
    rollkin::io::set_at_path(document, path, to_json(item.second, path, file), file);
  }
  return build(given(std::move(document)), file, s.dir, s.source);
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

py::object sweep_dict(const PyScene& s) {
  if (!s.scene->sweep) return py::none();
  const rollkin::Sweep& sw = *s.scene->sweep;
  py::dict d;
  d["input"] = sw.input;
  d["from"] = sw.from;
  d["to"] = sw.to;
  d["step"] = sw.step;
  return std::move(d);
}

/// The chains of a contour file (io/contour_formats.hpp) as dicts with the fields of `rollkin contours --json`
/// (io::contours_json): None for what an unreadable entity lacks, "no_selector", "hidden" and "unreadable".
py::list contours(const py::object& path) {
  const std::string file = path_argument(path, "path");
  const std::vector<rollkin::io::ListedChain> chains = interruptible<std::vector<rollkin::io::ListedChain>>(
      [file](const std::atomic<bool>&) { return rollkin::io::list_contours(file); });
  py::list out;
  for (const rollkin::io::ListedChain& c : chains) {
    py::dict d;
    d["group"] = text_of(c.group);
    py::list entities;
    for (const std::string& e : c.entities) entities.append(text_of(e));
    d["entities"] = entities;
    const bool chain = c.unreadable.empty();
    d["closed"] = chain ? py::object(py::bool_(c.closed)) : py::none();
    d["length"] = chain ? py::object(py::float_(c.length)) : py::none();
    d["min"] = chain ? py::object(py::make_tuple(c.min.x(), c.min.y())) : py::none();
    d["max"] = chain ? py::object(py::make_tuple(c.max.x(), c.max.y())) : py::none();
    d["corners"] = chain ? py::object(py::int_(c.corners)) : py::none();
    d["selector"] = c.selector.empty() ? py::none() : to_python(json::parse(c.selector));
    if (c.selector.empty()) d["no_selector"] = text_of(c.no_selector);
    if (!c.hidden.empty()) d["hidden"] = text_of(c.hidden);
    if (!chain) d["unreadable"] = text_of(c.unreadable);
    out.append(d);
  }
  return out;
}

/// contours()'s docstring, its formats from the table of contour file formats (io/contour_formats.hpp).
const char* contours_doc() {
  static const std::string doc =
      "What a drawing or point file offers as contours, as `rollkin contours FILE --json` lists it: one dict per\n"
      "chain with group (DXF layer, SVG element, file), entities, closed, length, min and max (bounding box\n"
      "corners), corners (tangent discontinuities) and selector (the contour dict that selects exactly this chain:\n"
      "add a \"name\" and put it in a scene's contours). The file's units; SVG: viewport units with y up.\n"
      "The formats, by extension (case ignored):\n" +
      rollkin::io::contour_file_formats_help() + "Raises InputError for a file that cannot be read or ends in none of " +
      rollkin::io::contour_file_extensions() + ".\n    for c in rollkin.contours(\"plate.svg\"): print(c[\"length\"], c[\"selector\"])";
  return doc.c_str();
}

}  // namespace

void bind_scenes(py::module_& m, py::class_<PyScene>& scene) {
  scene
      .def("modified", &modified, py::arg("overrides"),
           "A new scene with each value of `overrides` ({JSON path: value}, e.g. {\"links[1].contours[0].a\": 0.6})\n"
           "set in a copy of this scene's document, then checked like a scene file: a path that does not exist or a\n"
           "bad value raises InputError naming the path. Messages name the file as \"<file> (modified)\"; relative\n"
           "contour files are still found next to the original file.")
      .def("document", [](const PyScene& s) { return to_python(*s.document); },
           "The scene's JSON document as Python objects (dicts, lists, numbers, strings): edit it and pass it to\n"
           "rollkin.scene() for changes beyond modified().")
      .def_property_readonly("file", [](const PyScene& s) { return text_of(s.file); }, "The source named in messages.")
      .def_property_readonly("inputs", [](const PyScene& s) { return s.scene->inputs; },
                             "The full names of the inputs (drivers), e.g. [\"O_A.theta2\"].")
      .def_property_readonly("sweep", &sweep_dict,
                             "The scene's own sweep as {\"input\", \"from\", \"to\", \"step\"} (file units), or None.")
      .def(py::pickle(&scene_state, &scene_from_state))
      .def("__repr__", [](const PyScene& s) { return text_of("<rollkin.Scene " + s.file + ">"); });

  m.def("load_scene", &load_scene, py::arg("path"),
        "Reads a scene file (JSON, docs/scene_format.md) and checks it. Raises InputError with the command-line\n"
        "tool's message (file, JSON path, what is wrong and expected). path: str, bytes or os.PathLike. Ctrl-C\n"
        "interrupts it (KeyboardInterrupt).");
  m.def("scene", &scene_from_dict, py::arg("document"), py::arg("base_dir") = py::none(), py::arg("name") = py::none(),
        "A scene from its JSON document given as a dict (the content of a scene file). Relative contour files are\n"
        "resolved against base_dir (default: the current directory); `name` names the scene in messages (default\n"
        "\"<dict>\") and, as the scene's file, is never written over by write() or centrodes(dxf=).\n"
        "Raises InputError naming the JSON path of a bad value (NaN and infinities are not JSON numbers).");
  m.def("contours", &contours, py::arg("path"), contours_doc());
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
}

}  // namespace rollkin::python
