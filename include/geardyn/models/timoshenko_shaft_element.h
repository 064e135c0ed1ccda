#pragma once
/// \file
/// A two-node Timoshenko shaft element with six degrees of freedom per node: axial bar,
/// torsion and bending with shear deformation and rotary inertia in two planes, and the
/// gyroscopic matrix of the spinning section (Nelson 1980; shape functions of Friedman &
/// Kosmatka 1993, exact for the static Timoshenko beam).
///
/// Axes: the shaft axis is x; y is horizontal and z vertical (Visnadi 2021 §3). Node DOFs are
/// ordered [u_x, u_y, u_z, θ_x, θ_y, θ_z] (translations [m], small rotations [rad] about the
/// axes, right-handed). For bending the slopes are du_y/dx ≈ θ_z and du_z/dx ≈ −θ_y, so a rigid
/// rotation about any axis is a rigid-body mode of the element.

#include <Eigen/Dense>

namespace geardyn {

/// DOFs per FE node and their offsets.
inline constexpr int kNodeDofs = 6;
enum NodeDof : int { kUx = 0, kUy = 1, kUz = 2, kRx = 3, kRy = 4, kRz = 5 };

using ElementMatrix = Eigen::Matrix<double, 2 * kNodeDofs, 2 * kNodeDofs>;

/// A uniform (possibly hollow) circular shaft segment.
struct ShaftSegment {
  double length = 0.0;          ///< L [m]
  double outer_diameter = 0.0;  ///< D [m]
  double inner_diameter = 0.0;  ///< d [m], 0 for a solid shaft
  double youngs_modulus = 0.0;  ///< E [Pa]
  double shear_modulus = 0.0;   ///< G [Pa]
  double density = 0.0;         ///< ρ [kg/m³]

  double area() const;                ///< A = π (D² − d²) / 4 [m²]
  double secondMomentOfArea() const;  ///< I = π (D⁴ − d⁴) / 64 [m⁴]
  double polarMomentOfArea() const { return 2.0 * secondMomentOfArea(); }  ///< J [m⁴]
  /// Shear coefficient κ of a hollow circular section (Hutchinson 2001 / Cowper 1966):
  /// κ = 6 (1 + ν)(1 + m²)² / [(7 + 6ν)(1 + m²)² + (20 + 12ν) m²], m = d/D, ν = E/(2G) − 1.
  double shearCoefficient() const;
  /// Φ = 12 E I / (κ G A L²): the bending-to-shear stiffness ratio of the element.
  double shearParameter() const;
  /// Throws InputError naming `key` unless every field is finite, D > d ≥ 0, L, E, G, ρ > 0.
  void validate(const std::string& key) const;
};

/// Stiffness matrix [N/m, N, N m/rad]: symmetric, positive semi-definite with the six rigid-body
/// modes as its null space.
ElementMatrix shaftElementStiffness(const ShaftSegment& segment);
/// Consistent mass matrix [kg, kg m, kg m²]: translational and rotary inertia in bending,
/// axial and polar inertia; symmetric positive definite.
ElementMatrix shaftElementMass(const ShaftSegment& segment);
/// Gyroscopic matrix per unit spin speed about +x [kg m²]: skew-symmetric; the equations of
/// motion carry Ω G q̇ with Ω the signed spin speed [rad/s].
ElementMatrix shaftElementGyroscopic(const ShaftSegment& segment);

}  // namespace geardyn
