#pragma once
/// \file
/// Hertz's elastic point contact of two bodies with principal relative curvatures A ≤ B
/// (the gap h = A x² + B y²): an ellipse of semi-axes a ≥ b (a along x), the approach
/// δ = c_δ P^{2/3} and the peak pressure p₀ = c_p P^{1/3} under the normal load P.
/// Johnson, Contact Mechanics (1985), eqs. (3.69)–(3.71), with e² = 1 − b²/a²:
///   B/A = [E(e)/(1 − e²) − K(e)] / [K(e) − E(e)],
///   a³ = 3 P (K − E) / (2π A E* e²),  b = a √(1 − e²),
///   δ = A e² a² K / (K − E),           p₀ = 3 P / (2π a b),
/// K, E the complete elliptic integrals of modulus e. docs/theory/rolling_bearings.md.

namespace geardyn {

struct HertzPointContact {
  double eccentricity = 0.0;  ///< e = √(1 − b²/a²) [-]
  double deflection = 0.0;    ///< c_δ: δ = c_δ P^{2/3} [m N^{-2/3}]
  double semi_major = 0.0;    ///< c_a: a = c_a P^{1/3} [m N^{-1/3}]
  double semi_minor = 0.0;    ///< c_b: b = c_b P^{1/3} [m N^{-1/3}]
  double pressure = 0.0;      ///< c_p: p₀ = c_p P^{1/3} [Pa N^{-1/3}]
};

/// The contact of curvatures A, B > 0 [1/m] (half the curvature sums in the two principal
/// planes, in either order) and contact modulus E* = 1/[(1−ν₁²)/E₁ + (1−ν₂²)/E₂] [Pa].
/// std::invalid_argument when A, B or E* is not positive and finite.
HertzPointContact hertzPointContact(double curvature_a, double curvature_b, double contact_modulus);

/// E* of two bodies [Pa].
double contactModulus(double youngs_1, double poisson_1, double youngs_2, double poisson_2);

}  // namespace geardyn
