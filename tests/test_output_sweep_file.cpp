// A sweep kept in a temporary file (output/sweep_file.hpp) reads back exactly as the same sweep kept in memory:
// every row's values, rates and report, whichever side of the assembly input and window of the file it was
// written in, and the same --csv bytes; a directory without room or not there is refused up front, naming it.
#define BOOST_TEST_MODULE io_sweep_file
#include <boost/test/unit_test.hpp>

#include "paper_sweep.hpp"
#include "test_support.hpp"

#include "rollkin/io/output_set.hpp"
#include "rollkin/output/sweep_file.hpp"
#include "rollkin/output/sweep_table.hpp"

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

using namespace rollkin;
using testing::PaperSweep;

namespace {

/// The CSV of `out` (with rates and the analysis) as write_sweep_csv writes it with `threads`.
std::string csv_of(const io::SweepOutput& out, int threads, const std::string& name) {
  const std::filesystem::path file = testing::scratch_dir("io_sweep_file") / name;
  io::OutputSet set;
  set.set_writer(set.add("--csv", file.string()), [&](io::OutputSink& sink) { io::write_sweep_csv(out, true, sink, threads); });
  set.commit();
  return testing::read_text(file);
}

void same_report(const SolveReport<double>& a, const SolveReport<double>& b, std::size_t row) {
  BOOST_TEST_CONTEXT("row " << row) {
    BOOST_TEST(to_string(a.status) == to_string(b.status));
    BOOST_TEST(a.iterations == b.iterations);
    BOOST_TEST(a.evaluations == b.evaluations);
    BOOST_TEST(a.rank == b.rank);
    BOOST_TEST(a.residual == b.residual);
    BOOST_TEST(a.condition == b.condition);
    BOOST_TEST(a.limit_input == b.limit_input);
    BOOST_TEST(a.detail == b.detail);
    BOOST_TEST(a.pair == b.pair);
    BOOST_TEST(a.equations == b.equations);
  }
}

}  // namespace

// 16,001 rows: the assembly input (0 deg) splits them into an upward side written over three windows of the
// file and a downward side of 5,000 written backwards over two, then a limit and rows not reached.
BOOST_AUTO_TEST_CASE(rows_read_back_as_the_sweep_in_memory) {
  const PaperSweep paper(110, 0.01);
  io::SweepFile file(paper.assembly(), paper.inputs, paper.scene.mechanism.variable_count());
  paper.sweep_again(file);
  file.finish();
  const SweepResult<double>& mem = paper.result;
  BOOST_TEST_REQUIRE(file.size() == mem.size());
  BOOST_TEST(file.limits.size() == mem.limits.size());
  BOOST_TEST(file.solved() == summarise(mem).solved());
  BOOST_TEST(file.max_residual == summarise(mem).max_residual);
  std::size_t compared = 0, not_reached = 0;
  for (const std::size_t block : {std::size_t(1), std::size_t(700), std::size_t(5000)}) {
    SweepResult<double> rows;
    for (std::size_t first = 0; first < mem.size(); first += block) {
      file.read(first, block, rows);
      for (std::size_t j = 0; j < rows.size(); ++j) {
        const std::size_t r = first + j;
        BOOST_TEST_REQUIRE(rows.input(j) == mem.input(r));
        BOOST_TEST_REQUIRE((rows.q(j) == mem.q(r)));       // bit for bit: the same doubles
        BOOST_TEST_REQUIRE((rows.qdot(j) == mem.qdot(r)));
        same_report(rows.report(j), mem.report(r), r);
        not_reached += mem.status(r) == SolveStatus::NotReached;
        ++compared;
      }
    }
  }
  BOOST_TEST(compared == 3 * mem.size());
  BOOST_TEST(not_reached > 0u);
}

BOOST_AUTO_TEST_CASE(csv_from_the_file_is_the_csv_from_memory) {
  const PaperSweep paper(110, 0.02);
  io::SweepFile file(paper.assembly(), paper.inputs, paper.scene.mechanism.variable_count());
  paper.sweep_again(file);
  file.finish();
  io::SweepOutput in_memory{paper.scene, paper.sw, paper.result, paper.values};
  io::SweepOutput in_file{paper.scene, paper.sw, file, paper.values};
  in_memory.analysis = in_file.analysis = true;
  const std::string expected = csv_of(in_memory, 1, "memory.csv");
  BOOST_TEST(expected.size() > 1000000u);
  BOOST_TEST(csv_of(in_file, 1, "file1.csv") == expected);
  BOOST_TEST(csv_of(in_file, 2, "file2.csv") == expected);
}

BOOST_AUTO_TEST_CASE(a_failed_assembly_leaves_every_row_without_values) {
  const PaperSweep paper(110, 1);
  SolveReport<double> failed = paper.assembly();
  failed.status = SolveStatus::NoConvergence;
  io::SweepFile file(failed, paper.inputs, paper.scene.mechanism.variable_count());
  file.finish();
  SweepResult<double> rows;
  file.read(0, file.size(), rows);
  BOOST_TEST_REQUIRE(rows.size() == paper.inputs.size());
  for (std::size_t r = 0; r < rows.size(); ++r) {
    BOOST_TEST(rows.status(r) == SolveStatus::NoConvergence);
    BOOST_TEST(rows.q(r).isZero(0.0));
  }
}

BOOST_AUTO_TEST_CASE(a_temporary_directory_that_is_not_there_is_named) {
  const PaperSweep paper(110, 1);
  const char* old = std::getenv("TMPDIR");
  const std::string saved = old ? old : "";
  ::setenv("TMPDIR", "/nonexistent/rollkin-tmp", 1);
  std::string message;
  try {
    io::SweepFile file(paper.assembly(), paper.inputs, paper.scene.mechanism.variable_count());
  } catch (const std::runtime_error& e) {
    message = e.what();
  }
  if (old) ::setenv("TMPDIR", saved.c_str(), 1);
  else ::unsetenv("TMPDIR");
  BOOST_TEST(message.find("/nonexistent/rollkin-tmp") != std::string::npos);
  BOOST_TEST(message.find("TMPDIR") != std::string::npos);
}
