#include "rollkin/io/svg_path.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

namespace rollkin {
namespace {

using P = Vec2<double>;
using Segment = BezierSegment<double>;

const double kPi = pi<double>();

// ---- elliptical arcs ----------------------------------------------------------------------------------

struct ArcCommand {
  P from, to;
  double rx, ry, rotation_deg;
  bool large_arc, sweep;
};

/// Exact rational quadratic pieces (<= 90 degrees each) of an SVG arc, by the endpoint-to-centre conversion
/// of SVG 1.1 implementation notes F.6.5 (eqs. F.6.5.1-6) with the out-of-range radii correction F.6.6.
/// A piece from eccentric angle ta to tb has end points E(ta), E(tb), middle control point
/// c + R(phi) (rx cos m, ry sin m) / cos(h) with m = (ta + tb)/2, h = (tb - ta)/2, and middle weight cos(h).
std::vector<Segment> arc_to_rational_quadratics(const ArcCommand& a) {
  if (a.from == a.to) return {};
  double rx = std::abs(a.rx), ry = std::abs(a.ry);
  if (rx == 0 || ry == 0) return {Segment{{a.from, a.to}, {}}};  // F.6.6: treated as a straight line
  const double phi = std::fmod(a.rotation_deg, 360.0) * kPi / 180.0;
  const double c = std::cos(phi), s = std::sin(phi);
  // F.6.5.1: the start point in the ellipse's axes, relative to the chord's midpoint.
  const P half = (a.from - a.to) / 2;
  const double x1 = c * half.x() + s * half.y(), y1 = -s * half.x() + c * half.y();
  // F.6.6.2-3: radii too small to span the chord are scaled up uniformly.
  const double lambda = x1 * x1 / (rx * rx) + y1 * y1 / (ry * ry);
  if (lambda > 1) {
    rx *= std::sqrt(lambda);
    ry *= std::sqrt(lambda);
  }
  // F.6.5.2: centre in the ellipse's axes; the sign picks one of the two candidate centres.
  const double num = rx * rx * ry * ry - rx * rx * y1 * y1 - ry * ry * x1 * x1;
  const double den = rx * rx * y1 * y1 + ry * ry * x1 * x1;
  double k = std::sqrt(std::max(0.0, num / den));
  if (a.large_arc == a.sweep) k = -k;
  const double cx1 = k * rx * y1 / ry, cy1 = -k * ry * x1 / rx;
  // F.6.5.3: centre in user space.
  const P centre = P(c * cx1 - s * cy1, s * cx1 + c * cy1) + (a.from + a.to) / 2;
  // F.6.5.5-6: start angle and sweep.
  const double t1 = std::atan2((y1 - cy1) / ry, (x1 - cx1) / rx);
  const double t2 = std::atan2((-y1 - cy1) / ry, (-x1 - cx1) / rx);
  double sweep = t2 - t1;
  if (!a.sweep && sweep > 0) sweep -= 2 * kPi;
  if (a.sweep && sweep < 0) sweep += 2 * kPi;

  auto on_ellipse = [&](double t, double scale) {
    const double ex = rx * std::cos(t) * scale, ey = ry * std::sin(t) * scale;
    return P(centre.x() + c * ex - s * ey, centre.y() + s * ex + c * ey);
  };
  const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / (kPi / 2) - 1e-9)));
  std::vector<Segment> out;
  P start = a.from;
  for (int i = 0; i < pieces; ++i) {
    const double ta = t1 + sweep * i / pieces, tb = t1 + sweep * (i + 1) / pieces;
    const double h = (tb - ta) / 2;
    const P end = i + 1 == pieces ? a.to : on_ellipse(tb, 1.0);
    out.push_back(Segment{{start, on_ellipse((ta + tb) / 2, 1.0 / std::cos(h)), end}, {1.0, std::cos(h), 1.0}});
    start = end;
  }
  return out;
}

// ---- path data ------------------------------------------------------------------------------------------

class PathDataParser {
 public:
  PathDataParser(const std::string& d, const std::string& file, const std::string& id) : d_(d), file_(file), id_(id) {}

  std::vector<SvgSubpath> parse() {
    skip_separators();
    if (at_end()) fail("the path data is empty; expected a moveto command (M or m)");
    if (d_[pos_] != 'M' && d_[pos_] != 'm')
      fail(std::string("path data must begin with a moveto (M or m), got '") + d_[pos_] + "'");
    char command = 0;
    while (true) {
      skip_separators();
      if (at_end()) break;
      const char c = d_[pos_];
      if (std::isalpha(static_cast<unsigned char>(c))) {
        if (!std::strchr("MmLlHhVvCcSsQqTtAaZz", c)) fail(std::string("unknown path command '") + c + "'");
        command = c;
        ++pos_;
      } else if (starts_number() && command != 0 && command != 'Z' && command != 'z') {
        if (command == 'M') command = 'L';  // extra pairs after a moveto are implicit line-tos
        if (command == 'm') command = 'l';
      } else {
        fail(std::string("unexpected character '") + c + "'; expected a path command letter or a number");
      }
      execute(command);
    }
    std::vector<SvgSubpath> out;
    for (auto& s : subpaths_)
      if (!s.segments.empty()) out.push_back(std::move(s));
    return out;
  }

 private:
  bool at_end() const { return pos_ >= d_.size(); }
  void skip_separators() {
    while (!at_end() && (std::isspace(static_cast<unsigned char>(d_[pos_])) || d_[pos_] == ',')) ++pos_;
  }
  bool starts_number() const {
    const char c = d_[pos_];
    return std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.';
  }

  [[noreturn]] void fail(const std::string& message) const {
    std::string location = id_.empty() ? "" : "path \"" + id_ + "\", ";
    throw InputError(file_, location + "d offset " + std::to_string(pos_), message);
  }

  /// SVG number: sign? (digits ('.' digits?)? | '.' digits) (('e'|'E') sign? digits)?
  double number(char command, int argument, int count) {
    skip_separators();
    const std::size_t start = pos_;
    auto digits = [&] {
      const std::size_t from = pos_;
      while (!at_end() && std::isdigit(static_cast<unsigned char>(d_[pos_]))) ++pos_;
      return pos_ > from;
    };
    if (!at_end() && (d_[pos_] == '+' || d_[pos_] == '-')) ++pos_;
    bool any = digits();
    if (!at_end() && d_[pos_] == '.') {
      ++pos_;
      any = digits() || any;
    }
    if (!any) {
      pos_ = start;
      fail(std::string("expected a number (argument ") + std::to_string(argument) + " of " + std::to_string(count) +
           " of the '" + command + "' command), got " + (at_end() ? "the end of the data" : "'" + std::string(1, d_[pos_]) + "'"));
    }
    if (!at_end() && (d_[pos_] == 'e' || d_[pos_] == 'E')) {
      const std::size_t mark = pos_++;
      if (!at_end() && (d_[pos_] == '+' || d_[pos_] == '-')) ++pos_;
      if (!digits()) pos_ = mark;  // not an exponent after all
    }
    const char* first = d_.data() + start + (d_[start] == '+' ? 1 : 0);
    double value = 0;
    const auto [end, ec] = std::from_chars(first, d_.data() + pos_, value);
    if (ec != std::errc() || end != d_.data() + pos_ || !std::isfinite(value)) {
      pos_ = start;
      fail("number out of range");
    }
    return value;
  }

  bool flag(char command, int argument) {
    skip_separators();
    if (at_end() || (d_[pos_] != '0' && d_[pos_] != '1'))
      fail(std::string("expected a flag 0 or 1 (argument ") + std::to_string(argument) + " of 7 of the '" + command +
           "' command)");
    return d_[pos_++] == '1';
  }

  P point(char command, int argument, int count, bool relative) {
    const double x = number(command, argument, count);
    const double y = number(command, argument + 1, count);
    return relative ? P(current_ + P(x, y)) : P(x, y);
  }

  void add(Segment s) {
    bool degenerate = true;
    for (const P& q : s.points) degenerate = degenerate && q == s.points.front();
    if (degenerate) return;
    if (need_subpath_) {
      subpaths_.push_back({});
      need_subpath_ = false;
    }
    current_ = s.points.back();
    subpaths_.back().segments.push_back(std::move(s));
  }

  void execute(char command) {
    const bool rel = std::islower(static_cast<unsigned char>(command));
    const char upper = static_cast<char>(std::toupper(static_cast<unsigned char>(command)));
    P cubic_control = current_, quad_control = current_;  // reflected by S and T when they follow C/S, Q/T
    switch (upper) {
      case 'M':
        current_ = start_ = point(command, 1, 2, rel);
        need_subpath_ = true;
        break;
      case 'L':
        add(Segment{{current_, point(command, 1, 2, rel)}, {}});
        break;
      case 'H': {
        const double x = number(command, 1, 1);
        add(Segment{{current_, P(rel ? current_.x() + x : x, current_.y())}, {}});
        break;
      }
      case 'V': {
        const double y = number(command, 1, 1);
        add(Segment{{current_, P(current_.x(), rel ? current_.y() + y : y)}, {}});
        break;
      }
      case 'C':
      case 'S': {
        const P from = current_;
        const P c1 = upper == 'C' ? point(command, 1, 6, rel) : reflected(last_cubic_control_, 'C', 'S');
        const int base = upper == 'C' ? 3 : 1, count = upper == 'C' ? 6 : 4;
        const P c2 = point(command, base, count, rel);
        const P to = point(command, base + 2, count, rel);
        add(Segment{{from, c1, c2, to}, {}});
        cubic_control = c2;
        break;
      }
      case 'Q':
      case 'T': {
        const P from = current_;
        const P c1 = upper == 'Q' ? point(command, 1, 4, rel) : reflected(last_quad_control_, 'Q', 'T');
        const P to = point(command, upper == 'Q' ? 3 : 1, upper == 'Q' ? 4 : 2, rel);
        add(Segment{{from, c1, to}, {}});
        quad_control = c1;
        break;
      }
      case 'A': {
        ArcCommand a;
        a.from = current_;
        a.rx = number(command, 1, 7);
        a.ry = number(command, 2, 7);
        a.rotation_deg = number(command, 3, 7);
        a.large_arc = flag(command, 4);
        a.sweep = flag(command, 5);
        a.to = point(command, 6, 7, rel);
        for (Segment& s : arc_to_rational_quadratics(a)) add(std::move(s));
        break;
      }
      case 'Z':
        add(Segment{{current_, start_}, {}});
        if (!need_subpath_) subpaths_.back().closed = true;
        current_ = start_;
        need_subpath_ = true;  // a following drawing command starts a new subpath at the same point
        break;
    }
    last_upper_ = upper;
    last_cubic_control_ = cubic_control;
    last_quad_control_ = quad_control;
  }

  /// The previous curve's last control point mirrored through the current point (S after C/S, T after Q/T);
  /// otherwise the current point itself (SVG 1.1, 8.3.6 and 8.3.7).
  P reflected(const P& control, char full, char smooth) const {
    if (last_upper_ != full && last_upper_ != smooth) return current_;
    return 2 * current_ - control;
  }

  const std::string& d_;
  const std::string& file_;
  const std::string& id_;
  std::size_t pos_ = 0;
  std::vector<SvgSubpath> subpaths_;
  bool need_subpath_ = true;
  P current_ = P::Zero(), start_ = P::Zero();
  P last_cubic_control_ = P::Zero(), last_quad_control_ = P::Zero();
  char last_upper_ = 0;
};

void map_points(std::vector<SvgSubpath>& subpaths, const SvgPathOptions& o) {
  const double sy = o.flip_y ? -o.scale : o.scale;
  for (auto& sub : subpaths)
    for (auto& seg : sub.segments)
      for (auto& p : seg.points) p = P(p.x() * o.scale, p.y() * sy);
}

// ---- SVG file scanning --------------------------------------------------------------------------------

std::size_t line_of(const std::string& text, std::size_t pos) {
  return 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<long>(pos), '\n'));
}

/// Attributes of the tag whose name ends at `pos` (name="value" or name='value'), up to '>'.
std::map<std::string, std::string> tag_attributes(const std::string& text, std::size_t pos, const std::string& file) {
  std::map<std::string, std::string> attrs;
  auto name_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || std::strchr("_:.-", c); };
  while (pos < text.size()) {
    while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos]))) ++pos;
    if (pos >= text.size() || text[pos] == '>' || text[pos] == '/') return attrs;
    const std::size_t name_start = pos;
    while (pos < text.size() && name_char(text[pos])) ++pos;
    const std::string name = text.substr(name_start, pos - name_start);
    while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos]))) ++pos;
    if (name.empty() || pos >= text.size() || text[pos] != '=')
      throw InputError(file, "line " + std::to_string(line_of(text, pos)), "malformed attribute in a <path> tag");
    ++pos;
    while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos]))) ++pos;
    const char quote = pos < text.size() ? text[pos] : 0;
    const std::size_t close = (quote == '"' || quote == '\'') ? text.find(quote, pos + 1) : std::string::npos;
    if (close == std::string::npos)
      throw InputError(file, "line " + std::to_string(line_of(text, pos)),
                       "attribute " + name + " of a <path> tag has no quoted value");
    attrs[name] = text.substr(pos + 1, close - pos - 1);
    pos = close + 1;
  }
  return attrs;
}

/// Skips comments, CDATA, processing instructions and declarations starting at `pos` ('<').
std::size_t skip_markup(const std::string& text, std::size_t pos) {
  static const std::pair<const char*, const char*> blocks[] = {{"<!--", "-->"}, {"<![CDATA[", "]]>"}, {"<?", "?>"}, {"<!", ">"}};
  for (const auto& [open, close] : blocks)
    if (text.compare(pos, std::strlen(open), open) == 0) {
      const std::size_t end = text.find(close, pos);
      return end == std::string::npos ? text.size() : end + std::strlen(close);
    }
  return pos;
}

}  // namespace

std::vector<SvgSubpath> parse_svg_path_data(const std::string& d, const SvgPathOptions& options, const std::string& file,
                                            const std::string& path_id) {
  std::vector<SvgSubpath> subpaths = PathDataParser(d, file, path_id).parse();
  map_points(subpaths, options);
  return subpaths;
}

std::string read_svg_path_data(const std::string& svg_file, const std::string& path_id) {
  std::ifstream in(svg_file, std::ios::binary);
  if (!in) throw InputError(svg_file, "", std::string("cannot open the SVG file: ") + std::strerror(errno));
  std::ostringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  std::vector<std::string> ids;
  for (std::size_t pos = text.find('<'); pos != std::string::npos; pos = text.find('<', pos + 1)) {
    const std::size_t after = skip_markup(text, pos);
    if (after != pos) {
      pos = after - 1;
      continue;
    }
    std::size_t name_end = pos + 1;
    while (name_end < text.size() && (std::isalnum(static_cast<unsigned char>(text[name_end])) || text[name_end] == ':'))
      ++name_end;
    const std::string name = text.substr(pos + 1, name_end - pos - 1);
    if (name != "path" && (name.size() < 5 || name.compare(name.size() - 5, 5, ":path") != 0)) continue;
    const auto attrs = tag_attributes(text, name_end, svg_file);
    const auto id = attrs.find("id");
    if (id == attrs.end()) continue;
    if (id->second != path_id) {
      ids.push_back(id->second);
      continue;
    }
    const std::string where = "line " + std::to_string(line_of(text, pos));
    if (const auto t = attrs.find("transform"); t != attrs.end())
      throw InputError(svg_file, where,
                       "path \"" + path_id + "\" has transform=\"" + t->second +
                           "\", which rollkin does not apply (transforms are not supported); apply it to the path "
                           "data in the editor first, or remove it");
    const auto d = attrs.find("d");
    if (d == attrs.end()) throw InputError(svg_file, where, "path \"" + path_id + "\" has no d attribute");
    return d->second;
  }
  std::string known;
  for (const auto& i : ids) known += (known.empty() ? "" : ", ") + i;
  throw InputError(svg_file, "", "no <path> element with id=\"" + path_id + "\"" +
                                     (known.empty() ? " (the file has no <path> with an id)" : "; path ids found: " + known));
}

std::vector<SvgSubpath> read_svg_path(const std::string& svg_file, const std::string& path_id,
                                      const SvgPathOptions& options) {
  return parse_svg_path_data(read_svg_path_data(svg_file, path_id), options, svg_file, path_id);
}

}  // namespace rollkin
