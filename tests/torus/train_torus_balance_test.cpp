/// The nonlinear torus balance (train_torus_balance.h): its analytic Jacobian against finite
/// differences, one generator against the common-period nonlinear balance
/// (train_harmonic_balance.h), and the hunting-tooth reducer with backlash against Newmark.

#include "geardyn/torus/train_torus_balance.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <numbers>

#include "geardyn/solvers/train_harmonic_balance.h"
#include "geardyn/torus/train_torus_lyapunov.h"
#include "system/nonlinear_sample_trains.h"
#include "torus/torus_newmark_comparison.h"

namespace geardyn {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// The hunting-tooth reducer of the example with backlash j at both meshes.
GearTrainSpec huntingWithBacklash(double j) {
  GearTrainSpec spec = testing::exampleGearbox("hunting_tooth_reducer.toml");
  for (auto& mesh : spec.meshes) mesh.contact = testing::nonlinear::backlash(j);
  return spec;
}

/// ‖∂R/∂ω − central difference (step 1e-6 ω)‖ / ‖difference‖ at (u, ω).
double speedDerivativeError(TrainTorusBalance& hb, const Eigen::VectorXd& u, double omega) {
  Eigen::VectorXd r, dr_domega, rp, rm;
  Eigen::MatrixXd J;
  hb.residual(u, omega, r, &J, &dr_domega);
  const double dw = 1e-6 * omega;
  hb.residual(u, omega + dw, rp, nullptr, nullptr);
  hb.residual(u, omega - dw, rm, nullptr, nullptr);
  const Eigen::VectorXd fd = (rp - rm) / (2.0 * dw);
  return (dr_domega - fd).norm() / fd.norm();
}

// ∂R/∂u and ∂R/∂ω against central differences at a state with contact loss on part of the grid
// (the linear solution pushed towards the back flank): the residual is piecewise smooth, so a
// step of 1e-7 of the state's scale changes the contact state of no grid point but a few; the
// tolerance 1e-5 of the Jacobian's largest entry is far above the differences' truncation and
// far below any missing or misplaced term (the slope spectra are O(1) of B k̄).
TEST(TrainTorusBalance, JacobianAgainstFiniteDifferences) {
  const GearTrainModel model(huntingWithBacklash(4e-5));
  TrainTorusBalanceOptions options;
  options.mesh_harmonics = 2;
  TrainTorusBalance hb(model, options);
  ASSERT_EQ(hb.generators().ratio.size(), 2u);
  const double omega = hb.baseFrequency(0.9 * model.inputSpeed());
  Eigen::VectorXd u = hb.startingGuess(omega);
  Eigen::VectorXd scatter = Eigen::VectorXd::LinSpaced(u.size(), -1.0, 1.0).array().sin();
  u += 0.3 * u.cwiseAbs().maxCoeff() * scatter;  // deep into contact loss somewhere
  Eigen::VectorXd r, dr_domega, rp, rm;
  Eigen::MatrixXd J;
  hb.residual(u, omega, r, &J, &dr_domega);
  const double h = 1e-7 * u.cwiseAbs().maxCoeff();
  Eigen::MatrixXd fd(u.size(), u.size());
  for (Eigen::Index i = 0; i < u.size(); ++i) {
    Eigen::VectorXd a = u, b = u;
    a(i) += h, b(i) -= h;
    hb.residual(a, omega, rp, nullptr, nullptr);
    hb.residual(b, omega, rm, nullptr, nullptr);
    fd.col(i) = (rp - rm) / (2.0 * h);
  }
  const double scale = J.cwiseAbs().maxCoeff();
  const double worst = (J - fd).cwiseAbs().maxCoeff() / scale;
  EXPECT_LT(worst, 1e-5);
  const double worst_omega = speedDerivativeError(hb, u, omega);
  EXPECT_LT(worst_omega, 1e-5);
  RecordProperty("jacobian", fmt::format("{:.3g}", worst));
  RecordProperty("omega", fmt::format("{:.3g}", worst_omega));
}

// The flexible hunting-tooth reducer (examples/gearboxes/hunting_tooth_reducer_flexible.toml:
// 270 DOFs, sparse harmonic blocks, the spinning shafts' gyroscopic terms): ∂R/∂ω, whose dD/dω
// is applied through the sparse M, C, K_Ω and G₁ (tone_block_derivative.h), against central
// differences of the residual in ω at a state with contact loss. The step 1e-6 ω leaves the
// grid's contact states as they are. Measured 2.8e-9; with the gyroscopic term dropped from
// dD/dω 7.2e-6 (this train's K_Ω is zero): the limit 1e-6 lies between.
TEST(TrainTorusBalance, SpeedDerivativeOfAFlexibleTrain) {
  const GearTrainModel model(testing::exampleGearbox("hunting_tooth_reducer_flexible.toml"));
  ASSERT_GT(model.dofCount(), 200);
  ASSERT_GT(model.gyroscopic().cwiseAbs().maxCoeff(), 0.0);
  TrainTorusBalanceOptions options;
  options.mesh_harmonics = 2;
  TrainTorusBalance hb(model, options);
  const double omega = hb.baseFrequency(1.2 * model.inputSpeed());
  Eigen::VectorXd u = hb.startingGuess(omega);
  Eigen::VectorXd scatter = Eigen::VectorXd::LinSpaced(u.size(), -1.0, 1.0).array().sin();
  u += 0.3 * u.cwiseAbs().maxCoeff() * scatter;
  const double worst = speedDerivativeError(hb, u, omega);
  EXPECT_LT(worst, 1e-6);
  RecordProperty("omega", fmt::format("{:.3g}", worst));
}

// One generator (the two-stage reducer's meshes are 3:1, common period of three stage-1 mesh
// periods): the torus tones are the harmonics 0..3L of the common period, the grid is the
// common period's samples, so both balances solve the same equations: the mesh deflections'
// harmonics agree to round-off at a speed where stage 1 loses contact (base 1.7 kHz).
TEST(TrainTorusBalance, OneGeneratorIsTheCommonPeriodBalance) {
  const GearTrainModel model(testing::nonlinear::twoStage(2e-5));
  TrainTorusBalanceOptions torus_options;
  torus_options.mesh_harmonics = 10;
  TrainTorusBalance torus(model, torus_options);
  ASSERT_EQ(torus.generators().ratio.size(), 1u);
  const int H = torus.generators().harmonics[0];
  ASSERT_EQ(H, 30);
  TrainHarmonicBalanceOptions common_options;
  common_options.harmonics = H;
  common_options.samples = torus.gridSamples()[0];
  TrainHarmonicBalance common(model, common_options);
  const double omega = kTwoPi * 1700.0;
  HarmonicBalancePoint a, b;
  a.omega = b.omega = omega;
  a.q = common.startingGuess(omega);
  b.q = torus.startingGuess(omega);
  common.solve(a);
  torus.solve(b);
  ASSERT_TRUE(a.converged && b.converged);
  const Eigen::MatrixXd da = common.meshDeflections(a.q);
  const Eigen::VectorXd t =
      Eigen::VectorXd::LinSpaced(da.rows(), 0.0, da.rows() - 1.0) * (kTwoPi / omega / da.rows());
  const Eigen::MatrixXd db = torus.coordinatesAt(b.q, omega, t);
  double worst = 0.0, contact_loss = 0.0;
  for (Eigen::Index m = 0; m < da.cols(); ++m) {
    const double p2p = da.col(m).maxCoeff() - da.col(m).minCoeff();
    worst = std::max(worst, (da.col(m) - db.col(m)).cwiseAbs().maxCoeff() / p2p);
  }
  const Eigen::MatrixXd forces = common.meshContactForces(a.q);
  contact_loss = (forces.col(0).array() == 0.0).cast<double>().mean();
  EXPECT_GT(contact_loss, 0.05);  // the nonlinearity is exercised
  EXPECT_LT(worst, 1e-8);
  RecordProperty("worst", fmt::format("{:.3g}", worst));
  RecordProperty("contact_loss_fraction", fmt::format("{:.3g}", contact_loss));
}

}  // namespace
}  // namespace geardyn

namespace geardyn {
namespace {

// The hunting-tooth reducer (common period 71 stage-1 mesh periods) with 20 µm backlash at both
// meshes, half the load (100 N m), the smooth three-harmonic stiffness of the two-stage fixture (so
// that L = 6 holds its force spectrum) and its transmission errors: the linear torus balance finds
// stage 1's resonance (largest dynamic factor over 1–16 × the operating speed), the nonlinear torus
// balance is continued in speed through it (each solution the next one's guess: all
// frequencies move together) and checked at three speeds against Newmark (average acceleration,
// 256 steps per stage-1 mesh period, event refinement) started on the solution and run for
// 0.3 s, beyond the decay time of the modes the meshes excite: the p2p of each mesh
// deflection over the last half of the run within 1 % of the torus solution's (issue 32).
TEST(TrainTorusBalance, HuntingToothReducerWithBacklashAgainstNewmark) {
  GearTrainSpec spec = huntingWithBacklash(2e-5);
  spec.meshes[0].stiffness = testing::nonlinear::smooth(4e8, 0.0);
  spec.meshes[1].stiffness = testing::nonlinear::smooth(6e8, 40.0);
  spec.meshes[0].transmission_error = {};
  spec.meshes[0].transmission_error.addFourier({8e-6, 2e-6}, {0.0, 0.5});
  spec.meshes[1].transmission_error.addFourier({6e-6}, {0.3});
  spec.operating.input_torque = 100.0;  // half the example's: stage 1's dynamic factor 2.7
  const GearTrainModel model(spec);
  TrainTorusOptions linear_options;
  linear_options.mesh_harmonics = 6;
  const TrainTorusSolver linear(model, linear_options);
  double peak = 0.0, largest = 0.0;
  for (int i = 0; i <= 150; ++i) {
    const double speed = model.inputSpeed() * (1.0 + 0.1 * i);
    const double factor = linear.solve(speed).dynamic_factor[0];
    if (factor > largest) largest = factor, peak = speed;
  }
  ASSERT_GT(largest, 2.0);  // the linear force changes sign: contact is lost there
  TrainTorusBalanceOptions options;
  options.mesh_harmonics = 6;
  TrainTorusBalance hb(model, options);
  HarmonicBalancePoint point;
  point.omega = hb.baseFrequency(0.8 * peak);
  point.q = hb.startingGuess(point.omega);
  int checked = 0, with_loss = 0;
  for (int i = 0; i <= 15; ++i) {
    const double f = 0.8 + 0.02 * i;
    point.omega = hb.baseFrequency(f * peak);
    hb.solve(point);
    if (!point.converged) break;  // a fold: the natural continuation ends
    const Eigen::MatrixXd forces = hb.gridMeshForces(point.q);
    const double loss = (forces.col(0).array() == 0.0).cast<double>().mean();
    RecordProperty(fmt::format("contact_loss_{:.2f}", f), fmt::format("{:.3g}", loss));
    if (i != 5 && i != 10 && i != 13) continue;
    const TorusNewmarkCheck check = torusNewmarkCheck(model, hb, point, 0.3);
    ASSERT_EQ(check.status, "completed") << f;
    ++checked;
    with_loss += loss > 0.0 ? 1 : 0;
    for (std::size_t m = 0; m < check.p2p_torus.size(); ++m) {
      const double error = std::abs(check.p2p_newmark[m] / check.p2p_torus[m] - 1.0);
      EXPECT_LT(error, 0.01) << f << " mesh " << m;
      RecordProperty(fmt::format("p2p_error_{:.2f}_mesh{}", f, m), fmt::format("{:.3g}", error));
      RecordProperty(fmt::format("deviation_{:.2f}_mesh{}", f, m),
                     fmt::format("{:.3g}", check.deviation[m]));
    }
    RecordProperty(fmt::format("stable_{:.2f}", f), check.stable ? 1 : 0);
    // The Lyapunov estimate (train_torus_lyapunov.h) over the same window gives the same verdict.
    const TorusLyapunovEstimate lyapunov = torusLyapunovEstimate(model, hb, point, 0.3);
    ASSERT_EQ(lyapunov.status, "completed") << f;
    EXPECT_EQ(lyapunov.stable, check.stable) << f;
    RecordProperty(fmt::format("lyapunov_{:.2f}", f), fmt::format("{:.4g}", lyapunov.max_exponent));
  }
  RecordProperty("peak_rpm", fmt::format("{:.0f}", peak * 30.0 / std::numbers::pi));
  EXPECT_GE(checked, 2);
  EXPECT_GE(with_loss, 1);
}

}  // namespace
}  // namespace geardyn
