#define BOOST_TEST_MODULE io_point_file
#include <boost/test/unit_test.hpp>

#include "test_support.hpp"

#include "rollkin/io/point_file.hpp"

#include <filesystem>
#include <fstream>

using rollkin::InputError;
using rollkin::parse_point_text;
using rollkin::read_point_file;

namespace {

using namespace rollkin::testing;

std::string write_temp(const std::string& name, const std::string& text) {
  return write_text(scratch_dir("io_point_file") / name, text);
}

/// The InputError message for reading `text` from a file called `name`, or "" if it reads fine.
std::string error_for(const std::string& name, const std::string& text, std::size_t min_points = 2) {
  return input_error_of([&] { read_point_file(write_temp(name, text), min_points); });
}

}  // namespace

BOOST_AUTO_TEST_CASE(reads_all_separators_comments_and_header) {
  const std::string text =
      "# cam profile, mm\n"
      "\n"
      "x y\n"
      "0 0\n"
      "1.5,2   # trailing comment\n"
      "-.5;\t3e-1\n"
      "  +2 ,  -4 \r\n"
      "1e3\t1E-3\n";
  const auto pts = read_point_file(write_temp("good.txt", text), 2);
  BOOST_TEST(pts.size() == 5u);
  BOOST_TEST(pts[1].x() == 1.5);
  BOOST_TEST(pts[1].y() == 2.0);
  BOOST_TEST(pts[2].x() == -0.5);
  BOOST_TEST(pts[2].y() == 0.3);
  BOOST_TEST(pts[3].x() == 2.0);
  BOOST_TEST(pts[3].y() == -4.0);
  BOOST_TEST(pts[4].x() == 1000.0);
  BOOST_TEST(pts[4].y() == 0.001);
}

BOOST_AUTO_TEST_CASE(scale_factor_applies_to_both_coordinates) {
  const auto pts = parse_point_text("10 20\n30 -40\n", "mm.txt", 2, 0.001);
  BOOST_TEST(pts[0].x() == 0.01);
  BOOST_TEST(pts[1].y() == -0.04);
  BOOST_CHECK_THROW(parse_point_text("1 2\n3 4\n", "x", 2, 0.0), InputError);
}

BOOST_AUTO_TEST_CASE(errors_name_file_line_and_expectation) {
  const std::string text_error = error_for("cam.txt", "# header comment\n0 0\n1 1\n1.5 abc\n");
  BOOST_TEST(contains(text_error, "cam.txt:4: expected two numbers \"x y\", got \"1.5 abc\""));
  BOOST_TEST(contains(error_for("third.txt", "0 0\n1 2 3\n"), "third.txt:2:"));
  BOOST_TEST(contains(error_for("third.txt", "0 0\n1 2 3\n"), "third column"));
  BOOST_TEST(contains(error_for("one.txt", "0 0\n7\n"), "one.txt:2:"));
  BOOST_TEST(contains(error_for("one.txt", "0 0\n7\n"), "only one number"));
  BOOST_TEST(contains(error_for("nan.txt", "0 0\n1 nan\n2 2\n"), "nan.txt:2:"));
  BOOST_TEST(contains(error_for("nan.txt", "0 0\n1 nan\n2 2\n"), "not a finite number"));
  BOOST_TEST(contains(error_for("inf.txt", "0 0\n-inf 1\n"), "inf.txt:2:"));
  BOOST_TEST(contains(error_for("empty.txt", ""), "empty.txt: no points"));
  BOOST_TEST(contains(error_for("comments.txt", "# only\n\n# comments\n"), "comments.txt: no points"));
  BOOST_TEST(contains(error_for("single.txt", "x y\n3 4\n"), "single.txt:2: only 1 point in the file, at least 2 needed"));
  BOOST_TEST(contains(error_for("few.txt", "0 0\n1 1\n2 0\n", 4), "only 3 points in the file, at least 4 needed"));
  // A second non-numeric line is not a header.
  BOOST_TEST(contains(error_for("header2.txt", "x y\nu v\n0 0\n"), "header2.txt:2: expected two numbers"));
  BOOST_TEST(contains(error_for("comma.txt", "0 0\n1,2x\n"), "comma.txt:2:"));
}

BOOST_AUTO_TEST_CASE(missing_file_is_an_input_error) {
  try {
    read_point_file("/nonexistent/dir/shape.txt", 2);
    BOOST_FAIL("no exception");
  } catch (const InputError& e) {
    BOOST_TEST(e.file() == "/nonexistent/dir/shape.txt");
    BOOST_TEST(contains(e.what(), "/nonexistent/dir/shape.txt: cannot open the point file"));
  }
}
