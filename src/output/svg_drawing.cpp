#include "rollkin/output/svg_drawing.hpp"

#include "rollkin/io/atomic_file.hpp"
#include "rollkin/io/svg/markup.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace rollkin::io {
namespace {

std::string style_stroke(const Stroke& s) {
  std::string out = " stroke=\"" + xml_escape(s.color) + "\" stroke-width=\"" + svg_size(s.width) + "\"";
  if (s.opacity < 1) out += " stroke-opacity=\"" + svg_size(std::max(0.0, s.opacity)) + "\"";
  if (!s.dash.empty()) out += " stroke-dasharray=\"" + xml_escape(s.dash) + "\"";
  return out;
}

std::string style_fill(const Fill& f) {
  if (f.color.empty()) return " fill=\"none\"";
  std::string out = " fill=\"" + xml_escape(f.color) + "\"";
  if (f.opacity < 1) out += " fill-opacity=\"" + svg_size(std::max(0.0, f.opacity)) + "\"";
  return out;
}

}  // namespace

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
      out += svg_pixel(q.x()) + "," + svg_pixel(q.y());
    }
    return out;
  };

  std::ostringstream o;
  o << svg_document_open(width_, height_);
  o << "<title>" << xml_escape(title_.empty() ? "drawing" : title_) << "</title>\n";
  if (!background_.empty())
    o << "<rect x=\"0\" y=\"0\" width=\"" << width_ << "\" height=\"" << height_ << "\" fill=\""
      << xml_escape(background_) << "\"/>\n";
  if (!title_.empty())
    o << "<text class=\"title\" x=\"" << svg_pixel(0.5 * width_) << "\" y=\"" << svg_pixel(margin_ * 0.5 + 14)
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
        o << "<circle cx=\"" << svg_pixel(c.x()) << "\" cy=\"" << svg_pixel(c.y()) << "\" r=\"" << svg_pixel(v.scale * it.radius) << "\""
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
            o << "<circle class=\"point\" cx=\"" << svg_pixel(c.x()) << "\" cy=\"" << svg_pixel(c.y()) << "\" r=\"" << svg_size(r)
              << "\" fill=\"" << col << "\" stroke=\"none\"/>\n";
            break;
          case Marker::Circle:
            o << "<circle class=\"point\" cx=\"" << svg_pixel(c.x()) << "\" cy=\"" << svg_pixel(c.y()) << "\" r=\"" << svg_size(r)
              << "\" fill=\"#ffffff\" stroke=\"" << col << "\" stroke-width=\"1.2\"/>\n";
            break;
          case Marker::Square:
            o << "<rect class=\"point\" x=\"" << svg_pixel(c.x() - r) << "\" y=\"" << svg_pixel(c.y() - r) << "\" width=\""
              << svg_pixel(2 * r) << "\" height=\"" << svg_pixel(2 * r) << "\" fill=\"" << col << "\" stroke=\"none\"/>\n";
            break;
          case Marker::Cross:
            o << "<path class=\"point\" d=\"M" << svg_pixel(c.x() - r) << "," << svg_pixel(c.y() - r) << "L" << svg_pixel(c.x() + r) << ","
              << svg_pixel(c.y() + r) << "M" << svg_pixel(c.x() - r) << "," << svg_pixel(c.y() + r) << "L" << svg_pixel(c.x() + r) << ","
              << svg_pixel(c.y() - r) << "\" stroke=\"" << col << "\" stroke-width=\"1.2\" fill=\"none\"/>\n";
            break;
        }
        break;
      }
      case Kind::Text: {
        if (!it.points[0].allFinite()) break;
        const Eigen::Vector2d c = P(it.points[0]);
        o << "<text x=\"" << svg_pixel(c.x() + it.dx) << "\" y=\"" << svg_pixel(c.y() + it.dy) << "\" font-size=\"" << svg_size(it.size)
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
