// Properties of GearPair that hold by construction of involute geometry, closed-form limits,
// and every rejected or warned design. Published cases are in tests/reference/.
#include "geardyn/geometry/gear_pair.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/geometry/involute.h"
#include "support/numeric_assertions.h"

namespace geardyn {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180.0;

GearSpec standardGear(int teeth, double module = 3e-3) {
  GearSpec gear;
  gear.teeth = teeth;
  gear.normal_module = module;
  gear.normal_pressure_angle = 20.0 * kDegree;
  gear.face_width = 20e-3;
  return gear;
}

GearPairSpec standardPair(int z1, int z2, double module = 3e-3) {
  GearPairSpec spec;
  spec.pinion = standardGear(z1, module);
  spec.gear = standardGear(z2, module);
  return spec;
}

std::string messageOf(const GearPairSpec& spec) {
  try {
    GearPair pair(spec);
  } catch (const InputError& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(GearPair, StandardSpurRadiiAreTheTextbookOnes) {
  const GearPair pair(standardPair(25, 30));
  EXPECT_CLOSE(pair.pinion().pitch_radius, 37.5e-3, testing::kRoundOff);
  EXPECT_CLOSE(pair.pinion().base_radius, 37.5e-3 * std::cos(20 * kDegree), testing::kRoundOff);
  EXPECT_CLOSE(pair.pinion().tip_radius, 40.5e-3, testing::kRoundOff);
  EXPECT_CLOSE(pair.pinion().root_radius, 37.5e-3 - 3.75e-3, testing::kRoundOff);
  EXPECT_CLOSE(pair.gear().pitch_radius, 45e-3, testing::kRoundOff);
  // Unshifted teeth mesh without backlash at the reference centre distance, at α_n.
  EXPECT_CLOSE(pair.centreDistance(), 82.5e-3, testing::kRoundOff);
  EXPECT_CLOSE(pair.operatingPressureAngle(), 20 * kDegree, testing::kRoundOff);
  EXPECT_NEAR(pair.backlashCircumferential(), 0.0, 1e-15);
  EXPECT_CLOSE(pair.basePitchTransverse(), kPi * 3e-3 * std::cos(20 * kDegree), testing::kRoundOff);
  EXPECT_EQ(pair.overlapRatio(), 0.0);
  EXPECT_FALSE(pair.meshFrequency().has_value());
  EXPECT_TRUE(pair.warnings().empty());
}

TEST(GearPair, PathOfContactIsBetweenTheTipPointsAndReversesWithTheDriver) {
  GearPairSpec spec = standardPair(25, 30);
  const GearPair driven_by_pinion(spec);
  spec.driver = Driver::kGear;
  const GearPair driven_by_gear(spec);
  const auto& p = driven_by_pinion;
  // End − start = contact length; the ends are the tip points measured from T1.
  const double rho_a1 =
      std::sqrt(std::pow(p.pinion().tip_radius, 2) - std::pow(p.pinion().base_radius, 2));
  EXPECT_CLOSE(p.pathOfContactEnd(), rho_a1, testing::kRoundOff);
  EXPECT_CLOSE(p.pathOfContactEnd() - p.pathOfContactStart(), p.pathOfContactLength(), 1e-12);
  EXPECT_CLOSE(driven_by_gear.pathOfContactStart(), p.pathOfContactEnd(), testing::kRoundOff);
  EXPECT_CLOSE(driven_by_gear.pathOfContactEnd(), p.pathOfContactStart(), testing::kRoundOff);
  // The start of active profile of each gear is where the mate's tip meets the line of action.
  const double r_sap1 = std::hypot(p.pinion().base_radius, p.pathOfContactStart());
  EXPECT_CLOSE(p.pinion().active_profile_start_radius, r_sap1, testing::kRoundOff);
}

TEST(GearPair, ProfileShiftSpreadsTheCentreDistanceWithoutBacklash) {
  GearPairSpec spec = standardPair(16, 35, 2e-3);
  spec.gear.profile_shift = 0.5;
  const GearPair tight(spec);
  EXPECT_GT(tight.centreDistance(), tight.referenceCentreDistance());
  EXPECT_NEAR(tight.backlashCircumferential(), 0.0, 1e-14);
  // inv α_wt = inv α + 2 tan α (x1 + x2)/(z1 + z2) — recovered from the centre distance.
  const double inv_expected = involute(20 * kDegree) + 2 * std::tan(20 * kDegree) * 0.5 / 51.0;
  EXPECT_CLOSE(involute(tight.operatingPressureAngle()), inv_expected, 1e-12);
  // Pulled apart by Δa, the pair gets backlash j_bn = 2 Δa sin α_wt to first order.
  spec.centre_distance = tight.centreDistance() + 1e-6;
  const GearPair apart(spec);
  EXPECT_CLOSE(apart.backlashNormal(), 2e-6 * std::sin(tight.operatingPressureAngle()), 1e-4);
  EXPECT_LT(apart.contactRatioTransverse(), tight.contactRatioTransverse());
}

TEST(GearPair, HelicalAgainstHandDerivedValues) {
  // m_n = 3 mm, z = 25/30, α_n = 20°, β = ±15°, b = 20 mm, x = 0. By hand:
  //   α_t = atan(tan 20° / cos 15°) = 20.646896°, m_t = 3/cos 15° = 3.105829 mm,
  //   sin β_b = sin β cos α_n  →  β_b = 14.0760954°,
  //   ε_α = [√(r_a1² − r_b1²) + √(r_a2² − r_b2²) − a sin α_t] / (π m_t cos α_t) = 1.5589359685,
  //   ε_β = b sin β / (π m_n) = 0.5492310719.
  GearPairSpec spec = standardPair(25, 30);
  spec.pinion.helix_angle = 15 * kDegree;
  spec.gear.helix_angle = -15 * kDegree;
  const GearPair pair(spec);
  EXPECT_CLOSE(pair.baseHelixAngle(), std::asin(std::sin(15 * kDegree) * std::cos(20 * kDegree)),
               testing::kRoundOff);
  EXPECT_CLOSE(pair.baseHelixAngle() / kDegree, 14.076095421662, 1e-11);
  EXPECT_CLOSE(pair.transversePressureAngle(),
               std::atan(std::tan(20 * kDegree) / std::cos(15 * kDegree)), testing::kRoundOff);
  EXPECT_CLOSE(pair.contactRatioTransverse(), 1.5589359685, 1e-9);
  EXPECT_CLOSE(pair.overlapRatio(), 0.5492310719, 1e-9);
  EXPECT_CLOSE(pair.contactRatioTotal(), 1.5589359685 + 0.5492310719, 1e-9);
  // Normal base pitch = transverse base pitch × cos β_b.
  EXPECT_CLOSE(pair.basePitchNormal(), pair.basePitchTransverse() * std::cos(pair.baseHelixAngle()),
               testing::kRoundOff);
}

TEST(GearPair, HelicalApproachesSpurAsHelixVanishes) {
  GearPairSpec spec = standardPair(25, 30);
  const double spur = GearPair(spec).contactRatioTransverse();
  spec.pinion.helix_angle = 1e-7;
  spec.gear.helix_angle = -1e-7;
  EXPECT_CLOSE(GearPair(spec).contactRatioTransverse(), spur, 1e-12);
}

TEST(GearPair, MassPropertiesOfAHollowDisc) {
  GearPairSpec spec = standardPair(25, 30);
  spec.pinion.bore_diameter = 20e-3;
  const GearPair pair(spec);
  const double r = 37.5e-3, ri = 10e-3, b = 20e-3, rho = 7850.0;
  const double mass = rho * kPi * (r * r - ri * ri) * b;
  EXPECT_CLOSE(pair.pinion().mass, mass, testing::kRoundOff);
  EXPECT_CLOSE(pair.pinion().polar_inertia, 0.5 * mass * (r * r + ri * ri), testing::kRoundOff);
  EXPECT_CLOSE(pair.pinion().diametral_inertia, mass * (3 * (r * r + ri * ri) + b * b) / 12,
               testing::kRoundOff);
  // Solid disc (no bore): J_d / J_p = 1/2 + b² / (6 r²), → 1/2 for a thin disc.
  EXPECT_CLOSE(pair.gear().diametral_inertia / pair.gear().polar_inertia,
               0.5 + b * b / (6 * 45e-3 * 45e-3), testing::kRoundOff);
}

TEST(GearPair, MeshFrequencyFromPinionSpeed) {
  GearPairSpec spec = standardPair(25, 30);
  spec.pinion_speed_rpm = 1200.0;
  EXPECT_CLOSE(*GearPair(spec).meshFrequency(), 25 * 20.0, testing::kRoundOff);
}

TEST(GearPair, RejectsContactRatioBelowOne) {
  GearPairSpec spec = standardPair(25, 30);
  spec.pinion.addendum_coefficient = 0.5;
  spec.gear.addendum_coefficient = 0.5;
  const std::string message = messageOf(spec);
  EXPECT_NE(message.find("contact ratio"), std::string::npos) << message;
  EXPECT_NE(message.find("cannot mesh continuously"), std::string::npos) << message;
  // The value: r_a = 39 / 46.5 mm give ε_α = (√(39² − r_b1²) + √(46.5² − r_b2²) − 82.5 sin 20°)
  // / (3π cos 20°) = 0.884847.
  EXPECT_NE(message.find("0.884847"), std::string::npos) << message;
}

TEST(GearPair, RejectsCentreDistanceBelowBaseRadii) {
  GearPairSpec spec = standardPair(25, 30);
  spec.centre_distance = 0.07;  // r_b1 + r_b2 = 77.5 mm
  const std::string message = messageOf(spec);
  EXPECT_NE(message.find("pair.centre_distance = 0.07 m"), std::string::npos) << message;
  EXPECT_NE(message.find("base radii"), std::string::npos) << message;
}

TEST(GearPair, RejectsCentreDistanceBelowTightMesh) {
  GearPairSpec spec = standardPair(25, 30);
  spec.centre_distance = 0.0824;
  EXPECT_NE(messageOf(spec).find("teeth would overlap"), std::string::npos) << messageOf(spec);
}

TEST(GearPair, RejectsMismatchedModulesAndHands) {
  GearPairSpec spec = standardPair(25, 30);
  spec.gear.normal_module = 2.5e-3;
  EXPECT_NE(messageOf(spec).find("gear.module"), std::string::npos);
  spec = standardPair(25, 30);
  spec.pinion.helix_angle = spec.gear.helix_angle = 10 * kDegree;
  EXPECT_NE(messageOf(spec).find("gear.helix_angle_deg"), std::string::npos);
}

TEST(GearPair, RejectsPointedTeeth) {
  GearPairSpec spec = standardPair(12, 40);
  spec.pinion.profile_shift = 1.2;
  spec.gear.profile_shift = -0.5;
  EXPECT_NE(messageOf(spec).find("pinion.profile_shift"), std::string::npos) << messageOf(spec);
  EXPECT_NE(messageOf(spec).find("comes to a point"), std::string::npos);
}

TEST(GearPair, RejectsTipInterference) {
  // A pinion that is not undercut (20 teeth), cut deep (h_f* = 1.6, for the tip clearance) by a
  // rack with a large tip radius (ρ_fP* = 0.9): its straight flank ends 1.6 − 0.9 (1 − sin 20°)
  // = 1.008 m_n deep, so a gear addendum of 1.3 m_n reaches below the pinion's form circle.
  GearPairSpec spec = standardPair(20, 80);
  spec.gear.addendum_coefficient = 1.3;
  spec.pinion.dedendum_coefficient = 1.6;
  spec.pinion.root_fillet_coefficient = 0.9;
  const std::string message = messageOf(spec);
  EXPECT_NE(message.find("gear.addendum_coefficient = 1.3: tip interference"), std::string::npos)
      << message;
  // A sharp-cornered rack cuts the straight flank 1.6 m_n deep: the same pair meshes.
  spec.pinion.root_fillet_coefficient = 0.0;
  EXPECT_NO_THROW(GearPair{spec});
}

TEST(GearPair, UndercutPinionAgainstALargeGearMeshesFromItsTrueFormCircle) {
  // 14/40 standard teeth: the gear tip passes beyond T1, through the pinion's undercut. The
  // fillet cuts the involute back to the true form radius r_Ff (rack_generation_test checks it
  // against a sweep of the rack), above the base circle: contact starts there, not at T1.
  const GearPair pair(standardPair(14, 40));
  EXPECT_TRUE(pair.pinion().undercut);
  const double rb1 = pair.pinion().base_radius, r_ff = pair.pinion().form_radius;
  EXPECT_GT(r_ff, rb1 * 1.0005);
  EXPECT_LT(r_ff, rb1 * 1.001);
  const double roll_ff = std::sqrt(r_ff * r_ff - rb1 * rb1);
  EXPECT_CLOSE(pair.pathOfContactStart(), roll_ff, 1e-12);
  EXPECT_CLOSE(pair.pinion().active_profile_start_radius, r_ff, testing::kRoundOff);
  const double rho_a1 = std::sqrt(std::pow(24e-3, 2) - std::pow(rb1, 2));
  EXPECT_CLOSE(pair.contactRatioTransverse(), (rho_a1 - roll_ff) / pair.basePitchTransverse(),
               1e-12);
  bool warned = false;
  for (const auto& w : pair.warnings())
    warned |= w.find("the gear tip reaches") != std::string::npos &&
              w.find("below the true form diameter") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(GearPair, WarnsOfUndercutAndThinTips) {
  GearPairSpec spec = standardPair(14, 14);
  const GearPair undercut(spec);
  ASSERT_TRUE(undercut.pinion().undercut);
  EXPECT_TRUE(undercut.gear().undercut);
  ASSERT_FALSE(undercut.warnings().empty());
  EXPECT_NE(undercut.warnings()[0].find("undercut"), std::string::npos);
  // z_min = 2 h_FfP* / sin²α = 17.097 for 20° with h_FfP* = 1.25 − 0.38 (1 − sin 20°) = 1.0:
  // 18 teeth are not undercut, 17 are.
  EXPECT_FALSE(GearPair(standardPair(18, 40)).pinion().undercut);
  EXPECT_TRUE(GearPair(standardPair(17, 40)).pinion().undercut);

  spec = standardPair(14, 14);
  spec.pinion.profile_shift = 0.75;
  const GearPair thin(spec);
  EXPECT_FALSE(thin.pinion().undercut);
  EXPECT_LT(thin.pinion().tip_thickness_normal, 0.2 * 3e-3);
  bool warned = false;
  for (const auto& w : thin.warnings()) warned |= w.find("tip thickness") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(GearPair, ValidatesEveryField) {
  GearPairSpec spec = standardPair(25, 30);
  spec.pinion.teeth = 0;
  EXPECT_NE(messageOf(spec).find("pinion.teeth = 0"), std::string::npos);
  spec = standardPair(25, 30);
  spec.gear.normal_module = -1e-3;
  EXPECT_NE(messageOf(spec).find("gear.module"), std::string::npos);
  spec = standardPair(25, 30);
  spec.pinion.normal_pressure_angle = 45 * kDegree;
  EXPECT_NE(messageOf(spec).find("pinion.pressure_angle_deg = 45"), std::string::npos);
  spec = standardPair(25, 30);
  spec.pinion.face_width = std::nan("");
  EXPECT_NE(messageOf(spec).find("must be finite"), std::string::npos);
  spec = standardPair(25, 30);
  spec.gear.bore_diameter = 0.09;
  EXPECT_NE(messageOf(spec).find("gear.bore_diameter"), std::string::npos);
  spec = standardPair(25, 30);
  spec.pinion_speed_rpm = -5.0;
  EXPECT_NE(messageOf(spec).find("pair.speed_rpm"), std::string::npos);
}

}  // namespace
}  // namespace geardyn
