// Point samples of a contour from a text file, one point per line:
//
//   # comment (anything after '#' is ignored), blank lines are skipped
//   x y            <- an optional header line naming the columns, allowed as the first non-comment line only:
//                     a contour's file names x then y (HeaderNames::XAndY: "theta r" would be polar samples read
//                     as x y), a table (a law, a transmission, a scan) names its two columns as it likes
//                     (HeaderNames::AnyTwo: "theta_deg,s_mm")
//   0.0  1.25      separators: spaces, tabs, ',' or ';' (any mix, "1.5,2" and "1.5; 2" too)
//   1e-3, -2.5
//
// Every other line must hold exactly two finite numbers (decimal points, not commas). Line ends LF or CR LF;
// text in ASCII or UTF-8 (a UTF-8 byte order mark is skipped). Rejected with a message that says what to do:
// UTF-16/UTF-32 text or NUL bytes, bare-CR line ends, decimal commas ("1,5 2,5"), a third column. Each point is multiplied by `scale` (the file's
// unit in scene units, e.g. 0.001 for a file in mm read into a scene in m). Errors are InputError naming the
// file, the 1-based line and what was expected.
//
// Written by PointFileText (synthesised profiles and pitch curves, envelopes, centrodes), so that every file
// rollkin writes in this format reads back to the same doubles:
//
//   const std::string text = io::PointFileText().comment("cam profile").points(profile).text();
#pragma once

#include "rollkin/io/input_error.hpp"
#include "rollkin/scalar.hpp"

#include <string>
#include <vector>

namespace rollkin::io {

/// What a header line may name (file comment): x then y (a contour), or any two columns (a table).
enum class HeaderNames { XAndY, AnyTwo };

/// Points and the 1-based line of the file each was read from (for messages about a point).
struct PointSamples {
  std::vector<Vec2<double>> points;
  std::vector<std::size_t> lines;
};

/// Reads the file at `path` (see above) with the line of every point; throws InputError.
PointSamples read_point_samples(const std::string& path, std::size_t min_points, double scale = 1.0,
                                HeaderNames columns = HeaderNames::XAndY);

/// A table of two columns (a motion law, a gear transmission, a scan): the same reader, a header line naming
/// any two columns allowed; the rows as points (first column, second column) with their lines.
PointSamples read_table_file(const std::string& path, std::size_t min_rows);

/// Reads the file at `path`; throws InputError if it cannot be opened, is malformed, or holds fewer than
/// `min_points` points.
std::vector<Vec2<double>> read_point_file(const std::string& path, std::size_t min_points, double scale = 1.0);

/// The same for text already in memory; `source` names it in messages.
std::vector<Vec2<double>> parse_point_text(const std::string& text, const std::string& source,
                                           std::size_t min_points, double scale = 1.0,
                                           HeaderNames columns = HeaderNames::XAndY);

/// The text of a point file: comment lines, an optional header line "x y", one line "x y" per point with each
/// number the shortest text that reads back to the same double (io::format_double). What it writes,
/// read_point_file reads back to the same points.
class PointFileText {
 public:
  /// Each line of `text` (split at '\n') as a comment line "# line", its control characters escaped (excerpt(),
  /// io/input_error.hpp) so that a comment never ends its line or holds a byte the reader refuses.
  PointFileText& comment(const std::string& text);
  /// The header line "x y"; std::logic_error after a point (the reader takes a header as the first line that is
  /// not a comment only).
  PointFileText& header();
  /// One line "x y". A non-finite coordinate would make a file the reader refuses: io::InternalError naming the
  /// point (a defect of rollkin, never the user's input; docs/reliability.md, "Outputs, signals and messages
  /// (issue 37)").
  PointFileText& point(const Vec2<double>& p);
  PointFileText& points(const std::vector<Vec2<double>>& ps);

  const std::string& text() const { return text_; }

 private:
  std::string text_;
  bool has_point_ = false;
};

/// The point file of `points` after the comment `what`: PointFileText().comment(what).points(points).text().
std::string point_file_text(const std::string& what, const std::vector<Vec2<double>>& points);

}  // namespace rollkin::io
