// libFuzzer harness: bytes -> the SVG path reader, through the public entry points of
// include/rollkin/io/svg/reader.hpp only (so it stays valid when the reader behind them changes).
//  - input starting with '<' or a byte-order mark byte (0xEF, 0xFE, 0xFF): a whole SVG document, written to a scratch file and read with
//    read_svg_path(file, "contour") as a scene's {"type": "svg", "path": "contour"} contour is, and every subpath
//    the document draws with read_svg_shapes(file, "") as `rollkin contours` and "near" read it (<use> clones,
//    <symbol>, <switch> expanded: cycles, depth and counts bounded);
//  - anything else: path data (the `d` attribute) for parse_svg_path_data.
#include "fuzz_support.hpp"
#include "rollkin/io/svg/reader.hpp"

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

namespace {

const std::string& scratch_file() {
  static const std::string path = "/tmp/rollkin_fuzz_svg_" + std::to_string(::getpid()) + ".svg";
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = rollkin::fuzz::as_text(data, size);
  const unsigned char first = text.empty() ? 0 : static_cast<unsigned char>(text[0]);
  if (first == '<' || first == 0xEF || first == 0xFE || first == 0xFF) {
    std::ofstream(scratch_file(), std::ios::binary | std::ios::trunc) << text;
    rollkin::fuzz::expect_documented_outcome([&] { rollkin::io::read_svg_path(scratch_file(), "contour"); });
    rollkin::fuzz::expect_documented_outcome([&] { rollkin::io::read_svg_shapes(scratch_file(), ""); });
  } else {
    rollkin::fuzz::expect_documented_outcome([&] { rollkin::io::parse_svg_path_data(text, {}, "fuzz.svg", "contour"); });
  }
  return 0;
}
