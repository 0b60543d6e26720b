// The profile kinds of the contract suites (test_profile_contract.cpp, test_solve_contact_domain.cpp): one
// factory struct per kind (make<S>() a valid profile, refuse<S>() invalid constructions, closed) and the list
// Kinds. A new kind joins by one struct and one entry in Kinds.
#pragma once

#include <boost/test/unit_test.hpp>

#include "rollkin/profile/profile.hpp"

#include <tuple>
#include <vector>

namespace rollkin::testing {

// ---- one factory per kind: make<S>() builds a valid profile, refuse<S>() tries invalid ones ---------

struct LineKind {
  static constexpr bool closed = false;
  template <class S> static Line<S> make() { return Line<S>(S(-1) / S(2), S(3)); }
  template <class S> static void refuse() {
    BOOST_CHECK_THROW(Line<S>(S(1), S(1)), std::invalid_argument);
    BOOST_CHECK_THROW(Line<S>(S(2), S(1)), std::invalid_argument);
    BOOST_CHECK_THROW(Line<S>(S(0), std::numeric_limits<S>::infinity()), std::invalid_argument);
  }
};

struct CircleKind {
  static constexpr bool closed = true;
  template <class S> static Circle<S> make() { return Circle<S>(S(3) / S(2)); }
  template <class S> static void refuse() {
    BOOST_CHECK_THROW(Circle<S>(S(0)), std::invalid_argument);
    BOOST_CHECK_THROW(Circle<S>(S(-1)), std::invalid_argument);
    BOOST_CHECK_THROW(Circle<S>(std::numeric_limits<S>::quiet_NaN()), std::invalid_argument);
  }
};

struct CircleArcKind {
  static constexpr bool closed = false;
  template <class S> static Circle<S> make() { return Circle<S>(S(2), S(-1) / S(3), S(2)); }
  template <class S> static void refuse() {
    BOOST_CHECK_THROW(Circle<S>(S(0), S(0), S(1)), std::invalid_argument);
    BOOST_CHECK_THROW(Circle<S>(S(-2), S(0), S(1)), std::invalid_argument);
    BOOST_CHECK_THROW(Circle<S>(S(1), S(1), S(1)), std::invalid_argument);
    BOOST_CHECK_THROW(Circle<S>(S(1), S(1), S(0)), std::invalid_argument);
  }
};

struct ParabolaKind {
  static constexpr bool closed = false;
  template <class S> static Parabola<S> make() { return Parabola<S>(S(1) / S(4), S(-2), S(3)); }
  template <class S> static void refuse() {
    BOOST_CHECK_THROW(Parabola<S>(S(0), S(-1), S(1)), std::invalid_argument);
    BOOST_CHECK_THROW(Parabola<S>(S(1), S(1), S(1)), std::invalid_argument);
    BOOST_CHECK_THROW(Parabola<S>(S(1), S(2), S(-1)), std::invalid_argument);
  }
};

struct EllipseKind {
  static constexpr bool closed = true;
  template <class S> static Ellipse<S> make() { return Ellipse<S>(S(3), S(2)); }
  template <class S> static void refuse() {
    BOOST_CHECK_THROW(Ellipse<S>(S(0), S(1)), std::invalid_argument);
    BOOST_CHECK_THROW(Ellipse<S>(S(1), S(-1)), std::invalid_argument);
  }
};

/// Arc length by its own quadrature (Gauss-Legendre, 20 points on 2 panels) instead of the closed form.
struct EllipseQuadratureKind {
  static constexpr bool closed = true;
  template <class S> static Ellipse<S> make() {
    ArcLengthMethod am;
    am.closed_form = false;
    am.rule.order = 20;
    am.rule.panels = 2;
    return Ellipse<S>(S(2), S(7) / S(2), am);
  }
  template <class S> static void refuse() {
    BOOST_CHECK_THROW(Ellipse<S>(S(-3), S(1), ArcLengthMethod{}), std::invalid_argument);
  }
};

/// n samples equally spaced on a circle of radius r from angle 0 to `turn` (a whole turn: closed, without
/// repeating the first): equal chords, hence knots of equal spacing in the chord-length parameter.
template <class S> std::vector<Vec2<S>> arc_samples(int n, const S& r, const S& turn, bool closed) {
  std::vector<Vec2<S>> out;
  using std::cos;
  using std::sin;
  for (int i = 0; i < n; ++i) {
    const S a = turn * S(i) / S(closed ? n : n - 1);
    out.emplace_back(r * cos(a), r * sin(a));
  }
  return out;
}

template <class S> SplineOptions<S> spline_options(bool closed) {
  SplineOptions<S> o;
  o.closed = closed;
  return o;
}

template <class S> void refuse_samples(bool closed) {
  const std::vector<Vec2<S>> three = {Vec2<S>(S(0), S(0)), Vec2<S>(S(1), S(0)), Vec2<S>(S(1), S(1))};
  // Too few samples: an open (natural) spline needs 2, a closed one 3.
  const std::vector<Vec2<S>> too_few(three.begin(), three.begin() + (closed ? 2 : 1));
  BOOST_CHECK_THROW(SampledProfile<S>(too_few, spline_options<S>(closed)), std::invalid_argument);
  std::vector<Vec2<S>> repeated = three;
  repeated.insert(repeated.begin() + 1, three[0]);  // two equal consecutive samples
  repeated.push_back(Vec2<S>(S(0), S(2)));
  BOOST_CHECK_THROW(SampledProfile<S>(repeated, spline_options<S>(closed)), std::invalid_argument);
  SplineOptions<S> negative = spline_options<S>(closed);
  negative.smoothing_tolerance = S(-1);
  BOOST_CHECK_THROW(SampledProfile<S>(arc_samples<S>(8, S(1), S(2), closed), negative), std::invalid_argument);
}

struct SamplesOpenKind {
  static constexpr bool closed = false;
  template <class S> static SampledProfile<S> make() {
    return SampledProfile<S>(arc_samples<S>(9, S(2), S(3), false), spline_options<S>(false));
  }
  template <class S> static void refuse() { refuse_samples<S>(false); }
};

struct SamplesClosedKind {
  static constexpr bool closed = true;
  template <class S> static SampledProfile<S> make() {
    return SampledProfile<S>(arc_samples<S>(8, S(2), S(2) * pi<S>(), true), spline_options<S>(true));
  }
  template <class S> static void refuse() { refuse_samples<S>(true); }
};

template <class S> BezierSegment<S> segment(std::vector<Vec2<S>> points, std::vector<S> weights = {}) {
  return BezierSegment<S>{std::move(points), std::move(weights)};
}

/// Two cubic segments meeting with a continuous tangent at (2, 1).
template <class S> BezierPath<S> two_cubics() {
  auto P = [](int x, int y) { return Vec2<S>(S(x), S(y)); };
  return BezierPath<S>({segment<S>({P(0, 0), P(1, 0), P(1, 1), P(2, 1)}), segment<S>({P(2, 1), P(3, 1), P(4, 3), P(5, 2)})},
                       false);
}

/// An exact ellipse (semi-axes 2 and 1) as four rational quadratic quarter arcs (weights 1, 1/sqrt 2, 1).
template <class S> BezierPath<S> rational_ellipse() {
  using std::sqrt;
  const S w = S(1) / sqrt(S(2));
  std::vector<BezierSegment<S>> segs;
  const Vec2<S> c[4] = {Vec2<S>(S(2), S(0)), Vec2<S>(S(0), S(1)), Vec2<S>(S(-2), S(0)), Vec2<S>(S(0), S(-1))};
  for (int k = 0; k < 4; ++k) {
    const Vec2<S> a = c[k], b = c[(k + 1) % 4];
    segs.push_back(segment<S>({a, a + b, b}, {S(1), w, S(1)}));
  }
  return BezierPath<S>(std::move(segs), true);
}

template <class S> void refuse_bezier() {
  const Vec2<S> o(S(0), S(0)), x(S(1), S(0));
  BOOST_CHECK_THROW(BezierPath<S>({}, false), std::invalid_argument);
  BOOST_CHECK_THROW(BezierPath<S>({segment<S>({o})}, false), std::invalid_argument);
  BOOST_CHECK_THROW(BezierPath<S>({segment<S>({o, o, o})}, false), std::invalid_argument);
  BOOST_CHECK_THROW(BezierPath<S>({segment<S>({o, x}, {S(1), S(0)})}, false), std::invalid_argument);
  BOOST_CHECK_THROW(BezierPath<S>({segment<S>({o, x}, {S(1)})}, false), std::invalid_argument);
}

struct BezierKind {
  static constexpr bool closed = false;
  template <class S> static BezierPath<S> make() { return two_cubics<S>(); }
  template <class S> static void refuse() { refuse_bezier<S>(); }
};

struct RationalBezierKind {
  static constexpr bool closed = true;
  template <class S> static BezierPath<S> make() { return rational_ellipse<S>(); }
  template <class S> static void refuse() { refuse_bezier<S>(); }
};

/// Re-parameterised by arc length: the closed sampled circle (8 congruent spans, each of length L/8).
struct ArcLengthSamplesKind {
  static constexpr bool closed = true;
  template <class S> static ArcLengthProfile<S> make() { return ArcLengthProfile<S>(SamplesClosedKind::make<S>()); }
  template <class S> static void refuse() { refuse_samples<S>(true); }  // it only takes a valid base
};

/// Re-parameterised by arc length: the rational ellipse (four congruent quarters, pieces of length L/4).
struct ArcLengthBezierKind {
  static constexpr bool closed = true;
  template <class S> static ArcLengthProfile<S> make() { return ArcLengthProfile<S>(rational_ellipse<S>()); }
  template <class S> static void refuse() { refuse_bezier<S>(); }
};

/// An open rational path: a half circle of radius 3 as two exact quarter arcs (what the DXF and SVG readers
/// make of an ARC or an elliptical arc command), u in [0, 2].
struct RationalArcKind {
  static constexpr bool closed = false;
  template <class S> static BezierPath<S> make() {
    return BezierPath<S>::circle_arc(Vec2<S>(S(0), S(0)), S(3), S(0), pi<S>());
  }
  template <class S> static void refuse() { refuse_bezier<S>(); }
};

/// Re-parameterised by arc length: the open pair of cubics.
struct ArcLengthOpenBezierKind {
  static constexpr bool closed = false;
  template <class S> static ArcLengthProfile<S> make() { return ArcLengthProfile<S>(two_cubics<S>()); }
  template <class S> static void refuse() { refuse_bezier<S>(); }
};

using Kinds = std::tuple<LineKind, CircleKind, CircleArcKind, ParabolaKind, EllipseKind, EllipseQuadratureKind,
                         SamplesOpenKind, SamplesClosedKind, BezierKind, RationalBezierKind, ArcLengthSamplesKind,
                         ArcLengthBezierKind, RationalArcKind, ArcLengthOpenBezierKind>;

}  // namespace rollkin::testing
