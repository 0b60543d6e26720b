// The envelope of a scene's contour along a solved sweep (include/rollkin/synthesis/scene_envelope.hpp).
#include "rollkin/synthesis/scene_envelope.hpp"

#include "rollkin/io/format.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace rollkin::synthesis {
namespace {

using V = Vec2<double>;
V perp(const V& x) { return V(-x.y(), x.x()); }

/// Cubic Hermite on [0, h] from values and slopes at both ends: value, first and second derivative at s.
std::array<double, 3> hermite(double y0, double m0, double y1, double m1, double h, double s) {
  const double x = s / h, x2 = x * x, x3 = x2 * x;
  const double h00 = 2 * x3 - 3 * x2 + 1, h10 = x3 - 2 * x2 + x, h01 = -2 * x3 + 3 * x2, h11 = x3 - x2;
  const double d00 = (6 * x2 - 6 * x) / h, d10 = 3 * x2 - 4 * x + 1, d01 = (-6 * x2 + 6 * x) / h, d11 = 3 * x2 - 2 * x;
  const double e00 = (12 * x - 6) / (h * h), e10 = (6 * x - 4) / h, e01 = (-12 * x + 6) / (h * h), e11 = (6 * x - 2) / h;
  return {h00 * y0 + h10 * h * m0 + h01 * y1 + h11 * h * m1, d00 * y0 + d10 * m0 + d01 * y1 + d11 * m1,
          e00 * y0 + e10 * m0 + e01 * y1 + e11 * m1};
}

}  // namespace

SweepMotion::SweepMotion(const Mechanism<double>& m, const SweepResult<double>& sweep, int a, int b) {
  KinematicsData<double> d(m);
  for (std::size_t k = 0; k < sweep.size(); ++k) {
    if (!sweep.has_pose(k))
      throw std::invalid_argument("the sweep has a pose that was not solved (at its " + std::to_string(k + 1) +
                                  "th input): the motion must be known over the whole range");
    const SweepPose<double> p = sweep.poses[k];
    evaluate_pairs<double>(m, p.q, nullptr, 1, d);
    const std::vector<SE2<double>> pose = link_poses(m, d);
    const std::vector<Twist<double>> tw = link_twists<double>(m, d, pose, p.qdot);
    const V oa = pose[a].translation(), ob = pose[b].translation();
    const V va = V(tw[a].x(), tw[a].y()) + tw[a].z() * perp(oa), vb = V(tw[b].x(), tw[b].y()) + tw[b].z() * perp(ob);
    const SE2<double> back = SE2<double>::rotation(-pose[a].angle());
    const V rel = back.rotate(ob - oa);
    double phi = pose[b].angle() - pose[a].angle();
    const double dphi = tw[b].z() - tw[a].z();
    if (!t_.empty()) {  // unwrap: the turn nearest the previous angle advanced by its rate
      const double predicted = phi_.back() + dphi_.back() * (sweep.input(k) - t_.back());
      phi += 2 * pi<double>() * std::round((predicted - phi) / (2 * pi<double>()));
    }
    t_.push_back(sweep.input(k));
    phi_.push_back(phi);
    dphi_.push_back(dphi);
    d_.push_back(rel);
    dd_.push_back(back.rotate(vb - va) - tw[a].z() * perp(rel));
  }
  if (t_.size() < 2) throw std::invalid_argument("the sweep needs at least two poses");
  if (t_.back() < t_.front()) {  // a sweep run backwards: increasing t for the engine
    std::reverse(t_.begin(), t_.end());
    std::reverse(phi_.begin(), phi_.end());
    std::reverse(dphi_.begin(), dphi_.end());
    std::reverse(d_.begin(), d_.end());
    std::reverse(dd_.begin(), dd_.end());
  }
  const double turns = (phi_.back() - phi_.front()) / (2 * pi<double>());
  periodic_ = std::abs(turns - std::round(turns)) < 1e-9 && (d_.back() - d_.front()).norm() <= 1e-9 * m.length_scale;
}

MotionJet<double> SweepMotion::operator()(double t) const {
  std::size_t k = static_cast<std::size_t>(std::upper_bound(t_.begin(), t_.end(), t) - t_.begin());
  k = std::min(std::max<std::size_t>(k, 1), t_.size() - 1) - 1;
  const double h = t_[k + 1] - t_[k], s = t - t_[k];
  const auto p = hermite(phi_[k], dphi_[k], phi_[k + 1], dphi_[k + 1], h, s);
  const auto x = hermite(d_[k].x(), dd_[k].x(), d_[k + 1].x(), dd_[k + 1].x(), h, s);
  const auto y = hermite(d_[k].y(), dd_[k].y(), d_[k + 1].y(), dd_[k + 1].y(), h, s);
  return MotionJet<double>{p[0], p[1], p[2], V(x[0], y[0]), V(x[1], y[1]), V(x[2], y[2])};
}

std::string envelope_start_problem(double start) {
  if (std::isfinite(start)) return "";
  return "expected a contour parameter (a finite number, radians for an angle parameter), got " + io::format_number(start);
}

std::string envelope_tolerance_problem(double tolerance) {
  if (std::isfinite(tolerance) && tolerance > 0) return "";
  return "expected a distance > 0 (scene length units), got " + io::format_number(tolerance);
}

EnvelopeProblem<double> scene_envelope_problem(const Mechanism<double>& m, const SweepMotion& motion, int contour,
                                               const std::optional<double>& u_start) {
  const Contour<double>& c = m.contours[contour];
  EnvelopeProblem<double> pr;
  pr.contour = [&c](const double& u) { return c.jet(u, 2); };
  pr.motion = [motion](const double& t) { return motion(t); };
  pr.t_begin = motion.t_begin();
  pr.t_end = motion.t_end();
  pr.periodic = motion.periodic();
  const Domain<double>& dom = c.domain();
  pr.u_scale = dom.hi - dom.lo;
  if (!dom.closed) {
    pr.u_lo = dom.lo;
    pr.u_hi = dom.hi;
  }
  if (u_start) {
    if (const std::string bad = envelope_start_problem(*u_start); !bad.empty()) throw std::invalid_argument("start: " + bad);
    pr.u_guess = *u_start;
    return pr;
  }
  // The roots of the meshing equation at the first pose, on 2000 points of the domain; the one nearest the
  // instant centre seen from B (where every contact normal passes: the relative velocity is a rotation about it).
  const MotionJet<double> m0 = motion(pr.t_begin);
  const SE2<double> back = SE2<double>::rotation(-m0.phi);
  const V w = back.rotate(m0.dd);
  const V centre_in_b = std::abs(m0.dphi) > 0 ? V(perp(w) / m0.dphi) : V(0, 0);  // v_rel = dphi J p + w = 0
  double best = std::numeric_limits<double>::infinity();
  pr.u_guess = (dom.lo + dom.hi) / 2;
  const int n = 2000;
  double prev_u = dom.lo, prev_f = meshing(pr, dom.lo, m0).f;
  for (int i = 1; i <= n; ++i) {
    const double u = dom.lo + (dom.hi - dom.lo) * i / n;
    const double f = meshing(pr, u, m0).f;
    if ((f < 0) != (prev_f < 0)) {
      const double mid = (prev_u + u) / 2;
      const double dist = (c.jet(mid, 0).p - centre_in_b).norm();
      if (dist < best) {
        best = dist;
        pr.u_guess = mid;
      }
    }
    prev_u = u;
    prev_f = f;
  }
  return pr;
}

}  // namespace rollkin::synthesis
