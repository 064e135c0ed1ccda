/// DTE identification (Rao 2023 §4.6–4.7): both estimators recover every parameter from
/// noise-free frequency-domain peaks of Table 4.1 and of each varied case of Table 4.3, with
/// 1–5 harmonics (the thesis reports 0 % deviation).

#include "geardyn/identify/dte_identification.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "geardyn/error.h"

namespace geardyn {
namespace {

MeasuredWhirlPeaks exactPeaks(const LateralRotorSpec& truth) {
  MeasuredWhirlPeaks m;
  m.pinion_speed = truth.pinion_speed;
  m.peaks = modelWhirlPeaks(truth);
  return m;
}

LateralRotorSpec withHarmonics(LateralRotorSpec s, int n) {
  s.te_x.resize(n);
  s.te_y.resize(n);
  return s;
}

void expectRecovered(const DteIdentification& r, const LateralRotorSpec& truth, double tol,
                     const std::string& label) {
  const auto rel = [&](double a, double b) { return std::abs(a / b - 1.0); };
  EXPECT_LT(rel(r.mesh_stiffness.value, truth.mesh_stiffness), tol) << label;
  EXPECT_LT(rel(r.mean_te.value, truth.mean_te), tol) << label;
  EXPECT_LT(rel(r.mesh_damping.value, truth.mesh_damping), tol) << label;
  ASSERT_EQ(r.te_x.size(), truth.te_x.size());
  for (std::size_t i = 0; i < truth.te_x.size(); ++i) {
    EXPECT_LT(rel(r.te_x[i].amplitude.value, truth.te_x[i].amplitude), tol) << label << i;
    EXPECT_LT(rel(r.te_y[i].amplitude.value, truth.te_y[i].amplitude), tol) << label << i;
    EXPECT_LT(std::abs(std::remainder(r.te_x[i].phase.value - truth.te_x[i].phase, 2 * M_PI)), tol)
        << label << i;
    EXPECT_LT(std::abs(std::remainder(r.te_y[i].phase.value - truth.te_y[i].phase, 2 * M_PI)), tol)
        << label << i;
  }
  EXPECT_LT(rel(r.pinion_runout.amplitude.value, truth.pinion_runout), tol) << label;
  EXPECT_LT(rel(r.gear_runout.amplitude.value, truth.gear_runout), tol) << label;
  EXPECT_LT(
      std::abs(std::remainder(r.pinion_runout.phase.value - truth.pinion_runout_phase, 2 * M_PI)),
      tol)
      << label;
  EXPECT_LT(std::abs(std::remainder(r.gear_runout.phase.value - truth.gear_runout_phase, 2 * M_PI)),
            tol)
      << label;
}

TEST(DteIdentification, BothMethodsRecoverTable41WithOneToFiveHarmonics) {
  for (int n = 1; n <= 5; ++n) {
    const LateralRotorSpec truth = withHarmonics(raoTable41Spec(), n);
    for (auto method : {IdentificationMethod::kThreeStep, IdentificationMethod::kJoint}) {
      IdentificationOptions o;
      o.method = method;
      const auto r = identifyDte(truth, {exactPeaks(truth)}, o);
      expectRecovered(r, truth, 1e-6,
                      fmt::format("{} harmonics, {}", n,
                                  method == IdentificationMethod::kJoint ? "joint" : "three-step"));
      EXPECT_TRUE(r.converged) << r.message;
    }
  }
}

TEST(DteIdentification, BothMethodsRecoverTheVariedCasesOfTable43) {
  // Table 4.3: speed 660/1320 rpm; k_m 6e8/7e8; e_m 10/100 µm; TE 10/50 µm; runouts 100/200 µm;
  // mesh damping ratio 0.01/0.02.
  std::vector<std::pair<std::string, std::function<void(LateralRotorSpec&, double&)>>> cases = {
      {"1320 rpm", [](LateralRotorSpec& s, double&) { s.pinion_speed = 1320.0 / 60.0; }},
      {"k_m 7e8", [](LateralRotorSpec& s, double&) { s.mesh_stiffness = 7e8; }},
      {"e_m 10", [](LateralRotorSpec& s, double&) { s.mean_te = 10e-6; }},
      {"e_m 100", [](LateralRotorSpec& s, double&) { s.mean_te = 100e-6; }},
      {"TE 10",
       [](LateralRotorSpec& s, double&) {
         for (auto* l : {&s.te_x, &s.te_y})
           for (auto& h : *l) h.amplitude = 10e-6;
       }},
      {"TE 50",
       [](LateralRotorSpec& s, double&) {
         for (auto* l : {&s.te_x, &s.te_y})
           for (auto& h : *l) h.amplitude = 50e-6;
       }},
      {"runouts 100",
       [](LateralRotorSpec& s, double&) { s.pinion_runout = s.gear_runout = 100e-6; }},
      {"runouts 200",
       [](LateralRotorSpec& s, double&) { s.pinion_runout = s.gear_runout = 200e-6; }},
      {"damping 0.02", [](LateralRotorSpec& s, double& zeta) { zeta = 0.02; }},
  };
  for (auto& [label, change] : cases) {
    for (int n = 1; n <= 5; ++n) {
      LateralRotorSpec truth = withHarmonics(raoTable41Spec(), n);
      double zeta = 0.01;
      change(truth, zeta);
      lateralRotorDamping(truth, 0.01, zeta);
      for (auto method : {IdentificationMethod::kThreeStep, IdentificationMethod::kJoint}) {
        IdentificationOptions o;
        o.method = method;
        o.mesh_damping_ratio = zeta;  // the three-step method assumes ζ_m (eq. 4.10)
        expectRecovered(
            identifyDte(truth, {exactPeaks(truth)}, o), truth, 1e-6,
            fmt::format("{}, {} harmonics, {}", label, n,
                        method == IdentificationMethod::kJoint ? "joint" : "three-step"));
      }
    }
  }
}

TEST(DteIdentification, TwoSpeedsTogetherAndAFixedStiffness) {
  LateralRotorSpec a = raoTable41Spec(), b = raoTable41Spec();
  b.pinion_speed = 1260.0 / 60.0;  // Table 4.4's second speed
  IdentificationOptions o;
  o.mesh_stiffness.value = 6e8;  // fixed (relative_sd 0)
  const auto r = identifyDte(a, {exactPeaks(a), exactPeaks(b)}, o);
  expectRecovered(r, a, 1e-6, "two speeds");
  EXPECT_EQ(r.mesh_stiffness.low, 6e8);
  EXPECT_EQ(r.mesh_stiffness.high, 6e8);
}

TEST(DteIdentification, RejectsDataThatCannotSupportTheEstimate) {
  const LateralRotorSpec truth = raoTable41Spec();
  IdentificationOptions o;
  EXPECT_THROW(identifyDte(truth, {}, o), InputError);
  auto m = exactPeaks(truth);
  o.harmonics = 6;
  EXPECT_THROW(identifyDte(truth, {m}, o), InputError);
  o.harmonics = -1;
  m.peaks[1].pop_back();  // gear_1x_bwd missing on the gear shaft
  EXPECT_THROW(identifyDte(truth, {m}, o), InputError);
}

}  // namespace
}  // namespace geardyn
