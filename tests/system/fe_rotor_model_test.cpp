// The finite-element geared rotor as its gear train with the FE rotor's numbering: matrix
// structure, the rolling rigid-body mode, torque and mesh-force balance, the bearings carrying
// the whole weight, the gear shaft's counter-rotation and its unbalance, bad layouts.
//
// Tolerances: symmetry and equilibria hold to round-off of assembled matrices (1e-12…1e-14
// relative); the static solves are of well-conditioned supported systems (1e-9).

#include "geardyn/system/fe_rotor_model.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/system/train_excitation.h"
#include "support/fe_rotor_cases.h"

namespace geardyn {
namespace {

using testing::constantMesh;
using testing::visnadiFeRotor;

/// The static deflection under the constant loads with the mesh stiffness k [N/m]: the
/// minimum-norm solution of (K + k v vᵀ) q = F₀ (the rolling rigid-body mode left at zero).
Eigen::VectorXd staticDeflection(const FeRotorModel& m, double k) {
  const Eigen::MatrixXd K = m.stiffness() + k * m.meshVector() * m.meshVector().transpose();
  return K.completeOrthogonalDecomposition().solve(m.staticLoad());
}

Eigen::VectorXd rollingMode(const FeRotorModel& m) {
  Eigen::VectorXd r = Eigen::VectorXd::Zero(m.dofCount());
  const TrainMesh& mesh = m.train().meshes().front();
  for (int i = 0; i < m.dofCount(); ++i) {
    if (m.typeOf(i) == kRx)
      r(i) = m.shaftOf(i) == 0 ? 1.0 : -mesh.base_radius_a / mesh.base_radius_b;
  }
  return r;
}

TEST(FeRotorModel, MatricesHaveTheirStructureAndOneRollingRigidMode) {
  for (double helix : {0.0, 5.0}) {
    const FeRotorModel m = visnadiFeRotor(constantMesh(3e8), helix).model();
    EXPECT_EQ(m.dofCount(), 2 * 3 * 5);  // axial DOFs removed, as in the paper
    const Eigen::MatrixXd& M = m.mass();
    const Eigen::MatrixXd K = m.stiffness() + 3e8 * m.meshVector() * m.meshVector().transpose();
    EXPECT_LT((M - M.transpose()).norm(), 1e-14 * M.norm());
    EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
    EXPECT_LT((m.gyroscopic() + m.gyroscopic().transpose()).norm(), 1e-16);
    EXPECT_GT(m.gyroscopic().norm(), 0.0);
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(M).eigenvalues().minCoeff(), 0.0);
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues();
    EXPECT_LT(std::abs(ev(0)), 1e-8 * ev.maxCoeff());  // the rolling mode
    EXPECT_GT(ev(1), 1e3);                             // everything else is supported
    const Eigen::VectorXd r = rollingMode(m);
    EXPECT_LT((K * r).norm(), 1e-9 * K.norm());
    // The loads leave the rolling mode in equilibrium (drive and load torques balance).
    EXPECT_NEAR(r.dot(m.staticLoad()), 0.0, 1e-12);
    // Every DOF name resolves to its index.
    for (int i = 0; i < m.dofCount(); ++i)
      EXPECT_EQ(m.dofIndex(m.shaftOf(i), m.nodeOf(i), m.typeOf(i)), i) << m.dofName(i);
  }
}

// In the static equilibrium the mesh force k vᵀq equals |T| / (r_bp cos β_b): the pinion shaft's
// torsion balances the drive torque whatever the lateral deflection and gravity do (the train
// orients the mesh by the load, so a negative torque loads the other flank, in compression too).
TEST(FeRotorModel, StaticMeshForceBalancesTheDriveTorque) {
  for (double helix : {0.0, 5.0}) {
    for (double torque : {50.0, -20.0}) {
      const FeRotorModel m = visnadiFeRotor(constantMesh(3e8), helix, 4, torque).model();
      const Eigen::VectorXd q = staticDeflection(m, 3e8);
      const double force = 3e8 * m.meshVector().dot(q);
      EXPECT_NEAR(force, m.nominalMeshForce(), 1e-9 * std::abs(force));
      const TrainMesh& mesh = m.train().meshes().front();
      const double expected =
          std::abs(torque) / (mesh.base_radius_a * std::cos(mesh.base_helix_angle));
      EXPECT_NEAR(m.nominalMeshForce(), expected, 1e-12 * std::abs(expected));
    }
  }
}

TEST(FeRotorModel, GravityLoadsTheBearingsWithTheTotalWeight) {
  const testing::FeRotorCase c = visnadiFeRotor(constantMesh(3e8), 0.0, 2, 0.0);
  const FeRotorModel m = c.model();
  const Eigen::VectorXd q = staticDeflection(m, 3e8);
  double bearing_force = 0.0, weight = 0.0;
  for (int s = 0; s < 2; ++s) {
    const TrainShaftSpec& shaft = c.train.shafts[s];
    for (std::size_t b = 0; b < c.layout.bearing_nodes[s].size(); ++b) {
      const double kzz = c.train.bearings[s * 2 + b].kzz;
      bearing_force += kzz * q(m.dofIndex(s, c.layout.bearing_nodes[s][b], kUz));
    }
    for (std::size_t e = 0; e < shaft.section_lengths.size(); ++e) {
      const double d = shaft.outer_diameters[e];
      weight += shaft.density * std::numbers::pi / 4 * d * d * shaft.section_lengths[e] * 9.81;
    }
  }
  for (const TrainDiskSpec& d : c.train.disks) weight += d.mass * 9.81;
  EXPECT_NEAR(bearing_force, -weight, 1e-9 * weight);
}

TEST(FeRotorModel, GearShaftCounterRotatesAndUnbalanceSpins) {
  testing::FeRotorCase c = visnadiFeRotor(constantMesh(3e8));
  c.addUnbalance(1, 1, 1e-4, 0.3);
  const FeRotorModel m = c.model();
  EXPECT_TRUE(m.hasUnbalance());
  EXPECT_DOUBLE_EQ(m.spinRatio(1), -25.0 / 30.0);
  // The gear shaft's gyroscopic block is −z_p/z_g times that of an identical pinion shaft.
  const int py = m.dofIndex(0, 1, kRy), pz = m.dofIndex(0, 1, kRz);
  const int gy = m.dofIndex(1, 1, kRy), gz = m.dofIndex(1, 1, kRz);
  const double pinion_disk = c.train.disks[0].polar_inertia;
  const double gear_disk = c.train.disks[1].polar_inertia;
  const double shaft_part = m.gyroscopic()(py, pz) - pinion_disk;
  EXPECT_NEAR(m.gyroscopic()(gy, gz), -25.0 / 30.0 * (shaft_part + gear_disk), 1e-15);
  // Unbalance (the train's excitation): a force m e Ω_g² turning about −x with the gear.
  const double wp = m.speed().start, wg = wp * 25.0 / 30.0;
  const GearTrainModel& t = m.train();
  const double k = m.meanMeshStiffness();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(t.dofCount());
  addExcitationForce(t.excitations(), 0.0, wp, 0.0, &k, f);
  const int uy = m.trainDofs()[m.dofIndex(1, 1, kUy)], uz = m.trainDofs()[m.dofIndex(1, 1, kUz)];
  EXPECT_NEAR(std::hypot(f(uy), f(uz)), 1e-4 * wg * wg, 1e-15);
  EXPECT_NEAR(std::atan2(f(uz), f(uy)), 0.3, 1e-12);
  f.setZero();
  const double quarter_turn = std::numbers::pi / 2 / wg;
  addExcitationForce(t.excitations(), wp * quarter_turn, wp, 0.0, &k, f);
  EXPECT_NEAR(std::atan2(f(uz), f(uy)), 0.3 - std::numbers::pi / 2, 1e-9);  // turned about −x
}

TEST(FeRotorModel, RejectsABadLayoutNamingTheKey) {
  auto expectKey = [](const testing::FeRotorCase& c, const std::string& key) {
    try {
      const FeRotorModel m = c.model();
      ADD_FAILURE() << "accepted bad input for " << key;
    } catch (const InputError& e) {
      EXPECT_EQ(e.key().rfind(key, 0), 0u) << e.what();
    }
  };
  testing::FeRotorCase c = visnadiFeRotor(constantMesh(3e8));
  c.layout.gear_nodes[0] = 7;
  expectKey(c, "pinion_shaft.gear_node");
  c = visnadiFeRotor(constantMesh(3e8));
  c.layout.load_node = 3;
  expectKey(c, "load.load_node");
  c = visnadiFeRotor(constantMesh(3e8));
  c.layout.bearing_nodes[1][0] = -1;
  expectKey(c, "gear_shaft.bearings.nodes");
}

}  // namespace
}  // namespace geardyn
