#pragma once
/// \file
/// The gear-mesh coupling of a finite-element geared rotor: the gradient v of the mesh
/// deflection along the line of action with respect to the DOFs of the pinion and gear nodes,
/// so that the mesh adds k_m(t) v vᵀ to the stiffness (Visnadi 2021 eqs. 10–16).
///
/// Derivation (first principles, replacing the printed eqs. 11–16). Both shafts lie along x;
/// the pinion centre is at the origin of its transverse plane. The transverse line of action
/// has direction n_t = (sin ψ, cos ψ) in (y, z), ψ measured from the vertical z axis as in
/// the paper. The contact normal of an involute helicoid is inclined by the base helix angle
/// β_b in the plane of action: n = (sin β_b, cos β_b n_t) in (x, y, z). The pinion's base circle
/// touches the line of action at T₁ = r_bp m with m = (cos ψ, −sin ψ) (so a positive pinion
/// rotation about +x advances its flank along +n), the gear's at T₂ = T₁ + T₁T₂ n_t, and the
/// gear centre sits at C = (r_bp + r_bg) m + T₁T₂ n_t. With the contact at a point c, a node
/// with translation u and small rotation θ moves c by u + θ × (c − centre), so the mesh
/// deflection (compression) is
///   δ = n · [u_p + θ_p × (c − 0)] − n · [u_g + θ_g × (c − C)],
/// i.e. v = [n, (c − 0) × n, −n, −(c − C) × n] over [u_p, θ_p, u_g, θ_g].
///
/// With c the pitch point (the default) the same physical point is used for both bodies, so
/// every rigid-body motion of the pair (and the rolling motion θ_xg = −(r_bp/r_bg) θ_xp) gives
/// δ = 0. The paper (after Kubur 2004) takes the axial force's moment arm at each body's own
/// base tangent point (c = T₁ for the pinion, T₂ for the gear); that is `kBaseTangentPoints`.
/// Corrections to the printed eq. 11: the torsion term reads r_bp θ_xp + r_bg θ_xg (the print
/// has θ_xg twice) and the gear tilt term r_bg θ_zg cos ψ (the print has θ_zp twice); the
/// normal inclination is the base helix angle β_b (the print writes β; tan β_b = tan β cos α_t).

#include <Eigen/Dense>

#include "geardyn/models/timoshenko_shaft_element.h"

namespace geardyn {

/// Where the mesh force acts for the tilting moments of its axial component.
enum class MeshContactPoint {
  kPitchPoint,         ///< one physical point, the operating pitch point (rigid-body exact)
  kBaseTangentPoints,  ///< each body's base tangent point (Visnadi 2021 eq. 11, Kubur 2004)
};

struct MeshCouplingGeometry {
  double line_of_action_angle = 0.0;   ///< ψ: transverse line of action from the z axis [rad]
  double base_helix_angle = 0.0;       ///< β_b, signed: > 0 gives n_x > 0 [rad]
  double pinion_base_radius = 0.0;     ///< r_bp [m]
  double gear_base_radius = 0.0;       ///< r_bg [m]
  double line_of_action_length = 0.0;  ///< T₁T₂ [m]
  double pitch_point_distance = 0.0;   ///< T₁P = r_bp tan α_wt [m]
  MeshContactPoint contact_point = MeshContactPoint::kPitchPoint;
};

using MeshVector = Eigen::Matrix<double, 2 * kNodeDofs, 1>;

/// v = ∂δ/∂[q_pinion, q_gear] (node DOF order of timoshenko_shaft_element.h) [1, m].
MeshVector meshDeflectionGradient(const MeshCouplingGeometry& geometry);

/// The gear centre relative to the pinion centre in the transverse plane, (y, z) [m].
Eigen::Vector2d gearCentreOffset(const MeshCouplingGeometry& geometry);

}  // namespace geardyn
