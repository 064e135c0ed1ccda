/// The Lyapunov estimate of torus solutions (train_torus_lyapunov.h): on a time-invariant train
/// against the damped modes' decay rate (closed form from the state matrix's eigenvalues), and
/// through a parametric instability against the monodromy matrix of the common-period balance.

#include "geardyn/torus/train_torus_lyapunov.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "geardyn/solvers/train_harmonic_balance.h"
#include "geardyn/stiffness/api_stiffness.h"
#include "system/nonlinear_sample_trains.h"
#include "torus/torus_newmark_comparison.h"

namespace geardyn {
namespace {

// The hunting-tooth reducer with constant mesh stiffnesses, no transmission error and linear
// contact: S(t) = 0, the variational equation is M x″ + C x′ + K̄ x = 0 and its largest Lyapunov
// exponent is the largest real part of the elastic damped modes' eigenvalues of
// [0 I; −M⁻¹K̄ −M⁻¹C] (the rigid rolling mode, λ = 0, excluded as the estimate projects it out).
// Newmark's decay error is O((λh)²) (h = 1/(64 f_mesh)), the window's 1.5 s is many decay times
// of the slowest mode, so the estimate is within a fraction of a percent: limit 1 %.
TEST(TrainTorusLyapunov, TimeInvariantTrainDecaysAsItsLeastDampedMode) {
  GearTrainSpec spec = testing::exampleGearbox("hunting_tooth_reducer.toml");
  for (auto& mesh : spec.meshes) {
    mesh.stiffness = std::make_shared<ConstantMeshStiffness>("constant", 5e8, 1.6);
    mesh.transmission_error = {};
  }
  const GearTrainModel model(spec);
  TrainTorusBalanceOptions options;
  options.mesh_harmonics = 2;
  TrainTorusBalance hb(model, options);
  HarmonicBalancePoint point;
  point.omega = hb.baseFrequency(model.inputSpeed());
  point.q = hb.startingGuess(point.omega);
  hb.solve(point);
  ASSERT_TRUE(point.converged);
  const TorusLyapunovEstimate estimate = torusLyapunovEstimate(model, hb, point, 1.5);
  ASSERT_EQ(estimate.status, "completed");

  const int n = model.dofCount();
  const double speed = model.inputSpeed();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  const Eigen::MatrixXd Minv = model.mass().inverse();
  A.topRightCorner(n, n).setIdentity();
  A.bottomLeftCorner(n, n) = -Minv * model.meanStiffnessAt(speed);
  A.bottomRightCorner(n, n) = -Minv * model.dampingAt(speed);
  const Eigen::VectorXcd lambda = Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues();
  const double scale = lambda.cwiseAbs().maxCoeff();
  double largest = -std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < lambda.size(); ++i) {
    if (std::abs(lambda(i)) > 1e-9 * scale) largest = std::max(largest, lambda(i).real());
  }
  ASSERT_LT(largest, 0.0);
  EXPECT_TRUE(estimate.stable);
  EXPECT_NEAR(estimate.max_exponent, largest, 0.01 * std::abs(largest));
  RecordProperty("estimate", fmt::format("{:.6g}", estimate.max_exponent));
  RecordProperty("closed_form", fmt::format("{:.6g}", largest));
  RecordProperty("steps", std::to_string(estimate.steps));
}

// One torsional pair (one generator: the torus balance is the common-period balance) with its
// smooth stiffness (first harmonic 12 % of k̄), linear contact and 1 % mesh damping, below and at
// the principal parametric resonance (mesh frequency 2 ω_n, ω_n the elastic mode): stable
// there and unstable here (ε/4 = 3 % > ζ). The Lyapunov estimate's λ₁ against the largest real
// Floquet exponent of the monodromy matrix (TrainHarmonicBalance::classify, Newmark over the
// period's 256 samples), both with 256 steps per mesh period. Measured: −0.009962 against
// −0.009999 ω_n (stable; the window's finite average) and 0.0201699 against 0.0201690 ω_n
// (unstable); the limit 5e-4 ω_n is 13 times the larger difference and 20 times below the
// exponents themselves.
TEST(TrainTorusLyapunov, ParametricResonanceAgainstTheMonodromyMatrix) {
  GearTrainSpec spec = testing::nonlinear::singlePair(1e-5);
  spec.meshes[0].contact = {};
  spec.meshes[0].damping_ratio = 0.01;
  const GearTrainModel model(spec);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> modes(
      model.meanStiffnessAt(model.inputSpeed()), model.mass(), Eigen::EigenvaluesOnly);
  const double omega_n = std::sqrt(modes.eigenvalues().maxCoeff());
  TrainTorusBalanceOptions torus_options;
  torus_options.mesh_harmonics = 10;
  TrainTorusBalance torus(model, torus_options);
  ASSERT_EQ(torus.generators().ratio.size(), 1u);
  TrainHarmonicBalanceOptions common_options;
  common_options.harmonics = 10;
  common_options.samples = 256;
  TrainHarmonicBalance common(model, common_options);
  int unstable = 0;
  for (double fraction : {0.8, 1.0}) {
    HarmonicBalancePoint a, b;
    a.omega = b.omega = 2.0 * omega_n * fraction;  // the mesh frequency (the base) [rad/s]
    a.q = common.startingGuess(a.omega);
    b.q = torus.startingGuess(b.omega);
    common.solve(a);
    torus.solve(b);
    ASSERT_TRUE(a.converged && b.converged) << fraction;
    common.classify(a, StabilityMethod::kMonodromy, false);
    const double window = 400.0 * 2.0 * std::numbers::pi / b.omega;  // 400 mesh periods
    const TorusLyapunovEstimate estimate = torusLyapunovEstimate(model, torus, b, window, 4, 256);
    ASSERT_EQ(estimate.status, "completed");
    EXPECT_EQ(estimate.stable, a.stable) << fraction;
    EXPECT_NEAR(estimate.max_exponent, a.max_floquet_real, 5e-4 * omega_n) << fraction;
    unstable += a.stable ? 0 : 1;
    RecordProperty(fmt::format("lyapunov_{:.1f}", fraction),
                   fmt::format("{:.6g}", estimate.max_exponent / omega_n));
    RecordProperty(fmt::format("floquet_{:.1f}", fraction),
                   fmt::format("{:.6g}", a.max_floquet_real / omega_n));
  }
  EXPECT_EQ(unstable, 1);  // the resonance is reached
}

}  // namespace
}  // namespace geardyn
