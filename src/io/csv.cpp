#include "rollkin/io/csv.hpp"

#include "rollkin/io/atomic_file.hpp"
#include "rollkin/io/input_error.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace rollkin::io {

namespace {

/// The longest text put_double writes: the shortest round-trip form of a double takes at most 24 characters.
constexpr std::size_t kMaxNumber = 24;

/// The bits of empty_cell(): a quiet NaN whose payload spells no arithmetic result.
constexpr std::uint64_t kEmptyCellBits = 0x7ff80000e3b7c311ULL;

/// Writes v at p as format_double does (empty_cell(): nothing); returns one past its last character.
char* put_double(char* p, double v) {
  if (std::isnan(v)) return is_empty_cell(v) ? p : std::copy_n("nan", 3, p);
  if (std::isinf(v)) return v > 0 ? std::copy_n("inf", 3, p) : std::copy_n("-inf", 4, p);
  return std::to_chars(p, p + kMaxNumber, v).ptr;
}

}  // namespace

double empty_cell() {
  double v;
  std::memcpy(&v, &kEmptyCellBits, sizeof v);
  return v;
}

bool is_empty_cell(double v) {
  std::uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  return bits == kEmptyCellBits;
}

void append_double(std::string& out, double v) {
  char buf[kMaxNumber];
  out.append(buf, put_double(buf, v));
}

std::string format_double(double v) {
  std::string out;
  append_double(out, v);
  return out;
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

void append_csv_header(std::string& out, const std::vector<std::string>& numeric_columns, const std::string& text_column) {
  bool first = true;
  for (const auto& c : numeric_columns) {
    if (!first) out += ',';
    out += csv_field(c);
    first = false;
  }
  if (!text_column.empty()) {
    if (!first) out += ',';
    out += csv_field(text_column);
  }
  out += '\n';
}

void append_csv_row(std::string& out, const double* values, std::size_t count, const std::string* text) {
  const std::string field = text ? csv_field(*text) : std::string();
  // Room for the longest row, filled in place and cut to what was written: two size changes per row instead
  // of two appends per number.
  const std::size_t at = out.size();
  out.resize(at + count * (kMaxNumber + 1) + field.size() + 2);
  char* p = out.data() + at;
  for (std::size_t i = 0; i < count; ++i) {
    if (i) *p++ = ',';
    p = put_double(p, values[i]);
  }
  if (text) {
    if (count) *p++ = ',';
    p = std::copy(field.begin(), field.end(), p);
  }
  *p++ = '\n';
  out.resize(static_cast<std::size_t>(p - out.data()));
}

std::string CsvWriter::to_string() const {
  std::string out;
  append_csv_header(out, columns_, text_column_);
  for (const auto& r : rows_) append_csv_row(out, r.values.data(), r.values.size(), has_text_ ? &r.text : nullptr);
  return out;
}

void CsvWriter::write(const std::string& path) const { write_file_atomic(path, to_string()); }

}  // namespace rollkin::io
