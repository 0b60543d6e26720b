#define BOOST_TEST_MODULE io_point_file
#include <boost/test/unit_test.hpp>

#include "test_support.hpp"

#include "rollkin/io/output_set.hpp"
#include "rollkin/io/point_file.hpp"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

namespace fs = std::filesystem;
using rollkin::io::InputError;
using rollkin::io::parse_point_text;
using rollkin::io::read_point_file;

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

// Spreadsheet CSV exports: a header row naming x and y, with quotes, units or other case.
BOOST_AUTO_TEST_CASE(csv_with_a_header_naming_x_and_y_is_accepted) {
  for (const std::string header : {"x,y", "\"X\";\"Y\"", "x_mm,y_mm", "x (mm), y (mm)", "X[in]\tY[in]"}) {
    BOOST_TEST_CONTEXT(header) {
      const auto pts = parse_point_text(header + "\r\n0,1\r\n2.5,-3\r\n", "export.csv", 2);
      BOOST_REQUIRE_EQUAL(pts.size(), 2u);
      BOOST_TEST(pts[1].x() == 2.5);
      BOOST_TEST(pts[1].y() == -3.0);
    }
  }
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
  // A header must name x then y: other columns (polar samples, swapped axes) would be misread.
  BOOST_TEST(contains(error_for("polar.csv", "theta,r\n0,1\n1,1\n"), "polar.csv:1: header \"theta,r\" does not name the columns x and y"));
  BOOST_TEST(contains(error_for("swapped.csv", "y,x\n0,1\n1,1\n"), "swapped.csv:1:"));
  BOOST_TEST(contains(error_for("three.csv", "x,y,z\n0,1\n1,1\n"), "three.csv:1:"));
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

BOOST_AUTO_TEST_CASE(encodings_line_ends_and_decimal_commas_say_what_to_do) {
  // Before: CR-only files read as one line ("a third column"), UTF-16 as "expected two numbers" with NUL
  // bytes in the message, decimal commas as a third or fourth column.
  const std::string cr = error_for("mac.txt", "0 0\r1 1\r2 0\r");
  BOOST_TEST(contains(cr, "mac.txt:1: line ends are a bare CR"));
  BOOST_TEST(contains(cr, "convert them"));
  BOOST_TEST(contains(error_for("mixed.txt", "0 0\n1 1\n2 0\r3 3\n"), "mixed.txt:3: line ends are a bare CR"));
  BOOST_TEST(error_for("crlf.txt", "0 0\r\n1 1\r\n") == "");  // CR LF is fine

  std::string utf16 = "\xFF\xFE";
  for (char c : std::string("0 0\n1 1\n")) utf16 += std::string{c, '\0'};
  const std::string u16 = error_for("u16.txt", utf16);
  BOOST_TEST(contains(u16, "u16.txt: the file is UTF-16 text (byte order mark FF FE)"));
  BOOST_TEST(contains(u16, "save it as plain text"));
  BOOST_TEST(contains(error_for("u16be.txt", "\xFE\xFF\0" "0"), "byte order mark FE FF"));
  BOOST_TEST(contains(error_for("nul.txt", std::string("0 0\n1\0 1\n", 9)), "nul.txt:2: the file holds NUL bytes"));

  const std::string comma = error_for("comma_dec.txt", "0 0\n1,5 2,25\n");
  BOOST_TEST(contains(comma, "comma_dec.txt:2: \"1,5 2,25\" looks like two numbers written with decimal commas"));
  BOOST_TEST(contains(comma, "write decimal points (\"1.5 2.25\")"));
  BOOST_TEST(contains(error_for("comma_semi.txt", "0 0\n-1,5;2,25\n"), "decimal commas"));
  // "1,2" is x = 1, y = 2 (',' separates columns), as before.
  BOOST_TEST(error_for("comma_sep.txt", "0 0\n1,2\n") == "");

  const std::string three = error_for("xyz.txt", "0 0 0\n1 1 0\n");
  BOOST_TEST(contains(three, "xyz.txt:1: expected two numbers \"x y\", got a third column in \"0 0 0\""));
  BOOST_TEST(contains(three, "keep the x and y columns only"));
  BOOST_TEST(contains(error_for("four.txt", "0 0 0 0\n"), "4 columns"));
}

BOOST_AUTO_TEST_CASE(long_or_control_character_lines_are_quoted_readably) {
  const std::string msg = error_for("long.txt", "0 0\n1 " + std::string(100000, 'x') + "\n");
  BOOST_TEST(contains(msg, "long.txt:2:"));
  BOOST_TEST(contains(msg, "xxx..."));
  BOOST_TEST(msg.size() < 400u);
  const std::string ctrl = error_for("ctrl.txt", "0 0\n1 a\x1b[2J\n");
  BOOST_TEST(contains(ctrl, "\"1 a\\x1b[2J\""));
  BOOST_TEST(ctrl.find('\x1b') == std::string::npos);
}

BOOST_AUTO_TEST_CASE(samples_come_with_their_lines) {
  const auto s = rollkin::io::read_point_samples(write_temp("lines.txt", "# c\nx y\n0 0\n\n1 1 # c\n2 0\n"), 2);
  BOOST_TEST(s.points.size() == 3u);
  BOOST_TEST(s.lines == (std::vector<std::size_t>{3, 5, 6}), boost::test_tools::per_element());
}

// ---- writing: io::PointFileText (docs/reliability.md, "What rollkin writes in an input format reads back") ----

namespace {

/// Doubles over the whole range: random bit patterns (finite ones), subnormals, extremes, signed zeros.
std::vector<rollkin::Vec2<double>> hard_points() {
  std::vector<double> v = {0.0, -0.0, 0.1, 1.0 / 3, 1e308, -1.7976931348623157e308, 4.9406564584124654e-324,
                           2.2250738585072014e-308, -2.2250738585072009e-308, 123456789012345680.0, 1e-7, 5e-324};
  std::mt19937_64 random(36);
  while (v.size() < 2000) {
    const std::uint64_t bits = random();
    double x;
    std::memcpy(&x, &bits, sizeof x);
    if (std::isfinite(x)) v.push_back(x);
  }
  std::vector<rollkin::Vec2<double>> points;
  for (std::size_t i = 0; i + 1 < v.size(); i += 2) points.emplace_back(v[i], v[i + 1]);
  return points;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

BOOST_AUTO_TEST_CASE(written_points_read_back_bit_for_bit) {
  const std::vector<rollkin::Vec2<double>> points = hard_points();
  const std::string text = rollkin::io::point_file_text("random doubles", points);
  // The reader of this module, and an independent one: strtod on the two fields of every line.
  const std::vector<rollkin::Vec2<double>> read = parse_point_text(text, "written", 1);
  BOOST_REQUIRE_EQUAL(read.size(), points.size());
  std::istringstream lines(text);
  std::string line;
  std::getline(lines, line);
  BOOST_TEST(line == "# random doubles");
  for (std::size_t k = 0; k < points.size(); ++k) {
    BOOST_REQUIRE(std::getline(lines, line));
    char* end = nullptr;
    const double x = std::strtod(line.c_str(), &end);
    const double y = std::strtod(end, &end);
    BOOST_TEST(*end == '\0');
    BOOST_TEST((same_bits(x, points[k].x()) && same_bits(y, points[k].y())), "line " << k + 2 << ": " << line);
    BOOST_TEST((same_bits(read[k].x(), points[k].x()) && same_bits(read[k].y(), points[k].y())));
  }
  BOOST_TEST(!std::getline(lines, line));
}

BOOST_AUTO_TEST_CASE(written_comments_stay_comments) {
  // Every byte below 0x20 and DEL in a name: none may end the comment line or be a byte the reader refuses
  // (NUL, a bare CR); a '\n' starts a new comment line.
  std::string name = "link";
  for (int c = 1; c < 0x20; ++c) name += static_cast<char>(c);
  name += '\x7f';
  name += std::string(1, '\0') + "end";
  rollkin::io::PointFileText file;
  file.comment(name).comment("two\nlines\r\n").header().point({1, 2}).comment("between").point({3, 4});
  const std::string text = file.text();
  const std::vector<rollkin::Vec2<double>> read = parse_point_text(text, "written", 2);
  BOOST_REQUIRE_EQUAL(read.size(), 2u);
  BOOST_TEST(read[1].x() == 3);
  BOOST_TEST(text.find('\0') == std::string::npos);
  std::istringstream lines(text);
  std::vector<std::string> all;
  for (std::string line; std::getline(lines, line);) all.push_back(line);
  // name (its '\n' splits it), "two", "lines\r" escaped, "" after the last '\n', header, point, comment, point
  BOOST_REQUIRE_EQUAL(all.size(), 9u);
  for (std::size_t i : {0, 1, 2, 3, 4, 7}) BOOST_TEST(all[i].rfind("# ", 0) == 0u, "line " << i + 1 << ": " << all[i]);
  BOOST_TEST(all[5] == "x y");
  BOOST_TEST(all[6] == "1 2");
}

BOOST_AUTO_TEST_CASE(writer_refuses_what_the_reader_refuses) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (const rollkin::Vec2<double>& p : {rollkin::Vec2<double>(nan, 0), rollkin::Vec2<double>(0, inf),
                                         rollkin::Vec2<double>(-inf, 1)})
    BOOST_CHECK_THROW(rollkin::io::PointFileText().point(p), rollkin::io::InternalError);
  rollkin::io::PointFileText file;
  file.point({0, 0});
  BOOST_CHECK_THROW(file.header(), std::logic_error);  // a header after a point would be read as a bad point
}

// A table (a motion law, a gear transmission, a scan) names its two columns as it likes (issue 37: a law file
// with the header "theta_deg,s_mm" was refused unless it said "x y"); the same reader, so every table reader
// takes it. Still refused: a header of three names, or names mixed with numbers; and a contour's file keeps
// the x y rule ("theta r" would be polar samples read as x y).
BOOST_AUTO_TEST_CASE(a_table_takes_a_header_naming_any_two_columns) {
  const fs::path dir = fs::temp_directory_path() / "rollkin_point_file_table";
  fs::create_directories(dir);
  for (const std::string header : {"theta_deg,s_mm", "\"cam_angle\";lift", "phi1 phi2", "Theta (deg), S (mm)", "x y"}) {
    BOOST_TEST_CONTEXT(header) {
      std::ofstream(dir / "law.txt") << header << "\n0 1\n90 2.5\n180 3\n270 -4\n";
      const rollkin::io::PointSamples rows = rollkin::io::read_table_file((dir / "law.txt").string(), 4);
      BOOST_REQUIRE_EQUAL(rows.points.size(), 4u);
      BOOST_TEST(rows.points[1].x() == 90.0);
      BOOST_TEST(rows.points[3].y() == -4.0);
      BOOST_TEST(rows.lines.front() == 2u);
    }
  }
  for (const std::string header : {"theta s extra", "theta 5"}) {
    BOOST_TEST_CONTEXT(header) {
      std::ofstream(dir / "bad.txt") << header << "\n0 1\n90 2.5\n180 3\n270 -4\n";
      try {
        rollkin::io::read_table_file((dir / "bad.txt").string(), 4);
        BOOST_FAIL("no error");
      } catch (const InputError& e) {
        BOOST_TEST(e.location() == "1");
        BOOST_TEST(std::string(e.what()).find("header") != std::string::npos);
      }
    }
  }
  BOOST_CHECK_THROW(parse_point_text("theta_deg,s_mm\n0 1\n1 2\n", "contour.txt", 2), InputError);
}
