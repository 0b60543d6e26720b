// Property tests over random inputs (seeded: every run draws the same cases; a failure names its case).
//  - Random valid mechanisms, solved in double, agree with the MPFR (50 digits) run of the same code on the
//    same mechanism (Mechanism::cast: every double number taken exactly), to a tolerance derived from the
//    pose's condition estimate and epsilon: |q_double - q_mpfr| / scale <= 64 eps cond (1 + |q| / scale).
//      * gear trains of 2..4 rolling circles on fixed pivots (and the closed form phi_k = (-1)^k r0/rk phi0,
//        in MPFR, which proves the reference itself);
//      * four-bars of revolutes in their Grashof crank-rocker range (transmission angle kept in
//        [35, 145] deg) (and the closed-form rocker angle, in MPFR);
//      * cam pairs: an elliptical (near-circular) cam on the crank pivot against a circular follower
//        on a rocker (the circle-circle case is the four-bar above, same margins);
//    every length multiplied by a random scale factor 10^U(-6, 6).
//  - Every truncation of a valid scene file (examples/*.json) before its closing brace is an InputError
//    from parse_scene (the CLI side, exit 2 with outputs untouched, is in tests/cli/run_cli_tests.sh).
#define BOOST_TEST_MODULE property
#include <boost/test/unit_test.hpp>

#include "rollkin/samples/mechanisms.hpp"
#include "rollkin/builder.hpp"
#include "rollkin/io/scene/reader.hpp"
#include "rollkin/scalar_mpfr.hpp"
#include "rollkin/solve/mpfr50_instances.hpp"
#include "test_support.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace rollkin;
using namespace rollkin::testing;
using M = mpfr50;

namespace {

#ifdef ROLLKIN_SANITIZED
constexpr int cases_per_family = 3;  // the sanitizer build (10-50x slower) draws fewer cases, same checks
#else
constexpr int cases_per_family = 8;
#endif

using Rng = std::mt19937_64;

double uniform(Rng& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

/// 10^U(-6, 6): the scale every length of a random mechanism is multiplied by.
double random_scale(Rng& rng) { return std::pow(10.0, uniform(rng, -6, 6)); }  // (gear trains: powers of two)

/// A random mechanism in double, with a description of the draw for failure messages and the closed form
/// (in MPFR) of one variable against the input, when there is one.
struct Case {
  std::string name;
  Fixture<double> f;
  std::vector<double> inputs;  // radians
  int checked = -1;            // variable with a closed form, or -1
  std::function<M(const M&, const VectorX<M>&)> closed_form;  // (input, assembled pose)
};

std::vector<double> degrees_grid(double from, double to, double step) {
  std::vector<double> v;
  for (double d = from; d <= to + 1e-9; d += step) v.push_back(d * pi<double>() / 180);
  return v;
}

// ---- gear train ----------------------------------------------------------------------------------------
/// Gears 0..n-1 on fixed pivots, gear k + 1 touching gear k from outside in the direction (a, b) / c of a
/// Pythagorean triple. Radii are integers, pivot offsets integer multiples of (a, b) and the scale a power of
/// two, so every length is exact in double: the rolling constraint is redundant and must stay consistent to
/// 50 digits in the MPFR run, which a rounded pivot position would break. Each rolling pair's parameters
/// are polar angles (circle parameter): u = atan2(b, a) on gear k and v = u + pi on gear k + 1 at phi = 0.
/// Variables: phi0 (input), then per gear k >= 1: phi_k and u, v of the mesh.
Case gear_train(Rng& rng) {
  static const int triples[][3] = {{3, 4, 5}, {4, 3, 5}, {5, 12, 13}, {12, 5, 13}, {8, 15, 17}, {1, 0, 1}, {0, 1, 1}};
  const int n = std::uniform_int_distribution<int>(2, 4)(rng);
  const double scale = std::ldexp(1.0, std::uniform_int_distribution<int>(-20, 20)(rng));  // 1e-6 .. 1e6
  std::vector<double> r{double(std::uniform_int_distribution<int>(1, 12)(rng))}, a;
  std::vector<Vec2<double>> offsets;
  while (static_cast<int>(r.size()) < n) {
    const int* t = triples[std::uniform_int_distribution<int>(0, 6)(rng)];
    const int next = std::uniform_int_distribution<int>(1, 12)(rng);
    if ((static_cast<int>(r.back()) + next) % t[2] != 0) continue;
    const int m = (static_cast<int>(r.back()) + next) / t[2];
    const int sx = std::uniform_int_distribution<int>(0, 1)(rng) ? 1 : -1, sy = std::uniform_int_distribution<int>(0, 1)(rng) ? 1 : -1;
    offsets.emplace_back(sx * m * t[0] * scale, sy * m * t[1] * scale);
    a.push_back(std::atan2(double(sy * t[1]), double(sx * t[0])));
    r.push_back(next);
  }
  MechanismBuilder<double> b;
  const int ground = b.link("ground", true);
  std::vector<int> gears, rims, pivots, meshes;
  Vec2<double> centre(0, 0);
  for (int k = 0; k < n; ++k) {
    if (k > 0) centre += offsets[k - 1];
    gears.push_back(b.link("gear" + std::to_string(k)));
    rims.push_back(b.contour(gears[k], "rim", Circle<double>(r[k] * scale)));
    pivots.push_back(b.revolute("pivot" + std::to_string(k), ground, gears[k], SE2<double>(0, centre), {},
                                "phi" + std::to_string(k)));
    if (k > 0) meshes.push_back(b.contact("mesh" + std::to_string(k), true, rims[k - 1], rims[k], "u", "v"));
  }
  b.driver(pivots[0]);
  Case c;
  c.f = {b.build(), {}, {}};
  const Mechanism<double>& m = c.f.mech;
  c.f.guess = VectorX<double>::Zero(m.variable_count());
  for (int k = 1; k < n; ++k) {
    c.f.guess(b.variable(meshes[k - 1], 0)) = a[k - 1];
    c.f.guess(b.variable(meshes[k - 1], 1)) = a[k - 1] + pi<double>();
  }
  c.inputs = degrees_grid(-180, 180, 30);
  c.checked = b.variable(pivots[n - 1]);
  // Pure rolling of gear k on gear k + 1: r_k dphi_k = -r_{k+1} dphi_{k+1}, counted from the assembled pose
  // (a circle's turn is fixed by the rolling rows relative to it, not by the loops).
  const M ratio = M((n - 1) % 2 ? -1 : 1) * M(r[0]) / M(r[n - 1]);
  const int last = c.checked;
  c.closed_form = [ratio, last](const M& phi0, const VectorX<M>& q0) { return q0(last) + ratio * (phi0 - q0(0)); };
  std::ostringstream name;
  name << "gear train of " << n << " (scale " << scale << ")";
  c.name = name.str();
  return c;
}

// ---- four-bar and cam: lengths of a Grashof crank-rocker with good transmission ------------------------
struct FourBar {
  double crank, coupler, rocker, frame;
};

/// Angle between coupler and rocker at crank angle t (law of cosines on the diagonal B-D).
double transmission_angle(const FourBar& g, double t) {
  const double diagonal2 = g.crank * g.crank + g.frame * g.frame - 2 * g.crank * g.frame * std::cos(t);
  return std::acos((g.coupler * g.coupler + g.rocker * g.rocker - diagonal2) / (2 * g.coupler * g.rocker));
}

/// Crank shortest, s + l < p + q, and the transmission angle in [35, 145] deg over the whole turn.
FourBar random_crank_rocker(Rng& rng) {
  for (;;) {
    FourBar g{uniform(rng, 0.1, 0.6), uniform(rng, 0.8, 2.0), uniform(rng, 0.8, 2.0), uniform(rng, 0.8, 2.0)};
    const double l = std::max({g.coupler, g.rocker, g.frame});
    if (g.crank + l >= g.coupler + g.rocker + g.frame - l) continue;
    bool good = true;
    for (int k = 0; k < 360 && good; ++k) {
      const double mu = transmission_angle(g, k * pi<double>() / 180) * 180 / pi<double>();
      good = mu > 35 && mu < 145;
    }
    if (good) return g;
  }
}

/// World angles of coupler (B -> C) and rocker (D -> C) at crank angle t, on the branch with C above the
/// diagonal B -> D (turning left from it); templated so that the closed form runs in MPFR.
template <class S> std::pair<S, S> four_bar_angles(const FourBar& g, const S& t) {
  using std::atan2;
  using std::cos;
  using std::sin;
  using std::sqrt;
  const S a(g.crank), b(g.coupler), c(g.rocker), d(g.frame);
  const Vec2<S> B(a * cos(t), a * sin(t)), D(d, S(0));
  const Vec2<S> BD = D - B;
  const S e2 = BD.squaredNorm(), e = sqrt(e2);
  const S along = (b * b - c * c + e2) / (S(2) * e);  // from B towards D
  const S across = sqrt(b * b - along * along);
  const Vec2<S> unit = BD / e, left(-unit.y(), unit.x());
  const Vec2<S> C = B + along * unit + across * left;
  return {atan2(C.y() - B.y(), C.x() - B.x()), atan2(C.y() - D.y(), C.x() - D.x())};
}

/// Frame (ground) A at the origin, D at (frame, 0); crank A -> B, coupler B -> C, rocker D -> C, each
/// link's x axis along its bar. Variables: theta2 (input), theta3 (coupler - crank), theta34 (rocker -
/// coupler), theta4 (rocker).
Case crank_rocker(Rng& rng) {
  const FourBar g = random_crank_rocker(rng);
  const double s = random_scale(rng);
  MechanismBuilder<double> b;
  const int frame = b.link("frame", true), crank = b.link("crank"), coupler = b.link("coupler"), rocker = b.link("rocker");
  const int drive = b.revolute("A", frame, crank, {}, {}, "theta2");
  b.revolute("B", crank, coupler, SE2<double>(0, Vec2<double>(g.crank * s, 0)), {}, "theta3");
  b.revolute("C", coupler, rocker, SE2<double>(0, Vec2<double>(g.coupler * s, 0)), SE2<double>(0, Vec2<double>(g.rocker * s, 0)),
             "theta34");
  b.revolute("D", frame, rocker, SE2<double>(0, Vec2<double>(g.frame * s, 0)), {}, "theta4");
  b.driver(drive);
  Case c;
  c.f = {b.build(), VectorX<double>(4), {}};
  // Each link's x axis runs along its bar: the link angles are the bar angles, the pair variables their
  // differences.
  const auto [coupler0, rocker0] = four_bar_angles<double>(g, 0.0);
  c.f.guess << 0, coupler0, rocker0 - coupler0, rocker0;
  c.inputs = degrees_grid(0, 360, 30);
  c.checked = 3;
  // The closed form on the very lengths the mechanism holds (scaled and rounded in double).
  const FourBar exact{g.crank * s, g.coupler * s, g.rocker * s, g.frame * s};
  c.closed_form = [exact](const M& t, const VectorX<M>&) { return four_bar_angles<M>(exact, t).second; };
  std::ostringstream name;
  name << "four-bar " << g.crank << ", " << g.coupler << ", " << g.rocker << ", " << g.frame << " (scale " << s << ")";
  c.name = name.str();
  return c;
}

/// Cam: an ellipse (semi-axes R, R (1 - flat), flat in [0, 0.08]) centred at (crank, 0) on the crank link,
/// pivoted at the origin; follower: a circle of radius r centred at (rocker, 0) on a rocker pivoted at
/// (frame, 0). With flat = 0 this is the four-bar of coupler R + r; the margins of random_crank_rocker hold
/// the contact normal away from the follower's pivot. Variables: theta2 (input), phi (rocker), u, v.
Case cam_pair(Rng& rng) {
  const FourBar g = random_crank_rocker(rng);
  const double s = random_scale(rng);
  const double follower_radius = uniform(rng, 0.2, 0.45) * g.coupler, cam_radius = g.coupler - follower_radius;
  const double flat = uniform(rng, 0, 0.08);
  MechanismBuilder<double> b;
  const int frame = b.link("frame", true), cam = b.link("cam"), follower = b.link("follower");
  const int cam_contour = b.contour(cam, "disk", Ellipse<double>(cam_radius * s, cam_radius * (1 - flat) * s),
                                    SE2<double>(0, Vec2<double>(g.crank * s, 0)));
  const int roller = b.contour(follower, "roller", Circle<double>(follower_radius * s),
                               SE2<double>(0, Vec2<double>(g.rocker * s, 0)));
  const int drive = b.revolute("O1", frame, cam, {}, {}, "theta2");
  b.revolute("O2", frame, follower, SE2<double>(0, Vec2<double>(g.frame * s, 0)), {}, "phi");
  b.contact("K", false, cam_contour, roller, "u", "v");
  b.driver(drive);
  Case c;
  c.f = {b.build(), VectorX<double>(4), {}};
  // Guess from the circle case: the contact lies on the line of centres B -> C.
  const auto [coupler0, rocker0] = four_bar_angles<double>(g, 0.0);
  c.f.guess << 0, rocker0, coupler0, coupler0 + pi<double>() - rocker0;
  c.inputs = degrees_grid(0, 360, 30);
  std::ostringstream name;
  name << "cam: ellipse flat " << flat << ", four-bar " << g.crank << ", " << g.coupler << ", " << g.rocker << ", "
       << g.frame << " (scale " << s << ")";
  c.name = name.str();
  return c;
}

/// Solves the case in double and in MPFR and checks every variable at every input.
void check_double_against_mpfr(const Case& c) {
  BOOST_TEST_CONTEXT(c.name) {
    const Mechanism<double>& m = c.f.mech;
    SolveData<double> sd(m);
    VectorX<double> q0;
    const SolveReport<double> assembly = assemble_fixture(c.f, q0, sd);
    BOOST_TEST_REQUIRE(assembly.ok(), "assembly: " << assembly.detail);
    const SweepResult<double> rd = sweep(m, sd, q0, assembly, 0, c.inputs);

    const Fixture<M> fm{m.cast<M>(), c.f.guess.cast<M>(), c.f.held};
    SolveData<M> sdm(fm.mech);
    VectorX<M> q0m;
    const SolveReport<M> assembly_m = assemble_fixture(fm, q0m, sdm);
    BOOST_TEST_REQUIRE(assembly_m.ok(), "MPFR assembly: " << assembly_m.detail);
    std::vector<M> inputs_m;
    for (double t : c.inputs) inputs_m.push_back(M(t));
    const SweepResult<M> rm = sweep(fm.mech, sdm, q0m, assembly_m, 0, inputs_m);

    const double eps = std::numeric_limits<double>::epsilon();
    double worst_ratio = 0;  // largest error / tolerance, logged
    for (std::size_t k = 0; k < c.inputs.size(); ++k) {
      const SolveReport<double>& rep = rd.poses[k].report;
      BOOST_TEST_REQUIRE(rep.ok(), "double at input " << c.inputs[k] << ": " << rep.status << " " << rep.detail);
      BOOST_TEST_REQUIRE(rm.poses[k].report.ok(), "MPFR at input " << c.inputs[k] << ": " << rm.poses[k].report.detail);
      const double condition = std::max(1.0, rep.condition);
      for (int i = 0; i < m.variable_count(); ++i) {
        const double scale = m.variable_scale(i);
        const M& exact = rm.poses[k].q(i);
        const double error = to_double(abs(M(rd.poses[k].q(i)) - exact)) / scale;
        const double tol = 64 * eps * condition * (1 + std::abs(to_double(exact)) / scale);
        worst_ratio = std::max(worst_ratio, error / tol);
        BOOST_TEST(error <= tol, m.variables[i].name << " at input " << c.inputs[k] << ": error " << error
                                                     << " > " << tol << " (condition " << rep.condition << ")");
      }
      if (c.checked >= 0) {  // the MPFR run itself against the closed form
        const M truth = c.closed_form(inputs_m[k], q0m);
        const M error = abs(wrap_angle(M(rm.poses[k].q(c.checked) - truth)));
        BOOST_TEST(error < M(std::string("1e-35")),
                   "MPFR " << m.variables[c.checked].name << " vs closed form at " << c.inputs[k] << ": " << error.str(3));
      }
    }
    BOOST_TEST_MESSAGE(c.name << ": largest error / tolerance " << worst_ratio);
  }
}

template <class Draw> void run_family(std::uint64_t seed, Draw draw) {
  Rng rng(seed);
  for (int i = 0; i < cases_per_family; ++i) check_double_against_mpfr(draw(rng));
}

}  // namespace

BOOST_AUTO_TEST_CASE(random_gear_trains_double_agrees_with_mpfr) { run_family(20261123, gear_train); }

BOOST_AUTO_TEST_CASE(random_crank_rockers_double_agrees_with_mpfr) { run_family(20261124, crank_rocker); }

BOOST_AUTO_TEST_CASE(random_cam_pairs_double_agrees_with_mpfr) { run_family(20261125, cam_pair); }

BOOST_AUTO_TEST_CASE(every_truncated_example_scene_is_an_input_error) {
  Rng rng(20261126);
  int files = 0, truncations = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(ROLLKIN_SOURCE_DIR) + "/examples")) {
    if (entry.path().extension() != ".json") continue;
    const std::string text = read_text(entry.path());
    const std::string file = entry.path().string();
    BOOST_TEST_REQUIRE(input_error_of([&] { io::parse_scene(text, file); }).empty(), file << " itself must be valid");
    // A JSON object is complete only with its closing brace: every shorter prefix is malformed.
    const std::size_t closing = text.rfind('}');
    BOOST_TEST_REQUIRE(closing != std::string::npos);
    std::vector<std::size_t> lengths{0, 1, closing};
    for (int k = 0; k < 40; ++k) lengths.push_back(std::uniform_int_distribution<std::size_t>(0, closing)(rng));
    for (std::size_t length : lengths) {
      const std::string message = input_error_of([&] { io::parse_scene(text.substr(0, length), file); });
      BOOST_TEST(!message.empty(), file << " truncated to " << length << " bytes was accepted");
      BOOST_TEST(contains(message, file), "the message names the file");
      ++truncations;
    }
    ++files;
  }
  BOOST_TEST(files >= 6);
  BOOST_TEST_MESSAGE(truncations << " truncations of " << files << " example scenes, each an InputError");
}
