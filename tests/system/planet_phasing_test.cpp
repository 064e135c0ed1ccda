/// γ_rs (system/planet_phasing.h) against a brute-force construction that uses only the polar
/// equation of the involute flank (angle = centre line ± (s_t/2r + inv α_t − inv α_ρ)) and
/// straight-line/circle geometry: no base-circle "string" argument, no GearPair path limits.
///
/// For a point X of a line of action, the planet turn angle θ*(X) (mod one angular pitch) at which
/// a loaded flank passes through X follows from the polar equation. The line of action through a
/// pitch point is the one along which the flank's normal points (checked numerically); the path of
/// contact is where both tooth regions overlap (tip circles); the entry end is the one the flanks
/// move away from as the planet turns. Then φ_j(θ) = σ (θ − θ*_j(A_j)) / (2π/z_p) and
/// γ_rs = φ_r − φ_s. Tolerance 1e-7 mesh periods: the bisections run to 1e-13 m on 1e-2 m
/// geometry, and the phase is a ratio of such lengths to a base pitch of a few millimetres.

#include "geardyn/system/planet_phasing.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <string>

#include "geardyn/geometry/gear_pair.h"
#include "geardyn/geometry/internal_gear_pair.h"
#include "geardyn/geometry/involute.h"
#include "geardyn/stiffness/mesh_stiffness.h"

namespace geardyn {
namespace {

constexpr double kPi = std::numbers::pi;
using V2 = Eigen::Vector2d;

GearSpec gearOf(int teeth, double shift, double helix = 0.0) {
  GearSpec g;
  g.teeth = teeth;
  g.normal_module = 2e-3;
  g.normal_pressure_angle = 20.0 * kPi / 180.0;
  g.helix_angle = helix;
  g.face_width = 0.02;
  g.profile_shift = shift;
  return g;
}

/// The planet's flanks in polar form, centre at the origin, tooth 0's centre line at angle θ.
struct PlanetFlankPolar {
  double rb, half_ref;  ///< base radius; s_t/(2r) + inv α_t [rad]
  int z;
  /// θ*(X) mod pitch for the flank facing `side` (+1 counter-clockwise, −1 clockwise).
  double turnAngle(const V2& x, int side) const {
    const double rho = x.norm();
    const double half = half_ref - involute(std::acos(rb / rho));
    const double pitch = 2.0 * kPi / z;
    const double a = std::atan2(x.y(), x.x()) - side * half;
    return a - pitch * std::floor(a / pitch);
  }
  /// Unit normal of the flank through x (finite differences along the flank curve).
  V2 flankNormal(const V2& x, int side) const {
    const double rho = x.norm(), h = 1e-6 * rho;
    const double theta =
        std::atan2(x.y(), x.x()) - side * (half_ref - involute(std::acos(rb / rho)));
    auto point = [&](double r) {
      const double ang = theta + side * (half_ref - involute(std::acos(rb / r)));
      return V2(r * std::cos(ang), r * std::sin(ang));
    };
    const V2 t = (point(rho + h) - point(rho - h)).normalized();
    return V2(-t.y(), t.x());
  }
};

/// Interval of s where |P + s d − c| <= r (empty: lo > hi).
std::pair<double, double> disk(const V2& p, const V2& d, const V2& c, double r) {
  const V2 w = p - c;
  const double b = w.dot(d), q = w.squaredNorm() - r * r, disc = b * b - q;
  if (disc < 0) return {1, -1};
  return {-b - std::sqrt(disc), -b + std::sqrt(disc)};
}

struct Mesh {
  V2 point, dir;  ///< line of action through the pitch point, unit direction
  double lo, hi;  ///< path of contact (s along dir)
};

/// The line through `pitch` at ±α from the common tangent along which the flank normal lies.
V2 lineDirection(const PlanetFlankPolar& p, const V2& pitch, double alpha, int side) {
  const V2 radial = pitch.normalized(), tangent(-radial.y(), radial.x());
  V2 best;
  double alignment = -1;
  for (int sign : {-1, 1}) {
    const V2 d = std::cos(alpha) * tangent + sign * std::sin(alpha) * radial;
    const double a = std::abs(p.flankNormal(pitch, side).dot(d));
    if (a > alignment) alignment = a, best = d;
  }
  EXPECT_NEAR(alignment, 1.0, 1e-7) << "the flank normal at the pitch point is the line of action";
  return best;
}

double entryAngle(const PlanetFlankPolar& p, const Mesh& m, int side, int sigma) {
  // Flanks move towards +dir when θ* grows along dir for a turn in the sense σ.
  const double mid = 0.5 * (m.lo + m.hi), ds = 1e-6;
  const double pitch = 2.0 * kPi / p.z;
  double dtheta =
      p.turnAngle(m.point + (mid + ds) * m.dir, side) - p.turnAngle(m.point + mid * m.dir, side);
  dtheta -= pitch * std::round(dtheta / pitch);
  // A flank at s at angle θ* is at s + ds at θ* + dθ: it moves to +dir if σ dθ > 0.
  const double entry = sigma * dtheta > 0 ? m.lo : m.hi;
  return p.turnAngle(m.point + entry * m.dir, side);
}

double bruteForceGamma(const GearSpec& sun, const GearSpec& planet, const GearSpec& ring,
                       int rotation, int sun_flank) {
  GearPairSpec spec;
  spec.pinion = sun, spec.gear = planet;
  const GearPair sp = makeGearPair(spec, "sun", "planet", "pair");
  const double a = sp.centreDistance();
  const InternalGearPair rp(planet, ring, a, "ring");
  const double mt = planet.normal_module / std::cos(planet.helix_angle);
  const double r = planet.teeth * mt / 2.0, at = sp.transversePressureAngle();
  const double st =
      mt * (kPi / 2 + 2 * planet.profile_shift * std::tan(planet.normal_pressure_angle));
  const PlanetFlankPolar p{sp.gear().base_radius, st / (2 * r) + involute(at), planet.teeth};
  const V2 centre_sun(0.0, -a);  // the sun and the ring share the stage axis
  // Sun mesh: pitch point towards the sun at r_wp; flank `sun_flank`; path inside both tips.
  Mesh ms;
  ms.point = V2(0.0, -sp.gear().operating_pitch_radius);
  ms.dir = lineDirection(p, ms.point, sp.operatingPressureAngle(), sun_flank);
  const auto dp = disk(ms.point, ms.dir, V2::Zero(), sp.gear().tip_radius);
  const auto ds = disk(ms.point, ms.dir, centre_sun, sp.pinion().tip_radius);
  ms.lo = std::max(dp.first, ds.first), ms.hi = std::min(dp.second, ds.second);
  // Ring mesh: pitch point away from the sun; the other flank; inside the planet tip circle and
  // outside the ring's inner tip circle, on the part that holds the pitch point (s = 0).
  Mesh mr;
  const double rwp = rp.pinionBaseRadius() / std::cos(rp.operatingPressureAngle());
  mr.point = V2(0.0, rwp);
  mr.dir = lineDirection(p, mr.point, rp.operatingPressureAngle(), -sun_flank);
  const auto rpl = disk(mr.point, mr.dir, V2::Zero(), rp.pinionTipRadius());
  const auto rr = disk(mr.point, mr.dir, centre_sun, rp.ringTipRadius());
  // Outside the ring tip disk: s <= rr.first or s >= rr.second; the pitch point (0) is outside.
  if (rr.second < 0) {
    mr.lo = std::max(rpl.first, rr.second), mr.hi = rpl.second;
  } else {
    mr.lo = rpl.first, mr.hi = std::min(rpl.second, rr.first);
  }
  EXPECT_LT(ms.lo, 0.0);
  EXPECT_GT(ms.hi, 0.0);
  EXPECT_LT(mr.lo, 0.0);
  EXPECT_GT(mr.hi, 0.0);
  const double pitch = 2.0 * kPi / planet.teeth;
  const double ts = entryAngle(p, ms, sun_flank, rotation);
  const double tr = entryAngle(p, mr, -sun_flank, rotation);
  return wrapPhase(rotation * (ts - tr) / pitch);
}

double phaseDistance(double a, double b) {
  const double d = std::abs(wrapPhase(a - b));
  return std::min(d, 1.0 - d);
}

struct Case {
  int zs, zp, zr;
  double xs, xp, xr, helix;
};

class RingSunPhase : public ::testing::TestWithParam<Case> {};

TEST_P(RingSunPhase, MatchesBruteForceInvoluteConstructionForAllFlanksAndSenses) {
  const Case c = GetParam();
  const GearSpec sun = gearOf(c.zs, c.xs, c.helix), planet = gearOf(c.zp, c.xp, -c.helix),
                 ring = gearOf(c.zr, c.xr, -c.helix);
  GearPairSpec spec;
  spec.pinion = sun, spec.gear = planet;
  const double a = makeGearPair(spec, "sun", "planet", "pair").centreDistance();
  const PlanetMeshGeometry g = planetMeshGeometry(sun, planet, ring, a, "planetary.stage");
  for (int rotation : {1, -1}) {
    for (int flank : {1, -1}) {
      const double gamma = ringSunMeshPhase(g, {rotation, flank});
      const double reference = bruteForceGamma(sun, planet, ring, rotation, flank);
      EXPECT_LT(phaseDistance(gamma, reference), 1e-7)
          << "rotation " << rotation << " flank " << flank << ": " << gamma << " vs " << reference;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Stages, RingSunPhase,
    ::testing::Values(Case{21, 30, 81, 0.0, 0.0, 0.0, 0.0},    // standard, z_p even
                      Case{20, 31, 82, 0.0, 0.0, 0.0, 0.0},    // z_p odd
                      Case{17, 22, 61, 0.3, -0.1, -0.2, 0.0},  // FVA-like counts, shifted
                      Case{23, 25, 73, 0.2, 0.1, 0.0, 15.0 * kPi / 180.0}),  // helical
    [](const ::testing::TestParamInfo<Case>& info) {
      const Case& c = info.param;
      return "z" + std::to_string(c.zs) + "_" + std::to_string(c.zp) + "_" + std::to_string(c.zr) +
             (c.xs != 0.0 || c.xp != 0.0 ? "_shifted" : "") + (c.helix != 0.0 ? "_helical" : "");
    });

TEST(RingSunPhase, TurningBackIsTheMirrorImage) {
  // Reversing both the rotation and the loaded flank is the mirror image: the same γ_rs.
  GearPairSpec spec;
  spec.pinion = gearOf(21, 0.1), spec.gear = gearOf(30, 0.0);
  const double a = makeGearPair(spec, "sun", "planet", "pair").centreDistance();
  const PlanetMeshGeometry g =
      planetMeshGeometry(spec.pinion, spec.gear, gearOf(81, 0.0), a, "planetary.stage");
  EXPECT_DOUBLE_EQ(ringSunMeshPhase(g, {1, 1}), ringSunMeshPhase(g, {-1, -1}));
  EXPECT_DOUBLE_EQ(ringSunMeshPhase(g, {1, -1}), ringSunMeshPhase(g, {-1, 1}));
}

}  // namespace
}  // namespace geardyn
