// A planar NURBS curve and its exact conversion into rational Bezier pieces for BezierPath.
//
// Definition (Piegl and Tiller, The NURBS Book, eqs. 2.5 and 4.2): degree p >= 1, control points P_0..P_{n-1}
// with weights w_i > 0 and a non-decreasing knot vector u_0..u_{n+p} (n + p + 1 knots),
//   C(u) = sum_i N_{i,p}(u) w_i P_i / sum_i N_{i,p}(u) w_i,   u in [u_p, u_n],
// with the Cox-de Boor B-spline basis N_{i,p}. Clamped (end knots of multiplicity p + 1) and unclamped knot
// vectors are both accepted: the curve is always the one on [u_p, u_n].
//
// Conversion (exact, no sampling): in homogeneous coordinates Q_i = (w_i P_i, w_i) the curve is a polynomial
// B-spline. Boehm's knot insertion (The NURBS Book, eq. 5.15),
//   Q'_i = a_i Q_i + (1 - a_i) Q_{i-1},  a_i = (u - u_i) / (u_{i+p} - u_i)   for k-p+1 <= i <= k,
// (u_k <= u < u_{k+1}; Q'_i = Q_i below that range and Q_{i-1} above it) inserts one knot without changing
// the curve. On a non-empty span [u_j, u_{j+1}] the curve depends only on Q_{j-p}..Q_j and the knots
// u_{j-p}..u_{j+p+1} (eq. 2.5: N_{i,p} vanishes outside [u_i, u_{i+p+1}]), so each span is converted on its
// own: both span ends are inserted into that local B-spline until their multiplicity is p, and the span is
// then the Bezier curve with the p + 1 homogeneous control points between them, projected back to (P, w).
// O(p^2) per span: the conversion is linear in the number of control points. A piece's start is set to the
// previous piece's end (the same point C(u_j), computed twice to round-off), so joints are shared exactly.
// A polynomial curve (all weights 1) gives polynomial pieces.
//
// Corners: at every joint between consecutive pieces (and the closing joint of a closed curve) the tangent
// directions are compared (direction towards the first control point distinct from the joint, so zero end
// derivatives are allowed); a turn beyond `corner_tolerance` (radians; by default the one BezierPath refuses)
// is reported with the index of the piece that starts there and the point. Kinks arise only at knots of
// multiplicity >= p (C0 joins) or at zero-speed points.
//
// Closed curves: with `closed` set, C(u_p) must equal C(u_n) (within BezierPathOptions' joint tolerance,
// relative to the control polygon's extent), as for a periodic NURBS (wrapped control points) or a clamped
// one whose first and last control points coincide.
//
// Invalid input throws std::invalid_argument naming what is wrong and what would be right.
#pragma once

#include "rollkin/profile/bezier.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace rollkin {

template <class S> struct Nurbs {
  int degree = 3;
  std::vector<S> knots;          // points.size() + degree + 1 values, non-decreasing
  std::vector<Vec2<S>> points;   // control points
  std::vector<S> weights;        // empty: all 1 (polynomial B-spline); otherwise one positive weight per point
  bool closed = false;           // the curve returns to its start; the pieces form a closed path

  S weight(std::size_t i) const { return weights.empty() ? S(1) : weights[i]; }
  /// Parameter interval [u_p, u_n] of the curve.
  S lo() const { return knots[static_cast<std::size_t>(degree)]; }
  S hi() const { return knots[points.size()]; }
};

template <class S> struct NurbsPieces {
  std::vector<BezierSegment<S>> segments;  // BezierPath<S>(segments, closed) accepts them when corners is empty
  bool closed = false;
  std::vector<PathCorner<S>> corners;
  std::vector<S> breaks;  // NURBS parameter at the start of each piece, and the end of the last (size + 1)
};

namespace detail {

inline std::string nurbs_number(double x) {
  std::ostringstream os;
  os.precision(17);
  os << x;
  return os.str();
}

/// Number of knots equal to knots[i] (exact equality: knot values are data, not results of arithmetic).
template <class S> int knot_multiplicity(const std::vector<S>& knots, const S& value) {
  int m = 0;
  for (const S& k : knots) m += (k == value) ? 1 : 0;
  return m;
}

/// Inserts the knot value u once into the homogeneous B-spline (knots U, points Q), eq. 5.15. With k the last
/// index with U[k] <= u and s the multiplicity u already has, only Q_{k-p+1}..Q_{k-s} are blended (the a_i of
/// the next s points are 0: they shift), so no knot beyond U[k-s+p] is read; callers insert u in [u_p, u_n]
/// with s < p, which keeps k - s + p within the knot vector and U[i + p] > U[i] for every blended i.
template <class S> void insert_knot(int p, std::vector<S>& U, std::vector<Vec3<S>>& Q, const S& u) {
  const std::size_t ps = static_cast<std::size_t>(p);
  std::size_t k = 0;
  while (k + 1 < U.size() && U[k + 1] <= u) ++k;
  const std::size_t s = static_cast<std::size_t>(knot_multiplicity(U, u));
  std::vector<Vec3<S>> R(Q.size() + 1);
  const std::size_t first = k + 1 - ps;  // k >= p because u >= U[p]
  for (std::size_t i = 0; i < first; ++i) R[i] = Q[i];
  for (std::size_t i = first; i + s <= k; ++i) {
    const S a = (u - U[i]) / (U[i + ps] - U[i]);
    R[i] = a * Q[i] + (S(1) - a) * Q[i - 1];
  }
  for (std::size_t i = k + 1 - s; i < R.size(); ++i) R[i] = Q[i - 1];
  U.insert(U.begin() + static_cast<std::ptrdiff_t>(k) + 1, u);
  Q = std::move(R);
}

}  // namespace detail

/// Throws std::invalid_argument if `c` is not a valid NURBS curve (see the header comment for the rules).
template <class S> void validate_nurbs(const Nurbs<S>& c) {
  using std::isfinite;
  const std::string where = "NURBS: ";
  if (c.degree < 1) throw std::invalid_argument(where + "degree " + std::to_string(c.degree) + " must be at least 1");
  const std::size_t p = static_cast<std::size_t>(c.degree), n = c.points.size();
  if (n < p + 1)
    throw std::invalid_argument(where + std::to_string(n) + " control points are too few for degree " + std::to_string(p) +
                                " (at least degree + 1 = " + std::to_string(p + 1) + " needed)");
  if (c.knots.size() != n + p + 1)
    throw std::invalid_argument(where + std::to_string(c.knots.size()) + " knots given; " + std::to_string(n) +
                                " control points of degree " + std::to_string(p) + " need points + degree + 1 = " +
                                std::to_string(n + p + 1));
  if (!c.weights.empty() && c.weights.size() != n)
    throw std::invalid_argument(where + std::to_string(c.weights.size()) + " weights given for " + std::to_string(n) +
                                " control points (one weight per point, or none for a polynomial B-spline)");
  for (std::size_t i = 0; i < c.knots.size(); ++i) {
    if (!isfinite(to_double(c.knots[i])))
      throw std::invalid_argument(where + "knot " + std::to_string(i) + " is not a finite number");
    if (i > 0 && c.knots[i] < c.knots[i - 1])
      throw std::invalid_argument(where + "knots must be non-decreasing; knot " + std::to_string(i) + " = " +
                                  detail::nurbs_number(to_double(c.knots[i])) + " is less than knot " +
                                  std::to_string(i - 1) + " = " + detail::nurbs_number(to_double(c.knots[i - 1])));
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!isfinite(to_double(c.points[i].x())) || !isfinite(to_double(c.points[i].y())))
      throw std::invalid_argument(where + "control point " + std::to_string(i) + " is not finite");
    if (!c.weights.empty() && !(c.weights[i] > S(0) && isfinite(to_double(c.weights[i]))))
      throw std::invalid_argument(where + "weight " + std::to_string(i) + " = " + detail::nurbs_number(to_double(c.weights[i])) +
                                  " must be positive and finite");
  }
  if (!(c.lo() < c.hi()))
    throw std::invalid_argument(where + "empty parameter range: knot " + std::to_string(p) + " (" +
                                detail::nurbs_number(to_double(c.lo())) + ") must be less than knot " + std::to_string(n) +
                                " (" + detail::nurbs_number(to_double(c.hi())) + ")");
  // The knots are non-decreasing (checked above): a value's multiplicity is the length of its run.
  for (std::size_t i = 0, end = 0; i < c.knots.size(); i = end) {
    while (end < c.knots.size() && c.knots[end] == c.knots[i]) ++end;
    const std::size_t m = end - i;
    const bool interior = c.knots[i] > c.lo() && c.knots[i] < c.hi();
    if (m > p + 1 || (interior && m > p))
      throw std::invalid_argument(where + "knot value " + detail::nurbs_number(to_double(c.knots[i])) + " has multiplicity " +
                                  std::to_string(m) + "; at most degree (" + std::to_string(p) +
                                  ") inside the parameter range, degree + 1 at its ends (the curve would break apart)");
  }
}

namespace detail {

/// Homogeneous Bezier control points of the span [U[j], U[j + 1]] (p <= j < number of points, U[j] < U[j + 1]):
/// the local B-spline Q_{j-p}..Q_j on the knots U[j-p]..U[j+p+1] with both span ends inserted up to
/// multiplicity p (see the header comment). The multiplicity of a span end counts the same in the local knots
/// as in U: a valid vector has at most p + 1 equal knots, all within the window.
template <class S>
std::vector<Vec3<S>> span_to_bezier(int p, const std::vector<S>& U, const std::vector<Vec3<S>>& Q, std::size_t j) {
  const std::size_t ps = static_cast<std::size_t>(p);
  std::vector<S> L(U.begin() + static_cast<std::ptrdiff_t>(j - ps), U.begin() + static_cast<std::ptrdiff_t>(j + ps + 2));
  std::vector<Vec3<S>> R(Q.begin() + static_cast<std::ptrdiff_t>(j - ps), Q.begin() + static_cast<std::ptrdiff_t>(j + 1));
  const S a = U[j], b = U[j + 1];
  for (const S& v : {a, b})
    for (int m = knot_multiplicity(L, v); m < p; ++m) insert_knot(p, L, R, v);
  std::size_t k = ps;  // the last local knot equal to a: the span is [L[k], L[k + 1]], its points R[k-p..k]
  while (!(a < L[k + 1])) ++k;
  return std::vector<Vec3<S>>(R.begin() + static_cast<std::ptrdiff_t>(k - ps), R.begin() + static_cast<std::ptrdiff_t>(k + 1));
}

}  // namespace detail

/// Exact rational Bezier pieces of a valid NURBS curve (validate_nurbs is called first), with its corners.
template <class S>
NurbsPieces<S> nurbs_to_bezier(const Nurbs<S>& c, const S& corner_tolerance = BezierPathOptions<S>{}.corner_tolerance) {
  validate_nurbs(c);
  const std::vector<S>& U = c.knots;
  std::vector<Vec3<S>> Q;
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    const S w = c.weight(i);
    Q.emplace_back(w * c.points[i].x(), w * c.points[i].y(), w);
  }
  NurbsPieces<S> out;
  out.closed = c.closed;
  Vec3<S> joint = Vec3<S>::Zero();  // the previous piece's last homogeneous point
  for (std::size_t j = static_cast<std::size_t>(c.degree); j < c.points.size(); ++j) {
    if (!(U[j] < U[j + 1])) continue;
    std::vector<Vec3<S>> H = detail::span_to_bezier(c.degree, U, Q, j);
    if (!out.segments.empty()) H.front() = joint;  // C(U[j]) as the previous piece ends it
    joint = H.back();
    BezierSegment<S> seg;
    bool rational = false;
    for (const Vec3<S>& h : H) {
      seg.points.push_back(h.template head<2>() / h.z());
      seg.weights.push_back(h.z());
      rational = rational || !(h.z() == S(1));
    }
    if (!rational) seg.weights.clear();
    if (out.breaks.empty()) out.breaks.push_back(U[j]);
    out.breaks.push_back(U[j + 1]);
    out.segments.push_back(std::move(seg));
  }

  // Extent and tolerances as BezierPath uses them (bezier.hpp).
  const BezierPathOptions<S> options;
  Vec2<S> box_lo = c.points[0], box_hi = c.points[0];
  for (const auto& q : c.points) {
    box_lo = box_lo.cwiseMin(q);
    box_hi = box_hi.cwiseMax(q);
  }
  const S gap = options.joint_tolerance * (box_hi - box_lo).norm();
  if (c.closed) {
    const Vec2<S> a = out.segments.front().points.front(), b = out.segments.back().points.back();
    if ((a - b).norm() > gap)
      throw std::invalid_argument("NURBS: marked closed but its end (" + detail::nurbs_number(to_double(b.x())) + ", " +
                                  detail::nurbs_number(to_double(b.y())) + ") is not its start (" +
                                  detail::nurbs_number(to_double(a.x())) + ", " + detail::nurbs_number(to_double(a.y())) +
                                  "); a closed NURBS needs a periodic knot vector with wrapped control points, or "
                                  "coinciding first and last control points");
  }
  out.corners = path_corners(out.segments, c.closed, gap, corner_tolerance);
  return out;
}

}  // namespace rollkin
