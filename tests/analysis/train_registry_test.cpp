// `train` in the analysis registry (issue 31, item 4): runAnalysis on the configuration
// loadAnalysisConfig reads — an analysis file with the gearbox file it names, as one — gives
// exactly the numbers of trainAnalysis on the two files, overrides reaching either file.
#include <gtest/gtest.h>

#include <algorithm>

#include "geardyn/analysis/analyses.h"
#include "geardyn/error.h"

namespace geardyn {
namespace {

const std::string kReducer =
    std::string(GEARDYN_SOURCE_DIR) + "/examples/train_two_stage_reducer.toml";

TEST(TrainRegistry, RunAnalysisGivesTheNumbersOfTrainAnalysis) {
  const auto& names = analysis::analysisNames();
  ASSERT_NE(std::find(names.begin(), names.end(), "train"), names.end());
  const std::vector<std::string> overrides{"analysis.run=[\"static\", \"modal\"]",
                                           "operating_point.torque=300.0",
                                           "meshes.stage2.damping_ratio=0.07"};
  const config::Config config = analysis::loadAnalysisConfig("train", kReducer, overrides);
  EXPECT_EQ(config.real("operating_point.torque"), 300.0);  // the gearbox file's key
  EXPECT_EQ(config.stringList("analysis.run").size(), 2u);  // the analysis file's
  const analysis::AnalysisResult a = analysis::runAnalysis("train", config, {});
  const analysis::AnalysisResult b =
      analysis::trainAnalysis(analysis::loadTrainInputs(kReducer, overrides), {});
  ASSERT_EQ(a.summary.status, "ok");
  for (const char* part : {"static", "modal"}) {
    auto x = a.summary.results[part], y = b.summary.results[part];
    x.erase("wall_time_s"), y.erase("wall_time_s");
    EXPECT_EQ(x, y) << part;  // bit-identical: the same model from the same keys
  }
  EXPECT_GT(a.summary.results["modal"]["lowest_frequency_hz"].get<double>(), 1.0);
}

TEST(TrainRegistry, EveryLoadCaseInOneRunIsRefused) {
  try {
    analysis::loadAnalysisConfig("train", kReducer, {"gearbox.all_load_cases=true"});
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "gearbox.all_load_cases");
  }
}

}  // namespace
}  // namespace geardyn
