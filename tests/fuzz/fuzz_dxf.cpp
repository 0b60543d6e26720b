// libFuzzer harness: bytes -> the DXF contour reader the scene's {"type": "dxf"} contours use
// (parse_dxf_contour, include/rollkin/io/dxf/reader.hpp), selecting layer "0", by handle "2F", by handles "2F" and
// "30", and near (0, 0): every selection path, the order-free chaining and the placement of INSERTs (nesting
// depth and cycles bounded) behind them are exercised.
#include "fuzz_support.hpp"
#include "rollkin/io/dxf/reader.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = rollkin::fuzz::as_text(data, size);
  rollkin::fuzz::expect_documented_outcome([&] { rollkin::io::parse_dxf_contour(text, rollkin::io::DxfSelection{"0", ""}, "fuzz.dxf"); });
  rollkin::fuzz::expect_documented_outcome([&] { rollkin::io::parse_dxf_contour(text, rollkin::io::DxfSelection{"", "2F"}, "fuzz.dxf"); });
  rollkin::io::DxfSelection handles;
  handles.handles = {"2F", "30"};
  rollkin::fuzz::expect_documented_outcome([&] { rollkin::io::parse_dxf_contour(text, handles, "fuzz.dxf"); });
  rollkin::io::DxfSelection near;
  near.near = rollkin::Vec2<double>(0, 0);
  rollkin::fuzz::expect_documented_outcome([&] { rollkin::io::parse_dxf_contour(text, near, "fuzz.dxf"); });
  return 0;
}
