// Assembly of the finite-element geared rotor: matrix structure, the rolling rigid-body mode,
// torque and mesh-force balance, the gear shaft's counter-rotation, unbalance, bad input.

#include "geardyn/models/fe_geared_rotor.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "geardyn/error.h"
#include "support/fe_rotor_cases.h"

namespace geardyn {
namespace {

using testing::constantMesh;
using testing::visnadiFeRotorSpec;

/// The static deflection under the constant loads with the mesh stiffness k [N/m]: the
/// minimum-norm solution of (K + k v vᵀ) q = F₀ (the rolling rigid-body mode left at zero).
Eigen::VectorXd staticDeflection(const FeGearedRotor& m, double k) {
  const Eigen::MatrixXd K = m.stiffness() + k * m.meshVector() * m.meshVector().transpose();
  return K.completeOrthogonalDecomposition().solve(m.staticLoad());
}

Eigen::VectorXd rollingMode(const FeGearedRotor& m) {
  Eigen::VectorXd r = Eigen::VectorXd::Zero(m.dofCount());
  const auto& g = m.spec().mesh;
  for (int i = 0; i < m.dofCount(); ++i) {
    if (m.typeOf(i) == kRx)
      r(i) = m.shaftOf(i) == 0 ? 1.0 : -g.pinion_base_radius / g.gear_base_radius;
  }
  return r;
}

TEST(FeGearedRotor, MatricesHaveTheirStructureAndOneRollingRigidMode) {
  for (double helix : {0.0, 5.0}) {
    const FeGearedRotor m(visnadiFeRotorSpec(constantMesh(3e8), helix));
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
  }
}

// In the static equilibrium the mesh force k vᵀq equals T / (r_bp cos β_b): the pinion shaft's
// torsion balances the drive torque whatever the lateral deflection and gravity do.
TEST(FeGearedRotor, StaticMeshForceBalancesTheDriveTorque) {
  for (double helix : {0.0, 5.0}) {
    for (double torque : {50.0, -20.0}) {
      const FeGearedRotor m(visnadiFeRotorSpec(constantMesh(3e8), helix, 4, torque));
      const Eigen::VectorXd q = staticDeflection(m, 3e8);
      const double force = 3e8 * m.meshVector().dot(q);
      EXPECT_NEAR(force, m.nominalMeshForce(), 1e-9 * std::abs(force));
      const double expected =
          torque / (m.spec().mesh.pinion_base_radius * std::cos(m.spec().mesh.base_helix_angle));
      EXPECT_NEAR(m.nominalMeshForce(), expected, 1e-12 * std::abs(expected));
    }
  }
}

TEST(FeGearedRotor, GravityLoadsTheBearingsWithTheTotalWeight) {
  const FeGearedRotor m(visnadiFeRotorSpec(constantMesh(3e8), 0.0, 2, 0.0));
  const Eigen::VectorXd q = staticDeflection(m, 3e8);
  double bearing_force = 0.0, weight = 0.0;
  for (int s = 0; s < 2; ++s) {
    const auto& shaft = m.spec().shafts[s];
    for (const auto& b : shaft.bearings) bearing_force += b.kzz * q(m.dofIndex(s, b.node, kUz));
    for (const auto& e : shaft.elements) weight += e.density * e.area() * e.length * 9.81;
    for (const auto& d : shaft.disks) weight += d.mass * 9.81;
  }
  EXPECT_NEAR(bearing_force, -weight, 1e-9 * weight);
}

TEST(FeGearedRotor, GearShaftCounterRotatesAndUnbalanceSpins) {
  auto spec = visnadiFeRotorSpec(constantMesh(3e8));
  spec.shafts[1].unbalances.push_back({1, 1e-4, 0.3});
  const FeGearedRotor m(spec);
  EXPECT_DOUBLE_EQ(m.spinRatio(1), -25.0 / 30.0);
  // The gear shaft's gyroscopic block is −z_p/z_g times that of an identical pinion shaft.
  const int py = m.dofIndex(0, 1, kRy), pz = m.dofIndex(0, 1, kRz);
  const int gy = m.dofIndex(1, 1, kRy), gz = m.dofIndex(1, 1, kRz);
  const double pinion_disk = m.spec().shafts[0].disks[0].polar_inertia;
  const double gear_disk = m.spec().shafts[1].disks[0].polar_inertia;
  const double shaft_part = m.gyroscopic()(py, pz) - pinion_disk;
  EXPECT_NEAR(m.gyroscopic()(gy, gz), -25.0 / 30.0 * (shaft_part + gear_disk), 1e-15);
  // Unbalance: a force m e Ω_g² turning about −x with the gear.
  const double wg = spec.speed.start * 25.0 / 30.0;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(m.dofCount());
  m.addUnbalanceForce(0.0, f);
  const int uy = m.dofIndex(1, 1, kUy), uz = m.dofIndex(1, 1, kUz);
  EXPECT_NEAR(std::hypot(f(uy), f(uz)), 1e-4 * wg * wg, 1e-15);
  EXPECT_NEAR(std::atan2(f(uz), f(uy)), 0.3, 1e-12);
  f.setZero();
  const double quarter_turn = 3.14159265358979 / 2 / wg;
  m.addUnbalanceForce(quarter_turn, f);
  EXPECT_NEAR(std::atan2(f(uz), f(uy)), 0.3 - 3.14159265358979 / 2, 1e-9);  // turned about −x
}

TEST(FeGearedRotor, RejectsBadInputNamingTheKey) {
  auto expectKey = [](FeGearedRotorSpec spec, const std::string& key) {
    try {
      FeGearedRotor m(std::move(spec));
      ADD_FAILURE() << "accepted bad input for " << key;
    } catch (const InputError& e) {
      EXPECT_EQ(e.key().rfind(key, 0), 0u) << e.what();
    }
  };
  auto spec = visnadiFeRotorSpec(constantMesh(3e8));
  spec.shafts[0].gear_node = 7;
  expectKey(spec, "pinion_shaft.gear_node");
  spec = visnadiFeRotorSpec(constantMesh(3e8));
  spec.shafts[1].bearings[0].kyy = -1.0;
  expectKey(spec, "gear_shaft.bearings[0]");
  spec = visnadiFeRotorSpec(constantMesh(3e8));
  spec.shafts[0].elements[1].outer_diameter = std::nan("");
  expectKey(spec, "pinion_shaft.element[1].outer_diameter");
  spec = visnadiFeRotorSpec(constantMesh(3e8));
  spec.axial = true;
  expectKey(spec, "pinion_shaft.bearings.k_axial");
  spec = visnadiFeRotorSpec(constantMesh(3e8));
  spec.load_node = 3;
  expectKey(spec, "load.load_node");
}

}  // namespace
}  // namespace geardyn
