#pragma once
/// \file
/// The harmonic blocks of a linear train's periodic steady state (train_response.cpp),
/// factorised once per speed: D(h) = K̄ − (hω₀)² M + i hω₀ C for h = 0..H (D(−h) = conj D(h)
/// since K̄, M and C are real). Dense LU for small trains; sparse LU (Eigen::SparseLU) from
/// `sparse_dofs` DOFs, where the FE trains' banded matrices make it far cheaper.
///
/// A train with rigid-body modes R (K̄ R = 0, the rolling mode no mesh deflects) has a
/// singular D(0); its static balance fixes them by Rᵀ M X₀ = 0. The dense path adds the penalty
/// p (MR)(MR)ᵀ (p the largest |K̄_ii|), the sparse path borders the block instead,
/// [D(0) MR; (MR)ᵀ 0], whose dense border would fill a sparse penalty term in. Both give the
/// same X₀ when the loads are balanced (Rᵀ F₀ = 0).
///
/// With `keep_factors` false the sparse path keeps only the latest block's factors: the
/// pattern of D(h) (the union of K̄'s, M's and C's) is analysed once (COLAMD ordering, elimination
/// tree) and every block with w ≠ 0 only refactorised in it, so a caller that is done with a block
/// before the next (train_response.cpp) pays one symbolic analysis per speed, not per harmonic.

#include <Eigen/Dense>
#include <Eigen/SparseLU>
#include <complex>
#include <memory>
#include <vector>

#include "geardyn/solvers/detail/housing_condensation.h"

namespace geardyn::detail {

class HarmonicBlocks {
 public:
  using Complex = std::complex<double>;

  /// K̄ [N/m], M [kg], C [N s/m] at the speed, R the rigid-body modes (n × k, may be empty).
  /// `housing` (may be null): condense the flexible housing out of every block exactly
  /// (housing_condensation.h) when the train without it has fewer than `sparse_dofs` DOFs and
  /// the rigid-body modes leave the housing at rest; the whole block is factorised otherwise.
  HarmonicBlocks(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M, const Eigen::MatrixXd& C,
                 const Eigen::MatrixXd& R, int sparse_dofs, bool keep_factors = true,
                 std::shared_ptr<const HousingCondensation> housing = nullptr);
  /// The housing condensed, given the train's blocks only: `Ktt` and `Ctt` the train's n_t × n_t
  /// blocks of K̄ and C (the housing's block is never read: the condensation has it in its
  /// modes, so a caller need not form the n_h-wide sums per speed), M the whole mass, `MR` the
  /// mass times the rigid-body modes (n × k, M R: a caller whose modes are the same at every
  /// speed forms it once), `penalty` the largest |K̄_ii| over all n DOFs (as the constructor
  /// above takes it). Only where `condenses(*housing, M, R, sparse_dofs)`.
  HarmonicBlocks(const Eigen::MatrixXd& Ktt, const Eigen::MatrixXd& M, const Eigen::MatrixXd& Ctt,
                 Eigen::MatrixXd MR, double penalty,
                 std::shared_ptr<const HousingCondensation> housing);
  /// Whether the constructor above condenses `housing` (then the second one may be used): the
  /// train without it has fewer than `sparse_dofs` DOFs and the rigid-body modes R leave the
  /// housing at rest.
  static bool condenses(const HousingCondensation& housing, const Eigen::MatrixXd& M,
                        const Eigen::MatrixXd& R, int sparse_dofs);
  ~HarmonicBlocks();

  /// Factorises block h at the angular frequency w [rad/s] (hω₀ over a common period, n·ω of a
  /// torus tone), for h = 0..H in order; the rigid-body modes are fixed in a block at w = 0.
  void factorize(int h, double w);
  /// D(h)⁻¹ rhs for h ≥ 0 (factorised; without keep_factors the latest only), and for h < 0
  /// through conj(D(|h|)⁻¹ conj rhs).
  Eigen::MatrixXcd solve(int h, const Eigen::MatrixXcd& rhs) const;
  bool sparse() const noexcept { return sparse_; }
  /// The housing is condensed out (see the constructor).
  bool condensesHousing() const noexcept { return housing_ != nullptr; }
  /// The DOFs `solveTrain` solves for: the train's n_t when the housing is condensed, else all.
  int trainDofs() const noexcept { return housing_ ? housing_->first : n_; }
  /// With the housing condensed: the train's rows of D(h)⁻¹ rhs for a load on the train's DOFs
  /// only (`rhs_t`, trainDofs() rows; h as in solve); the housing's modal amplitudes of the
  /// same solution follow from `housingModesOfBlocks` (every factorised block is kept). This
  /// skips the housing's n_h rows of every right-hand side when only a combination of them is
  /// wanted. Without the condensation it is `solve`.
  Eigen::MatrixXcd solveTrain(int h, const Eigen::MatrixXcd& rhs_t) const;
  /// The housing's modal amplitudes y (n_h, housing rows Φ y) of the blocks h = 0, 1, ...,
  /// q_t.cols() − 1 at once, column h of q_t the train rows of block h's solution.
  Eigen::MatrixXcd housingModesOfBlocks(const Eigen::MatrixXcd& q_t) const;
  /// With the housing condensed: the frequencies w[h] [rad/s] the blocks h = 0, 1, ... will be
  /// factorised at, so that the housing's receptances at all of them are formed in one product
  /// (HousingReceptances) and factorize(h, w[h]) reads them. Without the condensation: nothing.
  void prepare(const std::vector<double>& w);

 private:
  using SparseMatrixC = Eigen::SparseMatrix<Complex>;
  using SparseLUC = Eigen::SparseLU<SparseMatrixC>;
  Eigen::MatrixXcd solveNonNegative(int h, const Eigen::MatrixXcd& rhs) const;

  const Eigen::MatrixXd &K_, &M_, &C_;
  Eigen::MatrixXd MR_;  // M R, the constraint of the rigid-body modes
  double penalty_ = 0.0;
  bool sparse_ = false, keep_factors_ = true, analysed_ = false;
  int n_ = 0, latest_ = -1, latest_slot_ = -1;
  std::vector<Eigen::PartialPivLU<Eigen::MatrixXcd>> dense_;
  SparseMatrixC Ks_, Ms_, Cs_;
  std::vector<std::unique_ptr<SparseLUC>> sparse_lu_;  // per h, or [bordered, w ≠ 0] (not kept)
  std::shared_ptr<const HousingCondensation> housing_;
  std::vector<CondensedHousingBlock> housed_;
  HousingReceptances receptances_;  // from prepare()
};

}  // namespace geardyn::detail
