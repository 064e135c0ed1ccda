#pragma once
/// \file
/// ISO 6336-1:2006 method B tooth stiffness: single stiffness c′ and mesh stiffness c_γα of a
/// spur or helical pair (§9), as an independent cross-check of the potential-energy model.
/// Formulas: shared/reference/mesh_stiffness.md, "ISO 6336-1 method B".

#include <optional>

#include "geardyn/geometry/gear_pair.h"
#include "geardyn/geometry/internal_gear_pair.h"
#include "geardyn/stiffness/mesh_stiffness.h"

namespace geardyn {

/// The data of ISO 6336-1 §9.3 beyond the gear geometry.
struct Iso6336Options {
  double c_m = 0.8;  ///< theoretical correction factor C_M (0.8 for solid discs)
  /// Rim and web (ISO eq. 78): web width b_s [m] and rim thickness s_R [m]; C_R = 1 (solid
  /// blank) when absent.
  std::optional<double> web_width;
  std::optional<double> rim_thickness;
  /// Scale c′ by E/E_steel (ISO 6336-1 §9.3.1 for materials other than steel, E = 2E₁E₂/(E₁+E₂),
  /// E_steel = 206 GPa). Off reproduces ISO's steel values whatever E is given.
  bool material_factor = true;
};

/// All the intermediate values, in ISO's units: stiffnesses in N/(mm·µm), flexibility in
/// mm·µm/N.
struct Iso6336Stiffness {
  double zn1 = 0, zn2 = 0;           ///< virtual numbers of teeth z / (cos² β_b cos β)
  double q_prime = 0;                ///< minimum flexibility q′ [mm·µm/N]
  double c_prime_th = 0;             ///< theoretical single stiffness 1/q′
  double c_m = 0, c_r = 0, c_b = 0;  ///< correction, blank and basic-rack factors
  double material_factor = 0;        ///< E / E_steel, E = 2E₁E₂/(E₁+E₂), E_steel = 206 GPa
  double c_prime = 0;        ///< single stiffness c′ = c′_th C_M C_R C_B cos β (× E/E_st)
  double c_gamma_alpha = 0;  ///< mesh stiffness c_γα = c′ (0.75 ε_α + 0.25)
  double c_gamma_beta = 0;   ///< c_γβ = 0.85 c_γα
  double face_width = 0;     ///< b [m]
  /// Mean mesh stiffness of the pair c_γα · b [N/m].
  double meshStiffness() const { return c_gamma_alpha * face_width * 1e3 * 1e6; }
};

/// ISO values for explicit data: teeth, normal profile shifts, helix and base helix angles
/// [rad], normal pressure angle of the basic rack [rad], its dedendum h_fP/m_n [-], the normal
/// module [m], the face width [m], the transverse contact ratio, Young's moduli [Pa].
/// z2 may be infinite (a rack, or a ring gear: see the internal overload).
Iso6336Stiffness iso6336Stiffness(int z1, double z2, double x1, double x2, double helix_angle,
                                  double base_helix_angle, double pressure_angle,
                                  double dedendum_coefficient, double normal_module,
                                  double face_width, double contact_ratio_transverse,
                                  double youngs1, double youngs2,
                                  const Iso6336Options& options = {});

/// ISO values for a gear pair (its geometry, contact ratio and materials).
Iso6336Stiffness iso6336Stiffness(const GearPair& pair, const Iso6336Options& options = {});

/// ISO values for an internal pair: `pinion` (a planet) inside `ring`. Method B's fit of q′
/// (ISO 6336-1 §9.3.2) is written for external pairs; the ring's concave tooth is taken as a
/// rack tooth, z_n2 → ∞ (its x₂ terms C₆x₂ + C₉x₂² kept), a lower bound of its stiffness and
/// the form DIN 3990-1/ISO 6336-1 give for internal gears as we read them (the extract in
/// shared/reference/mesh_stiffness.md does not cover internal gears). ε_α and β_b are the
/// internal pair's; the face width is the narrower member's.
Iso6336Stiffness iso6336Stiffness(const InternalGearPair& pair, const GearSpec& pinion,
                                  const GearSpec& ring, const Iso6336Options& options = {});

}  // namespace geardyn
