// The --csv of a sweep (output/sweep_table.hpp) streamed row by row (docs/reliability.md, "Outputs at any size"): the
// same bytes as the whole table's csv(), and every number reads back (strtod) to exactly the double of the table,
// which for a length variable is the solver's own value.
#define BOOST_TEST_MODULE io_sweep_table
#include <boost/test/unit_test.hpp>

#include "paper_sweep.hpp"
#include "test_support.hpp"

#include "rollkin/io/output_set.hpp"
#include "rollkin/output/sweep_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

using namespace rollkin;

namespace {

using testing::PaperSweep;

/// The CSV of `out` as write_sweep_csv writes it with `threads` into scratch file `name`, read back.
std::string written_csv(const io::SweepOutput& out, bool rates, int threads, const std::string& name) {
  const std::filesystem::path file = testing::scratch_dir("io_sweep_table") / name;
  io::OutputSet set;
  set.set_writer(set.add("--csv", file.string()), [&](io::OutputSink& sink) { io::write_sweep_csv(out, rates, sink, threads); });
  set.commit();
  return testing::read_text(file);
}

/// Column `name` of the table (a test failure if it has none).
const std::vector<double>& column(const io::SweepTable& t, const std::string& name) {
  for (std::size_t c = 0; c < t.names.size(); ++c)
    if (t.names[c] == name) return t.columns[c];
  BOOST_FAIL("no column " << name);
  return t.columns.front();
}

}  // namespace

BOOST_AUTO_TEST_CASE(streamed_csv_reads_back_to_the_solver_values) {
  const PaperSweep paper(110, 0.25);
  const io::Scene& scene = paper.scene;
  const std::vector<double>& values = paper.values;
  const SweepResult<double>& result = paper.result;
  const io::SweepOutput out{scene, paper.sw, result, values};
  const io::SweepTable table = io::sweep_table(out, /*rates=*/true);

  const std::string text = written_csv(out, true, 1, "paper.csv");
  BOOST_TEST(text == table.csv());

  std::istringstream lines(text);
  std::string line;
  std::getline(lines, line);  // header
  const int x = 1;           // A.x, a length: the column holds the solver's value itself
  const std::vector<double>& x_values = column(table, "A.x");
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
    if (result.has_pose(r)) BOOST_TEST(x_values[r] == result.q(r)(x));
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
    const std::string text = written_csv(out, true, threads, "threads" + std::to_string(threads) + ".csv");
    BOOST_TEST(text.size() == expected.size(), "threads " << threads);
    BOOST_TEST((text == expected), "threads " << threads << ": not the bytes of the one-thread table");
  }
}

// --analysis builds each row's analysis as the row is built (nothing per pose is kept): every thread count
// gives the bytes of the one-thread table, and the columns of row r belong to pose r. Their second and third
// derivatives of B.theta4 match central differences of the table's own B.theta4 column (degrees per degree^n)
// on the 0.015-degree grid, away from the dead point: they agree to 9e-8 and 2e-7 (truncation and round-off
// of the differences; |d2| reaches 0.066), where one row off misses by 2e-4 and 7e-5.
BOOST_AUTO_TEST_CASE(analysis_columns_are_built_per_row_and_match_differences_of_the_poses) {
  const PaperSweep paper(130, 0.015);
  io::SweepOutput out{paper.scene, paper.sw, paper.result, paper.values};
  out.analysis = true;
  const io::SweepTable table = io::sweep_table(out, /*rates=*/false);
  const std::string expected = table.csv();
  for (int threads : {1, 2, 0}) {
    const std::string text = written_csv(out, false, threads, "analysis" + std::to_string(threads) + ".csv");
    BOOST_TEST((text == expected), "threads " << threads << ": not the bytes of the table");
  }

  const double h = paper.sw.step;
  const std::vector<double>& theta4 = column(table, "B.theta4");
  const std::vector<double>& d2 = column(table, "d2(B.theta4)/d(O_A.theta2)2");
  const std::vector<double>& d3 = column(table, "d3(B.theta4)/d(O_A.theta2)3");
  double worst2 = 0, worst3 = 0;
  std::size_t compared = 0;
  for (std::size_t r = 2; r + 2 < paper.values.size() && paper.values[r] <= 90; ++r) {
    const double fd2 = (theta4[r + 1] - 2 * theta4[r] + theta4[r - 1]) / (h * h);
    const double fd3 = (theta4[r + 2] - 2 * theta4[r + 1] + 2 * theta4[r - 1] - theta4[r - 2]) / (2 * h * h * h);
    worst2 = std::max(worst2, std::abs(fd2 - d2[r]));
    worst3 = std::max(worst3, std::abs(fd3 - d3[r]));
    ++compared;
  }
  BOOST_TEST(compared > 9000u);
  BOOST_TEST(worst2 < 1e-6);
  BOOST_TEST(worst3 < 2e-6);
  BOOST_TEST_MESSAGE("largest differences: d2 " << worst2 << ", d3 " << worst3);
}
