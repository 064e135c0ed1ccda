#pragma once
/// \file
/// Generation of one gear by its rack (the counterpart of the ISO 53 basic rack): the envelope
/// of the rack's tip rounding (the trochoidal root fillet) and the true form radius r_Ff, where
/// the generated profile becomes involute. Without undercut r_Ff is where the rack's straight
/// flank ends (ISO 21771:2007 §5.4, closed form); with undercut it is where the fillet cuts the
/// involute, the root of one equation solved here to round-off (docs/theory/geometry.md,
/// "True form radius").
///
/// Frame (transverse section, as the rack stands when the tooth being cut is centred on +y,
/// heights measured from the gear centre): reference line y = r + x m_n; right rack flank
/// x_F(y) = π m_t / 4 + (r + x m_n − y) tan α_t; tip line y = r + x m_n − h_f* m_n. For a roll
/// parameter φ the gear centre is at G = (−r φ, 0), the gear has turned by −φ and the
/// instantaneous centre of rotation is I = (−r φ, r); a rack point p lands in the gear frame at
/// P = R(φ) (p − G) (Litvin & Fuentes, Gear Geometry and Applied Theory, 2nd ed. 2004, §6.1).

#include <Eigen/Core>

#include "geardyn/geometry/gear.h"

namespace geardyn {

/// The transverse section of the generating rack of one gear. The rack is defined in the normal
/// section (ISO 53); its transverse section stretches horizontal lengths by 1 / cos β, so the
/// tip rounding of radius ρ_fP* m_n becomes an ellipse with semi-axes ρ / cos β (horizontal)
/// and ρ (vertical), tangent to the transverse flank (pressure angle α_t) and to the tip line.
struct GeneratingRack {
  double pitch_radius = 0.0;          ///< r [m]
  double base_radius = 0.0;           ///< r_b = r cos α_t [m]
  double transverse_pressure = 0.0;   ///< α_t [rad]
  double normal_pressure = 0.0;       ///< α_n [rad]
  double cos_beta = 1.0;              ///< cos β [-]
  double half_thickness_angle = 0.0;  ///< s_t / (2 r) + inv α_t: ψ at the base circle [rad]
  double rounding_radius = 0.0;       ///< ρ = ρ_fP* m_n [m]
  Eigen::Vector2d rounding_centre;    ///< centre of the rounding, rack frame [m]
  Eigen::Vector2d flank_end;          ///< E: where the straight flank ends, rack frame [m]
  /// Roll distance from T at which E generates, r sin α_t − (r − y_E) / sin α_t [m]; negative:
  /// E cuts beyond the interference point T, the tooth is undercut (ISO 21771 §5.4).
  double flank_end_roll = 0.0;
};

/// The generating rack of `gear` (its own m_n, α_n, β, x, h_f*, ρ_fP*).
GeneratingRack generatingRack(const GearSpec& gear);

/// A rack point p [m] at roll parameter φ [rad], in the gear frame: P = R(φ) (p − G) with
/// G = (−r φ, 0) [m].
Eigen::Vector2d rackPointInGearFrame(const GeneratingRack& rack, const Eigen::Vector2d& p,
                                     double phi);

/// The roll parameter φ_E [rad] at which E lies on the line of action (where the flank's
/// envelope condition holds at E).
double flankEndRollParameter(const GeneratingRack& rack);

/// A point of the generated root fillet in the gear frame [m], u in [0, 1]: u = 0 is generated
/// by E (the top of the fillet), u = 1 by the rounding's tangent point with the tip line (on
/// the root circle). For ρ > 0, u sweeps the rounding's normal direction θ from π + α_n to
/// 3π/2 and the envelope condition (Q − I) · dQ/dθ = 0 gives φ(θ) explicitly; for a sharp rack
/// (ρ = 0) u sweeps φ along the path of the corner.
Eigen::Vector2d generatedFilletPoint(const GeneratingRack& rack, double u);

/// Involute half-angle ψ(r) = s_t / (2 r) + inv α_t − inv α_y, cos α_y = r_b / r, for r ≥ r_b
/// [rad] (ISO 21771 eq. 47 divided by 2 r).
double involuteHalfAngle(const GeneratingRack& rack, double radius);

/// The true form radius r_Ff [m]: where the generated profile becomes involute.
/// - E generates on the involute (flank_end_roll ≥ 0): r_Ff = √(r_b² + flank_end_roll²).
/// - Undercut: the outermost radius where the fillet crosses the involute (it enters the
///   tooth there); bracketed on 500 samples of u and refined by bisection to round-off. r_b if
///   the fillet never crosses the involute above the base circle.
double trueFormRadius(const GeneratingRack& rack);

}  // namespace geardyn
