// The formats of a solved sweep's files and their requests (rollkin/output/sweep_files.hpp).
#include "rollkin/output/sweep_files.hpp"

#include "rollkin/output/animation.hpp"
#include "rollkin/output/charts.hpp"
#include "rollkin/output/drawing.hpp"

#include <stdexcept>

namespace rollkin::output {
namespace {

/// A writer of a whole text built in memory (the charts, the drawing, the page: their size does not grow
/// with the number of poses).
template <std::string (*text)(const SweepOutput&)>
void write_text(const SweepOutput& out, const WriteOptions&, io::OutputSink& sink) {
  sink.buffer() += text(out);
}

void write_csv(const SweepOutput& out, const WriteOptions& o, io::OutputSink& sink) {
  io::write_sweep_csv(out, o.rates, sink, o.threads);
}

}  // namespace

const std::vector<SweepFormat>& sweep_formats() {
  static const std::vector<SweepFormat> formats{
      {"csv", "one row per input value: input, pair variables, link poses, residual, status", &write_csv},
      {"plot", "SVG chart of the pair variables against the input", &write_text<plot_svg>},
      {"draw", "SVG drawing of the mechanism at four poses across the solved range, one panel each", &write_text<draw_svg>},
      {"animate", "self-contained HTML page animating the mechanism over the solved poses (play/pause, slider)",
       &write_text<animation_html>},
  };
  return formats;
}

const SweepFormat& sweep_format(const std::string& name) {
  std::string known;
  for (const SweepFormat& f : sweep_formats()) {
    if (name == f.name) return f;
    known += std::string(known.empty() ? "" : ", ") + f.name;
  }
  throw std::invalid_argument("no output format '" + name + "' (the formats are " + known + ")");
}

void SweepFiles::request(const std::string& format, const std::string& path, const std::string& label) {
  const SweepFormat& f = sweep_format(format);
  files_.emplace_back(set_.add(label, path), &f);
}

void SweepFiles::write(const io::SweepOutput& out, const WriteOptions& options) {
  for (const auto& [index, format] : files_)
    set_.set_writer(index, [&out, options, write = format->write](io::OutputSink& sink) { write(out, options, sink); });
}

}  // namespace rollkin::output
