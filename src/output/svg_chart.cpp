#include "rollkin/output/svg_chart.hpp"

#include "rollkin/io/atomic_file.hpp"
#include "rollkin/output/decimate.hpp"
#include "rollkin/io/svg/markup.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace rollkin::io {
namespace {

/// 1, 2, 2.5, 5 or 10 times a power of ten, the smallest not below raw.
double nice_step(double raw) {
  if (!(raw > 0) || !std::isfinite(raw)) return 1.0;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / mag;
  double m = 10;
  for (double c : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (f <= c * (1 + 1e-9)) {
      m = c;
      break;
    }
  return m * mag;
}

/// A usable finite interval: non-finite -> [0, 1]; lo == hi -> widened around the value.
void sanitize(double& lo, double& hi) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) {
    lo = 0;
    hi = 1;
  }
  if (lo > hi) std::swap(lo, hi);
  if (hi - lo <= 1e-12 * std::max(std::abs(lo), std::abs(hi))) {
    const double d = lo == 0 ? 1.0 : 0.1 * std::abs(lo);
    lo -= d;
    hi += d;
  }
}

}  // namespace

Ticks ticks_with_step(double lo, double hi, double step, bool widen) {
  if (!(step > 0) || !std::isfinite(step)) throw std::invalid_argument("ticks_with_step: step must be positive");
  sanitize(lo, hi);
  Ticks t;
  t.step = step;
  const double tol = 1e-9 * step;
  long long k0, k1;
  if (widen) {
    k0 = static_cast<long long>(std::floor((lo + tol) / step));
    k1 = static_cast<long long>(std::ceil((hi - tol) / step));
    if (k1 <= k0) k1 = k0 + 1;
    t.lo = static_cast<double>(k0) * step;
    t.hi = static_cast<double>(k1) * step;
  } else {
    k0 = static_cast<long long>(std::ceil((lo - tol) / step));
    k1 = static_cast<long long>(std::floor((hi + tol) / step));
    t.lo = lo;
    t.hi = hi;
  }
  if (k1 - k0 > 1000) k1 = k0 + 1000;  // absurd steps: keep the document small
  for (long long k = k0; k <= k1; ++k) {
    double v = static_cast<double>(k) * step;
    if (std::abs(v) < tol) v = 0;
    t.values.push_back(v);
  }
  return t;
}

Ticks ticks_in_range(double lo, double hi, int target) {
  sanitize(lo, hi);
  return ticks_with_step(lo, hi, nice_step((hi - lo) / std::max(1, target)), false);
}

Ticks nice_ticks(double lo, double hi, int target) {
  sanitize(lo, hi);
  return ticks_with_step(lo, hi, nice_step((hi - lo) / std::max(1, target)), true);
}

std::string format_tick(double value, double step) {
  if (!std::isfinite(value)) return value != value ? "nan" : (value > 0 ? "inf" : "-inf");
  if (!(step > 0) || !std::isfinite(step)) step = std::abs(value) > 0 ? std::abs(value) : 1;
  if (std::abs(value) < 1e-9 * step) value = 0;
  int decimals = 0;
  while (decimals < 12) {
    const double scaled = step * std::pow(10.0, decimals);
    if (std::abs(scaled - std::round(scaled)) <= 1e-6 * scaled) break;
    ++decimals;
  }
  char buf[48];
  if (decimals > 6 || std::abs(value) >= 1e9) {
    std::snprintf(buf, sizeof buf, "%.6g", value);
  } else {
    std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  }
  std::string s = buf;
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);  // "-0.0" -> "0.0"
  return s;
}

// ---- SvgChart ------------------------------------------------------------------------------------------

SvgChart::SvgChart(int width_px, int height_px) : width_(std::max(width_px, 160)), height_(std::max(height_px, 120)) {}

SvgChart& SvgChart::set_title(std::string title) {
  title_ = std::move(title);
  return *this;
}
SvgChart& SvgChart::set_x_label(std::string label) {
  x_label_ = std::move(label);
  return *this;
}
SvgChart& SvgChart::set_y_label(std::string label) {
  y_label_ = std::move(label);
  return *this;
}
namespace {

/// A fixed axis range: finite lo <= hi, widened around the value when lo == hi (a constant), as the fitted
/// ranges are.
void fix_range(const char* setter, double lo, double hi, bool& fixed, double& to_lo, double& to_hi) {
  if (!(lo <= hi) || !std::isfinite(lo) || !std::isfinite(hi))
    throw std::invalid_argument(std::string("SvgChart::") + setter + ": need finite lo <= hi");
  sanitize(lo, hi);
  fixed = true;
  to_lo = lo;
  to_hi = hi;
}

}  // namespace

SvgChart& SvgChart::set_x_range(double lo, double hi) {
  fix_range("set_x_range", lo, hi, x_fixed_, x_lo_, x_hi_);
  return *this;
}
SvgChart& SvgChart::set_y_range(double lo, double hi) {
  fix_range("set_y_range", lo, hi, y_fixed_, y_lo_, y_hi_);
  return *this;
}
SvgChart& SvgChart::set_tick_target(int x_intervals, int y_intervals) {
  x_target_ = std::max(1, x_intervals);
  y_target_ = std::max(1, y_intervals);
  return *this;
}
SvgChart& SvgChart::set_tick_steps(double x_step, double y_step) {
  if (!(x_step >= 0) || !(y_step >= 0) || !std::isfinite(x_step) || !std::isfinite(y_step))
    throw std::invalid_argument("SvgChart::set_tick_steps: steps must be finite and >= 0");
  x_step_ = x_step;
  y_step_ = y_step;
  return *this;
}
SvgChart& SvgChart::set_legend(LegendPosition position) {
  legend_ = position;
  return *this;
}
SvgChart& SvgChart::set_grid(bool on) {
  grid_ = on;
  return *this;
}

SvgChart& SvgChart::add_series(ChartSeries series) {
  if (series.x.size() != series.y.size())
    throw std::invalid_argument("SvgChart::add_series: series '" + series.name + "' has " +
                                std::to_string(series.x.size()) + " x values and " +
                                std::to_string(series.y.size()) + " y values");
  series_.push_back(std::move(series));
  return *this;
}

SvgChart& SvgChart::add_series(std::string name, std::vector<double> x, std::vector<double> y, std::string color) {
  ChartSeries s;
  s.name = std::move(name);
  s.x = std::move(x);
  s.y = std::move(y);
  s.color = std::move(color);
  return add_series(std::move(s));
}

namespace {
void data_range(const std::vector<ChartSeries>& series, bool use_x, double& lo, double& hi) {
  lo = std::numeric_limits<double>::infinity();
  hi = -lo;
  for (const auto& s : series)
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      const double v = use_x ? s.x[i] : s.y[i];
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  if (!(lo <= hi)) {
    lo = 0;
    hi = 1;
  }
}
}  // namespace

namespace {
Ticks axis_ticks(const std::vector<ChartSeries>& series, bool use_x, bool fixed, double flo, double fhi, double step,
                 int target) {
  double lo = flo, hi = fhi;
  if (!fixed) data_range(series, use_x, lo, hi);
  if (step > 0) return ticks_with_step(lo, hi, step, !fixed);
  return fixed ? ticks_in_range(lo, hi, target) : nice_ticks(lo, hi, target);
}
}  // namespace

Ticks SvgChart::x_ticks() const { return axis_ticks(series_, true, x_fixed_, x_lo_, x_hi_, x_step_, x_target_); }
Ticks SvgChart::y_ticks() const { return axis_ticks(series_, false, y_fixed_, y_lo_, y_hi_, y_step_, y_target_); }

std::string SvgChart::to_svg() const {
  const Ticks xt = x_ticks(), yt = y_ticks();
  const double font = 12, small = 11;

  // Legend geometry (estimated text width: 0.6 em per character).
  const bool legend = legend_ != LegendPosition::None && !series_.empty();
  std::size_t longest = 0;
  for (const auto& s : series_) longest = std::max(longest, s.name.size());
  const double legend_w = 36 + 0.6 * small * static_cast<double>(longest) + 10;
  const double legend_row = small + 6;
  const double legend_h = legend_row * static_cast<double>(series_.size()) + 8;

  // Plot area.
  std::size_t ylab_chars = 0;
  for (double v : yt.values) ylab_chars = std::max(ylab_chars, format_tick(v, yt.step).size());
  const double left = 14 + (y_label_.empty() ? 0 : font + 8) + 0.6 * small * static_cast<double>(ylab_chars) + 8;
  const double right = 16 + ((legend && legend_ == LegendPosition::Outside) ? legend_w + 12 : 0);
  const double top = title_.empty() ? 16 : 16 + font + 14;
  const double bottom = 10 + small + 8 + (x_label_.empty() ? 0 : font + 10) + 6;
  const double pw = std::max(20.0, width_ - left - right), ph = std::max(20.0, height_ - top - bottom);
  auto X = [&](double x) { return left + (x - xt.lo) / (xt.hi - xt.lo) * pw; };
  auto Y = [&](double y) { return top + ph - (y - yt.lo) / (yt.hi - yt.lo) * ph; };

  // The clip id must be unique in a document that nests several charts: derive it from the title.
  const std::string clip_id = "plot-area-" + std::to_string(std::hash<std::string>{}(title_) % 1000000007u);
  std::ostringstream o;
  o << svg_document_open(width_, height_);
  o << "<title>" << xml_escape(title_.empty() ? "chart" : title_) << "</title>\n";
  o << "<defs><clipPath id=\"" << clip_id << "\"><rect x=\"" << svg_pixel(left) << "\" y=\"" << svg_pixel(top) << "\" width=\"" << svg_pixel(pw)
    << "\" height=\"" << svg_pixel(ph) << "\"/></clipPath></defs>\n";
  o << "<rect x=\"0\" y=\"0\" width=\"" << width_ << "\" height=\"" << height_ << "\" fill=\"#ffffff\"/>\n";

  // Grid and ticks.
  o << "<g class=\"axes\" font-size=\"" << svg_size(small) << "\" fill=\"#000000\">\n";
  for (double v : xt.values) {
    const double x = X(v);
    if (grid_)
      o << "<line x1=\"" << svg_pixel(x) << "\" y1=\"" << svg_pixel(top) << "\" x2=\"" << svg_pixel(x) << "\" y2=\"" << svg_pixel(top + ph)
        << "\" stroke=\"#dddddd\" stroke-width=\"1\"/>\n";
    o << "<line x1=\"" << svg_pixel(x) << "\" y1=\"" << svg_pixel(top + ph) << "\" x2=\"" << svg_pixel(x) << "\" y2=\"" << svg_pixel(top + ph + 5)
      << "\" stroke=\"#000000\" stroke-width=\"1\"/>\n";
    o << "<text x=\"" << svg_pixel(x) << "\" y=\"" << svg_pixel(top + ph + 8 + small) << "\" text-anchor=\"middle\">"
      << xml_escape(format_tick(v, xt.step)) << "</text>\n";
  }
  for (double v : yt.values) {
    const double y = Y(v);
    if (grid_)
      o << "<line x1=\"" << svg_pixel(left) << "\" y1=\"" << svg_pixel(y) << "\" x2=\"" << svg_pixel(left + pw) << "\" y2=\"" << svg_pixel(y)
        << "\" stroke=\"#dddddd\" stroke-width=\"1\"/>\n";
    o << "<line x1=\"" << svg_pixel(left - 5) << "\" y1=\"" << svg_pixel(y) << "\" x2=\"" << svg_pixel(left) << "\" y2=\"" << svg_pixel(y)
      << "\" stroke=\"#000000\" stroke-width=\"1\"/>\n";
    o << "<text x=\"" << svg_pixel(left - 8) << "\" y=\"" << svg_pixel(y + small * 0.35) << "\" text-anchor=\"end\">"
      << xml_escape(format_tick(v, yt.step)) << "</text>\n";
  }
  o << "<rect x=\"" << svg_pixel(left) << "\" y=\"" << svg_pixel(top) << "\" width=\"" << svg_pixel(pw) << "\" height=\"" << svg_pixel(ph)
    << "\" fill=\"none\" stroke=\"#000000\" stroke-width=\"1\"/>\n";
  o << "</g>\n";

  // Title and axis labels.
  if (!title_.empty())
    o << "<text class=\"title\" x=\"" << svg_pixel(left + pw / 2) << "\" y=\"" << svg_pixel(16 + font) << "\" font-size=\""
      << svg_size(font + 2) << "\" font-weight=\"bold\" text-anchor=\"middle\">" << xml_escape(title_) << "</text>\n";
  if (!x_label_.empty())
    o << "<text class=\"x-label\" x=\"" << svg_pixel(left + pw / 2) << "\" y=\"" << svg_pixel(height_ - 10) << "\" font-size=\""
      << svg_size(font) << "\" text-anchor=\"middle\">" << xml_escape(x_label_) << "</text>\n";
  if (!y_label_.empty()) {
    const double cx = 14 + font * 0.8, cy = top + ph / 2;
    o << "<text class=\"y-label\" x=\"" << svg_pixel(cx) << "\" y=\"" << svg_pixel(cy) << "\" font-size=\"" << svg_size(font)
      << "\" text-anchor=\"middle\" transform=\"rotate(-90 " << svg_pixel(cx) << " " << svg_pixel(cy) << ")\">"
      << xml_escape(y_label_) << "</text>\n";
  }

  // Series, clipped to the plot area.
  o << "<g class=\"data\" clip-path=\"url(#" << clip_id << ")\">\n";
  for (std::size_t k = 0; k < series_.size(); ++k) {
    const auto& s = series_[k];
    const std::string color = s.color.empty() ? palette_color(k) : s.color;
    o << "<g class=\"series\" data-name=\"" << xml_escape(s.name) << "\" stroke=\"" << xml_escape(color)
      << "\" stroke-width=\"" << svg_size(s.stroke_width) << "\" fill=\"none\" stroke-linejoin=\"round\"";
    if (!s.dash.empty()) o << " stroke-dasharray=\"" << xml_escape(s.dash) << "\"";
    o << ">\n";
    // The points a pixel column can show (output/decimate.hpp): a series of any length draws in bounded size.
    SeriesReducer reduced(xt.lo, xt.hi, static_cast<int>(std::ceil(pw)));
    for (std::size_t i = 0; i < s.x.size(); ++i) reduced.add(s.x[i], s.y[i]);
    reduced.finish();
    const std::vector<double>&sx = reduced.x(), &sy = reduced.y();
    const auto runs = finite_runs(sx.size(), [&](std::size_t i) { return std::isfinite(sx[i]) && std::isfinite(sy[i]); });
    for (const auto& r : runs) {
      if (r.second - r.first == 1) {  // isolated point: a dot, since a one-point polyline is invisible
        o << "<circle cx=\"" << svg_pixel(X(sx[r.first])) << "\" cy=\"" << svg_pixel(Y(sy[r.first])) << "\" r=\""
          << svg_size(s.stroke_width) << "\" fill=\"" << xml_escape(color) << "\" stroke=\"none\"/>\n";
        continue;
      }
      o << "<polyline points=\"";
      for (std::size_t i = r.first; i < r.second; ++i) {
        if (i > r.first) o << ' ';
        o << svg_pixel(X(sx[i])) << ',' << svg_pixel(Y(sy[i]));
      }
      o << "\"/>\n";
    }
    if (s.markers)
      for (const auto& r : runs)
        for (std::size_t i = r.first; i < r.second; ++i)
          o << "<circle class=\"marker\" cx=\"" << svg_pixel(X(sx[i])) << "\" cy=\"" << svg_pixel(Y(sy[i])) << "\" r=\""
            << svg_size(2 * s.stroke_width) << "\" fill=\"#ffffff\" stroke-dasharray=\"none\"/>\n";
    o << "</g>\n";
  }
  o << "</g>\n";

  // Legend.
  if (legend) {
    double lx = left + pw - legend_w - 8, ly = top + 8;
    switch (legend_) {
      case LegendPosition::TopLeft: lx = left + 8; break;
      case LegendPosition::BottomLeft: lx = left + 8; ly = top + ph - legend_h - 8; break;
      case LegendPosition::BottomRight: ly = top + ph - legend_h - 8; break;
      case LegendPosition::Outside: lx = left + pw + 12; break;
      default: break;
    }
    o << "<g class=\"legend\" font-size=\"" << svg_size(small) << "\">\n";
    o << "<rect x=\"" << svg_pixel(lx) << "\" y=\"" << svg_pixel(ly) << "\" width=\"" << svg_pixel(legend_w) << "\" height=\"" << svg_pixel(legend_h)
      << "\" fill=\"#ffffff\" fill-opacity=\"0.85\" stroke=\"#999999\" stroke-width=\"0.8\"/>\n";
    for (std::size_t k = 0; k < series_.size(); ++k) {
      const auto& s = series_[k];
      const std::string color = s.color.empty() ? palette_color(k) : s.color;
      const double cy = ly + 4 + legend_row * (static_cast<double>(k) + 0.5);
      o << "<line x1=\"" << svg_pixel(lx + 6) << "\" y1=\"" << svg_pixel(cy) << "\" x2=\"" << svg_pixel(lx + 30) << "\" y2=\"" << svg_pixel(cy)
        << "\" stroke=\"" << xml_escape(color) << "\" stroke-width=\"" << svg_size(s.stroke_width) << "\"";
      if (!s.dash.empty()) o << " stroke-dasharray=\"" << xml_escape(s.dash) << "\"";
      o << "/>\n";
      o << "<text x=\"" << svg_pixel(lx + 36) << "\" y=\"" << svg_pixel(cy + small * 0.35) << "\">" << xml_escape(s.name)
        << "</text>\n";
    }
    o << "</g>\n";
  }
  o << "</svg>\n";
  return o.str();
}

void SvgChart::write(const std::string& path) const { write_file_atomic(path, to_svg()); }

}  // namespace rollkin::io
