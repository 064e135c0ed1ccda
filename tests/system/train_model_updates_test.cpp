// GearTrainModel::withParameters (issue 39): a changed mesh stiffness or operating point gives
// the model built anew from the changed spec — its matrices, loads, meshes and modes —, whether
// it is updated in place (rank-one updates) or rebuilt (a mesh changes flank).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geardyn/solvers/train_modal.h"
#include "geardyn/stiffness/api_stiffness.h"
#include "geardyn/system/gear_train_model.h"
#include "support/numeric_assertions.h"
#include "system/sample_trains.h"

namespace geardyn {
namespace {

using testing::kRoundOff;

// The update adds (k̄_new − k̄_old) v vᵀ where the constructor sums k̄ v vᵀ over the meshes in
// order: the entries agree to a few ulps of the largest one; 1e-13 of the matrix norm leaves a
// factor ~500 over double round-off and fails on any wrong coefficient (a change of 1e-6 of one
// mesh stiffness moves the norm by ~1e-7).
constexpr double kMatrixTolerance = 1e-13;
// Natural frequencies of matrices equal to round-off: relative 1e-12 (the symmetric
// eigensolver's backward error is ~1e-15 of ‖K‖; the spread of 18 frequencies is 1e4).
constexpr double kFrequencyTolerance = 1e-12;

void expectSameModel(const GearTrainModel& updated, const GearTrainModel& fresh) {
  const auto close = [](const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, const char* what) {
    EXPECT_LE((a - b).norm(), kMatrixTolerance * std::max(1.0, b.norm())) << what;
  };
  close(updated.meanMeshStiffness(), fresh.meanMeshStiffness(), "sum of k v v^T");
  close(updated.damping(), fresh.damping(), "C");
  close(updated.stiffness(), fresh.stiffness(), "K");
  close(updated.staticLoad(), fresh.staticLoad(), "F0");
  EXPECT_EQ(updated.inputSpeed(), fresh.inputSpeed());
  EXPECT_EQ(updated.outputTorque(), fresh.outputTorque());
  ASSERT_EQ(updated.meshes().size(), fresh.meshes().size());
  for (std::size_t i = 0; i < fresh.meshes().size(); ++i) {
    const TrainMesh &u = updated.meshes()[i], &f = fresh.meshes()[i];
    EXPECT_EQ(u.mean_stiffness, f.mean_stiffness) << f.name;
    EXPECT_CLOSE(u.damping, f.damping, kRoundOff) << f.name;
    EXPECT_CLOSE(u.damping_ratio, f.damping_ratio, kRoundOff) << f.name;
    EXPECT_CLOSE(u.normal, f.normal, kRoundOff, kRoundOff) << f.name;
  }
  EXPECT_EQ(updated.warnings(), fresh.warnings());
  const auto a = trainModes(updated, updated.inputSpeed());
  const auto b = trainModes(fresh, fresh.inputSpeed());
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t j = 0; j < b.size(); ++j) {
    EXPECT_NEAR(a[j].frequency, b[j].frequency, kFrequencyTolerance * b.back().frequency) << j;
    EXPECT_NEAR(a[j].damping_ratio, b[j].damping_ratio, 1e-10) << j;
  }
}

TEST(TrainModelUpdates, PlanetaryMeshStiffnessEqualsAFreshModel) {
  const GearTrainModel model(testing::linParker1999(3));
  GearTrainSpec spec = model.spec();
  spec.stages[0].sun_planet_stiffness =
      std::make_shared<ConstantMeshStiffness>("constant", 6.5e8, 1.5);
  const GearTrainModel updated = model.withParameters(spec);
  const GearTrainModel fresh(spec);
  expectSameModel(updated, fresh);
  // The change is seen (a test that cannot pass on the old model).
  EXPECT_EQ(updated.meshes()[0].mean_stiffness, 6.5e8);
  EXPECT_GT((updated.meanMeshStiffness() - model.meanMeshStiffness()).norm(), 1e7);
}

TEST(TrainModelUpdates, ReducerStiffnessSpeedAndTorqueEqualAFreshModel) {
  // Dashpots from a damping ratio (ζ = 0.05): c = 2ζ√(k̄ m_e) follows k̄; Rayleigh damping β.
  GearTrainSpec base = testing::twoStageReducer();
  base.stiffness_proportional_damping = 1e-6;
  const GearTrainModel model(base);
  GearTrainSpec spec = model.spec();
  spec.meshes[0].stiffness = std::make_shared<ConstantMeshStiffness>("constant", 3.1e8, 1.6);
  spec.operating.input_speed *= 1.3;
  spec.operating.input_torque *= 2.5;
  const GearTrainModel updated = model.withParameters(spec);
  expectSameModel(updated, GearTrainModel(spec));
  EXPECT_CLOSE(updated.outputTorque(), 2.5 * model.outputTorque(), kRoundOff);
}

TEST(TrainModelUpdates, GivenDashpotKeepsItsValueAndChangesItsRatio) {
  GearTrainSpec base = testing::twoStageReducer();
  base.meshes[1].damping = 1500.0;  // N s/m
  const GearTrainModel model(base);
  GearTrainSpec spec = model.spec();
  spec.meshes[1].stiffness = std::make_shared<ConstantMeshStiffness>("constant", 9e8, 1.6);
  const GearTrainModel updated = model.withParameters(spec);
  expectSameModel(updated, GearTrainModel(spec));
  EXPECT_EQ(updated.meshes()[1].damping, 1500.0);
  EXPECT_LT(updated.meshes()[1].damping_ratio, model.meshes()[1].damping_ratio);
}

TEST(TrainModelUpdates, TorqueReversalRebuildsOnTheOtherFlank) {
  const GearTrainModel model(testing::twoStageReducer());
  GearTrainSpec spec = model.spec();
  spec.operating.input_torque = -spec.operating.input_torque;
  const GearTrainModel updated = model.withParameters(spec);
  expectSameModel(updated, GearTrainModel(spec));
  // Both meshes moved to their other flank: the lines of action are mirrored.
  for (std::size_t i = 0; i < model.meshes().size(); ++i) {
    EXPECT_GT((updated.meshes()[i].normal - model.meshes()[i].normal).norm(), 0.1) << i;
  }
}

TEST(TrainModelUpdates, LoadingAnUnloadedTrainRebuildsIt) {
  // Lin & Parker's stage at zero torque: every mesh unloaded (a warning each); loaded, none.
  const GearTrainModel model(testing::linParker1999(3));
  ASSERT_FALSE(model.warnings().empty());
  GearTrainSpec spec = model.spec();
  spec.operating.input_torque = 50.0;
  const GearTrainModel updated = model.withParameters(spec);
  expectSameModel(updated, GearTrainModel(spec));
}

}  // namespace
}  // namespace geardyn
