// CSV writer: header, full round-trip precision of doubles, RFC 4180 quoting of the text column, argument
// checks, and atomic writes (no partial file, error names the path).
#define BOOST_TEST_MODULE io_csv
#include <boost/test/unit_test.hpp>

#include "test_support.hpp"

#include "rollkin/io/atomic_file.hpp"
#include "rollkin/io/csv.hpp"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace rollkin::io;

namespace {

fs::path out_dir() { return rollkin::testing::scratch_dir("io_csv"); }

std::string read_file(const fs::path& p) { return rollkin::testing::read_text(p); }

std::vector<std::string> lines(const std::string& s) {
  std::vector<std::string> out;
  std::istringstream in(s);
  std::string l;
  while (std::getline(in, l)) out.push_back(l);
  return out;
}

std::vector<std::string> split(const std::string& l) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : l) {
    if (c == ',') {
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

BOOST_AUTO_TEST_CASE(round_trip_precision) {
  const std::vector<double> values = {0.1,
                                      1.0 / 3.0,
                                      3.141592653589793,
                                      -2.5e300,
                                      1e-300,
                                      std::numeric_limits<double>::denorm_min(),
                                      std::numeric_limits<double>::max(),
                                      std::nextafter(1.0, 2.0),
                                      -0.0,
                                      123456789.0};
  for (double v : values) {
    const std::string s = format_double(v);
    BOOST_TEST_CONTEXT(s) { BOOST_TEST(same_bits(std::strtod(s.c_str(), nullptr), v)); }
  }
  BOOST_TEST(format_double(0.5) == "0.5");
  BOOST_TEST(format_double(0.1) == "0.1");  // printf %.17g wrote 0.10000000000000001
  BOOST_TEST(format_double(std::nan("")) == "nan");
  BOOST_TEST(format_double(-std::numeric_limits<double>::infinity()) == "-inf");
}

BOOST_AUTO_TEST_CASE(table_layout_and_quoting) {
  CsvWriter csv({"theta2_deg", "x", "theta23_deg"}, "status");
  csv.add_row({0.0, 0.1, 1.0 / 3.0}, "ok");
  csv.add_row({10.0, std::nan(""), -1e-17}, "singular, rank 4");
  csv.add_row({20.0, 2.0, 3.0}, "said \"no\"");
  csv.add_row({30.0, 2.0, 3.0});
  BOOST_TEST(csv.rows() == 4u);
  BOOST_TEST(csv.columns() == 4u);
  const auto ls = lines(csv.to_string());
  BOOST_REQUIRE_EQUAL(ls.size(), 5u);
  BOOST_TEST(ls[0] == "theta2_deg,x,theta23_deg,status");
  BOOST_TEST(ls[1] == "0,0.1,0.3333333333333333,ok");
  BOOST_TEST(ls[2] == "10,nan,-1e-17,\"singular, rank 4\"");
  BOOST_TEST(ls[3] == "20,2,3,\"said \"\"no\"\"\"");
  BOOST_TEST(ls[4] == "30,2,3,");
  // Numeric fields parse back exactly.
  const auto f = split(ls[1]);
  BOOST_TEST(same_bits(std::strtod(f[2].c_str(), nullptr), 1.0 / 3.0));

  // Without a text column: no trailing field; header names with commas are quoted.
  CsvWriter plain({"a,b", "c"});
  plain.add_row({1, 2});
  BOOST_TEST(plain.to_string() == "\"a,b\",c\n1,2\n");
  // Control characters are escaped (a row stays one line), then the field is quoted if needed.
  BOOST_TEST(csv_field("x\ny") == "x\\ny");
  BOOST_TEST(csv_field("a\x1b[31m,\r") == "\"a\\x1b[31m,\\r\"");

  BOOST_CHECK_THROW(csv.add_row({1.0, 2.0}), std::invalid_argument);
  BOOST_CHECK_THROW(plain.add_row({1.0, 2.0}, "text"), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(atomic_write) {
  CsvWriter csv({"a"}, "note");
  csv.add_row({1.5}, "x");
  const fs::path file = out_dir() / "table.csv";
  { std::ofstream(file) << "stale"; }
  csv.write(file.string());
  BOOST_TEST(read_file(file) == "a,note\n1.5,x\n");
  BOOST_TEST(rollkin::testing::no_temporaries_in(file.parent_path()));

  const fs::path missing = out_dir() / "no-such-dir" / "table.csv";
  fs::remove_all(missing.parent_path());
  try {
    csv.write(missing.string());
    BOOST_FAIL("write into a missing directory must throw");
  } catch (const std::runtime_error& e) {
    BOOST_TEST(std::string(e.what()).find(missing.string()) != std::string::npos);
  }
  BOOST_TEST(!fs::exists(missing));
  BOOST_TEST(rollkin::testing::no_temporaries_in(missing.parent_path()));
}

BOOST_AUTO_TEST_CASE(numbers_take_the_fewest_digits_that_read_back) {
  // Independent truth: the least printf precision p for which "%.{p}e" reads back to v. The text written must read
  // back to v and have exactly p + 1 significant digits (docs/reliability.md, "Outputs at any size": the CSV stays
  // exact).
  const std::vector<double> values = {0.1, 1.0 / 3.0, -48.971, 2.0 / 3.0 * 1e-7, 123456789.0, 5e-324, 1e23,
                                      0.30000000000000004, 6.02214076e23, -1.7976931348623157e308};
  for (double v : values) {
    const std::string s = format_double(v);
    int p = 0;
    char buf[64];
    for (;; ++p) {
      std::snprintf(buf, sizeof buf, "%.*e", p, v);
      if (std::strtod(buf, nullptr) == v) break;
    }
    // Significant digits of the text: no leading zeros, nor trailing zeros of an integer written without a point.
    std::string mantissa = s.substr(0, s.find_first_of("eE"));
    if (mantissa.find('.') == std::string::npos)
      while (mantissa.size() > 1 && mantissa.back() == '0') mantissa.pop_back();
    std::size_t digits = 0;
    bool leading = true;
    for (char c : mantissa) {
      if (c < '0' || c > '9' || (c == '0' && leading)) continue;
      leading = false;
      ++digits;
    }
    BOOST_TEST_CONTEXT(s << " vs " << buf) {
      BOOST_TEST(same_bits(std::strtod(s.c_str(), nullptr), v));
      BOOST_TEST(digits == static_cast<std::size_t>(p + 1));
    }
  }
}

BOOST_AUTO_TEST_CASE(an_empty_cell_is_written_empty_and_only_it) {
  // docs/reliability.md, "A force is determined or its cell is empty": io::empty_cell() is an empty field; a
  // NaN from arithmetic (either sign, as x86 makes it) stays "nan", and so does a quiet NaN of the library.
  const double zero = 0.0;
  const double values[] = {1.5, rollkin::io::empty_cell(), zero / zero, -(zero / zero),
                           std::numeric_limits<double>::quiet_NaN(), 2};
  std::string row;
  rollkin::io::append_csv_row(row, values, 6, nullptr);
  BOOST_TEST(row == "1.5,,nan,nan,nan,2\n");
  BOOST_TEST(rollkin::io::is_empty_cell(rollkin::io::empty_cell()));
  BOOST_TEST(std::isnan(rollkin::io::empty_cell()));
  BOOST_TEST(!rollkin::io::is_empty_cell(zero / zero));
}
