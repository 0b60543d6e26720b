// SvgChart: a 2-D line chart like a paper's figure (joint variables against the crank angle), written as a
// standalone SVG document independent of mechanisms: title, axis labels, several named series of (x, y)
// points, automatic "nice" ticks, grid, legend, fixed pixel size. A non-finite x or y in a series breaks its
// line (no segment is drawn across it). Each series is drawn at the chart's resolution (output/decimate.hpp,
// SeriesReducer): of the points in one pixel column the first, lowest, highest and last, so a series of any
// length gives a document of bounded size and loses no peak.
//
// The file is written atomically (io/atomic_file.hpp): PATH.tmp, then rename; on failure no file is left
// behind and std::runtime_error names PATH. Colours are any SVG colour string ("#1f77b4", "red", ...).
// Text is XML-escaped (io/svg/markup.hpp). Pixel coordinates are written with two decimals.
#pragma once

#include <string>
#include <vector>

namespace rollkin::io {

// ---- axis ticks ------------------------------------------------------------------------------------------

/// Tick values for an axis: `values` are multiples of `step` (1, 2, 2.5 or 5 times a power of ten) from `lo`
/// to `hi` inclusive, where [lo, hi] is the data interval widened to whole steps. Degenerate or non-finite
/// input is widened to a usable interval.
struct Ticks {
  double lo = 0, hi = 1, step = 0.2;
  std::vector<double> values;
};
Ticks nice_ticks(double lo, double hi, int target_intervals = 6);

/// Tick values inside a fixed [lo, hi] (lo and hi are kept, not widened).
Ticks ticks_in_range(double lo, double hi, int target_intervals = 6);

/// Ticks with a given step: the multiples of step in [lo, hi], or, when widen is true, [lo, hi] widened to
/// whole steps first. Throws std::invalid_argument for a step that is not positive and finite.
Ticks ticks_with_step(double lo, double hi, double step, bool widen);

/// Label of a tick value: as many decimals as the step needs ("0.25", "90", "-180"), never "-0".
std::string format_tick(double value, double step);

// ---- chart ---------------------------------------------------------------------------------------------

struct ChartSeries {
  std::string name;          // shown in the legend and as data-name of the series' <g>
  std::vector<double> x, y;  // equal sizes; a non-finite x or y breaks the line
  std::string color;         // empty: palette_color(index of the series)
  double stroke_width = 1.6; // px
  std::string dash;          // SVG stroke-dasharray, e.g. "6 3"; empty: solid
  bool markers = false;      // a small circle at every finite point drawn (all of them below the resolution)
};

enum class LegendPosition { TopRight, TopLeft, BottomRight, BottomLeft, Outside, None };

class SvgChart {
 public:
  explicit SvgChart(int width_px = 720, int height_px = 450);

  SvgChart& set_title(std::string title);
  SvgChart& set_x_label(std::string label);
  SvgChart& set_y_label(std::string label);
  /// Fixed axis ranges (default: automatic, widened to nice ticks). lo < hi required.
  SvgChart& set_x_range(double lo, double hi);  // finite lo <= hi; lo == hi is widened around the value
  SvgChart& set_y_range(double lo, double hi);  // likewise
  /// Preferred number of tick intervals per axis (default 6 for x, 5 for y).
  SvgChart& set_tick_target(int x_intervals, int y_intervals);
  /// Fixed tick steps (e.g. 45 or 90 for angles in degrees); 0 restores the automatic nice step.
  SvgChart& set_tick_steps(double x_step, double y_step);
  SvgChart& set_legend(LegendPosition position);
  SvgChart& set_grid(bool on);

  /// Adds a series; throws std::invalid_argument when x and y differ in size.
  SvgChart& add_series(ChartSeries series);
  SvgChart& add_series(std::string name, std::vector<double> x, std::vector<double> y, std::string color = {});

  const std::vector<ChartSeries>& series() const { return series_; }
  int width() const { return width_; }
  int height() const { return height_; }

  /// The ticks actually used for the axes (automatic or fixed ranges).
  Ticks x_ticks() const;
  Ticks y_ticks() const;

  /// The complete SVG document.
  std::string to_svg() const;
  /// Writes to_svg() atomically; throws std::runtime_error naming the path on failure.
  void write(const std::string& path) const;

 private:
  int width_, height_;
  std::string title_, x_label_, y_label_;
  bool x_fixed_ = false, y_fixed_ = false;
  double x_lo_ = 0, x_hi_ = 1, y_lo_ = 0, y_hi_ = 1;
  int x_target_ = 6, y_target_ = 5;
  double x_step_ = 0, y_step_ = 0;
  LegendPosition legend_ = LegendPosition::TopRight;
  bool grid_ = true;
  std::vector<ChartSeries> series_;
};

}  // namespace rollkin::io
