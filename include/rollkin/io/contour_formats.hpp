// The contour file formats: one descriptor per format (the scene's contour "type" that reads such a file, its
// extensions, what `rollkin contours` lists of it, one line for the help texts), kept in the contour kinds'
// registry (src/io/scene/contours/registry.cpp) beside that type's reader. The listing (io::list_contours), the
// CLI's help of `rollkin contours`, Python's docstring of rollkin.contours and the readers' contract test
// (tests/test_io_contour_formats.cpp) loop over them: a new format is one row of the registry and its own files.
//
//   for (const io::ContourFileFormat& f : io::contour_file_formats()) std::cout << f.name << "\n";
#pragma once

#include "rollkin/io/contour_listing.hpp"

#include <string>
#include <vector>

namespace rollkin::io {

/// Every chain a file of one format offers as contours, each with its selector (contour_listing.hpp).
using ContourLister = std::vector<ListedChain> (*)(const std::string& path);

struct ContourFileFormat {
  const char* name = nullptr;           // "DXF drawing"
  std::vector<std::string> extensions;  // lower case, with the dot: ".dxf" (a file is matched ignoring case)
  const char* description = nullptr;    // what is listed of such a file, one short line (help texts)
  ContourLister list = nullptr;
  const char* type = nullptr;           // the scene's contour "type" that reads it (docs/scene_format.md)
};

/// Every contour file format, in the registry's order.
const std::vector<ContourFileFormat>& contour_file_formats();
/// The format of the file at `path` by its extension (case-insensitive); nullptr when none has it.
const ContourFileFormat* contour_file_format_of(const std::string& path);
/// Every extension of every format, for messages and help: ".dxf, .svg, .txt or .csv" (`last` joins the last).
std::string contour_file_extensions(const std::string& last = "or");
/// One line per format, "<indent><name> (<extensions>): <description>", for help texts and docstrings.
std::string contour_file_formats_help(const std::string& indent = "  ");

}  // namespace rollkin::io
