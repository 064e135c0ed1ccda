/// A planetary stage in its carrier frame at speed: the rolling motion stays neutral (the
/// centripetal term acts on the planets' motion relative to the carrier's rotation), Lin &
/// Parker's form −m_p Ω_c² u_p would make it diverge at the rate its Rayleigh quotient
/// predicts, and divergent modes are reported, never clipped to rigid-body modes
/// (docs/theory/gear_trains.md, "Planetary stages in the carrier frame").

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <vector>

#include "geardyn/numerics/damped_modes.h"
#include "geardyn/solvers/train_modal.h"
#include "geardyn/system/gear_train_model.h"
#include "system/sample_trains.h"

namespace geardyn {
namespace {

using testing::linParker1999;

/// The Lin & Parker stage with the sun turning at `sun_speed` [rad/s], carrier-frame terms on.
GearTrainModel stageAt(double sun_speed) {
  GearTrainSpec spec = linParker1999(3);
  spec.operating.input_speed = sun_speed;
  return GearTrainModel(spec);
}

/// The stage's rolling mode: the null vector of the mean stiffness at rest (the ring is held in
/// torsion, so the sun, carrier and planets roll on it).
Eigen::VectorXd rollingMode(const GearTrainModel& model) {
  const Eigen::MatrixXd K = model.stiffness() + model.meanMeshStiffness();
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(K, model.mass());
  EXPECT_LT(std::abs(eig.eigenvalues()(0)), 1e-6 * std::abs(eig.eigenvalues()(1)));
  return eig.eigenvectors().col(0);
}

/// Lin & Parker's (1999, eq. 1) centripetal matrix: −m ω_c² on every translation of the stage.
Eigen::MatrixXd linParkerCentripetal(const GearTrainModel& model) {
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(model.dofCount(), model.dofCount());
  const double rc = model.bodies()[model.bodyIndex("carrier")].speed_ratio;
  for (const TrainBody& b : model.bodies()) {
    if (b.stage < 0) continue;
    K(b.first_dof, b.first_dof) = K(b.first_dof + 1, b.first_dof + 1) = -b.mass * rc * rc;
  }
  return K;
}

TEST(CarrierFrame, RollingModeStaysNeutralAtSpeed) {
  // Carrier at 300 rad/s (sun 4 × 300): Σ m_p Ω_c² R² = 640 N m/rad would be the rolling mode's
  // negative stiffness in Lin & Parker's form. Here K̄(Ω) r = 0 to round-off: 1e-12 of ‖K̄‖‖r‖
  // (‖K̄‖ ~ 1e9 N/m, cancellations of mesh terms ~ 1e-16 each).
  const GearTrainModel model = stageAt(1200.0);
  const Eigen::VectorXd r = rollingMode(model);
  const Eigen::MatrixXd K = model.meanStiffnessAt(model.inputSpeed());
  EXPECT_LT((K * r).norm(), 1e-12 * K.norm() * r.norm());
  EXPECT_LT((K - K.transpose()).norm(), 1e-15 * K.norm());  // still symmetric

  // Modal analysis at speed: no divergent mode, 17 oscillating ones (18 DOFs less the rolling).
  const auto modes = trainModes(model, model.inputSpeed());
  EXPECT_EQ(modes.size(), 17u);
  for (const TrainMode& m : modes) EXPECT_FALSE(m.divergent) << m.eigenvalue;
}

TEST(CarrierFrame, LinParkerFormDivergesAtTheRayleighRate) {
  // The same stage with Lin & Parker's −m Ω_c² u on the planets: the rolling mode becomes a real
  // eigenvalue pair ±λ. First-order perturbation of the neutral mode r: λ² = −rᵀ ΔK r / rᵀ M r
  // with ΔK = Ω² K_Ω,LP (the elastic modes are ≥ 700 Hz ≫ λ/2π ≈ 20 Hz, so the shape is r to
  // O(λ²/ω²) ~ 1e-3: tolerance 1 %). dampedModes reports it as divergent (before, the negative
  // stiffness was clipped to 0 and the mode dropped as rigid).
  const GearTrainModel model = stageAt(1200.0);
  const double speed = model.inputSpeed();
  const Eigen::MatrixXd dK = speed * speed * linParkerCentripetal(model);
  const Eigen::MatrixXd K = model.stiffness() + model.meanMeshStiffness() + dK;
  const Eigen::VectorXd r = rollingMode(model);
  const double predicted = std::sqrt(-r.dot(dK * r) / r.dot(model.mass() * r));
  ASSERT_GT(predicted, 10.0);
  const auto found = detail::dampedModes(model.mass(), model.dampingAt(speed), K);
  int divergent = 0;
  double rate = 0.0;
  for (const auto& m : found) {
    if (!detail::isDivergent(m.eigenvalue)) continue;
    ++divergent;
    rate = m.eigenvalue.real();
  }
  EXPECT_EQ(divergent, 1);
  EXPECT_NEAR(rate, predicted, 0.01 * predicted);
}

TEST(CarrierFrame, ElasticModesMoveByOrderCentripetalOverPinStiffness) {
  // The two forms differ by m_p Ω_c² R θ_c (u_p − θ_c J R)·t: a coupling of the carrier's
  // rotation with the pin deflection, O(m_p Ω_c² / k) relative on the elastic modes (≈ 6e-4
  // here, k = 1e8 N/m): the frequencies agree within 10 × that bound. A sign error in the new
  // term (+m Ω_c² instead of −) doubles the centripetal coupling and fails the rolling test.
  const GearTrainModel model = stageAt(1200.0);
  const double speed = model.inputSpeed();
  const double rc = model.bodies()[model.bodyIndex("carrier")].speed_ratio;
  const double bound = 10.0 * 0.66 * std::pow(rc * speed, 2) / 1e8;
  const Eigen::MatrixXd D = model.dampingAt(speed);
  const Eigen::MatrixXd base = model.stiffness() + model.meanMeshStiffness();
  auto frequencies = [&](const Eigen::MatrixXd& K) {
    std::vector<double> f;
    for (const auto& m : detail::dampedModes(model.mass(), D, K)) {
      if (!detail::isDivergent(m.eigenvalue) && m.eigenvalue.imag() > 1.0) {
        f.push_back(m.eigenvalue.imag());
      }
    }
    std::sort(f.begin(), f.end());
    return f;
  };
  const auto ours = frequencies(model.meanStiffnessAt(speed));
  const auto lin_parker = frequencies(base + speed * speed * linParkerCentripetal(model));
  ASSERT_EQ(ours.size(), 17u);
  ASSERT_EQ(lin_parker.size(), 17u);
  double largest = 0.0;
  for (std::size_t j = 0; j < ours.size(); ++j) {
    largest = std::max(largest, std::abs(ours[j] / lin_parker[j] - 1.0));
  }
  EXPECT_LT(largest, bound);
  EXPECT_GT(largest, 0.0);
}

TEST(DampedModes, ReportsADivergenceWithItsExactRate) {
  // M = I, D = 0.1 I, K = diag(−4, 9): λ² + 0.1 λ − 4 = 0 gives the divergence
  // λ = (−0.1 + √16.01)/2, and λ² + 0.1 λ + 9 = 0 the oscillating pair −0.05 ± i √8.9975.
  const Eigen::MatrixXd M = Eigen::MatrixXd::Identity(2, 2);
  const Eigen::MatrixXd D = 0.1 * M;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(2, 2);
  K(0, 0) = -4.0;
  K(1, 1) = 9.0;
  const auto modes = detail::dampedModes(M, D, K);
  ASSERT_EQ(modes.size(), 2u);
  int divergent = 0;
  for (const auto& m : modes) {
    if (detail::isDivergent(m.eigenvalue)) {
      ++divergent;
      EXPECT_NEAR(m.eigenvalue.real(), 0.5 * (-0.1 + std::sqrt(16.01)), 1e-12);
      EXPECT_NEAR(std::abs(m.shape(0)), 1.0, 1e-12);
      EXPECT_NEAR(std::abs(m.shape(1)), 0.0, 1e-12);
    } else {
      EXPECT_NEAR(m.eigenvalue.real(), -0.05, 1e-12);
      EXPECT_NEAR(m.eigenvalue.imag(), std::sqrt(8.9975), 1e-12);
    }
  }
  EXPECT_EQ(divergent, 1);
}

/// The Lin & Parker stage on soft radial pins (1e5 N/m) with soft meshes (1e7 N/m), the sun at
/// `rpm`: the planets' anisotropic support in the turning frame diverges at high speed.
GearTrainModel softPinStage(double rpm) {
  GearTrainSpec spec = linParker1999(3);
  spec.stages[0].pin_radial_stiffness = 1e5;
  spec.stages[0].sun_planet_stiffness =
      std::make_shared<ConstantMeshStiffness>("constant", 1e7, 1.5);
  spec.stages[0].ring_planet_stiffness =
      std::make_shared<ConstantMeshStiffness>("constant", 1e7, 1.5);
  spec.operating.input_speed = rpm * std::numbers::pi / 30.0;
  return GearTrainModel(spec);
}

/// The eigenvalues of the textbook first-order form [[0, I], [−M⁻¹K, −M⁻¹D]] at the model's
/// speed: an independent solution (18 DOFs). Scaled as [[0, s I], [−M⁻¹K/s, −M⁻¹D]] (state
/// (x, x′/s), the same eigenvalues) with s = √‖M⁻¹K‖: unscaled, ‖M⁻¹K‖ ~ 1e8 against 1 in the
/// identity block left the divergent rate (~145 1/s) with ~6e-6 relative round-off (measured
/// between builds with and without -march=native); balanced, 1.1e-9.
Eigen::VectorXcd textbookEigenvalues(const GearTrainModel& model) {
  const int n = model.dofCount();
  const double speed = model.inputSpeed();
  const Eigen::MatrixXd Minv = model.mass().inverse();
  const Eigen::MatrixXd MinvK = Minv * model.meanStiffnessAt(speed);
  const double s = std::sqrt(MinvK.norm());
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n) = s * Eigen::MatrixXd::Identity(n, n);
  A.bottomLeftCorner(n, n) = -MinvK / s;
  A.bottomRightCorner(n, n) = -Minv * model.dampingAt(speed);
  Eigen::EigenSolver<Eigen::MatrixXd> solver;
  solver.setMaxIterations(400 * A.rows());
  solver.compute(A, false);
  EXPECT_EQ(solver.info(), Eigen::Success);
  return solver.eigenvalues();
}

TEST(TrainModes, ListDivergentModesFirstWithTheGrowthRateOfTheFirstOrderForm) {
  // At 30 000 rpm one mode diverges; its rate against the textbook form (tolerance 1e-6).
  const GearTrainModel model = softPinStage(30000.0);
  const auto modes = trainModes(model, model.inputSpeed());
  ASSERT_FALSE(modes.empty());
  ASSERT_TRUE(modes.front().divergent);
  EXPECT_EQ(modes.front().frequency, 0.0);
  EXPECT_EQ(modes.front().damping_ratio, -1.0);
  const Eigen::VectorXcd lambda = textbookEigenvalues(model);
  double largest_real = 0.0;
  for (Eigen::Index j = 0; j < lambda.size(); ++j) {
    if (std::abs(lambda(j).imag()) < 1e-6 * std::abs(lambda(j))) {
      largest_real = std::max(largest_real, lambda(j).real());
    }
  }
  std::printf("divergent rate %.12g 1/s, textbook form %.12g 1/s\n",
              modes.front().eigenvalue.real(), largest_real);
  EXPECT_NEAR(modes.front().eigenvalue.real(), largest_real, 1e-6 * largest_real);
}

TEST(TrainModes, SolveNearTheGyroscopicStabilityBoundary) {
  // At 16 797 rpm a mode of the turning frame is near 0 Hz and the real QR of the balanced form
  // stagnates (it threw "did not converge" with 40 and with 400 sweeps per row); the complex QR
  // takes over. Every oscillating mode above 1 Hz is one of the textbook form's (1e-6).
  const GearTrainModel model = softPinStage(16797.468354430377);
  const auto modes = trainModes(model, model.inputSpeed());
  const Eigen::VectorXcd lambda = textbookEigenvalues(model);
  int compared = 0;
  for (const TrainMode& m : modes) {
    if (m.divergent || m.frequency < 1.0) continue;
    double nearest = HUGE_VAL;
    for (Eigen::Index j = 0; j < lambda.size(); ++j) {
      nearest = std::min(nearest, std::abs(lambda(j) - m.eigenvalue));
    }
    EXPECT_LT(nearest, 1e-6 * std::abs(m.eigenvalue)) << m.frequency << " Hz";
    ++compared;
  }
  EXPECT_GE(compared, 14);
}

}  // namespace
}  // namespace geardyn
