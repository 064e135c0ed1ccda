/// Reduction of the gear-train model to the two-shaft FE geared rotor (issue #16 acceptance):
/// the Visnadi & de Castro (2021) rotor described as a gear train with flexible shafts and
/// full DOFs gives FeGearedRotor's matrices and modes (its Newmark response is the train's
/// stepper's: tests/solvers/fe_rotor_response_test.cpp).
///
/// Tolerances: the matrices are assembled from the same element routines in another order,
/// so they agree to round-off (1e-12 of the largest entry); the eigenvalues of identical
/// matrices agree to the solvers' round-off amplified by the conditioning (1e-9 relative).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/solvers/train_modal.h"
#include "geardyn/system/fe_rotor_train.h"
#include "geardyn/system/gear_train_model.h"
#include "support/fe_rotor_cases.h"
#include "support/fe_rotor_modes.h"

namespace geardyn {
namespace {

constexpr int kOffset[kNodeDofs] = {3, 0, 1, 2, 4, 5};  // FE DOF type → train node order

/// Train DOF index of every active FE DOF.
std::vector<int> trainIndexOf(const FeGearedRotor& fe, const GearTrainModel& train) {
  std::vector<int> map(fe.dofCount());
  for (int i = 0; i < fe.dofCount(); ++i) {
    const int body = train.shaftNodes(fe.shaftOf(i))[fe.nodeOf(i)];
    map[i] = train.bodies()[body].first_dof + kOffset[fe.typeOf(i)];
  }
  return map;
}

Eigen::MatrixXd restrict(const Eigen::MatrixXd& A, const std::vector<int>& map) {
  Eigen::MatrixXd R(map.size(), map.size());
  for (std::size_t i = 0; i < map.size(); ++i)
    for (std::size_t j = 0; j < map.size(); ++j) R(i, j) = A(map[i], map[j]);
  return R;
}

double relative(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / std::max(b.cwiseAbs().maxCoeff(), 1e-300);
}

struct Pair {
  FeGearedRotorSpec fe;
  GearPairSpec gears;
};

/// Visnadi's rotor with `elements` per shaft, axial bearings when `axial`, the paper's
/// β = 3e-5 s on the shafts' elements (the translated shafts' stiffness_proportional_damping).
Pair visnadi(double helix_deg, int elements, bool axial,
             std::shared_ptr<const MeshStiffness> k = testing::constantMesh(2.5e8)) {
  Pair p{testing::visnadiFeRotorSpec(std::move(k), helix_deg, elements), {}};
  p.gears = testing::visnadiPairSpec(helix_deg);
  p.fe.stiffness_proportional = 3e-5;
  p.fe.mass_proportional = 3.0;
  p.fe.mesh_damping = 400.0;
  p.fe.axial = axial;
  for (auto& shaft : p.fe.shafts) {
    shaft.bearings.front().k_tilt = 2e4;
    shaft.bearings.back().k_torsion = 0.0;
    if (axial) shaft.bearings.front().kxx = 5e7, shaft.bearings.front().cxx = 80.0;
  }
  return p;
}

void expectSameMatrices(const Pair& p) {
  const FeGearedRotor fe(p.fe);
  const GearTrainModel train(gearTrainFromFeRotor(p.fe, p.gears));
  ASSERT_EQ(train.dofCount() -
                (p.fe.axial ? 0 : (p.fe.shafts[0].nodeCount() + p.fe.shafts[1].nodeCount())),
            fe.dofCount());
  const auto map = trainIndexOf(fe, train);
  EXPECT_LT(relative(restrict(train.mass(), map), fe.mass()), 1e-12);
  EXPECT_LT(relative(restrict(train.stiffness(), map), fe.stiffness()), 1e-12);
  EXPECT_LT(relative(restrict(train.gyroscopic(), map), fe.gyroscopic()), 1e-12);
  EXPECT_LT(relative(restrict(train.damping(), map), fe.damping()), 1e-12);
  const Eigen::VectorXd v_train = train.meshVector(0);
  Eigen::VectorXd v(map.size()), f(map.size());
  for (std::size_t i = 0; i < map.size(); ++i)
    v(i) = v_train(map[i]), f(i) = train.staticLoad()(map[i]);
  EXPECT_LT(relative(v * v.transpose(), fe.meshVector() * fe.meshVector().transpose()), 1e-12);
  EXPECT_LT(relative(v, fe.meshVector()), 1e-12) << "the same loaded flank and sign";
  EXPECT_LT(relative(f, fe.staticLoad()), 1e-12);
  EXPECT_NEAR(train.meshes()[0].mean_stiffness, fe.meanMeshStiffness(), 1e-6);
}

TEST(FeRotorReduction, SpurRotorWithAxialDofsHasTheFeMatrices) {
  expectSameMatrices(visnadi(0.0, 4, true));
}

TEST(FeRotorReduction, SpurRotorWithoutAxialDofsIsTheTrainRestricted) {
  expectSameMatrices(visnadi(0.0, 2, false));
}

TEST(FeRotorReduction, HelicalRotorHasTheFeMatrices) {
  expectSameMatrices(visnadi(20.0, 4, true));
}

TEST(FeRotorReduction, ShaftBetaDampsTheBeamsOnlyAsTheFeRotorsBetaKShafts) {
  const Pair p = visnadi(20.0, 4, true);
  ASSERT_GT(p.fe.stiffness_proportional, 0.0);
  const GearTrainSpec spec = gearTrainFromFeRotor(p.fe, p.gears);
  EXPECT_EQ(spec.stiffness_proportional_damping, 0.0) << "β K would damp bearings and mesh too";
  for (const TrainShaftSpec& shaft : spec.shafts)
    EXPECT_EQ(shaft.stiffness_proportional_damping, p.fe.stiffness_proportional);
  // C with β ≠ 0 (expectSameMatrices compares it to 1e-12); its β K_shafts part is not small.
  Pair undamped = p;
  undamped.fe.stiffness_proportional = 0.0;
  const GearTrainModel a(spec), b(gearTrainFromFeRotor(undamped.fe, undamped.gears));
  EXPECT_GT(relative(a.damping() - b.damping(), b.damping()), 1.0);
  expectSameMatrices(p);
}

TEST(FeRotorReduction, ShaftBetaOnARigidShaftIsRefusedNamingTheKey) {
  Pair p = visnadi(0.0, 2, true);
  GearTrainSpec spec = gearTrainFromFeRotor(p.fe, p.gears);
  spec.shafts[1].flexible = false;
  try {
    const GearTrainModel model(spec);
    FAIL() << "a rigid shaft with material damping was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("shafts.gear_shaft.stiffness_proportional_damping"),
              std::string::npos)
        << e.what();
  }
}

TEST(FeRotorReduction, UnbalancesAreRefusedNamingTheKey) {
  Pair p = visnadi(0.0, 2, true);
  p.fe.shafts[0].unbalances.push_back({1, 1e-5, 0.0});
  try {
    gearTrainFromFeRotor(p.fe, p.gears);
    FAIL() << "an unbalance was dropped silently";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("pinion_shaft.unbalance.nodes"), std::string::npos)
        << e.what();
  }
}

TEST(FeRotorReduction, ModesAtSpeedMatchTheFeRotor) {
  const Pair p = visnadi(20.0, 4, true);
  const FeGearedRotor fe(p.fe);
  const GearTrainModel train(gearTrainFromFeRotor(p.fe, p.gears));
  const double speed = 3000.0 * std::numbers::pi / 30.0;
  const auto fe_modes = testing::feReferenceModes(fe, speed, 16);
  TrainModalOptions options;
  options.modes = 16;
  const auto train_modes = trainModes(train, speed, options);
  ASSERT_GE(train_modes.size(), fe_modes.size());
  ASSERT_EQ(fe_modes.size(), 16u);
  for (std::size_t j = 0; j < fe_modes.size(); ++j) {
    EXPECT_NEAR(train_modes[j].frequency, fe_modes[j].frequency, 1e-9 * fe_modes[j].frequency)
        << "mode " << j;
    EXPECT_NEAR(train_modes[j].damping_ratio, fe_modes[j].damping_ratio, 1e-9) << "mode " << j;
  }
}

}  // namespace
}  // namespace geardyn
