// A set of output files written all or nothing, never over an input.
//
//   io::OutputSet out(scene.files_read_with_scene);   // the files the run read: never written
//   const auto csv = out.add("--csv", "run.csv");     // checks the path now, before any work is done
//   const auto plot = out.add("--plot", "run.svg");
//   ... solve ...
//   out.set(csv, csv_text);  out.set(plot, svg_text);
//   out.commit();                                     // every file replaced, or none
//
// An output may instead be streamed (set_writer): commit() calls its writer, which appends text to the
// sink's buffer and hands it over a block at a time (OutputSink::flush_full), so a large output is never
// held whole in memory; it still goes to the temporary and is renamed only with all the others.
//
// add() refuses (OutputError) an empty path, a directory, a path whose directory is missing or not
// writable, an existing file that is not a regular file, a file the run read (compared by realpath and by
// device/inode, so hard links and symlinks are caught) and a file already in the set. This is the one rule
// that no run loses a file (docs/reliability.md, "Outputs"): a run of several scenes checks all its outputs
// in one set holding every file any of its scenes reads (InputFile names the scene that reads each) before
// it solves anything.
// An output path that is a symbolic link is written to its target (as cp does); the link stays a link.
// commit() creates one temporary per output in the target's own directory (so that rename(2) stays on one
// file system): an unnamed file (O_TMPFILE), named only for the few system calls that rename it over its target,
// with SIGINT, SIGTERM, SIGHUP and SIGQUIT held meanwhile (io/temporary_file.hpp: no named temporary outlives
// the process). It writes them all, then runs the caller's check (commit(check)) with every output readable under
// its own path from its temporary (io::StagedOutputs), and only then renames them over their targets. A new file
// gets the mode a normally created file would get (0666 & ~umask); a replaced file keeps its mode. On any failure
// before the renames (a writer, the check) no target is touched and no temporary is left; a rename that fails
// after others succeeded puts the earlier targets back (they were exchanged with renameat2(RENAME_EXCHANGE), so
// their old content is still at hand).
//
// The rule (docs/reliability.md, "Outputs, signals and messages (issue 37)"): nothing is committed until
// everything that can fail has run. A check that reads back what the run wrote (synthesize's round trip) runs
// inside commit(check); an io::InputError out of it means rollkin's own reader refuses a file rollkin wrote:
// that is InternalError (exit 4 from the CLI), not the user's bad input, and nothing is written.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace rollkin::io {

/// An output that cannot or must not be written. The message names the output and the reason.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A defect of rollkin itself, such as a file it wrote that its own reader refuses. The message says what and
/// that nothing was written.
class InternalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class TemporaryFile;

/// The temporary file a streamed output is written to, through a buffer written out in large blocks.
class OutputSink {
 public:
  static constexpr std::size_t kBlock = std::size_t(1) << 20;  // bytes handed to write(2) at a time
  OutputSink(const OutputSink&) = delete;
  OutputSink& operator=(const OutputSink&) = delete;

  /// Append text here, then call flush_full().
  std::string& buffer() { return buffer_; }
  /// Writes the buffer out once it holds a block or more. Throws OutputError naming the output.
  void flush_full() {
    if (buffer_.size() >= kBlock) flush();
  }

 private:
  friend class OutputSet;
  OutputSink(int fd, std::string what) : fd_(fd), what_(std::move(what)) { buffer_.reserve(kBlock + kBlock / 4); }
  void flush();
  int fd_;
  std::string what_;  // "--csv 'run.csv': error while writing '.run.csv.XXXXXX'" for messages
  std::string buffer_;
};

/// A file a run reads, and what it is in messages: "the scene file 'a.json'", "the contour file 'b.svg' read
/// by scene 'a.json'" ("" : "the input file '<path>' read by this run").
struct InputFile {
  std::string path, what;
};

class OutputSet {
 public:
  /// `inputs`: every file the run read (paths as opened); an output resolving to one is refused.
  explicit OutputSet(std::vector<std::string> inputs = {});
  explicit OutputSet(std::vector<InputFile> inputs);
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  /// Declares an output (`label` names it in messages, e.g. "--csv"); checks its path (see above).
  /// Returns its index for set().
  std::size_t add(const std::string& label, const std::string& path);

  /// The content of output `index`, kept in memory until commit().
  void set(std::size_t index, std::string content);

  /// Output `index` is streamed: commit() calls `write` with the sink of its temporary file.
  void set_writer(std::size_t index, std::function<void(OutputSink&)> write);

  /// Output `index` is not written after all (there is nothing to write): commit() leaves its file alone.
  void omit(std::size_t index);

  /// Writes every output (all must have been set or omitted) all or nothing. Throws OutputError.
  /// `check`, when given, runs after every output is written to its temporary and before any is committed, with
  /// read_input_file reading each output's path from its temporary; whatever it throws leaves nothing written,
  /// and an io::InputError becomes InternalError (a file rollkin wrote that its own reader refuses).
  void commit(const std::function<void()>& check = {});

  /// The file an output path is written to: the path itself, or the final target of a symbolic link.
  static std::string resolve_target(const std::string& path);

 private:
  struct Output {
    std::string label, path, target, content;
    std::function<void(OutputSink&)> writer;  // when set, streams the content instead
    bool has_content = false;
    bool omitted = false;
  };
  void run_check(const std::function<void()>& check);
  std::vector<InputFile> inputs_;
  std::vector<Output> outputs_;
  std::vector<std::unique_ptr<TemporaryFile>> temporaries_;  // one per output until committed (none left after)
};

}  // namespace rollkin::io
