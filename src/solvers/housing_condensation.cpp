/// The flexible housing condensed out of a harmonic block (detail/housing_condensation.h).

#include "geardyn/solvers/detail/housing_condensation.h"

#include <Eigen/Eigenvalues>
#include <utility>

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
  const Eigen::Index r = out->W.rows(), n_h = out->W.cols();
  for (Eigen::Index j = 0; j < out->J.cols(); ++j) {
    if (out->J.col(j).cwiseAbs().maxCoeff() > 0.0) out->J_columns.push_back(j);
  }
  out->Jc = out->J(Eigen::all, out->J_columns);
  out->JcT = out->Jc.transpose().cast<std::complex<double>>();
  auto diagonal = [](const Eigen::MatrixXd& a) {
    return (a - Eigen::MatrixXd(a.diagonal().asDiagonal())).cwiseAbs().maxCoeff() == 0.0;
  };
  out->Z_diagonal = r == 0 || (diagonal(out->k) && diagonal(out->c));
  std::vector<char> read(static_cast<std::size_t>(n_h), 0);
  for (const TrainElement& e : model.elements()) {
    for (int d : e.dofs) {
      if (d >= n_t) read[static_cast<std::size_t>(d - n_t)] = 1;
    }
  }
  for (Eigen::Index i = 0; i < n_h; ++i) {
    if (read[static_cast<std::size_t>(i)]) out->read_rows.push_back(i);
  }
  if (!spec.reduced.points.empty()) out->points_Phi = spec.reduced.recovery * out->Phi;
  const Eigen::Index kept = static_cast<Eigen::Index>(out->read_rows.size());
  out->Phi_kept.resize(kept + out->points_Phi.rows(), n_h);
  out->Phi_kept.topRows(kept) = out->Phi(out->read_rows, Eigen::all);
  out->Phi_kept.bottomRows(out->points_Phi.rows()) = out->points_Phi;
  // G is symmetric: P holds the upper triangle's entries only, column by column.
  out->P.resize(r * (r + 1) / 2, n_h);
  for (Eigen::Index k = 0; k < n_h; ++k) {
    Eigen::Index row = 0;
    for (Eigen::Index j = 0; j < r; ++j) {
      for (Eigen::Index i = 0; i <= j; ++i) out->P(row++, k) = out->W(i, k) * out->W(j, k);
    }
  }
  out->dinv_static = out->lambda.cwiseInverse().cast<std::complex<double>>();
  out->g_static = (out->P * out->lambda.cwiseInverse()).cast<std::complex<double>>();
  return out;
}

namespace {

using Complex = std::complex<double>;

/// [Re x, Im x] as one real matrix (2 × x's columns), so that A is read once per product.
Eigen::MatrixXd splitParts(const Eigen::MatrixXcd& x) {
  Eigen::MatrixXd parts(x.rows(), 2 * x.cols());
  parts.leftCols(x.cols()) = x.real();
  parts.rightCols(x.cols()) = x.imag();
  return parts;
}

Eigen::MatrixXcd joinParts(const Eigen::MatrixXd& parts) {
  const Eigen::Index c = parts.cols() / 2;
  Eigen::MatrixXcd out(parts.rows(), c);
  out.real() = parts.leftCols(c);
  out.imag() = parts.rightCols(c);
  return out;
}

/// A x for a real A and a complex x: one real product with [Re x, Im x] (half the work of a
/// complex product, A read once). One column is two matrix–vector products instead: a matrix
/// product packs A for its kernel first, which for two columns costs as much as the product
/// (perf of bench/housing_bench.cpp, BM_ForcedPerSpeed).
Eigen::MatrixXcd realTimes(const Eigen::MatrixXd& A, const Eigen::MatrixXcd& x) {
  if (x.cols() == 1) {
    const Eigen::VectorXd re = x.real(), im = x.imag();
    Eigen::MatrixXcd out(A.rows(), 1);
    out.real() = A * re;
    out.imag() = A * im;
    return out;
  }
  return joinParts(A * splitParts(x));
}

/// Aᵀ x likewise.
Eigen::MatrixXcd realTransposeTimes(const Eigen::MatrixXd& A, const Eigen::MatrixXcd& x) {
  if (x.cols() == 1) {
    const Eigen::VectorXd re = x.real(), im = x.imag();
    Eigen::MatrixXcd out(A.cols(), 1);
    out.real() = A.transpose() * re;
    out.imag() = A.transpose() * im;
    return out;
  }
  return joinParts(A.transpose() * splitParts(x));
}

/// 1/d_k = 1/((1 + iwβ_h) λ_k − w²), the housing's modal receptances at w [rad/s], as
/// conj(d)/|d|² (libgcc's complex division __divdc3 rescales against overflow, which |d|² of
/// λ_k < 1e150 does not need, at several times the cost).
Eigen::VectorXcd modalReceptances(const HousingCondensation& h, double w) {
  const Complex loss(1.0, w * h.beta);
  Eigen::VectorXcd out(h.lambda.size());
  for (Eigen::Index k = 0; k < out.size(); ++k) {
    const Complex d = loss * h.lambda(k) - w * w;
    out(k) = std::conj(d) / std::norm(d);
  }
  return out;
}

}  // namespace

/// Gaussian elimination with partial pivoting on |Re| + |Im|, the pivot measure of LAPACK's
/// zgetrf (izamax; Anderson et al., LAPACK Users' Guide, 3rd ed., 1999), which needs no hypot
/// per candidate. Eigen's PartialPivLU (pivots on |z| by hypot) with its triangular solves for
/// Z_eff and the product Z G took half the condensation's time per harmonic (perf,
/// bench/housing_bench.cpp, BM_ForcedPerSpeed).
/// With |z| ≤ |Re z| + |Im z| ≤ √2 |z| the multipliers stay below √2 in modulus, so the growth
/// factor's bound for partial pivoting, 2^(r−1), becomes (1 + √2)^(r−1) (Higham, Accuracy and
/// Stability of Numerical Algorithms, 2nd ed., §9.3); r is the bearings' rows, a few dozen at most.
void SmallComplexLU::compute(const Eigen::MatrixXcd& A) {
  lu_ = A;
  const Eigen::Index n = A.rows();
  pivots_.resize(static_cast<std::size_t>(n));
  inverse_.resize(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    Eigen::Index p = k;
    double best = -1.0;
    for (Eigen::Index i = k; i < n; ++i) {
      const double size = std::abs(lu_(i, k).real()) + std::abs(lu_(i, k).imag());
      if (size > best) best = size, p = i;
    }
    pivots_[static_cast<std::size_t>(k)] = p;
    if (p != k) lu_.row(k).swap(lu_.row(p));
    // 1/u_kk as conj/|.|²: libgcc's complex division (__divdc3) costs several times more.
    inverse_(k) = std::conj(lu_(k, k)) / std::norm(lu_(k, k));
    const Eigen::Index m = n - k - 1;
    lu_.col(k).tail(m) *= inverse_(k);  // the multipliers
    for (Eigen::Index j = k + 1; j < n; ++j) lu_.col(j).tail(m) -= lu_(k, j) * lu_.col(k).tail(m);
  }
}

void SmallComplexLU::solveInPlace(Eigen::MatrixXcd& B) const {
  const Eigen::Index n = lu_.rows();
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Index p = pivots_[static_cast<std::size_t>(k)];
    if (p != k) B.row(k).swap(B.row(p));
  }
  // Column by column on the raw storage: the right-hand sides Z J are sparse (a column of J
  // holds a shaft's few bearing rows), so the forward sweep skips the zeros it meets.
  const Complex* L = lu_.data();
  for (Eigen::Index j = 0; j < B.cols(); ++j) {
    Complex* b = B.col(j).data();
    for (Eigen::Index k = 0; k + 1 < n; ++k) {
      const Complex bk = b[k];
      if (bk == 0.0) continue;
      const Complex* l = L + k * n;
      for (Eigen::Index i = k + 1; i < n; ++i) b[i] -= bk * l[i];
    }
    for (Eigen::Index k = n - 1; k >= 0; --k) {
      b[k] *= inverse_(k);
      const Complex bk = b[k];
      const Complex* u = L + k * n;
      for (Eigen::Index i = 0; i < k; ++i) b[i] -= bk * u[i];
    }
  }
}

Eigen::MatrixXcd HousingCondensation::physical(const Eigen::MatrixXcd& y) const {
  return realTimes(Phi, y);
}

Eigen::MatrixXcd HousingCondensation::keptRows(const Eigen::MatrixXcd& y) const {
  return realTimes(Phi_kept, y);
}

Eigen::MatrixXcd HousingCondensation::points(const Eigen::MatrixXcd& y) const {
  return realTimes(points_Phi, y);
}

Eigen::MatrixXcd HousingCondensation::modal(const Eigen::MatrixXcd& F) const {
  return realTransposeTimes(W, F);
}

HousingReceptances HousingReceptances::at(const HousingCondensation& h,
                                          const std::vector<double>& w) {
  HousingReceptances out;
  out.w = w;
  const Eigen::Index count = static_cast<Eigen::Index>(w.size());
  out.dinv.resize(h.lambda.size(), count);
  out.g.resize(h.P.rows(), count);
  // The static block (w = 0, the harmonic h = 0) from the condensation; the others in one
  // product, every G(w_j) = W diag(1/d) Wᵀ (w_j ≠ 0 follow the static one: h = 1, 2, ...).
  const Eigen::Index first = count > 0 && w[0] == 0.0 ? 1 : 0;
  if (first == 1) {
    out.dinv.col(0) = h.dinv_static;
    out.g.col(0) = h.g_static;
  }
  for (Eigen::Index j = first; j < count; ++j) {
    out.dinv.col(j) = modalReceptances(h, w[static_cast<std::size_t>(j)]);
  }
  if (count > first)
    out.g.rightCols(count - first) = realTimes(h.P, out.dinv.rightCols(count - first));
  return out;
}

void CondensedHousingBlock::factorize(const HousingCondensation& h, Eigen::MatrixXcd Dtt,
                                      double w) {
  const Eigen::VectorXcd dinv = modalReceptances(h, w);
  factorize(h, std::move(Dtt), w, dinv, realTimes(h.P, dinv));
}

void CondensedHousingBlock::factorize(const HousingCondensation& h, Eigen::MatrixXcd Dtt, double w,
                                      const Eigen::Ref<const Eigen::VectorXcd>& dinv,
                                      const Eigen::Ref<const Eigen::VectorXcd>& g) {
  const Complex iw(0.0, w);
  dinv_ = dinv;
  const auto r = h.k.rows();
  Eigen::MatrixXcd A(r, r);  // I + Z G, G = W diag(1/d) Wᵀ from its upper triangle g
  Eigen::MatrixXcd ZJ(r, h.Jc.cols());
  if (h.Z_diagonal) {  // Z G is G's rows scaled: formed from g directly, Z kept as its diagonal
    z_ = h.k.diagonal().cast<Complex>() + iw * h.c.diagonal().cast<Complex>();
    Z_.resize(0, 0);
    Eigen::Index row = 0;
    for (Eigen::Index j = 0; j < r; ++j) {
      for (Eigen::Index i = 0; i <= j; ++i, ++row) {
        A(i, j) = z_(i) * g(row);
        A(j, i) = z_(j) * g(row);
      }
    }
    ZJ = z_.asDiagonal() * h.Jc.cast<Complex>();
  } else {
    Eigen::MatrixXcd G(r, r);
    Eigen::Index row = 0;
    for (Eigen::Index j = 0; j < r; ++j) {
      for (Eigen::Index i = 0; i <= j; ++i) G(i, j) = G(j, i) = g(row++);
    }
    Z_ = h.k.cast<Complex>() + iw * h.c.cast<Complex>();
    A.noalias() = Z_ * G;
    ZJ.noalias() = Z_ * h.Jc.cast<Complex>();
  }
  A.diagonal().array() += 1.0;
  seat_lu_.compute(A);
  // Z_eff J = (I + Z G)⁻¹ Z J on J's c columns: c right-hand sides instead of r for Z_eff.
  if (h.Jc.cols() <= r) {
    ZeffJ_ = ZJ;
    seat_lu_.solveInPlace(ZeffJ_);
  } else {
    Eigen::MatrixXcd Zeff = Z_.size() > 0 ? Z_ : Eigen::MatrixXcd(z_.asDiagonal());
    seat_lu_.solveInPlace(Zeff);
    ZeffJ_.noalias() = Zeff * h.Jc.cast<Complex>();
  }
  // D_tt + Jᵀ (Z_eff − Z) J, on J's columns.
  Dtt(h.J_columns, h.J_columns) += h.JcT * (ZeffJ_ - ZJ);
  lu_.compute(Dtt);
}

Eigen::MatrixXcd CondensedHousingBlock::zeff(const Eigen::MatrixXcd& x) const {
  Eigen::MatrixXcd out =
      Z_.size() > 0 ? Eigen::MatrixXcd(Z_ * x) : Eigen::MatrixXcd(z_.asDiagonal() * x);
  seat_lu_.solveInPlace(out);
  return out;
}

Eigen::MatrixXcd CondensedHousingBlock::solve(const HousingCondensation& h,
                                              const Eigen::MatrixXcd& rhs) const {
  const Eigen::Index n_t = h.first, n_h = h.Phi.rows();
  Eigen::MatrixXcd out(n_t + n_h, rhs.cols());
  // The train's loads (mesh vectors, static load, excitations) leave the housing's rows zero:
  // then Φᵀ f_h and g vanish and two n_h × n_h products per column are skipped.
  if (rhs.bottomRows(n_h).isZero(0.0)) {
    out.topRows(n_t) = lu_.solve(rhs.topRows(n_t));
    out.bottomRows(n_h) = housingRows(h, out.topRows(n_t));
    return out;
  }
  const Eigen::MatrixXcd p = realTransposeTimes(h.Phi, rhs.bottomRows(n_h));  // Φᵀ f_h
  const Eigen::MatrixXcd g = realTimes(h.W, dinv_.asDiagonal() * p);          // J_H D_h0⁻¹ f_h
  out.topRows(n_t) = lu_.solve(rhs.topRows(n_t) + realTransposeTimes(h.J, zeff(g)));
  const Eigen::MatrixXcd F = zeff(realTimes(h.J, out.topRows(n_t)) - g);  // bearing forces
  out.bottomRows(n_h) = realTimes(h.Phi, dinv_.asDiagonal() * (realTransposeTimes(h.W, F) + p));
  return out;
}

Eigen::MatrixXcd CondensedHousingBlock::modalAmplitudes(const HousingCondensation& h,
                                                        const Eigen::MatrixXcd& q_t) const {
  return dinv_.asDiagonal() * h.modal(bearingForces(h, q_t));
}

void CondensedHousingBlock::bearingForces(const HousingCondensation& h,
                                          const Eigen::Ref<const Eigen::VectorXcd>& q_t,
                                          Eigen::Ref<Eigen::VectorXcd> F) const {
  F.setZero();
  for (std::size_t c = 0; c < h.J_columns.size(); ++c) {
    F += ZeffJ_.col(static_cast<Eigen::Index>(c)) * q_t(h.J_columns[c]);
  }
}

Eigen::MatrixXcd CondensedHousingBlock::bearingForces(const HousingCondensation& h,
                                                      const Eigen::MatrixXcd& q_t) const {
  return ZeffJ_ * q_t(h.J_columns, Eigen::all);
}

Eigen::MatrixXcd CondensedHousingBlock::housingRows(const HousingCondensation& h,
                                                    const Eigen::MatrixXcd& q_t) const {
  return h.physical(modalAmplitudes(h, q_t));
}

}  // namespace geardyn::detail
