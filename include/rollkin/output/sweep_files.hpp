// The files a solved sweep is written as, keyed by format like the contour readers: one table
// (src/output/sweep_files.cpp) of csv, plot, draw and animate. The command line (`rollkin solve --csv F --plot F
// --draw F --animate F`) declares its options from it and the Python module (`Scene.write(csv=F, plot=F, ...)`)
// its keywords; both request and write the files through SweepFiles, so a new format is one writer and one
// line of the table.
//
//   io::OutputSet set(inputs);                        // the files the run reads: never written over
//   output::SweepFiles files(set);
//   files.request("csv", "out.csv", "--csv");         // checked against the inputs and the other outputs now
//   ... solve ...
//   files.write(io::SweepOutput{scene, sweep, rows, values}, {});
//   set.commit();                                     // all or nothing
#pragma once

#include "rollkin/io/output_set.hpp"
#include "rollkin/output/sweep_table.hpp"

#include <string>
#include <utility>
#include <vector>

namespace rollkin::output {

/// What the writers may be asked besides the sweep: the CSV's rate columns and its formatting threads
/// (io::write_sweep_csv; 0: one per core). The analysis columns and charts are asked by SweepOutput::analysis.
struct WriteOptions {
  bool rates = false;
  int threads = 1;
};

/// One format: its name (the CLI option without "--", the Python keyword), what the file holds (the option's
/// help) and its writer, which streams the file into the sink at commit.
struct SweepFormat {
  const char* name;
  const char* help;
  void (*write)(const io::SweepOutput&, const WriteOptions&, io::OutputSink&);
};

/// Every format, in the order their options are listed.
const std::vector<SweepFormat>& sweep_formats();
/// The format named `name`; std::invalid_argument naming the known ones for any other.
const SweepFormat& sweep_format(const std::string& name);

/// The requested files of one sweep in an OutputSet.
class SweepFiles {
 public:
  explicit SweepFiles(io::OutputSet& set) : set_(set) {}
  /// Adds the file of format `format` (a name of sweep_formats(); std::invalid_argument otherwise) at `path`,
  /// named `label` in messages, to the set: OutputError now when it is an input or another output.
  void request(const std::string& format, const std::string& path, const std::string& label);
  bool empty() const { return files_.empty(); }
  /// Gives every requested file its writer over `out` (which must live until the set's commit).
  void write(const io::SweepOutput& out, const WriteOptions& options);

 private:
  io::OutputSet& set_;
  std::vector<std::pair<std::size_t, const SweepFormat*>> files_;  // index in the set, format
};

}  // namespace rollkin::output
