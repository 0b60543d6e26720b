// Independent tasks on worker threads: the batch call behind Python's solve_many and the CLI's --jobs.
//
//   std::vector<SweepResult<double>> results(scenes.size());
//   const BatchOutcome done = run_batch(scenes.size(), 0, [&](std::size_t k, const std::atomic<bool>& cancel) {
//     results[k] = ...;   // task k writes only its own slot: results come back in input order
//   });
//
// Tasks are taken in input order by up to `threads` workers (0: one per core, never more than the tasks). A
// task that throws keeps its exception in errors[k] and the others go on. The calling thread waits and
// calls `poll` about every `interval`: when it returns true the batch is cancelled (the flag passed to the
// tasks is raised, e.g. for ContinuationSettings::cancel, and no further task starts); run_batch returns
// once every started task has ended.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <exception>
#include <functional>
#include <vector>

namespace rollkin {

struct BatchOutcome {
  std::vector<std::exception_ptr> errors;  // one per task: null, or what the task threw
  std::vector<char> ran;                   // one per task: 0 when cancelled before it started
  bool cancelled = false;
};

using BatchTask = std::function<void(std::size_t, const std::atomic<bool>& cancel)>;

/// Runs task(k, cancel) for k = 0 .. n - 1 as described above. Throws std::invalid_argument for threads < 0,
/// std::system_error when no worker thread can be started, and what `poll` throws (after cancelling the
/// batch and waiting for its workers).
BatchOutcome run_batch(std::size_t n, int threads, const BatchTask& task, const std::function<bool()>& poll = {},
                       std::chrono::milliseconds interval = std::chrono::milliseconds(50));

/// The number of workers run_batch starts for n tasks and `threads` (0: one per core).
std::size_t batch_workers(std::size_t n, int threads);

}  // namespace rollkin
