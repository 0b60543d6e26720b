// Pieces shared by the SVG path-data parser (svg/path_data.cpp) and the document reader (svg/reader.cpp and
// the files of svg/document.hpp).
#pragma once

#include "rollkin/io/svg/path_data.hpp"

#include <string>

namespace rollkin::io::svg_detail {

enum class NumberScan { ok, none, out_of_range };

/// Scans an SVG number at `pos`: sign? (digits ('.' digits?)? | '.' digits) (('e'|'E') sign? digits)?.
/// ok / out_of_range: `pos` is past the number; none: `pos` unchanged.
NumberScan scan_number(const std::string& s, std::size_t& pos, double& value);

bool is_separator(char c);  // white space or ','

/// Diagonal of the bounding box of all control points (0 when there are none).
double control_extent(const std::vector<BezierSegment<double>>& segments);

/// Merges the pieces shorter than round-off (every control point within BezierPath's joint tolerance times the
/// subpath's extent of its start), which BezierPath cannot hold, into their neighbours without moving the
/// path: consecutive short pieces are collected until together they span more than the tolerance, and such a
/// run becomes a line from its start to its end, or extends the previous run's line while every run end stays
/// within the tolerance of it (10^5 steps "l 0 1e-6" after a 500-long line are one line 0.1 long; short steps
/// around a small circle are chords whose vertices are the path's). Every point of the path stays within
/// twice the tolerance of the result. A run that stays shorter joins the next piece (moving its start) or, at
/// the end, the previous piece (moving its end): the zero-length closing segment of a path closed after a
/// last point equal to the first goes this way.
void merge_short_segments(SvgSubpath& subpath);

/// "near" picks a subpath only when the next nearest is farther by more than this fraction of the distance
/// (plus 1e-9 of the drawing's size): otherwise the two are about equally near and the choice is an error.
constexpr double kNearTie = 0.01;

/// Path data in the path's own coordinates (no flip, no scale); `context` names the path in messages.
std::vector<SvgSubpath> parse_path_data(const std::string& d, const std::string& file, const std::string& context);

}  // namespace rollkin::io::svg_detail
