// Every reader of an input file refuses what is not a regular file before opening it (io/input_file.hpp,
// docs/reliability.md "Input files"): a directory (libdxflib spun on one forever) and a FIFO (a point file
// read from one blocked forever), for the scene, the point file, SVG and DXF drawings, the reference table,
// and each file a scene's contours read.
#define BOOST_TEST_MODULE io_input_file
#include <boost/test/unit_test.hpp>

#include "test_support.hpp"

#include "rollkin/io/dxf/reader.hpp"
#include "rollkin/io/input_file.hpp"
#include "rollkin/io/point_file.hpp"
#include "rollkin/io/scene/reader.hpp"
#include "rollkin/io/svg/reader.hpp"
#include "rollkin/reference.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <functional>
#include <thread>

using rollkin::testing::contains;
using rollkin::testing::input_error_of;
namespace fs = std::filesystem;

namespace {

/// While alive, watches a FIFO: if a reader ever blocks opening it, the guard opens its write end (and closes
/// it), so the reader sees an empty file instead of blocking the test forever, and records that it happened.
class FifoGuard {
 public:
  explicit FifoGuard(std::string fifo) : fifo_(std::move(fifo)), thread_([this] { watch(); }) {}
  ~FifoGuard() {
    stop_ = true;
    thread_.join();
  }
  bool a_reader_opened_it() const { return opened_; }

 private:
  void watch() {
    while (!stop_) {
      // Succeeds only when a reader has the FIFO open (O_NONBLOCK: ENXIO otherwise).
      const int fd = ::open(fifo_.c_str(), O_WRONLY | O_NONBLOCK);
      if (fd >= 0) {
        opened_ = true;
        ::close(fd);
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }
  std::string fifo_;
  std::atomic<bool> stop_{false}, opened_{false};
  std::thread thread_;
};

struct Reader {
  std::string kind;                           // for the test's messages
  std::string role;                           // how the message names the file
  std::function<void(const std::string&)> read;
};

/// A scene whose ground link has one contour of `type` reading `file` (relative to the scene file).
std::string scene_with_contour(const std::string& contour) {
  return R"({"links": [{"name": "frame", "ground": true, "contours": [)" + contour +
         R"(]}, {"name": "arm"}], "pairs": []})";
}

std::vector<Reader> readers(const fs::path& dir) {
  auto scene_reading = [dir](const std::string& contour_json) {
    return [dir, contour_json](const std::string& file) {
      const std::string name = fs::path(file).filename().string();
      std::string json = contour_json;
      json.replace(json.find("FILE"), 4, name);
      rollkin::io::parse_scene(scene_with_contour(json), (dir / "scene.json").string());
    };
  };
  return {
      {"scene", "the scene file", [](const std::string& f) { rollkin::io::load_scene(f); }},
      {"point file", "the point file", [](const std::string& f) { rollkin::io::read_point_file(f, 4); }},
      {"SVG", "the SVG file", [](const std::string& f) { rollkin::io::read_svg_shape(f, "cam"); }},
      {"DXF", "the DXF file", [](const std::string& f) { rollkin::io::read_dxf_contour(f, rollkin::io::DxfSelection{"CAM", ""}); }},
      {"reference table", "the reference file", [](const std::string& f) { rollkin::read_reference_csv(f); }},
      {"scene's samples contour", "the point file",
       scene_reading(R"({"name": "c", "type": "samples", "file": "FILE"})")},
      {"scene's svg contour", "the SVG file", scene_reading(R"({"name": "c", "type": "svg", "file": "FILE", "path": "cam"})")},
      {"scene's dxf contour", "the DXF file", scene_reading(R"({"name": "c", "type": "dxf", "file": "FILE", "layer": "CAM"})")},
  };
}

}  // namespace

BOOST_AUTO_TEST_CASE(every_reader_refuses_a_directory_and_a_fifo_before_opening_it) {
  const fs::path dir = rollkin::testing::scratch_dir("io_input_file");
  for (const Reader& r : readers(dir)) {
    BOOST_TEST_CONTEXT(r.kind) {
      const fs::path directory = dir / "a_directory";
      fs::create_directories(directory);
      const std::string dir_error = input_error_of([&] { r.read(directory.string()); });
      BOOST_TEST(contains(dir_error, directory.string() + ": " + r.role + " is a directory, not a regular file"));

      const fs::path fifo = dir / "a_fifo";
      fs::remove(fifo);
      BOOST_REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
      std::string fifo_error;
      bool blocked = false;
      {
        const FifoGuard guard(fifo.string());
        fifo_error = input_error_of([&] { r.read(fifo.string()); });
        blocked = guard.a_reader_opened_it();
      }
      BOOST_TEST(!blocked);  // the reader opened the FIFO (and would have waited for a writer forever)
      BOOST_TEST(contains(fifo_error, fifo.string() + ": " + r.role + " is a FIFO (named pipe), not a regular file"));
      fs::remove(fifo);
    }
  }
}

BOOST_AUTO_TEST_CASE(devices_are_named_and_regular_files_and_links_to_them_pass) {
  BOOST_TEST(rollkin::io::non_regular_kind("/dev/null") == "a character device");
  BOOST_TEST(contains(input_error_of([] { rollkin::io::read_point_file("/dev/zero", 4); }),
                      "/dev/zero: the point file is a character device, not a regular file"));
  const fs::path dir = rollkin::testing::scratch_dir("io_input_file");
  const std::string file = rollkin::testing::write_text(dir / "points.txt", "0 0\n1 0\n1 1\n0 1\n");
  BOOST_TEST(rollkin::io::non_regular_kind(file).empty());
  const fs::path link = dir / "points_link.txt";
  fs::remove(link);
  fs::create_symlink(file, link);
  BOOST_TEST(rollkin::io::read_point_file(link.string(), 4).size() == 4u);
  // A missing file is not refused here: opening it says why.
  BOOST_TEST(rollkin::io::non_regular_kind((dir / "missing.txt").string()).empty());
  BOOST_TEST(contains(input_error_of([&] { rollkin::io::read_point_file((dir / "missing.txt").string(), 4); }),
                      "cannot open the point file: No such file or directory"));
}
