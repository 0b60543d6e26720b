// A contour from an ASCII DXF drawing (R12 to R2018), read with libdxflib, as exact Bezier segments.
//
// Selection: among the entities of the ENTITIES section (model and paper space), by
//   layer             the entities on one layer (case-insensitive, as DXF layer names are); they must form one
//                     chain (else an InputError lists the chains, each with a point on it for "near");
//   near (+ layer)    the chain, among the chains of the layer (or of the whole drawing), passing nearest to a
//                     point (drawing units); two chains whose distances differ by at most kDxfNearTie x the
//                     drawing size are an InputError naming both;
//   handle, handles   these entities (group code 5, hexadecimal, case-insensitive), chained in any order; they
//                     must form one chain.
// An INSERT (block reference, also a MINSERT array) stands for its block's entities placed by it: insertion
// point, x/y scale (negative and non-uniform too), rotation, the block's base point, the MINSERT's columns and
// rows (spacing rotated, not scaled), extrusion +-Z; nested INSERTs compose (at most kDxfMaxInsertDepth deep, a
// block inserting itself is an error). The placement is an affine map applied to the Bezier control points
// (weights kept): exact. A block's entities count as the INSERT's: on its layer, selected by its handle, named
// "LINE 2A in INSERT 3F" (MINSERT: "in INSERT 3F (column c, row r)").
// Entities that are never curves (TEXT, MTEXT, DIMENSION, HATCH, POINT, VIEWPORT, MULTILEADER, ATTDEF, ...) are
// passed over (an error when named by handle); any other entity that is not read (a tilted one, an unknown
// type, a fit-point SPLINE, a malformed one) is an error when the selection considers it: only the considered
// entities are checked (a malformed entity elsewhere never makes the file unreadable).
//
// Entities and their exact conversion (drawing units; lines degree 1, circular and elliptical arcs rational
// quadratics of at most 90 degrees, BezierPath<double>::circle_arc mapped affinely):
//   LINE                  one line segment (z of both ends must agree: the drawing is read in the XY plane)
//   ARC, CIRCLE           centre, radius, start/end angle in degrees counter-clockwise (in the OCS)
//   ELLIPSE               centre, major axis end point, ratio > 0, start/end parameter in radians:
//                         p(t) = c + cos t M + sin t (ratio N x M); full when end - start = 2 pi (a ratio above
//                         1, as QCAD writes, is the ellipse with the axes swapped, read by the same formula)
//   LWPOLYLINE, POLYLINE  vertices with bulges: bulge b from vertex i to i + 1 is an arc of included angle
//                         4 atan(b) (counter-clockwise for b > 0), b = 0 a line; closed flag (70 bit 1) adds
//                         the closing piece; repeated vertices are skipped. Curve- and spline-fit POLYLINEs and
//                         meshes are refused. Arcs are built from the chord and the bulge alone, exact for
//                         every bulge (src/io/dxf/convert.cpp); |b| <= eps is a line, |b| > 2e9 an error.
//   SPLINE                the control-point form as an exact NURBS (profile/nurbs.hpp): degree (71), knots
//                         (40), control points (10/20/30) and weights (41); a periodic one (70 bit 2) with n
//                         control points and n + 1 knots is wrapped (p points, knots extended periodically);
//                         spans that are a single point (repeated control points) are dropped. Fit-point-only
//                         splines are an error. The normal (0, 0, 0) is +Z.
//   LINE of zero length   dropped from a chain (DxfContour::notes); alone, an error.
// Extrusion (210/220/230): (0, 0, 1) or (0, 0, -1), within 1e-12 radians. The latter mirrors the OCS x axis for
// ARC, CIRCLE, the polylines and INSERT (arbitrary axis algorithm) and makes ELLIPSE run clockwise; any other
// direction is an error naming the entity and its normal (printed exactly).
//
// Chaining (order-free): the considered pieces are grouped into connected chains by their end points (two
// ends meet within the tolerance); a chain is walked from one end: the free end of its entity first in file
// order (a closed chain: from its first entity's start, in that entity's direction), each entity reversed as
// needed; joints are snapped. A chain whose end returns to its start is closed. Three or more entity ends at
// one point in the selected chain is a branch: an InputError naming the entities.
// Tolerance: two points meet when they are within 1e-9 times the diagonal of the bounding box of the
// considered entities' control points (kDxfJoinTolerance).
//
// Corners: every joint (inside an entity or between two) where the tangent direction turns by more than
// BezierPathOptions' corner tolerance (sqrt(eps) radians, the turn at which BezierPath splits the path) is
// listed in `corners`; a contact stops there (status corner).
//
// Units: $INSUNITS 0 (unitless), 1 (in), 2 (ft), 4 (mm), 5 (cm), 6 (m) give metres_per_unit (0 for unitless
// or absent); any other value is an InputError naming it.
//
// Errors (InputError: file, location "entity TYPE HANDLE" or "line N", message): unsupported entities among
// those considered (3DFACE, HELIX, ... including types libdxflib does not know, found by the scan below), an
// empty selection, malformed numbers or counts in a considered entity, degenerate geometry, two entities with
// one handle, a file that ends inside an entity. Text after group 0 EOF is ignored (libdxflib is given the
// text up to it). Numbers are plain decimals read once by
// std::from_chars, the texts on which libdxflib's own conversion agrees (docs/scene_format.md, "Numbers").
// How skipped entities are found: libdxflib calls processCodeValuePair for every group before it
// interprets it; the reader's adapter records from it, for every entity of the ENTITIES and BLOCKS sections
// (block definitions: for INSERTs), its type
// (group 0), handle (5) and layer (8) and the group counts it needs to check libdxflib's arrays (knots,
// control points, weights, fit points, LWPOLYLINE vertices). Parsing stays with libdxflib; an entity that
// libdxflib passed to no callback is then still known by type and handle and is reported.
#pragma once

#include "rollkin/io/input_error.hpp"
#include "rollkin/profile/bezier.hpp"

#include <optional>
#include <string>
#include <vector>

namespace rollkin::io {

/// Points closer than this times the selection's bounding-box diagonal meet (joints, closure).
constexpr double kDxfJoinTolerance = 1e-9;
/// "near": two chains whose distances to the point differ by at most this times the drawing size are a tie.
constexpr double kDxfNearTie = 1e-6;
/// INSERTs nested deeper than this are an error (a block inserting itself is found before).
constexpr int kDxfMaxInsertDepth = 32;
/// An INSERT that places more entities than this (MINSERT arrays of nested blocks) is an error.
constexpr std::size_t kDxfMaxPlacedEntities = 1000000;

/// Which entities form the contour (see "Selection" above): `layer` alone, `near` with or without `layer`,
/// `handle` alone or `handles` alone.
struct DxfSelection {
  std::string layer;
  std::string handle;
  std::vector<std::string> handles;     // these entities (or INSERTs), chained in any order
  std::optional<Vec2<double>> near;     // drawing units: the chain passing nearest to this point
};

/// How every message names a selection: "handle 1F", "handles 1F, 2A", "layer \"CAM\"", "layer \"CAM\",
/// near (1, 2)" or "all layers, near (1, 2)".
std::string selection_text(const DxfSelection& selection);

/// A tangent discontinuity of the chained contour.
struct DxfCorner {
  std::string entity;      // "LWPOLYLINE 2F" inside an entity, "LINE 2A / ARC 2B" at a join of two
  std::size_t segment = 0; // index in DxfContour::segments of the segment that starts at the corner
  Vec2<double> point;      // drawing units
  double turn_degrees = 0; // signed turn of the tangent (counter-clockwise positive)
};

struct DxfContour {
  std::vector<BezierSegment<double>> segments;  // drawing units, end to end in chain order
  bool closed = false;
  std::vector<DxfCorner> corners;
  std::vector<std::string> joint_entities;  // per segment: the entity (or "A / B": the two) at its start
  std::vector<std::string> entities;  // "TYPE HANDLE" of the chained entities, in chain order
  int insunits = 0;                   // $INSUNITS (0 when absent)
  std::string unit;                   // "in", "ft", "mm", "cm", "m"; empty when unitless
  double metres_per_unit = 0;         // drawing unit in metres; 0 when unitless
  std::string description;            // one line for --verbose (with the notes)
  std::vector<std::string> notes;     // what was dropped on the way (a zero-length LINE)
};

/// Reads the contour from the DXF text `dxf` (the file's bytes). `file` only names the source in errors.
DxfContour parse_dxf_contour(const std::string& dxf, const DxfSelection& selection, const std::string& file = "");

/// Reads the file at `path` and calls parse_dxf_contour.
DxfContour read_dxf_contour(const std::string& path, const DxfSelection& selection);

}  // namespace rollkin::io
