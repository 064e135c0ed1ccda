/// The gearbox an FE rotor file is (config/fe_rotor_gearbox.h, issue #31): the translated text
/// is a gearbox file whose train has the FE rotor's matrices and modes.
///
/// Tolerances: the text's doubles read back exactly and the train assembles the same element
/// matrices in another order (ν = E/2G − 1 and the position angle in degrees round-trip to an
/// ulp): 1e-12 of the largest entry; eigenvalues of those matrices: 1e-9 relative.

#include "geardyn/config/fe_rotor_gearbox.h"

#include <gtest/gtest.h>

#include <numbers>

#include "geardyn/config/fe_rotor_config.h"
#include "geardyn/config/gearbox_config.h"
#include "geardyn/error.h"
#include "geardyn/solvers/train_modal.h"
#include "geardyn/system/gear_train_model.h"
#include "support/fe_rotor_modes.h"

namespace geardyn {
namespace {

constexpr int kTrainOffset[kNodeDofs] = {3, 0, 1, 2, 4, 5};

config::Config example(const std::string& name, std::vector<std::string> overrides = {}) {
  return config::loadConfigFile(std::string(GEARDYN_SOURCE_DIR "/examples/") + name,
                                config::feRotorSchema(), overrides);
}

double relative(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / std::max(b.cwiseAbs().maxCoeff(), 1e-300);
}

struct Translated {
  std::unique_ptr<FeRotorModel> fe;
  std::unique_ptr<GearTrainModel> train;
  std::vector<int> map;  // train DOF of each FE DOF
};

Translated translate(const config::Config& config) {
  Translated t;
  t.fe = std::make_unique<FeRotorModel>(config::feRotorModelFromConfig(config));
  const config::Config gearbox =
      config::parseConfig(config::feRotorGearboxToml(config), "printed", config::gearboxSchema());
  std::vector<std::string> warnings;
  t.train = std::make_unique<GearTrainModel>(config::gearTrainFromConfig(gearbox, warnings));
  for (int i = 0; i < t.fe->dofCount(); ++i) {
    const int body = t.train->shaftNodes(t.fe->shaftOf(i))[t.fe->nodeOf(i)];
    t.map.push_back(t.train->bodies()[body].first_dof + kTrainOffset[t.fe->typeOf(i)]);
  }
  return t;
}

Eigen::MatrixXd restrict(const Eigen::MatrixXd& A, const std::vector<int>& map) {
  Eigen::MatrixXd R(map.size(), map.size());
  for (std::size_t i = 0; i < map.size(); ++i)
    for (std::size_t j = 0; j < map.size(); ++j) R(i, j) = A(map[i], map[j]);
  return R;
}

TEST(FeRotorGearbox, ThePrintedGearboxHasTheFeRotorsMatrices) {
  // The modal example (spur, no axial DOFs, β = 3e-5 s on the shafts, gravity 9.81).
  const Translated t = translate(example("rotor_visnadi2021_modal.toml"));
  EXPECT_LT(relative(restrict(t.train->mass(), t.map), t.fe->mass()), 1e-12);
  EXPECT_LT(relative(restrict(t.train->stiffness(), t.map), t.fe->stiffness()), 1e-12);
  EXPECT_LT(relative(restrict(t.train->damping(), t.map), t.fe->damping()), 1e-12);
  EXPECT_LT(relative(restrict(t.train->gyroscopic(), t.map), t.fe->gyroscopic()), 1e-12);
  EXPECT_NEAR(t.train->meshes()[0].mean_stiffness, t.fe->meanMeshStiffness(),
              1e-12 * t.fe->meanMeshStiffness());
  Eigen::VectorXd v(t.map.size());
  for (std::size_t i = 0; i < t.map.size(); ++i) v(i) = t.train->meshVector(0)(t.map[i]);
  EXPECT_LT(relative(v, t.fe->meshVector()), 1e-12);
}

TEST(FeRotorGearbox, AHelicalRotorWithAxialDofsHasTheFeRotorsMatrices) {
  const Translated t = translate(example(
      "rotor_visnadi2021_modal.toml",
      {"pinion.helix_angle_deg=5.0", "gear.helix_angle_deg=-5.0", "model.axial=true",
       "pinion_shaft.bearings.k_axial=[5e7, 0.0]", "gear_shaft.bearings.k_axial=[5e7, 0.0]",
       "load.gravity=0.0", "mesh.damping=300.0", "damping.mass_proportional=2.0",
       "mesh.line_of_action_angle_deg=50.0", "load.drive_node=2", "load.load_node=0",
       "gear_shaft.disks.nodes=[2]", "gear_shaft.disks.mass=[1.5]",
       "gear_shaft.disks.polar_inertia=[0.01]", "gear_shaft.disks.diametral_inertia=[0.005]"}));
  ASSERT_EQ(t.train->dofCount(), t.fe->dofCount());
  EXPECT_LT(relative(restrict(t.train->mass(), t.map), t.fe->mass()), 1e-12);
  EXPECT_LT(relative(restrict(t.train->stiffness(), t.map), t.fe->stiffness()), 1e-12);
  EXPECT_LT(relative(restrict(t.train->damping(), t.map), t.fe->damping()), 1e-12);
  EXPECT_LT(relative(restrict(t.train->gyroscopic(), t.map), t.fe->gyroscopic()), 1e-12);
  Eigen::VectorXd f(t.map.size());
  for (std::size_t i = 0; i < t.map.size(); ++i) f(i) = t.train->staticLoad()(t.map[i]);
  EXPECT_LT(relative(f, t.fe->staticLoad()), 1e-12) << "no gravity: the same loads";
}

TEST(FeRotorGearbox, TheTrainsModesAreTheFeRotorsModes) {
  const Translated t = translate(example("rotor_visnadi2021_modal.toml"));
  const double speed = 500.0 * std::numbers::pi / 30.0;
  const auto fe_modes = testing::feReferenceModes(*t.fe, speed, 16);
  TrainModalOptions options;
  options.keep_rigid = false;
  std::vector<TrainMode> train_modes;
  for (TrainMode& m : trainModes(*t.train, speed, options))
    if (m.axial_fraction <= 0.5) train_modes.push_back(std::move(m));  // the spur's own axial
  ASSERT_EQ(fe_modes.size(), 16u);
  ASSERT_GE(train_modes.size(), fe_modes.size());
  for (std::size_t j = 0; j < fe_modes.size(); ++j) {
    EXPECT_NEAR(train_modes[j].frequency, fe_modes[j].frequency, 1e-9 * fe_modes[j].frequency)
        << "mode " << j;
    EXPECT_NEAR(train_modes[j].damping_ratio, fe_modes[j].damping_ratio, 1e-9) << "mode " << j;
    EXPECT_EQ(train_modes[j].whirl, fe_modes[j].whirl) << "mode " << j;
    EXPECT_NEAR(train_modes[j].torsional_fraction, fe_modes[j].torsional_fraction, 1e-6);
    // A degenerate pair (the two shafts' equal torsional modes) has no unique shapes within it:
    // its whirl split is any mix of the pair's.
    const auto close = [&](std::size_t k) {
      return k < fe_modes.size() &&
             std::abs(fe_modes[k].frequency - fe_modes[j].frequency) < 1e-9 * fe_modes[j].frequency;
    };
    if (close(j + 1) || (j > 0 && close(j - 1))) continue;
    EXPECT_NEAR(train_modes[j].forward_fraction, fe_modes[j].forward_fraction, 1e-6)
        << "mode " << j << " at " << fe_modes[j].frequency << " Hz";
  }
}

TEST(FeRotorGearbox, WhatAGearboxCannotSayIsRefusedNamingTheKey) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"pinion.helix_angle_deg=5.0", "gear.helix_angle_deg=-5.0"}, "model.axial"},
      {{"pinion.helix_angle_deg=5.0", "gear.helix_angle_deg=-5.0",
        "model.contact_point=base_tangent_points"},
       "model.contact_point"},
      {{"pair.driver=gear"}, "pair.driver"}};
  for (const auto& [overrides, key] : cases) {
    try {
      config::feRotorGearboxToml(example("rotor_visnadi2021_modal.toml", overrides));
      ADD_FAILURE() << key << " was translated";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }
}

// The unbalances are the gearbox's: printed as [unbalances.<shaft>_unbalance<i>] at their
// nodes' positions, read back exactly.
TEST(FeRotorGearbox, UnbalancesBecomeTheGearboxsUnbalances) {
  const config::Config config =
      example("rotor_visnadi2021_modal.toml",
              {"gear_shaft.unbalance.nodes=[1, 2]", "gear_shaft.unbalance.amount=[1e-5, 2e-5]",
               "gear_shaft.unbalance.phase_deg=[30.0]"});
  std::vector<std::string> warnings;
  const GearTrainSpec train = config::feRotorGearTrain(config, warnings);
  ASSERT_EQ(train.unbalances.size(), 2u);
  EXPECT_EQ(train.unbalances[1].name, "gear_shaft_unbalance1");
  EXPECT_EQ(train.unbalances[1].shaft, "gear_shaft");
  EXPECT_DOUBLE_EQ(train.unbalances[1].position, 0.2);
  EXPECT_DOUBLE_EQ(train.unbalances[1].mass_eccentricity, 2e-5);
  EXPECT_NEAR(train.unbalances[1].phase, 30.0 * std::numbers::pi / 180.0, 1e-15);
}

// The FE rotor file's own checks name its keys (the gearbox's would name others).
TEST(FeRotorGearbox, TheFileIsCheckedNamingItsKeys) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"gear_shaft.bearings.kyy=[-1.0]"}, "gear_shaft.bearings.kyy"},
      {{"pinion_shaft.outer_diameters=[0.03, 0.0]"}, "pinion_shaft.outer_diameters"},
      {{"model.axial=true"}, "pinion_shaft.bearings.k_axial"},
      {{"pinion_shaft.gear_node=7"}, "pinion_shaft.gear_node"},
      {{"load.load_node=3"}, "load.load_node"},
      {{"gear_shaft.disks.nodes=[5]", "gear_shaft.disks.mass=[1.0]",
        "gear_shaft.disks.polar_inertia=[0.0]", "gear_shaft.disks.diametral_inertia=[0.0]"},
       "gear_shaft.disks.nodes"}};
  for (const auto& [overrides, key] : cases) {
    try {
      config::feRotorFromConfig(example("rotor_visnadi2021_modal.toml", overrides));
      ADD_FAILURE() << key << " was accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.key().rfind(key, 0), 0u) << e.what();
    }
  }
}

}  // namespace
}  // namespace geardyn
