// The full law of a rolling bearing in the nonlinear analyses (issue 35, bearings.<name>.model =
// "nonlinear"): its force and 2 × 2 Jacobian on (u_y, u_z), the harmonic balance's Jacobian
// against finite differences, the balance's mean against the nonlinear static deflection, small
// amplitudes against the linearised bearing, and the balance against nonlinear Newmark where
// balls leave contact every period.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <string>

#include "geardyn/error.h"
#include "geardyn/solvers/continuation.h"
#include "geardyn/solvers/train_harmonic_balance.h"
#include "geardyn/solvers/train_nonlinear_time.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/stiffness/api_stiffness.h"
#include "support/numeric_assertions.h"
#include "system/nonlinear_trains.h"
#include "system/rolling_bearing_law_trains.h"
#include "system/rolling_bearing_trains.h"

namespace geardyn {
namespace {

using namespace testing::nonlinear;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

using testing::rollingPair;
GearTrainModel linearised(const GearTrainSpec& spec) {
  return testing::linearisedAtStatics(spec);
}

/// The balance's solution at the operating speed from its starting guess (H harmonics, 16 H
/// samples, tolerance 1e-13): the coefficients of every DOF (displacementCoefficients).
Eigen::MatrixXd balanceAtOperatingSpeed(const GearTrainModel& model, int harmonics) {
  TrainHarmonicBalanceOptions options;
  options.harmonics = harmonics;
  options.samples = 16 * harmonics;
  options.tolerance = 1e-13;
  TrainHarmonicBalance hbm(model, options);
  HarmonicBalancePoint p;
  p.omega = hbm.baseFrequency(model.inputSpeed());
  p.q = hbm.startingGuess(p.omega);
  hbm.solve(p);
  EXPECT_TRUE(p.converged) << p.residual;
  return hbm.displacementCoefficients(p);
}

TEST(RollingBearingLaw, ForceAndJacobianAreTheBearingsRadialBlock) {
  const GearTrainModel model = linearised(rollingPair(15e-6, 1.0, true));
  ASSERT_EQ(model.clearanceBearings().size(), 1u);
  const TrainClearanceBearing& b = model.clearanceBearings()[0];
  ASSERT_TRUE(b.rolling);
  EXPECT_EQ(b.clearance, 7.5e-6);  // the radial play s_r / 2
  // Inside the play no ball is loaded.
  Eigen::Matrix2d J;
  EXPECT_EQ(b.contactForce({3e-6, -4e-6}, &J), Eigen::Vector2d::Zero());
  EXPECT_EQ(J, Eigen::Matrix2d::Zero());
  EXPECT_FALSE(b.touching({3e-6, -4e-6}));
  // 3.7 µm beyond the play: the law is RollingBearing's (y, z) rows.
  const Eigen::Vector2d u(10e-6, -5e-6);
  RollingBearing::Vector5 q = RollingBearing::Vector5::Zero(), F;
  q.head<2>() = u;
  RollingBearing::Matrix5 K;
  b.rolling->evaluate(q, F, &K);
  EXPECT_EQ(b.contactForce(u, &J), Eigen::Vector2d(F.head<2>()));
  EXPECT_EQ(J, Eigen::Matrix2d(K.topLeftCorner<2, 2>()));
  EXPECT_TRUE(b.touching(u));
  // The correction's Jacobian against central differences: δ^{3/2} is smooth where no ball is
  // at δ = 0 (checked: every ball's approach u·e_ψ − s_r/2 is ≥ 0.5 µm from 0), truncation
  // ~ h² f‴: 1e-6 of ‖J‖.
  Eigen::Matrix2d Jc;
  const Eigen::Vector2d fc = b.correctionForce(u, &Jc);
  EXPECT_LT((fc - (F.head<2>() - b.linear * u)).norm(), 1e-12 * F.norm());
  for (const RollingElementState& e : b.rolling->state(q).elements) {
    const double approach = u.dot(Eigen::Vector2d(std::cos(e.azimuth), std::sin(e.azimuth)));
    EXPECT_GT(std::abs(approach - 7.5e-6), 5e-7) << e.azimuth;
  }
  const double h = 1e-10;
  for (int j = 0; j < 2; ++j) {
    Eigen::Vector2d up = u, um = u;
    up(j) += h;
    um(j) -= h;
    const Eigen::Vector2d fd = (b.correctionForce(up) - b.correctionForce(um)) / (2 * h);
    EXPECT_LT((Jc.col(j) - fd).norm(), 1e-6 * J.norm()) << j;
  }
  // The starting guess's displacement carries the linear bearing's load exactly.
  const Eigen::Vector2d u_lin(2e-6, -3e-6);
  const Eigen::Vector2d loaded = b.loadedDisplacement(u_lin);
  EXPECT_LT((b.contactForce(loaded) - b.linear * u_lin).norm(), 1e-9 * (b.linear * u_lin).norm());
}

/// ∂R/∂u and ∂R/∂ω₀ of the balance against central differences with the bearing pressed
/// (every sample beyond the play) and swinging (balls leaving and re-entering contact): the
/// helper's 1e-5 of a column's norm, as for the meshes and the clearance law.
TEST(RollingBearingLaw, HarmonicBalanceJacobianMatchesFiniteDifferences) {
  const GearTrainModel model = linearised(rollingPair(15e-6, 1.0, true));
  TrainHarmonicBalanceOptions options;
  options.harmonics = 4;
  options.samples = 64;
  TrainHarmonicBalance hbm(model, options);
  ASSERT_EQ(hbm.coordinateCount(), 3);
  const int n = 2 * options.harmonics + 1;
  const double omega = hbm.baseFrequency(model.inputSpeed());
  const Eigen::VectorXd guess = hbm.startingGuess(omega);
  for (double A : {0.5e-6, 6e-6}) {  // orbit amplitude around the static point
    Eigen::VectorXd u = guess;
    u(n + 1) = A, u(2 * n + 2) = A;
    u(n + 5) = 0.2 * A;
    expectJacobianMatchesCentralDifferences(hbm, u, omega, A > 1e-6 ? "swinging" : "pressed");
  }
}

/// Without excitation (no transmission error, constant k) the balance's solution is its mean,
/// the static equilibrium K̄ q + Jᵀ f̃(Jq) = F₀ with the full law: the nonlinear static
/// deflection of the train with its rolling bearing (Newton, train_static_bearings.cpp), a second
/// solver of the same equations, to the two tolerances (1e-10 relative).
TEST(RollingBearingLaw, UnexcitedBalanceIsTheNonlinearStaticDeflection) {
  const GearTrainSpec spec = rollingPair(15e-6, 0.0, false);
  const GearTrainModel original(spec);
  const TrainStaticResult statics = solveTrainStatic(original, original.inputSpeed());
  const GearTrainModel model = original.linearisedAt(statics.displacement);
  const Eigen::MatrixXd X = balanceAtOperatingSpeed(model, 3);
  const Eigen::Vector2d u_static =
      original.rollingBearings()[0].displacement(statics.displacement).head<2>();
  const Eigen::Vector2d u_hbm = model.clearanceBearings()[0].displacement(X.col(0));
  EXPECT_CLOSE(u_hbm, u_static, 1e-8);
  // The linear model's own static solution (K_s u = load) differs: the bearing's secant is not
  // its tangent (δ^{3/2}: the linearised bearing deflects less under the same load).
  const Eigen::VectorXd linear = solveTrainStatic(model, model.inputSpeed()).displacement;
  EXPECT_GT((model.clearanceBearings()[0].displacement(linear) - u_static).norm(),
            0.05 * u_static.norm());
}

/// Small amplitudes: the full law is its tangent at the static point, so the dynamic response
/// (harmonics ≥ 1 of every DOF; constant k, so the mean does not enter it) tends to the linear
/// steady state of the linearised train as the excitation ε → 0, the difference falling as ε
/// (the law's quadratic term makes harmonics of relative size O(ε)). Measured relative
/// differences 9.7e-2, 1.95e-3, 1.51e-4, 1.48e-5 at ε = 1e-2 … 1e-5: first order once the
/// smallest loaded ball's approach dominates the amplitude (below 1e-3). Checked at ε = 1e-4
/// and 1e-5: difference ≤ 2 ε, and falling 10× (± 10 %) from one to the other.
TEST(RollingBearingLaw, SmallAmplitudeIsTheLinearisedBearing) {
  double previous = 0.0;
  for (double eps : {1e-4, 1e-5}) {
    const GearTrainModel model = linearised(rollingPair(15e-6, eps, false));
    const Eigen::MatrixXd X = balanceAtOperatingSpeed(model, 5);
    TrainSteadyOptions steady;
    steady.mesh_harmonics = 5;
    const TrainSteadyState linear = solveTrainSteadyState(model, model.inputSpeed(), steady);
    double diff = 0.0, size = 0.0;
    for (int h = 1; h <= 5; ++h) {
      diff += (X.col(2 * h - 1) - 2.0 * linear.harmonic.col(h).real()).squaredNorm() +
              (X.col(2 * h) + 2.0 * linear.harmonic.col(h).imag()).squaredNorm();
      size += X.col(2 * h - 1).squaredNorm() + X.col(2 * h).squaredNorm();
    }
    const double relative = std::sqrt(diff / size);
    std::printf("eps %.0e: full law vs linearised, relative difference %.3e\n", eps, relative);
    EXPECT_LT(relative, 2.0 * eps);
    if (eps == 1e-5) EXPECT_NEAR(previous / relative, 10.0, 1.0);
    previous = relative;
  }
}

/// The balance against nonlinear Newmark started on its solution (average acceleration, 512
/// steps a mesh period, steady to 1e-8) across the pinion-bearing resonance: the p2p of the
/// bearing's radial displacement |u| and of the mesh deflection agree within 1 % (the HBM's
/// truncation at H = 12 with the balls' contact kinks, Newmark's second-order error) at three
/// stable points of a sweep over mesh frequencies 1.9–3.3 kHz (the speeds of
/// examples/train_rolling_bearing_nonlinear.toml), where the orbit (|u| 8–21 µm against a
/// radial play of 7.5 µm) moves the load zone: balls leave and re-enter contact every period.
TEST(RollingBearingLaw, HarmonicBalanceAgreesWithNewmark) {
  const GearTrainModel model = linearised(rollingPair(15e-6, 1.0, true));
  TrainHarmonicBalanceOptions options;
  options.harmonics = 12;
  options.samples = 256;
  TrainHarmonicBalance hbm(model, options);
  const ContinuationResult s = sweepUp(hbm, 1900.0, 3300.0);
  ASSERT_TRUE(s.completed) << s.message;
  double worst = 0.0;
  for (double f : {2100.0, 2540.0, 3200.0}) {
    const std::vector<HarmonicBalancePoint> found = solutionsAtFrequency(hbm, {&s}, kTwoPi * f);
    ASSERT_EQ(found.size(), 1u) << f;
    HarmonicBalancePoint p = found.front();
    hbm.classify(p, StabilityMethod::kMonodromy, false);
    ASSERT_TRUE(p.stable) << f;  // the branch is unstable between 2118 and 2221 Hz
    const Eigen::VectorXd rho = hbm.bearingDisplacements(p.q).rowwise().norm();
    const Eigen::MatrixXd d = hbm.meshDeflections(p.q);
    const TrainNonlinearTimeResponse r = testing::newmarkOnBalance(model, hbm, p);
    EXPECT_EQ(r.status, "steady_state") << r.message;
    const double radial =
        std::abs(r.bearingRadialPeakToPeak(0) / (rho.maxCoeff() - rho.minCoeff()) - 1);
    const double mesh = std::abs(r.meshPeakToPeak(0) / (d.maxCoeff() - d.minCoeff()) - 1);
    EXPECT_LT(radial, 0.01) << f;
    EXPECT_LT(mesh, 0.01) << f;
    worst = std::max({worst, radial, mesh});
    std::printf("%.0f Hz: |u| %.3g..%.3g um (play 7.5 um), p2p HBM %.4g Newmark %.4g um\n", f,
                1e6 * rho.minCoeff(), 1e6 * rho.maxCoeff(), 1e6 * (rho.maxCoeff() - rho.minCoeff()),
                1e6 * r.bearingRadialPeakToPeak(0));
  }
  std::printf("worst relative p2p difference HBM vs Newmark: %.2e\n", worst);
}

/// The option's limit names the key: torsional DOFs (the law acts on translations and tilts).
TEST(RollingBearingLaw, TorsionalDofsAreRefusedNamingTheKey) {
  GearTrainSpec spec = rollingPair(15e-6, 1.0, true);
  spec.dofs = TrainDofs::kTorsional;
  try {
    const GearTrainModel model(spec);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "bearings.pinion_bearing.model");
  }
}

}  // namespace
}  // namespace geardyn
