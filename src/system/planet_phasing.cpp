/// \file
/// γ_rs, the ring-to-sun mesh phase of one planet (derivation: docs/theory/gear_trains.md,
/// "Ring-to-sun phase of one planet").
///
/// An involute flank is the path of a string unwound from the base circle. A flank whose string
/// leaves the base circle at angle ξ (its origin) meets a line of action that touches the base
/// circle at angle τ at the roll distance s = r_b (ξ − τ) from the tangent point, measured along
/// e_θ(τ); counter-clockwise-facing flanks use the half line s > 0, clockwise-facing ones s < 0.
/// The planet's flank origins all turn at its speed ω_p, so on both of its lines of action the
/// contact points move at ds/dt = r_bp ω_p and repeat every base pitch p_b = 2π r_bp / z_p.
///
/// With the sun loading the counter-clockwise-facing flank (origins ξ⁺) and the ring the
/// clockwise-facing one (origins ξ⁻ = ξ⁺ − s_bp / r_bp, s_bp the base tooth thickness), the sun
/// line touches the planet's base circle at τ_s = φ_sun − α_ws and the ring line at
/// τ_r = φ_sun + π + α_wr (φ_sun: direction from the planet's centre to the sun's; the pitch
/// points lie at s = r_bp tan α_ws and s = −r_bp tan α_wr). A new pair enters a mesh when a flank
/// reaches the start of that mesh's path of contact s_A (its lower end for ω_p > 0, its upper end
/// for ω_p < 0), so with σ = sgn ω_p each mesh's phase is φ = frac(σ (s − s_A) / p_b) and
///
///   γ_rs = φ_r − φ_s = frac( σ [ −s_bp − r_bp (π + α_ws + α_wr) + s_A,s − s_A,r ] / p_b ).
///
/// The mirror image of the stage (the other flank pair) is the same stage turning the other way,
/// so γ_rs(−flank, σ) = γ_rs(+flank, −σ).
///
/// Parker & Lin (2004, eqs. 13–21 of the conference version DETC2003/PTG-48067) build the same
/// quantity from the same ingredients (the two paths of contact, the travel π − α_s − α_r around
/// the planet's base circle, and the base tooth thickness t_b); their travel runs between the
/// other pair of tangent points, i.e. the mirror-image flank convention.

#include "geardyn/system/planet_phasing.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/geometry/gear_pair.h"
#include "geardyn/geometry/internal_gear_pair.h"
#include "geardyn/geometry/involute.h"
#include "geardyn/stiffness/mesh_stiffness.h"

namespace geardyn {

PlanetMeshGeometry planetMeshGeometry(const GearSpec& sun, const GearSpec& planet,
                                      const GearSpec& ring, double centre_distance,
                                      const std::string& key) {
  GearPairSpec spec;
  spec.pinion = sun;
  spec.gear = planet;
  spec.centre_distance = centre_distance;
  const GearPair sun_pair = makeGearPair(spec, key + ".sun", key + ".planet", key);
  const InternalGearPair ring_pair(planet, ring, centre_distance, key);

  PlanetMeshGeometry g;
  g.planet_teeth = planet.teeth;
  const double rbp = sun_pair.gear().base_radius;
  g.planet_base_radius = rbp;
  g.base_pitch = 2.0 * std::numbers::pi * rbp / planet.teeth;
  // Zero-backlash transverse thickness on the reference circle s_t = m_t (π/2 + 2 x tan α_n)
  // (ISO 21771), carried to the base circle: s_b = r_b (s_t / r + 2 inv α_t).
  const double alpha_t = sun_pair.transversePressureAngle();
  const double mt = planet.normal_module / std::cos(planet.helix_angle);
  const double st = mt * (std::numbers::pi / 2.0 +
                          2.0 * planet.profile_shift * std::tan(planet.normal_pressure_angle));
  const double r = planet.teeth * mt / 2.0;
  g.planet_base_thickness = rbp * (st / r + 2.0 * involute(alpha_t));
  g.sun_pressure_angle = sun_pair.operatingPressureAngle();
  g.ring_pressure_angle = ring_pair.operatingPressureAngle();

  // Sun line: GearPair measures the path from the sun's tangent point T₁; the planet's tangent
  // point is the other end of T₁T₂.
  const double length = sun_pair.lineOfActionLength();
  const double x0 = std::min(sun_pair.pathOfContactStart(), sun_pair.pathOfContactEnd());
  const double x1 = std::max(sun_pair.pathOfContactStart(), sun_pair.pathOfContactEnd());
  g.sun_path_min = length - x1;
  g.sun_path_max = length - x0;
  // Ring line (s < 0): the planet's tip at s = −√(r_ap² − r_bp²); the ring's tangent point lies
  // at s = (r_br − r_bp) tan α_wr, and its (inner) tip circle √(r_ar² − r_br²) before it.
  const double rap = ring_pair.pinionTipRadius(), rbr = ring_pair.ringBaseRadius();
  const double rar = ring_pair.ringTipRadius();
  g.ring_path_min = -std::sqrt(rap * rap - rbp * rbp);
  g.ring_path_max = std::min(
      (rbr - rbp) * std::tan(g.ring_pressure_angle) - std::sqrt(rar * rar - rbr * rbr), 0.0);
  if (!(g.ring_path_max > g.ring_path_min) || !(g.sun_path_max > g.sun_path_min)) {
    throw InputError(key, "", "planet meshes with a path of contact on both the sun and the ring");
  }
  return g;
}

double ringSunMeshPhase(const PlanetMeshGeometry& g, const PlanetFlanks& flanks) {
  const int sigma = (flanks.rotation >= 0 ? 1 : -1) * (flanks.sun_flank >= 0 ? 1 : -1);
  const double start_sun = sigma > 0 ? g.sun_path_min : g.sun_path_max;
  const double start_ring = sigma > 0 ? g.ring_path_min : g.ring_path_max;
  const double travel =
      -g.planet_base_thickness -
      g.planet_base_radius * (std::numbers::pi + g.sun_pressure_angle + g.ring_pressure_angle) +
      start_sun - start_ring;
  return wrapPhase(sigma * travel / g.base_pitch);
}

void addRingSunPhases(std::vector<TrainMesh>& meshes, const std::vector<TrainBody>& bodies,
                      int stage, double carrier_speed_ratio, const PlanetMeshGeometry& geometry) {
  for (const TrainMesh& sun : meshes) {
    if (sun.kind != TrainMeshKind::kSunPlanet || sun.stage != stage) continue;
    const TrainBody& planet = bodies[sun.body_b];
    const Eigen::Vector2d r = sun.pitch_point - planet.centre;
    const double torque = r.x() * sun.normal.y() - r.y() * sun.normal.x();  // of +n_t, per N
    const PlanetFlanks flanks{planet.speed_ratio - carrier_speed_ratio >= 0.0 ? 1 : -1,
                              torque < 0.0 ? 1 : -1};
    const double gamma = ringSunMeshPhase(geometry, flanks);
    for (TrainMesh& ring : meshes) {
      if (ring.kind == TrainMeshKind::kRingPlanet && ring.stage == stage &&
          ring.planet == sun.planet) {
        // Rounded to 1e-12 like the planet-to-planet phases, so whole periods read 0.
        const double p = wrapPhase(std::round((ring.phase + gamma) * 1e12) / 1e12);
        ring.phase = p >= 1.0 ? 0.0 : p;
      }
    }
  }
}

}  // namespace geardyn
