#pragma once
/// \file
/// One gear's tooth as a variable cross-section cantilever on an elastic foundation: the
/// potential-energy compliances of a contact force applied on the involute (Yang & Lin 1987,
/// Tian 2004, Ma et al. 2014; foundation: Sainsot et al. 2004). Formulas and coefficient table:
/// shared/reference/mesh_stiffness.md; derivation notes in docs/theory/mesh_stiffness.md.
///
/// Geometry in the transverse plane, per unit face width: every compliance is inversely
/// proportional to the face width, so a tooth of width L has compliance c / L.

#include <array>
#include <string>
#include <vector>

#include "geardyn/geometry/gear_pair.h"
#include "geardyn/geometry/tooth_profile.h"

namespace geardyn {

/// How the tooth below the involute is modelled.
enum class ToothRoot {
  kStraight,  ///< rectangle of the base-circle thickness from the base to the root circle (Ma 2014)
  kTrochoid,  ///< the rack-generated fillet (geometry/tooth_profile.h) from the form to the root
              ///< circle
};

/// Where the foundation moment arm u_f is measured to (Sainsot 2004 uses the force line).
enum class FoundationArm {
  kForceLine,      ///< where the line of action crosses the tooth centreline: r_b / cos α₁
  kContactHeight,  ///< the height of the contact point on the centreline
};

/// Compliances of one tooth for a unit force along the line of action, per unit face width
/// [m/N · m] (divide by the face width to get m/N).
struct ToothCompliance {
  double bending = 0.0;
  double shear = 0.0;
  double axial = 0.0;
  double foundation = 0.0;
  double total() const { return bending + shear + axial + foundation; }
};

class ToothBeam {
 public:
  /// \param hub_radius radius of the gear body's inner boundary r_int [m] (the bore) for the
  ///        Sainsot foundation fit; required (> 0) when `foundation` is true.
  ToothBeam(const GearPair& pair, Member member, ToothRoot root, FoundationArm arm, bool foundation,
            double hub_radius);

  /// Compliances for contact at the point of this tooth's involute whose roll angle is
  /// `roll` = tan α_r = √(r²/r_b² − 1) [rad]. Requires roll >= the involute's lower end.
  ToothCompliance compliance(double roll) const;

  /// α₂: half the tooth angle at the base circle, s_t / (2r) + inv α_t [rad].
  double alpha2() const noexcept { return alpha2_; }
  /// Lowest roll angle of the involute part of the beam [rad].
  double involuteStartRoll() const noexcept { return involute_start_roll_; }
  /// Half-angle of the tooth root θ_f [rad] and the foundation fit's L*, M*, P*, Q*.
  double rootHalfAngle() const noexcept { return theta_f_; }
  const std::array<double, 4>& foundationCoefficients() const noexcept { return lmpq_; }
  /// The foundation fit's coefficients that lie outside the range of Sainsot's (2004) data, as
  /// "M* = 1.078 (data 1.08 to 3.29)" joined by ", "; empty when the fit is interpolated.
  const std::string& foundationFitExtrapolation() const noexcept { return extrapolated_; }
  /// This beam with L*, M*, P*, Q* held at the nearest end of the fit's data range: the
  /// sensitivity of a result to the extrapolation (PotentialEnergyMeshStiffness).
  ToothBeam withFoundationFitClamped() const;

 private:
  double rb_, rf_, alpha2_, youngs_, poisson_;
  double involute_start_roll_;  // roll angle where the involute part ends (base or form circle)
  ToothRoot root_;
  FoundationArm arm_;
  bool foundation_;
  // Straight root: rectangle of half-thickness h_b between heights y_root and y_top.
  double straight_half_thickness_ = 0.0, straight_length_ = 0.0;
  // Trochoid root: the moments ∫ dy/I, ∫ (y−y₀) dy/I, ∫ (y−y₀)² dy/I and ∫ dy/A per unit width
  // over the fillet (y₀ = y at its top), from the generated profile.
  double fillet_top_y_ = 0.0;
  std::array<double, 3> fillet_inertia_moments_{};
  double fillet_area_integral_ = 0.0;
  double theta_f_ = 0.0;  // root half-angle
  double root_y_ = 0.0;   // height of the root section on the centreline, r_f cos θ_f
  std::array<double, 4> lmpq_{};
  std::string extrapolated_;
};

/// Hertzian contact stiffness of a tooth pair per unit face width,
/// k_h = π / (2 [(1 − ν₁²)/E₁ + (1 − ν₂²)/E₂]) [N/m/m] (= π E / (4 (1 − ν²)) for one material).
double hertzStiffnessPerWidth(double youngs1, double poisson1, double youngs2, double poisson2);

}  // namespace geardyn
