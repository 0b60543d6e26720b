// Contours for CAD: SPLINE entities in a DXF document, written with libdxflib (the library the reader uses).
//
// A sampled contour (profile/spline.hpp: a C2 cubic spline on the chord-length parameter) is written exactly:
// each span k, with h its parameter length and p(t) its cubic, is the Bezier segment
//   P0 = p(0), P1 = P0 + h p'(0) / 3, P2 = P3 - h p'(h) / 3, P3 = p(h),
// and the segments together are one degree-3 B-spline with the spline's knots, each interior one repeated
// three times (clamped ends: four times). Any NURBS reader (CAD programs, ezdxf, rollkin's own `dxf`
// contour) evaluates the same curve; the samples lie on it to round-off.
#pragma once

#include "rollkin/profile/spline.hpp"

#include <string>
#include <vector>

namespace rollkin::io {

/// One SPLINE entity: a non-rational B-spline in the drawing plane (weights 1).
struct DxfSpline {
  std::string layer;
  int degree = 3;
  std::vector<double> knots;
  std::vector<Vec2<double>> control;
  bool closed = false;  // DXF flag 1: the curve ends where it starts (tangent continuous there)
};

/// The sampled contour p as one SPLINE on `layer` (see the top of this file).
DxfSpline spline_of(const SampledProfile<double>& p, const std::string& layer);

/// The polyline through `points` (fewer than a cubic needs) as a degree-1 SPLINE on `layer`.
DxfSpline polyline_spline(const std::vector<Vec2<double>>& points, const std::string& layer);

/// A DXF (AutoCAD 2000) document holding `splines`, with one layer per distinct layer name and $INSUNITS
/// from `length_unit` ("mm", "m", "in", ...; unitless for a label DXF has no code for).
/// Throws std::runtime_error when the writer's scratch file cannot be made.
std::string dxf_text(const std::vector<DxfSpline>& splines, const std::string& length_unit);

}  // namespace rollkin::io
