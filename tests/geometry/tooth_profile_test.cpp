// The generated tooth profile against what the generating rack must produce, derived
// independently in GearPair (form circle, undercut) and in closed form (involute, root circle).
#include "geardyn/geometry/tooth_profile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/numeric_assertions.h"

namespace geardyn {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180.0;

GearPairSpec pairOf(int z1, int z2, double x1 = 0.0) {
  GearPairSpec spec;
  for (GearSpec* g : {&spec.pinion, &spec.gear}) {
    g->normal_module = 2e-3;
    g->normal_pressure_angle = 20.0 * kDegree;
    g->face_width = 20e-3;
  }
  spec.pinion.teeth = z1;
  spec.gear.teeth = z2;
  spec.pinion.profile_shift = x1;
  return spec;
}

double radiusOf(const Eigen::Vector2d& p) {
  return p.norm();
}
double angleOf(const Eigen::Vector2d& p) {
  return std::atan2(p.x(), p.y());
}

TEST(ToothProfile, FilletRunsFromTheRootCircleToTheFormCircleAndJoinsTheInvolute) {
  const GearPair pair(pairOf(25, 40));
  for (Member member : {Member::kPinion, Member::kGear}) {
    const GearGeometry& g = member == Member::kPinion ? pair.pinion() : pair.gear();
    const ToothProfile profile = computeToothProfile(pair, member);
    ASSERT_FALSE(g.undercut);
    // The tip rounding's lowest point cuts the root circle ...
    EXPECT_CLOSE(radiusOf(profile.fillet.front()), g.root_radius, 1e-12);
    // ... and its tangent point with the straight flank generates the first involute point: on
    // the form circle GearPair computes from the rack (ISO 21771), at the involute's angle.
    EXPECT_CLOSE(radiusOf(profile.fillet.back()), g.form_radius, 1e-10);
    EXPECT_CLOSE(angleOf(profile.fillet.back()), involuteHalfAngle(pair, member, g.form_radius),
                 1e-10);
    EXPECT_CLOSE(profile.form_radius, g.form_radius, 1e-10);
  }
}

TEST(ToothProfile, InvoluteFlankHasTheToothThicknessOfTheRack) {
  // On the reference circle the tooth is s = m (π/2 + 2 x tan α) thick.
  const double x1 = 0.3;
  const GearPair pair(pairOf(25, 40, x1));
  const double r = pair.pinion().pitch_radius;
  const double s = 2e-3 * (kPi / 2 + 2 * x1 * std::tan(20 * kDegree));
  EXPECT_CLOSE(2 * r * involuteHalfAngle(pair, Member::kPinion, r), s, 1e-13);
  // The profile passes through the tip corner and ends on the centreline.
  const ToothProfile profile = computeToothProfile(pair, Member::kPinion);
  EXPECT_CLOSE(radiusOf(profile.points.back()), pair.pinion().tip_radius, 1e-12);
  EXPECT_NEAR(angleOf(profile.points.back()), 0.0, 1e-15);
  // It starts in the middle of the tooth space on the root circle.
  EXPECT_CLOSE(angleOf(profile.points.front()), kPi / 25, 1e-12);
  EXPECT_CLOSE(radiusOf(profile.points.front()), pair.pinion().root_radius, 1e-12);
}

TEST(ToothProfile, FlankRadiusRisesMonotonicallyAndStaysInsideTheToothSpace) {
  for (int teeth : {10, 14, 17, 25, 60}) {
    const GearPair pair(pairOf(teeth, 60, teeth < 14 ? 0.5 : 0.0));
    const ToothProfile profile = computeToothProfile(pair, Member::kPinion);
    for (std::size_t i = 1; i < profile.points.size(); ++i) {
      EXPECT_GE(radiusOf(profile.points[i]), radiusOf(profile.points[i - 1]) - 1e-15)
          << teeth << " teeth, point " << i;
      EXPECT_LE(angleOf(profile.points[i]), kPi / teeth + 1e-12);
      EXPECT_GE(angleOf(profile.points[i]), -1e-15);
    }
  }
}

/// Independent reference: sweep a dense polygon of the rack tooth (straight flank and tip
/// rounding) through the rolling motion and keep, at each radius, the smallest angle any tool
/// point reaches (each point's path interpolated where it crosses the radius).
std::vector<double> bruteForceHalfAngles(const GearPair& pair, const std::vector<double>& radii) {
  const GearSpec& g = pair.spec().pinion;
  const double m = g.normal_module, alpha = g.normal_pressure_angle;
  const double r = pair.pinion().pitch_radius, rho = g.root_fillet_coefficient * m;
  const double y_ref = r + g.profile_shift * m;
  const auto flank_x = [&](double y) { return kPi * m / 4 + (y_ref - y) * std::tan(alpha); };
  const double y_c = y_ref - g.dedendum_coefficient * m + rho;
  const Eigen::Vector2d c(flank_x(y_c) + rho / std::cos(alpha), y_c);
  std::vector<Eigen::Vector2d> tool;
  const double y_e = y_c - rho * std::sin(alpha);
  for (int i = 0; i < 400; ++i) {
    const double y = y_e + (y_ref + m - y_e) * i / 399.0;
    tool.emplace_back(flank_x(y), y);
  }
  for (int i = 0; i < 60; ++i) {
    const double a = kPi + alpha + (0.5 * kPi - alpha) * i / 59.0;
    tool.push_back(c + rho * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  std::vector<double> best(radii.size(), 1e9);
  for (const auto& p : tool) {
    double previous_radius = 0, previous_angle = 0;
    for (int i = 0; i < 20000; ++i) {
      const double phi = -0.8 + 1.6 * i / 19999.0;
      const Eigen::Vector2d rel = p - Eigen::Vector2d(-r * phi, 0.0);
      const Eigen::Vector2d q(std::cos(phi) * rel.x() - std::sin(phi) * rel.y(),
                              std::sin(phi) * rel.x() + std::cos(phi) * rel.y());
      const double radius = q.norm(), angle = std::atan2(q.x(), q.y());
      if (i > 0) {
        for (std::size_t k = 0; k < radii.size(); ++k) {
          if ((radius - radii[k]) * (previous_radius - radii[k]) <= 0 &&
              radius != previous_radius) {
            const double w = (radii[k] - previous_radius) / (radius - previous_radius);
            best[k] = std::min(best[k], previous_angle + w * (angle - previous_angle));
          }
        }
      }
      previous_radius = radius;
      previous_angle = angle;
    }
  }
  return best;
}

double profileAngleAt(const ToothProfile& profile, double radius) {
  for (std::size_t i = 1; i < profile.points.size(); ++i) {
    const double r0 = radiusOf(profile.points[i - 1]), r1 = radiusOf(profile.points[i]);
    if (r1 > r0 && radius >= r0 && radius <= r1) {
      const double w = (radius - r0) / (r1 - r0);
      return angleOf(profile.points[i - 1]) +
             w * (angleOf(profile.points[i]) - angleOf(profile.points[i - 1]));
    }
  }
  return NAN;
}

TEST(ToothProfile, UndercutAndFilletMatchABruteForceSweepOfTheRack) {
  // 12 teeth, x = 0: undercut (z_min = 17), meshing with a short-addendum 60-tooth gear so that
  // the pair is valid. And a 25-tooth pinion with a normal fillet.
  for (int teeth : {12, 25}) {
    GearPairSpec spec = pairOf(teeth, 60);
    spec.gear.addendum_coefficient = 0.4;
    const GearPair pair(spec);
    EXPECT_EQ(pair.pinion().undercut, teeth == 12);
    const ToothProfile profile = computeToothProfile(pair, Member::kPinion, 200);
    const double rb = pair.pinion().base_radius, rf = pair.pinion().root_radius;
    std::vector<double> radii;
    for (int k = 0; k < 12; ++k)
      radii.push_back(std::max(rf, 0.995 * rb) * 1.0001 + k * 0.0002 * rb);
    const auto reference = bruteForceHalfAngles(pair, radii);
    for (std::size_t k = 0; k < radii.size(); ++k) {
      // 2e-5 rad: the sweep's sampling (Δφ = 8e-5 rad, 400 flank points) and the profile's
      // chords both resolve the boundary to a few 1e-6 rad.
      EXPECT_NEAR(profileAngleAt(profile, radii[k]), reference[k], 2e-5)
          << teeth << " teeth, r / r_b = " << radii[k] / rb;
    }
    if (teeth == 12) {
      // The undercut eats the involute up to 1.002–1.003 r_b (the sweep's crossing).
      EXPECT_GT(profile.form_radius, 1.002 * rb);
      EXPECT_LT(profile.form_radius, 1.003 * rb);
    }
  }
}

}  // namespace
}  // namespace geardyn
