#pragma once
/// \file
/// An external involute gear pair (spur or helical) in mesh: reference, base, tip and root
/// geometry, operating centre distance and pressure angle, path of contact, contact ratios,
/// backlash, checks of validity (undercut, tip pointing, interference, contact ratio) and the
/// mass properties of both gear bodies.
///
/// Formulas: ISO 21771:2007 (cylindrical involute gears) and ISO 1328 nomenclature; validated
/// against the Rao (2023) thesis, Table 5.1, and closed-form cases in tests/geometry.

#include <optional>
#include <string>
#include <vector>

#include "geardyn/error.h"
#include "geardyn/geometry/gear.h"

namespace geardyn {

/// Which member of the pair drives. It fixes where the path of contact starts: at the tip of
/// the driven gear.
enum class Driver { kPinion, kGear };

/// The defining data of a gear pair: two gears and how they are mounted.
struct GearPairSpec {
  GearSpec pinion;  ///< member 1 (conventionally the smaller)
  GearSpec gear;    ///< member 2
  /// Operating centre distance a_w [m]; when absent, the zero-backlash (tight mesh) distance of
  /// the profile shifts is used.
  std::optional<double> centre_distance;
  /// Pinion speed [rpm]; when absent the mesh frequency is not defined.
  std::optional<double> pinion_speed_rpm;
  Driver driver = Driver::kPinion;
};

/// Geometry of one member of a pair, derived in the operating condition. Radii in [m].
struct GearGeometry {
  double transverse_module = 0.0;       ///< m_t = m_n / cos β [m]
  double pitch_radius = 0.0;            ///< reference radius r = z m_t / 2 [m]
  double base_radius = 0.0;             ///< r_b = r cos α_t [m]
  double tip_radius = 0.0;              ///< r_a = r + (h_a* + x) m_n + Δr_a [m]
  double root_radius = 0.0;             ///< r_f = r − (h_f* − x) m_n [m]
  double operating_pitch_radius = 0.0;  ///< r_w = r_b / cos α_wt [m]
  /// Start of the generated involute, r_Ff [m]; with undercut where the fillet cuts it back
  /// (trueFormRadius, geometry/rack_generation.h). Contact starts no lower.
  double form_radius = 0.0;
  double active_profile_start_radius = 0.0;  ///< start of active profile (SAP), r_Nf [m]
  double tip_thickness_normal = 0.0;         ///< normal tooth thickness at the tip circle s_an [m]
  double tip_clearance = 0.0;                ///< a_w − r_a − r_f(mate) [m]
  bool undercut = false;                     ///< the basic rack cuts below the interference point
  double mass = 0.0;                         ///< body mass [kg]
  double polar_inertia = 0.0;                ///< about the axis of rotation [kg m²]
  double diametral_inertia = 0.0;            ///< about a diameter through the centre [kg m²]
};

/// An external involute gear pair in mesh. Immutable; validated once on construction.
/// Throws InputError (naming the configuration key) when the pair cannot exist or cannot mesh
/// continuously; conditions a designer should know about but that do not prevent meshing are
/// collected in warnings().
class GearPair {
 public:
  explicit GearPair(const GearPairSpec& spec);

  const GearPairSpec& spec() const noexcept { return spec_; }
  const GearGeometry& pinion() const noexcept { return pinion_; }
  const GearGeometry& gear() const noexcept { return gear_; }

  double gearRatio() const noexcept { return gear_ratio_; }             ///< u = z₂ / z₁ [-]
  double transversePressureAngle() const noexcept { return alpha_t_; }  ///< α_t [rad]
  double baseHelixAngle() const noexcept { return beta_b_; }            ///< β_b [rad], ≥ 0
  double basePitchTransverse() const noexcept { return p_bt_; }  ///< p_bt = π m_t cos α_t [m]
  double basePitchNormal() const noexcept { return p_bn_; }      ///< p_bn = π m_n cos α_n [m]
  double referenceCentreDistance() const noexcept { return a_ref_; }    ///< r₁ + r₂ [m]
  double tightMeshCentreDistance() const noexcept { return a_tight_; }  ///< zero backlash [m]
  double centreDistance() const noexcept { return a_w_; }               ///< operating a_w [m]
  double operatingPressureAngle() const noexcept { return alpha_wt_; }  ///< α_wt [rad]
  /// Circumferential backlash on the operating pitch circle, j_wt [m] (nominal teeth, no
  /// thickness tolerances): 0 at the tight-mesh centre distance.
  double backlashCircumferential() const noexcept { return j_wt_; }
  /// Normal backlash j_bn = j_wt cos α_wt cos β_b [m].
  double backlashNormal() const noexcept { return j_bn_; }
  /// Length T₁T₂ of the line of action between the base-circle tangent points [m].
  double lineOfActionLength() const noexcept { return line_of_action_; }
  /// Start and end of the path of contact, measured along the line of action from T₁ (the
  /// pinion's tangent point) [m]; the path runs from the driven gear's tip to the driver's tip.
  double pathOfContactStart() const noexcept { return path_start_; }
  double pathOfContactEnd() const noexcept { return path_end_; }
  double pathOfContactLength() const noexcept { return path_length_; }   ///< g_α [m]
  double contactRatioTransverse() const noexcept { return eps_alpha_; }  ///< ε_α = g_α / p_bt
  double overlapRatio() const noexcept { return eps_beta_; }  ///< ε_β = b sin|β| / (π m_n)
  double contactRatioTotal() const noexcept { return eps_alpha_ + eps_beta_; }  ///< ε_γ
  double effectiveFaceWidth() const noexcept { return face_width_; }  ///< common width [m]
  /// Mesh frequency f_m = z₁ n₁ / 60 [Hz]; absent when no speed was given.
  std::optional<double> meshFrequency() const noexcept { return mesh_frequency_; }

  /// Design conditions that do not prevent meshing (undercut, thin tips, contact below the
  /// form circle, ε_α < 1 with ε_γ ≥ 1), each a complete sentence.
  const std::vector<std::string>& warnings() const noexcept { return warnings_; }

 private:
  GearPairSpec spec_;
  GearGeometry pinion_;
  GearGeometry gear_;
  double gear_ratio_ = 0, alpha_t_ = 0, beta_b_ = 0, p_bt_ = 0, p_bn_ = 0;
  double a_ref_ = 0, a_tight_ = 0, a_w_ = 0, alpha_wt_ = 0, j_wt_ = 0, j_bn_ = 0;
  double line_of_action_ = 0, path_start_ = 0, path_end_ = 0, path_length_ = 0;
  double eps_alpha_ = 0, eps_beta_ = 0, face_width_ = 0;
  std::optional<double> mesh_frequency_;
  std::vector<std::string> warnings_;
};

/// The configuration paths of a pair's two members and of the pair itself, for messages:
/// "gears.z19", "gears.z71", "meshes.stage1" in a gearbox description.
struct PairKeyNames {
  std::string pinion = "pinion";
  std::string gear = "gear";
  std::string pair = "pair";
};

/// `error` with the pair's own paths "pinion.*", "gear.*" and "pair.*" — in its key and in
/// its text ("must equal pinion.module", "set gear.bore_diameter") — renamed to `names`'.
/// A path that continues another ("potential_energy.gear_hub_radius") is left alone.
InputError renamedForPair(const InputError& error, const PairKeyNames& names);

/// A GearPair whose validation messages name the caller's keys (renamedForPair).
GearPair makeGearPair(const GearPairSpec& spec, const std::string& pinion_key,
                      const std::string& gear_key, const std::string& pair_key);

/// "pinion" or "gear"; parseDriver throws InputError(key) for anything else.
std::string toString(Driver driver);
Driver parseDriver(const std::string& text, const std::string& key = "pair.driver");

}  // namespace geardyn
