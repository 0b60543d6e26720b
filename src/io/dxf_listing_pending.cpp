// TEMPORARY (branch h-svg27 only; the lead deletes this file at the merge): list_dxf_contours is defined by the
// DXF reader's branch. Until it is merged, `rollkin contours FILE.dxf` says so instead of failing to link.
#include "rollkin/io/contour_listing.hpp"
#include "rollkin/io/input_error.hpp"

namespace rollkin::io {

std::vector<ListedChain> list_dxf_contours(const std::string& path) {
  throw InputError(path, "", "DXF listing not built yet");
}

}  // namespace rollkin::io
