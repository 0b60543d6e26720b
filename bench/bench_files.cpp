// rollkin_bench, its output files (bench/main.cpp --csv, --svg; docs/benchmark.md).
#include "profile_bench.hpp"

#include "rollkin/io/atomic_file.hpp"
#include "rollkin/io/csv.hpp"
#include "rollkin/output/svg_chart.hpp"
#include "rollkin/io/svg/markup.hpp"

#include <regex>
#include <sstream>

namespace rollkin::bench::profiles {

void write_csv(const std::string& path, const std::vector<Row>& rows, const std::vector<Saving>& savings) {
  std::ostringstream o;
  o << "section,case,group,tag,scene,points,prep_ms,table_ms,profile_bytes,bytes_per_point,rss_bytes_per_point,"
       "peak_rss_bytes,us_per_pose,evals_per_pose,max_err_rad,solved,total,target,verdict,note,baseline,baseline_value,"
       "value,unit,ratio\n";
  auto d = [](double v) { return io::format_double(v); };
  for (const Row& r : rows)
    o << "case," << io::csv_field(r.name) << ',' << io::csv_field(r.group) << ',' << io::csv_field(r.tag) << ','
      << r.scene << ',' << r.points << ',' << d(r.prep_ms) << ',' << d(r.table_ms) << ',' << d(r.bytes) << ','
      << d(r.bytes_per_point) << ',' << d(r.rss_per_point) << ',' << d(r.peak_bytes) << ',' << d(r.us_pose) << ','
      << d(r.evals_pose) << ',' << d(r.max_err) << ',' << r.solved << ',' << r.total << ',' << r.target << ','
      << io::csv_field(r.verdict) << ',' << io::csv_field(r.note) << ",,,,,\n";
  for (const Saving& s : savings)
    o << "saving," << io::csv_field(s.what) << ",," << io::csv_field(s.alt_name) << std::string(16, ',')
      << io::csv_field(s.note) << ','
      << io::csv_field(s.base_name) << ',' << d(s.base) << ',' << d(s.alt) << ',' << io::csv_field(s.unit) << ','
      << d(s.ratio()) << '\n';
  io::write_file_atomic(path, o.str());
}

/// log10(time per pose) against log10(max error), one series per group; every marker labelled with its case
/// tag (the chart draws the markers, the labels are added at the markers' pixel positions).
void write_svg(const std::string& path, const std::vector<Row>& rows, const std::string& subtitle) {
  io::SvgChart chart(1100, 640);
  chart.set_title("rollkin: time per pose against max angle error (" + subtitle + ")")
      .set_x_label("log10(time per pose / us)")
      .set_y_label("log10(max link-angle error / rad), vs MPFR 50 digits")
      .set_legend(io::LegendPosition::Outside);
  std::vector<std::string> groups;
  std::map<std::string, std::vector<const Row*>> by_group;
  for (const Row& r : rows) {
    if (std::isnan(r.us_pose) || std::isnan(r.max_err) || r.solved < r.total || r.total == 0) continue;
    if (!by_group.count(r.group)) groups.push_back(r.group);
    by_group[r.group].push_back(&r);
  }
  std::vector<std::vector<std::string>> labels;
  for (const std::string& g : groups) {
    io::ChartSeries s;
    s.name = g;
    s.markers = true;
    s.stroke_width = 1.4;
    std::vector<std::string> tags;
    for (const Row* r : by_group[g]) {
      s.x.push_back(std::log10(r->us_pose));
      s.y.push_back(std::log10(std::max(r->max_err, 1e-17)));
      tags.push_back(r->tag);
    }
    if (g.find("sampled") == std::string::npos) s.dash = "2 4";  // unrelated variants: no curve implied
    chart.add_series(s);
    labels.push_back(tags);
  }
  std::string svg = chart.to_svg();
  // Label the markers: the k-th series <g> holds its markers in order.
  std::string out;
  std::size_t pos = 0, series = 0;
  const std::regex marker("<circle class=\"marker\" cx=\"([-0-9.]+)\" cy=\"([-0-9.]+)\"");
  std::string labels_svg = "<g class=\"labels\" font-size=\"10\" fill=\"#333333\">\n";
  while (true) {
    const std::size_t g = svg.find("<g class=\"series\"", pos);
    if (g == std::string::npos || series >= labels.size()) break;
    const std::size_t end = svg.find("</g>", g);
    const std::string block = svg.substr(g, end - g);
    std::size_t k = 0;
    for (auto it = std::sregex_iterator(block.begin(), block.end(), marker); it != std::sregex_iterator() && k < labels[series].size();
         ++it, ++k)
      labels_svg += "<text x=\"" + fmt("%.2f", std::stod((*it)[1]) + 5) + "\" y=\"" + fmt("%.2f", std::stod((*it)[2]) - 4) +
                    "\">" + io::xml_escape(labels[series][k]) + "</text>\n";
    pos = end;
    ++series;
  }
  labels_svg += "</g>\n";
  const std::size_t close = svg.rfind("</svg>");
  svg.insert(close, labels_svg);
  io::write_file_atomic(path, svg);
}

}  // namespace rollkin::bench::profiles
