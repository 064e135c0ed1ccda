#pragma once
/// \file
/// The selection of the Floquet exponents among the eigenvalues of a truncated Hill matrix,
/// shared by the 1-DOF harmonic balance's and the gear train's Hill methods.

#include <Eigen/Dense>
#include <complex>
#include <vector>

namespace geardyn::detail {

/// The Floquet exponents among eigenvalues of a Hill matrix (2n states, base frequency ω
/// [rad/s]), largest real part first: those of the strip |Im λ| <= ω/2 (widened by 1e-3 ω: the
/// truncation moves the exponents of real negative multipliers, on its edge, a little off it;
/// there a + iω/2 is kept and its copy a − iω/2 dropped), at most the 2n with the smallest
/// |Im λ| (Lazarus & Thomas 2010). Keeping one copy of an edge exponent matters: two exponents
/// on the edge give four eigenvalues of equal |Im| = ω/2, and "the 2n closest to the real axis"
/// could take both copies of the stable one (round-off decides).
std::vector<std::complex<double>> floquetStrip(const Eigen::VectorXcd& values, double omega, int n);

/// The multiplier e^{λT} of a Floquet exponent λ from a truncated Hill matrix (T = 2π/ω): the
/// truncation breaks the iω-periodicity, so a real multiplier's exponent lies only near Im = 0
/// or ±ω/2; within 1e-4 ω of those it is snapped there and the multiplier is real (±e^{Re λ T}),
/// so that the bifurcation type (fold or branch point, period doubling) reads off its sign.
std::complex<double> floquetMultiplier(std::complex<double> exponent, double omega);

}  // namespace geardyn::detail
