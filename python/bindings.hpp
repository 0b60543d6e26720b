// What the parts of the Python module `rollkin` share: the Scene class (PyScene) and the functions that bind
// scenes (python/scene_bindings.cpp: loading, building, overriding, contours) and solving (python/
// solve_bindings.cpp: solve, write, centrodes, reference, solve_many) into the module (python/rollkin_module.cpp).
#pragma once
#include "convert.hpp"

#include "rollkin/io/scene/reader.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

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

/// How often a call waiting for its worker checks for Ctrl-C, and how long after a Ctrl-C it waits for work
/// that stops at the cancellation flag (a sweep stops between poses) before it returns without it.
constexpr std::chrono::milliseconds kPollInterval{50}, kCancelGrace{500};

/// Ctrl-C for every long call of the module (reading and building a scene, assembling, sweeping, the MPFR
/// reference; docs/python.md): `work` runs on a worker thread with the GIL released while the calling thread
/// runs Python's signal handlers every kPollInterval. When one raises (KeyboardInterrupt), `cancel` is set
/// (sweep() stops between poses), the call waits up to kCancelGrace for the work to end and then propagates
/// the exception; work that does not look at `cancel` (a file being read, an assembly) goes on to its end on
/// its worker and its result is dropped. So `work` owns what it uses (captured by value or shared_ptr) and
/// holds no Python object. Otherwise returns its result or rethrows what it threw.
template <class R> R interruptible(std::function<R(const std::atomic<bool>& cancel)> work) {
  struct State {
    std::mutex mutex;
    std::condition_variable ended;
    bool done = false;
    std::optional<R> result;
    std::exception_ptr error;
    std::atomic<bool> cancel{false};
    std::function<R(const std::atomic<bool>&)> work;
  };
  auto state = std::make_shared<State>();
  state->work = std::move(work);
  std::thread worker([state] {
    std::optional<R> result;
    std::exception_ptr error;
    try {
      result.emplace(state->work(state->cancel));
    } catch (...) {
      error = std::current_exception();
    }
    const std::lock_guard<std::mutex> lock(state->mutex);
    state->result = std::move(result);
    state->error = error;
    state->done = true;
    state->ended.notify_all();
  });
  bool interrupted = false, finished = true;
  {
    py::gil_scoped_release nogil;
    std::unique_lock<std::mutex> lock(state->mutex);
    while (!state->ended.wait_for(lock, kPollInterval, [&] { return state->done; })) {
      lock.unlock();
      {
        py::gil_scoped_acquire gil;
        interrupted = PyErr_CheckSignals() != 0;
      }
      lock.lock();
      if (interrupted) {
        state->cancel = true;
        finished = state->ended.wait_for(lock, kCancelGrace, [&] { return state->done; });
        break;
      }
    }
  }
  if (interrupted) {
    if (finished) worker.join();
    else worker.detach();  // it ends on its own; `state` lives until then
    throw py::error_already_set();
  }
  worker.join();
  if (state->error) std::rethrow_exception(state->error);
  return std::move(*state->result);
}

/// The scene functions (load_scene, scene, samples, nurbs) and Scene's methods to read and modify it.
void bind_scenes(py::module_& m, py::class_<PyScene>& scene);

/// Solving: Scene.solve, write, centrodes, reference and the functions solve_many, _sweep_seconds.
void bind_solving(py::module_& m, py::class_<PyScene>& scene);

/// Synthesis (python/synthesis_bindings.cpp): synthesize_cam, synthesize_gears, envelope.
void bind_synthesis(py::module_& m);

}  // namespace rollkin::python
