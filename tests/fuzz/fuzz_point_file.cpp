// libFuzzer harness: bytes -> the point file reader (read_point_file reads the file and calls parse_point_text).
#include "fuzz_support.hpp"
#include "rollkin/io/point_file.hpp"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  rollkin::fuzz::expect_documented_outcome(
      [&] { rollkin::io::parse_point_text(rollkin::fuzz::as_text(data, size), "fuzz.txt", 4, 1e-3); });
  return 0;
}
