// Validation of a sampled contour (a dense polyline read from a point file) before it becomes a profile.
//
// Part of the CGAL boundary: this header uses plain types only; the implementation
// (src/geometry/validation.cpp) decides with CGAL's exact predicates (EPICK).
//
// Sample convention for CLOSED contours: the samples do NOT repeat the first point; the closing segment
// from the last sample back to sample 0 is implicit. A closed contour given with its first point repeated
// at the end (within the tolerance) is accepted: the repeat is ignored and a note says so.
//
// Tolerance: two samples "coincide" when they are closer than rel_tol times the diagonal of the samples'
// bounding box (the "contour size").
#pragma once

#include "rollkin/scalar.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace rollkin::geometry {

/// Which side of the traversal the link's material lies on. rollkin's convention is Left, so a closed
/// contour with material inside runs counter-clockwise (and the inner contour of a ring clockwise).
enum class MaterialSide { Left, Right };

enum class IssueKind {
  TooFewSamples,      // open: fewer than 2 samples; closed: fewer than 3
  NonFiniteSample,    // NaN or infinite coordinate at `first`
  CoincidentSamples,  // consecutive samples `first`, `second` closer than the tolerance
  SelfIntersection,   // segments `first` and `second` (segment i joins sample i to i+1) cross at `point`
  FoldsBack,          // the contour reverses direction at sample `first` (segments overlap)
  OpenEndsMeet,       // open contour whose first and last samples coincide: probably meant closed (warning)
  LongClosingSegment, // closed contour whose implicit closing segment is far longer than the sample
                      // spacing: probably meant open, or samples are missing there (warning)
  WrongMaterialSide   // simple closed contour running the wrong way for the expected material side
                      // (exact turn at its lexicographically smallest sample; value = signed area)
};

enum class Severity { Error, Warning };

struct ValidationIssue {
  IssueKind kind;
  Severity severity = Severity::Error;
  std::size_t first = 0;    // sample or segment index, see IssueKind
  std::size_t second = 0;   // second sample or segment index, see IssueKind
  Vec2<double> point = Vec2<double>::Zero();  // where (crossing point, offending sample)
  double value = 0;         // measured quantity: distance, signed area or length ratio
  double limit = 0;         // the bound it violates
};

struct ValidationReport {
  std::size_t sample_count = 0;       // samples used (after dropping a repeated closing sample)
  bool closed = false;
  MaterialSide expected = MaterialSide::Left;
  bool dropped_closing_repeat = false;  // the last sample repeated the first and was ignored
  double contour_size = 0;            // bounding-box diagonal
  double rel_tol = 0;
  double tolerance = 0;               // rel_tol * contour_size
  double signed_area = 0;             // closed contours: shoelace area, > 0 counter-clockwise
  std::size_t self_intersections_found = 0;  // may exceed the number reported as issues
  std::vector<ValidationIssue> issues;
  std::vector<std::string> notes;     // informational, never errors

  bool has_errors() const;
};

/// Checks a sampled contour: enough finite samples, coincident consecutive samples, self-intersections
/// (including the implicit closing segment), folds, closure and, for closed contours, the material side.
/// Self-intersections are found in O(n log^2 n + k) with CGAL::box_self_intersection_d on segment boxes,
/// each candidate pair then decided by the exact EPICK predicate do_intersect. At most
/// `max_reported_per_kind` issues of one kind are listed; a note gives the count of the rest.
ValidationReport validate_polyline(const std::vector<Vec2<double>>& pts, bool closed, MaterialSide expected,
                                   double rel_tol, std::size_t max_reported_per_kind = 20);

/// One line per issue (errors and warnings), each prefixed with `file: `, e.g.
/// `shapes/cam.txt: samples 41 and 42 coincide (distance 0 < 1e-09 of the contour size); remove one`.
/// With `sample_lines` (the line of the file each sample was read from) samples are named by their line:
/// `shapes/cam.txt: the points on lines 43 and 44 coincide ...`.
std::vector<std::string> describe_issues(const ValidationReport& report, const std::string& file,
                                         const std::vector<std::size_t>& sample_lines = {});

/// Throws std::runtime_error whose message holds describe_issues() joined by newlines, if the report has
/// at least one error. Warnings alone do not throw.
void throw_if_invalid(const ValidationReport& report, const std::string& file,
                      const std::vector<std::size_t>& sample_lines = {});

}  // namespace rollkin::geometry
