// libFuzzer harness: bytes -> io::parse_scene, the reader behind `rollkin solve SCENE` (load_scene reads the
// file and calls it). The scene is anchored in the source tree, so contour files named relative to it
// ("shapes/circle_n0032.txt") are read as the CLI would read them.
#include "fuzz_support.hpp"
#include "rollkin/io/scene/reader.hpp"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  rollkin::fuzz::expect_documented_outcome(
      [&] { rollkin::io::parse_scene(rollkin::fuzz::as_text(data, size), ROLLKIN_SOURCE_DIR "/fuzz_scene.json"); });
  return 0;
}
