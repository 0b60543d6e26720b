// The --csv of a sweep (io/sweep_table.hpp) streamed row by row (issue 15): the same bytes as the whole
// table's csv(), and every number reads back (strtod) to exactly the double of the table, which for a length
// variable is the solver's own value.
#define BOOST_TEST_MODULE io_sweep_table
#include <boost/test/unit_test.hpp>

#include "test_support.hpp"

#include "rollkin/io/output_set.hpp"
#include "rollkin/io/sweep_table.hpp"

#include <cstdlib>
#include <filesystem>
#include <sstream>

using namespace rollkin;

namespace {

/// The paper example swept from -50 to `to` degrees by `step`, past its dead point (one limit, then
/// not_reached rows with NaN).
struct PaperSweep {
  io::Scene scene = io::load_scene(std::string(ROLLKIN_SOURCE_DIR) + "/examples/paper_fourbar.json");
  io::Sweep sw;
  std::vector<double> inputs, values;
  SweepResult<double> result;

  PaperSweep(double to, double step) : sw(*scene.sweep), result(solve(to, step)) {}

 private:
  SweepResult<double> solve(double to, double step) {
    sw.from = -50;
    sw.to = to;
    sw.step = step;
    inputs = io::sweep_inputs(sw);
    values = io::sweep_values(sw);
    SolveData<double> sd(scene.mechanism);
    VectorX<double> q = scene.guess;
    const SolveReport<double> assembly = assemble(scene.mechanism, q, sd, scene.held);
    BOOST_TEST_REQUIRE(assembly.ok());
    SweepResult<double> r = sweep(scene.mechanism, sd, q, assembly, sw.driver, inputs);
    BOOST_TEST_REQUIRE(r.limits.size() == 1u);
    BOOST_TEST_REQUIRE(!r.has_pose(inputs.size() - 1));
    return r;
  }
};

}  // namespace

BOOST_AUTO_TEST_CASE(streamed_csv_reads_back_to_the_solver_values) {
  const PaperSweep paper(110, 0.25);
  const io::Scene& scene = paper.scene;
  const std::vector<double>& values = paper.values;
  const SweepResult<double>& result = paper.result;
  const io::SweepOutput out{scene, paper.sw, result, values};
  const io::SweepTable table = io::sweep_table(out, /*rates=*/true);

  const std::filesystem::path file = testing::scratch_dir("io_sweep_table") / "paper.csv";
  io::OutputSet set;
  set.set_writer(set.add("--csv", file.string()), [&](io::OutputSink& sink) { io::write_sweep_csv(out, true, sink); });
  set.commit();
  const std::string text = testing::read_text(file);
  BOOST_TEST(text == table.csv());

  std::istringstream lines(text);
  std::string line;
  std::getline(lines, line);  // header
  const int x = 1;           // A.x, a length: the column holds the solver's value itself
  int x_column = -1;
  for (std::size_t c = 0; c < table.names.size(); ++c)
    if (table.names[c] == "A.x") x_column = static_cast<int>(c);
  BOOST_TEST_REQUIRE(x_column >= 0);
  std::size_t r = 0, checked = 0;
  for (; std::getline(lines, line); ++r) {
    std::istringstream fields(line);
    std::string f;
    for (std::size_t c = 0; c < table.names.size() && std::getline(fields, f, ','); ++c) {
      const double v = std::strtod(f.c_str(), nullptr), t = table.columns[c][r];
      BOOST_TEST((v == t || (v != v && t != t)), "row " << r << " column " << table.names[c] << ": " << f);
      ++checked;
    }
    if (result.has_pose(r)) BOOST_TEST(std::strtod(line.substr(0).c_str(), nullptr) == values[r]);
    if (result.has_pose(r)) BOOST_TEST(table.columns[static_cast<std::size_t>(x_column)][r] == result.q(r)(x));
  }
  BOOST_TEST(r == result.size());
  BOOST_TEST(checked == r * table.names.size());
}

// Several threads format the rows in blocks (write_sweep_csv's `threads`); the file must be the same bytes in
// the same row order. 12,001 rows with a limit inside: several rounds of 1024-row blocks, the last one short,
// not_reached rows among them.
BOOST_AUTO_TEST_CASE(csv_formatted_by_several_threads_is_the_same_file) {
  const PaperSweep paper(130, 0.015);
  BOOST_TEST_REQUIRE(paper.inputs.size() == 12001u);
  const io::SweepOutput out{paper.scene, paper.sw, paper.result, paper.values};
  const std::string expected = io::sweep_table(out, /*rates=*/true).csv();
  for (int threads : {2, 3, 0}) {
    const std::filesystem::path file = testing::scratch_dir("io_sweep_table") / ("threads" + std::to_string(threads) + ".csv");
    io::OutputSet set;
    set.set_writer(set.add("--csv", file.string()), [&](io::OutputSink& sink) { io::write_sweep_csv(out, true, sink, threads); });
    set.commit();
    const std::string text = testing::read_text(file);
    BOOST_TEST(text.size() == expected.size(), "threads " << threads);
    BOOST_TEST((text == expected), "threads " << threads << ": not the bytes of the one-thread table");
  }
}
