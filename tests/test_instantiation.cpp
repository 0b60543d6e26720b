// Every class template of the library explicitly instantiated for both scalars, double and mpfr50 (as Sophus
// does): an explicit instantiation compiles every member, so a member that does not compile for one scalar
// fails this build instead of waiting for the first caller (docs/benchmark.md, "Build times"). The solver's
// class templates with bodies in .hxx files (SolveData, the tracer, the contact limits) are instantiated
// whole where they are compiled, src/solve/instantiate_double.cpp and instantiate_mpfr50.cpp, so that this
// test does not compile the solver a third time. The test case
// then runs the member that did not compile for MPFR (SolveData::factor_sparse, reached when a sparse
// factorisation is asked for) in both scalars, against the closed form of a rolling disk.
#define BOOST_TEST_MODULE instantiation
#include <boost/test/unit_test.hpp>

#include "rollkin/samples/mechanisms.hpp"
#include "rollkin/analysis/motion.hpp"
#include "rollkin/builder.hpp"
#include "rollkin/analysis/centrodes.hpp"
#include "rollkin/analysis/design_check.hpp"
#include "rollkin/profile/arc_length_parameterised.hpp"
#include "rollkin/profile/banded_solver.hpp"
#include "rollkin/profile/bezier.hpp"
#include "rollkin/profile/circle.hpp"
#include "rollkin/profile/ellipse.hpp"
#include "rollkin/profile/line.hpp"
#include "rollkin/profile/nurbs.hpp"
#include "rollkin/profile/parabola.hpp"
#include "rollkin/profile/piecewise_arc_length.hpp"
#include "rollkin/profile/profile.hpp"
#include "rollkin/profile/quadrature.hpp"
#include "rollkin/profile/spline.hpp"
#include "rollkin/scalar_mpfr.hpp"
#include "rollkin/solve/continuation.hpp"
#include "rollkin/solve/mpfr50_instances.hpp"
#include "rollkin/synthesis/pitch_curves.hpp"

namespace rollkin {

// The class templates of include/rollkin, one list for both scalars.
#define ROLLKIN_INSTANTIATE_CLASSES(S)           \
  template class SE2<S>;                         \
  template struct Domain<S>;                     \
  template struct Jet<S>;                        \
  template struct ContourPoint<S>;               \
  template class Line<S>;                        \
  template class Circle<S>;                      \
  template class Parabola<S>;                    \
  template class Ellipse<S>;                     \
  template struct GaussLegendreNodes<S>;         \
  template class BandedSystem<S>;                \
  template struct Nurbs<S>;                      \
  template struct NurbsPieces<S>;                \
  template class ArcLengthProfile<S>;            \
  template class PiecewiseArcLength<S>;          \
  template struct BezierSegment<S>;              \
  template struct PathCorner<S>;                 \
  template struct BezierPathOptions<S>;          \
  template class BezierPath<S>;                  \
  template struct SplineOptions<S>;              \
  template class SampledProfile<S>;              \
  template struct ArcOrigin<S>;                  \
  template struct ContourCorner<S>;              \
  template class Contour<S>;                     \
  template struct Pair<S>;                       \
  template struct PairState<S>;                  \
  template class Mechanism<S>;                   \
  template class MechanismBuilder<S>;            \
  template struct KinematicsData<S>;             \
  template struct NewtonSettings<S>;             \
  template class SmallLU<S>;                     \
  template struct SolveReport<S>;                \
  template struct SweepPose<S>;                  \
  template struct detail::SweepColumns<S>;       \
  template class SweepResult<S>;                 \
  template struct SweepSummary<S>;               \
  template struct ContinuationSettings<S>;       \
  template struct ContactAnalysis<S>;            \
  template struct PoseAnalysis<S>;               \
  template struct AnalysisData<S>;               \
  template struct TouchedPoint<S>;               \
  template struct ContourCurvatureCheck<S>;      \
  template struct PairDesignCheck<S>;            \
  template struct DesignCheck<S>;                \
  template struct detail::ContactPath<S>;        \
  template struct detail::Extreme<S>;            \
  template struct InstantCentre<S>;              \
  template struct TransmissionFunction<S>;       \
  template struct PitchRadii<S>;                 \
  template struct GearPair<S>;

ROLLKIN_INSTANTIATE_CLASSES(double)
ROLLKIN_INSTANTIATE_CLASSES(mpfr50)

}  // namespace rollkin

using namespace rollkin;

namespace {

/// A disk of radius 3/4 rolled along a line (rollkin/samples/mechanisms.hpp, disk_on_line) with a sparse factorisation
/// asked for: double takes it, other scalars the dense path (SolveData::resolve). The disk turns by -x / r.
template <class S> S worst_roll_error(Factorisation asked) {
  const S r = S(3) / S(4);
  const auto f = testing::disk_on_line<S>(r);
  SolveData<S> sd(f.mech, asked);
  VectorX<S> q;
  const auto assembly = testing::assemble_fixture(f, q, sd);
  BOOST_TEST_REQUIRE(assembly.ok());
  std::vector<S> xs;
  for (int k = -4; k <= 8; ++k) xs.push_back(S(k) * S(3) / S(10));
  const auto res = sweep(f.mech, sd, q, assembly, 0, xs);
  BOOST_TEST_REQUIRE(res.all_solved());
  S worst(0);
  for (const auto& p : res.poses) {
    using std::abs;
    using std::max;
    worst = max(worst, S(abs(p.q(1) + p.input / r)));
  }
  return worst;
}

}  // namespace

BOOST_AUTO_TEST_CASE(a_sparse_factorisation_asked_for_in_either_scalar_solves_to_its_precision) {
  const auto resolved = [](auto scalar) {
    using S = decltype(scalar);
    return SolveData<S>::resolve(testing::disk_on_line<S>(S(1)).mech, Factorisation::EigenSparseLU);
  };
  BOOST_TEST((resolved(0.0) == Factorisation::EigenSparseLU));
  BOOST_TEST((resolved(mpfr50(0)) == Factorisation::Dense));
  BOOST_TEST(worst_roll_error<double>(Factorisation::EigenSparseLU) < 1e-12);
  BOOST_TEST(worst_roll_error<double>(Factorisation::Dense) < 1e-12);
  BOOST_TEST(worst_roll_error<mpfr50>(Factorisation::EigenSparseLU) < mpfr50("1e-40"));
}
