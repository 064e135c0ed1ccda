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

#include "geardyn/system/lateral_rotor_reduction.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <complex>

#include "geardyn/config/rotor_gearbox.h"
#include "geardyn/error.h"
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

// The lateral rotor of the gearbox `geardyn rotor --print-gearbox` writes
// (lateral_rotor_reduction.h): the inverse of config::lateralRotorGearTrain. Tolerance: the
// phases go through ±90°/180° shifts and atan2, so 1e-12 of each quantity (phasors compared as
// complex numbers: a phase is defined modulo 2π).
void expectSameRotor(const LateralRotorSpec& a, const LateralRotorSpec& b) {
  const auto near = [](double x, double y) { return std::abs(x - y) <= 1e-12 * std::abs(y); };
  EXPECT_TRUE(near(a.pinion_mass, b.pinion_mass) && near(a.gear_mass, b.gear_mass));
  EXPECT_TRUE(near(a.pinion_shaft_stiffness, b.pinion_shaft_stiffness));
  EXPECT_TRUE(near(a.gear_shaft_stiffness, b.gear_shaft_stiffness));
  EXPECT_TRUE(near(a.pinion_shaft_damping, b.pinion_shaft_damping));
  EXPECT_TRUE(near(a.gear_shaft_damping, b.gear_shaft_damping));
  EXPECT_TRUE(near(a.mesh_stiffness, b.mesh_stiffness) && near(a.mesh_damping, b.mesh_damping));
  EXPECT_TRUE(near(a.mean_te, b.mean_te) && near(a.gravity, b.gravity));
  EXPECT_TRUE(near(a.pinion_speed, b.pinion_speed));
  EXPECT_EQ(a.pinion_teeth, b.pinion_teeth);
  EXPECT_EQ(a.gear_teeth, b.gear_teeth);
  const auto phasor = [](double amplitude, double phase) { return std::polar(amplitude, phase); };
  const auto same = [&](double a1, double p1, double a2, double p2) {
    return std::abs(phasor(a1, p1) - phasor(a2, p2)) <= 1e-12 * a2;
  };
  EXPECT_TRUE(same(a.pinion_runout, a.pinion_runout_phase, b.pinion_runout, b.pinion_runout_phase));
  EXPECT_TRUE(same(a.gear_runout, a.gear_runout_phase, b.gear_runout, b.gear_runout_phase));
  ASSERT_EQ(a.te_x.size(), b.te_x.size());
  ASSERT_EQ(a.te_y.size(), b.te_y.size());
  for (std::size_t i = 0; i < b.te_x.size(); ++i) {
    EXPECT_TRUE(same(a.te_x[i].amplitude, a.te_x[i].phase, b.te_x[i].amplitude, b.te_x[i].phase))
        << "harmonic " << i + 1;
    EXPECT_TRUE(same(a.te_y[i].amplitude, a.te_y[i].phase, b.te_y[i].amplitude, b.te_y[i].phase))
        << "harmonic " << i + 1;
  }
}

GearTrainSpec raoGearbox(const LateralRotorSpec& rotor) {
  std::vector<std::string> warnings;
  return config::lateralRotorGearTrain(rotor, "test", warnings);
}

TEST(LateralRotorReduction, TheGearboxOfARotorReducesToIt) {
  const LateralRotorSpec rotor = raoTable41Spec();
  const GearTrainSpec gearbox = raoGearbox(rotor);
  EXPECT_EQ(lateralRotorReductionObstacle(gearbox), "");
  expectSameRotor(lateralRotorReduction(gearbox), rotor);
  // Another rig: shared tooth factor (20/45), phases beyond ±π, no gravity, 1500 rpm.
  LateralRotorSpec other = rotor;
  other.pinion_teeth = 20, other.gear_teeth = 45, other.gravity = 0.0;
  other.pinion_speed = 25.0;
  other.pinion_runout_phase = 4.0, other.gear_runout_phase = -3.5;
  other.te_x.resize(2), other.te_y.resize(2);
  other.te_y[1].phase = 5.5;
  expectSameRotor(lateralRotorReduction(raoGearbox(other)), other);
}

TEST(LateralRotorReduction, ExcitationTablesAreSummedWhateverTheirNames) {
  const LateralRotorSpec rotor = raoTable41Spec();
  GearTrainSpec gearbox = raoGearbox(rotor);
  // The TE's harmonics split over two tables, the first's named otherwise.
  auto& excitations = gearbox.bearing_excitations;
  auto te = std::find_if(excitations.begin(), excitations.end(),
                         [](const auto& e) { return e.orders.size() > 1; });
  ASSERT_NE(te, excitations.end());
  TrainBearingExcitationSpec rest = *te;
  rest.name = "te_upper";
  rest.mean_y = rest.mean_z = 0.0;
  for (auto* v : {&rest.orders, &rest.amplitude_y, &rest.phase_y, &rest.amplitude_z, &rest.phase_z})
    v->erase(v->begin(), v->begin() + 2);
  for (auto* v : {&te->orders, &te->amplitude_y, &te->phase_y, &te->amplitude_z, &te->phase_z})
    v->resize(2);
  te->name = "lower";
  excitations.push_back(rest);
  expectSameRotor(lateralRotorReduction(gearbox), rotor);
}

TEST(LateralRotorReduction, OtherGearboxesNameWhatIsNotOfItsForm) {
  const LateralRotorSpec rotor = raoTable41Spec();
  const auto obstacle = [](const GearTrainSpec& t) { return lateralRotorReductionObstacle(t); };
  GearTrainSpec torsional = raoGearbox(rotor);
  torsional.dofs = TrainDofs::kTorsional;
  EXPECT_NE(obstacle(torsional).find("gearbox.dofs"), std::string::npos);
  GearTrainSpec anisotropic = raoGearbox(rotor);
  anisotropic.bearings[0].kzz *= 1.1;
  EXPECT_NE(obstacle(anisotropic).find("bearings." + anisotropic.bearings[0].name),
            std::string::npos);
  // A runout's unbalance that does not match its offset (m e 1 % off).
  GearTrainSpec unbalance = raoGearbox(rotor);
  unbalance.unbalances[0].mass_eccentricity *= 1.01;
  EXPECT_NE(obstacle(unbalance).find("runouts are stated once"), std::string::npos)
      << obstacle(unbalance);
  // A TE order that is not a multiple of t_p = 16.
  GearTrainSpec orders = raoGearbox(rotor);
  for (auto& e : orders.bearing_excitations)
    if (e.orders.size() > 1) e.orders[1] = 33.0;
  EXPECT_NE(obstacle(orders).find("not a multiple of t_p = 16"), std::string::npos)
      << obstacle(orders);
  GearTrainSpec turning = raoGearbox(rotor);
  turning.operating.input_speed *= -1.0;
  EXPECT_NE(obstacle(turning).find("operating_point.speed_rpm"), std::string::npos);
  // The hand-built train above (no excitations, the ratio 1 coupling) is not of the form
  // either: an external pair's ratio is negative.
  EXPECT_NE(obstacle(lateralRotorAsTrain(rotor)).find("ratio"), std::string::npos);
  EXPECT_THROW(lateralRotorReduction(torsional), InputError);
}

}  // namespace
}  // namespace geardyn
