// A contour given by point samples: a C2 cubic spline on the chord-length parameter.
//
// Parameter: u_0 = 0, u_{k+1} = u_k + |q_{k+1} - q_k| (cumulative chord length of the samples q_k, a
// Length parameter close to, but not equal to, arc length). On span k, with h = u_{k+1} - u_k, t = u - u_k
// and the nodal values g_k and second derivatives M_k (the usual moment form of the cubic spline):
//   p(u)    = g_k + b_k t + M_k t^2 / 2 + (M_{k+1} - M_k) t^3 / (6 h),
//   b_k     = (g_{k+1} - g_k) / h - h (2 M_k + M_{k+1}) / 6,
// so p'' is continuous by construction and p' is continuous when, at every interior node,
//   (h_{k-1}/6) M_{k-1} + ((h_{k-1} + h_k)/3) M_k + (h_k/6) M_{k+1}
//       = (g_{k+1} - g_k)/h_k - (g_k - g_{k-1})/h_{k-1}          i.e.  R M = Q^T g.
// Ends: natural (M = 0 at both ends), not-a-knot (p''' continuous at the second and last-but-one nodes) or
// periodic (closed contour, indices wrap, the domain [0, L) wraps too).
//
// Smoothing (optional, natural or periodic ends): the Reinsch smoothing spline minimises
//   sum_k |q_k - g_k|^2 + alpha * integral |p''|^2 du,
// whose solution is (R + alpha Q^T Q) M = Q^T q, g = q - alpha Q M (Green & Silverman, sec. 2.3). alpha is
// chosen by geometric bisection as the largest value with max_k |q_k - g_k| <= the requested tolerance, and
// that deviation (distance from each sample to its own curve point p(u_k)) is reported by max_deviation().
//
// All solves are banded (see banded_solver.hpp): O(n) time and memory. Outside an open domain the end
// cubics are extrapolated.
#pragma once

#include "rollkin/profile/banded_solver.hpp"
#include "rollkin/profile/jet.hpp"
#include "rollkin/profile/piecewise_arc_length.hpp"
#include "rollkin/profile/quadrature.hpp"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace rollkin {

enum class SplineEnd { Natural, NotAKnot };

template <class S> struct SplineOptions {
  bool closed = false;                 // periodic spline; the samples must not repeat the first point
                                       // at the end (a repeated last point is dropped)
  SplineEnd end = SplineEnd::Natural;  // open splines only
  S smoothing_tolerance = S(0);        // 0: interpolate; > 0: smooth with max sample deviation <= this
};

/// Last span found, so that the continuously moving solver finds its span in O(1). Atomic (relaxed) so
/// that concurrent const use from several threads is race-free; a stale hint only costs a binary search.
class SpanHint {
 public:
  SpanHint() = default;
  SpanHint(const SpanHint& o) : last_(o.get()) {}
  SpanHint& operator=(const SpanHint& o) {
    set(o.get());
    return *this;
  }
  std::size_t get() const { return last_.load(std::memory_order_relaxed); }
  void set(std::size_t k) const { last_.store(k, std::memory_order_relaxed); }

 private:
  mutable std::atomic<std::size_t> last_{0};
};

template <class S> class SampledProfile {
 public:
  using Scalar = S;

  explicit SampledProfile(const std::vector<Vec2<S>>& samples, const SplineOptions<S>& options = {})
      : closed_(options.closed) {
    std::vector<Vec2<S>> q = samples;
    if (closed_ && q.size() > 1 && q.front() == q.back()) q.pop_back();
    check_sample_count(q.size(), options);
    knots_ = chord_length_knots(q);
    if (closed_) q.push_back(q.front());
    fit(q, options);
    arc_ = PiecewiseArcLength<S>(*this);
  }

  Domain<S> domain() const { return Domain<S>{knots_.front(), knots_.back(), closed_}; }
  ParamKind parameter_kind() const { return ParamKind::Length; }
  int continuity() const { return 2; }
  /// Largest distance from a sample q_k to its curve point p(u_k) (0 up to rounding when interpolating).
  const S& max_deviation() const { return max_deviation_; }
  std::size_t span_count() const { return knots_.size() - 1; }
  const std::vector<S>& knots() const { return knots_; }

  /// p(u) and derivatives up to `order` (p''' is piecewise constant).
  Jet<S> jet(const S& u, int order) const {
    const S w = domain().wrap(u);
    const std::size_t k = piece_of(w);
    const S h = knots_[k + 1] - knots_[k], t = w - knots_[k];
    const Vec2<S>& m0 = second_[k];
    const Vec2<S> jump = (second_[k + 1] - m0) / h;  // p''' on this span
    const Vec2<S> b = slope_at_start(k);
    Jet<S> j;
    j.p = values_[k] + t * (b + t * (m0 / S(2) + t * jump / S(6)));
    if (order >= 1) j.d1 = b + t * (m0 + t * jump / S(2));
    if (order >= 2) j.d2 = m0 + t * jump;
    if (order >= 3) j.d3 = jump;
    return j;
  }

  S arc_length(const S& u0, const S& u1) const { return arc_.between(*this, domain(), u0, u1); }
  bool has_arc_length_primitive() const { return true; }
  S arc_length_primitive(const S& u) const { return arc_.primitive(*this, domain(), u); }
  S param_at_arc_length(const S& u0, const S& ds) const { return arc_.param_at(*this, domain(), u0, ds); }
  S total_length() const { return arc_.total(); }

  template <class T> SampledProfile<T> cast() const {
    return SampledProfile<T>(cast_all<T>(knots_), cast_all<Vec2<T>>(values_), cast_all<Vec2<T>>(second_), closed_,
                             scalar_cast<T>(max_deviation_));
  }

  // ---- the `Pieces` interface of PiecewiseArcLength ----
  std::size_t piece_count() const { return span_count(); }
  S knot(std::size_t k) const { return knots_[k]; }
  /// Span holding u (clamped to the end spans): the hinted span or its neighbours, else binary search.
  std::size_t piece_of(const S& u) const {
    const std::size_t n = span_count();
    const std::size_t h = std::min(hint_.get(), n - 1);
    for (std::size_t k : {h, h + 1, h - 1}) {
      if (k < n && (k == 0 || knots_[k] <= u) && (k + 1 == n || u < knots_[k + 1])) {
        hint_.set(k);
        return k;
      }
    }
    const auto it = std::upper_bound(knots_.begin() + 1, knots_.end() - 1, u);
    const std::size_t k = static_cast<std::size_t>(it - knots_.begin()) - 1;
    hint_.set(k);
    return k;
  }
  S speed(std::size_t k, const S& u) const {
    const S h = knots_[k + 1] - knots_[k], t = u - knots_[k];
    const Vec2<S> jump = (second_[k + 1] - second_[k]) / h;
    return (slope_at_start(k) + t * (second_[k] + t * jump / S(2))).norm();
  }
  /// Gauss-Legendre on the span: |p'| is the square root of a quartic, smooth on chord-length spans.
  S piece_length(std::size_t k, const S& a, const S& b) const {
    return integrate<S>([&](const S& u) { return speed(k, u); }, a, b, span_rule());
  }

 private:
  template <class> friend class SampledProfile;

  SampledProfile(std::vector<S> knots, std::vector<Vec2<S>> values, std::vector<Vec2<S>> second, bool closed,
                 S max_deviation)
      : closed_(closed), knots_(std::move(knots)), values_(std::move(values)), second_(std::move(second)),
        max_deviation_(std::move(max_deviation)) {
    arc_ = PiecewiseArcLength<S>(*this);
  }

  template <class T, class V> static std::vector<T> cast_all(const std::vector<V>& v) {
    std::vector<T> out;
    out.reserve(v.size());
    for (const V& x : v) {
      if constexpr (std::is_same_v<V, S>) out.push_back(scalar_cast<T>(x));
      else out.push_back(x.template cast<typename T::Scalar>());
    }
    return out;
  }

  /// Enough Gauss-Legendre points per span for the working precision (10 in double, 31 at 50 digits).
  static QuadratureRule span_rule() {
    QuadratureRule r;
    r.kind = Quadrature::GaussLegendre;
    r.order = std::clamp(std::numeric_limits<S>::digits10 * 3 / 5 + 1, 8, 40);
    return r;
  }

  Vec2<S> slope_at_start(std::size_t k) const {
    const S h = knots_[k + 1] - knots_[k];
    return (values_[k + 1] - values_[k]) / h - h * (S(2) * second_[k] + second_[k + 1]) / S(6);
  }

  void check_sample_count(std::size_t n, const SplineOptions<S>& o) const {
    const std::size_t needed = closed_ ? 3 : (o.end == SplineEnd::NotAKnot ? 4 : 2);
    if (n < needed)
      throw std::invalid_argument("SampledProfile: " + std::to_string(n) + " distinct samples, at least " +
                                  std::to_string(needed) + " needed for this spline");
    if (o.smoothing_tolerance < S(0))
      throw std::invalid_argument("SampledProfile: negative smoothing tolerance");
    if (o.smoothing_tolerance > S(0) && !closed_ && o.end == SplineEnd::NotAKnot)
      throw std::invalid_argument("SampledProfile: smoothing needs natural or periodic ends, not not-a-knot");
  }

  /// u_0 = 0, u_{k+1} = u_k + |q_{k+1} - q_k| (plus the closing chord for closed splines).
  std::vector<S> chord_length_knots(const std::vector<Vec2<S>>& q) const {
    const std::size_t n = q.size(), spans = closed_ ? n : n - 1;
    std::vector<S> u(spans + 1);
    u[0] = S(0);
    for (std::size_t k = 0; k < spans; ++k) {
      const S chord = (q[(k + 1) % n] - q[k]).norm();
      if (!(chord > S(0)))
        throw std::invalid_argument("SampledProfile: samples " + std::to_string(k) + " and " +
                                    std::to_string((k + 1) % n) + " coincide (zero chord)");
      u[k + 1] = u[k] + chord;
    }
    return u;
  }

  // ---- fitting -----------------------------------------------------------------------------------------
  // Unknown moments: open splines M_1 .. M_{n-2} (node k+1 is unknown k), periodic M_0 .. M_{N-1}.

  S h(std::size_t k) const { return knots_[k + 1] - knots_[k]; }
  std::size_t unknown_count() const { return closed_ ? span_count() : span_count() - 1; }
  std::size_t node_of_unknown(std::size_t j) const { return closed_ ? j : j + 1; }
  /// Span lengths on both sides of node i, wrapping for periodic splines.
  S h_before(std::size_t i) const { return h(i == 0 ? span_count() - 1 : i - 1); }
  S h_after(std::size_t i) const { return h(i); }

  /// Entry Q(k, i) of column i at row i + offset, offset in {-1, 0, 1}.
  S q_entry(std::size_t i, int offset) const {
    if (offset < 0) return S(1) / h_before(i);
    if (offset > 0) return S(1) / h_after(i);
    return -(S(1) / h_before(i) + S(1) / h_after(i));
  }

  void fit(const std::vector<Vec2<S>>& q, const SplineOptions<S>& o) {
    const S alpha = o.smoothing_tolerance > S(0) ? smoothing_weight(q, o) : S(0);
    solve_moments(q, o.end, alpha);
    max_deviation_ = S(0);
    for (std::size_t i = 0; i < q.size(); ++i) max_deviation_ = std::max(max_deviation_, S((q[i] - values_[i]).norm()));
  }

  /// Solves (R + alpha Q^T Q) M = Q^T q and sets values_ = q - alpha Q M and second_ = M (all nodes).
  void solve_moments(const std::vector<Vec2<S>>& q, SplineEnd end, const S& alpha) {
    const std::size_t m = unknown_count(), nodes = knots_.size();
    second_.assign(nodes, Vec2<S>::Zero());
    values_ = q;
    if (m == 0) return;  // two-point natural spline: a straight segment
    BandedSystem<S> system(m, alpha > S(0) ? 2 : 1, closed_);
    std::vector<Vec2<S>> rhs(m);
    for (std::size_t j = 0; j < m; ++j) {
      const std::size_t i = node_of_unknown(j);
      const std::size_t prev = i == 0 ? nodes - 2 : i - 1;
      rhs[j] = (q[i + 1] - q[i]) / h_after(i) - (q[i] - q[prev]) / h_before(i);
      add_moment(system, j, j - 1, h_before(i) / S(6), end);
      add_moment(system, j, j, (h_before(i) + h_after(i)) / S(3), end);
      add_moment(system, j, j + 1, h_after(i) / S(6), end);
    }
    if (alpha > S(0)) add_smoothing(system, alpha);
    const std::vector<Vec2<S>> moments = system.solve(rhs);
    for (std::size_t j = 0; j < m; ++j) second_[node_of_unknown(j)] = moments[j];
    if (closed_) second_.back() = second_.front();
    if (!closed_ && end == SplineEnd::NotAKnot) extrapolate_not_a_knot_ends();
    if (alpha > S(0)) subtract_smoothing_correction(alpha);
  }

  /// Adds coeff * M_col to row `row` (unknown indices, col may be -1 or m for the open ends): periodic
  /// indices wrap; natural ends have M = 0; not-a-knot ends substitute p''' continuity,
  ///   M_0 = (1 + h0/h1) M_1 - (h0/h1) M_2   and its mirror image at the far end.
  void add_moment(BandedSystem<S>& system, std::size_t row, std::size_t col, const S& coeff, SplineEnd end) const {
    const std::size_t m = unknown_count();
    if (closed_) {
      system.add(row, (col + m) % m, coeff);  // col == size_t(-1) wraps to m - 1
      return;
    }
    if (col < m) {
      system.add(row, col, coeff);
      return;
    }
    if (end == SplineEnd::Natural) return;
    const std::size_t last = span_count() - 1;
    const S r = col == m ? h(last) / h(last - 1) : h(0) / h(1);
    const std::size_t near = col == m ? m - 1 : 0, far = col == m ? m - 2 : 1;
    system.add(row, near, coeff * (S(1) + r));
    system.add(row, far, -coeff * r);
  }

  void extrapolate_not_a_knot_ends() {
    const std::size_t n = knots_.size() - 1;  // last node
    const S r0 = h(0) / h(1), r1 = h(n - 1) / h(n - 2);
    second_[0] = (S(1) + r0) * second_[1] - r0 * second_[2];
    second_[n] = (S(1) + r1) * second_[n - 1] - r1 * second_[n - 2];
  }

  /// Unknown index of the node at `offset` from unknown j's node, or -1 if that node is not an unknown.
  long neighbour_unknown(std::size_t j, int offset) const {
    const long m = static_cast<long>(unknown_count());
    const long k = static_cast<long>(j) + offset;
    if (closed_) return (k + m) % m;
    return (k < 0 || k >= m) ? -1 : k;
  }

  /// alpha Q^T Q: row k of Q touches the unknowns of nodes k-1, k, k+1, so (Q^T Q)(i, j) sums Q(k,i) Q(k,j).
  void add_smoothing(BandedSystem<S>& system, const S& alpha) const {
    const long m = static_cast<long>(unknown_count());
    const long first_row = closed_ ? 0 : -1, last_row = closed_ ? m - 1 : m;  // open: node rows 0 .. n-1
    for (long row = first_row; row <= last_row; ++row) {
      long cols[3];
      S vals[3];
      int count = 0;
      for (int off = -1; off <= 1; ++off) {
        const long col = closed_ ? ((row + off) % m + m) % m : row + off;
        if (col < 0 || col >= m) continue;
        cols[count] = col;
        vals[count] = q_entry(node_of_unknown(col), -off);  // row = col - off
        ++count;
      }
      for (int a = 0; a < count; ++a)
        for (int b = 0; b < count; ++b) system.add(cols[a], cols[b], alpha * vals[a] * vals[b]);
    }
  }

  /// g = q - alpha Q M.
  void subtract_smoothing_correction(const S& alpha) {
    const std::size_t m = unknown_count();
    for (std::size_t j = 0; j < m; ++j) {
      const std::size_t i = node_of_unknown(j);
      for (int off = -1; off <= 1; ++off) {
        std::size_t node = i + off;
        if (closed_) node = (i + m + off) % m;
        values_[node] -= alpha * q_entry(i, off) * second_[i];
      }
    }
    if (closed_) values_.back() = values_.front();
  }

  /// The largest distance of the fit with weight alpha from the samples; NaN if any is NaN (an overflowed
  /// fit), which no tolerance admits (std::max(dev, NaN) kept dev: such a fit counted as within).
  S deviation_for(const std::vector<Vec2<S>>& q, const S& alpha) {
    solve_moments(q, SplineEnd::Natural, alpha);
    S dev(0);
    for (std::size_t i = 0; i < q.size(); ++i) {
      const S d = (q[i] - values_[i]).norm();
      if (!(d == d)) return d;
      dev = std::max(dev, d);
    }
    return dev;
  }

  /// Largest alpha (to a factor 1.001) with max deviation <= tol: bracket by factors of 10 from the
  /// natural scale mean(h)^3 (R ~ h, Q^T Q ~ 1/h^2), then bisect log(alpha).
  S smoothing_weight(const std::vector<Vec2<S>>& q, const SplineOptions<S>& o) {
    using std::sqrt;
    const S tol = o.smoothing_tolerance;
    const S mean_h = knots_.back() / S(span_count());
    S lo(0), hi = mean_h * mean_h * mean_h;
    bool hi_within = deviation_for(q, hi) <= tol;
    for (int k = 0; k < 60 && hi_within; ++k) {
      lo = hi;
      hi *= S(10);
      hi_within = deviation_for(q, hi) <= tol;
    }
    if (hi_within) return hi;  // even the stiffest fit tried is within tol
    for (int k = 0; k < 60 && lo == S(0); ++k) {
      const S trial = hi / S(10);
      if (deviation_for(q, trial) <= tol) lo = trial; else hi = trial;
    }
    if (lo == S(0)) return S(0);
    // Bisection of log(alpha) from hi / lo = 10 to 1.001 takes 12 steps; at most 64, so an infinite hi (the
    // bracket's last factor of 10 overflowed and its fit failed) ends too. sqrt(lo) sqrt(hi) cannot overflow
    // where lo hi would (lo from about 1e154): sqrt(inf) was inf, whose fit fails, and hi stayed inf for ever.
    for (int k = 0; k < 64 && hi > lo * (S(1) + S(1) / S(1000)); ++k) {
      const S mid = sqrt(lo) * sqrt(hi);
      if (deviation_for(q, mid) <= tol) lo = mid; else hi = mid;
    }
    return lo;
  }

  bool closed_;
  std::vector<S> knots_;
  std::vector<Vec2<S>> values_, second_;
  S max_deviation_ = S(0);
  PiecewiseArcLength<S> arc_;
  SpanHint hint_;
};

}  // namespace rollkin
