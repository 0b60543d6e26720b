#include "rollkin/io/svg/path_data.hpp"

#include "detail.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <optional>

namespace rollkin::io {
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
  // Scaled up, the radii span the chord exactly: the centre is the chord's midpoint (k = 0 below), which
  // F.6.5.2 would only reach through sqrt(round-off), an error of sqrt(eps) in the centre.
  const double lambda = x1 * x1 / (rx * rx) + y1 * y1 / (ry * ry);
  if (std::isinf(lambda)) {  // tiny radii (1e-300): rx sqrt(lambda) = hypot(x1, y1 rx / ry) without overflow
    const double aspect = ry / rx;
    rx = std::hypot(x1, y1 / aspect);
    ry = rx * aspect;
  } else if (lambda >= 1) {
    rx *= std::sqrt(lambda);
    ry *= std::sqrt(lambda);
  }
  // Radii whose ratio over- or underflows (1e300 against 1e-300) leave no ellipse to evaluate: the arc is
  // then as flat as its chord (F.6.6's straight line is the limit).
  if (!(std::isfinite(rx) && std::isfinite(ry) && rx > 0 && ry > 0)) return {Segment{{a.from, a.to}, {}}};
  // F.6.5.2: centre in the ellipse's axes; the sign picks one of the two candidate centres. In the ellipse's
  // unit-circle coordinates (u, v) = (x1 / rx, y1 / ry), m = |(u, v)|, its factor is k = sqrt(1 - m^2) / m, so
  // cx1 = k rx v = rx sqrt(1 - m^2) (v / m) and cy1 = -ry sqrt(1 - m^2) (u / m). The direction (u, v) / m is
  // taken from (x1, y1) scaled to order one: a chord tiny against the radii (fuzz_svg: 1e-299 under radii of
  // 300) neither underflows m^2 nor makes k infinite and the centre NaN.
  const double d = std::max(std::abs(x1), std::abs(y1));
  if (d == 0) return {Segment{{a.from, a.to}, {}}};  // the half chord underflows: no arc to speak of
  const double ud = x1 / d / rx, vd = y1 / d / ry, md = std::hypot(ud, vd);
  // Radii so far from the chord, or from each other, that these overflow (fuzz_svg: radii 10 and 1e-310)
  // leave, like F.6.6, the chord.
  if (!(std::isfinite(md) && md > 0)) return {Segment{{a.from, a.to}, {}}};
  const double m = md * d;
  double root = lambda >= 1 ? 0.0 : std::sqrt(std::max(0.0, 1 - m * m));
  if (a.large_arc == a.sweep) root = -root;
  const double cx1 = root * rx * (vd / md), cy1 = -root * ry * (ud / md);
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
  /// `context` names the path in messages ("path \"cam\"" or "line 12, path \"cam\"").
  PathDataParser(const std::string& d, const std::string& file, const std::string& context)
      : d_(d), file_(file), context_(context) {}

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
        ++command_index_;
        letter_ = c;
        set_ = 1;
        if (!std::strchr("MmLlHhVvCcSsQqTtAaZz", c)) fail(std::string("unknown path command '") + c + "'");
        command = c;
        ++pos_;
      } else if (starts_number() && command != 0 && command != 'Z' && command != 'z') {
        ++set_;
        if (command == 'M') command = 'L';  // extra pairs after a moveto are implicit line-tos
        if (command == 'm') command = 'l';
      } else {
        fail(std::string("unexpected character '") + c + "'; expected a path command letter or a number");
      }
      execute(command);
    }
    std::vector<SvgSubpath> out;
    for (auto& s : subpaths_) {
      svg_detail::merge_short_segments(s);
      if (!s.segments.empty()) out.push_back(std::move(s));
    }
    return out;
  }

 private:
  bool at_end() const { return pos_ >= d_.size(); }
  void skip_separators() {
    while (!at_end() && svg_detail::is_separator(d_[pos_])) ++pos_;
  }
  bool starts_number() const {
    const char c = d_[pos_];
    return std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.';
  }

  /// "command 7 (C)", or "command 7 (C, set 2)" for a coordinate set repeated without its letter.
  std::string command_name() const {
    std::string s = "command " + std::to_string(command_index_) + " (" + std::string(1, letter_);
    if (set_ > 1) s += ", set " + std::to_string(set_);
    return s + ")";
  }

  [[noreturn]] void fail(const std::string& message) const {
    std::string location = context_.empty() ? "" : context_ + ", ";
    if (command_index_ > 0) location += command_name() + ", ";
    throw InputError(file_, location + "d offset " + std::to_string(pos_), message);
  }

  double number(char command, int argument, int count) {
    skip_separators();
    const std::size_t start = pos_;
    double value = 0;
    switch (svg_detail::scan_number(d_, pos_, value)) {
      case svg_detail::NumberScan::ok:
        return value;
      case svg_detail::NumberScan::out_of_range:
        pos_ = start;
        fail("number " + d_.substr(start, 40) + " out of range (not a finite double)");
      case svg_detail::NumberScan::none:
        break;
    }
    fail(std::string("expected a number (argument ") + std::to_string(argument) + " of " + std::to_string(count) +
         " of the '" + command + "' command), got " +
         (at_end() ? "the end of the data" : "'" + std::string(1, d_[pos_]) + "'"));
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
    for (const P& q : s.points)
      if (!std::isfinite(q.x()) || !std::isfinite(q.y()))
        fail("the coordinates overflow (relative moves add up beyond the largest double); expected the "
             "coordinates of a drawing");
    bool degenerate = true;
    for (const P& q : s.points) degenerate = degenerate && q == s.points.front();
    if (degenerate) return;
    if (need_subpath_) {
      subpaths_.push_back({});
      need_subpath_ = false;
    }
    current_ = s.points.back();
    subpaths_.back().segments.push_back(std::move(s));
    subpaths_.back().origins.push_back(command_name());
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
  const std::string& context_;
  std::size_t pos_ = 0;
  int command_index_ = 0, set_ = 0;  // the user's numbering: k-th command letter, coordinate set within it
  char letter_ = 0;
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

}  // namespace

namespace svg_detail {

bool is_separator(char c) { return std::isspace(static_cast<unsigned char>(c)) || c == ','; }

NumberScan scan_number(const std::string& s, std::size_t& pos, double& value) {
  const std::size_t start = pos;
  std::size_t i = pos;
  auto digits = [&] {
    const std::size_t from = i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
    return i > from;
  };
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  bool any = digits();
  if (i < s.size() && s[i] == '.') {
    ++i;
    any = digits() || any;
  }
  if (!any) return NumberScan::none;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    const std::size_t mark = i++;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    if (!digits()) i = mark;  // not an exponent after all ("1em", or "1e" before a command)
  }
  pos = i;
  const char* first = s.data() + start + (s[start] == '+' ? 1 : 0);
  const auto [end, ec] = std::from_chars(first, s.data() + i, value);
  if (ec != std::errc() || end != s.data() + i || !std::isfinite(value)) return NumberScan::out_of_range;
  return NumberScan::ok;
}

double control_extent(const std::vector<BezierSegment<double>>& segments) {
  if (segments.empty()) return 0;
  P lo = segments[0].points[0], hi = lo;
  for (const auto& s : segments)
    for (const auto& p : s.points) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  return (hi - lo).norm();
}

namespace {

/// Whether every control point of s lies within tol of its start: a piece BezierPath cannot hold.
bool shorter_than(const Segment& s, double tol) {
  for (const P& q : s.points)
    if ((q - s.points.front()).norm() > tol) return false;
  return true;
}

/// "A through B (merged: ...)" for a piece made of the pieces from origin A to origin B.
std::string merged_origin(const std::string& first, const std::string& last) {
  return first == last ? first : first + " through " + last + " (merged: each shorter than the tolerance)";
}

/// Consecutive pieces shorter than the tolerance, collected until together they span more than it.
struct ShortRun {
  std::optional<P> start;  // none: no run pending
  P end = P::Zero();
  std::string first, last;  // the origins of the run's first and last piece

  void add(const Segment& s, const std::string& origin) {
    if (!start) {
      start = s.points.front();
      first = origin;
    }
    end = s.points.back();
    last = origin;
  }
};

/// A line made of runs of short pieces, from `start`, and the directions it may still turn to: every run end
/// so far lies within tol of the line from start in any direction of [lo, hi] (radians, relative to
/// `reference`), and farther from start than the previous one, so within tol of the line segment itself.
struct MergedLine {
  P start;
  std::string first;  // origin of its first short piece
  double reference, lo, hi, reach;

  MergedLine(const P& from, const P& to, std::string origin, double tol)
      : start(from), first(std::move(origin)), reference(std::atan2((to - from).y(), (to - from).x())),
        lo(0), hi(0), reach(0) {
    narrow(to, tol);
  }
  /// Whether the line may end at `to` instead (then narrows its directions to keep the earlier ends near it).
  bool extends_to(const P& to, double tol) {
    const P d = to - start;
    const double turn = std::remainder(std::atan2(d.y(), d.x()) - reference, 2 * kPi);
    if (!(d.norm() > reach) || turn < lo || turn > hi) return false;
    narrow(to, tol);
    return true;
  }

 private:
  void narrow(const P& to, double tol) {
    const P d = to - start;
    const double turn = std::remainder(std::atan2(d.y(), d.x()) - reference, 2 * kPi);
    const double half = std::asin(std::min(1.0, tol / d.norm()));
    lo = reach == 0 ? turn - half : std::max(lo, turn - half);
    hi = reach == 0 ? turn + half : std::min(hi, turn + half);
    reach = d.norm();
  }
};

}  // namespace

void merge_short_segments(SvgSubpath& sub) {
  const double tol = BezierPathOptions<double>{}.joint_tolerance * control_extent(sub.segments);
  if (!std::isfinite(tol)) return;  // an overflowing shape is refused by the caller, with its own message
  std::vector<Segment> kept;
  std::vector<std::string> origins;
  ShortRun run;
  std::optional<MergedLine> line;  // the last line made of runs, while it is the last kept piece
  for (std::size_t i = 0; i < sub.segments.size(); ++i) {
    Segment& s = sub.segments[i];
    const std::string origin = i < sub.origins.size() ? sub.origins[i] : "";
    if (!shorter_than(s, tol)) {
      if (run.start) s.points.front() = *run.start;  // a run too short to stand alone joins the next piece
      run = {};
      line.reset();
      kept.push_back(std::move(s));
      origins.push_back(origin);
      continue;
    }
    run.add(s, origin);
    if (!((run.end - *run.start).norm() > tol)) continue;
    // Long enough together: the run's chord is a piece, or extends the line the previous runs made.
    if (line && line->extends_to(run.end, tol)) {
      kept.back().points.back() = run.end;
      origins.back() = merged_origin(line->first, run.last);
    } else {
      line.emplace(*run.start, run.end, run.first, tol);
      kept.push_back(Segment{{*run.start, run.end}, {}});
      origins.push_back(merged_origin(run.first, run.last));
    }
    run = {};
  }
  if (run.start && !kept.empty()) kept.back().points.back() = run.end;  // a short tail joins the last piece
  sub.segments = std::move(kept);
  sub.origins = std::move(origins);
}

}  // namespace svg_detail

std::vector<SvgSubpath> parse_svg_path_data(const std::string& d, const SvgPathOptions& options, const std::string& file,
                                            const std::string& path_id) {
  const std::string context = path_id.empty() ? "" : "path \"" + path_id + "\"";
  std::vector<SvgSubpath> subpaths = PathDataParser(d, file, context).parse();
  map_points(subpaths, options);
  return subpaths;
}

std::vector<SvgSubpath> svg_detail::parse_path_data(const std::string& d, const std::string& file,
                                                    const std::string& context) {
  return PathDataParser(d, file, context).parse();
}

}  // namespace rollkin::io
