// Numerical quadrature for arc length (eq. 4) where no closed form exists, in any scalar type.
//  - Gauss-Legendre: n-point rule, nodes computed in S by Newton's method on P_n (so MPFR runs get
//    full-precision nodes), applied on equal panels.
//  - Newton-Cotes: the closed composite rule the paper uses (Simpson's rule, degree 2, by default; Boole's
//    rule, degree 4, on request), so the two families can be compared in the benchmark.
#pragma once

#include "rollkin/scalar.hpp"

#include <stdexcept>
#include <vector>

namespace rollkin {

enum class Quadrature { GaussLegendre, NewtonCotes };

/// Quadrature settings used by a profile that has no closed-form arc length (or is told not to use it).
struct QuadratureRule {
  Quadrature kind = Quadrature::GaussLegendre;
  int order = 8;    // Gauss-Legendre points per panel, or Newton-Cotes degree (2: Simpson, 4: Boole)
  int panels = 1;   // equal panels per integration interval
};

template <class S> struct GaussLegendreNodes {
  std::vector<S> x, w;  // nodes and weights on [-1, 1]
};

/// Nodes and weights of the n-point Gauss-Legendre rule: roots of P_n by Newton from Chebyshev guesses,
/// w_i = 2 / ((1 - x_i^2) P_n'(x_i)^2).
template <class S> GaussLegendreNodes<S> gauss_legendre_nodes(int n) {
  using std::abs;
  using std::cos;
  if (n < 1) throw std::invalid_argument("gauss_legendre_nodes: n must be >= 1");
  GaussLegendreNodes<S> g;
  g.x.resize(n);
  g.w.resize(n);
  const S tol = epsilon<S>() * S(4);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    S x = cos(pi<S>() * (S(i) + S(3) / S(4)) / (S(n) + S(1) / S(2)));
    S dp(0);
    for (int it = 0; it < 100; ++it) {
      S p0(1), p1 = x;  // three-term recurrence (k+1) P_{k+1} = (2k+1) x P_k - k P_{k-1}
      for (int k = 1; k < n; ++k) {
        const S p2 = ((S(2 * k + 1)) * x * p1 - S(k) * p0) / S(k + 1);
        p0 = p1;
        p1 = p2;
      }
      if (n == 1) p0 = S(1);
      dp = S(n) * (x * p1 - p0) / (x * x - S(1));
      const S dx = p1 / dp;
      x -= dx;
      if (abs(dx) <= tol) break;
    }
    // Recompute the derivative at the converged root for the weight.
    S p0(1), p1 = x;
    for (int k = 1; k < n; ++k) {
      const S p2 = ((S(2 * k + 1)) * x * p1 - S(k) * p0) / S(k + 1);
      p0 = p1;
      p1 = p2;
    }
    dp = (n == 1) ? S(1) : S(n) * (x * p1 - p0) / (x * x - S(1));
    const S w = S(2) / ((S(1) - x * x) * dp * dp);
    g.x[i] = -x;
    g.w[i] = w;
    g.x[n - 1 - i] = x;
    g.w[n - 1 - i] = w;
  }
  if (n % 2 == 1) g.x[n / 2] = S(0);
  return g;
}

/// Cached rule per scalar type and order (built once per process and order).
template <class S> const GaussLegendreNodes<S>& gauss_legendre(int n) {
  static thread_local std::vector<GaussLegendreNodes<S>> cache;
  if (static_cast<int>(cache.size()) <= n) cache.resize(n + 1);
  if (cache[n].x.empty()) cache[n] = gauss_legendre_nodes<S>(n);
  return cache[n];
}

/// Closed Newton-Cotes weights (times the step h) of degree 2 (Simpson) or 4 (Boole).
template <class S> std::vector<S> newton_cotes_weights(int degree) {
  if (degree == 2) return {S(1) / S(3), S(4) / S(3), S(1) / S(3)};
  if (degree == 4) return {S(14) / S(45), S(64) / S(45), S(24) / S(45), S(64) / S(45), S(14) / S(45)};
  throw std::invalid_argument("newton_cotes_weights: degree must be 2 (Simpson) or 4 (Boole)");
}

/// Integral of f over [a, b] with the given rule (a > b gives the negated integral).
template <class S, class F> S integrate(const F& f, const S& a, const S& b, const QuadratureRule& rule) {
  const int panels = rule.panels < 1 ? 1 : rule.panels;
  const S width = (b - a) / S(panels);
  S sum(0);
  if (rule.kind == Quadrature::GaussLegendre) {
    const auto& g = gauss_legendre<S>(rule.order);
    const S half = width / S(2);
    for (int k = 0; k < panels; ++k) {
      const S mid = a + width * (S(k) + S(1) / S(2));
      for (std::size_t i = 0; i < g.x.size(); ++i) sum += g.w[i] * f(mid + half * g.x[i]);
    }
    return sum * half;
  }
  const std::vector<S> w = newton_cotes_weights<S>(rule.order);
  const int m = static_cast<int>(w.size()) - 1;
  const S h = width / S(m);
  for (int k = 0; k < panels; ++k) {
    const S left = a + width * S(k);
    for (int i = 0; i <= m; ++i) sum += w[i] * f(left + h * S(i));
  }
  return sum * h;
}

}  // namespace rollkin
