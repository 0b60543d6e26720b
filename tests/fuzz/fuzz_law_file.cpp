// libFuzzer harness: bytes -> the law-file readers: the bytes are a table file ("theta s" rows, or a header of
// column names) read as a cam's motion law ({"law": {"file": ...}}, degrees and radians) and as a gear pair's
// transmission table ({"transmission": {"file": ...}}), through the spec readers the CLI uses
// (cam_spec_from_document, gear_spec_from_document: read_point_samples, then the periodic table of
// motion_law.hpp); an accepted law is evaluated at 64 angles and its continuity checked, as the CLI does.
// The file lives in a private directory made once per process.
#include "fuzz_support.hpp"
#include "rollkin/synthesis/cam.hpp"
#include "rollkin/synthesis/gears.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>

namespace {

/// A private directory for the table file (removed by the system's tmp cleaning; one per fuzzing process).
const std::string& directory() {
  static const std::string dir = [] {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/rollkin_fuzz_law.XXXXXX";
    if (!::mkdtemp(pattern.data())) std::abort();
    return pattern;
  }();
  return dir;
}

nlohmann::ordered_json cam_spec(const char* angle_unit) {
  return nlohmann::ordered_json::parse(std::string(R"({"units": {"length": "mm", "angle": ")") + angle_unit +
                                       R"("}, "base_radius": 40, "follower": {"motion": "translating"},
                                        "contact": {"roller_radius": 10}, "law": {"file": "law.txt"}})");
}

void law(const rollkin::synthesis::CamSpec& spec) {
  (void)spec.law->check_continuity();
  for (int k = 0; k < 64; ++k) (void)(*spec.law)(2 * rollkin::pi<double>() * k / 64);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rollkin;
  const std::string& dir = directory();
  {
    std::ofstream out(dir + "/law.txt", std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  for (const char* unit : {"deg", "rad"})
    fuzz::expect_documented_outcome([&] { law(synthesis::cam_spec_from_document(cam_spec(unit), "fuzz.json", dir)); });
  fuzz::expect_documented_outcome([&] {
    const nlohmann::ordered_json gear = nlohmann::ordered_json::parse(
        R"({"units": {"length": "mm", "angle": "deg"}, "centre_distance": 80, "transmission": {"file": "law.txt"}})");
    const synthesis::GearSpec spec = synthesis::gear_spec_from_document(gear, "fuzz.json", dir);
    const auto f = synthesis::transmission(spec);
    for (int k = 0; k < 64; ++k) (void)(f.f(2 * pi<double>() * k / 64) + f.df(2 * pi<double>() * k / 64));
  });
  return 0;
}
