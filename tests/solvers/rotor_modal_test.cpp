// Modal analysis of the FE geared rotor: the gyroscopic forward/backward split of a disk against
// its closed form (on either shaft, so for either spin sense), eigen-residuals, Campbell
// tracking and critical speeds.

#include "geardyn/solvers/rotor_modal.h"

#include <gtest/gtest.h>

#include <cmath>

#include "support/fe_rotor_cases.h"

namespace geardyn {
namespace {

using testing::constantMesh;
using testing::visnadiFeRotorSpec;

/// A disk (m, I_p, I_d) at node 0 of one shaft, held in translation and torsion by a stiff
/// bearing (1e12) with a soft tilt stiffness k_θ; every other node of both shafts is clamped
/// (1e12 in every direction) and the mesh (1 N/m) barely couples the shafts. The tilt of node 0
/// then obeys I_d θ̈ ± I_p Ω θ̇ + k_θ θ = 0 with the first element's node-0 mass, gyroscopic
/// and stiffness terms added to the disk's:
///   ω_fwd/bwd = [±I_p Ω + √((I_p Ω)² + 4 I_d k_θ)] / (2 I_d).
constexpr double kClamp = 1e12;

FeGearedRotorSpec tiltingDisk(int shaft_with_disk) {
  auto spec = visnadiFeRotorSpec(constantMesh(1.0), 0.0, 2, 0.0);
  for (int s = 0; s < 2; ++s) {
    FeShaftSpec& shaft = spec.shafts[s];
    shaft.disks.clear();
    shaft.bearings.clear();
    for (int node = 0; node < 3; ++node) {
      FeBearing b;
      b.node = node;
      b.kyy = b.kzz = b.k_torsion = b.k_tilt = kClamp;
      if (node == 0 && s == shaft_with_disk) b.k_tilt = 2e5;
      shaft.bearings.push_back(b);
    }
    shaft.gear_node = 1;
  }
  spec.shafts[shaft_with_disk].disks.push_back({0, 10.0, 0.2, 0.1});
  spec.stiffness_proportional = 0.0;
  return spec;
}

/// I_d, I_p and k_θ of node 0's tilt: the disk's plus the first element's node-0 terms, with
/// the clamped translations of nodes 0 and 1 condensed out statically (each lowers k_θ by
/// (6EI/L²)²/k_clamp ~ 5e-5).
std::array<double, 3> tiltingDiskParameters(const FeGearedRotorSpec& spec, int shaft) {
  const ShaftSegment& e = spec.shafts[shaft].elements[0];
  const ElementMatrix ke = shaftElementStiffness(e);
  const int uz1 = kNodeDofs + kUz;
  return {0.1 + shaftElementMass(e)(kRy, kRy), 0.2 + shaftElementGyroscopic(e)(kRy, kRz),
          2e5 + ke(kRy, kRy) - ke(kRy, kUz) * ke(kRy, kUz) / (ke(kUz, kUz) + kClamp) -
              ke(kRy, uz1) * ke(kRy, uz1) / (ke(uz1, uz1) + kClamp)};
}

TEST(RotorModal, DiskGyroscopicSplitMatchesClosedForm) {
  for (int shaft : {0, 1}) {
    auto spec = tiltingDisk(shaft);
    for (double speed : {0.0, 500.0, 3000.0}) {
      spec.speed = {speed, speed, 0, 0};
      const FeGearedRotor m(spec);
      ModalOptions o;
      o.modes = 40;
      const auto modes = modalAnalysis(m, speed, o);
      const auto [Id, Ip, k] = tiltingDiskParameters(spec, shaft);
      const double own = std::abs(m.spinRatio(shaft)) * speed;
      const double root = std::sqrt(Ip * Ip * own * own + 4 * Id * k);
      const double fwd = (Ip * own + root) / (2 * Id) / (2 * M_PI);
      const double bwd = (-Ip * own + root) / (2 * Id) / (2 * M_PI);
      // The two lowest modes are the disk's tilt whirls (everything else is clamped).
      ASSERT_GE(modes.size(), 2u);
      const RotorMode& low = modes[0];
      const RotorMode& high = modes[1];
      // 1e-5: what is left of the clamps' compliance and the element's mass coupling.
      EXPECT_NEAR(low.frequency / bwd, 1.0, 1e-5) << "shaft " << shaft << " speed " << speed;
      EXPECT_NEAR(high.frequency / fwd, 1.0, 1e-5) << "shaft " << shaft << " speed " << speed;
      if (speed > 0) {
        EXPECT_EQ(low.whirl, "backward");
        EXPECT_EQ(high.whirl, "forward");
      }
      EXPECT_GT(modes[2].frequency, 5 * fwd);
    }
  }
}

TEST(RotorModal, ModesSatisfyTheQuadraticEigenproblem) {
  const FeGearedRotor m(visnadiFeRotorSpec(constantMesh(3e8), 5.0));
  const double speed = 300.0;
  ModalOptions o;
  o.modes = 16;
  const auto modes = modalAnalysis(m, speed, o);
  ASSERT_EQ(modes.size(), 16u);
  const Eigen::VectorXd& w = m.meshVector();
  const Eigen::MatrixXcd K =
      (m.stiffness() + m.meanMeshStiffness() * w * w.transpose()).cast<std::complex<double>>();
  const Eigen::MatrixXcd D = (m.damping() + speed * m.gyroscopic()).cast<std::complex<double>>();
  const Eigen::MatrixXcd M = m.mass().cast<std::complex<double>>();
  for (const auto& mode : modes) {
    const std::complex<double> l = mode.eigenvalue;
    const Eigen::VectorXcd r = (l * l * M + l * D + K) * mode.shape;
    EXPECT_LT(r.norm(), 1e-8 * (K * mode.shape).norm());
    EXPECT_NEAR(mode.lateral_fraction + mode.torsional_fraction + mode.axial_fraction, 1.0, 1e-12);
    EXPECT_GT(mode.damping_ratio, 0.0);
    EXPECT_LT(mode.damping_ratio, o.max_damping_ratio);
  }
  for (std::size_t j = 1; j < modes.size(); ++j)
    EXPECT_GE(modes[j].frequency, modes[j - 1].frequency);
  // One mode is the gear-pair torsional (mesh) mode.
  int torsional = 0;
  for (const auto& mode : modes) torsional += mode.whirl == "torsional";
  EXPECT_GE(torsional, 1);
}

TEST(RotorModal, CampbellTracksModesAndFindsCriticalSpeeds) {
  auto spec = tiltingDisk(0);
  const FeGearedRotor m(spec);
  std::vector<double> speeds;
  for (int i = 0; i <= 40; ++i) speeds.push_back(100.0 * i);
  ModalOptions o;
  o.modes = 2;
  const CampbellDiagram d = campbellDiagram(m, speeds, o, {{"1x", 1.0}});
  ASSERT_EQ(d.modes.size(), speeds.size());
  // Tracks keep their whirl sense: the backward track falls, the forward track rises.
  EXPECT_LT(d.modes.back()[0].frequency, d.modes[1][0].frequency);
  EXPECT_GT(d.modes.back()[1].frequency, d.modes[1][1].frequency);
  // The forward whirl meets 1× where ω = Ω: I_d Ω² − I_p Ω² − k_θ = 0 has no root for
  // I_p > I_d; the backward one where I_d Ω² + I_p Ω² = k_θ → Ω = √(k_θ/(I_d + I_p)).
  // Linear interpolation between speeds 100 rad/s apart: 1e-3.
  const auto [Id, Ip, k] = tiltingDiskParameters(spec, 0);
  ASSERT_EQ(d.critical_speeds.size(), 1u);
  EXPECT_EQ(d.critical_speeds[0].mode, 0);
  EXPECT_NEAR(d.critical_speeds[0].speed / std::sqrt(k / (Id + Ip)), 1.0, 1e-3);
  EXPECT_EQ(d.critical_speeds[0].whirl, "backward");
}

}  // namespace
}  // namespace geardyn
