#pragma once
/// \file
/// The ring-to-sun mesh phase of one planet, γ_rs: where the ring–planet mesh is in its cycle
/// when a new tooth pair enters the sun–planet mesh of the same planet. Together with the
/// planet-to-planet phases γ_sn, γ_rn (Parker & Lin 2004, J. Mech. Des. 126:365–370, eq. 1) it
/// fixes the phase of every mesh of a planetary stage. Derived from first principles in
/// docs/theory/gear_trains.md ("Ring-to-sun phase of one planet"): involute flanks as strings
/// unwound from the planet's base circle, the two lines of action, the planet's base tooth
/// thickness and the start of each path of contact.

#include <string>
#include <vector>

#include "geardyn/geometry/gear.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn {

/// The planet's rotation and loaded flanks, in the carrier frame (angles counter-clockwise about
/// the stage axis, seen from +x).
struct PlanetFlanks {
  /// Sense of the planet's rotation relative to the carrier: +1 counter-clockwise, −1 clockwise.
  int rotation = 1;
  /// +1 when the sun loads the planet's counter-clockwise-facing flank (the sun's force turns
  /// the planet clockwise), −1 for the clockwise-facing flank. The ring loads the other flank.
  int sun_flank = 1;
};

/// Geometry of one planet's two meshes, as used by the phase (transverse plane) [m, rad].
struct PlanetMeshGeometry {
  int planet_teeth = 0;
  double planet_base_radius = 0.0;     ///< r_bp [m]
  double planet_base_thickness = 0.0;  ///< transverse tooth thickness on the base circle s_bp [m]
  double base_pitch = 0.0;             ///< p_bt = 2π r_bp / z_p [m]
  double sun_pressure_angle = 0.0;     ///< operating α_ws of the sun–planet mesh [rad]
  double ring_pressure_angle = 0.0;    ///< operating α_wr of the ring–planet mesh [rad]
  /// Ends of each path of contact, as roll distances s from the planet's tangent point on that
  /// line of action [m]: s > 0 on the sun line, s < 0 on the ring line (flank + on the sun).
  double sun_path_min = 0.0, sun_path_max = 0.0;
  double ring_path_min = 0.0, ring_path_max = 0.0;
};

/// The geometry of a planet between `sun` and the internal `ring` at the sun–planet centre
/// distance `centre_distance` [m] (zero-backlash tooth thickness, ISO 21771). Throws InputError
/// (key `key`) when the gears cannot mesh there.
PlanetMeshGeometry planetMeshGeometry(const GearSpec& sun, const GearSpec& planet,
                                      const GearSpec& ring, double centre_distance,
                                      const std::string& key);

/// γ_rs in [0, 1) mesh periods: with φ = 0 the instant a new tooth pair enters a mesh at the
/// start of its path of contact (stiffness/mesh_stiffness.h), the ring–planet mesh phase is
/// φ_r = φ_s + γ_rs when φ_s is the sun–planet mesh phase of the same planet.
double ringSunMeshPhase(const PlanetMeshGeometry& geometry, const PlanetFlanks& flanks);

/// Adds γ_rs to the phase of every ring–planet mesh of planetary stage `stage`. Each planet's
/// loaded flanks come from its sun–planet mesh (the mesh force +F n_t acts on the planet, body b)
/// and its rotation from its speed relative to the carrier (`carrier_speed_ratio`, per unit input
/// speed; a positive input speed is assumed, as for every phase of the train).
void addRingSunPhases(std::vector<TrainMesh>& meshes, const std::vector<TrainBody>& bodies,
                      int stage, double carrier_speed_ratio, const PlanetMeshGeometry& geometry);

}  // namespace geardyn
