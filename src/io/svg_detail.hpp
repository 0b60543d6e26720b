// Pieces shared by the SVG path-data parser (svg_path.cpp) and the document reader (svg_document.cpp).
#pragma once

#include "rollkin/io/svg_path.hpp"

#include <string>

namespace rollkin::svg_detail {

enum class NumberScan { ok, none, out_of_range };

/// Scans an SVG number at `pos`: sign? (digits ('.' digits?)? | '.' digits) (('e'|'E') sign? digits)?.
/// ok / out_of_range: `pos` is past the number; none: `pos` unchanged.
NumberScan scan_number(const std::string& s, std::size_t& pos, double& value);

bool is_separator(char c);  // white space or ','

/// Diagonal of the bounding box of all control points (0 when there are none).
double control_extent(const std::vector<BezierSegment<double>>& segments);

/// Drops the segments whose control points all lie within round-off (BezierPath's joint tolerance times
/// the subpath's extent) of their start; the previous segment's end (or, for the first, the next
/// segment's start) is moved onto the dropped piece's far end so the subpath stays connected. This removes
/// the zero-length closing segment of a path closed after a last point equal to the first.
void drop_degenerate_segments(SvgSubpath& subpath);

/// Path data in the path's own coordinates (no flip, no scale); `context` names the path in messages.
std::vector<SvgSubpath> parse_path_data(const std::string& d, const std::string& file, const std::string& context);

}  // namespace rollkin::svg_detail
