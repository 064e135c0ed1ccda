// The true form radius r_Ff of rack-generated gears: ISO 21771's closed form without undercut,
// a direct sweep of the rack's tip rounding with undercut, and what it does to the pair's start
// of active profile and transverse contact ratio.
#include "geardyn/geometry/rack_generation.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "geardyn/error.h"
#include "geardyn/geometry/gear_pair.h"
#include "geardyn/geometry/involute.h"
#include "geardyn/geometry/tooth_profile.h"
#include "support/numeric_assertions.h"

namespace geardyn {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180.0;

GearSpec gearOf(int teeth, double x = 0.0, double helix_deg = 0.0, double rho = 0.38) {
  GearSpec g;
  g.teeth = teeth;
  g.normal_module = 2e-3;
  g.normal_pressure_angle = 20.0 * kDegree;
  g.helix_angle = helix_deg * kDegree;
  g.face_width = 20e-3;
  g.profile_shift = x;
  g.root_fillet_coefficient = rho;
  return g;
}

/// ISO 21771:2007 §5.4 form diameter of a rack-generated gear without undercut, written from
/// the standard: d_Ff = √(d_b² + (d sin α_t − 2 (h_FfP − x m_n) / sin α_t)²), with
/// h_FfP = h_fP − ρ_fP (1 − sin α_n).
double isoFormRadius(const GearSpec& g) {
  const double beta = std::abs(g.helix_angle);
  const double alpha_t = std::atan(std::tan(g.normal_pressure_angle) / std::cos(beta));
  const double d = g.teeth * g.normal_module / std::cos(beta);
  const double h_ffp =
      g.dedendum_coefficient * g.normal_module -
      g.root_fillet_coefficient * g.normal_module * (1.0 - std::sin(g.normal_pressure_angle));
  const double roll =
      d * std::sin(alpha_t) - 2.0 * (h_ffp - g.profile_shift * g.normal_module) / std::sin(alpha_t);
  return 0.5 * std::hypot(d * std::cos(alpha_t), roll);
}

TEST(RackGeneration, WithoutUndercutTheFormRadiusIsIsoClosedFormAndTheFilletJoinsTheInvolute) {
  // Spur and helical, shifted, and a sharp-cornered rack: E generates on the involute.
  for (const GearSpec& g : {gearOf(25), gearOf(12, 0.5), gearOf(20, 0.2, 15.0), gearOf(40, -0.3),
                            gearOf(25, 0.0, 0.0, 0.0), gearOf(30, 0.1, 25.0, 0.25)}) {
    const GeneratingRack rack = generatingRack(g);
    ASSERT_GE(rack.flank_end_roll, 0.0) << g.teeth;
    const double r_ff = isoFormRadius(g);
    // 1e-9: two evaluations of one closed form, round-off only.
    EXPECT_CLOSE(trueFormRadius(rack), r_ff, 1e-9) << g.teeth;
    // The envelope of the rounding, computed from the rolling motion, starts on the involute at
    // r_Ff (position and half-angle) and ends on the root circle r_f = r − (h_f* − x) m_n.
    const Eigen::Vector2d top = generatedFilletPoint(rack, 0.0);
    EXPECT_CLOSE(top.norm(), r_ff, 1e-9) << g.teeth;
    EXPECT_NEAR(std::atan2(top.x(), top.y()), involuteHalfAngle(rack, r_ff), 1e-12) << g.teeth;
    const double r_f = rack.pitch_radius - (g.dedendum_coefficient - g.profile_shift) * 2e-3;
    EXPECT_CLOSE(generatedFilletPoint(rack, 1.0).norm(), r_f, 1e-12) << g.teeth;
  }
}

/// Independent reference for the undercut: sweep the rack's tip rounding itself. For each of
/// `points` points p of the rounding (the ellipse of the transverse section), the radius of its
/// path |p − G(φ)| is r_y at r φ = −p_x ± √(r_y² − p_y²), so the angle it reaches at r_y is
/// exact; the smallest over the points is what the rounding leaves at r_y. Bisection on r_y for
/// where that equals the involute's half-angle (no envelope condition, no fillet polyline).
double sweptFormRadius(const GearSpec& g, int points) {
  const GeneratingRack rack = generatingRack(g);
  const double r = rack.pitch_radius, rho = rack.rounding_radius;
  const auto swept_angle = [&](double radius) {
    double best = 1e9;
    for (int i = 0; i <= points; ++i) {
      const double theta = kPi + rack.normal_pressure +
                           (0.5 * kPi - rack.normal_pressure) * i / static_cast<double>(points);
      const Eigen::Vector2d p =
          rack.rounding_centre +
          Eigen::Vector2d(rho * std::cos(theta) / rack.cos_beta, rho * std::sin(theta));
      if (radius * radius < p.y() * p.y()) continue;
      for (double sign : {-1.0, 1.0}) {
        const double phi = (-p.x() + sign * std::sqrt(radius * radius - p.y() * p.y())) / r;
        const Eigen::Vector2d rel = p - Eigen::Vector2d(-r * phi, 0.0);
        const Eigen::Vector2d q(std::cos(phi) * rel.x() - std::sin(phi) * rel.y(),
                                std::sin(phi) * rel.x() + std::cos(phi) * rel.y());
        best = std::min(best, std::atan2(q.x(), q.y()));
      }
    }
    return best;
  };
  // The involute written out again: ψ = s_t / (2r) + inv α_t − inv α_y.
  const double s_t = g.normal_module / rack.cos_beta *
                     (0.5 * kPi + 2.0 * g.profile_shift * std::tan(g.normal_pressure_angle));
  const auto psi = [&](double radius) {
    return s_t / (2.0 * r) + involute(rack.transverse_pressure) -
           involute(std::acos(rack.base_radius / radius));
  };
  double lo = rack.base_radius * (1.0 + 1e-9), hi = rack.base_radius * 1.1;
  EXPECT_LT(swept_angle(lo), psi(lo));  // the undercut cuts into the involute near r_b
  EXPECT_GT(swept_angle(hi), psi(hi));  // and the rounding no longer reaches it at 1.1 r_b
  for (int k = 0; k < 50; ++k) {
    const double mid = 0.5 * (lo + hi);
    (swept_angle(mid) < psi(mid) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(RackGeneration, UndercutFormRadiusMatchesASweepOfTheRackRounding) {
  // 17 teeth: barely undercut (ρ_F = −0.017 m_n), the crossing just above the base circle.
  for (const GearSpec& g : {gearOf(8), gearOf(10), gearOf(12), gearOf(16), gearOf(17),
                            gearOf(10, 0.2), gearOf(9, 0.0, 20.0)}) {
    const GeneratingRack rack = generatingRack(g);
    ASSERT_LT(rack.flank_end_roll, 0.0) << g.teeth;
    const double exact = trueFormRadius(rack);
    // The sweep's minimum over a grid of rounding points lies above the true one by O(Δθ²);
    // at 20000 points that moves the crossing by < 1e-9 r_b (measured: 2.5e-10 for z = 10),
    // while the crossing lies 6e-5 (z = 16) to 1.6e-2 (z = 8) r_b above the base circle.
    const double swept = sweptFormRadius(g, 20000);
    EXPECT_CLOSE(exact, swept, 1e-9) << g.teeth << " teeth, helix " << g.helix_angle;
    EXPECT_GT(exact, rack.base_radius * (1.0 + 1e-9)) << g.teeth;
  }
}

GearPairSpec pairOf(const GearSpec& pinion, int gear_teeth) {
  GearPairSpec spec;
  spec.pinion = pinion;
  spec.gear = gearOf(gear_teeth, 0.0, -pinion.helix_angle / kDegree);
  return spec;
}

TEST(RackGeneration, UndercutPinionMeshesFromItsTrueFormCircle) {
  // 10/40 standard teeth, α = 20°: the gear tip reaches beyond T1, through the undercut.
  const GearPair pair(pairOf(gearOf(10), 40));
  const GeneratingRack rack = generatingRack(pair.spec().pinion);
  const double r_ff = sweptFormRadius(pair.spec().pinion, 20000);
  const double rb = pair.pinion().base_radius, ra = pair.pinion().tip_radius;
  EXPECT_CLOSE(pair.pinion().form_radius, r_ff, 1e-9);
  EXPECT_CLOSE(pair.pinion().active_profile_start_radius, r_ff, 1e-9);
  EXPECT_CLOSE(computeToothProfile(pair, Member::kPinion).form_radius, trueFormRadius(rack),
               testing::kRoundOff);
  // Driving pinion: contact from the pinion's form point to its tip point (the pinion tip does
  // not reach the 40-tooth gear's form circle).
  const double roll_ff = std::sqrt(r_ff * r_ff - rb * rb), rho_a1 = std::sqrt(ra * ra - rb * rb);
  EXPECT_CLOSE(pair.pathOfContactStart(), roll_ff, 1e-8);
  const double eps = (rho_a1 - roll_ff) / pair.basePitchTransverse();
  const double eps_uncut = rho_a1 / pair.basePitchTransverse();  // from T1, as before
  EXPECT_CLOSE(pair.contactRatioTransverse(), eps, 1e-9);
  EXPECT_LT(pair.contactRatioTransverse(), eps_uncut - 0.15);  // 1.093 against 1.264
  bool warned = false;
  for (const auto& w : pair.warnings())
    warned |= w.find("below the true form diameter") != std::string::npos &&
              w.find(fmt::format("{:.4f}", eps)) != std::string::npos &&
              w.find(fmt::format("{:.4f}", eps_uncut)) != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(RackGeneration, MateTipAboveTheUndercutFormCircleLeavesContactAtTheTip) {
  // 12/60 with a short gear addendum (0.4): the gear tip stays above the pinion's r_Ff, so the
  // undercut does not shorten the path of contact and nothing is said about it.
  GearPairSpec spec = pairOf(gearOf(12), 60);
  spec.gear.addendum_coefficient = 0.4;
  const GearPair pair(spec);
  ASSERT_TRUE(pair.pinion().undercut);
  const double rb1 = pair.pinion().base_radius;
  const double gear_tip_from_t1 =
      pair.lineOfActionLength() -
      std::sqrt(std::pow(pair.gear().tip_radius, 2) - std::pow(pair.gear().base_radius, 2));
  EXPECT_GT(std::hypot(rb1, gear_tip_from_t1), pair.pinion().form_radius);
  EXPECT_CLOSE(pair.pathOfContactStart(), gear_tip_from_t1, 1e-12);
  for (const auto& w : pair.warnings())
    EXPECT_EQ(w.find("the gear tip reaches"), std::string::npos) << w;
}

TEST(RackGeneration, MateTipBeyondTheRacksFlankEndIsTipInterference) {
  // 10/60 with a 1.2 m_n gear addendum: beyond T1 the gear tip runs further along the line of
  // action than the rack's flank end E did, into fillet the rack left standing.
  GearPairSpec spec = pairOf(gearOf(10), 60);
  spec.gear.addendum_coefficient = 1.2;
  const double roll_e = generatingRack(spec.pinion).flank_end_roll;
  try {
    GearPair{spec};
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.key(), "gear.addendum_coefficient");
    EXPECT_NE(
        std::string(error.what()).find(fmt::format("straight flank ({:.6g} mm)", -1e3 * roll_e)),
        std::string::npos)
        << error.what();
  }
  spec.gear.addendum_coefficient = 1.0;  // the standard gear passes through the undercut
  EXPECT_NO_THROW(GearPair{spec});
}

TEST(RackGeneration, UndercutCanLeaveTooShortAPathOfContact) {
  // 8/40 standard spur teeth: from T1, as before, ε_α = 1.115; from the 8-tooth pinion's true
  // form circle (r_Ff = 1.0128 r_b) only 0.913, and the pair is refused, saying why.
  try {
    GearPair{pairOf(gearOf(8), 40)};
    FAIL() << "no error";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("transverse 0.9127"), std::string::npos) << message;
    EXPECT_NE(message.find("would be 1.11"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace geardyn
