#pragma once
/// \file
/// The few damped modes of a large sparse M q̈ + D q̇ + K q = 0 nearest a real shift σ, by
/// shift-and-invert Arnoldi (Spectra's GenEigsRealShiftSolver) on the first-order form
/// A = [[0, I], [−M⁻¹K, −M⁻¹D]] without forming A: (A − σI) z = b, z = (x, v), is solved by
///   P(σ) x = −[M b₂ + (D + σM) b₁],  v = b₁ + σ x,   P(σ) = σ² M + σ D + K,
/// with P(σ) factorised once (SparseLU). For the lowest modes σ is a small negative number
/// (P(0) = K is singular when the train has a rolling rigid-body mode).

#include <Eigen/Sparse>
#include <vector>

#include "geardyn/numerics/damped_modes.h"

namespace geardyn::detail {

/// The modes with Im λ > 0 among the `eigenvalues` eigenvalues of A nearest σ [1/s], in
/// solver order; the shapes are the displacement parts, largest entry 1. Throws
/// std::runtime_error naming the cause when the factorisation or Arnoldi fails.
/// `krylov_start` (optional, length 2n): in, Arnoldi's start vector when it has that length
/// (else a random one); out, the sum of the computed eigenvectors (real and imaginary parts,
/// each of unit norm): the start for a neighbouring problem, e.g. the next speed of a
/// Campbell diagram, whose eigenvectors differ little.
std::vector<DampedMode> shiftInvertModes(const Eigen::SparseMatrix<double>& M,
                                         const Eigen::SparseMatrix<double>& D,
                                         const Eigen::SparseMatrix<double>& K, int eigenvalues,
                                         double sigma, Eigen::VectorXd* krylov_start = nullptr);

}  // namespace geardyn::detail
