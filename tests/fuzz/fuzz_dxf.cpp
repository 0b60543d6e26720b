// libFuzzer harness: bytes -> the DXF contour reader the scene's {"type": "dxf"} contours use
// (parse_dxf_contour, include/rollkin/io/dxf.hpp), selecting layer "0" and, by handle, "2F". Every input is
// read once by layer and once by handle, so both selection paths and the chaining behind them are exercised.
#include "fuzz_support.hpp"
#include "rollkin/io/dxf.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = rollkin::fuzz::as_text(data, size);
  rollkin::fuzz::expect_documented_outcome([&] { rollkin::parse_dxf_contour(text, rollkin::DxfSelection{"0", ""}, "fuzz.dxf"); });
  rollkin::fuzz::expect_documented_outcome([&] { rollkin::parse_dxf_contour(text, rollkin::DxfSelection{"", "2F"}, "fuzz.dxf"); });
  return 0;
}
