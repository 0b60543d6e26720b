// A contour from an ASCII DXF drawing (R12 to R2018), read with libdxflib, as exact Bezier segments.
//
// Selection: the entities of the ENTITIES section (model and paper space; block definitions are not
// searched) on one layer (case-insensitive, as DXF layer names are), or the single entity with a handle
// (group code 5, hexadecimal, case-insensitive).
//
// Entities and their exact conversion (drawing units; lines degree 1, circular and elliptical arcs rational
// quadratics of at most 90 degrees, BezierPath<double>::circle_arc mapped affinely):
//   LINE                  one line segment (z of both ends must agree: the drawing is read in the XY plane)
//   ARC, CIRCLE           centre, radius, start/end angle in degrees counter-clockwise (in the OCS)
//   ELLIPSE               centre, major axis end point, ratio (0, 1], start/end parameter in radians:
//                         p(t) = c + cos t M + sin t (ratio N x M); full when end - start = 2 pi
//   LWPOLYLINE, POLYLINE  vertices with bulges: bulge b from vertex i to i + 1 is an arc of included angle
//                         4 atan(b) (counter-clockwise for b > 0), b = 0 a line; closed flag (70 bit 1) adds
//                         the closing piece; repeated vertices are skipped. Curve- and spline-fit POLYLINEs and
//                         meshes are refused. Arcs are built from the chord and the bulge alone, exact for
//                         every bulge (src/io/dxf_convert.cpp); |b| <= eps is a line, |b| > 2e9 an error.
//   SPLINE                the control-point form as an exact NURBS (profile/nurbs.hpp): degree (71), knots
//                         (40), control points (10/20/30) and weights (41). Fit-point-only splines are an error.
// Extrusion (210/220/230): (0, 0, 1) or (0, 0, -1), within 1e-12 radians. The latter mirrors the OCS x axis for ARC, CIRCLE and the
// polylines (arbitrary axis algorithm) and makes ELLIPSE run clockwise; any other direction is an error.
//
// Chaining: the selected entities, in file order, are joined end to end into one contour, starting in the
// first entity's direction; a later entity is reversed when its end, not its start, meets the chain's end.
// Joints are snapped to the chain's end point. A chain whose end returns to its start is closed; a closed
// entity (CIRCLE, full ELLIPSE, closed polyline, closed SPLINE) must be the only one selected.
// Tolerance: two points meet when they are within 1e-9 times the diagonal of the bounding box of all selected
// entities' control points (kDxfJoinTolerance). A gap beyond it, or a branch (an entity meeting the chain
// somewhere else than its end), is an InputError naming both entities (type and handle) and the gap.
//
// Corners: every joint (inside an entity or between two) where the tangent direction turns by more than
// BezierPathOptions' corner tolerance (sqrt(eps) radians, the turn at which BezierPath splits the path) is
// listed in `corners`; a contact stops there (status corner).
//
// Units: $INSUNITS 0 (unitless), 1 (in), 2 (ft), 4 (mm), 5 (cm), 6 (m) give metres_per_unit (0 for unitless
// or absent); any other value is an InputError naming it.
//
// Errors (InputError: file, location "entity TYPE HANDLE" or "line N", message): unsupported entities on the
// selected layer (TEXT, MTEXT, HATCH, INSERT, DIMENSION, POINT, 3DFACE, ... including types libdxflib does
// not know, found by the scan below), an empty selection, malformed numbers or counts, degenerate geometry,
// two entities with one handle, a file that ends inside an entity. Numbers are plain decimals read once by
// std::from_chars, the texts on which libdxflib's own conversion agrees (docs/scene_format.md, "Numbers").
// How skipped entities are found: libdxflib calls processCodeValuePair for every group before it
// interprets it; the reader's adapter records from it, for every entity of the ENTITIES section, its type
// (group 0), handle (5) and layer (8) and the group counts it needs to check libdxflib's arrays (knots,
// control points, weights, fit points, LWPOLYLINE vertices). Parsing stays with libdxflib; an entity that
// libdxflib passed to no callback is then still known by type and handle and is reported.
#pragma once

#include "rollkin/io/input_error.hpp"
#include "rollkin/profile/bezier.hpp"

#include <string>
#include <vector>

namespace rollkin {

/// Points closer than this times the selection's bounding-box diagonal meet (joints, closure).
constexpr double kDxfJoinTolerance = 1e-9;

/// Which entities form the contour: exactly one of `layer` and `handle` is non-empty.
struct DxfSelection {
  std::string layer;
  std::string handle;
};

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
  std::string description;            // one line for --verbose
};

/// Reads the contour from the DXF text `dxf` (the file's bytes). `file` only names the source in errors.
DxfContour parse_dxf_contour(const std::string& dxf, const DxfSelection& selection, const std::string& file = "");

/// Reads the file at `path` and calls parse_dxf_contour.
DxfContour read_dxf_contour(const std::string& path, const DxfSelection& selection);

}  // namespace rollkin
