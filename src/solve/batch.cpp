#include "rollkin/solve/batch.hpp"

#include <algorithm>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

namespace rollkin {

std::size_t batch_workers(std::size_t n, int threads) {
  if (threads < 0) throw std::invalid_argument("threads must be >= 0 (0: one per core), got " + std::to_string(threads));
  const std::size_t wanted = threads > 0 ? static_cast<std::size_t>(threads) : std::max(1u, std::thread::hardware_concurrency());
  return std::min(wanted, n);
}

BatchOutcome run_batch(std::size_t n, int threads, const BatchTask& task, const std::function<bool()>& poll,
                       std::chrono::milliseconds interval) {
  BatchOutcome out;
  out.errors.resize(n);
  out.ran.assign(n, 0);
  const std::size_t workers = batch_workers(n, threads);
  if (workers == 0) return out;
  std::atomic<bool> cancel{false};
  std::atomic<std::size_t> next{0};
  std::mutex mutex;
  std::condition_variable done;
  std::size_t finished = 0;  // workers that have returned (under mutex)
  auto work = [&] {
    for (std::size_t k; !cancel && (k = next++) < n;) {
      out.ran[k] = 1;  // each k is written by one worker only, and read after the joins
      try {
        task(k, cancel);
      } catch (...) {
        out.errors[k] = std::current_exception();
      }
    }
    const std::lock_guard<std::mutex> lock(mutex);
    ++finished;
    done.notify_all();
  };
  std::vector<std::thread> pool;
  try {
    for (std::size_t i = 0; i < workers; ++i) pool.emplace_back(work);
  } catch (...) {  // a thread could not be started: go on with those that were, or report
    if (pool.empty()) throw;
  }
  std::exception_ptr poll_error;
  {
    std::unique_lock<std::mutex> lock(mutex);
    while (!done.wait_for(lock, interval, [&] { return finished == pool.size(); })) {
      if (!poll || out.cancelled) continue;
      lock.unlock();
      bool stop = true;
      try {
        stop = poll();
      } catch (...) {
        poll_error = std::current_exception();
      }
      lock.lock();
      if (stop) {
        out.cancelled = true;
        cancel = true;
      }
    }
  }
  for (std::thread& t : pool) t.join();
  if (poll_error) std::rethrow_exception(poll_error);
  return out;
}

}  // namespace rollkin
