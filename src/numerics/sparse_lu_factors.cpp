/// Allocation-free solves with one sparse LU factorisation (detail/sparse_lu_factors.h).

#include "geardyn/numerics/sparse_lu_factors.h"

#include <vector>

namespace geardyn::detail {

bool SparseLuFactors::factorize(const SparseMatrix& A) {
  Eigen::SparseLU<SparseMatrix> lu;
  lu.analyzePattern(A);
  lu.factorize(A);
  if (lu.info() != Eigen::Success) {
    message_ = lu.lastErrorMessage();
    return false;
  }
  const Eigen::Index n = A.rows();
  // The supernodal L holds, per column j, the rows of its supernode's block: those above j
  // belong to U (the block's upper triangle), j itself is U's diagonal, those below are L's.
  // SparseLU's U store holds the rest of U (rows above the supernode).
  std::vector<Eigen::Triplet<double>> lower, upper;
  const auto& supernodal = lu.matrixL().m_mapL;
  using SupernodalIterator = std::decay_t<decltype(supernodal)>::InnerIterator;
  for (Eigen::Index j = 0; j < n; ++j) {
    for (SupernodalIterator it(supernodal, j); it; ++it) {
      if (it.row() > j) {
        lower.emplace_back(it.row(), j, it.value());
      } else {
        upper.emplace_back(it.row(), j, it.value());
      }
    }
  }
  const auto& rest = lu.matrixU().m_mapU;
  for (Eigen::Index j = 0; j < n; ++j) {
    for (std::decay_t<decltype(rest)>::InnerIterator it(rest, j); it; ++it) {
      upper.emplace_back(it.row(), j, it.value());
    }
  }
  L_.resize(n, n);
  L_.setFromTriplets(lower.begin(), lower.end());
  U_.resize(n, n);
  U_.setFromTriplets(upper.begin(), upper.end());
  row_permutation_ = lu.rowsPermutation().indices();
  column_permutation_ = lu.colsPermutation().indices();
  work_.resize(n);
  message_.clear();
  return true;
}

void SparseLuFactors::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  const Eigen::Index n = size();
  // work = P_r b: (P v)(p(i)) = v(i) for a permutation with indices p (Eigen's convention).
  for (Eigen::Index i = 0; i < n; ++i) work_(row_permutation_(i)) = b(i);
  L_.triangularView<Eigen::UnitLower>().solveInPlace(work_);
  U_.triangularView<Eigen::Upper>().solveInPlace(work_);
  // x = P_c⁻¹ work: (P⁻¹ v)(i) = v(p(i)).
  x.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) x(i) = work_(column_permutation_(i));
}

}  // namespace geardyn::detail
