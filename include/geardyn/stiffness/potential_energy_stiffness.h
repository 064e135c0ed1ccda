#pragma once
/// \file
/// Time-varying mesh stiffness from the potential-energy method (Visnadi & de Castro 2021
/// §2.3, eq. 9; Ma et al. 2014): each tooth pair in contact is a series of the two teeth's
/// bending, shear, axial and fillet-foundation compliances and the Hertzian contact; the pairs
/// in contact add up, placed by exact roll-angle kinematics on the line of action. Helical
/// gears: the face is a stack of thin spur slices staggered along the line of action by the
/// base helix angle (Wan et al. 2015), either as n slices or in the limit n → ∞ (an exact
/// integral over the face).
///
/// Preparation tabulates the pair stiffness per unit face width k′(s) along the path of contact
/// once (cubic Hermite on a uniform grid) with its running integral; evaluating k(φ) then costs
/// a few table look-ups per pair in contact.

#include <optional>
#include <string>
#include <vector>

#include "geardyn/geometry/gear_pair.h"
#include "geardyn/stiffness/mesh_stiffness.h"
#include "geardyn/stiffness/tooth_beam.h"

namespace geardyn {

/// The conventions of the potential-energy model. The defaults reproduce Ma et al. (2014) with
/// Sainsot's foundation: a straight root segment, u_f along the force line, the bore as hub.
struct PotentialEnergyOptions {
  ToothRoot root = ToothRoot::kStraight;
  FoundationArm foundation_arm = FoundationArm::kForceLine;
  bool foundation = true;                   ///< include the fillet-foundation compliance
  std::optional<double> pinion_hub_radius;  ///< r_int [m]; default: pinion bore / 2
  std::optional<double> gear_hub_radius;    ///< r_int [m]; default: gear bore / 2
  int slices = 0;                    ///< helical: face slices; 0 = exact integral over the face
  bool helical_cos2_beta_b = false;  ///< multiply helical stiffness by cos² β_b (normal direction)
  int table_points = 257;            ///< nodes of k′(s) along the path of contact (>= 16)

  void validate() const;
};

class PotentialEnergyMeshStiffness final : public MeshStiffness {
 public:
  PotentialEnergyMeshStiffness(const GearPair& pair, const PotentialEnergyOptions& options = {});

  std::string model() const override { return "potential_energy"; }
  double stiffness(double phase) const override;
  std::vector<double> discontinuities() const override { return breaks_; }
  int pairCount() const override { return pair_slots_; }
  double pairStiffness(double phase, int pair) const override;
  double contactRatio() const override { return contact_ratio_; }

  /// Stiffness of one tooth pair per unit face width at position s along the line of action
  /// from T₁ (0 outside the path of contact) [N/m/m]: the interpolated table.
  double pairStiffnessPerWidth(double s) const;
  /// The same, computed directly (no table): for tests and the table itself.
  double pairStiffnessPerWidthExact(double s) const;
  /// Compliances of the pinion's and the gear's tooth at s, per unit width [m/N·m].
  ToothCompliance pinionCompliance(double s) const;
  ToothCompliance gearCompliance(double s) const;
  double hertzPerWidth() const noexcept { return hertz_per_width_; }

  /// Path of contact on the line of action from T₁ [m].
  double contactStart() const noexcept { return s_begin_; }
  double contactEnd() const noexcept { return s_end_; }
  /// The kinematics the loaded contact analysis shares (contact/loaded_contact.h): the
  /// transverse base pitch [m], the effective face width [m], the stagger b tan β_b of a helical
  /// contact line along the line of action [m], the scale of helical slices (cos² β_b or 1), and
  /// whether the pinion drives (pairs run from contactStart to contactEnd).
  double basePitch() const noexcept { return base_pitch_; }
  double faceWidth() const noexcept { return face_width_; }
  double stagger() const noexcept { return stagger_; }
  double sliceScale() const noexcept { return scale_; }
  bool driverIsPinion() const noexcept { return driver_is_pinion_; }
  /// Position along the line of action (from T₁) of the z = 0 face section of pair j at mesh
  /// phase φ, and whether that pair is within its contact window.
  bool pairSection(double phase, int pair, double& s_pair) const;
  /// Sentences about the model used outside its data: one per mesh when Sainsot's fillet-
  /// foundation fit is extrapolated (tooth_beam.h) so far that the mean mesh stiffness moves by
  /// more than kFoundationFitWarning when the fit is held at its data range.
  const std::vector<std::string>& warnings() const noexcept { return warnings_; }
  /// Which members' foundation fits are extrapolated ("pinion: M* = 1.078 (data 1.08 to
  /// 3.29)"; empty when none), and the relative change of the mean mesh stiffness when their
  /// coefficients are held at the fit's data range (0 when none): the size of the uncertainty
  /// the extrapolation adds to k̄.
  const std::string& foundationFitNote() const noexcept { return foundation_fit_note_; }
  double foundationFitEffect() const noexcept { return foundation_fit_effect_; }
  /// 0.5 %: below it the extrapolation is noted, not warned about — the potential-energy model
  /// itself differs from finite elements by several per cent (docs/theory/mesh_stiffness.md).
  static constexpr double kFoundationFitWarning = 5e-3;

 private:
  double interpolate(double s) const;      // k′(s), 0 outside the path
  double runningIntegral(double u) const;  // ∫_{s_begin}^{u} k′(v) dv
  double pairAt(double s_pair) const;  // one pair's stiffness [N/m], s_pair of its z = 0 section

  ToothBeam pinion_beam_, gear_beam_;
  double rb1_, rb2_, line_of_action_, hertz_per_width_;
  double s_begin_, s_end_, base_pitch_;
  double face_width_, stagger_;  // stagger = b tan β_b: spread of one pair along the line [m]
  double window_;                // progress over which one pair is in contact [m]
  double scale_;                 // cos² β_b or 1
  int slices_;
  bool driver_is_pinion_;
  double contact_ratio_;
  int pair_slots_;
  // Table of k′ on a uniform grid over [s_begin, s_end]: values, slopes, running integral.
  double step_;
  std::vector<double> values_, slopes_, cumulative_;
  std::vector<double> breaks_;
  std::vector<std::string> warnings_;
  std::string foundation_fit_note_;
  double foundation_fit_effect_ = 0.0;
  void assessFoundationFit();  // fills the three above
};

}  // namespace geardyn
