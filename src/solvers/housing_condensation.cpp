/// The flexible housing condensed out of a harmonic block (detail/housing_condensation.h).

#include "geardyn/solvers/detail/housing_condensation.h"

#include <Eigen/Eigenvalues>

#include "geardyn/system/train_housing.h"

namespace geardyn::detail {

std::shared_ptr<const HousingCondensation> HousingCondensation::of(const GearTrainModel& model) {
  const int n_t = model.housingFirstDof();
  if (n_t < 0) return nullptr;
  const TrainHousingSpec& spec = *model.spec().housing;
  const HousingLinkTerms terms = housingLinkTerms(model);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(spec.reduced.K, spec.reduced.M);
  if (eig.info() != Eigen::Success) return nullptr;
  // A housing that is not held has rigid-body modes: D_h0(0) is singular.
  if (!(eig.eigenvalues().minCoeff() > 1e-9 * eig.eigenvalues().cwiseAbs().maxCoeff())) {
    return nullptr;
  }
  auto out = std::make_shared<HousingCondensation>();
  out->first = n_t;
  out->J = terms.J;
  out->Phi = eig.eigenvectors();
  out->lambda = eig.eigenvalues();
  out->W = terms.JH * out->Phi;
  out->k = terms.k;
  out->c = terms.c;
  out->beta = spec.stiffness_proportional_damping;
  out->Jc = out->J.cast<std::complex<double>>();
  out->Wc = out->W.cast<std::complex<double>>();
  out->Phic = out->Phi.cast<std::complex<double>>();
  return out;
}

void CondensedHousingBlock::factorize(const HousingCondensation& h, const Eigen::MatrixXcd& Dtt,
                                      double w) {
  const Complex iw(0.0, w);
  dinv_ =
      ((1.0 + iw * h.beta) * h.lambda.cast<Complex>().array() - Complex(w * w)).inverse().matrix();
  const Eigen::MatrixXcd G = h.Wc * dinv_.asDiagonal() * h.Wc.transpose();
  const Eigen::MatrixXcd Z = h.k.cast<Complex>() + iw * h.c.cast<Complex>();
  const auto r = Z.rows();
  Zeff_ = (Eigen::MatrixXcd::Identity(r, r) + Z * G).partialPivLu().solve(Z);
  lu_.compute(Dtt + h.Jc.transpose() * (Zeff_ - Z) * h.Jc);
}

Eigen::MatrixXcd CondensedHousingBlock::solve(const HousingCondensation& h,
                                              const Eigen::MatrixXcd& rhs) const {
  const Eigen::Index n_t = h.first, n_h = h.Phi.rows();
  Eigen::MatrixXcd out(n_t + n_h, rhs.cols());
  // The train's loads (mesh vectors, static load, excitations) leave the housing's rows zero:
  // then Φᵀ f_h and g vanish and two n_h × n_h products per column are skipped.
  if (rhs.bottomRows(n_h).isZero(0.0)) {
    out.topRows(n_t) = lu_.solve(rhs.topRows(n_t));
    const Eigen::MatrixXcd F = Zeff_ * (h.Jc * out.topRows(n_t));  // bearing forces
    out.bottomRows(n_h) = h.Phic * (dinv_.asDiagonal() * (h.Wc.transpose() * F));
    return out;
  }
  const Eigen::MatrixXcd p = h.Phic.transpose() * rhs.bottomRows(n_h);  // Φᵀ f_h
  const Eigen::MatrixXcd g = h.Wc * (dinv_.asDiagonal() * p);           // J_H D_h0⁻¹ f_h
  out.topRows(n_t) = lu_.solve(rhs.topRows(n_t) + h.Jc.transpose() * (Zeff_ * g));
  const Eigen::MatrixXcd F = Zeff_ * (h.Jc * out.topRows(n_t) - g);  // bearing forces
  out.bottomRows(n_h) = h.Phic * (dinv_.asDiagonal() * (h.Wc.transpose() * F + p));
  return out;
}

}  // namespace geardyn::detail
