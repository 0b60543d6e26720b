#include "rollkin/io/csv.hpp"

#include "rollkin/io/atomic_file.hpp"
#include "rollkin/io/input_error.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace rollkin::io {

std::string format_double(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string csv_field(const std::string& field) {
  // Control characters (a name may hold any) are escaped so that every row stays one line of plain text.
  const std::string text = excerpt(field, std::string::npos);
  if (text.find_first_of(",\"") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
  return out;
}

CsvWriter::CsvWriter(std::vector<std::string> numeric_columns, std::string text_column)
    : columns_(std::move(numeric_columns)), text_column_(std::move(text_column)), has_text_(!text_column_.empty()) {}

void CsvWriter::add_row(const std::vector<double>& values, const std::string& text) {
  if (values.size() != columns_.size())
    throw std::invalid_argument("CsvWriter::add_row: " + std::to_string(values.size()) + " values for " +
                                std::to_string(columns_.size()) + " numeric columns");
  if (!has_text_ && !text.empty())
    throw std::invalid_argument("CsvWriter::add_row: text given but the table has no text column");
  rows_.push_back({values, text});
}

std::string CsvWriter::to_string() const {
  std::string out;
  bool first = true;
  for (const auto& c : columns_) {
    if (!first) out += ',';
    out += csv_field(c);
    first = false;
  }
  if (has_text_) {
    if (!first) out += ',';
    out += csv_field(text_column_);
  }
  out += '\n';
  for (const auto& r : rows_) {
    first = true;
    for (double v : r.values) {
      if (!first) out += ',';
      out += format_double(v);
      first = false;
    }
    if (has_text_) {
      if (!first) out += ',';
      out += csv_field(r.text);
    }
    out += '\n';
  }
  return out;
}

void CsvWriter::write(const std::string& path) const { write_file_atomic(path, to_string()); }

}  // namespace rollkin::io
