// Sampled-contour validation (geometry/validation.hpp). Predicates are CGAL's exact EPICK predicates
// (orientation, collinear, angle, do_intersect on segments); the only constructions are the reported
// crossing points and the signed area, both informational.
#include "rollkin/geometry/validation.hpp"
#include "rollkin/io/format.hpp"

#include "epick.hpp"

#include <CGAL/box_intersection_d.h>
#include <CGAL/Box_intersection_d/Box_with_info_d.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace rollkin::geometry {
namespace {

using detail::common_point;
using detail::to_point;
using Point = detail::Point2;
using Segment = detail::Segment2;
// A segment's bounding box carrying the segment's index; ID_EXPLICIT because box_self_intersection_d
// works on copies of the boxes.
using SegmentBox = CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t>;

// Warn when the implicit closing segment is longer than this many times the longest explicit segment.
constexpr double kClosingSegmentRatio = 4.0;

bool is_finite(const Vec2<double>& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }

/// Two samples coincide when closer than the tolerance; exact duplicates always coincide (tolerance 0).
bool coincide(double distance, double tolerance) { return distance < tolerance || distance == 0; }

double bounding_box_diagonal(const std::vector<Vec2<double>>& pts) {
  Vec2<double> lo = pts.front(), hi = pts.front();
  for (const auto& p : pts) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

/// Collects a capped list of issues of one kind and counts the rest.
class IssueSink {
 public:
  IssueSink(ValidationReport& report, std::size_t cap) : report_(report), cap_(cap) {}
  void add(const ValidationIssue& issue) {
    if (++counts_[issue.kind] <= cap_) report_.issues.push_back(issue);
  }
  void note_overflow(IssueKind kind, const char* what) {
    const std::size_t n = counts_[kind];
    if (n > cap_) {
      report_.notes.push_back(std::to_string(n - cap_) + " more " + what + " not listed (" + std::to_string(n) +
                              " in total)");
    }
  }

 private:
  ValidationReport& report_;
  std::size_t cap_;
  std::map<IssueKind, std::size_t> counts_;
};

ValidationIssue make_issue(IssueKind kind, std::size_t first, std::size_t second, const Vec2<double>& point,
                           double value, double limit, Severity severity = Severity::Error) {
  ValidationIssue i;
  i.kind = kind;
  i.severity = severity;
  i.first = first;
  i.second = second;
  i.point = point;
  i.value = value;
  i.limit = limit;
  return i;
}

std::size_t segment_count(std::size_t n, bool closed) { return closed ? n : n - 1; }

void check_coincident_samples(const std::vector<Vec2<double>>& pts, std::size_t n, bool closed, double tol,
                              IssueSink& sink) {
  for (std::size_t i = 0; i < segment_count(n, closed); ++i) {
    const std::size_t j = (i + 1) % n;
    const double d = (pts[j] - pts[i]).norm();
    if (coincide(d, tol))
      sink.add(make_issue(IssueKind::CoincidentSamples, i, j, pts[i], d, tol));
  }
  sink.note_overflow(IssueKind::CoincidentSamples, "coincident sample pairs");
}

/// Indices i of the segments [p_i, p_{i+1}] (cyclic when closed) that are not a single point. Exact
/// duplicates are already reported; dropping their zero-length segments keeps the neighbours of a
/// duplicate adjacent, so they are not reported as crossing at the shared sample.
std::vector<std::size_t> proper_segments(const std::vector<Vec2<double>>& pts, std::size_t n, bool closed) {
  std::vector<std::size_t> segs;
  for (std::size_t i = 0; i < segment_count(n, closed); ++i)
    if (pts[i] != pts[(i + 1) % n]) segs.push_back(i);
  return segs;
}

/// A fold: the segments on either side of a sample overlap, i.e. the neighbours are collinear with it
/// and on the same side (CGAL::collinear and CGAL::angle == ACUTE, both exact). Returns the number found.
std::size_t check_folds(const std::vector<Vec2<double>>& pts, std::size_t n, bool closed,
                        const std::vector<std::size_t>& segs, IssueSink& sink) {
  const std::size_t m = segs.size();
  std::size_t folds = 0;
  for (std::size_t k = 0; k < m; ++k) {
    if (!closed && k + 1 == m) break;
    const std::size_t in = segs[k], out = segs[(k + 1) % m];
    const std::size_t vertex = out;  // the sample where segment `out` starts
    const Point a = to_point(pts[in]), q = to_point(pts[vertex]), b = to_point(pts[(out + 1) % n]);
    if (!CGAL::collinear(a, q, b) || CGAL::angle(a, q, b) != CGAL::ACUTE) continue;
    ++folds;
    sink.add(make_issue(IssueKind::FoldsBack, vertex, vertex, pts[vertex], 0, 0));
  }
  sink.note_overflow(IssueKind::FoldsBack, "folds");
  return folds;
}

/// Consecutive segments boxed together for the search of crossing_pairs: the segment tree, n log^2 n in its
/// boxes, gets n / kSegmentsPerBox of them, and the pairs inside two candidate boxes are compared directly
/// (kSegmentsPerBox^2 box tests per pair of boxes that meet). With one box per segment the tree took half
/// of a 200,000-sample load, its n log^2 n the part of the load that grew faster than the input.
constexpr std::size_t kSegmentsPerBox = 8;

/// Pairs (i, j), i < j, of non-adjacent proper segments that intersect. Candidates: the pairs of segments
/// in one run of kSegmentsPerBox consecutive segments, and in two runs whose bounding boxes meet (from
/// CGAL::box_self_intersection_d, a streamed segment tree); each candidate whose own boxes meet is decided
/// by the exact predicate do_intersect. Every pair of segments whose boxes meet is a candidate exactly once
/// (a run's box holds its segments' boxes). Adjacent segments share a sample and are skipped here; their
/// only other way to meet is a fold (check_folds).
std::vector<std::pair<std::size_t, std::size_t>> crossing_pairs(const std::vector<Vec2<double>>& pts,
                                                                 std::size_t n, bool closed,
                                                                 const std::vector<std::size_t>& segs) {
  const std::size_t m = segs.size();
  std::vector<Segment> segments;
  std::vector<CGAL::Bbox_2> bounds;
  segments.reserve(m);
  bounds.reserve(m);
  for (std::size_t k = 0; k < m; ++k) {
    segments.emplace_back(to_point(pts[segs[k]]), to_point(pts[(segs[k] + 1) % n]));
    bounds.push_back(segments.back().bbox());
  }
  std::vector<SegmentBox> runs;  // info: the run's number; run r holds segments [r K, min((r + 1) K, m))
  runs.reserve(m / kSegmentsPerBox + 1);
  for (std::size_t first = 0; first < m; first += kSegmentsPerBox) {
    CGAL::Bbox_2 box = bounds[first];
    for (std::size_t k = first + 1; k < std::min(first + kSegmentsPerBox, m); ++k) box += bounds[k];
    runs.emplace_back(box, first / kSegmentsPerBox);
  }
  // An open contour whose ends are the same point joins its first and last segments there (reported
  // as OpenEndsMeet), so they are adjacent like those of a closed contour.
  const bool wraps = closed || pts[segs.front()] == pts[(segs.back() + 1) % n];
  auto adjacent = [&](std::size_t k, std::size_t l) {
    if (k > l) std::swap(k, l);
    return l == k + 1 || (wraps && k == 0 && l + 1 == m);
  };
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  auto decide = [&](std::size_t k, std::size_t l) {
    if (adjacent(k, l) || !CGAL::do_overlap(bounds[k], bounds[l]) || !CGAL::do_intersect(segments[k], segments[l]))
      return;
    pairs.emplace_back(std::min(segs[k], segs[l]), std::max(segs[k], segs[l]));
  };
  auto run_end = [&](std::size_t run) { return std::min((run + 1) * kSegmentsPerBox, m); };
  for (std::size_t run = 0; run < runs.size(); ++run)
    for (std::size_t k = run * kSegmentsPerBox; k < run_end(run); ++k)
      for (std::size_t l = k + 1; l < run_end(run); ++l) decide(k, l);
  CGAL::box_self_intersection_d(runs.begin(), runs.end(), [&](const SegmentBox& a, const SegmentBox& b) {
    for (std::size_t k = a.info() * kSegmentsPerBox; k < run_end(a.info()); ++k)
      for (std::size_t l = b.info() * kSegmentsPerBox; l < run_end(b.info()); ++l) decide(k, l);
  });
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

std::size_t check_self_intersections(const std::vector<Vec2<double>>& pts, std::size_t n, bool closed,
                                     const std::vector<std::size_t>& segs, IssueSink& sink) {
  const auto pairs = crossing_pairs(pts, n, closed, segs);
  auto segment = [&](std::size_t i) { return Segment(to_point(pts[i]), to_point(pts[(i + 1) % n])); };
  for (const auto& [i, j] : pairs) {
    sink.add(make_issue(IssueKind::SelfIntersection, i, j, common_point(segment(i), segment(j)), 0, 0));
  }
  sink.note_overflow(IssueKind::SelfIntersection, "self-intersections");
  return pairs.size();
}

void check_open_ends(const std::vector<Vec2<double>>& pts, std::size_t n, double tol, IssueSink& sink) {
  const double d = (pts[n - 1] - pts[0]).norm();
  if (n >= 3 && coincide(d, tol))
    sink.add(make_issue(IssueKind::OpenEndsMeet, n - 1, 0, pts[0], d, tol, Severity::Warning));
}

void check_closing_segment(const std::vector<Vec2<double>>& pts, std::size_t n, IssueSink& sink) {
  double longest = 0;
  for (std::size_t i = 0; i + 1 < n; ++i) longest = std::max(longest, (pts[i + 1] - pts[i]).norm());
  const double closing = (pts[0] - pts[n - 1]).norm();
  if (longest > 0 && closing > kClosingSegmentRatio * longest)
    sink.add(make_issue(IssueKind::LongClosingSegment, n - 1, 0, pts[n - 1], closing / longest,
                        kClosingSegmentRatio, Severity::Warning));
}

/// Shoelace formula about the first sample (less cancellation than about the origin).
double signed_area(const std::vector<Vec2<double>>& pts, std::size_t n) {
  double twice = 0;
  for (std::size_t i = 1; i + 1 < n; ++i) twice += cross2<double>(pts[i] - pts[0], pts[i + 1] - pts[0]);
  return twice / 2;
}

/// Orientation of a simple polygon, exactly: the turn at its lexicographically smallest vertex (the
/// vertex-based test behind CGAL::orientation_2). Never collinear there unless the polygon folds.
int simple_polygon_orientation(const std::vector<Vec2<double>>& pts, std::size_t n,
                               const std::vector<std::size_t>& segs) {
  const std::size_t m = segs.size();
  std::size_t best = 0;
  for (std::size_t k = 1; k < m; ++k)
    if (CGAL::compare_xy(to_point(pts[segs[k]]), to_point(pts[segs[best]])) == CGAL::SMALLER) best = k;
  const Point prev = to_point(pts[segs[(best + m - 1) % m]]);
  const Point here = to_point(pts[segs[best]]);
  const Point next = to_point(pts[(segs[best] + 1) % n]);
  return static_cast<int>(CGAL::orientation(prev, here, next));
}

/// Only for simple contours: a self-intersecting one has no single material side.
void check_material_side(const std::vector<Vec2<double>>& pts, std::size_t n,
                         const std::vector<std::size_t>& segs, MaterialSide expected, IssueSink& sink) {
  const int wanted = expected == MaterialSide::Left ? CGAL::LEFT_TURN : CGAL::RIGHT_TURN;
  if (simple_polygon_orientation(pts, n, segs) != wanted)
    sink.add(make_issue(IssueKind::WrongMaterialSide, 0, n - 1, pts[0], signed_area(pts, n), 0));
}

/// Drops a last sample that repeats the first one of a closed contour (see the header's convention).
std::size_t samples_without_closing_repeat(const std::vector<Vec2<double>>& pts, double tol,
                                           ValidationReport& report) {
  std::size_t n = pts.size();
  if (n >= 2 && coincide((pts[n - 1] - pts[0]).norm(), tol)) {
    --n;
    report.dropped_closing_repeat = true;
    report.notes.push_back("the last sample (" + std::to_string(n) +
                           ") repeats the first one; closed contours need no repeat, it was ignored");
  }
  return n;
}

bool report_non_finite(const std::vector<Vec2<double>>& pts, IssueSink& sink) {
  bool any = false;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (is_finite(pts[i])) continue;
    any = true;
    sink.add(make_issue(IssueKind::NonFiniteSample, i, i, pts[i], 0, 0));
  }
  sink.note_overflow(IssueKind::NonFiniteSample, "non-finite samples");
  return any;
}

}  // namespace

bool ValidationReport::has_errors() const {
  return std::any_of(issues.begin(), issues.end(),
                     [](const ValidationIssue& i) { return i.severity == Severity::Error; });
}

ValidationReport validate_polyline(const std::vector<Vec2<double>>& pts, bool closed, MaterialSide expected,
                                   double rel_tol, std::size_t max_reported_per_kind) {
  ValidationReport report;
  report.closed = closed;
  report.expected = expected;
  report.rel_tol = rel_tol;
  report.sample_count = pts.size();
  IssueSink sink(report, max_reported_per_kind);
  if (pts.empty()) {
    sink.add(make_issue(IssueKind::TooFewSamples, 0, 0, Vec2<double>::Zero(), 0, closed ? 3 : 2));
    return report;
  }
  if (report_non_finite(pts, sink)) return report;
  report.contour_size = bounding_box_diagonal(pts);
  report.tolerance = rel_tol * report.contour_size;
  const std::size_t n = closed ? samples_without_closing_repeat(pts, report.tolerance, report) : pts.size();
  report.sample_count = n;
  if (n < (closed ? 3u : 2u)) {
    sink.add(make_issue(IssueKind::TooFewSamples, n, n, pts[0], double(n), closed ? 3 : 2));
    return report;
  }

  check_coincident_samples(pts, n, closed, report.tolerance, sink);
  if (closed) check_closing_segment(pts, n, sink);
  else check_open_ends(pts, n, report.tolerance, sink);

  const auto segs = proper_segments(pts, n, closed);
  if (segs.size() < (closed ? 3u : 1u)) return report;  // everything collapsed onto one or two points
  const std::size_t folds = check_folds(pts, n, closed, segs, sink);
  report.self_intersections_found = check_self_intersections(pts, n, closed, segs, sink);
  if (!closed) return report;
  report.signed_area = signed_area(pts, n);
  if (folds > 0 || report.self_intersections_found > 0)
    report.notes.push_back("material side not checked: the contour is not simple");
  else
    check_material_side(pts, n, segs, expected, sink);
  return report;
}

// ---- messages --------------------------------------------------------------------------------------
namespace {

using io::format_number;

std::string point_text(const Vec2<double>& p) { return "(" + format_number(p.x()) + ", " + format_number(p.y()) + ")"; }

/// Names samples in messages: "sample 12", or "line 14" when the samples came from a file with those lines.
struct SampleNames {
  const std::vector<std::size_t>& lines;
  std::string one(std::size_t i) const {
    return i < lines.size() ? "the point on line " + std::to_string(lines[i]) : "sample " + std::to_string(i);
  }
  std::string two(std::size_t i, std::size_t j) const {
    return i < lines.size() && j < lines.size()
               ? "the points on lines " + std::to_string(lines[i]) + " and " + std::to_string(lines[j])
               : "samples " + std::to_string(i) + " and " + std::to_string(j);
  }
  std::string segment(std::size_t i, std::size_t n) const {
    const std::size_t j = (i + 1) % n;
    return "segment " + std::to_string(i) +
           (i < lines.size() && j < lines.size()
                ? " (lines " + std::to_string(lines[i]) + " to " + std::to_string(lines[j]) + ")"
                : " (samples " + std::to_string(i) + " to " + std::to_string(j) + ")");
  }
};

std::string describe(const ValidationIssue& i, const ValidationReport& r, const SampleNames& name) {
  const std::size_t n = r.sample_count;
  switch (i.kind) {
    case IssueKind::TooFewSamples:
      return "only " + std::to_string(i.first) + " usable samples; " + (r.closed ? "a closed" : "an open") +
             " contour needs at least " + format_number(i.limit);
    case IssueKind::NonFiniteSample:
      return name.one(i.first) + " has a non-finite coordinate " + point_text(i.point) +
             "; every coordinate must be a finite number";
    case IssueKind::CoincidentSamples:
      return name.two(i.first, i.second) +
             (i.second == 0 ? " (the implicit closing segment)" : "") + " coincide (distance " + format_number(i.value) +
             (i.value < i.limit ? " < " : " <= ") + format_number(r.rel_tol) + " of the contour size); remove one";
    case IssueKind::SelfIntersection:
      return name.segment(i.first, n) + " and " + name.segment(i.second, n) + " cross at " + point_text(i.point) +
             "; a contour must not intersect itself: fix the sample order or remove the loop";
    case IssueKind::FoldsBack:
      return "the contour folds back at " + name.one(i.first) + " " + point_text(i.point) +
             " (its neighbours lie on the same side of it, on one line); remove the sample or its spike";
    case IssueKind::OpenEndsMeet:
      return "warning: the first and last samples of this open contour coincide (distance " + format_number(i.value) +
             "); if it is meant to be closed, declare it closed and drop the last sample";
    case IssueKind::LongClosingSegment:
      return "warning: the implicit closing segment from " + name.one(i.first) +
             " back to the first one is " + format_number(i.value) +
             " times as long as the longest other segment; if the contour is open, declare it open, "
             "otherwise add samples along that gap";
    case IssueKind::WrongMaterialSide: {
      const bool left = r.expected == MaterialSide::Left;
      return std::string("the closed contour runs ") + (left ? "clockwise" : "counter-clockwise") +
             " (signed area " + format_number(i.value) + ") but material on the " + (left ? "left" : "right") +
             " needs it " + (left ? "counter-clockwise" : "clockwise") + "; reverse the sample order";
    }
  }
  return "unknown issue";
}

}  // namespace

std::vector<std::string> describe_issues(const ValidationReport& report, const std::string& file,
                                         const std::vector<std::size_t>& sample_lines) {
  std::vector<std::string> lines;
  const SampleNames names{sample_lines};
  for (const auto& issue : report.issues) lines.push_back(file + ": " + describe(issue, report, names));
  return lines;
}

void throw_if_invalid(const ValidationReport& report, const std::string& file,
                      const std::vector<std::size_t>& sample_lines) {
  if (!report.has_errors()) return;
  std::string message;
  for (const auto& line : describe_issues(report, file, sample_lines)) message += (message.empty() ? "" : "\n") + line;
  throw std::runtime_error(message);
}

}  // namespace rollkin::geometry
