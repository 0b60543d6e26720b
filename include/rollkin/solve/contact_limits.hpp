// The contact limits a sweep watches (solve/continuation.hpp): the contact variables whose contours have an
// end (open domain) or corners (tangent discontinuities a contact may not pass), and the first limit a step
// leaves or reaches; the tracer then locates it by bisection.
#pragma once

#include "rollkin/kinematics.hpp"
#include "rollkin/mechanism.hpp"

#include <cmath>
#include <cstddef>
#include <vector>

namespace rollkin::detail {

/// A contact limit met by a step: contact variable `variable` leaves its open contour's domain (corner < 0)
/// or reaches corner number `corner` of its contour (Contour::corners()). variable < 0: none.
struct ContactLimit {
  int variable = -1;
  int corner = -1;
  explicit operator bool() const { return variable >= 0; }
};

/// The first contact variable of pose q that lies off its open contour (Domain::contains, the one rule for
/// assembly and every swept pose), with its pair and contour; variable < 0: every contact is on its contour.
struct ContactOffContour {
  int variable = -1, pair = -1, contour = -1;
  explicit operator bool() const { return variable >= 0; }
};
template <class S> ContactOffContour contact_off_contour(const Mechanism<S>& m, const VectorX<S>& q) {
  for (std::size_t k = 0; k < m.pairs.size(); ++k) {
    const Pair<S>& p = m.pairs[k];
    if (!p.traits().has_contours) continue;
    for (int j = 0; j < 2; ++j) {
      const int c = j == 0 ? p.contour_a : p.contour_b;
      if (!m.contours[c].domain().contains(q(p.first_variable + j))) return {p.first_variable + j, static_cast<int>(k), c};
    }
  }
  return {};
}

/// The contact variables whose contours have an end (open domain) or corners, collected once per sweep: the
/// check runs after every accepted step. Closed contours wrap, so only their corners can stop a contact.
template <class S> class ContactLimits {
 public:
  explicit ContactLimits(const Mechanism<S>& m) {
    for (const Pair<S>& p : m.pairs) {
      if (!p.traits().has_contours) continue;
      for (int j = 0; j < 2; ++j) {
        const Contour<S>& c = m.contours[j == 0 ? p.contour_a : p.contour_b];
        if (c.domain().closed && c.corners().empty()) continue;
        watched_.push_back({p.first_variable + j, c.domain(), &c.corners()});
      }
    }
  }

  /// The first limit met by the step from pose `from` to pose `to`: an open domain left at `to`, or a corner
  /// passed or reached on the way (a contact that starts on a corner may leave it).
  ContactLimit met(const VectorX<S>& from, const VectorX<S>& to) const {
    for (const Watched& w : watched_) {
      const S a = from(w.variable), b = to(w.variable);
      if (!w.domain.contains(b)) return {w.variable, -1};
      for (std::size_t k = 0; k < w.corners->size(); ++k)
        if (reaches(a, b, (*w.corners)[k].u, w.domain)) return {w.variable, static_cast<int>(k)};
    }
    return {};
  }

  /// A corner that pose q lies within reach[variable] of (in the contact parameter; a closed contour's
  /// nearest copy): where a step collapsed because the contact cannot go past the corner.
  ContactLimit at_corner(const VectorX<S>& q, const VectorX<S>& reach) const {
    using std::abs;
    using std::round;
    for (const Watched& w : watched_) {
      const S u = q(w.variable);
      for (std::size_t k = 0; k < w.corners->size(); ++k) {
        S c = (*w.corners)[k].u;
        if (w.domain.closed) c += w.domain.period() * round((u - c) / w.domain.period());
        if (abs(u - c) <= reach(w.variable)) return {w.variable, static_cast<int>(k)};
      }
    }
    return {};
  }

 private:
  struct Watched {
    int variable;
    Domain<S> domain;
    const std::vector<ContourCorner<S>>* corners;
  };

  /// Whether moving the parameter from a to b passes or reaches corner c (on a closed contour, its copy
  /// c + k * period next beyond a in the direction of motion), without counting a itself.
  static bool reaches(const S& a, const S& b, const S& c, const Domain<S>& d) {
    using std::floor;
    if (a == b) return false;
    const bool up = b > a;
    S next = c;
    if (d.closed) {
      const S period = d.period();
      next = up ? S(c + period * (floor((a - c) / period) + S(1))) : S(c - period * (floor((c - a) / period) + S(1)));
    }
    return up ? (next > a && next <= b) : (next < a && next >= b);
  }

  std::vector<Watched> watched_;
};

}  // namespace rollkin::detail
