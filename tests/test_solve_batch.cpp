// rollkin::run_batch (solve/batch.hpp): input order, errors kept per task, cancellation by the poll.
#define BOOST_TEST_MODULE solve_batch
#include <boost/test/unit_test.hpp>

#include "rollkin/solve/batch.hpp"

#include <set>
#include <stdexcept>
#include <string>
#include <thread>

using namespace rollkin;
using namespace std::chrono_literals;

BOOST_AUTO_TEST_CASE(every_task_writes_its_own_slot_in_input_order) {
  for (int threads : {0, 1, 2, 3, 64}) {
    std::vector<std::size_t> squares(1000, 0);
    std::vector<std::thread::id> who(1000);
    const BatchOutcome out = run_batch(squares.size(), threads, [&](std::size_t k, const std::atomic<bool>&) {
      squares[k] = k * k;
      who[k] = std::this_thread::get_id();
    });
    BOOST_TEST(!out.cancelled);
    for (std::size_t k = 0; k < squares.size(); ++k) {
      BOOST_TEST(squares[k] == k * k);
      BOOST_TEST(out.ran[k] == 1);
      BOOST_TEST(!out.errors[k]);
    }
    const std::set<std::thread::id> workers(who.begin(), who.end());
    BOOST_TEST(workers.size() <= batch_workers(squares.size(), threads));
    BOOST_TEST(workers.count(std::this_thread::get_id()) == 0u);  // the caller only waits
  }
  BOOST_TEST(batch_workers(3, 64) == 3u);
  BOOST_TEST(batch_workers(0, 0) == 0u);
  BOOST_TEST(run_batch(0, 0, [](std::size_t, const std::atomic<bool>&) { throw std::logic_error("never"); }).errors.empty());
}

BOOST_AUTO_TEST_CASE(a_task_that_throws_does_not_stop_the_others) {
  std::vector<int> done(50, 0);
  const BatchOutcome out = run_batch(done.size(), 3, [&](std::size_t k, const std::atomic<bool>&) {
    if (k % 7 == 3) throw std::runtime_error("task " + std::to_string(k));
    done[k] = 1;
  });
  for (std::size_t k = 0; k < done.size(); ++k) {
    BOOST_TEST(done[k] == (k % 7 == 3 ? 0 : 1));
    BOOST_TEST(static_cast<bool>(out.errors[k]) == (k % 7 == 3));
    if (out.errors[k]) BOOST_CHECK_EXCEPTION(std::rethrow_exception(out.errors[k]), std::runtime_error,
                                             [&](const std::runtime_error& e) { return e.what() == "task " + std::to_string(k); });
  }
}

BOOST_AUTO_TEST_CASE(the_poll_cancels_running_tasks_and_no_new_one_starts) {
  // Each task runs until cancelled; the poll says stop once both workers are in a task.
  std::atomic<int> started{0}, saw_cancel{0};
  int polls = 0;
  const BatchOutcome out = run_batch(
      100, 2,
      [&](std::size_t, const std::atomic<bool>& cancel) {
        ++started;
        while (!cancel) std::this_thread::sleep_for(1ms);
        ++saw_cancel;
      },
      [&] {
        ++polls;
        return started == 2;
      },
      5ms);
  BOOST_TEST(out.cancelled);
  BOOST_TEST(polls >= 1);
  int ran = 0;
  for (char r : out.ran) ran += r;
  BOOST_TEST(ran == 2);  // the two that were running when the poll said stop
  BOOST_TEST(saw_cancel == 2);
}

BOOST_AUTO_TEST_CASE(a_throwing_poll_cancels_waits_and_rethrows) {
  std::atomic<int> running{0};
  BOOST_CHECK_THROW(run_batch(
                        10, 2,
                        [&](std::size_t, const std::atomic<bool>& cancel) {
                          ++running;
                          while (!cancel) std::this_thread::sleep_for(1ms);
                          --running;
                        },
                        []() -> bool { throw std::runtime_error("interrupted"); }, 2ms),
                    std::runtime_error);
  BOOST_TEST(running == 0);  // every worker had ended before the exception left run_batch
  BOOST_CHECK_THROW(run_batch(1, -1, [](std::size_t, const std::atomic<bool>&) {}), std::invalid_argument);
}
