// Internals of the DXF reader (io/dxf/reader.hpp), shared by its parts: src/io/dxf/drawing.cpp (the checks before
// libdxflib reads, units, handles, blocks), dxf/selection.cpp (the selection, the entry points),
// dxf/collector.hpp (what libdxflib delivers), dxf/convert.cpp (one entity to exact Bezier segments),
// dxf/chain.cpp (the pieces grouped into chains by their end points, one walked end to end)
// and dxf/listing.cpp (every chain of a drawing, io/contour_listing.hpp).
#pragma once

#include "rollkin/io/dxf/reader.hpp"
#include "rollkin/io/input_error.hpp"
#include "rollkin/profile/bezier.hpp"

#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace rollkin::io::dxf {

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
/// libdxflib's conversion agree (dxf/drawing.cpp). nullopt, with `problem` saying why ("is not ...", what libdxflib
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

/// One entity of the ENTITIES or BLOCKS section (a BLOCK and ENDBLK record too): what the scan saw and what
/// libdxflib delivered.
struct RawEntity {
  std::string type, handle, layer = "0";
  std::string block;     // the block definition it belongs to (BLOCKS section); empty in ENTITIES
  std::string name;      // INSERT: the block it inserts; BLOCK: the block's name
  std::size_t line = 0;  // line of its group 0
  // The first problem found in its groups (a malformed number, a count that does not match): reported when the
  // entity is used, so that an entity no contour needs never makes the file unreadable.
  std::string defect, defect_where;
  // group counts from the scan (checked against the counts libdxflib sizes its arrays with)
  long n10 = 0, n11 = 0, n40 = 0, n41 = 0;
  long g72 = -1, g73 = -1, g74 = -1, g90 = -1;
  // geometry from libdxflib callbacks
  bool delivered = false;
  // LINE x1 y1 z1 x2 y2 z2; ARC cx cy cz r a1 a2; CIRCLE cx cy cz r; ELLIPSE c M ratio t0 t1;
  // INSERT ipx ipy sx sy angle(degrees) columns rows column-spacing row-spacing; BLOCK base point x y
  std::array<double, 9> v{};
  std::array<double, 3> extrusion{{0, 0, 1}};
  int flags = 0, degree = 0;
  std::vector<Vertex> vertices;
  std::vector<double> knots;
  std::vector<std::array<double, 4>> control;  // x y z w

  std::string label() const { return type + " " + (handle.empty() ? "(no handle, line " + std::to_string(line) + ")" : handle); }
};

/// An affine map of the plane, p -> A p + t (A = [[a, b], [c, d]]): an INSERT's placement of its block.
struct Affine {
  double a = 1, b = 0, c = 0, d = 1;
  V t{0, 0};
  V operator()(const V& p) const { return V(a * p.x() + b * p.y() + t.x(), c * p.x() + d * p.y() + t.y()); }
  /// This map after `inner`: p -> this(inner(p)).
  Affine after(const Affine& inner) const {
    Affine m;
    m.a = a * inner.a + b * inner.c, m.b = a * inner.b + b * inner.d;
    m.c = c * inner.a + d * inner.c, m.d = c * inner.b + d * inner.d;
    m.t = (*this)(inner.t);
    return m;
  }
  bool identity() const { return a == 1 && b == 0 && c == 0 && d == 1 && t == V(0, 0); }
};

/// One entity converted: its exact Bezier segments in its own direction.
struct Piece {
  std::string label;   // "LINE 2A", or "LINE 2A in INSERT 3F" for a block's entity placed by an INSERT
  std::string layer;   // of the entity of the ENTITIES section it comes from (the INSERT's for a block's entity)
  std::string handle;  // likewise
  std::vector<Segment> segments;
  bool closed = false;  // closed on its own (CIRCLE, full ELLIPSE, closed polyline or SPLINE)
  bool zero_length = false;  // a LINE from a point to itself: dropped from a chain (DxfContour::notes)
};

/// A chain walked from one end: its segments end to end.
struct Chain {
  std::vector<Segment> segments;
  std::vector<std::size_t> owner;  // piece index of each segment
  std::vector<std::size_t> pieces; // piece indices in chain order
  bool closed = false;
};

/// A connected set of pieces (joined at end points within the tolerance), before it is walked.
struct Component {
  std::vector<std::size_t> pieces;  // piece indices in file order
  std::string branch;               // empty, or where three or more piece ends meet (naming the entities)
};

/// The segment traversed backwards (dxf/convert.cpp).
Segment reversed(Segment s);

/// The exact Bezier segments of one entity (dxf/convert.cpp), in its block's coordinates. InputError naming the
/// entity otherwise (also for its recorded defect).
Piece convert_entity(const RawEntity& e, const std::string& file);

/// Diagonal of the bounding box of the pieces' control points (the drawing's size that scales the tolerances).
double pieces_size(const std::vector<Piece>& pieces, const std::vector<std::size_t>& which);

/// The pieces grouped into connected chains by their end points (dxf/chain.cpp): two ends meet within `tol`.
/// Components in the order of their first piece.
std::vector<Component> connected_chains(const std::vector<Piece>& pieces, double tol);

/// One component walked from one end (the free end of its piece first in file order; a closed one from its
/// first piece's start, in that piece's direction); joints snapped. InputError for a branch or a piece no longer
/// than `tol`.
Chain walk_chain(const std::string& file, const std::vector<Piece>& pieces, const Component& component, double tol,
                 double size);

/// Smallest distance from q to the pieces of a component (control-point hull pruning, sampling and golden
/// section refinement: accurate to round-off of the distance).
double distance_to_component(const std::vector<Piece>& pieces, const Component& component, const V& q);

/// A point on the component: the middle (parameter 1/2) of the middle segment of its first piece.
V point_on_component(const std::vector<Piece>& pieces, const Component& component);

/// "LINE 2A, ARC 2B" (at most `limit` names, then "...").
std::string component_entities(const std::vector<Piece>& pieces, const Component& component, std::size_t limit = 6);

}  // namespace rollkin::io::dxf

namespace rollkin::io::dxf {

// ---- the drawing (dxf/drawing.cpp) -----------------------------------------------------------------------------------

/// What libdxflib delivered of a DXF text, with $INSUNITS.
struct Drawing {
  std::vector<RawEntity> entities;  // ENTITIES and BLOCKS, in file order
  bool has_insunits = false;
  int insunits = 0;
  /// The entities of the ENTITIES section (not the records and entities of block definitions).
  std::vector<const RawEntity*> top_level() const;
};

/// Checks `text` (the file's bytes), then reads it with libdxflib (the text up to group 0 EOF; from
/// `disk_path` when that is the file and nothing follows EOF).
Drawing read_drawing(const std::string& text, const std::string& disk_path, const std::string& file);

/// What makes every selection of the drawing fail: an unsupported $INSUNITS.
void check_drawing(const Drawing& drawing, const std::string& file);

/// The drawing's $INSUNITS as out's unit, metres per unit and insunits; InputError for an unsupported code.
void set_units(DxfContour& out, const Drawing& drawing, const std::string& file);

/// InputError naming `handle` when more than one entity (`with_it`, of the ENTITIES section) has it: a selection
/// by that handle is ambiguous (drawing.cpp).
void check_one_entity(const std::string& handle, const std::vector<const RawEntity*>& with_it, const std::string& file);

/// The entity types a contour is made of, as messages list them; supported(type) for each.
inline constexpr const char* kSupported =
    "LINE, ARC, CIRCLE, ELLIPSE, LWPOLYLINE, POLYLINE, SPLINE (and INSERTs of blocks made of them)";
bool supported(const std::string& type);

/// Entity types that are never curves (text, dimensions, hatches, viewports, ...): passed over.
bool never_a_curve(const std::string& type);

/// Converts entities of the ENTITIES section into pieces, an INSERT into its block's entities placed by it
/// (dxf/drawing.cpp, "blocks"). InputError for an entity that is not read.
class Placer {
 public:
  Placer(const Drawing& drawing, std::string file);
  /// Appends the pieces of `top` (none for a type that is never a curve).
  void place(const RawEntity& top, std::vector<Piece>& out);

 private:
  struct Block {
    std::string name;
    V base{0, 0};
    std::vector<const RawEntity*> entities;
  };
  void place_in(const RawEntity& e, const Affine& m, const std::string& suffix, std::vector<std::string>& stack,
                const RawEntity& top, std::vector<Piece>& out);
  void place_insert(const RawEntity& e, const Affine& m, const std::string& suffix, std::vector<std::string>& stack,
                    const RawEntity& top, std::vector<Piece>& out);
  [[noreturn]] void fail(const RawEntity& e, const std::string& what) const;

  std::string file_;
  std::map<std::string, Block> blocks_;  // by upper-case name
  std::size_t placed_ = 0;
};

}  // namespace rollkin::io::dxf
