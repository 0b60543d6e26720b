// Internals of the DXF reader (io/dxf.hpp), shared by its parts: src/io/dxf.cpp (checks, selection, units,
// the entry points), dxf_collector.hpp (what libdxflib delivers), dxf_convert.cpp (one entity to exact Bezier
// segments) and dxf_chain.cpp (the entities chained end to end into one contour).
#pragma once

#include "rollkin/io/dxf.hpp"
#include "rollkin/io/input_error.hpp"
#include "rollkin/profile/bezier.hpp"

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace rollkin::dxf {

using V = Vec2<double>;
using Segment = BezierSegment<double>;

// ---- text ----------------------------------------------------------------------------------------------------

/// A number as messages write it (10 significant digits), a point as "(x, y)".
std::string number(double x);
/// A value a message compares with a bound: the shortest text that reads back to it exactly, so that the
/// message never shows a value that contradicts what it says (0.99999999999999989, not 1).
std::string exact_number(double x);
std::string point_text(const V& p);
std::string upper(std::string s);
std::string trim(const std::string& s);
/// A group value (trimmed) as a number: the one reading of DXF numbers, on which rollkin's checks and
/// libdxflib's conversion agree (dxf.cpp). nullopt, with `problem` saying why ("is not ...", what libdxflib
/// would read instead), for any other text.
std::optional<double> read_real(const std::string& text, std::string& problem);
std::optional<int> read_int(const std::string& text, std::string& problem);
/// Group codes whose values are real numbers or integers (DXF reference, "Group code value types").
bool real_code(unsigned c);
bool int_code(unsigned c);

// ---- entities ------------------------------------------------------------------------------------------------

struct Vertex {
  double x, y, z, bulge;
};

/// One entity of the ENTITIES section: what the scan saw and what libdxflib delivered.
struct RawEntity {
  std::string type, handle, layer = "0";
  std::size_t line = 0;  // line of its group 0
  // group counts from the scan (checked against the counts libdxflib sizes its arrays with)
  long n10 = 0, n11 = 0, n40 = 0, n41 = 0;
  long g72 = -1, g73 = -1, g74 = -1, g90 = -1;
  // geometry from libdxflib callbacks
  bool delivered = false;
  std::array<double, 9> v{};  // LINE x1 y1 z1 x2 y2 z2; ARC cx cy cz r a1 a2; CIRCLE cx cy cz r; ELLIPSE c M ratio t0 t1
  std::array<double, 3> extrusion{{0, 0, 1}};
  int flags = 0, degree = 0;
  std::vector<Vertex> vertices;
  std::vector<double> knots;
  std::vector<std::array<double, 4>> control;  // x y z w

  std::string label() const { return type + " " + (handle.empty() ? "(no handle, line " + std::to_string(line) + ")" : handle); }
};

/// One entity converted: its exact Bezier segments in file order.
struct Piece {
  std::string label;
  std::vector<Segment> segments;
  bool closed = false;  // closed on its own (CIRCLE, full ELLIPSE, closed polyline or SPLINE)
};

/// The selected pieces chained end to end.
struct Chain {
  std::vector<Segment> segments;
  std::vector<std::size_t> owner;  // piece index of each segment
  bool closed = false;
};

/// The segment traversed backwards (dxf_convert.cpp).
Segment reversed(Segment s);

/// The exact Bezier segments of one entity (dxf_convert.cpp). InputError naming the entity otherwise.
Piece convert_entity(const RawEntity& e, const std::string& file);

/// The pieces chained end to end in file order (dxf_chain.cpp); `size` gets the drawing's size (the diagonal
/// of the pieces' control points), which scales the join tolerance. InputError for a gap, a branch, a leftover.
Chain chain_pieces(const std::string& file, const std::vector<Piece>& pieces, double& size);

}  // namespace rollkin::dxf
