// The FE geared rotor's modes and Campbell diagram as `rotor` and Python compute them (the gear
// train's modal solver on the translated rotor, analysis/fe_rotor_modes.h): the gyroscopic
// forward/backward split of a disk against its closed form (on either shaft, so for either spin
// sense), eigen-residuals on the FE rotor's own matrices, Campbell tracking and the 1× critical
// speed. (These checked the FE rotor's own modal solver before issue #31 removed it.)

#include "geardyn/analysis/fe_rotor_modes.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "geardyn/models/timoshenko_shaft_element.h"
#include "support/fe_rotor_cases.h"

namespace geardyn {
namespace {

using testing::constantMesh;
using testing::visnadiFeRotor;

constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// The rotor's train (the spur pair of `spec`) and its DOF map, as analysis::feRotorTrain
/// builds it from a file.
analysis::FeRotorTrain trainOf(const FeRotorModel& fe) {
  analysis::FeRotorTrain t;
  t.model = std::make_unique<GearTrainModel>(fe.train().spec());
  t.train_dof = fe.trainDofs();
  t.without_axial = !fe.axial();
  return t;
}

/// A disk (m, I_p, I_d) at node 0 of one shaft, held in translation by a stiff bearing (1e12)
/// with a soft tilt stiffness k_θ; every other node of both shafts is clamped laterally and in
/// tilt (1e12) and the mesh (1 N/m) barely couples the shafts. Torsion stays free (a gearbox has
/// no torsional spring to ground on a turning shaft): the shafts' torsional modes are left out
/// below (whirl "torsional"). The tilt of node 0
/// then obeys I_d θ̈ ± I_p Ω θ̇ + k_θ θ = 0 with the first element's node-0 mass, gyroscopic
/// and stiffness terms added to the disk's:
///   ω_fwd/bwd = [±I_p Ω + √((I_p Ω)² + 4 I_d k_θ)] / (2 I_d).
constexpr double kClamp = 1e12;

testing::FeRotorCase tiltingDisk(int shaft_with_disk) {
  testing::FeRotorCase c = visnadiFeRotor(constantMesh(1.0), 0.0, 2, 0.0);
  c.train.disks.clear();
  c.train.bearings.clear();
  c.layout.bearing_nodes = {};
  for (int s = 0; s < 2; ++s) {
    for (int node = 0; node < 3; ++node) {
      TrainBearingSpec b;
      b.name = fmt::format("b{}{}", s, node);
      b.shaft = c.train.shafts[s].name;
      b.position = c.position(s, node);
      b.kyy = b.kzz = b.k_tilt = kClamp;
      if (node == 0 && s == shaft_with_disk) b.k_tilt = 2e5;
      c.train.bearings.push_back(b);
      c.layout.bearing_nodes[s].push_back(node);
    }
    c.train.shafts[s].stiffness_proportional_damping = 0.0;
  }
  c.train.disks.push_back({"disk", c.train.shafts[shaft_with_disk].name, 0.0, 10.0, 0.2, 0.1});
  return c;
}

/// I_d, I_p and k_θ of node 0's tilt: the disk's plus the first element's node-0 terms, with
/// the clamped translations of nodes 0 and 1 condensed out statically (each lowers k_θ by
/// (6EI/L²)²/k_clamp ~ 5e-5).
std::array<double, 3> tiltingDiskParameters(const testing::FeRotorCase& c, int shaft) {
  const TrainShaftSpec& s = c.train.shafts[shaft];
  ShaftSegment e;
  e.length = s.section_lengths[0];
  e.outer_diameter = s.outer_diameters[0];
  e.inner_diameter = s.inner_diameters[0];
  e.youngs_modulus = s.youngs_modulus;
  e.shear_modulus = s.youngs_modulus / (2.0 * (1.0 + s.poisson_ratio));
  e.density = s.density;
  const ElementMatrix ke = shaftElementStiffness(e);
  const int uz1 = kNodeDofs + kUz;
  return {0.1 + shaftElementMass(e)(kRy, kRy), 0.2 + shaftElementGyroscopic(e)(kRy, kRz),
          2e5 + ke(kRy, kRy) - ke(kRy, kUz) * ke(kRy, kUz) / (ke(kUz, kUz) + kClamp) -
              ke(kRy, uz1) * ke(kRy, uz1) / (ke(uz1, uz1) + kClamp)};
}

TEST(FeRotorModes, DiskGyroscopicSplitMatchesClosedForm) {
  for (int shaft : {0, 1}) {
    testing::FeRotorCase c = tiltingDisk(shaft);
    for (double speed : {0.0, 500.0, 3000.0}) {
      c.setSpeed({speed, speed, 0, 0});
      const FeRotorModel m = c.model();
      const analysis::FeRotorTrain train = trainOf(m);
      std::vector<TrainMode> modes;
      for (TrainMode& mode : analysis::feRotorModes(train, speed, 40, 0.99))
        if (mode.whirl != "torsional") modes.push_back(std::move(mode));
      const auto [Id, Ip, k] = tiltingDiskParameters(c, shaft);
      const double own = std::abs(m.spinRatio(shaft)) * speed;
      const double root = std::sqrt(Ip * Ip * own * own + 4 * Id * k);
      const double fwd = (Ip * own + root) / (2 * Id) / kTwoPi;
      const double bwd = (-Ip * own + root) / (2 * Id) / kTwoPi;
      // The two lowest modes are the disk's tilt whirls (everything else is clamped).
      ASSERT_GE(modes.size(), 3u);
      // 1e-5: what is left of the clamps' compliance and the element's mass coupling.
      EXPECT_NEAR(modes[0].frequency / bwd, 1.0, 1e-5) << "shaft " << shaft << " speed " << speed;
      EXPECT_NEAR(modes[1].frequency / fwd, 1.0, 1e-5) << "shaft " << shaft << " speed " << speed;
      if (speed > 0) {
        EXPECT_EQ(modes[0].whirl, "backward");
        EXPECT_EQ(modes[1].whirl, "forward");
      }
      EXPECT_GT(modes[2].frequency, 5 * fwd);
    }
  }
}

// The train's modes, mapped onto the FE rotor's DOFs, solve the FE rotor's own quadratic
// eigenproblem (λ² M + λ (C + Ω G₁) + K + k̄ v vᵀ) φ = 0 (residual 1e-8: the train's matrices
// are the FE rotor's to 1e-12, amplified by the conditioning).
TEST(FeRotorModes, ModesSatisfyTheFeRotorsQuadraticEigenproblem) {
  const FeRotorModel m = visnadiFeRotor(constantMesh(3e8)).model();
  const double speed = 300.0;
  const analysis::FeRotorTrain train = trainOf(m);
  const auto modes = analysis::feRotorModes(train, speed, 16, 0.99);
  ASSERT_EQ(modes.size(), 16u);
  const Eigen::VectorXd& w = m.meshVector();
  const Eigen::MatrixXcd K =
      (m.stiffness() + m.meanMeshStiffness() * w * w.transpose()).cast<std::complex<double>>();
  const Eigen::MatrixXcd D = (m.damping() + speed * m.gyroscopic()).cast<std::complex<double>>();
  const Eigen::MatrixXcd M = m.mass().cast<std::complex<double>>();
  int torsional = 0;
  for (const auto& mode : modes) {
    Eigen::VectorXcd shape(m.dofCount());
    for (int i = 0; i < m.dofCount(); ++i) shape(i) = mode.shape(train.train_dof[i]);
    const std::complex<double> l = mode.eigenvalue;
    const Eigen::VectorXcd r = (l * l * M + l * D + K) * shape;
    EXPECT_LT(r.norm(), 1e-8 * (K * shape).norm()) << mode.frequency << " Hz";
    EXPECT_NEAR(mode.lateral_fraction + mode.torsional_fraction + mode.axial_fraction, 1.0, 1e-12);
    EXPECT_GT(mode.damping_ratio, 0.0);
    EXPECT_LT(mode.damping_ratio, 0.99);
    torsional += mode.whirl == "torsional";
  }
  for (std::size_t j = 1; j < modes.size(); ++j)
    EXPECT_GE(modes[j].frequency, modes[j - 1].frequency);
  EXPECT_GE(torsional, 1);  // the gear pair's torsional (mesh) mode
}

TEST(FeRotorModes, CampbellTracksModesAndFindsTheCriticalSpeed) {
  const testing::FeRotorCase c = tiltingDisk(0);
  const FeRotorModel m = c.model();
  const analysis::FeRotorTrain train = trainOf(m);
  std::vector<double> speeds;
  for (int i = 0; i <= 40; ++i) speeds.push_back(100.0 * i);
  const TrainCampbell d = analysis::feRotorCampbell(train, m, speeds, 4, 0.99);
  ASSERT_EQ(d.modes.size(), speeds.size());
  // The disk's two tilt whirls among the tracks (the others are the shafts' torsion).
  std::vector<int> tilt;
  for (int j = 0; j < static_cast<int>(d.modes[1].size()); ++j)
    if (d.modes[1][j].whirl != "torsional") tilt.push_back(j);
  ASSERT_EQ(tilt.size(), 2u);
  // Tracks keep their whirl sense: the backward track falls, the forward track rises.
  EXPECT_LT(d.modes.back()[tilt[0]].frequency, d.modes[1][tilt[0]].frequency);
  EXPECT_GT(d.modes.back()[tilt[1]].frequency, d.modes[1][tilt[1]].frequency);
  // The forward whirl meets 1× where ω = Ω: I_d Ω² − I_p Ω² − k_θ = 0 has no root for
  // I_p > I_d; the backward one where I_d Ω² + I_p Ω² = k_θ → Ω = √(k_θ/(I_d + I_p)).
  // Linear interpolation between speeds 100 rad/s apart: 1e-3.
  const auto [Id, Ip, k] = tiltingDiskParameters(c, 0);
  std::vector<TrainCriticalSpeed> pinion;
  for (const auto& c : d.critical_speeds)
    if (c.line == "1x pinion" && (c.mode == tilt[0] || c.mode == tilt[1])) pinion.push_back(c);
  ASSERT_EQ(pinion.size(), 1u);
  EXPECT_EQ(pinion[0].mode, tilt[0]);
  EXPECT_NEAR(pinion[0].speed / std::sqrt(k / (Id + Ip)), 1.0, 1e-3);
  EXPECT_EQ(pinion[0].whirl, "backward");
}

}  // namespace
}  // namespace geardyn
