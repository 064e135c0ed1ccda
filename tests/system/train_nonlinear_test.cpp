// Nonlinear gear trains (issue 17, item 2): contact loss and backlash at every mesh, harmonic
// balance condensed onto the mesh deflections against the 1-DOF harmonic balance (reduction),
// finite differences (Jacobian), the linear steady-state solver (condensation and recovery) and
// nonlinear Newmark (planetary stage, two-stage reducer).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/solvers/continuation.h"
#include "geardyn/solvers/harmonic_balance.h"
#include "geardyn/solvers/train_harmonic_balance.h"
#include "geardyn/solvers/train_modal.h"
#include "geardyn/solvers/train_nonlinear_time.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "system/nonlinear_trains.h"

namespace geardyn {
namespace {

using namespace testing::nonlinear;

TEST(TrainNonlinear, ContactLawOfAMesh) {
  TrainMesh mesh;
  mesh.contact = backlash(2e-6);
  double s = 0.0;
  EXPECT_DOUBLE_EQ(mesh.contactDeflection(1e-6, &s), 1e-6);
  EXPECT_EQ(s, 1.0);
  EXPECT_DOUBLE_EQ(mesh.contactDeflection(-1e-6, &s), 0.0);
  EXPECT_EQ(s, 0.0);
  EXPECT_DOUBLE_EQ(mesh.contactDeflection(-3e-6, &s), -1e-6);  // back flank
  mesh.contact = {ContactLaw::kOneSided, 0.0};
  EXPECT_DOUBLE_EQ(mesh.contactDeflection(-3e-6, &s), 0.0);
  GearTrainSpec bad = singlePair(0.0);
  EXPECT_THROW(GearTrainModel{bad}, InputError);  // backlash law with j = 0
}

}  // namespace
}  // namespace geardyn

namespace geardyn {
namespace {

/// Reduction (issue 17 acceptance): one pair with torsional DOFs and backlash j is the 1-DOF
/// gear pair with half clearance b = j/2 (its deflection x = δ + b: the train measures δ from
/// contact onset on the loaded flank, the pair from the middle of the clearance), mass m_e,
/// mean force T/r_b1 and the same c, k, e. Along a continuation through contact loss, back-flank
/// impacts and six folds, every 15th point refined to 1e-12 solves the 1-DOF balance (relative
/// residual < 1e-11), and the 1-DOF Newton started 1e-6 away from it returns to it within 1e-9.
TEST(TrainNonlinear, SinglePairReducesToTheSdofHarmonicBalance) {
  const double j = 2e-5;
  const GearTrainModel train(singlePair(j));
  const TrainMesh& m = train.meshes()[0];
  ReductionPair r(train, reducedPair(train, j), 0.35, 1.0);
  ASSERT_EQ(r.hbm.size(), r.reference.size());
  ASSERT_TRUE(r.sweep.completed) << r.sweep.message;
  EXPECT_EQ(r.sweep.folds.size(), 6u);  // 3rd and 2nd superharmonic and primary loops
  const ReductionCheck check =
      compareWithSdof(r.hbm, r.reference, r.sweep, 15, 0.5 * j, [&](const Eigen::MatrixXd& d) {
        bool open = false;
        for (int k = 0; k < d.rows(); ++k) {
          open = open || d(k, 0) - m.transmission_error.value(m.phase + k / 256.0) < 0.0;
        }
        return open;
      });
  EXPECT_LT(check.worst, 1e-9);
  EXPECT_LT(check.residual, 1e-11);
  EXPECT_GT(check.compared, 40);
  EXPECT_GT(check.separated, 20);  // most compared points lose contact
}

/// ∂R/∂δ and ∂R/∂ω₀ against central differences on the planetary stage (18 DOFs, 6 meshes with
/// backlash, Coriolis and centripetal terms), at a state whose meshes open and hit their back
/// flanks (samples off the kinks: differences exact to round-off).
TEST(TrainNonlinear, JacobianMatchesFiniteDifferences) {
  const GearTrainModel model(planetary(4e-6));
  TrainHarmonicBalanceOptions options;
  options.harmonics = 4;
  options.samples = 64;
  TrainHarmonicBalance hbm(model, options);
  const double omega = hbm.baseFrequency(model.inputSpeed());
  Eigen::VectorXd u = hbm.startingGuess(omega);
  for (int mm = 0; mm < hbm.meshCount(); ++mm) {
    u(mm * 9 + 1) += 5e-6 * (1.0 + 0.1 * mm);  // swing every mesh across its clearance
    u(mm * 9 + 4) -= 1e-6;
  }
  expectJacobianMatchesCentralDifferences(hbm, u, omega);
}

/// With the clearance never reached the nonlinear balance is the linear steady state: against
/// TrainSteadySolver (exact Fourier coefficients, the same harmonics) every DOF recovered
/// agrees to 1e-9 of the response, and Vᵀ X = δ (the condensation is exact).
TEST(TrainNonlinear, ContactKeptIsTheLinearSteadyStateForEveryDof) {
  GearTrainSpec spec = testing::twoStageReducer(smooth(4e8, 0.0), smooth(6e8, 40.0));
  spec.meshes[0].transmission_error.addFourier({2e-6, 0.5e-6}, {0.0, 0.5});
  spec.meshes[0].contact = spec.meshes[1].contact = backlash(1e-4);
  const GearTrainModel model(spec);
  TrainHarmonicBalanceOptions options;
  options.harmonics = 15;  // 5 harmonics of stage 1 (P = 3), 15 of stage 2
  options.samples = 256;
  options.tolerance = 1e-13;
  TrainHarmonicBalance hbm(model, options);
  TrainSteadyOptions steady;
  steady.mesh_harmonics = 5;
  const TrainSteadyState linear = solveTrainSteadyState(model, model.inputSpeed(), steady);
  ASSERT_EQ(linear.harmonics, 15);
  HarmonicBalancePoint point;
  point.omega = hbm.baseFrequency(model.inputSpeed());
  point.q = hbm.startingGuess(point.omega);
  hbm.solve(point);
  ASSERT_TRUE(point.converged) << point.residual;
  const Eigen::MatrixXd X = hbm.displacementCoefficients(point);
  for (int h = 0; h <= 15; ++h) {
    for (int mm = 0; mm < 2; ++mm) {
      for (int col : {h == 0 ? 0 : 2 * h - 1, 2 * h}) {
        EXPECT_NEAR(model.meshVector(mm).dot(X.col(col)), point.q(mm * 31 + col),
                    1e-10 * point.q.norm());
      }
    }
  }
  EXPECT_LT(linearSteadyStateDifference(X, linear, 15), 1e-9 * X.norm());
}

/// The planetary stage against Newmark at two frequencies of the softening loop near 5.6 kHz
/// (the 12-frequency comparisons of both acceptance trains are in train_nonlinear_long_test):
/// the stable branches with contact loss persist, the middle branch is left.
TEST(TrainNonlinear, PlanetaryStageAgreesWithNewmarkInTheLoop) {
  const GearTrainModel model(planetary(4e-6));
  TrainHarmonicBalanceOptions options;
  TrainHarmonicBalance hbm(model, options);
  ContinuationOptions c;
  c.start = 2 * std::numbers::pi * 5000;
  c.stop = 2 * std::numbers::pi * 6500;
  c.stability = false;
  c.max_step = (c.stop - c.start) / 50;
  deriveContinuationSteps(c, 0.0, 0.05, options.harmonics);
  const ContinuationResult sweep = continueInFrequency(hbm, c);
  ASSERT_TRUE(sweep.completed) << sweep.message;
  ASSERT_EQ(sweep.folds.size(), 2u);
  const NewmarkCheck check = checkAgainstNewmark(model, hbm, sweep, {2 * std::numbers::pi * 5650});
  EXPECT_EQ(check.stable, 2);  // low and high branch
  EXPECT_EQ(check.unstable, 1);
  EXPECT_GE(check.contact_loss, 1);
  EXPECT_LT(check.worst, 0.01);
}

}  // namespace
}  // namespace geardyn
