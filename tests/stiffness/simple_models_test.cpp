// API, step and Fourier mesh stiffness: closed forms, Gelman (2005) statistics, invariants.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/models/transmission_error.h"
#include "geardyn/stiffness/api_stiffness.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "geardyn/stiffness/iso6336_stiffness.h"
#include "geardyn/stiffness/mesh_stiffness_summary.h"
#include "geardyn/stiffness/scaled_stiffness.h"
#include "geardyn/stiffness/step_stiffness.h"
#include "support/numeric_assertions.h"

namespace geardyn {
namespace {

constexpr double kPi = std::numbers::pi;
/// Piecewise Gauss–Legendre integration of piecewise-constant or trigonometric curves is exact
/// to round-off; 1e-12 relative leaves room for a few hundred additions.
constexpr double kQuadrature = 1e-12;

// ISO 6336-1 method B on a ring mesh: the ring's tooth as a rack's (z_n2 -> inf). By hand for a
// spur planet z 30 in a ring z 90, x = 0, α_n = 20°, h_fP* = 1.25, steel: q' = C1 + C2/30,
// c' = C_M C_B / q' with C_M = 0.8, C_B = 1 + 0.5 (1.2 − 1.25), c_γα = c' (0.75 ε_α + 0.25);
// and the external formula's limit of a huge z2 (C3/z_n2 → 0). Round-off only: 1e-12.
TEST(Iso6336Stiffness, RingMeshTakesTheRingToothAsARackTooth) {
  GearSpec planet, ring;
  planet.teeth = 30;
  ring.teeth = 90;
  for (GearSpec* g : {&planet, &ring}) {
    g->normal_module = 2e-3;
    g->normal_pressure_angle = 20.0 * kPi / 180.0;
    g->face_width = 0.02;
  }
  const InternalGearPair pair(planet, ring, std::nullopt, "stage");
  const Iso6336Stiffness s = iso6336Stiffness(pair, planet, ring);
  const double c_prime = 0.8 * 0.975 / (0.04723 + 0.15551 / 30.0);
  EXPECT_NEAR(s.c_prime, c_prime, 1e-12 * c_prime);
  const double c_gamma = c_prime * (0.75 * pair.contactRatioTransverse() + 0.25);
  EXPECT_NEAR(s.meshStiffness(), c_gamma * 20.0 * 1e6, 1e-12 * c_gamma * 20.0 * 1e6);
  const Iso6336Stiffness rack =
      iso6336Stiffness(30, 1e15, 0.0, 0.0, 0.0, 0.0, 20.0 * kPi / 180.0, 1.25, 2e-3, 0.02,
                       pair.contactRatioTransverse(), 206e9, 206e9);
  EXPECT_NEAR(s.meshStiffness(), rack.meshStiffness(), 1e-12 * rack.meshStiffness());
}

TEST(ApiStiffness, ConstantAndDirectionalMatrix) {
  // Visnadi eqs. 1–6 by hand: K′ = 12.057 · 20 · 1e6; γ = 20° + 90° = 110°.
  EXPECT_CLOSE(apiMeshStiffness(0.020, 0.0), 2.41140e8, 1e-12);
  EXPECT_CLOSE(apiMeshStiffness(0.020, 15 * kPi / 180), 2.249867e8, 1e-6);
  const double gamma = apiMeshDirection(20 * kPi / 180, ApiLoading::kDown, ApiRotation::kClockwise);
  EXPECT_CLOSE(gamma, 110 * kPi / 180, 1e-15);
  const Eigen::Matrix2d k = apiDirectionalStiffness(2.41140e8, gamma);
  EXPECT_CLOSE(k(0, 0), 2.820802e7, 1e-6);
  EXPECT_CLOSE(k(0, 1), -7.750090e7, 1e-6);
  EXPECT_CLOSE(k(1, 0), -7.750090e7, 1e-6);
  EXPECT_CLOSE(k(1, 1), 2.129320e8, 1e-6);
  // Trace = K′; rank one (determinant 0).
  EXPECT_CLOSE(k.trace(), 2.41140e8, 1e-14);
  EXPECT_NEAR(k.determinant() / (2.41140e8 * 2.41140e8), 0.0, 1e-14);
  EXPECT_CLOSE(apiMeshDirection(20 * kPi / 180, ApiLoading::kUp, ApiRotation::kCounterClockwise),
               250 * kPi / 180, 1e-15);
  EXPECT_THROW(apiMeshStiffness(-1.0, 0.0), InputError);
}

TEST(StepStiffness, MeanHarmonicAndJumpsAtTheContactRatioPoints) {
  const double k_min = 2e8, k_max = 3.5e8, eps = 1.63;
  const StepMeshStiffness k(k_min, k_max, eps);
  const auto s = summarizeMeshStiffness(k, 3);
  EXPECT_CLOSE(s.mean, k_min + (eps - 1) * (k_max - k_min), kQuadrature);
  EXPECT_CLOSE(s.amplitude[0], 2 / kPi * (k_max - k_min) * std::sin(kPi * (eps - 1)), kQuadrature);
  // A rectangular wave of duty p: std = (k_max − k_min) √(p (1 − p)).
  EXPECT_CLOSE(s.std, (k_max - k_min) * std::sqrt(0.63 * 0.37), kQuadrature);
  EXPECT_EQ(s.min, k_min);
  EXPECT_EQ(s.max, k_max);
  // k_max from the entry of a pair for (ε − 1) of the period, exactly.
  const double p = k.multiContactFraction();
  EXPECT_EQ(p, eps - 1.0);  // 1.63 − 1 in double precision
  EXPECT_EQ(k.stiffness(0.0), k_max);
  EXPECT_EQ(k.stiffness(std::nextafter(p, 0.0)), k_max);
  EXPECT_EQ(k.stiffness(p), k_min);
  EXPECT_EQ(k.stiffness(0.999999), k_min);
  EXPECT_EQ(k.stiffness(1.3), k.stiffness(0.3));  // periodic
  EXPECT_EQ(k.stiffness(-0.7), k.stiffness(0.3));
  ASSERT_EQ(k.discontinuities().size(), 2u);
  EXPECT_EQ(k.discontinuities()[1], eps - 1.0);
}

TEST(StepStiffness, GelmanVariancesOfTheNormalisedStiffness) {
  // Gelman et al. 2005, normalised k = K / K̄ with stiffness proportional to the pairs in
  // contact. Eq. 17 (its first harmonic): d² = 2 sin²((ε−n)π) / (πε)². Eq. 18 (rectangular):
  // the OCR prints (ε−n)(n+1−ε)/ε; the variance of N(t)/ε is (ε−n)(n+1−ε)/ε², which also gives
  // the paper's own d_kr = 0.3 for ε = 1.5 (the printed form gives 0.41).
  for (double eps : {1.2, 1.5, 1.75, 2.3, 3.6}) {
    const double n = std::floor(eps);
    const auto k = StepMeshStiffness::fromMean(1.0, eps);
    const auto s = summarizeMeshStiffness(k, 1);
    EXPECT_CLOSE(s.mean, 1.0, kQuadrature);
    EXPECT_CLOSE(s.std * s.std, (eps - n) * (n + 1 - eps) / (eps * eps), kQuadrature) << eps;
    EXPECT_CLOSE(0.5 * s.amplitude[0] * s.amplitude[0],
                 2 * std::pow(std::sin((eps - n) * kPi), 2) / std::pow(kPi * eps, 2), kQuadrature)
        << eps;
    EXPECT_CLOSE(k.kMax() / k.kMin(), (n + 1) / n, 1e-15);
  }
  // The paper's numbers for ε = 1.5: d_kr ≈ 0.3 (0.333), d_kc ≈ 0.3 (0.300).
  const auto s = summarizeMeshStiffness(StepMeshStiffness::fromMean(1.0, 1.5), 1);
  EXPECT_NEAR(s.std, 0.3333, 1e-4);
  EXPECT_NEAR(s.amplitude[0] / std::sqrt(2.0), 0.3001, 1e-4);
}

TEST(StepStiffness, FromModelPreservesTheMean) {
  const FourierMeshStiffness source(3e8, {0.2, 0.05}, {0.4, -1.0}, 1.6);
  const auto step = StepMeshStiffness::fromModel(source);
  EXPECT_CLOSE(summarizeMeshStiffness(step, 0).mean, 3e8, kQuadrature);
  EXPECT_GT(step.kMax(), step.kMin());
}

TEST(StepStiffness, RejectsNonPhysicalInput) {
  EXPECT_THROW(StepMeshStiffness(2e8, 3e8, 0.9), InputError);   // contact ratio < 1
  EXPECT_THROW(StepMeshStiffness(-2e8, 3e8, 1.5), InputError);  // negative stiffness
  EXPECT_THROW(StepMeshStiffness(3e8, 2e8, 1.5), InputError);   // k_max < k_min
  EXPECT_THROW(StepMeshStiffness(2e8, NAN, 1.5), InputError);
}

TEST(FourierStiffness, EvaluatesEquation8AndFitsItself) {
  const double k0 = 3e8;
  const FourierMeshStiffness k(k0, {0.25, 0.1}, {0.3, 2.0}, 1.6);
  for (double phase : {0.0, 0.17, 0.5, 0.93}) {
    const double expected =
        k0 * (1 + 0.25 * std::cos(2 * kPi * phase - 0.3) + 0.1 * std::cos(4 * kPi * phase - 2.0));
    EXPECT_CLOSE(k.stiffness(phase), expected, 1e-15);
  }
  const auto fitted = FourierMeshStiffness::fit(k, 2);
  EXPECT_CLOSE(fitted.mean(), k0, kQuadrature);
  EXPECT_CLOSE(fitted.relativeAmplitudes()[0], 0.25, 1e-12);
  EXPECT_CLOSE(fitted.relativeAmplitudes()[1], 0.1, 1e-12);
  EXPECT_CLOSE(fitted.phases()[0], 0.3, 1e-12);
  EXPECT_CLOSE(fitted.phases()[1], 2.0, 1e-12);
  // A new mean keeps the relative amplitudes (Visnadi's sinusoid around the API mean).
  const auto around_api = FourierMeshStiffness::fit(k, 1, 2.4114e8);
  EXPECT_CLOSE(around_api.mean(), 2.4114e8, 1e-15);
  EXPECT_CLOSE(around_api.relativeAmplitudes()[0], 0.25, 1e-12);
}

TEST(FourierStiffness, RejectsAmplitudesThatMakeStiffnessNegative) {
  EXPECT_THROW(FourierMeshStiffness(3e8, {0.7, 0.4}, {0.0, 0.0}, 1.5), InputError);
  EXPECT_THROW(FourierMeshStiffness(3e8, {0.2}, {}, 1.5), InputError);
  EXPECT_THROW(FourierMeshStiffness(-3e8, {0.2}, {0.0}, 1.5), InputError);
}

TEST(ScaledStiffness, IsTheModelTimesTheFactorWithItsJumpsAndName) {
  // k_n = k_t / cos² β_b of a helical mesh and back: the product of two factors, exact but for
  // the round-off of their product (a few ulps).
  const auto step = std::make_shared<StepMeshStiffness>(4e8, 6e8, 1.6);
  const double cb2 = std::pow(std::cos(0.25), 2);
  const auto normal = scaledMeshStiffness(step, 1.0 / cb2);
  const auto back = scaledMeshStiffness(normal, cb2);
  EXPECT_EQ(scaledMeshStiffness(step, 1.0), step);  // a factor of exactly 1 is the model
  EXPECT_EQ(normal->model(), "step");
  EXPECT_EQ(normal->discontinuities(), step->discontinuities());
  EXPECT_EQ(normal->contactRatio(), step->contactRatio());
  for (const double phi : {0.0, 0.3, 0.7, 1.45}) {
    EXPECT_CLOSE(normal->stiffness(phi), step->stiffness(phi) / cb2, 1e-15);
    EXPECT_CLOSE(back->stiffness(phi), step->stiffness(phi), 1e-15);
  }
  // One wrapper: the factors are multiplied, not nested.
  ASSERT_NE(dynamic_cast<const ScaledMeshStiffness*>(back.get()), nullptr);
  EXPECT_EQ(&dynamic_cast<const ScaledMeshStiffness&>(*back).unscaled(), step.get());
  EXPECT_THROW(ScaledMeshStiffness(step, 0.0), InputError);
  EXPECT_THROW(ScaledMeshStiffness(nullptr, 1.0), InputError);
}

TEST(TransmissionError, ScaledScalesEveryPart) {
  TransmissionError e;
  e.addFourier({2e-6, -1e-6}, {0.3, 1.1});
  e.addRectangular(1e-6, 0.4, 0.2);
  e.addTable({0.0, 0.5}, {1e-6, -3e-6});
  const TransmissionError half = e.scaled(0.5);
  for (const double phi : {0.05, 0.25, 0.55, 0.9}) {
    EXPECT_CLOSE(half.value(phi), 0.5 * e.value(phi), 1e-15, 1e-22);
    EXPECT_CLOSE(half.derivative(phi), 0.5 * e.derivative(phi), 1e-15, 1e-22);
  }
}

TEST(MeshStiffnessSummary, ConstantHasNoFluctuation) {
  const ConstantMeshStiffness k("api", 2.4114e8, 1.6);
  const auto s = summarizeMeshStiffness(k, 4);
  EXPECT_CLOSE(s.mean, 2.4114e8, kQuadrature);
  EXPECT_EQ(s.std, 0.0);
  for (double a : s.amplitude) EXPECT_LT(a, 1e-6 * 2.4114e8);
}

TEST(MeshPhase, RollAngleConversions) {
  EXPECT_CLOSE(meshPhaseFromRollAngle(2 * kPi / 25, 25), 1.0, 1e-15);
  EXPECT_CLOSE(rollAngleFromMeshPhase(0.5, 16), kPi / 16, 1e-15);
  EXPECT_EQ(wrapPhase(-0.25), 0.75);
  EXPECT_EQ(wrapPhase(3.0), 0.0);
  EXPECT_LT(wrapPhase(-1e-18), 1.0);
}

}  // namespace
}  // namespace geardyn
