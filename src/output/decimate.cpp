// Outputs reduced to what can be seen (rollkin/output/decimate.hpp).
#include "rollkin/output/decimate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rollkin::io {

SeriesReducer::SeriesReducer(double x_lo, double x_hi, int columns) : lo_(x_lo), columns_(std::max(1, columns)) {
  const double width = x_hi - x_lo;
  // A degenerate or non-finite interval is one column.
  scale_ = std::isfinite(width) && width > 0 && std::isfinite(x_lo) ? columns_ / width : 0;
  if (!std::isfinite(lo_)) lo_ = 0;
}

int SeriesReducer::column(double x) const {
  const double c = std::floor((x - lo_) * scale_);
  if (!(c > 0)) return 0;  // also NaN
  return c >= columns_ - 1 ? columns_ - 1 : static_cast<int>(c);
}

void SeriesReducer::keep(double x, double y) {
  x_.push_back(x);
  y_.push_back(y);
}

void SeriesReducer::add(double x, double y) {
  const std::size_t index = seen_++;
  if (!std::isfinite(x) || !std::isfinite(y)) {
    finish();
    if (!broken_ && !x_.empty()) keep(std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN());
    broken_ = !x_.empty();
    return;
  }
  const int c = column(x);
  if (c != run_column_) {
    finish();
    run_column_ = c;
  }
  const Point p{x, y, index};
  if (run_size_ < 4) few_[run_size_] = p;
  if (run_size_ == 0) first_ = low_ = high_ = p;
  if (y < low_.y) low_ = p;
  if (y > high_.y) high_ = p;
  last_ = p;
  ++run_size_;
}

void SeriesReducer::finish() {
  if (run_size_ == 0) return;
  broken_ = false;
  if (run_size_ <= 4) {
    for (std::size_t k = 0; k < run_size_; ++k) keep(few_[k].x, few_[k].y);
  } else {
    Point kept[4] = {first_, low_, high_, last_};
    std::sort(kept, kept + 4, [](const Point& a, const Point& b) { return a.index < b.index; });
    for (int k = 0; k < 4; ++k)
      if (k == 0 || kept[k].index != kept[k - 1].index) keep(kept[k].x, kept[k].y);
  }
  run_size_ = 0;
  run_column_ = -1;
}

std::vector<std::size_t> pick_frames(std::size_t poses, const std::function<int(std::size_t)>& status, std::size_t frames) {
  std::vector<std::size_t> picks;
  frames = std::max<std::size_t>(frames, 2);
  if (poses <= frames) {
    for (std::size_t k = 0; k < poses; ++k) picks.push_back(k);
    return picks;
  }
  // The poses where the status changes, thinned as they come: change number c is kept when c is a multiple of
  // `stride`; when more than frames / 2 are kept, every other one goes and the stride doubles.
  std::vector<std::size_t> changes;
  std::size_t stride = 1, count = 0;
  int before = status(0);
  for (std::size_t k = 1; k < poses; ++k) {
    const int now = status(k);
    if (now == before) continue;
    before = now;
    if (count++ % stride != 0) continue;
    changes.push_back(k);
    if (changes.size() > frames / 2) {
      std::size_t kept = 0;
      for (std::size_t i = 0; i < changes.size(); i += 2) changes[kept++] = changes[i];
      changes.resize(kept);
      stride *= 2;
    }
  }
  for (std::size_t f = 0; f < frames; ++f) picks.push_back((f * (poses - 1) + (frames - 1) / 2) / (frames - 1));
  for (std::size_t k : changes) picks.insert(picks.end(), {k - 1, k});
  std::sort(picks.begin(), picks.end());
  picks.erase(std::unique(picks.begin(), picks.end()), picks.end());
  return picks;
}

}  // namespace rollkin::io
