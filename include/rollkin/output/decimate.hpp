// Outputs that are for eyes, reduced to what can be seen (docs/reliability.md, "Outputs at any size"): a
// chart's series to its pixel columns, an animation to a bounded number of frames. Both work in one pass over
// the points or poses, with memory bounded by the picture, not by the number of poses: every chart series
// (SvgChart::to_svg, the CLI's --plot as it reads the sweep) and the --animate page go through here.
//
//   SeriesReducer r(x_lo, x_hi, 600);                 // 600 pixel columns over [x_lo, x_hi]
//   for (...) r.add(x, y);                            // in drawing order; NaN breaks the line
//   r.finish();                                       // r.x(), r.y(): the points to draw
//
//   const std::vector<std::size_t> frames = pick_frames(n, [&](std::size_t k) { return status_of(k); });
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

namespace rollkin::io {

/// Reduces a line through points fed in order to a chart's resolution: the x interval [x_lo, x_hi] is cut
/// into `columns` equal pixel columns, and of each run of consecutive finite points within one column only the
/// first, the lowest, the highest and the last are kept, in their input order (the same point once). No peak
/// is lost and the line enters and leaves every column where it did; a run of at most four points is kept
/// whole, so a series with no more than four points in any column is not changed. A non-finite x or y is a
/// break in the line: a run of them is kept as one NaN point. A point outside [x_lo, x_hi] counts in the
/// nearest end column.
/// Size: with x monotone (a sweep's inputs) at most 4 x columns points plus 5 per break; memory: the kept
/// points only.
class SeriesReducer {
 public:
  SeriesReducer(double x_lo, double x_hi, int columns);

  void add(double x, double y);
  /// Closes the open column; x() and y() then hold every kept point. add() may continue afterwards.
  void finish();

  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& y() const { return y_; }
  /// Points given to add() so far.
  std::size_t seen() const { return seen_; }
  /// The pixel column of x (clamped to 0 .. columns - 1).
  int column(double x) const;

 private:
  struct Point {
    double x = 0, y = 0;
    std::size_t index = 0;  // position in the input
  };
  void keep(double x, double y);

  double lo_, scale_;  // column(x) = floor((x - lo) * scale)
  int columns_;
  std::size_t seen_ = 0;
  // The open run: its column, how many points, its first four as given, its first, lowest, highest, last.
  int run_column_ = -1;
  std::size_t run_size_ = 0;
  Point few_[4], first_, low_, high_, last_;
  bool broken_ = false;  // the last thing kept is a break
  std::vector<double> x_, y_;
};

/// Frames an animation shows at most: evenly spaced over the poses, plus up to as many again where the
/// status changes (pick_frames).
constexpr std::size_t kAnimationFrames = 2000;

/// The poses an animation of `poses` poses shows, in increasing order: all of them when there are at most
/// `frames`; else `frames` poses evenly spaced over them (the first and the last among them) and, where the
/// status (status(k), any integer code) changes from pose k - 1 to pose k, both poses k - 1 and k, so that no
/// limit, singular pose or unsolved stretch falls between two frames. When the status changes more than
/// `frames` / 2 times, the changes shown are spread evenly over all of them (a change kept every 2^j, j the
/// smallest that fits). One pass over the statuses; memory: the frames only.
std::vector<std::size_t> pick_frames(std::size_t poses, const std::function<int(std::size_t)>& status,
                                     std::size_t frames = kAnimationFrames);

}  // namespace rollkin::io
