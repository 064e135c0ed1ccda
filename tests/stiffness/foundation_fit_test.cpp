// Sainsot's (2004) fillet-foundation fit used outside its data (issue 34): the potential-energy
// mesh stiffness names the members and coefficients, quantifies what holding them at the data
// range does to k̄, and warns only when that exceeds kFoundationFitWarning.
#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <numbers>

#include "geardyn/stiffness/potential_energy_stiffness.h"
#include "geardyn/stiffness/tooth_beam.h"
#include "support/reference_pairs.h"

namespace geardyn {
namespace {

/// Stage 2 of examples/gearboxes/two_stage_reducer.toml: a 17-tooth pinion (x = 0.3) on a
/// 55 mm bore, r_f/r_int ≈ 1.7, below the range of Sainsot's data.
GearPairSpec reducerStage2() {
  GearPairSpec spec;
  for (GearSpec* g : {&spec.pinion, &spec.gear}) {
    g->normal_module = 4.5e-3;
    g->normal_pressure_angle = 20.0 * std::numbers::pi / 180.0;
    g->youngs_modulus = 2.1e11;
    g->poisson_ratio = 0.3;
  }
  spec.pinion.teeth = 17;
  spec.pinion.face_width = 0.045;
  spec.pinion.bore_diameter = 0.055;
  spec.pinion.profile_shift = 0.3;
  spec.gear.teeth = 47;
  spec.gear.face_width = 0.042;
  spec.gear.bore_diameter = 0.075;
  spec.gear.profile_shift = -0.3;
  return spec;
}

/// ∫ k′(s) ds over the path of contact with the given beams, by Gauss–Legendre on 200 panels
/// (independent of the model's table and of its trapezoidal rule) [N/m].
double pathIntegral(const GearPair& pair, const ToothBeam& pinion, const ToothBeam& gear) {
  const GearSpec& a = pair.spec().pinion;
  const GearSpec& b = pair.spec().gear;
  const double hertz =
      hertzStiffnessPerWidth(a.youngs_modulus, a.poisson_ratio, b.youngs_modulus, b.poisson_ratio);
  const double rb1 = pair.pinion().base_radius, rb2 = pair.gear().base_radius;
  const double line = pair.lineOfActionLength();
  const double s0 = std::min(pair.pathOfContactStart(), pair.pathOfContactEnd());
  const double s1 = std::max(pair.pathOfContactStart(), pair.pathOfContactEnd());
  const auto k = [&](double s) {
    const double c = 1.0 / hertz +
                     pinion.compliance(std::max(s / rb1, pinion.involuteStartRoll())).total() +
                     gear.compliance(std::max((line - s) / rb2, gear.involuteStartRoll())).total();
    return 1.0 / c;
  };
  constexpr int kPanels = 200;
  const double width = (s1 - s0) / kPanels;
  double sum = 0.0;
  for (int p = 0; p < kPanels; ++p) {
    sum += boost::math::quadrature::gauss<double, 10>::integrate(k, s0 + p * width,
                                                                 s0 + (p + 1) * width);
  }
  return sum;
}

TEST(FoundationFit, InsideTheDataNothingIsNotedOrWarned) {
  const GearPair pair(testing::visnadiPairSpec());
  const PotentialEnergyMeshStiffness k(pair);
  EXPECT_TRUE(k.foundationFitNote().empty());
  EXPECT_EQ(k.foundationFitEffect(), 0.0);
  EXPECT_TRUE(k.warnings().empty());
}

TEST(FoundationFit, ExtrapolationIsNamedQuantifiedAndWarnedOnce) {
  const GearPair pair(reducerStage2());
  const PotentialEnergyMeshStiffness k(pair);
  const PotentialEnergyOptions o;
  const ToothBeam pinion(pair, Member::kPinion, o.root, o.foundation_arm, true, 0.0275);
  const ToothBeam gear(pair, Member::kGear, o.root, o.foundation_arm, true, 0.0375);
  ASSERT_FALSE(pinion.foundationFitExtrapolation().empty());
  EXPECT_NE(k.foundationFitNote().find("pinion: M* = "), std::string::npos)
      << k.foundationFitNote();

  // Held coefficients: each inside its range, and the effect is the independent quadrature's
  // ratio (the model's trapezoid on its 257-point grid cancels in the ratio; 1e-5).
  const ToothBeam held = pinion.withFoundationFitClamped();
  EXPECT_TRUE(held.foundationFitExtrapolation().empty());
  const double expected =
      pathIntegral(pair, held, gear.withFoundationFitClamped()) / pathIntegral(pair, pinion, gear) -
      1.0;
  EXPECT_NEAR(k.foundationFitEffect(), expected, 1e-5);
  // M* and P* rise to the range's lower ends: a softer foundation, a lower k̄ (-3.1 % here,
  // more than the 0.5 % threshold).
  EXPECT_LT(k.foundationFitEffect(), -PotentialEnergyMeshStiffness::kFoundationFitWarning);
  ASSERT_EQ(k.warnings().size(), 1u);
  EXPECT_NE(k.warnings()[0].find("-3.0"), std::string::npos) << k.warnings()[0];

  // The model's own table keeps the fitted coefficients (the held ones were put back).
  const double s = 0.5 * (k.contactStart() + k.contactEnd());
  const double direct = pathIntegral(pair, pinion, gear);
  EXPECT_GT(direct, 0.0);
  const GearSpec& a = pair.spec().pinion;
  const double c =
      1.0 / hertzStiffnessPerWidth(a.youngs_modulus, a.poisson_ratio, a.youngs_modulus,
                                   a.poisson_ratio) +
      pinion.compliance(s / pair.pinion().base_radius).total() +
      gear.compliance((pair.lineOfActionLength() - s) / pair.gear().base_radius).total();
  EXPECT_NEAR(k.pairStiffnessPerWidthExact(s) * c, 1.0, 1e-12);
}

}  // namespace
}  // namespace geardyn
