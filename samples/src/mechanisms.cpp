// The sample mechanisms of rollkin/samples/mechanisms.hpp, compiled once for double and mpfr50.
#include "rollkin/samples/mechanisms.hpp"

#include "rollkin/builder.hpp"
#include "rollkin/scalar_mpfr.hpp"
#include "rollkin/solve/continuation.hpp"

#include <cmath>

namespace rollkin::testing {
namespace {


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

}  // namespace

template <class S> Fixture<S> paper_fourbar(const S& scale, bool osculating,
                                            ArcLengthMethod arc) {
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

template <class S> Fixture<S> elliptical_gears(const S& a, const S& e, bool rolling, ArcLengthMethod arc,
                                               const S& start) {
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

template <class S> Fixture<S> four_bar(const Vec2<S>& a, const Vec2<S>& b_coupler, const Vec2<S>& b_follower, const S& o4,
                                       const std::string& follower) {
  MechanismBuilder<S> b;
  const int frame = b.link("frame", true), crank = b.link("crank"), coupler = b.link("coupler"), out = b.link(follower);
  const int o2 = b.revolute("O2", frame, crank, SE2<S>(), SE2<S>(), "theta2");
  b.revolute("A", crank, coupler, SE2<S>(S(0), a), SE2<S>(), "theta3");
  b.revolute("B", coupler, out, SE2<S>(S(0), b_coupler), SE2<S>(S(0), b_follower), "theta_b");
  b.revolute("O4", frame, out, SE2<S>(S(0), Vec2<S>(o4, S(0))), SE2<S>(), "theta4");
  b.driver(o2);
  return Fixture<S>{b.build(), VectorX<S>(4), {}};
}

template <class S> Fixture<S> antiparallelogram() {
  const S deg = pi<S>() / S(180);
  Fixture<S> f = four_bar<S>(Vec2<S>(S(0), S(2)), Vec2<S>(S(4), S(0)), Vec2<S>(S(2), S(0)), S(4));
  f.guess << S(0), S(-53) * deg, S(-90) * deg, S(-143) * deg;
  return f;
}

template <class S> Fixture<S> driven_open_chain(const S& scale) {
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

template <class S> Fixture<S> eccentric_cam(const S& R, const S& e, bool roller, const S& r, const S& beta) {
  MechanismBuilder<S> b;
  const int ground = b.link("ground", true), cam = b.link("cam");
  const int pivot = b.revolute("pivot", ground, cam, SE2<S>(), SE2<S>(), "theta");
  const CamFollower<S> c = add_eccentric_cam<S>(b, ground, cam, Vec2<S>(S(0), S(0)), {R, e, roller, r, beta});
  b.driver(pivot);
  Fixture<S> f{b.build(), VectorX<S>(4), {}};
  f.guess << S(0), c.s, c.u, c.v;
  return f;
}

template <class S> S disk_train_radius(int k) {
  const int pattern[4] = {4, 6, 3, 5};
  return S(pattern[k % 4]) / S(4);
}

template <class S> Fixture<S> disk_train(int n) {
  MechanismBuilder<S> b;
  const int ground = b.link("ground", true);
  const DiskTrain<S> t = add_disk_train(b, ground, n);
  b.driver(t.pivot[0]);
  Fixture<S> f{b.build(), VectorX<S>::Zero(3 * n + 1), {}};
  disk_train_guess(b, t, f.guess);
  return f;
}

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

template <class S> CamFollowerDims<S> cam_gear_train_cam(int k) {
  const S rk = disk_train_radius<S>(k);
  const int kind = k % 3;
  return {rk / S(2), rk / S(5), kind == 1, rk / S(4), kind == 0 ? S(pi<S>() / S(12)) : S(0)};
}

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

template <class S> ChainBar<S> four_bar_chain_bar(int k) {
  using std::sqrt;
  const S a = k % 2 ? S(2) : S(3) / S(2), c = k % 2 ? S(3) / S(2) : S(2), d(4);
  return {a, c, d, sqrt(d * d + (c - a) * (c - a))};
}

template <class S> ChainBar<S> change_point_chain_bar(int k) {
  using std::sqrt;
  const S d(4);
  if (k == 0) return {S(2), S(2), d, d};
  const S a = S(3) / S(2), c(2);
  return {a, c, d, sqrt(d * d + (c - a) * (c - a))};
}

template <class S> Fixture<S> four_bar_chain(int n, ChainBar<S> (*bar_of)(int)) {
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

SweepResult<double> assemble_and_sweep(const Fixture<double>& f, const std::vector<double>& inputs,
                                              SolveReport<double>* assembly) {
  SolveData<double> sd(f.mech);
  VectorX<double> q;
  const auto rep = assemble_fixture(f, q, sd);
  if (assembly) *assembly = rep;
  return sweep(f.mech, sd, q, rep, 0, inputs);
}

// The samples for one scalar S (the scalars the tests and the benchmark build them in).
#define ROLLKIN_SAMPLES_INSTANCES(S)                                                                          \
  template Fixture<S> paper_fourbar(const S&, bool, ArcLengthMethod);                                          \
  template Fixture<S> planet_on_arm(const S&, const S&, bool);                                                 \
  template Fixture<S> elliptical_gears(const S&, const S&, bool, ArcLengthMethod, const S&);                   \
  template Fixture<S> disk_on_line(const S&);                                                                  \
  template Fixture<S> four_bar(const Vec2<S>&, const Vec2<S>&, const Vec2<S>&, const S&, const std::string&);  \
  template Fixture<S> antiparallelogram();                                                                     \
  template Fixture<S> driven_open_chain(const S&);                                                             \
  template Fixture<S> eccentric_cam(const S&, const S&, bool, const S&, const S&);                             \
  template S disk_train_radius(int);                                                                           \
  template Fixture<S> disk_train(int);                                                                         \
  template Fixture<S> gear_train_with_parallelogram(int);                                                      \
  template CamFollowerDims<S> cam_gear_train_cam(int);                                                         \
  template Fixture<S> cam_gear_train(int);                                                                     \
  template ChainBar<S> four_bar_chain_bar(int);                                                                \
  template ChainBar<S> change_point_chain_bar(int);                                                            \
  template Fixture<S> four_bar_chain(int, ChainBar<S> (*)(int));

ROLLKIN_SAMPLES_INSTANCES(double)
ROLLKIN_SAMPLES_INSTANCES(mpfr50)

}  // namespace rollkin::testing
