#pragma once
/// \file
/// Flank modifications and errors of a gear pair as initial separations of the tooth surfaces
/// along the line of action (Harris 1958; ISO 21771): tip and root relief (linear or
/// parabolic, amount and length along the line of action), profile slope errors and per-tooth
/// pitch errors; across the face (the lead, ISO 21771 §8; ISO 1328-1 helix deviations): lead
/// crowning, helix slope f_Hβ, end relief and a measured lead error table; and the pair's mesh
/// misalignment f_ma (ISO 6336-1 §7.5; system/mesh_misalignment.h). A positive separation means
/// material missing: the flanks meet that much later than perfect involutes would. The face
/// position z runs from −b/2 to b/2 (along +x of a train's mesh).

#include <vector>

namespace geardyn {

class PotentialEnergyMeshStiffness;

enum class ReliefShape { kLinear, kParabolic };

/// A relief at one end of a profile: `amount` at the tip (or the start of active root) falling
/// to 0 over `length` along the line of action [m].
struct Relief {
  double amount = 0.0;  ///< C [m]
  double length = 0.0;  ///< L along the line of action [m]
  ReliefShape shape = ReliefShape::kLinear;

  /// The relief at distance d from the profile's end (0 at d >= L): C (1 − d/L)^{1 or 2} [m].
  double at(double distance) const;
  void validate(const char* key) const;
};

/// The modifications and errors of one gear's flanks.
struct ToothModification {
  Relief tip;
  Relief root;
  double crowning = 0.0;  ///< C_β: separation C_β (2z/b)² at face position z from the middle [m]
  /// Helix slope deviation f_Hβ: a separation varying linearly by f_Hβ across the face,
  /// f_Hβ z/b (positive: material missing towards +z) [m].
  double helix_slope = 0.0;
  /// End relief C_I over a length L_I from each face end (Relief::at of the distance from the
  /// end, linear or parabolic) [m].
  Relief end_relief;
  /// Measured lead errors: separations [m] at face positions z [m] in [−b/2, b/2] (ascending),
  /// linearly interpolated, constant beyond the ends. Empty: none.
  std::vector<double> lead_error_positions, lead_errors;
  /// Profile slope error f_Hα: a separation varying linearly by f_Hα over the active profile,
  /// positive towards the tip [m].
  double profile_slope_error = 0.0;
  /// Pitch errors of the teeth (index = tooth number, cyclic): a constant separation of every
  /// contact of that tooth [m]. Empty: none.
  std::vector<double> pitch_errors;

  void validate(const char* key) const;
};

struct PairModifications {
  ToothModification pinion;
  ToothModification gear;
  /// Mesh misalignment f_ma [m]: the flanks approach by f_ma more at z = b/2 than at −b/2, a
  /// separation −f_ma z/b (system/mesh_misalignment.h's sign).
  double misalignment = 0.0;

  /// Separation [m] of the flanks at position s along the line of action (from T₁), face
  /// position z ∈ [−b/2, b/2], for the pinion tooth `pinion_tooth` and gear tooth `gear_tooth`,
  /// on a path of contact [s_begin, s_end] of face width b. The pinion's tip is at s_end and its
  /// root at s_begin; the gear's the reverse.
  double separation(double s, double z, int pinion_tooth, int gear_tooth, double s_begin,
                    double s_end, double face_width) const;
  bool none() const;
  /// The lead part of separation() alone (crowning, helix slope, end relief, lead errors,
  /// misalignment) at face position z of a face width b [m].
  double leadSeparation(double z, double face_width) const;
};

/// Tip relief of both gears designed for a load (Harris): amount = the deflection of one tooth
/// pair carrying `design_load` in the middle of the single-contact zone, length = the
/// two-pair zone (ε_α − 1) p_b ("long") or half of it ("short"); spur or transverse section.
PairModifications designedTipRelief(const PotentialEnergyMeshStiffness& stiffness,
                                    double design_load, bool long_relief, ReliefShape shape);

}  // namespace geardyn
