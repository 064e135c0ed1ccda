// The full law of a rolling bearing with full DOFs (issue 35: bearings.<name>.model =
// "nonlinear" over (u_y, u_z, u_x, θ_y, θ_z)) in the harmonic balance and nonlinear Newmark,
// the `time` response with the full law (the nonlinear Newmark on the linear run's plan)
// against the nonlinear balance's steady state, and the torus balance with the full law
// (planar and full DOFs) against Newmark.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>

#include "geardyn/solvers/train_harmonic_balance.h"
#include "geardyn/solvers/train_nonlinear_time.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/solvers/train_time.h"
#include "geardyn/system/bearing_law.h"
#include "geardyn/torus/train_torus_balance.h"
#include "support/numeric_assertions.h"
#include "system/nonlinear_trains.h"
#include "system/rolling_bearing_law_trains.h"
#include "torus/torus_newmark_comparison.h"

namespace geardyn {
namespace {

using testing::linearisedAtStatics;
using testing::rollingPair;
using testing::rollingPairFullDofs;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
using Matrix = TrainBearingLaw::Matrix;
using Vector = TrainBearingLaw::Vector;

/// The balance at the operating speed from its starting guess (H harmonics, 16 H samples).
HarmonicBalancePoint balanceAt(TrainHarmonicBalance& hbm, double speed) {
  HarmonicBalancePoint p;
  p.omega = hbm.baseFrequency(speed);
  p.q = hbm.startingGuess(p.omega);
  hbm.solve(p);
  EXPECT_TRUE(p.converged) << p.residual;
  return p;
}

TrainHarmonicBalanceOptions balanceOptions(int harmonics) {
  TrainHarmonicBalanceOptions options;
  options.harmonics = harmonics;
  options.samples = 16 * harmonics;
  options.tolerance = 1e-12;
  return options;
}

/// With full DOFs the bearing's coordinates are its five, its force and 5 × 5 Jacobian the
/// bearing's own (exactly), the correction's Jacobian against central differences (1e-6 of
/// ‖J‖: δ^{3/2} is smooth where no ball is at δ = 0; h = 1e-10 m or rad × 1e-2 m, truncation
/// ~ h² f‴), and the harmonic balance has 1 + 5 coordinates.
TEST(RollingBearingFullDofs, CoordinatesAreTheBearingsFive) {
  const GearTrainModel model = linearisedAtStatics(rollingPairFullDofs(5e-6, 1.0, true));
  ASSERT_EQ(model.clearanceBearings().size(), 1u);
  const TrainBearingLaw b(model, model.clearanceBearings()[0]);
  ASSERT_EQ(b.width(), 5);
  EXPECT_EQ(model.nonlinearVectors().cols(), 6);
  // K keeps the bearing's linearised 5 × 5 tangent: the law's linear part.
  Vector u(5);
  u << 8e-6, -3e-6, 4e-6, 2e-5, -1e-5;
  RollingBearing::Vector5 F;
  RollingBearing::Matrix5 K;
  b.bearing().rolling->evaluate(RollingBearing::Vector5(u), F, &K);
  Matrix J(5, 5);
  EXPECT_EQ(Vector(b.contactForce(u, &J)), Vector(F));
  EXPECT_EQ(J, Matrix(K));
  EXPECT_TRUE(b.touching(u));
  Matrix Jc(5, 5);
  const Vector fc = b.correctionForce(u, &Jc);
  EXPECT_LT((fc - (F - b.linear() * u)).norm(), 1e-12 * F.norm());
  for (int j = 0; j < 5; ++j) {
    const double h = j < 3 ? 1e-10 : 1e-8;
    Vector up = u, um = u;
    up(j) += h;
    um(j) -= h;
    const Vector fd = (b.correctionForce(up, nullptr) - b.correctionForce(um, nullptr)) / (2 * h);
    EXPECT_LT((Jc.col(j) - fd).norm(), 1e-6 * J.norm()) << j;
  }
}

/// ∂R/∂u and ∂R/∂ω₀ of the full-DOF balance against central differences (the helper's 1e-5 of
/// a column's norm) about the starting guess, pressed and with an orbit of every coordinate.
TEST(RollingBearingFullDofs, HarmonicBalanceJacobianMatchesFiniteDifferences) {
  const GearTrainModel model = linearisedAtStatics(rollingPairFullDofs(5e-6, 1.0, true));
  TrainHarmonicBalance hbm(model, balanceOptions(3));
  ASSERT_EQ(hbm.coordinateCount(), 6);
  const int n = 2 * 3 + 1;
  const double omega = hbm.baseFrequency(model.inputSpeed());
  const Eigen::VectorXd guess = hbm.startingGuess(omega);
  for (double A : {0.3e-6, 3e-6}) {
    Eigen::VectorXd u = guess;
    for (int c = 1; c <= 3; ++c) u(c * n + 1) = A, u(c * n + 2) = 0.5 * A;
    for (int c = 4; c <= 5; ++c) u(c * n + 1) = A / 0.03;  // tilts moving the balls by ~A
    testing::nonlinear::expectJacobianMatchesCentralDifferences(hbm, u, omega,
                                                                A > 1e-6 ? "orbit" : "pressed");
  }
}

/// Without excitation the balance's solution is its mean, the static equilibrium with the full
/// law: the nonlinear static deflection (train_static_bearings.cpp, Newton on all DOFs), a
/// second solver of the same equations, in all five coordinates (1e-8 relative, the two
/// tolerances); the helix's axial force moves the bearing axially (|u_x| > 1 µm).
TEST(RollingBearingFullDofs, UnexcitedBalanceIsTheNonlinearStaticDeflection) {
  const GearTrainSpec spec = rollingPairFullDofs(5e-6, 0.0, false);
  const GearTrainModel original(spec);
  const TrainStaticResult statics = solveTrainStatic(original, original.inputSpeed());
  const GearTrainModel model = original.linearisedAt(statics.displacement);
  TrainHarmonicBalance hbm(model, balanceOptions(3));
  const HarmonicBalancePoint p = balanceAt(hbm, model.inputSpeed());
  const Eigen::VectorXd mean = hbm.displacementCoefficients(p).col(0);
  const Eigen::Matrix<double, 5, 1> expected =
      original.rollingBearings()[0].displacement(statics.displacement);
  const Eigen::Matrix<double, 5, 1> got = original.rollingBearings()[0].displacement(mean);
  std::printf("static bearing deflection (y, z, x) %.4g %.4g %.4g um, tilts %.3g %.3g mrad\n",
              1e6 * expected(0), 1e6 * expected(1), 1e6 * expected(2), 1e3 * expected(3),
              1e3 * expected(4));
  EXPECT_GT(std::abs(expected(2)), 1e-6);
  EXPECT_LT((got.head<3>() - expected.head<3>()).norm(), 1e-8 * expected.head<3>().norm());
  EXPECT_LT((got.tail<2>() - expected.tail<2>()).norm(), 1e-8 * expected.tail<2>().norm() + 1e-14);
}

/// The full-DOF balance against nonlinear Newmark started on its solution (512 steps a mesh
/// period, steady to 1e-8) at 5040 and 3000 rpm (mesh frequencies 2.1 and 1.25 kHz): the p2p of
/// the bearing's radial |u|, of its axial u_x and of the mesh deflection agree within 1 % (the
/// balance's truncation at H = 12, Newmark's second-order error), and the axial motion is not
/// negligible (its p2p above 1 % of the radial one: the helical mesh drives the axial DOF).
TEST(RollingBearingFullDofs, HarmonicBalanceAgreesWithNewmark) {
  const GearTrainModel model = linearisedAtStatics(rollingPairFullDofs(5e-6, 1.0, true));
  TrainHarmonicBalance hbm(model, balanceOptions(12));
  double worst = 0.0;
  for (double rpm : {5040.0, 6100.0, 7680.0}) {
    HarmonicBalancePoint p = balanceAt(hbm, rpm * kTwoPi / 60.0);
    hbm.classify(p, StabilityMethod::kMonodromy, false);
    ASSERT_TRUE(p.stable) << rpm;
    const int c = hbm.bearingCoordinate(0);
    const Eigen::VectorXd rho = hbm.bearingDisplacements(p.q).rowwise().norm();
    const Eigen::MatrixXd d = hbm.meshDeflections(p.q);
    const TrainNonlinearTimeResponse r = testing::newmarkOnBalance(model, hbm, p);
    ASSERT_EQ(r.status, "steady_state") << r.message;
    // u_x over Newmark's last period and over the balance's samples.
    const TrainClearanceBearing& b = model.clearanceBearings()[0];
    Eigen::VectorXd ux_newmark(r.displacement.rows());
    for (Eigen::Index k = 0; k < ux_newmark.size(); ++k) {
      double ux = 0.0;
      for (std::size_t i = 0; i < b.dofs.size(); ++i)
        ux += b.jacobian(2, static_cast<Eigen::Index>(i)) * r.displacement(k, b.dofs[i]);
      ux_newmark(k) = ux;
    }
    // The balance's u_x (its coordinate block c + 2) on 256 points of the period.
    const int H = hbm.harmonics(), N = 256;
    Eigen::VectorXd ux_hbm(N);
    const int n = 2 * H + 1;
    for (int k = 0; k < N; ++k) {
      const double tau = kTwoPi * k / N;
      double ux = p.q((c + 2) * n);
      for (int h = 1; h <= H; ++h) {
        ux += p.q((c + 2) * n + 2 * h - 1) * std::cos(h * tau) +
              p.q((c + 2) * n + 2 * h) * std::sin(h * tau);
      }
      ux_hbm(k) = ux;
    }
    const double p2p_x = ux_hbm.maxCoeff() - ux_hbm.minCoeff();
    const double p2p_r = rho.maxCoeff() - rho.minCoeff();
    const double radial = std::abs(r.bearingRadialPeakToPeak(0) / p2p_r - 1);
    const double axial = std::abs((ux_newmark.maxCoeff() - ux_newmark.minCoeff()) / p2p_x - 1);
    const double mesh = std::abs(r.meshPeakToPeak(0) / (d.maxCoeff() - d.minCoeff()) - 1);
    EXPECT_LT(radial, 0.01) << rpm;
    EXPECT_LT(axial, 0.01) << rpm;
    EXPECT_LT(mesh, 0.01) << rpm;
    EXPECT_GT(p2p_x, 0.01 * p2p_r) << rpm;
    worst = std::max({worst, radial, axial, mesh});
    std::printf(
        "%.0f rpm: p2p |u| %.4g um (Newmark %.4g), u_x %.4g um (Newmark %.4g), mesh "
        "%.4g um\n",
        rpm, 1e6 * p2p_r, 1e6 * r.bearingRadialPeakToPeak(0), 1e6 * p2p_x,
        1e6 * (ux_newmark.maxCoeff() - ux_newmark.minCoeff()), 1e6 * (d.maxCoeff() - d.minCoeff()));
  }
  std::printf("worst relative p2p difference HBM vs Newmark (full DOFs): %.2e\n", worst);
}

/// The `time` response with the full law (planar pair, s_r 15 µm, at 7680 rpm, a mesh frequency
/// of 3.2 kHz: a stable point of train_rolling_bearing_law_test's sweep where the orbit moves
/// the load zone) against the nonlinear balance's steady state at that speed (H = 12): the p2p
/// of the mesh force and of the bearing's |u| over the recorded period within 1 % (the
/// balance's truncation, Newmark's 128 steps a mesh period); the linearised bearing (what
/// `time` ran before) is ≥ 5 % off, so the check separates the two.
TEST(RollingBearingTime, TimeWithTheFullLawIsTheNonlinearSteadyState) {
  GearTrainSpec spec0 = rollingPair(15e-6, 1.0, true);
  spec0.operating.input_speed = 7680.0 * kTwoPi / 60.0;
  const GearTrainModel model = linearisedAtStatics(spec0);
  const double speed = model.inputSpeed();
  TrainHarmonicBalance hbm(model, balanceOptions(12));
  const HarmonicBalancePoint p = balanceAt(hbm, speed);
  const Eigen::MatrixXd f_hbm = hbm.meshContactForces(p.q);
  const Eigen::VectorXd rho = hbm.bearingDisplacements(p.q).rowwise().norm();
  const double p2p_f = f_hbm.maxCoeff() - f_hbm.minCoeff(), p2p_u = rho.maxCoeff() - rho.minCoeff();

  TrainTimeOptions options;
  options.steps_per_mesh_period = 128;
  options.duration = 0.3;  // s: 960 mesh periods for the transient to decay
  const TrainTimeResponse r = solveTrainTimeResponse(model, speed, options);
  ASSERT_EQ(r.status, "completed") << r.message;
  const TrainClearanceBearing& b = model.clearanceBearings()[0];
  Eigen::VectorXd radius(r.displacement.rows());
  for (Eigen::Index k = 0; k < radius.size(); ++k)
    radius(k) = b.displacement(r.displacement.row(k).transpose()).norm();
  const double force = std::abs((r.mesh_force.maxCoeff() - r.mesh_force.minCoeff()) / p2p_f - 1);
  const double orbit = std::abs((radius.maxCoeff() - radius.minCoeff()) / p2p_u - 1);
  std::printf("time vs nonlinear balance: mesh force p2p %.4g N (%.2e), |u| p2p %.4g um (%.2e)\n",
              p2p_f, force, 1e6 * p2p_u, orbit);
  EXPECT_LT(force, 0.01);
  EXPECT_LT(orbit, 0.01);

  // The linearised bearing (what `time` ran before): the same plan through the linear stepper.
  GearTrainSpec spec = model.spec();
  spec.bearings[0].nonlinear_law = nullptr;
  spec.bearings[0].full_law = false;
  const GearTrainModel linear(spec);
  ASSERT_TRUE(linear.clearanceBearings().empty());
  const TrainTimeResponse l = solveTrainTimeResponse(linear, speed, options);
  const double linear_force =
      std::abs((l.mesh_force.maxCoeff() - l.mesh_force.minCoeff()) / p2p_f - 1);
  Eigen::VectorXd linear_radius(l.displacement.rows());
  for (Eigen::Index k = 0; k < linear_radius.size(); ++k)
    linear_radius(k) = b.displacement(l.displacement.row(k).transpose()).norm();
  const double linear_orbit =
      std::abs((linear_radius.maxCoeff() - linear_radius.minCoeff()) / p2p_u - 1);
  std::printf(
      "linearised bearing vs nonlinear balance: mesh force p2p off by %.2e, |u| p2p "
      "by %.2e\n",
      linear_force, linear_orbit);
  EXPECT_GT(linear_orbit, 0.05);
}

/// The torus balance with the full law (planar DOFs): the hunting-tooth reducer of
/// examples/gearboxes (its common period needs ~10⁴ harmonics) with smooth k(φ) and the
/// transmission errors of train_torus_balance_test, its input shaft on two 6208-like ball
/// bearings (s_r 15 µm) with their full law. At the operating speed and at twice it the torus
/// solution (6 mesh harmonics per generator) against Newmark started on it and run for 0.3 s
/// (torusNewmarkCheck: 256 steps per stage-1 mesh period): the p2p of every nonlinear
/// coordinate (the two mesh deflections, each bearing's u_y and u_z) over the last half of the
/// run within 1 % of the torus solution's, as for the meshes with backlash there.
TEST(RollingBearingTorus, HuntingReducerWithFullLawAgainstNewmark) {
  GearTrainSpec spec = testing::exampleGearbox("hunting_tooth_reducer.toml");
  spec.meshes[0].stiffness = testing::nonlinear::smooth(4e8, 0.0);
  spec.meshes[1].stiffness = testing::nonlinear::smooth(6e8, 40.0);
  spec.meshes[0].transmission_error = {};
  spec.meshes[0].transmission_error.addFourier({8e-6, 2e-6}, {0.0, 0.5});
  spec.meshes[1].transmission_error.addFourier({6e-6}, {0.3});
  spec.operating.input_torque = 100.0;
  for (TrainBearingSpec& b : spec.bearings) {
    if (b.shaft != "input") continue;
    b.kyy = b.kzz = b.kyz = b.kzy = 0.0;
    b.rolling = testing::deepGroove6208();
    b.full_law = true;
  }
  const GearTrainModel model = linearisedAtStatics(spec);
  ASSERT_EQ(model.clearanceBearings().size(), 2u);
  TrainTorusBalanceOptions options;
  options.mesh_harmonics = 6;
  TrainTorusBalance hb(model, options);
  for (double factor : {1.0, 2.0}) {
    HarmonicBalancePoint point;
    point.omega = hb.baseFrequency(factor * model.inputSpeed());
    point.q = hb.startingGuess(point.omega);
    hb.solve(point);
    ASSERT_TRUE(point.converged) << factor << ": " << point.residual;
    const TorusNewmarkCheck check = torusNewmarkCheck(model, hb, point, 0.3);
    ASSERT_EQ(check.status, "completed") << factor;
    for (std::size_t c = 0; c < check.p2p_torus.size(); ++c) {
      const double error = std::abs(check.p2p_newmark[c] / check.p2p_torus[c] - 1.0);
      std::printf("torus %.1f x speed, coordinate %zu: p2p %.4g um, Newmark %.2e off\n", factor, c,
                  1e6 * check.p2p_torus[c], error);
      EXPECT_LT(error, 0.01) << factor << " coordinate " << c;
    }
  }
}

/// The hunting-tooth reducer with full DOFs: the flexible two-stage reducer of
/// examples/gearboxes (helical, 12°; its shafts here rigid bodies with six DOFs, 24 DOFs in all)
/// with the hunting-tooth ratios 19/71 and 21/59 (mesh frequencies 71/21 apart: two
/// generators), smooth k(φ) and the transmission errors of the planar test above; the input
/// shaft's locating bearing input_a on the full law of rollingPairFullDofs's back-to-back pair
/// of 25° angular-contact rows (9 × 12.7 mm on 60 mm, rows 20 mm apart, 5 µm play) over its
/// five coordinates (`full_law` false: linearised at the static deflection). 20 N m, a light
/// load (~0.5 kN on the pair): the orbit is a large part of the static deflection, so the full
/// law differs from the linearised bearing by more than the comparison's 1 % (at 100 N m by
/// 0.4 %). The helix's thrust loads one row more than the other.
GearTrainSpec huntingReducerFullDofs(bool full_law = true) {
  GearTrainSpec spec = testing::exampleGearbox("two_stage_reducer_flexible.toml");
  EXPECT_EQ(spec.dofs, TrainDofs::kFull);
  for (TrainShaftSpec& shaft : spec.shafts) shaft.flexible = false;
  const int teeth[] = {19, 71, 21, 59};
  for (int i = 0; i < 4; ++i) {
    spec.gears[i].gear.teeth = teeth[i];
    spec.gears[i].gear.profile_shift = 0.0;
  }
  spec.meshes[0].stiffness = testing::nonlinear::smooth(4e8, 0.0);
  spec.meshes[1].stiffness = testing::nonlinear::smooth(6e8, 40.0);
  spec.meshes[0].transmission_error = {};
  spec.meshes[0].transmission_error.addFourier({8e-6, 2e-6}, {0.0, 0.5});
  spec.meshes[1].transmission_error = {};
  spec.meshes[1].transmission_error.addFourier({6e-6}, {0.3});
  spec.operating.input_torque = 20.0;
  const GearTrainSpec pair = rollingPairFullDofs(5e-6, 1.0, true);
  for (TrainBearingSpec& b : spec.bearings) {
    if (b.name != "input_a") continue;
    b.kyy = b.kzz = b.kyz = b.kzy = b.k_axial = b.k_tilt = 0.0;
    b.rolling = pair.bearings[0].rolling;
    b.c_tilt = 30.0;
    b.full_law = full_law;
  }
  return spec;
}

/// The torus solution at ω over `times` [s] through the columns `Wb` of W: Wbᵀ q(t) (rows:
/// times) [m, rad].
Eigen::MatrixXd torusThrough(TrainTorusBalance& hb, const HarmonicBalancePoint& point,
                             const Eigen::MatrixXd& Wb, const Eigen::VectorXd& times) {
  const Eigen::MatrixXcd X =
      Wb.transpose().cast<std::complex<double>>() * hb.displacementHarmonics(point);
  Eigen::MatrixXd w(times.size(), Wb.cols());
  for (Eigen::Index i = 0; i < times.size(); ++i) {
    Eigen::VectorXd sum = X.col(0).real();
    for (Eigen::Index p = 1; p < X.cols(); ++p) {
      const double phase = hb.toneFrequency(static_cast<int>(p), point.omega) * times(i);
      sum += 2.0 * (X.col(p) * std::polar(1.0, phase)).real();
    }
    w.row(i) = sum.transpose();
  }
  return w;
}

/// ∂R/∂u and ∂R/∂ω of the torus balance with the full-DOF bearing against central differences
/// (step 1e-7 of the state's largest entry), about the starting guess and with every
/// coordinate's harmonics scattered by 30 % of that entry (the bearing swinging through its
/// load zone on part of the grid): within 1e-5 of the Jacobian's largest entry (as
/// train_torus_balance_test's check with backlash; a misplaced slope column of the 5 × 5 block
/// is O(1) of B K).
TEST(RollingBearingTorus, FullDofsJacobianAgainstFiniteDifferences) {
  const GearTrainModel model = linearisedAtStatics(huntingReducerFullDofs());
  ASSERT_EQ(model.clearanceBearings().size(), 1u);
  TrainTorusBalanceOptions options;
  options.mesh_harmonics = 2;
  TrainTorusBalance hb(model, options);
  ASSERT_EQ(hb.generators().ratio.size(), 2u);
  ASSERT_EQ(hb.coordinateCount(), 2 + 5);
  const double omega = hb.baseFrequency(model.inputSpeed());
  const Eigen::VectorXd guess = hb.startingGuess(omega);
  for (double spread : {0.0, 0.3}) {
    Eigen::VectorXd u = guess;
    const Eigen::VectorXd scatter = Eigen::VectorXd::LinSpaced(u.size(), -1.0, 1.0).array().sin();
    u += spread * u.cwiseAbs().maxCoeff() * scatter;
    Eigen::VectorXd r, dr_domega, rp, rm;
    Eigen::MatrixXd J;
    hb.residual(u, omega, r, &J, &dr_domega);
    const double h = 1e-7 * u.cwiseAbs().maxCoeff();
    double worst = 0.0;
    for (Eigen::Index i = 0; i < u.size(); ++i) {
      Eigen::VectorXd a = u, b = u;
      a(i) += h, b(i) -= h;
      hb.residual(a, omega, rp, nullptr, nullptr);
      hb.residual(b, omega, rm, nullptr, nullptr);
      worst = std::max(worst, ((rp - rm) / (2.0 * h) - J.col(i)).cwiseAbs().maxCoeff());
    }
    worst /= J.cwiseAbs().maxCoeff();
    const double dw = 1e-6 * omega;
    hb.residual(u, omega + dw, rp, nullptr, nullptr);
    hb.residual(u, omega - dw, rm, nullptr, nullptr);
    const Eigen::VectorXd fd_omega = (rp - rm) / (2.0 * dw);
    const double worst_omega = (dr_domega - fd_omega).norm() / fd_omega.norm();
    std::printf("torus full DOFs, spread %.1f: Jacobian %.2e, d/domega %.2e off\n", spread, worst,
                worst_omega);
    EXPECT_LT(worst, 1e-5) << spread;
    EXPECT_LT(worst_omega, 1e-5) << spread;
  }
}

/// The torus balance on huntingReducerFullDofs (6 mesh harmonics per generator) against
/// Newmark started on it and run for 0.3 s (torusNewmarkCheck: 256 steps per stage-1 mesh
/// period) at 1× and 2× the operating speed: the p2p of every nonlinear coordinate (the two
/// mesh deflections and the bearing's u_y, u_z, u_x, θ_y, θ_z) over the last half of the run
/// within 1 % of the torus solution's (the balance's truncation and Newmark's second-order
/// error, as for the planar case above); the bearing's axial and tilt motions are not
/// negligible (the helical meshes drive them: u_x's p2p and θ_y's times d_m/2 above 10 % of the
/// radial p2p), and the linearised bearing's differ by more than 2 % (the check separates them).
TEST(RollingBearingTorus, HuntingReducerFullDofsAgainstNewmark) {
  const GearTrainModel model = linearisedAtStatics(huntingReducerFullDofs());
  TrainTorusBalanceOptions options;
  options.mesh_harmonics = 6;
  TrainTorusBalance hb(model, options);
  const GearTrainModel linear_model = linearisedAtStatics(huntingReducerFullDofs(false));
  ASSERT_TRUE(linear_model.clearanceBearings().empty());
  TrainTorusBalance linear(linear_model, options);
  const Eigen::MatrixXd Wb = model.nonlinearVectors().rightCols(5);
  const double dm = 60e-3;  // the pair's pitch diameter
  for (double factor : {1.0, 2.0}) {
    HarmonicBalancePoint point;
    point.omega = hb.baseFrequency(factor * model.inputSpeed());
    point.q = hb.startingGuess(point.omega);
    hb.solve(point);
    ASSERT_TRUE(point.converged) << factor << ": " << point.residual;
    const TorusNewmarkCheck check = torusNewmarkCheck(model, hb, point, 0.3);
    ASSERT_EQ(check.status, "completed") << factor;
    ASSERT_EQ(check.p2p_torus.size(), 7u);
    for (std::size_t c = 0; c < check.p2p_torus.size(); ++c) {
      const double error = std::abs(check.p2p_newmark[c] / check.p2p_torus[c] - 1.0);
      std::printf(
          "torus full DOFs %.1f x speed, coordinate %zu: p2p %.4g (um or urad), Newmark "
          "%.2e off\n",
          factor, c, 1e6 * check.p2p_torus[c], error);
      EXPECT_LT(error, 0.01) << factor << " coordinate " << c;
    }
    const double radial = std::max(check.p2p_torus[2], check.p2p_torus[3]);
    EXPECT_GT(check.p2p_torus[4], 0.1 * radial) << "u_x";
    EXPECT_GT(0.5 * dm * check.p2p_torus[5], 0.1 * radial) << "theta_y moves a ball by";
    // The bearing linearised at the static deflection (its tangent in K, no law): its five
    // coordinates' p2p over the same 0.3 s differ from the full law's by more than the 1 %
    // above in some coordinate, so the check separates the two.
    HarmonicBalancePoint lin_point;
    lin_point.omega = point.omega;
    lin_point.q = linear.startingGuess(lin_point.omega);
    linear.solve(lin_point);
    ASSERT_TRUE(lin_point.converged) << factor;
    const Eigen::VectorXd times = Eigen::VectorXd::LinSpaced(20001, 0.0, 0.3);
    const Eigen::MatrixXd full_law = torusThrough(hb, point, Wb, times);
    const Eigen::MatrixXd linearised = torusThrough(linear, lin_point, Wb, times);
    double largest = 0.0;
    for (int c = 0; c < 5; ++c) {
      const auto p2p = [&](const Eigen::MatrixXd& w) {
        return w.col(c).maxCoeff() - w.col(c).minCoeff();
      };
      const double difference = std::abs(p2p(linearised) / p2p(full_law) - 1.0);
      std::printf("  bearing coordinate %d: linearised p2p %.2e off the full law's\n", c,
                  difference);
      largest = std::max(largest, difference);
    }
    EXPECT_GT(largest, 0.02) << factor;
  }
}

}  // namespace
}  // namespace geardyn
