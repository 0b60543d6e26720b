// What a CAD drawing or point file offers as contours (`rollkin contours FILE`, Python `rollkin.contours`):
// every chain it holds (DXF: per layer, order-free chaining by end points; SVG: per element and subpath; a
// point file: its one spline), each with what a user needs to pick it and the scene snippet that selects it.
// The formats and their listers: io/contour_formats.hpp.
//
//   for (const io::ListedChain& c : io::list_contours("gear.dxf")) std::cout << c.selector << "\n";
#pragma once

#include "rollkin/profile/bezier.hpp"

#include <string>
#include <vector>

namespace rollkin::io {

/// One chain of a drawing, in drawing units (DXF: the drawing's units; SVG: viewport units, y up).
struct ListedChain {
  std::string group;                  // DXF: the layer; SVG: the element ("path #cam", or its location)
  std::vector<std::string> entities;  // "LINE 2A", "ARC 2B" (DXF, chain order); "subpath 1" (SVG)
  bool closed = false;
  double length = 0;                  // arc length
  Vec2<double> min, max;              // bounding box
  std::size_t corners = 0;            // tangent discontinuities (a contact stops there)
  std::vector<BezierSegment<double>> segments;  // the chain as read (for --draw)
  std::string selector;               // the JSON contour object that selects exactly this chain
};

/// Every chain of the DXF drawing at `path`, layer by layer (layers in file order, chains by first entity).
std::vector<ListedChain> list_dxf_contours(const std::string& path);
/// Every subpath of every drawable element of the SVG document at `path`, in document order.
std::vector<ListedChain> list_svg_contours(const std::string& path);
/// By the file's format (io::contour_file_format_of: its extension, case-insensitive); InputError for a file of
/// no format.
std::vector<ListedChain> list_contours(const std::string& path);

}  // namespace rollkin::io
