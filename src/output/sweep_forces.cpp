// The forces of a solved sweep (rollkin/output/sweep_forces.hpp; docs/forces.md).
#include "rollkin/output/sweep_forces.hpp"

#include "rollkin/analysis/forces.hpp"
#include "rollkin/analysis/hertz.hpp"
#include "rollkin/io/csv.hpp"
#include "rollkin/io/format.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace rollkin::output {
namespace {

const double kInf = std::numeric_limits<double>::infinity();

/// Where each quantity of a pair sits in a row of the table (-1: not a column of this pair).
struct PairColumns {
  int fx = -1, fy = -1, moment = -1, normal = -1, friction = -1, needed = -1;
  int pressure = -1, half_width = -1, shear = -1, depth = -1;
};

/// The --forces columns (docs/forces.md, "Columns"): per pair in pair order <pair>.Fx, <pair>.Fy, a prismatic
/// pair's <pair>.M, a contact pair's normal_force, friction_force, a rolling pair's friction_needed, with a
/// contact material contact_pressure, contact_half_width, max_shear, max_shear_depth; per input its effort;
/// power.
struct Columns {
  std::vector<std::string> names;
  std::vector<PairColumns> pair;
  std::vector<int> effort;  // per driver
  int power = -1;

  Columns(const Mechanism<double>& m, const Dynamics<double>& dyn) : pair(m.pairs.size()) {
    const auto add = [this](const std::string& name) {
      names.push_back(name);
      return static_cast<int>(names.size()) - 1;
    };
    for (std::size_t k = 0; k < m.pairs.size(); ++k) {
      const Pair<double>& p = m.pairs[k];
      PairColumns& c = pair[k];
      c.fx = add(p.name + ".Fx");
      c.fy = add(p.name + ".Fy");
      if (p.traits().slides) c.moment = add(p.name + ".M");
      if (!p.traits().has_contours) continue;
      c.normal = add(p.name + ".normal_force");
      c.friction = add(p.name + ".friction_force");
      if (p.traits().constrains_sliding) c.needed = add(p.name + ".friction_needed");
      if (!dyn.contact[k].given) continue;
      c.pressure = add(p.name + ".contact_pressure");
      c.half_width = add(p.name + ".contact_half_width");
      c.shear = add(p.name + ".max_shear");
      c.depth = add(p.name + ".max_shear_depth");
    }
    for (int d : m.drivers) effort.push_back(add(m.variables[static_cast<std::size_t>(d)].name + ".effort"));
    power = add("power");
  }
};

/// A quantity's extreme over the sweep and where: the input in internal units.
struct Peak {
  double value = 0, input = 0;
  bool found = false;
  void offer(double v, double x) {
    if (!std::isfinite(v)) return;
    if (!found || std::abs(v) > std::abs(value)) {
      value = v;
      input = x;
      found = true;
    }
  }
};

/// What the summary gathers over the rows, per pair and in all.
struct Gathered {
  std::vector<Peak> needed;              // per pair: the friction a rolling pair needs
  std::vector<bool> open;                // per pair: some reaction not unique
  std::vector<int> no_hertz;             // per pair: poses without a Hertz contact (relative curvature <= 0)
  std::vector<double> no_hertz_first;    // ... the first of them
  std::vector<int> separated, slipped;   // per pair: poses with status separation or slip
  Peak effort, power;
  int undetermined = 0;
  double undetermined_first = 0;
};

/// The solved pose at an input between rows: Newton from a neighbouring row's pose moved to first order,
/// then the rates (position.hpp), with the assembly's arc-length origins.
class PoseBetween {
 public:
  PoseBetween(const Mechanism<double>& m, const VectorX<double>& reference, int driver)
      : m_(m), sd_(m), driver_(driver), variable_(m.drivers[static_cast<std::size_t>(driver)]) {
    sd_.kin.reference = reference;
  }
  /// From the row pose (q0, qdot0) at input x0 to x: false where Newton fails.
  bool solve(const VectorX<double>& q0, const VectorX<double>& qdot0, double x0, double x, VectorX<double>& q,
             VectorX<double>& qdot) {
    q = q0 + (x - x0) * qdot0;
    q(variable_) = x;
    if (!solve_position(m_, q, sd_).ok()) return false;
    VectorX<double> rates = VectorX<double>::Zero(static_cast<Eigen::Index>(m_.drivers.size()));
    rates(driver_) = 1;
    qdot = solve_velocity(m_, sd_, rates);
    return true;
  }

 private:
  const Mechanism<double>& m_;
  SolveData<double> sd_;
  int driver_, variable_;
};

/// The context of one sweep's forces.
struct Context {
  const io::Scene& scene;
  const Sweep& sweep;
  const Mechanism<double>& m;
  const Dynamics<double>& dyn;
  double speed;
  Columns columns;
  std::vector<ShearPeak<double>> shear;  // per pair with a contact material: the larger body's peak
  std::vector<double> modulus;           // per pair: E*
  const ForceLayout& layout;
};

/// "'a', 'b'".
std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

/// A row's values at speed w (Context::speed) from the pose's forces; the statuses' causes and the peaks
/// into g.
void pose_values(const Context& c, const PoseForces<double>& f, double x, double* row, Gathered& g, std::string& status) {
  const Mechanism<double>& m = c.m;
  const ForceLayout& layout = c.layout;
  const double w = c.speed, empty = io::empty_cell();
  const auto value = [&](int k) { return f.unique[static_cast<std::size_t>(k)] ? f.value(k, w) : empty; };
  std::fill(row, row + c.columns.names.size(), empty);
  if (!f.determined) {
    if (g.undetermined++ == 0) g.undetermined_first = x;
    return;
  }
  bool separation = false, slip = false;
  for (std::size_t k = 0; k < m.pairs.size(); ++k) {
    const PairColumns& pc = c.columns.pair[k];
    const int first = layout.first[k], count = layout.count[k];
    bool unique = true;
    Vec2<double> force = Vec2<double>::Zero();
    for (int j = first; j < first + count; ++j) {
      unique = unique && f.unique[static_cast<std::size_t>(j)];
      force += f.value(j, w) * f.direction[static_cast<std::size_t>(j)];
    }
    if (!unique) g.open[k] = true;
    row[pc.fx] = unique ? force.x() : empty;
    row[pc.fy] = unique ? force.y() : empty;
    if (pc.moment >= 0) row[pc.moment] = value(first + 1);
    if (pc.normal < 0) continue;
    const double normal = value(first);
    const bool known = !io::is_empty_cell(normal);
    row[pc.normal] = normal;
    const bool rolling = m.pairs[k].traits().constrains_sliding;
    row[pc.friction] = rolling ? value(first + 1) : known ? f.friction_ratio[k] * normal : empty;
    if (known && normal < 0) {
      separation = true;
      ++g.separated[k];
    }
    if (rolling) {
      const double tangential = row[pc.friction];
      const double needed = known && normal > 0 && !io::is_empty_cell(tangential) ? std::abs(tangential) / normal : empty;
      row[pc.needed] = needed;
      if (!io::is_empty_cell(needed)) {
        g.needed[k].offer(needed, x);
        if (c.dyn.friction[k] >= 0 && needed > c.dyn.friction[k]) {
          slip = true;
          ++g.slipped[k];
        }
      }
    }
    if (pc.pressure < 0 || !known) continue;
    const ContactAnalysis<double>* ca = nullptr;
    for (const auto& a : f.contacts)
      if (a.pair == static_cast<int>(k)) ca = &a;
    // The zero band of the design check (docs/analysis.md, "Conformity"): parallel flats, osculating contours.
    const double band = 1e-9 * (std::abs(ca->kappa1) + std::abs(ca->kappa2));
    const double relative = ca->relative_curvature > band ? ca->relative_curvature : 0.0;
    const HertzLine<double> h = hertz_line(normal, relative, c.dyn.contact[k].width, c.modulus[k], c.shear[k]);
    if (!h.valid) {
      if (g.no_hertz[k]++ == 0) g.no_hertz_first[k] = x;
      continue;
    }
    row[pc.pressure] = h.pressure;
    row[pc.half_width] = h.half_width;
    row[pc.shear] = h.max_shear;
    row[pc.depth] = h.max_shear_depth;
  }
  for (std::size_t d = 0; d < m.drivers.size(); ++d) row[c.columns.effort[d]] = value(layout.effort[d]);
  const double effort = row[c.columns.effort[static_cast<std::size_t>(c.sweep.driver)]];
  // Power in W: effort (N * length or N) times speed (rad/s or length/s) is l W (docs/forces.md, "Units").
  row[c.columns.power] = io::is_empty_cell(effort) ? empty : effort * w * c.dyn.metres_per_length;
  g.effort.offer(effort, x);
  g.power.offer(row[c.columns.power], x);
  status = separation ? "separation" : slip ? "slip" : "";
}

/// The input x (internal units) as the summaries print it, to 8 digits as the limits are: "O.phi = 180 deg".
std::string where(const Context& c, double x) {
  const std::string unit = c.scene.unit_label(c.sweep.variable);
  return c.sweep.input + " = " + io::format_number(x / c.sweep.unit, 8) + (unit.empty() ? "" : " " + unit);
}

std::string speed_text(const Context& c, double w) {
  return io::format_number(w / c.scene.speed_unit.per_second, 10) + " " + c.scene.speed_unit.label;
}

/// Normal force of contact pair k at a pose, split as a + w^2 b; nullopt where it is not unique or not defined.
std::optional<std::pair<double, double>> normal_split(const ForceLayout& layout, const PoseForces<double>& f, std::size_t k) {
  const int n = layout.first[k];
  if (!f.determined || !f.unique[static_cast<std::size_t>(n)]) return std::nullopt;
  return std::make_pair(f.a(n), f.b(n));
}

/// The speed w^2 = -a / b at which a normal force a + w^2 b reaches zero (b < 0); infinite when it never does.
double zero_speed_squared(const std::pair<double, double>& ab) { return ab.second < 0 ? -ab.first / ab.second : kInf; }

}  // namespace

SweepForceReport sweep_forces(const io::Scene& scene, const Sweep& sweep, const io::SweepRows& rows,
                              const VectorX<double>& reference, double speed) {
  if (!scene.dynamics)
    throw ForcesUnavailable("--forces needs the scene's \"dynamics\" object (at least its \"speed\"; docs/forces.md), which " +
                            scene.file + " does not have");
  const Mechanism<double>& m = scene.mechanism;
  Dynamics<double> dyn = *scene.dynamics;
  dyn.speed = speed;
  std::optional<ForceData<double>> data;
  try {
    data.emplace(m);
  } catch (const std::invalid_argument& e) {
    throw ForcesUnavailable(scene.file + ": " + e.what());
  }
  Context c{scene, sweep, m, dyn, speed, Columns(m, dyn), std::vector<ShearPeak<double>>(m.pairs.size()),
            std::vector<double>(m.pairs.size(), 0.0), data->layout};
  for (std::size_t k = 0; k < m.pairs.size(); ++k) {
    const ContactMaterial<double>& cm = dyn.contact[k];
    if (!cm.given) continue;
    c.modulus[k] = effective_modulus(cm.modulus[0], cm.poisson[0], cm.modulus[1], cm.poisson[1]);
    const ShearPeak<double> a = subsurface_shear_peak(cm.poisson[0]), b = subsurface_shear_peak(cm.poisson[1]);
    c.shear[k] = a.ratio >= b.ratio ? a : b;
  }
  SweepForceReport out;
  const std::size_t n = rows.size(), cols = c.columns.names.size();
  out.table.names = c.columns.names;
  out.table.values.assign(n * cols, io::empty_cell());
  out.table.status.assign(n, "");
  Gathered g;
  g.needed.resize(m.pairs.size());
  g.open.assign(m.pairs.size(), false);
  g.no_hertz.assign(m.pairs.size(), 0);
  g.no_hertz_first.assign(m.pairs.size(), 0.0);
  g.separated.assign(m.pairs.size(), 0);
  g.slipped.assign(m.pairs.size(), 0);
  // Per contact pair: the row where its normal force reaches zero at the lowest speed, that speed squared,
  // and whether it is ever known (unique and defined).
  const ForceLayout& layout = data->layout;
  std::vector<std::size_t> lowest_row(m.pairs.size(), n);
  std::vector<double> lowest(m.pairs.size(), kInf);
  std::vector<bool> known(m.pairs.size(), false);
  io::RowReader reader(rows);
  for (std::size_t r = 0; r < n; ++r) {
    if (!rows.has_pose(r)) continue;
    const VectorX<double> q = reader.q(r), qdot = reader.qdot(r);
    const PoseForces<double> f = pose_forces(m, dyn, q, qdot, *data);
    std::string status;
    pose_values(c, f, rows.input(r), out.table.values.data() + r * cols, g, status);
    if (rows.status(r) == SolveStatus::Converged) out.table.status[r] = status;
    out.separation_or_slip = out.separation_or_slip || !out.table.status[r].empty();
    for (std::size_t k = 0; k < m.pairs.size(); ++k) {
      if (!m.pairs[k].traits().has_contours) continue;
      const auto ab = normal_split(layout, f, k);
      if (!ab) continue;
      known[k] = true;
      const double w2 = ab->first <= 0 ? 0.0 : zero_speed_squared(*ab);
      if (w2 < lowest[k]) {
        lowest[k] = w2;
        lowest_row[k] = r;
      }
    }
  }
  // Separation speeds, each located between the rows around its lowest row (to 1e-9 of the input's range;
  // docs/forces.md, "Separation speed").
  const double range = std::abs(sweep.to - sweep.from) * sweep.unit;
  PoseBetween between(m, reference, sweep.driver);
  for (std::size_t k = 0; k < m.pairs.size(); ++k) {
    if (!m.pairs[k].traits().has_contours) continue;
    const std::string head = "separation speed of pair '" + m.pairs[k].name + "': ";
    if (!known[k]) {
      out.summary.push_back(head + "none (its normal force is not unique at any solved pose: redundant constraints)");
      continue;
    }
    if (lowest_row[k] == n) {
      out.summary.push_back(head + "none (the inertia never pulls the contours apart: the normal force does not fall "
                                   "with the speed at any solved pose)");
      continue;
    }
    const std::size_t r = lowest_row[k];
    double best_x = rows.input(r), best = lowest[k];
    if (best > 0 && r > 0 && r + 1 < n && rows.has_pose(r - 1) && rows.has_pose(r + 1) && range > 0) {
      const VectorX<double> q0 = reader.q(r), qdot0 = reader.qdot(r);
      const double x0 = rows.input(r);
      VectorX<double> q, qdot;
      const auto speed2 = [&](double x) {
        if (!between.solve(q0, qdot0, x0, x, q, qdot)) return kInf;
        const auto ab = normal_split(layout, pose_forces(m, dyn, q, qdot, *data), k);
        return ab ? zero_speed_squared(*ab) : kInf;
      };
      double lo = std::min(rows.input(r - 1), rows.input(r + 1)), hi = std::max(rows.input(r - 1), rows.input(r + 1));
      // The minimum of a smooth w^2(x) is flat: its value fixes its place only to the square root of round-off.
      // Its slope's zero does better: the slope by central differences (step 1e-4 of the bracket, whose
      // truncation and round-off both stay near 1e-11 of the bracket), its sign change bisected; where the slope
      // does not change sign over the bracket (the minimum at a kink or where the pose cannot be solved),
      // golden-section search on the values.
      const double h = 1e-4 * (hi - lo);
      const auto slope = [&](double x) { return (speed2(x + h) - speed2(x - h)) / (2 * h); };
      double s_lo = slope(lo), s_hi = slope(hi);
      if (s_lo < 0 && s_hi > 0) {
        while (hi - lo > 1e-9 * range) {
          const double mid = (lo + hi) / 2, s_mid = slope(mid);
          if (!std::isfinite(s_mid)) break;
          (s_mid < 0 ? lo : hi) = mid;
        }
      } else {
        const double golden = (std::sqrt(5.0) - 1) / 2;
        double x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo), f1 = speed2(x1), f2 = speed2(x2);
        while (hi - lo > 1e-9 * range) {
          if (f1 <= f2) {
            hi = x2, x2 = x1, f2 = f1, x1 = hi - golden * (hi - lo), f1 = speed2(x1);
          } else {
            lo = x1, x1 = x2, f1 = f2, x2 = lo + golden * (hi - lo), f2 = speed2(x2);
          }
        }
      }
      const double x = (lo + hi) / 2, fx = speed2(x);
      if (fx < best) best = fx, best_x = x;
    }
    out.summary.push_back(head + speed_text(c, std::sqrt(best)) + " (first at " + where(c, best_x) + ")" +
                          (best == 0 ? ": the contact opens at rest" : ""));
  }
  for (std::size_t k = 0; k < m.pairs.size(); ++k) {
    const std::string& name = m.pairs[k].name;
    if (g.needed[k].found)
      out.summary.push_back("largest friction needed at pair '" + name + "': " + io::format_number(g.needed[k].value, 10) +
                            " at " + where(c, g.needed[k].input) +
                            (dyn.friction[k] >= 0 ? " (coefficient " + io::format_number(dyn.friction[k], 10) + ")" : ""));
    if (g.separated[k])
      out.problems.push_back("separation: the contact of pair '" + name + "' opens (normal force below zero) at " +
                             std::to_string(g.separated[k]) + " pose(s) at " + speed_text(c, speed));
    if (g.slipped[k])
      out.problems.push_back("slip: rolling pair '" + name + "' needs more friction than its coefficient " +
                             io::format_number(dyn.friction[k], 10) + " at " + std::to_string(g.slipped[k]) + " pose(s) at " +
                             speed_text(c, speed));
    if (g.no_hertz[k])
      out.problems.push_back("no contact stress at pair '" + name + "' at " + std::to_string(g.no_hertz[k]) +
                             " pose(s), first at " + where(c, g.no_hertz_first[k]) +
                             ": the relative curvature kappa1 + kappa2 is not positive there (flat on flat, osculating or "
                             "conforming contours), so the relative radius of curvature is infinite and Hertz's line "
                             "contact does not apply; the cells are empty");
  }
  const std::string unit = scene.length_unit;
  const bool angular = m.variables[static_cast<std::size_t>(sweep.variable)].kind != ParamKind::Length;
  if (g.effort.found)
    out.summary.push_back("peak effort of " + sweep.input + ": " + io::format_number(g.effort.value, 10) +
                          (angular ? " N*" + unit : " N") + " at " + where(c, g.effort.input) + "; peak power " +
                          io::format_number(g.power.value, 10) + " W at " + where(c, g.power.input) + " (" +
                          speed_text(c, speed) + ")");
  std::vector<std::string> massless, open;
  for (std::size_t i = 0; i < m.links.size(); ++i)
    if (static_cast<int>(i) != m.ground && !(dyn.links[i].mass > 0)) massless.push_back("'" + m.links[i].name + "'");
  for (std::size_t k = 0; k < m.pairs.size(); ++k)
    if (g.open[k]) open.push_back("'" + m.pairs[k].name + "'");
  if (!massless.empty()) out.summary.push_back("massless links (no mass in \"dynamics\"): " + joined(massless));
  if (!open.empty())
    out.summary.push_back("not unique: the reactions of pair(s) " + joined(open) +
                          " (redundant constraints: any share of them between the redundant pairs balances the links; "
                          "their cells are empty, the efforts are unique)");
  if (g.undetermined)
    out.problems.push_back("no forces at " + std::to_string(g.undetermined) + " pose(s), first at " +
                           where(c, g.undetermined_first) +
                           ": the links cannot be in balance there (a singular pose: the inputs do not hold the motion); the "
                           "cells are empty");
  return out;
}

}  // namespace rollkin::output
