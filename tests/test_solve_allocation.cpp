// Memory of a sweep (docs/benchmark.md, "The CLI path"): a sweep's results are columns sized once
// (solve/sweep_result.hpp), so the per-pose work allocates nothing. Counted with a replacement of the global operator
// new in this test executable alone: the allocations of sweeps of 10 and of 1000 requested poses (and of a sweep of
// the same range that reaches the dead point at the end of the paper example's motion) must not grow with the poses;
// nor those of a summary whose poses are interpolated between strides (dense output), nor those of writing a sweep's
// CSV (output/sweep_table.hpp).
#define BOOST_TEST_MODULE solve_allocation
#include <boost/test/unit_test.hpp>

#include "rollkin/samples/mechanisms.hpp"
#include "rollkin/solve/continuation.hpp"
#include "test_support.hpp"

#include "rollkin/io/output_set.hpp"
#include "rollkin/output/sweep_table.hpp"

#include <atomic>
#include <cstdlib>
#include <new>

namespace {

std::atomic<long> g_allocations{0};

}  // namespace

void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

using namespace rollkin;
using namespace rollkin::testing;

namespace {

/// n inputs evenly over [from, to] degrees (radians).
std::vector<double> grid(int n, double from, double to) {
  std::vector<double> v;
  for (int k = 0; k < n; ++k) v.push_back((from + (to - from) * k / (n - 1)) * pi<double>() / 180);
  return v;
}

struct Counted {
  long allocations;
  SweepResult<double> result;
};

/// The allocations made by one sweep of the paper example over `inputs` (the inputs and the fixture made
/// before counting).
Counted count_sweep(const std::vector<double>& inputs) {
  const Fixture<double> f = paper_fourbar<double>();
  SolveData<double> sd(f.mech);
  VectorX<double> q;
  const SolveReport<double> assembly = assemble_fixture(f, q, sd);
  BOOST_TEST_REQUIRE(assembly.ok());
  const long before = g_allocations.load();
  SweepResult<double> r = sweep(f.mech, sd, q, assembly, 0, inputs);
  return {g_allocations.load() - before, std::move(r)};
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_counter_counts) {
  const long before = g_allocations.load();
  auto* v = new std::vector<double>(1000);
  delete v;
  BOOST_TEST(g_allocations.load() - before == 2);  // the vector object and its storage
}

BOOST_AUTO_TEST_CASE(per_pose_work_allocates_nothing) {
  // Both sweeps cover the same range (same sub-steps of the continuation between the requested values up to
  // the finer grid), so only the number of poses stored differs.
  const Counted few = count_sweep(grid(10, -40, 90));
  const Counted many = count_sweep(grid(1000, -40, 90));
  BOOST_TEST_REQUIRE(few.result.all_solved());
  BOOST_TEST_REQUIRE(many.result.all_solved());
  BOOST_TEST_MESSAGE("allocations: 10 poses " << few.allocations << ", 1000 poses " << many.allocations);
  BOOST_TEST(many.allocations == few.allocations);
  // The values are stored: pose 999 is theta2 = 90 degrees, solved.
  BOOST_TEST(many.result.q(999)(0) == 90 * pi<double>() / 180);
}

BOOST_AUTO_TEST_CASE(interpolated_poses_allocate_nothing) {
  // sweep_summary() on grids of 0.013 and 0.0013 degrees: most poses interpolated between strides (dense
  // output, solve/continuation.hpp); only the per-pose status vector grows, allocated once either way.
  const Fixture<double> f = paper_fourbar<double>();
  long allocations[2];
  std::size_t interpolated[2];
  const int sizes[2] = {10000, 100000};
  for (int i = 0; i < 2; ++i) {
    const std::vector<double> inputs = grid(sizes[i], -40, 90);
    SolveData<double> sd(f.mech);
    VectorX<double> q;
    const SolveReport<double> assembly = assemble_fixture(f, q, sd);
    const long before = g_allocations.load();
    const SweepSummary<double> s = sweep_summary(f.mech, sd, q, assembly, 0, inputs);
    allocations[i] = g_allocations.load() - before;
    interpolated[i] = s.interpolated;
    BOOST_TEST(s.solved() == inputs.size());
  }
  BOOST_TEST_MESSAGE("summary allocations: 10^4 poses " << allocations[0] << " (" << interpolated[0]
                     << " interpolated), 10^5 poses " << allocations[1] << " (" << interpolated[1] << " interpolated)");
  BOOST_TEST(interpolated[1] > 50000u);
  BOOST_TEST(allocations[1] == allocations[0]);
}

BOOST_AUTO_TEST_CASE(poses_beyond_a_limit_share_one_report) {
  // Past the dead point (about 97.7 degrees in the paper example) every pose is not_reached with the limit's
  // detail: stored once, not once per pose.
  const Counted few = count_sweep(grid(10, 90, 120));
  const Counted many = count_sweep(grid(1000, 90, 120));
  BOOST_TEST_REQUIRE(many.result.limits.size() == 1u);
  BOOST_TEST(many.result.status(999) == SolveStatus::NotReached);
  BOOST_TEST(!many.result.report(999).detail.empty());
  BOOST_TEST_MESSAGE("allocations past a limit: 10 poses " << few.allocations << ", 1000 poses " << many.allocations);
  BOOST_TEST(many.allocations == few.allocations);
}

namespace {

/// The allocations made by writing the CSV (one thread, no analysis) of the paper example swept from -40 to
/// 90 degrees by `step`; the sweep and the output's declaration made before counting.
long count_csv(double step) {
  const io::Scene scene = io::load_scene(std::string(ROLLKIN_SOURCE_DIR) + "/examples/paper_fourbar.json");
  Sweep sw = *scene.sweep;
  sw.from = -40;
  sw.to = 90;
  sw.step = step;
  const std::vector<double> inputs = sweep_inputs(sw), values = sweep_values(sw);
  SolveData<double> sd(scene.mechanism);
  VectorX<double> q = scene.guess;
  const SolveReport<double> assembly = assemble(scene.mechanism, q, sd, scene.held);
  const SweepResult<double> result = sweep(scene.mechanism, sd, q, assembly, sw.driver, inputs);
  BOOST_TEST_REQUIRE(result.all_solved());
  const io::SweepOutput out{scene, sw, result, values};
  const std::filesystem::path file = testing::scratch_dir("solve_allocation") / "rows.csv";
  io::OutputSet set;
  set.set_writer(set.add("--csv", file.string()), [&](io::OutputSink& sink) { io::write_sweep_csv(out, false, sink, 1); });
  const long before = g_allocations.load();
  set.commit();
  const long allocations = g_allocations.load() - before;
  BOOST_TEST(std::filesystem::file_size(file) > 100 * inputs.size());  // the rows were written
  return allocations;
}

}  // namespace

BOOST_AUTO_TEST_CASE(csv_rows_allocate_nothing) {
  // 1,001 and 10,001 rows (2.4 MB: the sink's block is written out twice): the row's values, the link poses,
  // the status field and the text are built in buffers sized once.
  const long few = count_csv(0.13), many = count_csv(0.013);
  BOOST_TEST_MESSAGE("CSV allocations: 1001 rows " << few << ", 10001 rows " << many);
  BOOST_TEST(many == few);
}
