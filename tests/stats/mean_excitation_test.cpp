// Gelman, Giurgiutiu & Bayoumi (2005): the paper's examples from its statistics, the closed
// forms of eqs. 16–18, and the dynamic check that the mean of k·y in a simulated periodic steady
// state equals the dynamic mean excitation L_d.
#include "geardyn/stats/mean_excitation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/solvers/time_response.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "geardyn/stiffness/step_stiffness.h"
#include "geardyn/system/gear_pair_model.h"
#include "support/numeric_assertions.h"

namespace geardyn {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(MeanExcitation, PaperCasesFromTheirStatistics) {
  // §3, Case 1 (harmonic stiffness, ε = 1.5, d_kc = 0.3): a = 0.25: Δm₁(e_f) = 0.05a,
  // r_ke = 1, d_e = 0.55a → R = 1.215 (printed 1.2); a = 0.75: Δ = 0.04a, r = 0.5, d_e = 0.05a
  // → R = 1.0475 (1.05). Case 2 (rectangular, d_kr = 0.3): a = 1.5: Δ = −0.08a, r = −1,
  // d_e = 0.08a → R = 0.896 (0.9). m₁(ė) = 0 (eq. 14), m₁(k) = 1.
  struct Case {
    double a, delta, r, d_e, expected;
    const char* classification;
  };
  for (const Case& c : {Case{0.25, 0.05, 1.0, 0.55, 1.215, "greater than"},
                        Case{0.75, 0.04, 0.5, 0.05, 1.0475, "greater than"},
                        Case{1.5, -0.08, -1.0, 0.08, 0.896, "less than"}}) {
    const MeanExcitation s =
        meanExcitationFromMoments(1.0, (1 + c.delta) * c.a, 0.3, c.d_e * c.a, c.r, 0.0, c.a, 0.05);
    EXPECT_CLOSE(s.ratio, c.expected, 1e-12) << c.a;
    EXPECT_CLOSE(s.ratio_eq15, c.expected, 1e-12);
    EXPECT_CLOSE(s.variable_term, c.expected - 1.0, 1e-12);
    EXPECT_EQ(s.classification(), c.classification);
  }
  EXPECT_THROW(meanExcitationFromMoments(1, 1, 0.3, 0.1, 1.5, 0, 1, 0.05), InputError);  // |r| > 1
  EXPECT_THROW(meanExcitationFromMoments(1, 1, 0.3, 0.1, 0.5, 0, 0, 0.05), InputError);  // a = 0
}

TEST(MeanExcitation, ErrorlessGearsGiveUnity) {
  // e = 0: e_f = a/k and L_d = m₁(k · a/k) = a exactly, whatever k (the paper: R = 1 for
  // errorless, unmodified gears).
  const auto k = StepMeshStiffness::fromMean(1.0, 1.5);
  const MeanExcitation s = meanExcitationFromCurves(k, TransmissionError{}, 0.7, 0.05, 0.4);
  EXPECT_CLOSE(s.ratio, 1.0, 1e-12);
  EXPECT_CLOSE(s.m1_k, 1.0, 1e-12);
  EXPECT_CLOSE(s.d_k, std::sqrt(0.25 / 2.25), 1e-12);  // eq. 18 (corrected): d_kr = 1/3
  EXPECT_LT(s.r_ke, 0.0);                              // deflection a/k is out of phase with k
  EXPECT_EQ(s.m1_edot, 0.0);
}

TEST(MeanExcitation, CorrelatedErrorRaisesTheRatio) {
  // A gear error in phase with the stiffness: r_ke > 0 contributes r d_k d_e / a > 0.
  const FourierMeshStiffness k(1.0, {0.3}, {0.0}, 1.5);
  TransmissionError e;
  e.addFourier({0.2}, {0.0});  // e = 0.2 cos(2πφ), k = 1 + 0.3 cos(2πφ)
  const MeanExcitation s = meanExcitationFromCurves(k, e, 1.0, 0.05, 0.5);
  // L_d = m₁(k e_f) = m₁(k e) + a = 0.3 · 0.2 / 2 + 1 = 1.03.
  EXPECT_CLOSE(s.dynamic_mean_excitation, 1.03, 1e-12);
  EXPECT_EQ(s.classification(), "greater than");
}

TEST(MeanExcitation, DynamicMeanOfKTimesYEqualsTheStatisticalLd) {
  // Eq. 3: ÿ + 2ζẏ + k y = k e_f + 2ζė. Over a period of the steady state ÿ and ẏ average to
  // zero, so m₁(k y) = L_d. Nondimensional model: m = 1, c = 2ζ, F = a, stiffness k, error e.
  const double a = 0.8, zeta = 0.05, omega = 0.7;
  GearPairModelSpec spec;
  spec.mass = 1.0;
  spec.damping = 2 * zeta;
  spec.mean_force = a;
  spec.stiffness = std::make_shared<FourierMeshStiffness>(1.0, std::vector<double>{0.25, 0.08},
                                                          std::vector<double>{0.0, 0.4}, 1.5);
  spec.transmission_error.addFourier({0.3, 0.1}, {0.5, -1.0});
  spec.mesh_frequency = omega / (2 * kPi);
  const GearPairModel model(spec);
  TimeResponseOptions options;
  options.steps_per_period = 4096;
  options.output_points_per_period = 4096;
  options.output_periods = 1;
  options.steady_tolerance = 1e-10;
  const TimeResponse r = solveTimeResponse(model, options);
  ASSERT_TRUE(r.converged()) << r.message;
  double mean_ky = 0.0;
  for (std::size_t j = 0; j < r.t.size(); ++j) mean_ky += model.stiffness(r.t[j]) * r.x[j];
  mean_ky /= r.t.size();
  const MeanExcitation s =
      meanExcitationFromCurves(*spec.stiffness, spec.transmission_error, a, zeta, omega);
  // 1e-3 relative, the bound (rectangle rule on a smooth periodic signal: far better).
  EXPECT_CLOSE(mean_ky, s.dynamic_mean_excitation, 1e-3);
  EXPECT_CLOSE(mean_ky, s.dynamic_mean_excitation, 1e-8);
}

TEST(MeanExcitation, DimensionalModelNormalisesLikeGelman) {
  // The same pair in SI (m = 1.589 kg, K̄ = 4.55e8 N/m, F = 1418.4 N, baseload F₀ = 2000 N) and
  // in Gelman's units (a = F/F₀, e/x₀, Ω = ω_m/ω_n) gives the same statistics; and the SI
  // steady state satisfies m₁(K x)/F₀ = L_d.
  const double mass = 1.589, k_mean = 4.55e8, force = 1418.4, baseload = 2000.0, zeta = 0.05;
  const double omega_n = std::sqrt(k_mean / mass), f_m = 0.4 * omega_n / (2 * kPi);
  GearPairModelSpec spec;
  spec.mass = mass;
  spec.damping = 2 * zeta * std::sqrt(k_mean * mass);
  spec.mean_force = force;
  spec.stiffness = std::make_shared<FourierMeshStiffness>(k_mean, std::vector<double>{0.2},
                                                          std::vector<double>{0.3}, 1.6);
  spec.transmission_error.addFourier({2e-6}, {1.0});
  spec.mesh_frequency = f_m;
  const GearPairModel model(spec);
  const MeanExcitation si = meanExcitationFromModel(model, baseload);
  const double x0 = baseload / k_mean;
  TransmissionError e;
  e.addFourier({2e-6 / x0}, {1.0});
  const MeanExcitation nd = meanExcitationFromCurves(FourierMeshStiffness(1.0, {0.2}, {0.3}, 1.6),
                                                     e, force / baseload, zeta, 0.4);
  EXPECT_CLOSE(si.ratio, nd.ratio, 1e-12);
  EXPECT_CLOSE(si.r_ke, nd.r_ke, 1e-12);
  EXPECT_CLOSE(si.a, force / baseload, 1e-15);
  TimeResponseOptions options;
  options.steps_per_period = 2048;
  options.output_points_per_period = 2048;
  options.output_periods = 1;
  options.steady_tolerance = 1e-10;
  const TimeResponse r = solveTimeResponse(model, options);
  ASSERT_TRUE(r.converged());
  double mean_kx = 0.0;
  for (std::size_t j = 0; j < r.t.size(); ++j) mean_kx += model.stiffness(r.t[j]) * r.x[j];
  EXPECT_CLOSE(mean_kx / r.t.size() / baseload, si.dynamic_mean_excitation, 1e-6);
}

}  // namespace
}  // namespace geardyn
