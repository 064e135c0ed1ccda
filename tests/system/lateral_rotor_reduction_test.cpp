/// Reduction of the gear-train model to the 4-DOF lateral geared rotor of the Rao thesis
/// (system/lateral_rotor.h, eqs. 2.30–2.33). That model couples pinion and gear by a mesh spring
/// and dashpot acting equally in x and in y (not along a line of action), so in a train it is a
/// translational bearing between the two shafts (kyy = kzz = k_m) with planar DOFs; the shafts'
/// lateral stiffness is a bearing to the housing. Restricted to the lateral DOFs the train's M,
/// C, K are the model's (the rotations are free and uncoupled), and so are its modes. Its forcing
/// (transmission error applied to that isotropic spring, runouts, unbalance) is made of the
/// train's excitations in the gearbox `geardyn rotor --print-gearbox` writes
/// (config/rotor_gearbox.h), checked in train_excitation_test.cpp.
///
/// Tolerances: the same sums in another order, 1e-12 of the largest entry; eigenvalues of equal
/// 4 × 4 problems, 1e-9.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "geardyn/system/gear_train_model.h"
#include "geardyn/system/lateral_rotor.h"

namespace geardyn {
namespace {

GearTrainSpec lateralRotorAsTrain(const LateralRotorSpec& rotor) {
  GearTrainSpec spec;
  spec.dofs = TrainDofs::kPlanar;
  spec.gravity = rotor.gravity;  // along −z here, −y in the thesis: compared as a magnitude
  // Polar inertias only keep the (uncoupled) rotations regular.
  spec.shafts = {{"pinion", rotor.pinion_mass, 1e-3, {}, {}, {}, 7850.0},
                 {"gear", rotor.gear_mass, 1e-3, {}, {}, {}, 7850.0}};
  TrainBearingSpec s1{"pinion_shaft", "pinion", "", rotor.pinion_shaft_stiffness,
                      rotor.pinion_shaft_stiffness};
  s1.cyy = s1.czz = rotor.pinion_shaft_damping;
  TrainBearingSpec s2{"gear_shaft", "gear", "", rotor.gear_shaft_stiffness,
                      rotor.gear_shaft_stiffness};
  s2.cyy = s2.czz = rotor.gear_shaft_damping;
  TrainBearingSpec mesh{"mesh", "pinion", "gear", rotor.mesh_stiffness, rotor.mesh_stiffness};
  mesh.cyy = mesh.czz = rotor.mesh_damping;
  spec.bearings = {s1, s2, mesh};
  // Torques on both shafts keep the operating point well defined; nothing transmits them.
  spec.couplings = {{"drive", "pinion", "gear", 1.0, 0.0, 0.0, 0.0}};
  spec.operating = {"pinion", 2.0 * 3.141592653589793 * rotor.pinion_speed, 0.0, "gear"};
  return spec;
}

TEST(LateralRotorReduction, MatricesAndModesAreTheFourDofModel) {
  const LateralRotorSpec rotor = raoTable41Spec();
  const LateralRotorModel model(rotor);
  const GearTrainModel train(lateralRotorAsTrain(rotor));
  // Thesis order (x₁, y₁, x₂, y₂) ↔ train (pinion.y, pinion.z, gear.y, gear.z).
  const int p = train.translationDof(train.bodyIndex("pinion"));
  const int g = train.translationDof(train.bodyIndex("gear"));
  const int map[4] = {p, p + 1, g, g + 1};
  Eigen::Matrix4d M, C, K;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      M(i, j) = train.mass()(map[i], map[j]);
      C(i, j) = train.damping()(map[i], map[j]);
      K(i, j) = train.stiffness()(map[i], map[j]);
    }
  }
  auto rel = [](const Eigen::Matrix4d& a, const Eigen::Matrix4d& b) {
    return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
  };
  EXPECT_LT(rel(M, model.mass()), 1e-12);
  EXPECT_LT(rel(K, model.stiffness()), 1e-12);
  EXPECT_LT(rel(C, model.damping()), 1e-12);
  // The lateral DOFs do not couple to the rotations.
  for (int i : map) {
    for (int r : {train.rotationDof(0), train.rotationDof(1)}) {
      EXPECT_EQ(train.stiffness()(i, r), 0.0);
      EXPECT_EQ(train.mass()(i, r), 0.0);
    }
  }
  // Undamped natural frequencies of both.
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix4d> a(model.stiffness(), model.mass());
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix4d> b(K, M);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(std::sqrt(b.eigenvalues()(i)), std::sqrt(a.eigenvalues()(i)),
                1e-9 * std::sqrt(a.eigenvalues()(i)));
  }
  // Weights: m g on each centre.
  EXPECT_NEAR(train.staticLoad()(p + 1), -rotor.pinion_mass * rotor.gravity, 1e-12);
  EXPECT_NEAR(train.staticLoad()(g + 1), -rotor.gear_mass * rotor.gravity, 1e-12);
}

}  // namespace
}  // namespace geardyn
