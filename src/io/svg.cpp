#include "rollkin/io/svg.hpp"

#include "rollkin/io/atomic_file.hpp"
#include "rollkin/io/decimate.hpp"
#include "rollkin/io/format.hpp"
#include "rollkin/io/input_error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <functional>
#include <sstream>
#include <stdexcept>

namespace rollkin::io {

// ---- helpers -------------------------------------------------------------------------------------------

const std::vector<std::string>& default_palette() {
  static const std::vector<std::string> p = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                                             "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
  return p;
}

const std::string& palette_color(std::size_t i) { return default_palette()[i % default_palette().size()]; }

namespace {

/// Length of the valid UTF-8 character at text[i] that XML 1.0 allows (no U+FFFE, U+FFFF, surrogates),
/// or 0 if the bytes there are not one.
std::size_t xml_char_length(const std::string& text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return k < text.size() ? static_cast<unsigned char>(text[k]) : 0u; };
  const unsigned c = byte(i);
  const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
  if (n == 0) return 0;
  unsigned long cp = n == 1 ? c : n == 2 ? (c & 0x1f) : n == 3 ? (c & 0x0f) : (c & 0x07);
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xc0) != 0x80) return 0;
    cp = (cp << 6) | (byte(i + k) & 0x3f);
  }
  const unsigned long smallest[] = {0, 0, 0x80, 0x800, 0x10000};
  if (cp < smallest[n] || cp > 0x10ffff || (cp >= 0xd800 && cp <= 0xdfff) || cp == 0xfffe || cp == 0xffff) return 0;
  return n;
}

}  // namespace

std::string xml_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    const std::size_t n = xml_char_length(text, i);
    // Control characters (not allowed in XML 1.0, even as references) and bytes that are not UTF-8 are
    // shown as escapes (\n, \x01, \xff) so that the document stays well-formed XML.
    if (n == 0 || static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      out += escaped_byte(static_cast<unsigned char>(c));
      ++i;
      continue;
    }
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out.append(text, i, n);
    }
    i += n;
  }
  return out;
}

namespace {

/// Pixel coordinate with two decimals; huge values are clamped so the document stays sane.
std::string px(double v) {
  if (!std::isfinite(v)) v = 0;
  v = std::clamp(v, -1e7, 1e7);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  std::string s = buf;
  if (s == "-0.00") s = "0.00";
  return s;
}

/// Sizes and widths of the drawing: 4 significant digits.
std::string num(double v) { return format_number(v, 4); }

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

std::string style_stroke(const Stroke& s) {
  std::string out = " stroke=\"" + xml_escape(s.color) + "\" stroke-width=\"" + num(s.width) + "\"";
  if (s.opacity < 1) out += " stroke-opacity=\"" + num(std::max(0.0, s.opacity)) + "\"";
  if (!s.dash.empty()) out += " stroke-dasharray=\"" + xml_escape(s.dash) + "\"";
  return out;
}

std::string style_fill(const Fill& f) {
  if (f.color.empty()) return " fill=\"none\"";
  std::string out = " fill=\"" + xml_escape(f.color) + "\"";
  if (f.opacity < 1) out += " fill-opacity=\"" + num(std::max(0.0, f.opacity)) + "\"";
  return out;
}

/// Splits a sequence of points into runs of finite points.
template <class Finite> std::vector<std::pair<std::size_t, std::size_t>> finite_runs(std::size_t n, Finite finite) {
  std::vector<std::pair<std::size_t, std::size_t>> runs;  // [begin, end)
  std::size_t i = 0;
  while (i < n) {
    while (i < n && !finite(i)) ++i;
    const std::size_t b = i;
    while (i < n && finite(i)) ++i;
    if (i > b) runs.emplace_back(b, i);
  }
  return runs;
}

const char* kHeader = "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n";

std::string svg_open(int w, int h) {
  return std::string(kHeader) + "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" +
         std::to_string(w) + "\" height=\"" + std::to_string(h) + "\" viewBox=\"0 0 " + std::to_string(w) + " " +
         std::to_string(h) + "\" font-family=\"Helvetica, Arial, sans-serif\">\n";
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
SvgChart& SvgChart::set_x_range(double lo, double hi) {
  if (!(lo <= hi) || !std::isfinite(lo) || !std::isfinite(hi))
    throw std::invalid_argument("SvgChart::set_x_range: need finite lo <= hi");
  sanitize(lo, hi);  // lo == hi (a constant): widened around the value, as the fitted ranges are
  x_fixed_ = true;
  x_lo_ = lo;
  x_hi_ = hi;
  return *this;
}
SvgChart& SvgChart::set_y_range(double lo, double hi) {
  if (!(lo <= hi) || !std::isfinite(lo) || !std::isfinite(hi))
    throw std::invalid_argument("SvgChart::set_y_range: need finite lo <= hi");
  sanitize(lo, hi);  // lo == hi (a constant): widened around the value, as the fitted ranges are
  y_fixed_ = true;
  y_lo_ = lo;
  y_hi_ = hi;
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
  o << svg_open(width_, height_);
  o << "<title>" << xml_escape(title_.empty() ? "chart" : title_) << "</title>\n";
  o << "<defs><clipPath id=\"" << clip_id << "\"><rect x=\"" << px(left) << "\" y=\"" << px(top) << "\" width=\"" << px(pw)
    << "\" height=\"" << px(ph) << "\"/></clipPath></defs>\n";
  o << "<rect x=\"0\" y=\"0\" width=\"" << width_ << "\" height=\"" << height_ << "\" fill=\"#ffffff\"/>\n";

  // Grid and ticks.
  o << "<g class=\"axes\" font-size=\"" << num(small) << "\" fill=\"#000000\">\n";
  for (double v : xt.values) {
    const double x = X(v);
    if (grid_)
      o << "<line x1=\"" << px(x) << "\" y1=\"" << px(top) << "\" x2=\"" << px(x) << "\" y2=\"" << px(top + ph)
        << "\" stroke=\"#dddddd\" stroke-width=\"1\"/>\n";
    o << "<line x1=\"" << px(x) << "\" y1=\"" << px(top + ph) << "\" x2=\"" << px(x) << "\" y2=\"" << px(top + ph + 5)
      << "\" stroke=\"#000000\" stroke-width=\"1\"/>\n";
    o << "<text x=\"" << px(x) << "\" y=\"" << px(top + ph + 8 + small) << "\" text-anchor=\"middle\">"
      << xml_escape(format_tick(v, xt.step)) << "</text>\n";
  }
  for (double v : yt.values) {
    const double y = Y(v);
    if (grid_)
      o << "<line x1=\"" << px(left) << "\" y1=\"" << px(y) << "\" x2=\"" << px(left + pw) << "\" y2=\"" << px(y)
        << "\" stroke=\"#dddddd\" stroke-width=\"1\"/>\n";
    o << "<line x1=\"" << px(left - 5) << "\" y1=\"" << px(y) << "\" x2=\"" << px(left) << "\" y2=\"" << px(y)
      << "\" stroke=\"#000000\" stroke-width=\"1\"/>\n";
    o << "<text x=\"" << px(left - 8) << "\" y=\"" << px(y + small * 0.35) << "\" text-anchor=\"end\">"
      << xml_escape(format_tick(v, yt.step)) << "</text>\n";
  }
  o << "<rect x=\"" << px(left) << "\" y=\"" << px(top) << "\" width=\"" << px(pw) << "\" height=\"" << px(ph)
    << "\" fill=\"none\" stroke=\"#000000\" stroke-width=\"1\"/>\n";
  o << "</g>\n";

  // Title and axis labels.
  if (!title_.empty())
    o << "<text class=\"title\" x=\"" << px(left + pw / 2) << "\" y=\"" << px(16 + font) << "\" font-size=\""
      << num(font + 2) << "\" font-weight=\"bold\" text-anchor=\"middle\">" << xml_escape(title_) << "</text>\n";
  if (!x_label_.empty())
    o << "<text class=\"x-label\" x=\"" << px(left + pw / 2) << "\" y=\"" << px(height_ - 10) << "\" font-size=\""
      << num(font) << "\" text-anchor=\"middle\">" << xml_escape(x_label_) << "</text>\n";
  if (!y_label_.empty()) {
    const double cx = 14 + font * 0.8, cy = top + ph / 2;
    o << "<text class=\"y-label\" x=\"" << px(cx) << "\" y=\"" << px(cy) << "\" font-size=\"" << num(font)
      << "\" text-anchor=\"middle\" transform=\"rotate(-90 " << px(cx) << " " << px(cy) << ")\">"
      << xml_escape(y_label_) << "</text>\n";
  }

  // Series, clipped to the plot area.
  o << "<g class=\"data\" clip-path=\"url(#" << clip_id << ")\">\n";
  for (std::size_t k = 0; k < series_.size(); ++k) {
    const auto& s = series_[k];
    const std::string color = s.color.empty() ? palette_color(k) : s.color;
    o << "<g class=\"series\" data-name=\"" << xml_escape(s.name) << "\" stroke=\"" << xml_escape(color)
      << "\" stroke-width=\"" << num(s.stroke_width) << "\" fill=\"none\" stroke-linejoin=\"round\"";
    if (!s.dash.empty()) o << " stroke-dasharray=\"" << xml_escape(s.dash) << "\"";
    o << ">\n";
    // The points a pixel column can show (io/decimate.hpp): a series of any length draws in bounded size.
    SeriesReducer reduced(xt.lo, xt.hi, static_cast<int>(std::ceil(pw)));
    for (std::size_t i = 0; i < s.x.size(); ++i) reduced.add(s.x[i], s.y[i]);
    reduced.finish();
    const std::vector<double>&sx = reduced.x(), &sy = reduced.y();
    const auto runs = finite_runs(sx.size(), [&](std::size_t i) { return std::isfinite(sx[i]) && std::isfinite(sy[i]); });
    for (const auto& r : runs) {
      if (r.second - r.first == 1) {  // isolated point: a dot, since a one-point polyline is invisible
        o << "<circle cx=\"" << px(X(sx[r.first])) << "\" cy=\"" << px(Y(sy[r.first])) << "\" r=\""
          << num(s.stroke_width) << "\" fill=\"" << xml_escape(color) << "\" stroke=\"none\"/>\n";
        continue;
      }
      o << "<polyline points=\"";
      for (std::size_t i = r.first; i < r.second; ++i) {
        if (i > r.first) o << ' ';
        o << px(X(sx[i])) << ',' << px(Y(sy[i]));
      }
      o << "\"/>\n";
    }
    if (s.markers)
      for (const auto& r : runs)
        for (std::size_t i = r.first; i < r.second; ++i)
          o << "<circle class=\"marker\" cx=\"" << px(X(sx[i])) << "\" cy=\"" << px(Y(sy[i])) << "\" r=\""
            << num(2 * s.stroke_width) << "\" fill=\"#ffffff\" stroke-dasharray=\"none\"/>\n";
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
    o << "<g class=\"legend\" font-size=\"" << num(small) << "\">\n";
    o << "<rect x=\"" << px(lx) << "\" y=\"" << px(ly) << "\" width=\"" << px(legend_w) << "\" height=\"" << px(legend_h)
      << "\" fill=\"#ffffff\" fill-opacity=\"0.85\" stroke=\"#999999\" stroke-width=\"0.8\"/>\n";
    for (std::size_t k = 0; k < series_.size(); ++k) {
      const auto& s = series_[k];
      const std::string color = s.color.empty() ? palette_color(k) : s.color;
      const double cy = ly + 4 + legend_row * (static_cast<double>(k) + 0.5);
      o << "<line x1=\"" << px(lx + 6) << "\" y1=\"" << px(cy) << "\" x2=\"" << px(lx + 30) << "\" y2=\"" << px(cy)
        << "\" stroke=\"" << xml_escape(color) << "\" stroke-width=\"" << num(s.stroke_width) << "\"";
      if (!s.dash.empty()) o << " stroke-dasharray=\"" << xml_escape(s.dash) << "\"";
      o << "/>\n";
      o << "<text x=\"" << px(lx + 36) << "\" y=\"" << px(cy + small * 0.35) << "\">" << xml_escape(s.name)
        << "</text>\n";
    }
    o << "</g>\n";
  }
  o << "</svg>\n";
  return o.str();
}

void SvgChart::write(const std::string& path) const { write_file_atomic(path, to_svg()); }

// ---- SvgDrawing ----------------------------------------------------------------------------------------

SvgDrawing::SvgDrawing(int width_px, int height_px, double margin_px)
    : width_(std::max(width_px, 16)), height_(std::max(height_px, 16)), margin_(std::max(0.0, margin_px)) {
  margin_ = std::min(margin_, 0.45 * std::min(width_, height_));
}

SvgDrawing& SvgDrawing::set_title(std::string title) {
  title_ = std::move(title);
  return *this;
}
SvgDrawing& SvgDrawing::set_background(std::string color) {
  background_ = std::move(color);
  return *this;
}
namespace {

/// A world box made drawable (xmin, ymin, xmax, ymax): an extent that is zero or round-off (1e-12) relative to
/// the box's size, e.g. a straight line parallel to an axis, gets 5% of the other extent on each side; a point
/// (both extents zero) gets 10% of its largest coordinate, at least 1, on every side. The larger extent keeps
/// setting the scale.
Eigen::Vector4d drawable_box(Eigen::Vector4d b) {
  const double w = b[2] - b[0], h = b[3] - b[1];
  const double size = std::max(w, h), magnitude = b.cwiseAbs().maxCoeff();
  const double round_off = 1e-12 * std::max(size, magnitude);
  if (size <= round_off) {
    const double pad = std::max(1.0, 0.1 * magnitude);
    return b + Eigen::Vector4d(-pad, -pad, pad, pad);
  }
  if (w <= round_off) b += Eigen::Vector4d(-0.05 * size, 0, 0.05 * size, 0);
  if (h <= round_off) b += Eigen::Vector4d(0, -0.05 * size, 0, 0.05 * size);
  return b;
}

}  // namespace

SvgDrawing& SvgDrawing::set_world_box(double xmin, double ymin, double xmax, double ymax) {
  if (!(xmin <= xmax) || !(ymin <= ymax) || !std::isfinite(xmin) || !std::isfinite(xmax) || !std::isfinite(ymin) ||
      !std::isfinite(ymax))
    throw std::invalid_argument("SvgDrawing::set_world_box: need finite xmin <= xmax and ymin <= ymax");
  fixed_box_ = true;
  box_ = drawable_box(Eigen::Vector4d(xmin, ymin, xmax, ymax));
  return *this;
}

SvgDrawing& SvgDrawing::add_polyline(const std::vector<Eigen::Vector2d>& points, const Stroke& stroke, bool closed,
                                     const Fill& fill) {
  Item it;
  it.kind = Kind::Polyline;
  it.points = points;
  it.stroke = stroke;
  it.fill = fill;
  it.closed = closed;
  items_.push_back(std::move(it));
  return *this;
}

SvgDrawing& SvgDrawing::add_circle(const Eigen::Vector2d& center, double radius, const Stroke& stroke,
                                   const Fill& fill) {
  Item it;
  it.kind = Kind::Circle;
  it.points = {center};
  it.stroke = stroke;
  it.fill = fill;
  it.radius = std::abs(radius);
  items_.push_back(std::move(it));
  return *this;
}

SvgDrawing& SvgDrawing::add_point(const Eigen::Vector2d& p, const std::string& color, double size_px, Marker marker) {
  Item it;
  it.kind = Kind::Point;
  it.points = {p};
  it.color = color;
  it.radius = size_px;
  it.marker = marker;
  items_.push_back(std::move(it));
  return *this;
}

SvgDrawing& SvgDrawing::add_text(const Eigen::Vector2d& p, std::string text, double size_px, const std::string& color,
                                 double dx_px, double dy_px) {
  Item it;
  it.kind = Kind::Text;
  it.points = {p};
  it.text = std::move(text);
  it.color = color;
  it.size = size_px;
  it.dx = dx_px;
  it.dy = dy_px;
  items_.push_back(std::move(it));
  return *this;
}

Eigen::Vector4d SvgDrawing::content_box() const {
  if (fixed_box_) return box_;
  const double inf = std::numeric_limits<double>::infinity();
  Eigen::Vector4d b(inf, inf, -inf, -inf);
  auto extend = [&](const Eigen::Vector2d& p, double r) {
    if (!p.allFinite() || !std::isfinite(r)) return;
    b[0] = std::min(b[0], p.x() - r);
    b[1] = std::min(b[1], p.y() - r);
    b[2] = std::max(b[2], p.x() + r);
    b[3] = std::max(b[3], p.y() + r);
  };
  for (const auto& it : items_)
    for (const auto& p : it.points) extend(p, it.kind == Kind::Circle ? it.radius : 0.0);
  if (!(b[0] <= b[2])) return Eigen::Vector4d(-1, -1, 1, 1);
  return drawable_box(b);  // a single point, a line parallel to an axis
}

SvgDrawing::View SvgDrawing::view() const {
  const Eigen::Vector4d b = content_box();
  const double top_extra = title_.empty() ? 0.0 : 22.0;
  const double aw = width_ - 2 * margin_, ah = height_ - 2 * margin_ - top_extra;
  const double bw = std::max(b[2] - b[0], 1e-300), bh = std::max(b[3] - b[1], 1e-300);
  double s = std::min(aw / bw, ah / bh);
  if (!(s > 0) || !std::isfinite(s)) s = 1;
  // Centre the box in the available area.
  const double cx = 0.5 * (b[0] + b[2]), cy = 0.5 * (b[1] + b[3]);
  View v;
  v.scale = s;
  v.ox = 0.5 * width_ - s * cx;
  v.oy = top_extra + margin_ + 0.5 * ah + s * cy;
  return v;
}

Eigen::Vector2d SvgDrawing::to_pixel(const Eigen::Vector2d& w) const {
  const View v = view();
  return Eigen::Vector2d(v.ox + v.scale * w.x(), v.oy - v.scale * w.y());
}

double SvgDrawing::scale() const { return view().scale; }

std::string SvgDrawing::to_svg() const {
  const View v = view();
  auto P = [&](const Eigen::Vector2d& w) { return Eigen::Vector2d(v.ox + v.scale * w.x(), v.oy - v.scale * w.y()); };
  auto pts = [&](const std::vector<Eigen::Vector2d>& ps, std::size_t b, std::size_t e) {
    std::string out;
    for (std::size_t i = b; i < e; ++i) {
      const Eigen::Vector2d q = P(ps[i]);
      if (i > b) out += ' ';
      out += px(q.x()) + "," + px(q.y());
    }
    return out;
  };

  std::ostringstream o;
  o << svg_open(width_, height_);
  o << "<title>" << xml_escape(title_.empty() ? "drawing" : title_) << "</title>\n";
  if (!background_.empty())
    o << "<rect x=\"0\" y=\"0\" width=\"" << width_ << "\" height=\"" << height_ << "\" fill=\""
      << xml_escape(background_) << "\"/>\n";
  if (!title_.empty())
    o << "<text class=\"title\" x=\"" << px(0.5 * width_) << "\" y=\"" << px(margin_ * 0.5 + 14)
      << "\" font-size=\"14\" font-weight=\"bold\" text-anchor=\"middle\">" << xml_escape(title_) << "</text>\n";
  o << "<g class=\"content\" stroke-linejoin=\"round\" stroke-linecap=\"round\">\n";
  for (const auto& it : items_) {
    switch (it.kind) {
      case Kind::Polyline: {
        const auto& ps = it.points;
        const auto runs = finite_runs(ps.size(), [&](std::size_t i) { return ps[i].allFinite(); });
        const bool whole = runs.size() == 1 && runs[0].first == 0 && runs[0].second == ps.size();
        if (it.closed && whole) {
          o << "<polygon points=\"" << pts(ps, 0, ps.size()) << "\"" << style_stroke(it.stroke) << style_fill(it.fill)
            << "/>\n";
        } else {
          for (const auto& r : runs)
            o << "<polyline points=\"" << pts(ps, r.first, r.second) << "\"" << style_stroke(it.stroke)
              << " fill=\"none\"/>\n";
        }
        break;
      }
      case Kind::Circle: {
        if (!it.points[0].allFinite() || !std::isfinite(it.radius)) break;
        const Eigen::Vector2d c = P(it.points[0]);
        o << "<circle cx=\"" << px(c.x()) << "\" cy=\"" << px(c.y()) << "\" r=\"" << px(v.scale * it.radius) << "\""
          << style_stroke(it.stroke) << style_fill(it.fill) << "/>\n";
        break;
      }
      case Kind::Point: {
        if (!it.points[0].allFinite()) break;
        const Eigen::Vector2d c = P(it.points[0]);
        const std::string col = xml_escape(it.color);
        const double r = it.radius;
        switch (it.marker) {
          case Marker::Dot:
            o << "<circle class=\"point\" cx=\"" << px(c.x()) << "\" cy=\"" << px(c.y()) << "\" r=\"" << num(r)
              << "\" fill=\"" << col << "\" stroke=\"none\"/>\n";
            break;
          case Marker::Circle:
            o << "<circle class=\"point\" cx=\"" << px(c.x()) << "\" cy=\"" << px(c.y()) << "\" r=\"" << num(r)
              << "\" fill=\"#ffffff\" stroke=\"" << col << "\" stroke-width=\"1.2\"/>\n";
            break;
          case Marker::Square:
            o << "<rect class=\"point\" x=\"" << px(c.x() - r) << "\" y=\"" << px(c.y() - r) << "\" width=\""
              << px(2 * r) << "\" height=\"" << px(2 * r) << "\" fill=\"" << col << "\" stroke=\"none\"/>\n";
            break;
          case Marker::Cross:
            o << "<path class=\"point\" d=\"M" << px(c.x() - r) << "," << px(c.y() - r) << "L" << px(c.x() + r) << ","
              << px(c.y() + r) << "M" << px(c.x() - r) << "," << px(c.y() + r) << "L" << px(c.x() + r) << ","
              << px(c.y() - r) << "\" stroke=\"" << col << "\" stroke-width=\"1.2\" fill=\"none\"/>\n";
            break;
        }
        break;
      }
      case Kind::Text: {
        if (!it.points[0].allFinite()) break;
        const Eigen::Vector2d c = P(it.points[0]);
        o << "<text x=\"" << px(c.x() + it.dx) << "\" y=\"" << px(c.y() + it.dy) << "\" font-size=\"" << num(it.size)
          << "\" fill=\"" << xml_escape(it.color) << "\">" << xml_escape(it.text) << "</text>\n";
        break;
      }
    }
  }
  o << "</g>\n</svg>\n";
  return o.str();
}

void SvgDrawing::write(const std::string& path) const { write_file_atomic(path, to_svg()); }

}  // namespace rollkin::io
