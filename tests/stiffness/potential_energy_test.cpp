// The potential-energy model: the α-integral compliances against direct integration of the beam
// energies along the tooth height, the table against direct evaluation, invariants of the mesh
// curve, helical slicing and its limits.
#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/geometry/involute.h"
#include "geardyn/stiffness/api_stiffness.h"
#include "geardyn/stiffness/mesh_stiffness_summary.h"
#include "geardyn/stiffness/potential_energy_stiffness.h"
#include "support/numeric_assertions.h"
#include "support/reference_pairs.h"

namespace geardyn {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180;

GearPairSpec visnadiPair(double helix_deg = 0.0, double module = 3e-3) {
  return testing::visnadiPairSpec(helix_deg, module);
}

/// Beam energies integrated directly along the tooth, parametrised by the radius r of the
/// involute point (independent of the α-forms): half-thickness h = r sin ψ, height y = r cos ψ,
/// ψ(r) = α₂ − inv(acos(r_b / r)); M = F [cos α₁ (y_c − y) − sin α₁ h_c], I = (2/3) h³,
/// A = 2h; 1/k_b = ∫ M²/(E I F²) dy, 1/k_s = ∫ 1.2 cos²α₁ / (G A) dy, 1/k_a = ∫ sin²α₁/(E A) dy.
ToothCompliance directIntegration(double rb, double alpha2, double r_low, double r_contact,
                                  double youngs, double poisson) {
  const auto psi = [&](double r) { return alpha2 - involute(std::acos(rb / r)); };
  const auto dy_dr = [&](double r) {
    const double ar = std::acos(rb / r);
    const double dpsi = -std::pow(std::tan(ar), 2) * rb / (r * std::sqrt(r * r - rb * rb));
    return std::cos(psi(r)) - r * std::sin(psi(r)) * dpsi;
  };
  const double roll = std::sqrt(r_contact * r_contact / (rb * rb) - 1);
  const double a1 = roll - alpha2;
  const double yc = r_contact * std::cos(psi(r_contact)), hc = r_contact * std::sin(psi(r_contact));
  const double shear_modulus = youngs / (2 * (1 + poisson));
  ToothCompliance c;
  constexpr int kPanels = 400;
  const double width = (r_contact - r_low) / kPanels;
  using Gauss = boost::math::quadrature::gauss<double, 20>;
  for (int p = 0; p < kPanels; ++p) {
    const double a = r_low + p * width, b = a + width;
    c.bending += Gauss::integrate(
        [&](double r) {
          const double h = r * std::sin(psi(r)), y = r * std::cos(psi(r));
          const double m = std::cos(a1) * (yc - y) - std::sin(a1) * hc;
          return m * m / (youngs * (2.0 / 3.0) * h * h * h) * dy_dr(r);
        },
        a, b);
    const double area_integral =
        Gauss::integrate([&](double r) { return dy_dr(r) / (2 * r * std::sin(psi(r))); }, a, b);
    c.shear += 1.2 * std::pow(std::cos(a1), 2) * area_integral / shear_modulus;
    c.axial += std::pow(std::sin(a1), 2) * area_integral / youngs;
  }
  return c;
}

TEST(ToothBeam, AlphaIntegralsEqualDirectIntegrationAlongTheHeight) {
  // A 60-tooth gear: the root circle lies above the base circle, so the beam is the involute
  // alone (no straight segment) and both forms integrate exactly the same body.
  GearPairSpec spec = visnadiPair();
  spec.gear.teeth = 60;
  const GearPair pair(spec);
  const ToothBeam beam(pair, Member::kGear, ToothRoot::kStraight, FoundationArm::kForceLine, false,
                       0.0);
  const double rb = pair.gear().base_radius, rf = pair.gear().root_radius;
  ASSERT_GT(rf, rb);
  for (double r_contact : {pair.gear().active_profile_start_radius, pair.gear().pitch_radius,
                           pair.gear().tip_radius}) {
    const double roll = std::sqrt(r_contact * r_contact / (rb * rb) - 1);
    const ToothCompliance alpha_form = beam.compliance(roll);
    const ToothCompliance direct = directIntegration(rb, beam.alpha2(), rf, r_contact, 200e9, 0.3);
    // 1e-10: both quadratures converge to round-off; the bound is the issue's.
    EXPECT_CLOSE(alpha_form.bending, direct.bending, 1e-10) << r_contact;
    EXPECT_CLOSE(alpha_form.shear, direct.shear, 1e-10) << r_contact;
    EXPECT_CLOSE(alpha_form.axial, direct.axial, 1e-10, 1e-30) << r_contact;
  }
}

TEST(ToothBeam, StraightRootSegmentEqualsItsBeamEnergy) {
  // 25 teeth: r_b > r_f, a rectangle of half-thickness r_b sin α₂ below the base circle. Its
  // closed forms against the same beam energy integrated numerically over the rectangle.
  const GearPair pair(visnadiPair());
  const ToothBeam beam(pair, Member::kPinion, ToothRoot::kStraight, FoundationArm::kForceLine,
                       false, 0.0);
  const ToothBeam involute_only(pair, Member::kPinion, ToothRoot::kStraight,
                                FoundationArm::kForceLine, false, 0.0);
  const double rb = pair.pinion().base_radius, rf = pair.pinion().root_radius, a2 = beam.alpha2();
  const double roll = 0.5;  // a contact point on the flank
  const double a1 = roll - a2;
  const double hb = rb * std::sin(a2), a3 = std::asin(hb / rf);
  const double y_top = rb * std::cos(a2), y_root = rf * std::cos(a3);
  const double yc = rb * (std::cos(a1) + roll * std::sin(a1)),
               hc = rb * (roll * std::cos(a1) - std::sin(a1));
  const double bending_segment = boost::math::quadrature::gauss<double, 20>::integrate(
      [&](double y) {
        const double m = std::cos(a1) * (yc - y) - std::sin(a1) * hc;
        return m * m / (200e9 * (2.0 / 3.0) * hb * hb * hb);
      },
      y_root, y_top);
  const ToothCompliance whole = beam.compliance(roll);
  const ToothCompliance involute_part =
      directIntegration(rb, a2, rb * (1 + 1e-14), rb * std::sqrt(1 + roll * roll), 200e9, 0.3);
  (void)involute_only;
  EXPECT_CLOSE(whole.bending - involute_part.bending, bending_segment, 1e-8);
  EXPECT_CLOSE(whole.axial - involute_part.axial,
               std::pow(std::sin(a1), 2) * (y_top - y_root) / (200e9 * 2 * hb), 1e-8);
}

TEST(ToothBeam, HertzStiffness) {
  EXPECT_CLOSE(hertzStiffnessPerWidth(200e9, 0.3, 200e9, 0.3) * 0.020, 3.4522996e9, 1e-8);
  EXPECT_CLOSE(hertzStiffnessPerWidth(206e9, 0.3, 206e9, 0.3) * 0.020, 3.5558686e9, 1e-8);
}

TEST(PotentialEnergy, TableMatchesDirectEvaluation) {
  const GearPair pair(visnadiPair());
  const PotentialEnergyMeshStiffness k(pair);
  for (int i = 0; i <= 97; ++i) {
    const double s = k.contactStart() + (k.contactEnd() - k.contactStart()) * i / 97.0;
    // Cubic Hermite with 4th-order slopes on 257 nodes: 1e-9 relative.
    EXPECT_CLOSE(k.pairStiffnessPerWidth(s), k.pairStiffnessPerWidthExact(s), 1e-9) << s;
  }
  EXPECT_EQ(k.pairStiffnessPerWidth(k.contactStart() - 1e-9), 0.0);
  EXPECT_EQ(k.pairStiffnessPerWidth(k.contactEnd() + 1e-9), 0.0);
}

TEST(PotentialEnergy, InvariantsOfTheSpurCurve) {
  const GearPair pair(visnadiPair());
  const PotentialEnergyMeshStiffness k(pair);
  const double eps = pair.contactRatioTransverse();
  EXPECT_CLOSE(k.contactRatio(), eps, 1e-12);
  ASSERT_EQ(k.discontinuities().size(), 2u);
  EXPECT_CLOSE(k.discontinuities()[1], eps - 1, 1e-12);
  // Positive, periodic, double contact exactly for (ε − 1) of the period.
  for (int i = 0; i < 500; ++i) {
    const double phase = i / 500.0;
    EXPECT_GT(k.stiffness(phase), 0.0);
    EXPECT_CLOSE(k.stiffness(phase + 3.0), k.stiffness(phase), 1e-12);
    const int pairs = (k.pairStiffness(phase, 0) > 0) + (k.pairStiffness(phase, 1) > 0);
    EXPECT_EQ(pairs, phase < eps - 1 ? 2 : 1) << phase;
  }
  // Continuous between the jumps (steps of 1e-6 of a period change k by < 1e-4 relative).
  for (double phase : {0.1, 0.3, 0.5, 0.7, 0.9}) {
    EXPECT_CLOSE(k.stiffness(phase + 1e-6), k.stiffness(phase), 1e-4);
  }
  // The jump at ε − 1: a whole pair leaves.
  const double jump = eps - 1;
  EXPECT_GT(k.stiffness(jump - 1e-9) - k.stiffness(jump + 1e-9), 0.3 * k.stiffness(jump + 1e-9));
}

TEST(PotentialEnergy, StiffnessOverYoungsModulusAndWidthIsScaleFree) {
  // All lengths scaled by 2 (module, face width, bore): k / (E L) unchanged.
  const auto small =
      summarizeMeshStiffness(PotentialEnergyMeshStiffness(GearPair(visnadiPair(0, 3e-3))), 0);
  const auto large =
      summarizeMeshStiffness(PotentialEnergyMeshStiffness(GearPair(visnadiPair(0, 6e-3))), 0);
  EXPECT_CLOSE(large.mean / (200e9 * 0.040), small.mean / (200e9 * 0.020), 1e-12);
}

TEST(PotentialEnergy, HelicalTendsToSpurAndSlicesConvergeToTheExactFace) {
  const auto spur =
      summarizeMeshStiffness(PotentialEnergyMeshStiffness(GearPair(visnadiPair(0.0))), 2);
  const auto tiny =
      summarizeMeshStiffness(PotentialEnergyMeshStiffness(GearPair(visnadiPair(1e-6))), 2);
  EXPECT_CLOSE(tiny.mean, spur.mean, 1e-6);
  EXPECT_CLOSE(tiny.amplitude[0], spur.amplitude[0], 1e-5);

  const GearPair helical(visnadiPair(5.0));
  const PotentialEnergyMeshStiffness exact(helical);
  double previous_error = 1.0;
  for (int slices : {5, 20, 80}) {
    PotentialEnergyOptions options;
    options.slices = slices;
    const PotentialEnergyMeshStiffness sliced(helical, options);
    double error = 0.0;
    for (int i = 0; i < 200; ++i) {
      const double phase = (i + 0.5) / 200;
      error = std::max(error, std::abs(sliced.stiffness(phase) / exact.stiffness(phase) - 1));
    }
    EXPECT_LT(error, previous_error) << slices << " slices";
    previous_error = error;
  }
  EXPECT_LT(previous_error, 0.02);  // 80 slices: within 2 % everywhere (midpoint rule, jumps)
  // The helical curve is continuous and its contact ratio includes the overlap.
  EXPECT_CLOSE(exact.contactRatio(), helical.contactRatioTotal(), 1e-12);
  for (double phase : exact.discontinuities()) {
    EXPECT_CLOSE(exact.stiffness(phase - 1e-9), exact.stiffness(phase), 1e-6);
  }
  PotentialEnergyOptions projected;
  projected.helical_cos2_beta_b = true;
  EXPECT_CLOSE(PotentialEnergyMeshStiffness(helical, projected).stiffness(0.3),
               std::pow(std::cos(helical.baseHelixAngle()), 2) * exact.stiffness(0.3), 1e-14);
}

TEST(PotentialEnergy, MeanAboveApiForSpurAndHelical) {
  // Visnadi & de Castro 2021, §4: the beam model's mean exceeds the API constant.
  for (double helix : {0.0, 5.0}) {
    const GearPair pair(visnadiPair(helix));
    const double mean = summarizeMeshStiffness(PotentialEnergyMeshStiffness(pair), 0).mean;
    EXPECT_GT(mean, apiMeshStiffness(0.020, helix * kDegree)) << helix;
  }
}

TEST(PotentialEnergy, ConventionsChangeTheResultAsDocumented) {
  const GearPair pair(visnadiPair());
  const auto mean = [&](PotentialEnergyOptions o) {
    return summarizeMeshStiffness(PotentialEnergyMeshStiffness(pair, o), 0).mean;
  };
  const double base = mean({});
  PotentialEnergyOptions height;
  height.foundation_arm = FoundationArm::kContactHeight;
  PotentialEnergyOptions trochoid;
  trochoid.root = ToothRoot::kTrochoid;
  PotentialEnergyOptions rigid_body;
  rigid_body.foundation = false;
  EXPECT_LT(mean(height), base);      // a longer arm: a softer foundation
  EXPECT_GT(mean(trochoid), base);    // the fillet is thicker than the straight segment
  EXPECT_GT(mean(rigid_body), base);  // no foundation compliance: stiffer
  PotentialEnergyOptions no_hub;
  no_hub.pinion_hub_radius = 0.5 * pair.pinion().root_radius * 2;  // r_int = r_f: invalid
  EXPECT_THROW(PotentialEnergyMeshStiffness(pair, no_hub), geardyn::InputError);
}

}  // namespace
}  // namespace geardyn
