// Small CSV writer for result tables: a header row, rows of doubles each written as the shortest text that
// reads back (strtod) to the identical double (io::format_double, io/format.hpp; non-finite values as nan /
// inf / -inf) and an optional trailing text column (e.g. a solver status); io::empty_cell() values as empty fields. Fields are quoted per RFC 4180
// only when they contain a comma, a double quote, CR or LF. Lines end with '\n'. Files are written atomically
// (io/atomic_file.hpp): PATH.tmp, then rename; on failure std::runtime_error naming PATH.
//
//   rollkin::io::CsvWriter csv({"theta2_deg", "x", "theta23_deg"}, "status");
//   csv.add_row({0.0, 0.0, 0.0}, "ok");
//   csv.write("out/paper_fourbar.csv");
#pragma once

#include "rollkin/io/format.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace rollkin::io {

/// The field as it must appear in a CSV line: control characters written as escapes ("\n", "\r",
/// "\t", "\x1b") so that a row is one line, then double-quoted with inner quotes doubled when it
/// contains ',' or '"'.
std::string csv_field(const std::string& field);

/// Appends the header line: the numeric columns' names, then text_column unless it is empty.
void append_csv_header(std::string& out, const std::vector<std::string>& numeric_columns, const std::string& text_column);

/// Appends one row: `count` values (append_double), then the text field when `text` is given.
void append_csv_row(std::string& out, const double* values, std::size_t count, const std::string* text);

class CsvWriter {
 public:
  /// numeric_columns: names of the double columns, in order; text_column: name of the trailing text column,
  /// or empty for none.
  explicit CsvWriter(std::vector<std::string> numeric_columns, std::string text_column = {});

  /// Appends a row. Throws std::invalid_argument when values.size() differs from the number of numeric
  /// columns, or when text is given but the writer has no text column.
  void add_row(const std::vector<double>& values, const std::string& text = {});

  std::size_t rows() const { return rows_.size(); }
  std::size_t columns() const { return columns_.size() + (has_text_ ? 1 : 0); }
  const std::vector<std::string>& numeric_columns() const { return columns_; }

  /// The whole table as CSV text (header first).
  std::string to_string() const;

  /// Writes to_string() atomically; throws std::runtime_error naming the path on failure.
  void write(const std::string& path) const;

 private:
  struct Row {
    std::vector<double> values;
    std::string text;
  };
  std::vector<std::string> columns_;
  std::string text_column_;
  bool has_text_ = false;
  std::vector<Row> rows_;
};

}  // namespace rollkin::io
