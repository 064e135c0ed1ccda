/// The Lyapunov estimate of torus solutions (train_torus_lyapunov.h): on a time-invariant train
/// against the damped modes' decay rate (closed form from the state matrix's eigenvalues).

#include "geardyn/solvers/train_torus_lyapunov.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "geardyn/stiffness/api_stiffness.h"
#include "solvers/torus_newmark_comparison.h"

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

}  // namespace
}  // namespace geardyn
