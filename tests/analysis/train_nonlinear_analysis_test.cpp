// The `nonlinear` analysis of `geardyn train` (issue 17) against the library call it wraps: the
// p2p mesh deflections it reports at each speed of examples/train_planetary_nonlinear.toml are
// those of TrainHarmonicBalance solved on its own at that speed (from the linear starting
// guess), and the continuation steps come from the train's modes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <variant>

#include "geardyn/analysis/analyses.h"
#include "geardyn/config/gearbox_config.h"
#include "geardyn/error.h"
#include "geardyn/solvers/train_harmonic_balance.h"

namespace geardyn {
namespace {

const std::string kNonlinearExample =
    std::string(GEARDYN_SOURCE_DIR) + "/examples/train_planetary_nonlinear.toml";

const std::vector<double>& reals(const analysis::ResultTable& t, const std::string& name) {
  return std::get<std::vector<double>>(t.column(name));
}

/// Below the first fold of the up sweep the solution is unique, so Newton from the linear
/// response must find the analysis's. Both solve to a relative residual of 1e-10 or better on
/// the same samples: the p2p values agree to ~1e-9; 1e-7 leaves room for the different Newton
/// paths across the contact kinks.
TEST(TrainNonlinearAnalysis, ReportsTheLibraryHarmonicBalanceAtEachSpeed) {
  const analysis::TrainInputs inputs = analysis::loadTrainInputs(
      kNonlinearExample, {"nonlinear.direction=\"up\"", "nonlinear.stability=false",
                          "nonlinear.newmark_speeds_rpm=[]", "nonlinear.speed_max_rpm=16000.0"});
  const analysis::AnalysisResult result = analysis::trainAnalysis(inputs, {});
  ASSERT_EQ(result.summary.status, "ok") << result.report;
  const auto& info = result.summary.results["nonlinear"];
  // Steps from the modes the meshes excite: the narrowest resonance j f₀ = f_n in the range
  // (here the mode near 11.7 kHz at j = 2: the loop near 15 000 rpm is its second
  // superharmonic resonance) bounds the step, with range / 50.
  const auto& steps = info["continuation_steps"];
  ASSERT_FALSE(steps["narrowest_resonance"].is_null());
  const auto& res = steps["narrowest_resonance"];
  const double per_rpm = info["base_frequency_hz_per_rpm"].get<double>();
  const double at = res["mode_frequency_hz"].get<double>() / res["harmonic"].get<int>() / per_rpm;
  EXPECT_NEAR(res["speed_rpm"].get<double>(), at, 1e-9 * at);
  EXPECT_GE(at, 13000.0);
  EXPECT_LE(at, 16000.0);
  const double half_width = res["damping_ratio"].get<double>() * at;
  EXPECT_NEAR(steps["max_step_rpm"].get<double>(), std::min(half_width, 3000.0 / 50), 1e-9 * at);

  std::vector<std::string> warnings;
  const GearTrainModel model(config::gearTrainFromConfig(inputs.gearbox, warnings));
  TrainHarmonicBalanceOptions options;  // the example's H = 15, N = 256 are the defaults
  TrainHarmonicBalance hbm(model, options);
  const analysis::ResultTable& table = result.table("nonlinear_up.csv");
  const auto& speed = reals(table, "speed_rpm");
  double first_fold = HUGE_VAL;
  for (const auto& f : info["folds"])
    first_fold = std::min(first_fold, f["speed_rpm"].get<double>());
  int compared = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < table.rows(); i += 4) {
    if (speed[i] >= first_fold) break;
    HarmonicBalancePoint p;
    p.omega = hbm.baseFrequency(speed[i] * std::numbers::pi / 30.0);
    p.q = hbm.startingGuess(p.omega);
    hbm.solve(p);
    ASSERT_TRUE(p.converged) << speed[i] << " rpm";
    const Eigen::MatrixXd d = hbm.meshDeflections(p.q);
    for (int m = 0; m < hbm.meshCount(); ++m) {
      const double p2p = d.col(m).maxCoeff() - d.col(m).minCoeff();
      const double reported = reals(table, "p2p_deflection_" + model.meshes()[m].name + "_m")[i];
      worst = std::max(worst, std::abs(reported / p2p - 1.0));
    }
    ++compared;
  }
  EXPECT_GE(compared, 5);
  EXPECT_LT(worst, 1e-7);
  ::testing::Test::RecordProperty("worst_relative_difference", std::to_string(worst));
  std::printf("compared %d speeds, worst relative p2p difference %.3g\n", compared, worst);
}

/// nonlinear.stability_method = "hill" reaches the sweep and is recorded in summary.json: on
/// the example's lower branch (13 000–13 400 rpm, before the loop: a short run) every point's
/// verdict and the largest multiplier's modulus |e^{λT}| are the default monodromy's (within
/// 1e-3 of the multiplier: the cross-check's tolerance, tests/system/train_hill_test.cpp).
TEST(TrainNonlinearAnalysis, HillStabilityMethodIsSelectableAndRecorded) {
  std::vector<analysis::AnalysisResult> results;
  for (const char* method : {"\"monodromy\"", "\"hill\""}) {
    const analysis::TrainInputs inputs = analysis::loadTrainInputs(
        kNonlinearExample,
        {"nonlinear.direction=\"up\"", "nonlinear.newmark_speeds_rpm=[]",
         "nonlinear.speed_min_rpm=13000.0", "nonlinear.speed_max_rpm=13400.0",
         "nonlinear.max_step_rpm=20.0", std::string("nonlinear.stability_method=") + method});
    results.push_back(analysis::trainAnalysis(inputs, {}));
    ASSERT_EQ(results.back().summary.status, "ok") << results.back().report;
  }
  EXPECT_EQ(results[0].summary.results["nonlinear"]["stability_method"], "monodromy");
  EXPECT_EQ(results[1].summary.results["nonlinear"]["stability_method"], "hill");
  const analysis::ResultTable& a = results[0].table("nonlinear_up.csv");
  const analysis::ResultTable& b = results[1].table("nonlinear_up.csv");
  ASSERT_EQ(a.rows(), b.rows());
  EXPECT_GT(a.rows(), 10u);
  EXPECT_EQ(std::get<std::vector<std::int64_t>>(a.column("stable")),
            std::get<std::vector<std::int64_t>>(b.column("stable")));
  const auto& ma = reals(a, "critical_multiplier_abs");
  const auto& mb = reals(b, "critical_multiplier_abs");
  for (std::size_t i = 0; i < a.rows(); ++i) EXPECT_NEAR(ma[i], mb[i], 1e-3) << i;
}

/// H below a mesh's multiple of the common frequency, and samples that alias, name their keys.
TEST(TrainNonlinearAnalysis, BadHarmonicsAndSamplesNameTheKey) {
  const auto fails = [](const std::string& set, const std::string& key) {
    try {
      analysis::trainAnalysis(analysis::loadTrainInputs(kNonlinearExample, {set}), {});
      ADD_FAILURE() << set;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  };
  fails("nonlinear.samples=30", "nonlinear.samples");
  fails("nonlinear.initial_step_rpm=1000.0", "nonlinear.initial_step_rpm");
  fails("nonlinear.newmark_speeds_rpm=[20000.0]", "nonlinear.newmark_speeds_rpm");
  fails("nonlinear.stability_method=\"floquet\"", "nonlinear.stability_method");
}

}  // namespace
}  // namespace geardyn
