// Harmonic balance: the linear limit against the analytic FRF, the AFT Jacobian against finite
// differences, agreement with Newmark on the Saletti (2025) contact problem, Hill's stability
// against Floquet multipliers from the monodromy matrix, continuation through folds.
#include "geardyn/solvers/harmonic_balance.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/solvers/time_response.h"
#include "geardyn/stiffness/api_stiffness.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "geardyn/stiffness/step_stiffness.h"
#include "support/numeric_assertions.h"
#include "support/reference_pairs.h"

namespace geardyn {
namespace {

constexpr double kPi = std::numbers::pi;

GearPairModelSpec saletti(double torque) {
  return testing::salettiModelSpec(torque);
}
using testing::peakToPeak;

TEST(HarmonicBalance, LinearLimitIsTheAnalyticFrf) {
  GearPairModelSpec spec;
  spec.mass = 1.589;
  spec.damping = 2 * 0.05 * std::sqrt(4.55e8 * 1.589);
  spec.mean_force = 1418.4;
  spec.stiffness = std::make_shared<ConstantMeshStiffness>("constant", 4.55e8, 1.6);
  spec.transmission_error.addFourier({2e-6, 0.5e-6}, {0.7, -0.2});
  const GearPairModel model(spec);
  HarmonicBalanceOptions options;
  options.harmonics = 4;
  options.samples_per_period = 64;
  options.tolerance = 1e-13;
  HarmonicBalance hbm(model, options);
  const std::complex<double> i(0, 1);
  for (double ratio : {0.3, 0.9, 1.4}) {
    HarmonicBalancePoint point;
    point.omega = ratio * std::sqrt(4.55e8 / spec.mass);
    point.q = hbm.linearGuess(point.omega);
    hbm.solve(point);
    ASSERT_TRUE(point.converged);
    EXPECT_CLOSE(point.q[0], 1418.4 / 4.55e8, 1e-12);
    for (int h = 1; h <= 2; ++h) {
      const double w = h * point.omega, a = h == 1 ? 2e-6 : 0.5e-6, phase = h == 1 ? 0.7 : -0.2;
      const std::complex<double> x = (4.55e8 + i * w * spec.damping) * a * std::exp(i * phase) /
                                     (4.55e8 - spec.mass * w * w + i * w * spec.damping);
      // 1e-9 of the amplitude (the bound).
      EXPECT_NEAR(point.q[2 * h - 1], x.real(), 1e-9 * std::abs(x)) << ratio;
      EXPECT_NEAR(point.q[2 * h], -x.imag(), 1e-9 * std::abs(x)) << ratio;
    }
    EXPECT_NEAR(point.q[5], 0.0, 1e-20);
  }
}

TEST(HarmonicBalance, JacobianMatchesFiniteDifferences) {
  // Backlash with a time-varying stiffness and an error, at a state whose samples stay off the
  // kinks of g (so that central differences are exact up to round-off).
  GearPairModelSpec spec;
  spec.mass = 1.0;
  spec.damping = 0.1;
  spec.mean_force = 1.0;
  spec.contact = ContactLaw::kBacklash;
  spec.backlash = 0.3;
  spec.stiffness = std::make_shared<FourierMeshStiffness>(1.0, std::vector<double>{0.2},
                                                          std::vector<double>{0.5}, 1.6);
  spec.transmission_error.addFourier({0.2}, {0.1});
  const GearPairModel model(spec);
  HarmonicBalanceOptions options;
  options.harmonics = 5;
  options.samples_per_period = 64;
  HarmonicBalance hbm(model, options);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(hbm.size());
  q[0] = 1.4;
  q[1] = 0.5;  // x = 1.4 + 0.5 cos τ − 0.3 sin 2τ: y − b swings across 0 → contact is lost
  q[4] = -0.3;
  const double omega = 0.8;
  Eigen::VectorXd r, dw, rp, rm;
  Eigen::MatrixXd J;
  hbm.residual(q, omega, r, &J, &dw);
  const double step = 1e-7;
  for (int j = 0; j < hbm.size(); ++j) {
    Eigen::VectorXd qp = q, qm = q;
    qp[j] += step;
    qm[j] -= step;
    hbm.residual(qp, omega, rp, nullptr, nullptr);
    hbm.residual(qm, omega, rm, nullptr, nullptr);
    const Eigen::VectorXd fd = (rp - rm) / (2 * step);
    EXPECT_TRUE(testing::isClose(J.col(j), fd, 1e-6, 1e-8)) << "column " << j;
  }
  hbm.residual(q, omega + step, rp, nullptr, nullptr);
  hbm.residual(q, omega - step, rm, nullptr, nullptr);
  EXPECT_TRUE(testing::isClose(dw, (rp - rm) / (2 * step), 1e-6, 1e-8));
}

TEST(HarmonicBalance, AgreesWithNewmarkOnTheContactElementModel) {
  // Table 1 at T = 100 N m, H = 14, away from the folds: peak to peak within 1 %.
  HarmonicBalanceOptions options;
  options.harmonics = 14;
  options.samples_per_period = 256;
  for (double f : {800.0, 2500.0, 3250.0}) {
    GearPairModelSpec spec = saletti(100.0);
    spec.mesh_frequency = f;
    const GearPairModel model(spec);
    HarmonicBalance hbm(model, options);
    HarmonicBalancePoint point;
    point.omega = 2 * kPi * f;
    point.q = hbm.linearGuess(point.omega);
    hbm.solve(point);
    ASSERT_TRUE(point.converged) << f;
    const auto x = hbm.timeSignal(point.q);
    const double p2p_hbm = peakToPeak(x);
    TimeResponseOptions newmark;
    newmark.steps_per_period = 2048;
    newmark.output_points_per_period = 256;
    newmark.steady_tolerance = 1e-9;
    const TimeResponse r = solveTimeResponse(model, newmark);
    ASSERT_TRUE(r.converged()) << r.message;
    const double p2p_dti = peakToPeak(r.x);
    EXPECT_NEAR(p2p_hbm / p2p_dti, 1.0, 0.01) << f << " Hz";
  }
}

TEST(HarmonicBalance, HillStabilityAgreesWithFloquetMultipliers) {
  // A smooth problem (linear contact, k = k̄(1 + 0.3 cos)) inside and outside the principal
  // parametric resonance (Ω ≈ 2ω_n): the largest real part of the Floquet exponents from Hill's
  // method against ln|μ|/T from the monodromy matrix integrated along the HBM orbit (RK4).
  const GearPairModelSpec spec = testing::mathieuModelSpec();
  const GearPairModel model(spec);
  HarmonicBalanceOptions options;
  options.harmonics = 20;
  options.samples_per_period = 128;
  HarmonicBalance hbm(model, options);
  for (double omega : {1.5, 1.98, 2.6}) {
    HarmonicBalancePoint point;
    point.omega = omega;
    point.q = hbm.linearGuess(omega);
    hbm.solve(point);
    ASSERT_TRUE(point.converged);
    hbm.stability(point);
    // Monodromy of δ″ = −(c δ′ + k(t) δ)/m over T = 2π/ω.
    const double T = 2 * kPi / omega;
    const int steps = 20000;
    const double h = T / steps;
    Eigen::Matrix2d phi = Eigen::Matrix2d::Identity();
    const auto rhs = [&](double t, const Eigen::Matrix2d& s) {
      const double k = model.meshStiffness().stiffness(omega * t / (2 * kPi));
      Eigen::Matrix2d a;
      a << 0, 1, -k / spec.mass, -spec.damping / spec.mass;
      return Eigen::Matrix2d(a * s);
    };
    for (int i = 0; i < steps; ++i) {
      const double t = i * h;
      const Eigen::Matrix2d k1 = rhs(t, phi), k2 = rhs(t + h / 2, phi + h / 2 * k1);
      const Eigen::Matrix2d k3 = rhs(t + h / 2, phi + h / 2 * k2), k4 = rhs(t + h, phi + h * k3);
      phi += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    const Eigen::EigenSolver<Eigen::Matrix2d> eig(phi);
    double floquet = -1e300;
    for (int j = 0; j < 2; ++j)
      floquet = std::max(floquet, std::log(std::abs(eig.eigenvalues()[j])) / T);
    EXPECT_NEAR(point.max_floquet_real, floquet, 1e-6) << omega;
    EXPECT_EQ(point.stable, floquet < 0.0) << omega;
    // The sampled monodromy (k held over each of the N = 128 intervals): first order in 1/N.
    // Its verdict must agree where the exponent is farther from 0 than that error bound (at
    // 1.98, next to the parametric resonance, it is not: the sign there is round-off's).
    HarmonicBalancePoint sampled = point;
    hbm.stabilityMonodromy(sampled);
    EXPECT_NEAR(sampled.max_floquet_real, floquet, 2e-3) << omega;
    std::printf("omega %.2f: Floquet exponent %.3e (Hill %.3e, sampled %.3e)\n", omega, floquet,
                point.max_floquet_real, sampled.max_floquet_real);
    if (std::abs(floquet) > 2e-3) EXPECT_EQ(sampled.stable, point.stable) << omega;
  }
}

TEST(HarmonicBalance, RejectsTooFewSamples) {
  HarmonicBalanceOptions options;
  options.harmonics = 14;
  options.samples_per_period = 28;
  EXPECT_THROW(options.validate(), InputError);
  options.samples_per_period = 29;
  EXPECT_NO_THROW(options.validate());
}

TEST(HarmonicBalance, ContinuationTracesTheSofteningPeakThroughItsFolds) {
  // Saletti Table 1, T = 100 N m, swept down from 3500 Hz (above the linear resonance, where
  // the start is easy) to 1500 Hz through the primary resonance: the one-sided contact softens
  // the peak; the curve must turn twice (two folds) and reach the end.
  GearPairModelSpec spec = saletti(100.0);
  const GearPairModel model(spec);
  HarmonicBalanceOptions options;
  options.harmonics = 14;
  options.samples_per_period = 256;
  HarmonicBalance hbm(model, options);
  ContinuationOptions sweep;
  sweep.start = 2 * kPi * 3500;
  sweep.stop = 2 * kPi * 1500;
  sweep.initial_step = 2 * kPi * 5;
  sweep.min_step = 2 * kPi * 0.01;
  sweep.max_step = 2 * kPi * 40;
  const ContinuationResult result = continueInFrequency(hbm, sweep);
  EXPECT_TRUE(result.completed) << result.message;
  EXPECT_GE(result.folds.size(), 2u) << result.message;
  EXPECT_EQ(result.folds.size() % 2, 0u) << result.message;  // the curve comes back: folds pair up
  int unstable = 0, disagree = 0;
  for (const auto& p : result.points) {
    unstable += !p.solution.stable;
    HarmonicBalancePoint copy = p.solution;
    hbm.stabilityMonodromy(copy);
    disagree += copy.stable != p.solution.stable;
  }
  EXPECT_GT(unstable, 0);  // the middle branch between the folds
  // Hill and the sampled monodromy classify the same points (but right at a fold, where the
  // exponent crosses 0 and either may fall on its side).
  EXPECT_LE(disagree, 4) << "of " << result.points.size();
}

}  // namespace
}  // namespace geardyn

namespace geardyn {
namespace {

TEST(HarmonicBalance, ConvergesAsHarmonicsAndSamplesGrow) {
  // Saletti Table 1, T = 100 N m, at 3250 Hz (contact kept, k steps k_c ↔ 2k_c) and 1250 Hz
  // (superharmonic with separation). The peak to peak against H (N = 16H) settles: the change
  // from H to the next H shrinks (the step gap makes the spectrum decay like 1/h², so the
  // convergence is algebraic). Prints the table.
  for (double f : {3250.0, 1250.0}) {
    GearPairModelSpec spec = saletti(100.0);
    const GearPairModel model(spec);
    std::vector<double> p2p;
    std::printf("f = %.0f Hz:", f);
    for (int harmonics : {4, 8, 14, 20, 28, 40}) {
      HarmonicBalanceOptions options;
      options.harmonics = harmonics;
      options.samples_per_period = 16 * harmonics;
      HarmonicBalance hbm(model, options);
      HarmonicBalancePoint point;
      point.omega = 2 * kPi * f;
      point.q = hbm.linearGuess(point.omega);
      hbm.solve(point);
      ASSERT_TRUE(point.converged) << harmonics;
      const auto x = hbm.timeSignal(point.q);
      p2p.push_back(peakToPeak(x));
      std::printf("  H=%d: %.6e", harmonics, p2p.back());
    }
    std::printf("\n");
    const double first_change = std::abs(p2p[1] / p2p[0] - 1),
                 last_change = std::abs(p2p[5] / p2p[4] - 1);
    EXPECT_LT(last_change, first_change) << f;
    EXPECT_LT(last_change, 0.01) << f;  // H = 28 → 40 changes p2p by < 1 %
  }
}

}  // namespace
}  // namespace geardyn
