// Published and independently computed mesh-stiffness values (label: validation).
#include <gtest/gtest.h>

#include <numbers>

#include "geardyn/stiffness/iso6336_stiffness.h"
#include "geardyn/stiffness/mesh_stiffness_summary.h"
#include "geardyn/stiffness/potential_energy_stiffness.h"
#include "support/numeric_assertions.h"
#include "support/reference_pairs.h"

namespace geardyn {
namespace {

constexpr double kDegree = std::numbers::pi / 180;

TEST(MeshStiffnessReference, Iso6336TechnicalReport30Example1) {
  // ISO/TR 6336-30, example 1: m_n = 8 mm, z = 17/103, x = 0.145/0, β = 15.8°, α_n = 20°,
  // h_fP = 1.4 m_n, solid blanks, steel. c′_th = 17.85584, c′ = 12.37047, c_γα = 17.46485
  // N/(mm µm) (tolerance 1e-4 relative, the reference's). The TR's ε_α = 1.54909 (implied by
  // its c_γα / c′; it comes from tip diameters the reference does not list — our geometry with
  // standard addenda gives 1.5495).
  GearPairSpec spec;
  for (GearSpec* g : {&spec.pinion, &spec.gear}) {
    g->normal_module = 8e-3;
    g->normal_pressure_angle = 20 * kDegree;
    g->face_width = 0.1;
    g->dedendum_coefficient = 1.4;
    g->youngs_modulus = 206e9;
  }
  spec.pinion.teeth = 17;
  spec.gear.teeth = 103;
  spec.pinion.profile_shift = 0.145;
  spec.pinion.helix_angle = 15.8 * kDegree;
  spec.gear.helix_angle = -15.8 * kDegree;
  const GearPair pair(spec);
  const Iso6336Stiffness geometric = iso6336Stiffness(pair);
  EXPECT_CLOSE(geometric.zn1, 18.905, 1e-4);
  EXPECT_CLOSE(geometric.zn2, 114.543, 1e-4);
  EXPECT_CLOSE(geometric.c_prime_th, 17.85584, 1e-4);
  EXPECT_CLOSE(geometric.c_prime, 12.37047, 1e-4);
  const Iso6336Stiffness tr =
      iso6336Stiffness(17, 103, 0.145, 0.0, 15.8 * kDegree, pair.baseHelixAngle(), 20 * kDegree,
                       1.4, 8e-3, 0.1, 1.549091, 206e9, 206e9);
  EXPECT_CLOSE(tr.c_gamma_alpha, 17.46485, 1e-4);
  EXPECT_CLOSE(tr.c_gamma_beta, 14.84512, 1e-4);
}

TEST(MeshStiffnessReference, VisnadiPairPotentialEnergyAgainstAnIndependentImplementation) {
  // m = 3 mm, z = 25/30, α = 20°, L = 20 mm, E = 200 GPa, ν = 0.3, bore 30 mm: an independent
  // implementation of Ma 2014 + Sainsot (straight root, u_f on the force line) gives max
  // 3.787e8, min 2.151e8, mean 3.164e8 N/m (shared/reference/mesh_stiffness.md). The issue asks
  // for 10 %; we agree to the reference's 4 digits (5e-4 relative covers its rounding).
  const GearPairSpec spec = testing::visnadiPairSpec();
  const GearPair pair(spec);
  const auto s = summarizeMeshStiffness(PotentialEnergyMeshStiffness(pair), 0);
  EXPECT_CLOSE(s.max, 3.787e8, 5e-4);
  EXPECT_CLOSE(s.min, 2.151e8, 5e-4);
  EXPECT_CLOSE(s.mean, 3.164e8, 5e-4);
  // ISO 6336 as the reference computes it (steel values, no E ratio): c_γα b = 3.707e8 N/m.
  Iso6336Options steel;
  steel.material_factor = false;
  EXPECT_CLOSE(iso6336Stiffness(pair, steel).meshStiffness(), 3.707e8, 5e-4);
  // ... and with ISO's E/E_steel = 200/206 for these E = 200 GPa gears.
  EXPECT_CLOSE(iso6336Stiffness(pair).meshStiffness(), 3.707e8 * 200 / 206, 5e-4);
}

}  // namespace
}  // namespace geardyn
