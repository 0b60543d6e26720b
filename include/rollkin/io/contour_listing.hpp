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

/// One chain of a drawing, in drawing units (DXF: the drawing's units; SVG: viewport units, y up); or, with
/// `unreadable` set, an entity or element that could not be read (no chain: no length, box or segments).
struct ListedChain {
  std::string group;                  // DXF: the layer; SVG: the element ("path #cam", or its location)
  std::vector<std::string> entities;  // "LINE 2A", "ARC 2B" (DXF, chain order); "subpath 1" (SVG)
  bool closed = false;
  double length = 0;                  // arc length
  Vec2<double> min{0, 0}, max{0, 0};  // bounding box
  std::size_t corners = 0;            // tangent discontinuities (a contact stops there)
  std::vector<BezierSegment<double>> segments;  // the chain as read (for --draw)
  std::string selector;               // the JSON contour object that selects exactly this chain, or empty
  std::string no_selector;            // when `selector` is empty: why no selector picks it (never empty then)
  std::string hidden;                 // SVG: why it is not drawn (display="none", ...); "near" passes it over
  std::string unreadable;             // the message of an entity or element that could not be read, or empty
};

/// Every chain of the DXF drawing at `path`, layer by layer (layers in file order, chains by first entity;
/// then the layer's unreadable entities).
std::vector<ListedChain> list_dxf_contours(const std::string& path);
/// Every subpath of every element of the SVG document at `path`, in document order (hidden ones marked).
std::vector<ListedChain> list_svg_contours(const std::string& path);
/// By the file's format (io::contour_file_format_of: its extension, case-insensitive); InputError for a file of
/// no format.
std::vector<ListedChain> list_contours(const std::string& path);

/// The listing as `rollkin contours --json` prints it and Python's rollkin.contours returns it: a JSON array
/// of one object per chain (group, entities, closed, length, min, max, corners, selector; "no_selector" when
/// the selector is null, "hidden" for a hidden SVG element, "unreadable" with null closed, length, min, max
/// and corners for an entity that could not be read), dumped with `indent` (-1: one line); text that is
/// not UTF-8 (a layer name in another code page) with U+FFFD.
std::string contours_json(const std::vector<ListedChain>& chains, int indent = 2);

/// The number of listed items that are not chains (unreadable entities or elements).
std::size_t unreadable_count(const std::vector<ListedChain>& chains);

}  // namespace rollkin::io
