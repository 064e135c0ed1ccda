// Time integration of the gear-pair model: order of accuracy, the analytic steady state of the
// linear time-invariant case, Newmark against Dormand–Prince on a time-varying case, the
// parametric-instability region and contact loss.
#include "geardyn/solvers/time_response.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "geardyn/stiffness/api_stiffness.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "geardyn/stiffness/step_stiffness.h"
#include "geardyn/system/gear_pair_model.h"
#include "support/numeric_assertions.h"
#include "support/reference_pairs.h"

namespace geardyn {
namespace {

constexpr double kPi = std::numbers::pi;

/// m = 1.589 kg, k = 4.55e8 N/m (ω_n = 16,922 rad/s), ζ = 0.05, F = 1418.4 N.
GearPairModelSpec lti(double mesh_frequency = 0.0) {
  GearPairModelSpec spec;
  spec.mass = 1.589;
  spec.stiffness = std::make_shared<ConstantMeshStiffness>("constant", 4.55e8, 1.6);
  spec.damping = 2 * 0.05 * std::sqrt(4.55e8 * 1.589);
  spec.mean_force = 1418.4;
  spec.mesh_frequency = mesh_frequency;
  return spec;
}

double exactFreeResponse(const GearPairModelSpec& spec, double x0, double t) {
  const double k = spec.stiffness->stiffness(0.0);
  const double wn = std::sqrt(k / spec.mass), zeta = spec.damping / (2 * std::sqrt(k * spec.mass));
  const double wd = wn * std::sqrt(1 - zeta * zeta), xe = spec.mean_force / k;
  return xe + (x0 - xe) * std::exp(-zeta * wn * t) *
                  (std::cos(wd * t) + zeta * wn / wd * std::sin(wd * t));
}

TEST(Newmark, SecondOrderForAverageAndLinearAcceleration) {
  const GearPairModelSpec spec = lti();
  const GearPairModel model(spec);
  const double t_end = 2e-3;  // ≈ 5.4 natural periods
  const double exact = exactFreeResponse(spec, 0.0, t_end);
  for (const auto& p :
       {NewmarkParameters::averageAcceleration(), NewmarkParameters::linearAcceleration()}) {
    double previous = 0.0;
    for (int n : {400, 800, 1600, 3200}) {
      const double error =
          std::abs(integrateNewmark(model, p, 0.0, t_end / n, n, 0.0, 0.0, 1e-14).x - exact);
      if (previous > 0.0) {
        // Observed order log2(e_h / e_{h/2}) → 2 (within 0.1).
        EXPECT_NEAR(std::log2(previous / error), 2.0, 0.1) << "beta " << p.beta << ", n " << n;
      }
      previous = error;
    }
  }
}

TEST(DormandPrince, ErrorFollowsTheTolerance) {
  const GearPairModelSpec spec = lti();
  const GearPairModel model(spec);
  const double exact = exactFreeResponse(spec, 0.0, 2e-3);
  const double scale = spec.mean_force / 4.55e8;
  for (double rtol : {1e-6, 1e-9, 1e-12}) {
    const double x = integrateDormandPrince(model, 0.0, 2e-3, 0.0, 0.0, rtol, rtol * scale).first;
    EXPECT_LT(std::abs(x - exact), 50 * rtol * scale) << rtol;
  }
}

TEST(TimeResponse, LinearTimeInvariantSteadyStateIsTheAnalyticOne) {
  // e = a cos(Ω t + φ) with Ω = 0.6 ω_n: x = F/k + Re{(k + iΩc) a e^{iφ} / (k − mΩ² + iΩc)
  // e^{iΩt}}.
  GearPairModelSpec spec = lti();
  const double k = 4.55e8, wn = std::sqrt(k / spec.mass), omega = 0.6 * wn;
  spec.mesh_frequency = omega / (2 * kPi);
  const double a = 2e-6, phi = 0.7;
  spec.transmission_error.addFourier({a}, {phi});
  const GearPairModel model(spec);
  const std::complex<double> i(0, 1);
  const std::complex<double> amplitude = (k + i * omega * spec.damping) * a * std::exp(i * phi) /
                                         (k - spec.mass * omega * omega + i * omega * spec.damping);
  const double x_static = spec.mean_force / k;
  for (const auto method : {TimeIntegrator::kNewmark, TimeIntegrator::kDormandPrince}) {
    TimeResponseOptions options;
    options.method = method;
    options.steps_per_period = 8192;
    options.steady_tolerance = 1e-9;
    options.relative_tolerance = 1e-11;
    options.max_periods = 400;
    const TimeResponse r = solveTimeResponse(model, options);
    ASSERT_TRUE(r.converged()) << r.message;
    double worst = 0.0;
    for (std::size_t j = 0; j < r.t.size(); ++j) {
      const double exact = x_static + std::real(amplitude * std::exp(i * omega * r.t[j]));
      worst = std::max(worst, std::abs(r.x[j] - exact));
    }
    // 1e-6 of the response amplitude (the bound): Newmark's phase error at 8192 steps
    // per period is (Ωh)²/12 ≈ 5e-8.
    EXPECT_LT(worst, 1e-6 * std::abs(amplitude)) << static_cast<int>(method);
  }
}

TEST(TimeResponse, NewmarkAgreesWithDormandPrinceOnATimeVaryingStiffness) {
  GearPairModelSpec spec = lti();
  spec.stiffness = std::make_shared<FourierMeshStiffness>(4.55e8, std::vector<double>{0.2, 0.1},
                                                          std::vector<double>{0.0, 1.0}, 1.6);
  spec.mesh_frequency =
      0.45 * std::sqrt(4.55e8 / spec.mass) / (2 * kPi);  // near the 2:1 resonance region edge
  spec.transmission_error.addFourier({1e-6}, {0.3});
  const GearPairModel model(spec);
  TimeResponseOptions newmark;
  newmark.steps_per_period = 4096;
  newmark.steady_tolerance = 1e-9;
  TimeResponseOptions dopri = newmark;
  dopri.method = TimeIntegrator::kDormandPrince;
  dopri.relative_tolerance = 1e-11;
  const TimeResponse a = solveTimeResponse(model, newmark);
  const TimeResponse b = solveTimeResponse(model, dopri);
  ASSERT_TRUE(a.converged() && b.converged()) << a.message << " / " << b.message;
  double range = 0.0, worst = 0.0;
  const std::size_t n = std::min(a.x.size(), b.x.size());
  for (std::size_t j = 0; j < n; ++j) {
    range = std::max(range, std::abs(a.x[j] - spec.mean_force / 4.55e8));
    worst = std::max(worst, std::abs(a.x[a.x.size() - n + j] - b.x[b.x.size() - n + j]));
  }
  EXPECT_LT(worst, 1e-5 * range);
}

TEST(TimeResponse, ParametricInstabilityNearTwiceTheNaturalFrequency) {
  // Nondimensional: x″ + 2ζx′ + (1 + ε cos φt) x = 1, ζ = 0.01, ε = 0.3. The first Mathieu
  // instability tongue around φ = 2 (Den Hartog) opens for ε/4 > ζ: unbounded growth there,
  // a bounded periodic response away from it.
  GearPairModelSpec spec = testing::mathieuModelSpec();
  TimeResponseOptions options;
  options.max_periods = 3000;
  for (double phi : {1.95, 2.0, 2.05}) {
    spec.mesh_frequency = phi / (2 * kPi);
    EXPECT_EQ(solveTimeResponse(GearPairModel(spec), options).status, TimeResponseStatus::kDiverged)
        << phi;
  }
  for (double phi : {1.2, 2.8}) {
    spec.mesh_frequency = phi / (2 * kPi);
    EXPECT_TRUE(solveTimeResponse(GearPairModel(spec), options).converged()) << phi;
  }
}

TEST(TransmissionError, TableSlopeOnATablePointIsTheMeanOfBothSidesWhateverTheRoundOff) {
  // Slopes 4, 0, 8, −12 [m per period] on the four segments (the last one wraps to φ = 1).
  TransmissionError e;
  e.addTable({0.0, 0.25, 0.5, 0.75}, {0.0, 1.0, 1.0, 3.0});
  EXPECT_EQ(e.derivative(0.1), 4.0);
  EXPECT_EQ(e.derivative(0.9), -12.0);
  // On a point: the mean, also a few ulps off it and after many periods (issue 21).
  for (double p : {0.25, 0.25 + 1e-15, 0.25 - 1e-15, 1000.25, 1000.25 - 2e-13})
    EXPECT_EQ(e.derivative(p), 2.0) << p;
  EXPECT_EQ(e.derivative(0.75), -2.0);
  EXPECT_EQ(e.derivative(0.0), -4.0);
  EXPECT_EQ(e.derivative(1e3 - 1e-13), -4.0);
}

TEST(TimeResponse, ABeatThatDipsBelowTheToleranceIsNotASteadyState) {
  // Nondimensional LTI (ω_n = 1, ζ = 0.1, x̄ = 1) at ω_m = 0.3 with two extra forces at
  // ω_m (1 ± 0.01) whose period-to-period changes have equal size d = 6.9e-5: together they
  // beat over 50 mesh periods, and near each node the change falls below the tolerance 2e-5 for
  // about 4.6 periods. Steady means that every returned period agrees with the one before, so
  // a dip shorter than output_periods is not a steady state (the solver once took it for one).
  GearPairModelSpec spec;
  spec.mass = 1.0;
  spec.stiffness = std::make_shared<ConstantMeshStiffness>("constant", 1.0, 1.6);
  spec.damping = 0.2;
  spec.mean_force = 1.0;
  const double w_m = 0.3, delta = 0.01;
  spec.mesh_frequency = w_m / (2 * kPi);
  const auto gain = [&](double w) { return 1.0 / std::hypot(1.0 - w * w, spec.damping * w); };
  const double w1 = w_m * (1 + delta), w2 = w_m * (1 - delta);
  spec.extra_forces = {{1e-3, w1, 0.0}, {1e-3 * gain(w1) / gain(w2), w2, 0.0}};
  TimeResponseOptions options;
  options.start_from_static = false;
  options.steady_tolerance = 2e-5;
  options.output_periods = 8;
  options.max_periods = 200;  // four beats
  const TimeResponse r = solveTimeResponse(GearPairModel(spec), options);
  EXPECT_EQ(r.status, TimeResponseStatus::kMaxPeriods) << r.message;  // it was "converged"
  // With a tolerance above the beat's largest change it is steady.
  options.steady_tolerance = 3e-4;
  EXPECT_TRUE(solveTimeResponse(GearPairModel(spec), options).converged());
}

TEST(TimeResponse, ContactLossWithBacklashConvergesEveryStep) {
  // Light load, large error, near resonance: the teeth separate and hit the back flank.
  GearPairModelSpec spec;
  spec.mass = 1.0;
  spec.damping = 0.1;
  spec.mean_force = 0.1;
  spec.contact = ContactLaw::kBacklash;
  spec.backlash = 0.5;
  spec.stiffness = std::make_shared<StepMeshStiffness>(StepMeshStiffness::fromMean(1.0, 1.6));
  spec.transmission_error.addFourier({0.6}, {0.0});
  spec.mesh_frequency = 0.9 / (2 * kPi);
  const GearPairModel model(spec);
  TimeResponseOptions options;
  options.max_periods = 400;
  const TimeResponse r = solveTimeResponse(model, options);
  EXPECT_EQ(r.newton_failures, 0);
  EXPECT_LE(r.max_newton_iterations, 8);
  int separated = 0;
  for (std::size_t j = 0; j < r.x.size(); ++j) {
    separated += std::abs(r.x[j] - model.error(r.t[j])) <= spec.backlash;
  }
  EXPECT_GT(separated, 0);  // contact is lost during part of the period
}

}  // namespace
}  // namespace geardyn
