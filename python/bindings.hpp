// What the parts of the Python module `rollkin` share: the Scene class (PyScene) and the functions that bind
// scenes (python/scene_bindings.cpp: loading, building, overriding, contours) and solving (python/
// solve_bindings.cpp: solve, write, centrodes, reference, solve_many) into the module (python/rollkin_module.cpp).
#pragma once
#include "convert.hpp"

#include "rollkin/io/scene.hpp"

#include <memory>
#include <string>

namespace rollkin::python {

/// A scene as Python sees it: the built scene and the JSON document it was built from (overrides edit a copy
/// of the document and build a new scene). Immutable, so batches share it between threads.
struct PyScene {
  std::shared_ptr<const rollkin::io::Scene> scene;
  std::shared_ptr<const json> document;
  std::string file;  // names the source in messages
  std::string dir;   // relative contour files are resolved against it
  std::string source;  // the scene file the document was read from ("" for a dict): never written over
};

/// The scene functions (load_scene, scene, samples, nurbs) and Scene's methods to read and modify it.
void bind_scenes(py::module_& m, py::class_<PyScene>& scene);

/// Solving: Scene.solve, write, centrodes, reference and the functions solve_many, _sweep_seconds.
void bind_solving(py::module_& m, py::class_<PyScene>& scene);

}  // namespace rollkin::python
