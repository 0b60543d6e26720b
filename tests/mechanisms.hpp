// Mechanisms used by several tests, built in code (the scene files in examples/ describe the same ones).
// Templates on the scalar so the MPFR tests run the very same mechanisms.
#pragma once

#include "rollkin/builder.hpp"
#include "rollkin/solve/continuation.hpp"

namespace rollkin::testing {

/// A mechanism with its assembly guess and the variables held at assembly.
template <class S> struct Fixture {
  Mechanism<S> mech;
  VectorX<S> guess;
  std::vector<int> held;
};

/// The reference example of docs/method.md section 4 (variables: theta2, x, theta23, theta34, theta4, theta5).
/// `scale` multiplies every length; `osculating` puts disk 3 of radius 1/(2a) inside the parabola's cup.
template <class S> Fixture<S> paper_fourbar(const S& scale = S(1), bool osculating = false,
                                            ArcLengthMethod arc = {}) {
  MechanismBuilder<S> b;
  const int l1 = b.link("link1", true), l2 = b.link("link2"), l3 = b.link("link3"), l4 = b.link("link4");
  const S a = S(1) / (S(2) * scale);  // y = a x^2 with a = 0.5 at scale 1
  // Parabola: vertex l2 = 2 from O_A on the crank line, axis along the crank, opening toward O_A.
  const int par = b.contour(l2, "parabola", Parabola<S>(a, S(-2) * scale, S(2) * scale, arc),
                            SE2<S>(pi<S>() / S(2), Vec2<S>(S(2) * scale, S(0))), osculating);
  const int rim3 = b.contour(l3, "rim", Circle<S>(S(1) * scale));
  const int rim4 = b.contour(l4, "rim", Circle<S>(S(4) * scale), SE2<S>(S(0), Vec2<S>(S(2) * scale, S(0))));
  const int oa = b.revolute("O_A", l1, l2, SE2<S>(), SE2<S>(), "theta2");
  b.contact("A", true, par, rim3, "x", "theta23");
  b.contact("B", true, rim3, rim4, "theta34", "theta4");
  b.revolute("O_B", l1, l4, SE2<S>(S(0), Vec2<S>(S(7) * scale, S(-2) * scale)), SE2<S>(), "theta5");
  b.driver(oa);
  Fixture<S> f{b.build(), VectorX<S>(6), {1, 2}};
  // Disk 3 touches the vertex from the convex side (centre (3, 0)) or from inside the cup (centre (1, 0)).
  const S deg = pi<S>() / S(180);
  if (!osculating) f.guess << S(0), S(0), S(180) * deg, S(-3) * deg, S(117) * deg, S(60) * deg;
  else f.guess << S(0), S(0), S(0), S(-3) * deg, S(117) * deg, S(80) * deg;
  return f;
}

/// Planet disk of radius r on an arm (input, revolute at the ring centre) rolling inside a fixed ring of
/// radius R (outside = true: on the outside of a fixed disk, the epicycloid). Variables:
/// arm, planet (relative to the arm), u (ring), v (planet rim). Overconstrained: 4 equations, 3 unknowns.
template <class S> Fixture<S> planet_on_arm(const S& R, const S& r, bool outside) {
  MechanismBuilder<S> b;
  const int ground = b.link("ground", true), arm = b.link("arm"), planet = b.link("planet");
  const S centre = outside ? S(R + r) : S(R - r);
  const int ring = b.contour(ground, "ring", Circle<S>(R), SE2<S>(), !outside);  // ring: material outside
  const int rim = b.contour(planet, "rim", Circle<S>(r));
  const int drive = b.revolute("arm", ground, arm, SE2<S>(), SE2<S>(), "phi");
  b.revolute("planet", arm, planet, SE2<S>(S(0), Vec2<S>(centre, S(0))), SE2<S>(), "psi");
  b.contact("mesh", true, ring, rim, "u", "v");
  b.driver(drive);
  Fixture<S> f{b.build(), VectorX<S>(4), {}};
  // Contact on the +x axis: the ring's point at angle 0 (reversed parameter: u = -0), the planet's at pi or 0.
  f.guess << S(0), S(0), S(0), outside ? pi<S>() : S(0);
  return f;
}

/// Twin elliptical gears (semi-major a, eccentricity e), each on a revolute at a focus, pivots 2a apart;
/// gear 1's nearest vertex touches gear 2's farthest vertex at phi1 = 0. Variables:
/// phi1 (input), u (gear 1, eccentric anomaly), v (gear 2), phi2. The guess is the exact pose at phi1 = start
/// (closed form of docs/method.md section 5): as a cam pair the vertex poses are singular, because the contact
/// normal then passes through both pivots, so a cam mechanism is assembled away from them.
template <class S> Fixture<S> elliptical_gears(const S& a, const S& e, bool rolling, ArcLengthMethod arc = {},
                                               const S& start = S(0)) {
  using std::sqrt;
  MechanismBuilder<S> b;
  const int ground = b.link("ground", true), g1 = b.link("gear1"), g2 = b.link("gear2");
  const S c = a * e, semi_minor = a * sqrt(S(1) - e * e);
  const SE2<S> centre_left_of_focus(S(0), Vec2<S>(-c, S(0)));
  const int e1 = b.contour(g1, "pitch", Ellipse<S>(a, semi_minor, arc), centre_left_of_focus);
  const int e2 = b.contour(g2, "pitch", Ellipse<S>(a, semi_minor, arc), centre_left_of_focus);
  const int drive = b.revolute("pivot1", ground, g1, SE2<S>(), SE2<S>(), "phi1");
  b.contact("mesh", rolling, e1, e2, "u", "v");
  b.revolute("pivot2", ground, g2, SE2<S>(S(0), Vec2<S>(S(2) * a, S(0))), SE2<S>(), "phi2");
  b.driver(drive);
  Fixture<S> f{b.build(), VectorX<S>(4), {}};
  // Gear 1 turned by start: its contact point has polar angle -start about its focus, eccentric anomaly
  // u = 2 atan(sqrt((1-e)/(1+e)) tan(theta/2)); gear 2 turned by phi2 = -2 atan(((1-e)/(1+e)) tan(start/2))
  // touches with its point of polar angle pi - phi2 (measured from its nearest vertex).
  using std::atan;
  using std::tan;
  const S k = sqrt((S(1) - e) / (S(1) + e));
  const S phi2 = S(-2) * atan(k * k * tan(start / S(2)));
  const S u = S(2) * atan(k * tan(-start / S(2)));
  const S theta2 = pi<S>() - phi2;
  const S v = S(2) * atan(k * tan(theta2 / S(2)));
  f.guess << start, u, v, phi2;
  return f;
}

/// Disk of radius r rolling on the ground line y = 0: its centre rides a slider (driven prismatic at
/// height r) and turns on a revolute. Variables: x (input), theta (disk), u (line), v (disk rim).
template <class S> Fixture<S> disk_on_line(const S& r) {
  MechanismBuilder<S> b;
  const int ground = b.link("ground", true), slider = b.link("slider"), disk = b.link("disk");
  // The floor's material lies below it: the line runs along +x with the material on its right (reversed).
  const int line = b.contour(ground, "floor", Line<S>(S(-100) * r, S(100) * r), SE2<S>(), true);
  const int rim = b.contour(disk, "rim", Circle<S>(r));
  const int drive = b.prismatic("slide", ground, slider, SE2<S>(S(0), Vec2<S>(S(0), r)), SE2<S>(), "x");
  b.revolute("axle", slider, disk, SE2<S>(), SE2<S>(), "theta");
  b.contact("tread", true, line, rim, "u", "v");
  b.driver(drive);
  Fixture<S> f{b.build(), VectorX<S>(4), {}};
  f.guess << S(0), S(0), S(0), S(-1) * pi<S>() / S(2);
  return f;
}

/// Four-bar with pivots O2 = (0, 0) and O4 = (o4, 0): crank pin A at `a` in the crank's frame, pin B at
/// `b_coupler` in the coupler's frame (whose origin is A) and at `b_follower` in the follower's frame (origin
/// O4). Links frame, crank, coupler and `follower`; variables theta2 (input), theta3 (coupler on crank),
/// theta_b (follower on coupler), theta4. The caller sets the assembly guess.
template <class S> Fixture<S> four_bar(const Vec2<S>& a, const Vec2<S>& b_coupler, const Vec2<S>& b_follower, const S& o4,
                                       const std::string& follower = "follower") {
  MechanismBuilder<S> b;
  const int frame = b.link("frame", true), crank = b.link("crank"), coupler = b.link("coupler"), out = b.link(follower);
  const int o2 = b.revolute("O2", frame, crank, SE2<S>(), SE2<S>(), "theta2");
  b.revolute("A", crank, coupler, SE2<S>(S(0), a), SE2<S>(), "theta3");
  b.revolute("B", coupler, out, SE2<S>(S(0), b_coupler), SE2<S>(S(0), b_follower), "theta_b");
  b.revolute("O4", frame, out, SE2<S>(S(0), Vec2<S>(o4, S(0))), SE2<S>(), "theta4");
  b.driver(o2);
  return Fixture<S>{b.build(), VectorX<S>(4), {}};
}

/// Crossed four-bar (anti-parallelogram, examples/antiparallelogram.json): frame 4 (pivots O2 = (0, 0),
/// O4 = (4, 0)), coupler 4, cranks 2; the crank's pin at 90 deg in its frame ((0, 2)), the follower's at 0 deg
/// ((2, 0)). Variables: theta2 (input), theta3 (coupler on crank), theta_b (follower on coupler), theta4.
/// Assembled at theta2 = 0 on the crossed branch (pin B at (2.4, -1.2), theta4 = -143.13 deg); at theta2 = 90
/// and 270 deg the joints are in line and the parallelogram branch (theta4 = theta2 + 90) crosses it.
template <class S> Fixture<S> antiparallelogram() {
  const S deg = pi<S>() / S(180);
  Fixture<S> f = four_bar<S>(Vec2<S>(S(0), S(2)), Vec2<S>(S(4), S(0)), Vec2<S>(S(2), S(0)), S(4));
  f.guess << S(0), S(-53) * deg, S(-90) * deg, S(-143) * deg;
  return f;
}

/// Zero unknowns: an open chain whose every pair is driven (a crank on a driven revolute, a slider on a
/// driven prismatic carried by it). Variables: theta (input), s (input). No loop, no equation.
template <class S> Fixture<S> driven_open_chain(const S& scale = S(1)) {
  MechanismBuilder<S> b;
  const int ground = b.link("ground", true), crank = b.link("crank"), slider = b.link("slider");
  const int r = b.revolute("O", ground, crank, SE2<S>(), SE2<S>(), "theta");
  const int p = b.prismatic("P", crank, slider, SE2<S>(S(0), Vec2<S>(S(2) * scale, S(0))), SE2<S>(), "s");
  b.driver(r);
  b.driver(p);
  Fixture<S> f{b.build(), VectorX<S>(2), {}};
  f.guess << S(0), S(0);
  return f;
}

/// Eccentric circular cam (radius R, centre e from the pivot along the cam's x-axis) with a translating
/// follower ending in a roller of radius r fixed to it (roller = true), or in a flat face through its origin
/// tilted by beta from the perpendicular to the stroke.
template <class S> struct CamFollowerDims {
  S R, e;
  bool roller;
  S r, beta;
};

/// The pairs add_eccentric_cam() adds and the exact values of their variables when the cam's angle is 0.
template <class S> struct CamFollower {
  int guide, contact;  // prismatic (variable s), cam pair (variables u, v)
  S s, u, v;
};

/// Adds to link `cam`, which turns on a revolute about the ground point `pivot` with its frame's origin
/// there, an eccentric circular cam (contour "disk<tag>", CamFollowerDims) and a follower link
/// ("follower<tag>") translating along the world y-axis through the pivot (prismatic "guide<tag>", variable s:
/// the follower's height above the pivot), touching the cam through the cam pair "contact<tag>" (u on the cam
/// circle, v the roller's angle or the position along the face).
template <class S> CamFollower<S> add_eccentric_cam(MechanismBuilder<S>& b, int ground, int cam, const Vec2<S>& pivot,
                                                    const CamFollowerDims<S>& d, const std::string& tag = "") {
  using std::atan2;
  using std::cos;
  using std::sin;
  using std::sqrt;
  const S& R = d.R;
  const S& e = d.e;
  const int follower = b.link("follower" + tag);
  const int disk = b.contour(cam, "disk" + tag, Circle<S>(R), SE2<S>(S(0), Vec2<S>(e, S(0))));
  // The follower's frame has its x-axis along the stroke (world +y): a prismatic slides along x.
  const S quarter = pi<S>() / S(2);
  const S reach = S(4) * (R + e);
  const int tip = d.roller ? b.contour(follower, "roller" + tag, Circle<S>(d.r))
                           // In the follower's frame angle beta - 90 deg is the world direction beta; material on
                           // the face's left, i.e. above it (the follower's side).
                           : b.contour(follower, "face" + tag, Line<S>(-reach, reach),
                                       SE2<S>(S(d.beta - quarter), Vec2<S>(S(0), S(0))));
  CamFollower<S> c;
  c.guide = b.prismatic("guide" + tag, ground, follower, SE2<S>(quarter, pivot), SE2<S>(), "s");
  c.contact = b.contact("contact" + tag, false, disk, tip, "u", "v");
  if (d.roller) {
    const S y0 = sqrt((R + d.r) * (R + d.r) - e * e);  // roller centre (0, y0), cam centre (e, 0) from the pivot
    // Contact on the line of centres: cam point in direction (-e, y0); the roller's point in the opposite
    // direction, seen in the follower's frame (turned +90 deg): (-y0, -e).
    c.s = y0;
    c.u = atan2(y0, -e);
    c.v = atan2(-e, -y0);
  } else {
    const Vec2<S> n(-sin(d.beta), cos(d.beta));  // face normal (up), the cam's contact point is C + R n
    const Vec2<S> point = Vec2<S>(e, S(0)) + n * R;
    const S along = point.x() / cos(d.beta);  // point = (0, s) + along (cos beta, sin beta)
    c.s = point.y() - along * sin(d.beta);
    c.u = atan2(n.y(), n.x());
    c.v = along;
  }
  return c;
}

/// Eccentric circular cam (add_eccentric_cam) turning about the origin; input theta, the cam's angle.
/// Variables: theta, s (follower height), u (cam circle), v (roller angle or position along the face).
/// The guess is the exact pose at theta = 0.
template <class S> Fixture<S> eccentric_cam(const S& R, const S& e, bool roller, const S& r, const S& beta = S(0)) {
  MechanismBuilder<S> b;
  const int ground = b.link("ground", true), cam = b.link("cam");
  const int pivot = b.revolute("pivot", ground, cam, SE2<S>(), SE2<S>(), "theta");
  const CamFollower<S> c = add_eccentric_cam<S>(b, ground, cam, Vec2<S>(S(0), S(0)), {R, e, roller, r, beta});
  b.driver(pivot);
  Fixture<S> f{b.build(), VectorX<S>(4), {}};
  f.guess << S(0), c.s, c.u, c.v;
  return f;
}

// ---- generated mechanisms of N loops (tests/test_solve_sparse.cpp and the benchmark's scaling section) ----

/// Radius of disk k of disk_train: 1, 1.5, 0.75, 1.25 repeating (unequal, so the ratios do not cancel).
template <class S> S disk_train_radius(int k) {
  const int pattern[4] = {4, 6, 3, 5};
  return S(pattern[k % 4]) / S(4);
}

/// The disks of a gear train added to a builder: links, revolutes to the ground, pivots, rolling contacts.
template <class S> struct DiskTrain {
  std::vector<int> disk, pivot, mesh;
  std::vector<Vec2<S>> centre;
};

/// Adds n + 1 disks (radii disk_train_radius, links "disk<k>"), each on a revolute "pivot<k>" (variable phi)
/// to the ground, pivots on the x-axis at the sum of neighbouring radii, neighbours rolling on each other
/// ("mesh<k>": disk k, disk k+1; u_k, v_k). The revolutes come first, then the contacts.
template <class S> DiskTrain<S> add_disk_train(MechanismBuilder<S>& b, int ground, int n) {
  DiskTrain<S> t;
  std::vector<int> rim;
  S x(0);
  for (int k = 0; k <= n; ++k) {
    t.disk.push_back(b.link("disk" + std::to_string(k)));
    if (k > 0) x += disk_train_radius<S>(k - 1) + disk_train_radius<S>(k);
    t.centre.emplace_back(x, S(0));
    rim.push_back(b.contour(t.disk.back(), "rim", Circle<S>(disk_train_radius<S>(k))));
    t.pivot.push_back(b.revolute("pivot" + std::to_string(k), ground, t.disk.back(), SE2<S>(S(0), t.centre.back()),
                                 SE2<S>(), "phi"));
  }
  for (int k = 0; k < n; ++k) t.mesh.push_back(b.contact("mesh" + std::to_string(k), true, rim[k], rim[k + 1], "u", "v"));
  return t;
}

/// Assembly guess of a disk train at phi = 0: contact k on the x-axis (u_k = 0, v_k = pi); exact.
template <class S> void disk_train_guess(const MechanismBuilder<S>& b, const DiskTrain<S>& t, VectorX<S>& guess) {
  for (int mesh : t.mesh) guess(b.variable(mesh, 1)) = pi<S>();
}

/// Train of n + 1 disks (add_disk_train): n loops, each closed through its own contact. Variables:
/// phi_0 .. phi_n (phi_0 the input), then (u_k, v_k) of contact k (disk k, disk k+1).
/// Rolling without slip: r_k dphi_k = -r_k+1 dphi_k+1, so phi_k = (-1)^k (r_0 / r_k) phi_0. Overconstrained:
/// each loop's centre distance row repeats what the pivots fix (4n equations, 3n unknowns, rank 3n).
/// Assembled at phi = 0 with contact k on the x-axis (u_k = 0, v_k = pi): the guess is exact.
template <class S> Fixture<S> disk_train(int n) {
  MechanismBuilder<S> b;
  const int ground = b.link("ground", true);
  const DiskTrain<S> t = add_disk_train(b, ground, n);
  b.driver(t.pivot[0]);
  Fixture<S> f{b.build(), VectorX<S>::Zero(3 * n + 1), {}};
  disk_train_guess(b, t, f.guess);
  return f;
}

/// disk_train(n) whose last disk also drives a parallelogram four-bar: a coupler from the pin (0, 2) on disk n
/// (revolute "A", variable psi) to the pin (0, 2) on a rocker (revolute "B", chi) turning about the ground
/// point 4 to the right of disk n's pivot (revolute "O", theta). Redundant as the train: 4n + 3 equations,
/// 3n + 3 unknowns. On the assembled (parallelogram) branch theta = phi_n; the crossed branch meets it where
/// the pins lie on the pivots' line, phi_n = +-90 deg (change points). Assembled at phi = 0 (exact guess).
template <class S> Fixture<S> gear_train_with_parallelogram(int n) {
  MechanismBuilder<S> b;
  const int ground = b.link("ground", true);
  const DiskTrain<S> t = add_disk_train(b, ground, n);
  const int coupler = b.link("coupler"), rocker = b.link("rocker");
  const Vec2<S> pin(S(0), S(2));
  b.revolute("A", t.disk[static_cast<std::size_t>(n)], coupler, SE2<S>(S(0), pin), SE2<S>(), "psi");
  b.revolute("B", coupler, rocker, SE2<S>(S(0), Vec2<S>(S(4), S(0))), SE2<S>(S(0), pin), "chi");
  b.revolute("O", ground, rocker, SE2<S>(S(0), Vec2<S>(t.centre.back() + Vec2<S>(S(4), S(0)))), SE2<S>(), "theta");
  b.driver(t.pivot[0]);
  Fixture<S> f{b.build(), VectorX<S>::Zero(3 * n + 4), {}};
  disk_train_guess(b, t, f.guess);
  return f;
}

/// Cam of stage k of cam_gear_train, scaled with disk k's radius r_k: R = r_k / 2, e = r_k / 5; stages
/// k = 1, 4, 7, ... a roller of radius r_k / 4, k = 2, 5, ... a flat face, k = 3, 6, ... a flat face tilted
/// by 15 deg.
template <class S> CamFollowerDims<S> cam_gear_train_cam(int k) {
  const S rk = disk_train_radius<S>(k);
  const int kind = k % 3;
  return {rk / S(2), rk / S(5), kind == 1, rk / S(4), kind == 0 ? S(pi<S>() / S(12)) : S(0)};
}

/// Mixed cam and gear mechanism of n stages: the gear train of disk_train(n) (disk 0 the input) where each
/// driven disk k = 1 .. n also carries an eccentric circular cam (cam_gear_train_cam(k), add_eccentric_cam
/// with tag k) driving a follower that translates along the vertical through disk k's pivot. Rolling pairs,
/// cam pairs, revolutes and prismatics; 2n loops, 7n equations, 6n unknowns, rank 6n (n redundant rows,
/// the gear train's). Variables: those of disk_train(n), then (s, u, v) of each stage's follower.
/// Closed forms: phi_k = (-1)^k (r_0 / r_k) phi_0; s_k = e sin phi_k + sqrt((R + r)^2 - e^2 cos^2 phi_k)
/// (roller) or (e sin(phi_k - beta) + R) / cos beta (flat face). Assembled at phi = 0 (exact guess).
template <class S> Fixture<S> cam_gear_train(int n) {
  MechanismBuilder<S> b;
  const int ground = b.link("ground", true);
  const DiskTrain<S> t = add_disk_train(b, ground, n);
  std::vector<CamFollower<S>> cams;
  for (int k = 1; k <= n; ++k)
    cams.push_back(add_eccentric_cam(b, ground, t.disk[k], t.centre[k], cam_gear_train_cam<S>(k), std::to_string(k)));
  b.driver(t.pivot[0]);
  Fixture<S> f{b.build(), VectorX<S>::Zero(6 * n + 1), {}};
  disk_train_guess(b, t, f.guess);
  for (const CamFollower<S>& c : cams) {
    f.guess(b.variable(c.guide)) = c.s;
    f.guess(b.variable(c.contact, 0)) = c.u;
    f.guess(b.variable(c.contact, 1)) = c.v;
  }
  return f;
}

/// Dimensions of bar k of four_bar_chain: pivot spacing 4, input pin radius a, output pin radius c
/// alternating (1.5, 2) and (2, 1.5), coupler length sqrt(4^2 + (c - a)^2) (pins straight up at rest).
template <class S> struct ChainBar {
  S a, c, d, coupler;
};
template <class S> ChainBar<S> four_bar_chain_bar(int k) {
  using std::sqrt;
  const S a = k % 2 ? S(2) : S(3) / S(2), c = k % 2 ? S(3) / S(2) : S(2), d(4);
  return {a, c, d, sqrt(d * d + (c - a) * (c - a))};
}

/// Bar k of change_point_chain: bar 0 a parallelogram (pin radii 2, pivot spacing and coupler 4: a Grashof
/// change-point linkage, whose parallelogram and crossed branches meet where the pins lie on the pivots' line,
/// at rocker angles +-90 deg), the others crank-rockers (input pin radius 1.5, output 2: the input turns fully,
/// transmission angle between 30 and 128 deg, so no bar after the first has a singular pose).
template <class S> ChainBar<S> change_point_chain_bar(int k) {
  using std::sqrt;
  const S d(4);
  if (k == 0) return {S(2), S(2), d, d};
  const S a = S(3) / S(2), c(2);
  return {a, c, d, sqrt(d * d + (c - a) * (c - a))};
}

/// Chain of n four-bars: n + 1 rockers turning about ground pivots (4 apart on the x-axis), rocker k joined
/// to rocker k + 1 by coupler k (pins at radius a on rocker k and c on rocker k + 1, both straight up, i.e.
/// at (0, a) and (0, c) in the rockers' frames; four_bar_chain_bar). n loops, 3n equations, 3n unknowns.
/// Variables: theta_0 .. theta_n (theta_0 the input), then per coupler (psi_k, chi_k): the coupler's angle on
/// rocker k and rocker k+1's on the coupler. Assembled at theta = 0 (exact guess). `bar_of` gives the
/// dimensions (four_bar_chain_bar; change_point_chain_bar for a chain that passes singular poses); the pivots
/// are 4 apart whatever it says.
template <class S> Fixture<S> four_bar_chain(int n, ChainBar<S> (*bar_of)(int) = four_bar_chain_bar<S>) {
  using std::atan2;
  MechanismBuilder<S> b;
  const int ground = b.link("ground", true);
  std::vector<int> rocker, pivot;
  for (int k = 0; k <= n; ++k) {
    rocker.push_back(b.link("rocker" + std::to_string(k)));
    pivot.push_back(b.revolute("pivot" + std::to_string(k), ground, rocker[k],
                               SE2<S>(S(0), Vec2<S>(S(4) * S(k), S(0))), SE2<S>(), "theta"));
  }
  std::vector<S> alpha;  // couplers' angles at rest
  for (int k = 0; k < n; ++k) {
    const ChainBar<S> bar = bar_of(k);
    const int coupler = b.link("coupler" + std::to_string(k));
    b.revolute("A" + std::to_string(k), rocker[k], coupler, SE2<S>(S(0), Vec2<S>(S(0), bar.a)), SE2<S>(), "psi");
    b.revolute("B" + std::to_string(k), coupler, rocker[k + 1], SE2<S>(S(0), Vec2<S>(bar.coupler, S(0))),
               SE2<S>(S(0), Vec2<S>(S(0), bar.c)), "chi");
    alpha.push_back(atan2(bar.c - bar.a, bar.d));
  }
  b.driver(pivot[0]);
  Fixture<S> f{b.build(), VectorX<S>::Zero(3 * n + 1), {}};
  for (int k = 0; k < n; ++k) {
    f.guess(n + 1 + 2 * k) = alpha[static_cast<std::size_t>(k)];
    f.guess(n + 2 + 2 * k) = -alpha[static_cast<std::size_t>(k)];
  }
  return f;
}

/// Assembles a fixture; returns the report (q holds the assembled pose, sd is ready for sweep()).
template <class S> SolveReport<S> assemble_fixture(const Fixture<S>& f, VectorX<S>& q, SolveData<S>& sd) {
  q = f.guess;
  return assemble(f.mech, q, sd, f.held);
}

/// Assembles a fixture and sweeps its first driver over `inputs`; the assembly report goes to *assembly.
inline SweepResult<double> assemble_and_sweep(const Fixture<double>& f, const std::vector<double>& inputs,
                                              SolveReport<double>* assembly = nullptr) {
  SolveData<double> sd(f.mech);
  VectorX<double> q;
  const auto rep = assemble_fixture(f, q, sd);
  if (assembly) *assembly = rep;
  return sweep(f.mech, sd, q, rep, 0, inputs);
}

template <class S> std::vector<S> degrees(int from, int to, int step = 1) {
  std::vector<S> v;
  for (int d = from; step > 0 ? d <= to : d >= to; d += step) v.push_back(S(d) * pi<S>() / S(180));
  return v;
}

}  // namespace rollkin::testing
