// SvgDrawing: a world-coordinate canvas (y up) for pictures of mechanisms, written as a standalone SVG
// document: polylines (open or closed), circles with a world radius, point markers and small text labels,
// scaled uniformly to fit all content inside the picture with a margin (or into a fixed world box). Stroke
// widths, marker sizes and font sizes are in pixels, so they do not depend on the world scale.
//
// The file is written atomically (io/atomic_file.hpp): PATH.tmp, then rename; on failure no file is left
// behind and std::runtime_error names PATH. Colours are any SVG colour string ("#1f77b4", "red", ...).
// Text is XML-escaped (io/svg/markup.hpp). Pixel coordinates are written with two decimals.
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

namespace rollkin::io {

struct Stroke {
  std::string color = "#000000";
  double width = 1.0;    // px
  double opacity = 1.0;  // 0..1
  std::string dash;      // SVG stroke-dasharray; empty: solid
};

struct Fill {
  std::string color;     // empty: no fill
  double opacity = 1.0;  // 0..1
};

enum class Marker { Dot, Circle, Cross, Square };

class SvgDrawing {
 public:
  explicit SvgDrawing(int width_px = 800, int height_px = 600, double margin_px = 24);

  SvgDrawing& set_title(std::string title);        // drawn at the top, also the document <title>
  SvgDrawing& set_background(std::string color);   // empty: transparent (default "#ffffff")
  /// Fixed world box instead of fitting the content (finite, xmin <= xmax, ymin <= ymax). A zero extent (a
  /// straight line parallel to an axis) is widened by 5% of the other extent on each side, a point by 10% of
  /// its largest coordinate (at least 1); the fitted box follows the same rule.
  SvgDrawing& set_world_box(double xmin, double ymin, double xmax, double ymax);

  /// Polyline through world points. A non-finite point breaks it into separate pieces; a closed polyline
  /// without breaks is drawn as a <polygon> (optionally filled), with breaks as open pieces.
  SvgDrawing& add_polyline(const std::vector<Eigen::Vector2d>& points, const Stroke& stroke = {},
                           bool closed = false, const Fill& fill = {});
  /// Circle of world radius r.
  SvgDrawing& add_circle(const Eigen::Vector2d& center, double radius, const Stroke& stroke = {},
                         const Fill& fill = {});
  /// Marker of a fixed pixel size at a world point.
  SvgDrawing& add_point(const Eigen::Vector2d& p, const std::string& color = "#000000", double size_px = 3.0,
                        Marker marker = Marker::Dot);
  /// Small text label; its anchor (start of the baseline, offset by (dx, dy) px, dy down) at world point p.
  SvgDrawing& add_text(const Eigen::Vector2d& p, std::string text, double size_px = 11.0,
                       const std::string& color = "#000000", double dx_px = 4.0, double dy_px = -4.0);

  /// World bounding box of all content: (xmin, ymin, xmax, ymax); a unit box around the origin when empty.
  Eigen::Vector4d content_box() const;
  /// World to pixel coordinates (y flipped) for the current content / world box.
  Eigen::Vector2d to_pixel(const Eigen::Vector2d& world) const;
  /// Pixels per world unit.
  double scale() const;

  int width() const { return width_; }
  int height() const { return height_; }
  std::size_t size() const { return items_.size(); }

  std::string to_svg() const;
  void write(const std::string& path) const;

 private:
  enum class Kind { Polyline, Circle, Point, Text };
  struct Item {
    Kind kind = Kind::Polyline;
    std::vector<Eigen::Vector2d> points;  // polyline points, or the single anchor / centre
    Stroke stroke;
    Fill fill;
    bool closed = false;
    double radius = 0;  // circle: world radius; point: px size
    Marker marker = Marker::Dot;
    std::string text, color;
    double size = 11, dx = 0, dy = 0;
  };
  struct View {
    double scale, ox, oy;  // pixel = (ox + scale * x, oy - scale * y)
  };
  View view() const;

  int width_, height_;
  double margin_;
  std::string title_, background_ = "#ffffff";
  bool fixed_box_ = false;
  Eigen::Vector4d box_ = Eigen::Vector4d(0, 0, 1, 1);
  std::vector<Item> items_;
};

}  // namespace rollkin::io
