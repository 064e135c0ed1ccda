#pragma once
/// \file
/// One involute cylindrical gear (spur or helical), cut by a standard basic rack: the data that
/// define it. Everything derived from it lives in GearPair, since the operating geometry depends
/// on the mating gear and the centre distance.

#include <string>
#include <vector>

namespace geardyn {

/// The defining data of one external involute gear. SI units; angles in radians.
/// Defaults are those of the standard basic rack (ISO 53 profile A) and of steel.
struct GearSpec {
  int teeth = 0;                       ///< number of teeth z [-], >= 3
  double normal_module = 0.0;          ///< normal module m_n [m]
  double normal_pressure_angle = 0.0;  ///< normal pressure angle α_n [rad], in (0, 45°)
  double helix_angle = 0.0;    ///< helix angle β at the reference circle [rad]; > 0 right hand
  double face_width = 0.0;     ///< face width b [m]
  double profile_shift = 0.0;  ///< profile shift coefficient x [-]
  double addendum_coefficient = 1.0;      ///< h_a* [-]: addendum h_a = h_a* m_n (before shift)
  double dedendum_coefficient = 1.25;     ///< h_f* = h_a* + c* [-]: dedendum h_f = h_f* m_n
  double root_fillet_coefficient = 0.38;  ///< ρ_fP* [-]: tip radius of the generating rack / m_n
  double tip_radius_modification = 0.0;  ///< Δr_a [m] added to the tip radius (< 0: tip shortening)
  double bore_diameter = 0.0;            ///< bore diameter of the gear body [m]
  double youngs_modulus = 206e9;         ///< Young's modulus E [Pa]
  double poisson_ratio = 0.3;            ///< Poisson's ratio ν [-]
  double density = 7850.0;               ///< density ρ [kg/m³]

  /// Depth below the reference line at which the straight flank of the generating rack (basic
  /// rack counterpart, ISO 53) ends and its tip rounding begins:
  /// h_FfP = (h_f* − ρ_fP* (1 − sin α_n)) m_n [m]; 1.0 m_n for the standard rack (1.25, 0.38).
  double rackStraightFlankDepth() const;

  /// Checks every field against its allowed range and throws InputError naming
  /// `<name>.<config key>` (e.g. "pinion.teeth"; just the key when name is empty), the value
  /// and the range.
  void validate(const std::string& name) const;
};

/// Mass properties of a gear body: a solid disc of the reference diameter minus the bore (the
/// teeth above and the tooth spaces below the reference circle roughly cancel).
struct GearBodyMass {
  double mass = 0.0;               ///< [kg]
  double polar_inertia = 0.0;      ///< about the axis [kg m²]
  double diametral_inertia = 0.0;  ///< about a diameter through the centre [kg m²]
};
/// For the reference radius r = z m_n / (2 cos β) of `gear`.
GearBodyMass gearBodyMass(const GearSpec& gear);

/// Values outside the usual engineering ranges, where a unit mix-up (a module of 3 meant as
/// 3 mm is 3 m in SI) is likelier than such a gear: a note per value, naming the key
/// (`name`.module, `name`.face_width), the value in metres and the usual range (module 0.1 mm
/// to 100 mm, face width 1 mm to 2 m). Warnings, not errors.
std::vector<std::string> plausibilityNotes(const GearSpec& gear, const std::string& name);

/// Speeds above this are flagged as implausible [rpm]: rad/s or Hz given as rpm is likelier.
inline constexpr double kPlausibleMaxRpm = 200000.0;
/// The note on `key` = `rpm` when it is above kPlausibleMaxRpm (empty otherwise).
std::string speedPlausibilityNote(double rpm, const std::string& key);

}  // namespace geardyn
