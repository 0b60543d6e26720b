// The files of a solved sweep keyed by format (output/sweep_files.hpp): every format of the table is written
// through one request, the CSV is the table built apart (io::sweep_table), the SVG and HTML files are whole
// documents, an unknown format is named with the known ones, and a file the run reads is never a target.
#define BOOST_TEST_MODULE output_sweep_files
#include <boost/test/unit_test.hpp>

#include "paper_sweep.hpp"
#include "test_support.hpp"

#include "rollkin/io/output_set.hpp"
#include "rollkin/output/sweep_files.hpp"

#include <filesystem>
#include <stdexcept>
#include <string>

using namespace rollkin;
using testing::PaperSweep;

BOOST_AUTO_TEST_CASE(every_format_of_the_table_is_written_by_one_request) {
  const PaperSweep paper(110, 0.5);
  const std::filesystem::path dir = testing::scratch_dir("output_sweep_files");
  io::OutputSet set;
  output::SweepFiles files(set);
  for (const output::SweepFormat& f : output::sweep_formats())
    files.request(f.name, (dir / (std::string("out.") + f.name)).string(), f.name);
  const io::SweepOutput out{paper.scene, paper.sw, paper.result, paper.values};
  files.write(out, output::WriteOptions{true, 2});
  set.commit();
  BOOST_TEST(output::sweep_formats().size() == 4u);
  BOOST_TEST(testing::read_text(dir / "out.csv") == io::sweep_table(out, true).csv());
  for (const char* svg : {"out.plot", "out.draw"}) {
    const std::string text = testing::read_text(dir / svg);
    BOOST_TEST(text.find("<svg") != std::string::npos);
    BOOST_TEST(text.rfind("</svg>") != std::string::npos);
  }
  const std::string page = testing::read_text(dir / "out.animate");
  BOOST_TEST(page.find("<html") != std::string::npos);
  BOOST_TEST(page.rfind("</html>") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(an_unknown_format_is_named_with_the_known_ones) {
  io::OutputSet set;
  output::SweepFiles files(set);
  std::string message;
  try {
    files.request("pdf", "out.pdf", "--pdf");
  } catch (const std::invalid_argument& e) {
    message = e.what();
  }
  BOOST_TEST(message.find("'pdf'") != std::string::npos);
  BOOST_TEST(message.find("csv, plot, draw, animate") != std::string::npos);
  BOOST_TEST(files.empty());
}

BOOST_AUTO_TEST_CASE(a_file_the_run_reads_is_never_a_target) {
  const std::filesystem::path dir = testing::scratch_dir("output_sweep_files_inputs");
  const std::filesystem::path scene = dir / "scene.json";
  testing::write_text(scene, "{}");
  io::OutputSet set({io::InputFile{scene.string(), "the scene file"}});
  output::SweepFiles files(set);
  BOOST_CHECK_THROW(files.request("plot", scene.string(), "--plot"), io::OutputError);
  BOOST_TEST(testing::read_text(scene) == "{}");
}
