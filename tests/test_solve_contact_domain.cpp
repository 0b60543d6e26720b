// The contract every profile kind keeps with the solver: a contact lies on the drawn contour. For every kind
// of profile_kinds.hpp, a disk on a slider (a carriage sliding along the contour's tangent at a point, the disk
// free to move along the normal) presses on the contour:
//  - assembly never answers ok with the contact beyond an end of an open contour, from any guess (random,
//    seeded, many beyond the ends): such a pose is cannot_assemble, naming the pair and the contour;
//  - a sweep toward an end stops there with domain_exit, located at the end's parameter, and no swept pose
//    has its contact off the contour.
// Rule and where it is enforced: Domain::contains (profile/jet.hpp) through contact_off_contour
// (solve/contact_limits.hpp), for assembly (solve/position.hpp) and every step of a sweep (continuation.hpp).
#define BOOST_TEST_MODULE solve_contact_domain
#include <boost/mp11/algorithm.hpp>
#include <boost/test/unit_test.hpp>

#include "profile_kinds.hpp"
#include "rollkin/builder.hpp"
#include "rollkin/solve/continuation.hpp"

#include <random>

using namespace rollkin;
using namespace rollkin::testing;

namespace {

/// The disk on its slider above contour `k` of link ground, at the contour's parameter `at`.
struct DiskOnContour {
  Mechanism<double> mech;
  VectorX<double> guess;
  int contact_u = -1;  // the contour's contact variable in q
  double radius = 0;
};

template <class Kind> DiskOnContour disk_on_contour(double at_fraction) {
  const auto profile = Kind::template make<double>();
  const Domain<double> d = profile.domain();
  const double at = d.lo + at_fraction * d.period();
  const ContourPoint<double> cp = contour_point(profile.jet(at, 2), 2);
  const Vec2<double> t = cp.tangent, out = cp.outward_normal();
  const double size = (profile.jet(d.lo, 0).p - profile.jet(d.lo + d.period() / 2, 0).p).norm();
  DiskOnContour f;
  f.radius = 0.05 * size;
  MechanismBuilder<double> b;
  const int ground = b.link("ground", true), carriage = b.link("carriage"), follower = b.link("follower");
  const int k = b.contour(ground, "k", ProfileShape<double>(profile));
  const int rim = b.contour(follower, "rim", Circle<double>(f.radius));
  const double along = std::atan2(t.y(), t.x());
  const int slide = b.prismatic("slide", ground, carriage, SE2<double>(along, cp.p + f.radius * out), SE2<double>(), "s");
  b.prismatic("lift", carriage, follower, SE2<double>::rotation(-pi<double>() / 2), SE2<double>(), "h");
  const int touch = b.contact("touch", false, k, rim, "u", "v");
  b.driver(slide);
  f.mech = b.build();
  f.contact_u = b.variable(touch, 0);
  f.guess = VectorX<double>::Zero(f.mech.variable_count());
  f.guess(f.contact_u) = at;
  f.guess(f.contact_u + 1) = pi<double>();  // the disk's point toward the contour: -out, i.e. (-r, 0) in its frame
  return f;
}

template <class Kind> using IsOpen = boost::mp11::mp_bool<!Kind::closed>;
using OpenKinds = boost::mp11::mp_copy_if<Kinds, IsOpen>;

}  // namespace

BOOST_AUTO_TEST_CASE_TEMPLATE(assembly_never_answers_ok_off_the_contour, Kind, Kinds) {
  const DiskOnContour f = disk_on_contour<Kind>(1.0 / 3);
  const Domain<double> d = f.mech.contours[0].domain();
  {  // the plain guess assembles, on the contour
    SolveData<double> sd(f.mech);
    VectorX<double> q = f.guess;
    const SolveReport<double> rep = assemble(f.mech, q, sd);
    BOOST_TEST_REQUIRE(rep.ok(), rep.detail);
    BOOST_TEST(std::abs(q(f.contact_u) - f.guess(f.contact_u)) <= 1e-9 * d.period());
  }
  std::mt19937 rng(20261125);
  std::uniform_real_distribution<double> where(d.lo - d.period(), d.hi + d.period()), unit(-1, 1);
  int refused = 0, off_guesses = 0;
  for (int trial = 0; trial < 60; ++trial) {
    SolveData<double> sd(f.mech);
    VectorX<double> q = f.guess;
    q(f.contact_u) = where(rng);
    q(f.contact_u + 1) = pi<double>() * (1 + unit(rng));
    q(1) = f.radius * 4 * unit(rng);  // the lift h
    q(0) = f.radius * unit(rng);      // the driver s
    const bool guessed_off = !d.contains(q(f.contact_u));
    off_guesses += guessed_off;
    const SolveReport<double> rep = assemble(f.mech, q, sd);
    if (rep.has_pose()) {
      BOOST_TEST(d.contains(q(f.contact_u)), "trial " << trial << ": assembled ok at u = " << q(f.contact_u)
                                                       << ", off the contour [" << d.lo << ", " << d.hi << "]");
    } else if (rep.contour == 0) {
      ++refused;
      BOOST_TEST(rep.status == SolveStatus::CannotAssemble);
      BOOST_TEST(rep.detail.find("beyond the end of contour 'ground.k'") != std::string::npos, rep.detail);
      BOOST_TEST(rep.detail.find("pair 'touch'") != std::string::npos, rep.detail);
    }
  }
  if (IsOpen<Kind>::value) BOOST_TEST(off_guesses > 0);
  BOOST_TEST_MESSAGE("refused off the contour: " << refused << " of " << off_guesses << " guesses beyond an end");
}

BOOST_AUTO_TEST_CASE_TEMPLATE(a_sweep_stops_at_the_end_of_an_open_contour, Kind, OpenKinds) {
  {
    const DiskOnContour f = disk_on_contour<Kind>(1.0 / 3);
    const Contour<double>& k = f.mech.contours[0];
    const Domain<double> d = k.domain();
    SolveData<double> sd(f.mech);
    VectorX<double> q0 = f.guess;
    const SolveReport<double> assembly = assemble(f.mech, q0, sd);
    BOOST_TEST_REQUIRE(assembly.ok(), assembly.detail);
    // The slider's travel over both ends: the contour's extent plus its length, either way.
    const double size = (k.jet(d.lo, 0).p - k.jet(d.hi, 0).p).norm() + std::abs(k.arc_length(d.lo, d.hi));
    std::vector<double> inputs;
    for (int i = -400; i <= 400; ++i) inputs.push_back(size * i / 400.0);
    const SweepResult<double> r = sweep(f.mech, sd, q0, assembly, 0, inputs);
    int exits = 0;
    for (const SolveReport<double>& limit : r.limits) {
      if (limit.status != SolveStatus::DomainExit) continue;
      ++exits;
      BOOST_TEST(limit.contour == 0);
      // The contact at the located input is at an end (solve that pose again from the nearest solved one).
      std::size_t nearest = 0;
      for (std::size_t i = 0; i < inputs.size(); ++i)
        if (r.status(i) == SolveStatus::Converged && std::abs(inputs[i] - limit.limit_input) < std::abs(inputs[nearest] - limit.limit_input))
          nearest = i;
      VectorX<double> q = r.q(nearest);
      q(f.mech.drivers[0]) = limit.limit_input;
      BOOST_TEST_REQUIRE(solve_position(f.mech, q, sd).ok());
      const double u = q(f.contact_u);
      BOOST_TEST(std::min(std::abs(u - d.lo), std::abs(u - d.hi)) <= 1e-7 * d.period(), "contact at " << u);
    }
    BOOST_TEST(exits >= 1);
    for (std::size_t i = 0; i < inputs.size(); ++i)
      if (r.status(i) == SolveStatus::Converged) BOOST_TEST(d.contains(r.q(i)(f.contact_u)), "input " << inputs[i]);
  }
}
