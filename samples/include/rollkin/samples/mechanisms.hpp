// Sample mechanisms built in code, for the tests and the benchmark (the scene files in examples/ describe the
// same ones). Templates on the scalar so the MPFR tests run the very same mechanisms. Declarations only: the
// bodies are compiled once, for double and mpfr50, in samples/src/mechanisms.cpp (the rollkin_samples
// library beside the library, as Pinocchio's sample models), so a translation unit that uses a sample
// neither builds the mechanism's code again nor the solver (docs/benchmark.md, "Build times").
#pragma once

#include "rollkin/mechanism.hpp"
#include "rollkin/profile/arc_length.hpp"
#include "rollkin/solve/position.hpp"
#include "rollkin/solve/sweep_result.hpp"

#include <string>
#include <vector>

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
                                            ArcLengthMethod arc = {});


/// Planet disk of radius r on an arm (input, revolute at the ring centre) rolling inside a fixed ring of
/// radius R (outside = true: on the outside of a fixed disk, the epicycloid). Variables:
/// arm, planet (relative to the arm), u (ring), v (planet rim). Overconstrained: 4 equations, 3 unknowns.
template <class S> Fixture<S> planet_on_arm(const S& R, const S& r, bool outside);


/// Twin elliptical gears (semi-major a, eccentricity e), each on a revolute at a focus, pivots 2a apart;
/// gear 1's nearest vertex touches gear 2's farthest vertex at phi1 = 0. Variables:
/// phi1 (input), u (gear 1, eccentric anomaly), v (gear 2), phi2. The guess is the exact pose at phi1 = start
/// (closed form of docs/method.md section 5): as a cam pair the vertex poses are singular, because the contact
/// normal then passes through both pivots, so a cam mechanism is assembled away from them.
template <class S> Fixture<S> elliptical_gears(const S& a, const S& e, bool rolling, ArcLengthMethod arc = {},
                                               const S& start = S(0));


/// Disk of radius r rolling on the ground line y = 0: its centre rides a slider (driven prismatic at
/// height r) and turns on a revolute. Variables: x (input), theta (disk), u (line), v (disk rim).
template <class S> Fixture<S> disk_on_line(const S& r);


/// Four-bar with pivots O2 = (0, 0) and O4 = (o4, 0): crank pin A at `a` in the crank's frame, pin B at
/// `b_coupler` in the coupler's frame (whose origin is A) and at `b_follower` in the follower's frame (origin
/// O4). Links frame, crank, coupler and `follower`; variables theta2 (input), theta3 (coupler on crank),
/// theta_b (follower on coupler), theta4. The caller sets the assembly guess.
template <class S> Fixture<S> four_bar(const Vec2<S>& a, const Vec2<S>& b_coupler, const Vec2<S>& b_follower, const S& o4,
                                       const std::string& follower = "follower");


/// Crossed four-bar (anti-parallelogram, examples/antiparallelogram.json): frame 4 (pivots O2 = (0, 0),
/// O4 = (4, 0)), coupler 4, cranks 2; the crank's pin at 90 deg in its frame ((0, 2)), the follower's at 0 deg
/// ((2, 0)). Variables: theta2 (input), theta3 (coupler on crank), theta_b (follower on coupler), theta4.
/// Assembled at theta2 = 0 on the crossed branch (pin B at (2.4, -1.2), theta4 = -143.13 deg); at theta2 = 90
/// and 270 deg the joints are in line and the parallelogram branch (theta4 = theta2 + 90) crosses it.
template <class S> Fixture<S> antiparallelogram();


/// Zero unknowns: an open chain whose every pair is driven (a crank on a driven revolute, a slider on a
/// driven prismatic carried by it). Variables: theta (input), s (input). No loop, no equation.
template <class S> Fixture<S> driven_open_chain(const S& scale = S(1));


/// Eccentric circular cam (radius R, centre e from the pivot along the cam's x-axis) with a translating
/// follower ending in a roller of radius r fixed to it (roller = true), or in a flat face through its origin
/// tilted by beta from the perpendicular to the stroke.
template <class S> struct CamFollowerDims {
  S R, e;
  bool roller;
  S r, beta;
};


/// Eccentric circular cam (add_eccentric_cam) turning about the origin; input theta, the cam's angle.
/// Variables: theta, s (follower height), u (cam circle), v (roller angle or position along the face).
/// The guess is the exact pose at theta = 0.
template <class S> Fixture<S> eccentric_cam(const S& R, const S& e, bool roller, const S& r, const S& beta = S(0));


// ---- generated mechanisms of N loops (tests/test_solve_sparse.cpp and the benchmark's scaling section) ----

/// Radius of disk k of disk_train: 1, 1.5, 0.75, 1.25 repeating (unequal, so the ratios do not cancel).
template <class S> S disk_train_radius(int k);


/// Train of n + 1 disks (add_disk_train): n loops, each closed through its own contact. Variables:
/// phi_0 .. phi_n (phi_0 the input), then (u_k, v_k) of contact k (disk k, disk k+1).
/// Rolling without slip: r_k dphi_k = -r_k+1 dphi_k+1, so phi_k = (-1)^k (r_0 / r_k) phi_0. Overconstrained:
/// each loop's centre distance row repeats what the pivots fix (4n equations, 3n unknowns, rank 3n).
/// Assembled at phi = 0 with contact k on the x-axis (u_k = 0, v_k = pi): the guess is exact.
template <class S> Fixture<S> disk_train(int n);


/// disk_train(n) whose last disk also drives a parallelogram four-bar: a coupler from the pin (0, 2) on disk n
/// (revolute "A", variable psi) to the pin (0, 2) on a rocker (revolute "B", chi) turning about the ground
/// point 4 to the right of disk n's pivot (revolute "O", theta). Redundant as the train: 4n + 3 equations,
/// 3n + 3 unknowns. On the assembled (parallelogram) branch theta = phi_n; the crossed branch meets it where
/// the pins lie on the pivots' line, phi_n = +-90 deg (change points). Assembled at phi = 0 (exact guess).
template <class S> Fixture<S> gear_train_with_parallelogram(int n);


/// Cam of stage k of cam_gear_train, scaled with disk k's radius r_k: R = r_k / 2, e = r_k / 5; stages
/// k = 1, 4, 7, ... a roller of radius r_k / 4, k = 2, 5, ... a flat face, k = 3, 6, ... a flat face tilted
/// by 15 deg.
template <class S> CamFollowerDims<S> cam_gear_train_cam(int k);


/// Mixed cam and gear mechanism of n stages: the gear train of disk_train(n) (disk 0 the input) where each
/// driven disk k = 1 .. n also carries an eccentric circular cam (cam_gear_train_cam(k), add_eccentric_cam
/// with tag k) driving a follower that translates along the vertical through disk k's pivot. Rolling pairs,
/// cam pairs, revolutes and prismatics; 2n loops, 7n equations, 6n unknowns, rank 6n (n redundant rows,
/// the gear train's). Variables: those of disk_train(n), then (s, u, v) of each stage's follower.
/// Closed forms: phi_k = (-1)^k (r_0 / r_k) phi_0; s_k = e sin phi_k + sqrt((R + r)^2 - e^2 cos^2 phi_k)
/// (roller) or (e sin(phi_k - beta) + R) / cos beta (flat face). Assembled at phi = 0 (exact guess).
template <class S> Fixture<S> cam_gear_train(int n);


/// Dimensions of bar k of four_bar_chain: pivot spacing 4, input pin radius a, output pin radius c
/// alternating (1.5, 2) and (2, 1.5), coupler length sqrt(4^2 + (c - a)^2) (pins straight up at rest).
template <class S> struct ChainBar {
  S a, c, d, coupler;
};

template <class S> ChainBar<S> four_bar_chain_bar(int k);


/// Bar k of change_point_chain: bar 0 a parallelogram (pin radii 2, pivot spacing and coupler 4: a Grashof
/// change-point linkage, whose parallelogram and crossed branches meet where the pins lie on the pivots' line,
/// at rocker angles +-90 deg), the others crank-rockers (input pin radius 1.5, output 2: the input turns fully,
/// transmission angle between 30 and 128 deg, so no bar after the first has a singular pose).
template <class S> ChainBar<S> change_point_chain_bar(int k);


/// Chain of n four-bars: n + 1 rockers turning about ground pivots (4 apart on the x-axis), rocker k joined
/// to rocker k + 1 by coupler k (pins at radius a on rocker k and c on rocker k + 1, both straight up, i.e.
/// at (0, a) and (0, c) in the rockers' frames; four_bar_chain_bar). n loops, 3n equations, 3n unknowns.
/// Variables: theta_0 .. theta_n (theta_0 the input), then per coupler (psi_k, chi_k): the coupler's angle on
/// rocker k and rocker k+1's on the coupler. Assembled at theta = 0 (exact guess). `bar_of` gives the
/// dimensions (four_bar_chain_bar; change_point_chain_bar for a chain that passes singular poses); the pivots
/// are 4 apart whatever it says.
template <class S> Fixture<S> four_bar_chain(int n, ChainBar<S> (*bar_of)(int) = four_bar_chain_bar<S>);


/// Assembles a fixture; returns the report (q holds the assembled pose, sd is ready for sweep()).
template <class S> SolveReport<S> assemble_fixture(const Fixture<S>& f, VectorX<S>& q, SolveData<S>& sd) {
  q = f.guess;
  return assemble(f.mech, q, sd, f.held);
}


/// Assembles a fixture and sweeps its first driver over `inputs`; the assembly report goes to *assembly.
SweepResult<double> assemble_and_sweep(const Fixture<double>& f, const std::vector<double>& inputs,
                                              SolveReport<double>* assembly = nullptr);


template <class S> std::vector<S> degrees(int from, int to, int step = 1) {
  std::vector<S> v;
  for (int d = from; step > 0 ? d <= to : d >= to; d += step) v.push_back(S(d) * pi<S>() / S(180));
  return v;
}

}  // namespace rollkin::testing
