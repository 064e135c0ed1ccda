/// The harmonic blocks of a linear train's steady state (detail/harmonic_blocks.h).

#include "geardyn/solvers/detail/harmonic_blocks.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <utility>

namespace geardyn::detail {
namespace {

Eigen::SparseMatrix<std::complex<double>> complexSparseOf(const Eigen::MatrixXd& A) {
  // Entries below 1e-14 of the largest are round-off of cancelling sums, not couplings.
  const double scale = std::max(A.cwiseAbs().maxCoeff(), 1e-300);
  return A.cast<std::complex<double>>().sparseView(1.0, 1e-14 * scale);
}

/// A rigid-body mode that moves the housing (M R's housing rows not zero): the whole block is
/// factorised, not condensed.
bool housingStill(const Eigen::MatrixXd& MR, Eigen::Index n_h) {
  return MR.cols() == 0 || MR.bottomRows(n_h).cwiseAbs().maxCoeff() <=
                               1e-12 * std::max(MR.cwiseAbs().maxCoeff(), 1e-300);
}

}  // namespace

bool HarmonicBlocks::condenses(const HousingCondensation& housing, const Eigen::MatrixXd& M,
                               const Eigen::MatrixXd& R, int sparse_dofs) {
  if (housing.first >= sparse_dofs) return false;
  return R.cols() == 0 || housingStill(M * R, M.rows() - housing.first);
}

HarmonicBlocks::HarmonicBlocks(const Eigen::MatrixXd& Ktt, const Eigen::MatrixXd& M,
                               const Eigen::MatrixXd& Ctt, Eigen::MatrixXd MR, double penalty,
                               std::shared_ptr<const HousingCondensation> housing)
    : K_(Ktt),
      M_(M),
      C_(Ctt),
      MR_(std::move(MR)),
      penalty_(penalty),
      sparse_(false),
      n_(static_cast<int>(M.rows())),
      housing_(std::move(housing)) {}

HarmonicBlocks::HarmonicBlocks(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M,
                               const Eigen::MatrixXd& C, const Eigen::MatrixXd& R, int sparse_dofs,
                               bool keep_factors,
                               std::shared_ptr<const HousingCondensation> housing)
    : K_(K),
      M_(M),
      C_(C),
      sparse_(K.rows() >= sparse_dofs),
      keep_factors_(keep_factors),
      n_(static_cast<int>(K.rows())) {
  if (R.cols() > 0) MR_ = M * R;
  if (housing && housing->first < sparse_dofs) {
    if (housingStill(MR_, n_ - housing->first)) housing_ = std::move(housing), sparse_ = false;
  }
  penalty_ = std::max(K.diagonal().cwiseAbs().maxCoeff(), 1e-300);
  if (sparse_) {
    Ks_ = complexSparseOf(K);
    Ms_ = complexSparseOf(M);
    Cs_ = complexSparseOf(C);
  }
}

HarmonicBlocks::~HarmonicBlocks() = default;

void HarmonicBlocks::factorize(int h, double w) {
  if (housing_) {
    const Eigen::Index n_t = housing_->first;
    Eigen::MatrixXcd D =
        (K_.topLeftCorner(n_t, n_t) - w * w * M_.topLeftCorner(n_t, n_t)).cast<Complex>() +
        Complex(0.0, w) * C_.topLeftCorner(n_t, n_t).cast<Complex>();
    if (w == 0.0 && MR_.cols() > 0) {
      D += (penalty_ * MR_.topRows(n_t) * MR_.topRows(n_t).transpose()).cast<Complex>();
    }
    housed_.resize(std::max<std::size_t>(housed_.size(), h + 1));
    const std::size_t k = static_cast<std::size_t>(h);
    if (k < receptances_.w.size() && receptances_.w[k] == w) {
      housed_[k].factorize(*housing_, std::move(D), w, receptances_.dinv.col(h),
                           receptances_.g.col(h));
    } else {
      housed_[k].factorize(*housing_, std::move(D), w);
    }
    return;
  }
  if (!sparse_) {
    Eigen::MatrixXcd D = (K_ - w * w * M_).cast<Complex>() + Complex(0.0, w) * C_.cast<Complex>();
    if (w == 0.0 && MR_.cols() > 0) D += (penalty_ * MR_ * MR_.transpose()).cast<Complex>();
    dense_.resize(std::max<std::size_t>(dense_.size(), h + 1));
    dense_[h].compute(D);
    return;
  }
  SparseMatrixC D = Ks_ - (w * w) * Ms_ + Complex(0.0, w) * Cs_;
  const bool bordered = w == 0.0 && MR_.cols() > 0;
  if (bordered) {
    // [D(0) MR; (MR)ᵀ 0]: the border's nonzeros appended to D's.
    const int k = static_cast<int>(MR_.cols());
    std::vector<Eigen::Triplet<Complex>> entries;
    entries.reserve(D.nonZeros() + 2 * static_cast<std::size_t>(n_) * k);
    for (int j = 0; j < D.outerSize(); ++j) {
      for (SparseMatrixC::InnerIterator it(D, j); it; ++it) {
        entries.emplace_back(static_cast<int>(it.row()), static_cast<int>(it.col()), it.value());
      }
    }
    for (int c = 0; c < k; ++c) {
      for (int i = 0; i < n_; ++i) {
        if (MR_(i, c) == 0.0) continue;
        entries.emplace_back(i, n_ + c, MR_(i, c));
        entries.emplace_back(n_ + c, i, MR_(i, c));
      }
    }
    D.resize(n_ + k, n_ + k);
    D.setFromTriplets(entries.begin(), entries.end());
  }
  D.makeCompressed();
  // Kept: one factorisation per h. Not kept: slot 0 the bordered block, slot 1 every other
  // one, in the pattern analysed once (the sum above keeps the union pattern, zeros included).
  const std::size_t slot = keep_factors_ ? static_cast<std::size_t>(h) : (bordered ? 0 : 1);
  sparse_lu_.resize(std::max<std::size_t>(sparse_lu_.size(), slot + 1));
  if (!sparse_lu_[slot]) sparse_lu_[slot] = std::make_unique<SparseLUC>();
  SparseLUC& lu = *sparse_lu_[slot];
  if (keep_factors_ || bordered) {
    lu.compute(D);
  } else {
    if (!analysed_) lu.analyzePattern(D), analysed_ = true;
    lu.factorize(D);
  }
  latest_ = h, latest_slot_ = static_cast<int>(slot);
  if (lu.info() != Eigen::Success) {
    throw std::runtime_error(fmt::format(
        "steady state: the harmonic block D(h) = K̄ − (hω₀)²M + i hω₀ C cannot be factorised at "
        "h = {}, hω₀ = {:g} rad/s ({})",
        h, w, lu.lastErrorMessage()));
  }
}

Eigen::MatrixXcd HarmonicBlocks::solveNonNegative(int h, const Eigen::MatrixXcd& rhs) const {
  if (housing_) return housed_[h].solve(*housing_, rhs);
  if (!sparse_) return dense_[h].solve(rhs);
  if (!keep_factors_ && h != latest_) {
    throw std::logic_error(fmt::format(
        "HarmonicBlocks: block {} asked after block {} (factors not kept)", h, latest_));
  }
  const SparseLUC& lu = *sparse_lu_[keep_factors_ ? h : latest_slot_];
  if (lu.rows() == n_) return lu.solve(rhs);
  Eigen::MatrixXcd padded = Eigen::MatrixXcd::Zero(lu.rows(), rhs.cols());
  padded.topRows(n_) = rhs;
  return Eigen::MatrixXcd(lu.solve(padded)).topRows(n_);
}

Eigen::MatrixXcd HarmonicBlocks::solve(int h, const Eigen::MatrixXcd& rhs) const {
  if (h >= 0) return solveNonNegative(h, rhs);
  return solveNonNegative(-h, rhs.conjugate()).conjugate();
}

Eigen::MatrixXcd HarmonicBlocks::solveTrain(int h, const Eigen::MatrixXcd& rhs_t) const {
  if (!housing_) return solve(h, rhs_t);
  const std::size_t k = static_cast<std::size_t>(std::abs(h));
  if (h >= 0) return housed_.at(k).solveTrain(rhs_t);
  return housed_.at(k).solveTrain(rhs_t.conjugate()).conjugate();
}

Eigen::MatrixXcd HarmonicBlocks::housingModesOfBlocks(const Eigen::MatrixXcd& q_t) const {
  if (!housing_)
    throw std::logic_error("HarmonicBlocks::housingModesOfBlocks: no condensed housing");
  Eigen::MatrixXcd F(housing_->W.rows(), q_t.cols());  // the bearing forces of every block
  for (Eigen::Index h = 0; h < q_t.cols(); ++h) {
    housed_.at(static_cast<std::size_t>(h)).bearingForces(*housing_, q_t.col(h), F.col(h));
  }
  Eigen::MatrixXcd y = housing_->modal(F);  // Wᵀ F of all blocks in one product
  for (Eigen::Index h = 0; h < q_t.cols(); ++h) {
    y.col(h).array() *= housed_[static_cast<std::size_t>(h)].receptances().array();
  }
  return y;
}

void HarmonicBlocks::prepare(const std::vector<double>& w) {
  if (housing_) receptances_ = HousingReceptances::at(*housing_, w);
}

}  // namespace geardyn::detail
