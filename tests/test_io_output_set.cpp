#define BOOST_TEST_MODULE io_output_set
#include <boost/test/unit_test.hpp>

#include "test_support.hpp"

#include "rollkin/io/atomic_file.hpp"
#include "rollkin/io/input_file.hpp"
#include "rollkin/io/output_set.hpp"

#include <filesystem>
#include <new>
#include <set>
#include <stdexcept>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

using rollkin::io::OutputError;
using rollkin::io::OutputSet;
using rollkin::io::write_file_atomic;
namespace fs = std::filesystem;

namespace {

using namespace rollkin::testing;

/// A fresh, empty scratch directory for one test case.
fs::path fresh_dir(const std::string& name) {
  const fs::path dir = scratch_dir("io_output_set") / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// The names in `dir` (temporaries left behind would show here).
std::set<std::string> names_in(const fs::path& dir) {
  std::set<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.insert(e.path().filename().string());
  return out;
}

mode_t mode_of(const fs::path& p) {
  struct stat st {};
  ::stat(p.c_str(), &st);
  return st.st_mode & 07777;
}

/// The OutputError message of `f()`, or "" if it throws none.
template <class F> std::string output_error_of(F&& f) {
  try {
    f();
  } catch (const OutputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

BOOST_AUTO_TEST_CASE(temporary_names_cannot_collide_with_user_files) {
  // Old code wrote through OUTPUT.tmp: a scene named out.csv.tmp was overwritten and removed.
  const fs::path dir = fresh_dir("collide");
  write_text(dir / "out.csv.tmp", "the user's scene");
  write_file_atomic((dir / "out.csv").string(), "a,b\n");
  BOOST_TEST(read_text(dir / "out.csv.tmp") == "the user's scene");
  BOOST_TEST(read_text(dir / "out.csv") == "a,b\n");
  BOOST_TEST(names_in(dir) == (std::set<std::string>{"out.csv", "out.csv.tmp"}));
}

BOOST_AUTO_TEST_CASE(new_files_get_the_umask_mode_and_replaced_files_keep_theirs) {
  const fs::path dir = fresh_dir("mode");
  const mode_t old_mask = ::umask(022);
  write_file_atomic((dir / "new.csv").string(), "x");
  BOOST_TEST(mode_of(dir / "new.csv") == 0644u);
  ::umask(027);
  write_file_atomic((dir / "new2.csv").string(), "x");
  BOOST_TEST(mode_of(dir / "new2.csv") == 0640u);
  write_text(dir / "kept.csv", "old");
  fs::permissions(dir / "kept.csv", fs::perms(0604));
  write_file_atomic((dir / "kept.csv").string(), "new");
  BOOST_TEST(mode_of(dir / "kept.csv") == 0604u);
  BOOST_TEST(read_text(dir / "kept.csv") == "new");
  ::umask(old_mask);
}

BOOST_AUTO_TEST_CASE(a_symlink_output_writes_its_target_and_stays_a_link) {
  const fs::path dir = fresh_dir("symlink");
  fs::create_directories(dir / "real");
  write_text(dir / "real" / "data.csv", "old");
  fs::create_symlink("real/data.csv", dir / "link.csv");
  fs::create_symlink("link.csv", dir / "link2.csv");  // a chain of two links
  write_file_atomic((dir / "link2.csv").string(), "new");
  BOOST_TEST(fs::is_symlink(dir / "link.csv"));
  BOOST_TEST(fs::is_symlink(dir / "link2.csv"));
  BOOST_TEST(read_text(dir / "real" / "data.csv") == "new");
  BOOST_TEST(names_in(dir / "real") == (std::set<std::string>{"data.csv"}));
  // A dangling link is written as cp would: its target is created.
  fs::create_symlink("real/fresh.csv", dir / "dangling.csv");
  write_file_atomic((dir / "dangling.csv").string(), "fresh");
  BOOST_TEST(fs::is_symlink(dir / "dangling.csv"));
  BOOST_TEST(read_text(dir / "real" / "fresh.csv") == "fresh");
  BOOST_TEST(OutputSet::resolve_target((dir / "link2.csv").string()) == (dir / "real/data.csv").string());
}

BOOST_AUTO_TEST_CASE(outputs_resolving_to_an_input_are_refused) {
  const fs::path dir = fresh_dir("inputs");
  const std::string scene = write_text(dir / "scene.json", "{}");
  fs::create_directories(dir / "sub");
  fs::create_symlink("../scene.json", dir / "sub" / "to_scene.csv");
  fs::create_hard_link(dir / "scene.json", dir / "hard.csv");
  OutputSet set({scene});
  for (const fs::path& p : {dir / "scene.json", dir / "sub" / ".." / "scene.json", dir / "sub" / "to_scene.csv", dir / "hard.csv"}) {
    const std::string msg = output_error_of([&] { set.add("--csv", p.string()); });
    BOOST_TEST_CONTEXT(p) {
      BOOST_TEST(contains(msg, "refusing to write --csv '" + p.string() + "'"));
      BOOST_TEST(contains(msg, "inputs are never overwritten"));
    }
  }
  BOOST_TEST(read_text(scene) == "{}");
}

BOOST_AUTO_TEST_CASE(a_run_of_several_scenes_names_the_scene_that_reads_the_input) {
  // One set for a whole run: every file any scene reads, each with what it is; a refusal names it.
  const fs::path dir = fresh_dir("run");
  const std::string points = write_text(dir / "b.svg", "<svg/>");
  OutputSet run({rollkin::io::InputFile{(dir / "a.json").string(), "the scene file 'a.json'"},
                 rollkin::io::InputFile{points, "the contour file 'b.svg' read by scene 'a.json'"}});
  const std::string msg = output_error_of([&] { run.add("b.json's --plot", (dir / "b.svg").string()); });
  BOOST_TEST(contains(msg, "refusing to write b.json's --plot '" + (dir / "b.svg").string() +
                               "': it is the contour file 'b.svg' read by scene 'a.json'; inputs are never overwritten"));
  run.add("x.json's --draw", (dir / "x_d.svg").string());
  BOOST_TEST(contains(output_error_of([&] { run.add("x_d.json's --plot", (dir / "x_d.svg").string()); }),
                      "x_d.json's --plot '" + (dir / "x_d.svg").string() + "' and x.json's --draw '" +
                          (dir / "x_d.svg").string() + "' name the same file"));
  BOOST_TEST(read_text(points) == "<svg/>");
}

BOOST_AUTO_TEST_CASE(an_omitted_output_leaves_its_file_alone) {
  const fs::path dir = fresh_dir("omit");
  write_text(dir / "kept.dxf", "the user's drawing");
  OutputSet set;
  const std::size_t txt = set.add("--out", (dir / "a.txt").string()), dxf = set.add("--dxf", (dir / "kept.dxf").string());
  set.set(txt, "0 2\n");
  set.omit(dxf);
  set.commit();
  BOOST_TEST(read_text(dir / "a.txt") == "0 2\n");
  BOOST_TEST(read_text(dir / "kept.dxf") == "the user's drawing");
  BOOST_TEST(names_in(dir) == (std::set<std::string>{"a.txt", "kept.dxf"}));
}

BOOST_AUTO_TEST_CASE(bad_output_paths_are_refused_when_added) {
  const fs::path dir = fresh_dir("paths");
  OutputSet set;
  set.add("--csv", (dir / "a.csv").string());
  BOOST_TEST(contains(output_error_of([&] { set.add("--plot", (dir / "." / "a.csv").string()); }), "name the same file"));
  BOOST_TEST(contains(output_error_of([&] { set.add("--plot", (dir / "no_such_dir" / "x.svg").string()); }), "no_such_dir"));
  BOOST_TEST(contains(output_error_of([&] { set.add("--plot", dir.string()); }), "is a directory"));
  BOOST_TEST(contains(output_error_of([&] { set.add("--plot", ""); }), "empty file name"));
  BOOST_TEST(contains(output_error_of([&] { set.add("--plot", "/dev/null"); }), "not a regular file"));
  write_text(dir / "file", "x");
  BOOST_TEST(contains(output_error_of([&] { set.add("--plot", (dir / "file" / "x.svg").string()); }), "not a directory"));
  fs::create_symlink("loop2", dir / "loop1");
  fs::create_symlink("loop1", dir / "loop2");
  BOOST_TEST(contains(output_error_of([&] { set.add("--plot", (dir / "loop1").string()); }), "symbolic links"));
}

BOOST_AUTO_TEST_CASE(several_outputs_are_written_all_or_nothing) {
  const fs::path dir = fresh_dir("all_or_nothing");
  write_text(dir / "a.csv", "old a");
  fs::create_directories(dir / "gone");
  {
    OutputSet set;
    const auto a = set.add("--csv", (dir / "a.csv").string());
    const auto b = set.add("--plot", (dir / "gone" / "b.svg").string());
    set.set(a, "new a");
    set.set(b, "new b");
    fs::remove(dir / "gone");  // the directory disappears after the check: creating b's temporary fails
    BOOST_TEST(contains(output_error_of([&] { set.commit(); }), "b.svg"));
  }
  BOOST_TEST(read_text(dir / "a.csv") == "old a");
  BOOST_TEST(names_in(dir) == (std::set<std::string>{"a.csv"}));

  // The rename of the second output fails (its target became a non-empty directory after the check): the
  // first, already replaced, is put back.
  write_text(dir / "b.svg", "old b");
  {
    OutputSet set;
    const auto a = set.add("--csv", (dir / "a.csv").string());
    const auto b = set.add("--plot", (dir / "b.svg").string());
    set.set(a, "new a");
    set.set(b, "new b");
    fs::remove(dir / "b.svg");
    fs::create_directories(dir / "b.svg" / "inside");
    const std::string msg = output_error_of([&] { set.commit(); });
    BOOST_TEST(contains(msg, "b.svg"));
    BOOST_TEST(contains(msg, "restored"));
  }
  BOOST_TEST(read_text(dir / "a.csv") == "old a");
  BOOST_TEST(fs::is_directory(dir / "b.svg" / "inside"));
  BOOST_TEST(names_in(dir) == (std::set<std::string>{"a.csv", "b.svg"}));

  // And when everything is fine, every output is replaced or created.
  fs::remove_all(dir / "b.svg");
  {
    OutputSet set;
    set.set(set.add("--csv", (dir / "a.csv").string()), "new a");
    set.set(set.add("--plot", (dir / "b.svg").string()), "new b");
    set.commit();
  }
  BOOST_TEST(read_text(dir / "a.csv") == "new a");
  BOOST_TEST(read_text(dir / "b.svg") == "new b");
  BOOST_TEST(names_in(dir) == (std::set<std::string>{"a.csv", "b.svg"}));
}

BOOST_AUTO_TEST_CASE(streamed_outputs_are_written_in_blocks_all_or_nothing) {
  // A streamed output of several blocks arrives whole; one whose writer fails leaves every target as it
  // was and no temporary behind, also for the outputs already streamed (docs/reliability.md, "Outputs at any size").
  const fs::path dir = fresh_dir("streamed");
  write_text(dir / "a.csv", "old a");
  write_text(dir / "b.csv", "old b");
  std::string expected;
  for (int k = 0; k < 300000; ++k) expected += std::to_string(k) + "\n";  // about 2 MB: three blocks
  // The writer of a.csv: the same numbers line by line, never holding more than a block or so.
  auto stream_numbers = [](rollkin::io::OutputSink& sink) {
    for (int k = 0; k < 300000; ++k) {
      sink.buffer() += std::to_string(k) + "\n";
      sink.flush_full();
      BOOST_TEST(sink.buffer().size() < 2 * rollkin::io::OutputSink::kBlock);
    }
  };
  {
    OutputSet out;
    const auto a = out.add("--csv", (dir / "a.csv").string());
    const auto b = out.add("--plot", (dir / "b.csv").string());
    out.set_writer(a, stream_numbers);
    out.set_writer(b, [](rollkin::io::OutputSink& sink) {
      sink.buffer() += "partial";
      throw std::runtime_error("the writer failed");
    });
    BOOST_CHECK_THROW(out.commit(), std::runtime_error);
  }
  BOOST_TEST(read_text(dir / "a.csv") == "old a");
  BOOST_TEST(read_text(dir / "b.csv") == "old b");
  BOOST_TEST(names_in(dir) == (std::set<std::string>{"a.csv", "b.csv"}));
  OutputSet out;
  const auto a = out.add("--csv", (dir / "a.csv").string());
  const auto b = out.add("--plot", (dir / "b.csv").string());
  out.set_writer(a, stream_numbers);
  out.set(b, "new b");
  out.commit();
  BOOST_TEST(read_text(dir / "a.csv") == expected);
  BOOST_TEST(read_text(dir / "b.csv") == "new b");
  BOOST_TEST(names_in(dir) == (std::set<std::string>{"a.csv", "b.csv"}));
}

// ---- the check inside the commit (docs/reliability.md, "Outputs, signals and messages (issue 37)") ---------

BOOST_AUTO_TEST_CASE(the_check_reads_the_outputs_before_they_are_committed) {
  const fs::path dir = fresh_dir("check_reads_staged");
  write_text(dir / "scene.json", "old scene\n");
  OutputSet out;
  const std::size_t scene = out.add("--out (scene)", (dir / "scene.json").string());
  const std::size_t points = out.add("--out (points)", (dir / "points.txt").string());
  out.set(scene, "new scene\n");
  out.set(points, "1 2\n");
  std::string seen_scene, seen_points;
  out.commit([&] {
    // What the readers see under the outputs' own names is the staged content; the targets are untouched.
    seen_scene = rollkin::io::read_input_file((dir / "scene.json").string(), "the scene file");
    seen_points = rollkin::io::read_input_file((dir / "points.txt").string(), "the point file");
    BOOST_TEST(read_text(dir / "scene.json") == "old scene\n");
    BOOST_TEST(!fs::exists(dir / "points.txt"));
  });
  BOOST_TEST(seen_scene == "new scene\n");
  BOOST_TEST(seen_points == "1 2\n");
  BOOST_TEST(read_text(dir / "scene.json") == "new scene\n");
  BOOST_TEST(read_text(dir / "points.txt") == "1 2\n");
  BOOST_TEST((names_in(dir) == std::set<std::string>{"points.txt", "scene.json"}));
  // Outside the check the outputs' names are the files' again.
  BOOST_TEST(rollkin::io::opened_path((dir / "points.txt").string()) == (dir / "points.txt").string());
}

BOOST_AUTO_TEST_CASE(a_check_that_refuses_an_output_commits_nothing_and_is_an_internal_error) {
  const fs::path dir = fresh_dir("check_refuses");
  write_text(dir / "a.txt", "old a\n");
  OutputSet out;
  const std::size_t a = out.add("--out (a)", (dir / "a.txt").string());
  const std::size_t b = out.add("--out (b)", (dir / "b.txt").string());
  out.set(a, "new a\n");
  out.set(b, "new b\n");
  std::string message;
  try {
    out.commit([&] {
      throw rollkin::io::InputError((dir / "b.txt").string(), "line 1", "expected two numbers");
    });
  } catch (const rollkin::io::InternalError& e) {
    message = e.what();
  }
  BOOST_TEST(contains(message, "refused by rollkin's own reader"));
  BOOST_TEST(contains(message, "b.txt:line 1: expected two numbers"));
  BOOST_TEST(contains(message, "nothing was written"));
  BOOST_TEST(read_text(dir / "a.txt") == "old a\n");
  BOOST_TEST((names_in(dir) == std::set<std::string>{"a.txt"}));  // no b.txt, no temporary
}

BOOST_AUTO_TEST_CASE(a_check_that_fails_otherwise_commits_nothing) {
  const fs::path dir = fresh_dir("check_fails");
  OutputSet out;
  out.set(out.add("--out", (dir / "c.txt").string()), "c\n");
  BOOST_CHECK_THROW(out.commit([] { throw std::bad_alloc(); }), std::bad_alloc);  // out of memory stays itself
  BOOST_TEST(names_in(dir).empty());
  OutputSet again;
  again.set(again.add("--out", (dir / "c.txt").string()), "c\n");
  BOOST_CHECK_THROW(again.commit([] { throw std::runtime_error("sweep: no pose"); }), rollkin::io::InternalError);
  BOOST_TEST(names_in(dir).empty());
}
