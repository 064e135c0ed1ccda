#pragma once
/// \file
/// Allocation-free repeated solves with one sparse LU factorisation. Eigen's SparseLU
/// (supernodal, SuperLU's algorithm) factorises well, but each solve allocates an n × nrhs
/// workspace in its supernodal L sweep. A time integrator solves with the same matrix at every
/// step, so the factors are copied once into plain column-compressed triangles,
///   A = P_r⁻¹ L U P_c   (L unit lower, U upper, as SparseLU returns them),
/// and x = P_c⁻¹ U⁻¹ L⁻¹ P_r b is two sparse triangular sweeps in a preallocated vector: the same
/// operations as SparseLU's solve, without its allocation.

#include <Eigen/Sparse>
#include <string>

namespace geardyn::detail {

class SparseLuFactors {
 public:
  using SparseMatrix = Eigen::SparseMatrix<double>;

  /// Factorises A (square); false when SparseLU fails (`message` says why).
  bool factorize(const SparseMatrix& A);
  const std::string& message() const noexcept { return message_; }

  /// x = A⁻¹ b; allocation-free once x has A's size (x and b must not alias).
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;

  Eigen::Index size() const noexcept { return L_.rows(); }
  Eigen::Index nonZeros() const noexcept { return L_.nonZeros() + U_.nonZeros(); }

 private:
  SparseMatrix L_, U_;  // strictly lower part of L (unit diagonal implied), U with its diagonal
  Eigen::VectorXi row_permutation_, column_permutation_;
  mutable Eigen::VectorXd work_;
  std::string message_;
};

}  // namespace geardyn::detail
