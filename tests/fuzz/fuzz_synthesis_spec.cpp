// libFuzzer harness: bytes -> the synthesis spec readers (rollkin synthesize cam / gears SPEC.json): the JSON
// document read as a cam spec and as a gear spec (cam_spec_from_document, gear_spec_from_document; a law or
// transmission file is looked up in examples/synthesis), then what the CLI does with an accepted spec before
// the synthesis itself: the law's continuity check and its values at 64 angles, the transmission function and
// its derivative at 64 angles.
#include "fuzz_support.hpp"
#include "rollkin/io/json/document.hpp"
#include "rollkin/synthesis/cam.hpp"
#include "rollkin/synthesis/gears.hpp"

#include <cstddef>
#include <cstdint>

namespace {

const char* const kDir = ROLLKIN_SOURCE_DIR "/examples/synthesis";

void cam(const nlohmann::ordered_json& document) {
  const rollkin::synthesis::CamSpec spec = rollkin::synthesis::cam_spec_from_document(document, "fuzz.json", kDir);
  (void)spec.law->check_continuity();
  for (int k = 0; k < 64; ++k) (void)(*spec.law)(2 * rollkin::pi<double>() * k / 64);
}

void gears(const nlohmann::ordered_json& document) {
  const rollkin::synthesis::GearSpec spec = rollkin::synthesis::gear_spec_from_document(document, "fuzz.json", kDir);
  const auto f = rollkin::synthesis::transmission(spec);
  for (int k = 0; k < 64; ++k) (void)(f.f(2 * rollkin::pi<double>() * k / 64) + f.df(2 * rollkin::pi<double>() * k / 64));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using rollkin::fuzz::expect_documented_outcome;
  expect_documented_outcome([&] {
    const nlohmann::ordered_json document = rollkin::io::parse_json_document(rollkin::fuzz::as_text(data, size), "fuzz.json");
    expect_documented_outcome([&] { cam(document); });
    expect_documented_outcome([&] { gears(document); });
  });
  return 0;
}
