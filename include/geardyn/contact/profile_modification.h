#pragma once
/// \file
/// Flank modifications and errors of a gear pair as initial separations of the tooth surfaces
/// along the line of action (Harris 1958; ISO 21771): tip and root relief (linear or
/// parabolic, amount and length along the line of action), lead crowning across the face,
/// profile slope errors and per-tooth pitch errors. A positive separation means material
/// missing: the flanks meet that much later than perfect involutes would.

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

  /// Separation [m] of the flanks at position s along the line of action (from T₁), face
  /// position z ∈ [−b/2, b/2], for the pinion tooth `pinion_tooth` and gear tooth `gear_tooth`,
  /// on a path of contact [s_begin, s_end] of face width b. The pinion's tip is at s_end and its
  /// root at s_begin; the gear's the reverse.
  double separation(double s, double z, int pinion_tooth, int gear_tooth, double s_begin,
                    double s_end, double face_width) const;
  bool none() const;
};

/// Tip relief of both gears designed for a load (Harris): amount = the deflection of one tooth
/// pair carrying `design_load` in the middle of the single-contact zone, length = the
/// two-pair zone (ε_α − 1) p_b ("long") or half of it ("short"); spur or transverse section.
PairModifications designedTipRelief(const PotentialEnergyMeshStiffness& stiffness,
                                    double design_load, bool long_relief, ReliefShape shape);

}  // namespace geardyn
