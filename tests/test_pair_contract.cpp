// The contract every pair kind keeps (include/rollkin/pair/pair_kind.hpp, pair.hpp), checked by one typed test
// body per (kind, scalar), in double and in MPFR at 50 digits, on the hard cases of each kind (identity, a half
// turn, a tiny angle or curvature) and on random ones:
//  - the twists lambda_j = (dE/dq_j) E^-1 and their rates against central differences computed in MPFR at 50
//    digits (step 1e-15: truncation ~1e-30, round-off ~1e-35);
//  - double against MPFR: the same pair evaluated in both;
//  - placement round trip: from the transform E(q) alone, q is recovered by Gauss-Newton on the twists from a
//    start 1e-3 away; pair_transform gives evaluate_pair's transform to the last bit;
//  - the table row against the evaluation: variable_count twists and no more; a kind without contours never
//    reads a contour (evaluated with none); a kind without joint frames ignores them; `turns`: a rotation
//    about the joint's origin at unit rate, pair_turn equal to the transform's angle; `slides`: a unit
//    translation along frame A's x; `has_contours`: eq. (1) (the contact points coincide, normals opposite);
//    `constrains_sliding`: the rolling row's derivative (sigma_A, sigma_B) against differences of the arc
//    lengths, and no slip at the contact along its null space; `freedoms`: the rank of the twists on the null
//    space of the pair's own rows.
// The kinds are generated from the table (kPairTraits), and each kind's cases from its traits (joint frames or
// contours): a new kind is checked without touching this file, or fails here naming what it lacks.
#define BOOST_TEST_MODULE pair_contract
#include <boost/mp11/algorithm.hpp>
#include <boost/test/unit_test.hpp>

#include "rollkin/pair/pair.hpp"
#include "rollkin/scalar_mpfr.hpp"

#include <Eigen/SVD>

#include <random>
#include <tuple>
#include <vector>

using namespace rollkin;
using M = mpfr_scalar<50>;
using Scalars = std::tuple<double, M>;

namespace {

template <std::size_t I> struct KindAt {
  static constexpr PairKind kind = kPairTraits[I].kind;
};
template <class I> using KindOf = KindAt<I::value>;
using Kinds = boost::mp11::mp_transform<KindOf, boost::mp11::mp_iota_c<sizeof kPairTraits / sizeof *kPairTraits>>;

template <class Kind, class S> struct Case {
  using kind = Kind;
  using scalar = S;
};
using Cases = boost::mp11::mp_product<Case, Kinds, Scalars>;

// ---- the cases of a kind --------------------------------------------------------------------------------

/// A placement given so that it is exact in every scalar: an angle (sine and cosine taken in the scalar, so the
/// rotation is orthonormal to its precision; a double rotation cast to MPFR is not, to 1e-16) or a whole number
/// of quarter turns (exact axes), and a translation.
struct Place {
  double angle = 0;
  Vec2<double> t{0, 0};
  int quarters = -1;  // >= 0: exactly this many quarter turns, `angle` unused
  template <class S> SE2<S> make() const {
    const Vec2<S> at(scalar_cast<S>(t.x()), scalar_cast<S>(t.y()));
    if (quarters < 0) return SE2<S>(scalar_cast<S>(angle), at);
    static const int c[] = {1, 0, -1, 0}, s[] = {0, 1, 0, -1};
    return SE2<S>::from_axis(S(c[quarters % 4]), S(s[quarters % 4]), at);
  }
};

/// A contour given by its kind and numbers, built in any scalar.
struct Shape {
  enum Kind { Line, Circle, Parabola, Ellipse } kind;
  double a, b, c;  // line: lo, hi; circle: radius, lo, hi; parabola: a, lo, hi; ellipse: semi-axes
  Place place;
  bool reversed = false;
  template <class S> Contour<S> make(int link) const {
    const std::string name = link == 0 ? "a" : "b";
    const S x = scalar_cast<S>(a), y = scalar_cast<S>(b), z = scalar_cast<S>(c);
    switch (kind) {
      case Line: return Contour<S>(name, link, rollkin::Line<S>(x, y), place.make<S>(), reversed);
      case Circle: return Contour<S>(name, link, rollkin::Circle<S>(x, y, z), place.make<S>(), reversed);
      case Parabola: return Contour<S>(name, link, rollkin::Parabola<S>(x, y, z), place.make<S>(), reversed);
      case Ellipse: break;
    }
    return Contour<S>(name, link, rollkin::Ellipse<S>(x, y), place.make<S>(), reversed);
  }
};

/// One pair of one kind at one pose (with rates, for the twist rates), built in any scalar.
struct Setup {
  std::string label;
  PairKind kind;
  Place frame_a, frame_b;          // kinds with joint frames
  std::vector<Shape> contours;     // kinds with contours: A on link 0, B on link 1
  std::array<double, 2> q{0, 0}, qdot{0.8, -1.3};
};

Place random_place(std::mt19937& rng) {
  std::uniform_real_distribution<double> angle(-3.1, 3.1), x(-2, 2);
  return Place{angle(rng), Vec2<double>(x(rng), x(rng))};
}

std::vector<Setup> joint_setups(PairKind kind) {
  std::vector<Setup> out;
  out.push_back({"identity", kind, {}, {}, {}, {0, 0}});
  const Place half_turn{0, Vec2<double>(1, 2), 2}, other{-0.5, Vec2<double>(0.4, -1)};
  out.push_back({"half turn", kind, half_turn, other, {}, {pi<double>(), 0}});
  out.push_back({"tiny variable", kind, half_turn, other, {}, {1e-9, 0}});
  std::mt19937 rng(36);
  std::uniform_real_distribution<double> q(-3, 3);
  for (int k = 0; k < 3; ++k) {
    const Place a = random_place(rng), b = random_place(rng);
    out.push_back({"random " + std::to_string(k), kind, a, b, {}, {q(rng), 0}});
  }
  return out;
}

std::vector<Setup> contact_setups(PairKind kind) {
  const Shape line{Shape::Line, -1, 1, 0, {}};
  // A circle of radius 2 whose point at v = 0 is the origin with its tangent along -x (E(0, 0) = I) or +x
  // (E(0, 0) = Rot(pi), the branch cut of the transform's angle).
  const Shape below{Shape::Circle, 2, -3, 3, {0, Vec2<double>(0, -2), 1}};
  const Shape above{Shape::Circle, 2, -3, 3, {0, Vec2<double>(0, 2), 3}};
  const Shape flat{Shape::Parabola, 1e-7, -2, 2, {0.4, Vec2<double>(2, 0.3)}};
  const Shape ellipse{Shape::Ellipse, 1.5, 0.9, 0, {-0.2, Vec2<double>(0.1, 0.2)}, true};
  std::vector<Setup> out;
  out.push_back({"identity", kind, {}, {}, {line, below}, {0, 0}});
  out.push_back({"half turn", kind, {}, {}, {line, above}, {0, 0}});
  out.push_back({"tiny curvature", kind, {}, {}, {flat, ellipse}, {0.6, 2.1}});
  std::mt19937 rng(36);
  std::uniform_real_distribution<double> u(-1.8, 1.8), v(0, 6.2);
  for (int k = 0; k < 3; ++k) {
    const Shape a{Shape::Parabola, 0.5, -2, 2, random_place(rng), k % 2 == 1};
    const Shape b{Shape::Ellipse, 1.5, 0.9, 0, random_place(rng), k % 2 == 0};
    out.push_back({"random " + std::to_string(k), kind, {}, {}, {a, b}, {u(rng), v(rng)}});
  }
  return out;
}

/// The cases of a kind, chosen by what its row says it is.
std::vector<Setup> setups(PairKind kind) {
  const PairTraits& t = traits(kind);
  if (t.has_contours) return contact_setups(kind);
  if (t.has_joint_frames) return joint_setups(kind);
  BOOST_FAIL(std::string("pair kind ") + t.name + " has neither contours nor joint frames: give it cases here");
  return {};
}

/// A pair, its contours and its pose in scalar S.
template <class S> struct Posed {
  Pair<S> pair;
  std::vector<Contour<S>> contours;
  std::array<S, 2> q, qdot;
  explicit Posed(const Setup& s)
      : q{scalar_cast<S>(s.q[0]), scalar_cast<S>(s.q[1])}, qdot{scalar_cast<S>(s.qdot[0]), scalar_cast<S>(s.qdot[1])} {
    pair.kind = s.kind;
    pair.name = to_string(s.kind);
    pair.link_a = 0;
    pair.link_b = 1;
    if (pair.traits().has_joint_frames) {
      pair.frame_a = s.frame_a.make<S>();
      pair.frame_b = s.frame_b.make<S>();
    }
    if (pair.traits().has_contours) {
      pair.contour_a = 0;
      pair.contour_b = 1;
      for (int link = 0; link < 2; ++link) contours.push_back(s.contours.at(static_cast<std::size_t>(link)).make<S>(link));
    }
  }
  PairState<S> at(const std::array<S, 2>& x, int order = 2, bool rates = false) const {
    return evaluate_pair(pair, contours, x.data(), rates ? qdot.data() : nullptr, order);
  }
};

// ---- tolerances and references -------------------------------------------------------------------------

/// Agreement with the MPFR differences: round-off of the scalar under test, times a margin for conditioning.
template <class S> double tolerance() { return std::is_same_v<S, double> ? 1e-11 : 1e-24; }

template <class S> double gap(const Twist<S>& a, const Twist<M>& b) {
  double worst = 0;
  for (int i = 0; i < 3; ++i) worst = std::max(worst, std::abs(to_double(M(scalar_cast<M>(a(i)) - b(i)))));
  return worst;
}

/// (E(x + h e_j) - E(x - h e_j)) / 2h E(x)^-1 as a twist, in MPFR.
Twist<M> difference_twist(const Posed<M>& p, std::array<M, 2> x, int j) {
  const M h("1e-15");
  auto at = [&](const M& dx) {
    std::array<M, 2> y = x;
    y[j] += dx;
    return p.at(y).transform.matrix();
  };
  const Eigen::Matrix<M, 3, 3> lam = ((at(h) - at(M(-h))) / (M(2) * h)) * p.at(x).transform.inverse().matrix();
  return Twist<M>(lam(0, 2), lam(1, 2), lam(1, 0));
}

/// d/dt lambda_j(q + t qdot) at t = 0 by central differences in MPFR.
Twist<M> difference_twist_rate(const Posed<M>& p, int j) {
  const M h("1e-15");
  auto along = [&](const M& t) {
    std::array<M, 2> y = p.q;
    for (int i = 0; i < 2; ++i) y[i] += p.qdot[i] * t;
    return p.at(y).twist[j];
  };
  return Twist<M>((along(h) - along(M(-h))) / (M(2) * h));
}

/// The translation and angle of D, the twist of a small motion to first order.
template <class S> Twist<S> small_twist(const SE2<S>& d) { return Twist<S>(d.translation().x(), d.translation().y(), d.angle()); }

/// The pair's own rows' null space in its variables (as columns): the rolling row (sigma_A, sigma_B) of a kind
/// that constrains sliding, none otherwise (kinematics.hpp, compute_constraints).
Eigen::MatrixXd own_null_space(const PairTraits& t, const PairState<double>& st) {
  const int n = t.variable_count;
  if (!t.constrains_sliding) return Eigen::MatrixXd::Identity(n, n);
  Eigen::MatrixXd z(2, 1);
  z << st.contact[1].speed, -st.contact[0].speed;
  return z / z.norm();
}

}  // namespace

// ---- the table --------------------------------------------------------------------------------------------

BOOST_AUTO_TEST_CASE(every_row_is_a_consistent_kind) {
  for (const PairTraits& t : kPairTraits) {
    BOOST_TEST_CONTEXT(t.name) {
      BOOST_TEST((t.variable_count == 1 || t.variable_count == 2));
      BOOST_TEST((pair_kind_named(t.name).value() == t.kind));
      BOOST_TEST(std::string(to_string(t.kind)) == t.name);
      for (int j = 0; j < 2; ++j) BOOST_TEST((std::string(t.default_variables[j]).empty() == (j >= t.variable_count)));
      BOOST_TEST((t.freedoms >= 1 && t.freedoms <= t.variable_count));
      BOOST_TEST(t.constraint_count() == 3 - t.freedoms);
      BOOST_TEST(!(t.turns && t.slides));
      BOOST_TEST((!t.constrains_sliding || t.has_contours));  // the row is written from the contact speeds
      BOOST_TEST((t.has_contours != t.has_joint_frames));     // placed by one or the other
      BOOST_TEST((t.joint_variable_kind() == ParamKind::Length) == t.slides);
    }
  }
  BOOST_TEST(!pair_kind_named("hinge").has_value());
}

// ---- per kind and scalar ----------------------------------------------------------------------------------

BOOST_AUTO_TEST_CASE_TEMPLATE(twists_and_rates_against_mpfr_differences, C, Cases) {
  using S = typename C::scalar;
  for (const Setup& s : setups(C::kind::kind)) {
    BOOST_TEST_CONTEXT(to_string(C::kind::kind) << ", " << s.label) {
      const Posed<S> p(s);
      const Posed<M> ref(s);
      const PairState<S> st = p.at(p.q, 3, true);
      const int n = p.pair.variable_count();
      for (int j = 0; j < n; ++j) {
        BOOST_TEST(gap(st.twist[j], difference_twist(ref, ref.q, j)) < tolerance<S>());
        BOOST_TEST(gap(st.twist_rate[j], difference_twist_rate(ref, j)) < tolerance<S>());
      }
      for (int j = n; j < 2; ++j) BOOST_TEST(gap(st.twist[j], Twist<M>(Twist<M>::Zero())) == 0.0);  // no more twists
    }
  }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(double_agrees_with_mpfr, C, Cases) {
  using S = typename C::scalar;
  for (const Setup& s : setups(C::kind::kind)) {
    BOOST_TEST_CONTEXT(to_string(C::kind::kind) << ", " << s.label) {
      const PairState<S> st = Posed<S>(s).at(Posed<S>(s).q, 3, true);
      const PairState<M> ref = Posed<M>(s).at(Posed<M>(s).q, 3, true);
      const double tol = std::is_same_v<S, double> ? 1e-13 : 1e-45;
      const Eigen::Matrix<M, 3, 3> d = st.transform.matrix().template cast<M>() - ref.transform.matrix();
      BOOST_TEST(to_double(M(d.cwiseAbs().maxCoeff())) < tol);
      for (int j = 0; j < 2; ++j) {
        BOOST_TEST(gap(st.twist[j], ref.twist[j]) < 10 * tol);
        BOOST_TEST(gap(st.twist_rate[j], ref.twist_rate[j]) < 10 * tol);
      }
    }
  }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(placement_round_trip, C, Cases) {
  using S = typename C::scalar;
  for (const Setup& s : setups(C::kind::kind)) {
    BOOST_TEST_CONTEXT(to_string(C::kind::kind) << ", " << s.label) {
      const Posed<S> p(s);
      const PairState<S> target = p.at(p.q);
      // pair_transform: evaluate_pair's transform to the last bit.
      const SE2<S> alone = pair_transform(p.pair, p.contours, p.q.data());
      BOOST_TEST(((alone.matrix() - target.transform.matrix()).cwiseAbs().maxCoeff() == S(0)));
      // Gauss-Newton on the twists: E(x + dx) = (I + sum_j lambda_j dx_j) E(x), so sum_j lambda_j dx_j = -D with
      // D the small motion E(x) E(q)^-1.
      const int n = p.pair.variable_count();
      std::array<S, 2> x = p.q;
      for (int j = 0; j < n; ++j) x[j] += S(1) / S(1000);
      for (int it = 0; it < 12; ++it) {
        const PairState<S> st = p.at(x);
        Eigen::Matrix<S, 3, Eigen::Dynamic> J(3, n);
        for (int j = 0; j < n; ++j) J.col(j) = st.twist[j];
        const Twist<S> r = small_twist<S>(st.transform * target.transform.inverse());
        const Eigen::Matrix<S, Eigen::Dynamic, 1> dx = (J.transpose() * J).ldlt().solve(J.transpose() * Twist<S>(-r));
        for (int j = 0; j < n; ++j) x[j] += dx(j);
      }
      using std::abs;
      for (int j = 0; j < n; ++j) BOOST_TEST(to_double(S(abs(x[j] - p.q[j]))) < tolerance<S>());
      for (int j = 0; j < n; ++j) BOOST_TEST(to_double(S(abs(target.evaluated_value(p.pair.traits(), j) - p.q[j]))) == 0.0);
    }
  }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(traits_agree_with_the_evaluation, C, Cases) {
  using S = typename C::scalar;
  using std::abs;
  const PairTraits& t = traits(C::kind::kind);
  for (const Setup& s : setups(C::kind::kind)) {
    BOOST_TEST_CONTEXT(t.name << ", " << s.label) {
      const Posed<S> p(s);
      const PairState<S> st = p.at(p.q);
      const double tol = tolerance<S>();
      if (!t.has_contours) {
        // Evaluated with no contours and indices that name none: a kind without contours never reads them.
        Posed<S> none = p;
        none.contours.clear();
        none.pair.contour_a = none.pair.contour_b = 1 << 20;
        BOOST_TEST(((none.at(p.q).transform.matrix() - st.transform.matrix()).cwiseAbs().maxCoeff() == S(0)));
        using std::isnan;
        BOOST_TEST((isnan(st.contact_value[0]) && isnan(st.contact_value[1])));
      } else {
        // Eq. (1): E places contour B's contact point on contour A's, with the outward normals opposite.
        const ContourPoint<S>& a = st.contact[0];
        const ContourPoint<S>& b = st.contact[1];
        BOOST_TEST(to_double(S((a.p - p.contours[0].jet(p.q[0], 0).p).norm())) == 0.0);
        BOOST_TEST(to_double(S((st.transform.act(b.p) - a.p).norm())) < tol);
        BOOST_TEST(to_double(S((st.transform.rotate(b.outward_normal()) + a.outward_normal()).norm())) < tol);
      }
      if (!t.has_joint_frames) {
        Posed<S> moved = p;  // frames a kind without joint frames does not read
        moved.pair.frame_a = SE2<S>(S(1), Vec2<S>(S(3), S(-2)));
        moved.pair.frame_b = SE2<S>(S(-2), Vec2<S>(S(1), S(5)));
        BOOST_TEST(((moved.at(p.q).transform.matrix() - st.transform.matrix()).cwiseAbs().maxCoeff() == S(0)));
      }
      const S turn = pair_turn(p.pair, p.q.data(), st.transform);
      BOOST_TEST(abs(std::remainder(to_double(S(turn - st.transform.angle())), 2 * pi<double>())) < tol);
      if (t.turns) {
        // A rotation at unit rate about the joint's origin, fixed in both links: the twist's velocity there is 0;
        // the turn is the joint angle itself, without atan2.
        const Twist<S>& w = st.twist[0];
        const Vec2<S>& o = p.pair.frame_a.translation();
        BOOST_TEST(to_double(S(abs(w.z() - S(1)))) < tol);
        BOOST_TEST(to_double(S(Vec2<S>(w.x() - w.z() * o.y(), w.y() + w.z() * o.x()).norm())) < tol);
        BOOST_TEST(to_double(S(abs(turn - (p.pair.frame_a.angle() + p.q[0] - p.pair.frame_b.angle())))) == 0.0);
      }
      if (t.slides) {
        // A translation at unit speed along frame A's x axis; no relative turning.
        const Twist<S>& w = st.twist[0];
        BOOST_TEST(to_double(S(abs(w.z()))) == 0.0);
        BOOST_TEST(to_double(S((Vec2<S>(w.x(), w.y()) - p.pair.frame_a.rotate(Vec2<S>(S(1), S(0)))).norm())) < tol);
      }
      if (t.constrains_sliding) {
        // The rolling row s_A(u0 -> u) + s_B(v0 -> v) (eqs. 3-4): its derivative (sigma_A, sigma_B) against MPFR
        // differences of the arc lengths, and along its null space no slip at the contact point.
        const Posed<M> ref(s);
        const M h("1e-15");
        for (int j = 0; j < 2; ++j) {
          const Contour<M>& c = ref.contours[static_cast<std::size_t>(j)];
          const M ds = (c.arc_length(ref.q[j], ref.q[j] + h) - c.arc_length(ref.q[j], ref.q[j] - h)) / (M(2) * h);
          BOOST_TEST(to_double(M(abs(scalar_cast<M>(st.contact[j].speed) - ds))) < tol);
        }
        const Twist<S> w = st.twist[0] * st.contact[1].speed - st.twist[1] * st.contact[0].speed;
        const Vec2<S> at = st.contact[0].p;
        BOOST_TEST(to_double(S(Vec2<S>(w.x() - w.z() * at.y(), w.y() + w.z() * at.x()).norm())) < tol);
      }
      // Freedoms: the rank of the twists on the null space of the pair's own rows (none of the cases osculates).
      const PairState<double> sd = Posed<double>(s).at(Posed<double>(s).q);
      Eigen::MatrixXd J(3, t.variable_count);
      for (int j = 0; j < t.variable_count; ++j) J.col(j) = sd.twist[j];
      Eigen::JacobiSVD<Eigen::MatrixXd> svd(J * own_null_space(t, sd));
      svd.setThreshold(1e-9);
      BOOST_TEST(svd.rank() == t.freedoms);
    }
  }
}
