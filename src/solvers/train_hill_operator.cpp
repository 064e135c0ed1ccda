/// The shift-invert operator of the gear train's Hill matrix (detail/train_hill_operator.h).

#include "geardyn/solvers/detail/train_hill_operator.h"

namespace geardyn::detail {

using Complex = std::complex<double>;

namespace {
/// Largest entry of 𝓖(h) − 𝓑(h) over the largest of 𝓑(h), per harmonic, below which the
/// balance's Jacobian is taken as Hill's capacitance: round-off only. The two are the same matrix
/// in exact arithmetic when the rigid-body modes decouple from the elastic ones
/// (docs/theory/nonlinear_gear_trains.md, "Reusing the balance's factors"), computed by
/// different LUs: measured 1.6e-15 apart on the 3-planet sweep's 201 bench points. Lin &
/// Parker's carrier-frame terms couple the rolling mode (its Coriolis terms), which Hill's
/// elastic subspace leaves out and the balance keeps: 6e-6 apart at h = 1, falling as h⁻².
/// Taken anyway (at 1e-4), they moved max Re λ by 1.1e-6 ω along that sweep, above the
/// neutral band kNeutralMultiplier/T = 1.6e-7 ω, so such trains factorise their own.
constexpr double kJacobianAgreement = 1e-8;
}  // namespace

void TrainHillShiftSolve::reset(const TrainHillProblem& problem) {
  p_ = &problem;
  n_ = static_cast<int>(problem.M.rows());
  r_ = static_cast<int>(problem.V.cols());
  h_ = problem.harmonics;
  nc_ = 2 * problem.harmonics + 1;
  Ar_.resize(h_ + 1);
  Ai_.resize(h_ + 1);
  As_.resize(h_ + 1);
  Z_.resize(h_ + 1);
  complex_R_.resize(h_ + 1);
  complex_Z_.resize(h_ + 1);
  vector_ad_.assign(h_ + 1, Eigen::VectorXcd(n_ + r_));
  vector_u_.assign(h_ + 1, Eigen::VectorXcd(2 * n_));
  vector_zc_.resize(r_);
  vector_e_.resize(r_ * nc_);
  vector_w_.resize(r_ * nc_);
  vector_z_.resize(r_ * nc_);
  s_.resize(h_ + 1);
  ad_.resize(h_ + 1);
  shifted_ = false;
}

void TrainHillShiftSolve::set_shift(double sigma) {
  if (shifted_ && sigma == sigma_) return;
  shifted_ = true, sigma_ = sigma;
  complex_ready_ = false;
  const Eigen::MatrixXd &M = p_->M, &C = p_->C, &K = p_->K, &V = p_->V;
  const int n = n_, r = r_, n2 = 2 * n_, width = 2 * n_ + r_;
  G_.resize(h_ + 1);
  // D(s) = A + iB, A = K + σC + (σ² − h²ω²)M, B = hω(C + 2σM), solved in its real form
  // [A −B; B A] (real arithmetic: without AVX, Eigen's small complex products are the slower):
  // D⁻¹[C + sM, M, V] (right-hand side Re [C + σM, M, V], Im [hωM, 0, 0]) in one solve, then
  // Vᵀ times it (Vᵀa's rows and G = VᵀD⁻¹V at once).
  Eigen::MatrixXd& F = harmonic_matrix_;
  F.resize(n2, n2);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n2, width);
  rhs.topLeftCorner(n, n2) << C + sigma * M, M;
  rhs.topRightCorner(n, r) = V;
  Eigen::MatrixXd X(n2, width);
  for (int h = 0; h <= h_; ++h) {
    const double hw = h * p_->omega;
    s_[h] = Complex(sigma, hw);
    F.topLeftCorner(n, n) = K + sigma * C + (sigma * sigma - hw * hw) * M;
    F.bottomRightCorner(n, n) = F.topLeftCorner(n, n);
    F.bottomLeftCorner(n, n) = hw * (C + 2.0 * sigma * M);
    F.topRightCorner(n, n) = -F.bottomLeftCorner(n, n);
    harmonic_lu_.compute(F);
    rhs.bottomLeftCorner(n, n) = hw * M;
    X.noalias() = harmonic_lu_.solve(rhs);  // (Re; Im) of D⁻¹[C + sM, M, V]
    const auto Xr = X.topRows(n), Xi = X.bottomRows(n);
    G_[h].resize(r, r);
    G_[h].real().noalias() = V.transpose() * Xr.rightCols(r);
    G_[h].imag().noalias() = V.transpose() * Xi.rightCols(r);
    // a = R u with R = −D⁻¹[C + sM, M] = Ar + iAi (and As = Ar + Ai for Gauss's three real
    // products); Z = D⁻¹V in real block form.
    Ar_[h] = -Xr.leftCols(n2);
    if (h == 0) {  // s = σ real: every factor real
      Z_[h] = Xr.rightCols(r);
      continue;
    }
    Ai_[h] = -Xi.leftCols(n2);
    As_[h] = Ar_[h] + Ai_[h];
    Z_[h].resize(n2, 2 * r);
    Z_[h] << Xr.rightCols(r), -Xi.rightCols(r), Xi.rightCols(r), Xr.rightCols(r);
  }
  jacobian_ = nullptr;
  if (sigma == 0.0 && p_->jacobian && jacobianAgrees()) {
    jacobian_ = p_->jacobian;
    return;
  }
  const std::vector<Eigen::MatrixXcd>& G = G_;
  // Capacitance I + 𝓖𝓢 (coordinate-major, 2H + 1 coefficients each): G(h) acts per harmonic
  // as the 2 × 2 real form of a complex number on the rows of 𝓢's blocks.
  const int rho = r_ * nc_;
  Eigen::MatrixXd& Kc = capacitance_matrix_;
  Kc.setIdentity(rho, rho);
  for (const TrainHillProblem::Block& b : p_->slopes) {
    const Eigen::MatrixXd& JF = b.galerkin;
    for (int mr = 0; mr < r_; ++mr) {
      auto block = Kc.block(mr * nc_, b.j * nc_, nc_, nc_);
      block.row(0) += G[0](mr, b.i).real() * JF.row(0);
      for (int h = 1; h <= h_; ++h) {
        const double gr = G[h](mr, b.i).real(), gi = G[h](mr, b.i).imag();
        block.row(2 * h - 1) += gr * JF.row(2 * h - 1) + gi * JF.row(2 * h);
        block.row(2 * h) += -gi * JF.row(2 * h - 1) + gr * JF.row(2 * h);
      }
    }
  }
  capacitance_.compute(Kc);
}

bool TrainHillShiftSolve::jacobianAgrees() const {
  const std::vector<Eigen::MatrixXcd>* B = p_->jacobian_blocks;
  if (!B || static_cast<int>(B->size()) != h_ + 1) return false;
  if (p_->jacobian->rows() != static_cast<Eigen::Index>(r_) * nc_) return false;
  for (int h = 0; h <= h_; ++h) {
    const Eigen::MatrixXcd& b = (*B)[h];
    if (b.rows() != r_ || b.cols() != r_) return false;
    const double scale = b.cwiseAbs().maxCoeff();
    if (!((G_[h] - b).cwiseAbs().maxCoeff() <= kJacobianAgreement * scale)) return false;
  }
  return true;
}

void TrainHillShiftSolve::multiply(const double* X, Eigen::Index k) const {
  // a = R u per harmonic, u = (f_x, f_v) = x_cos − i x_sin: a of g = 𝓓⁻¹f, where
  // (A₀ − s)(a, b) = f ⇔ a = −D(s)⁻¹(M f_v + (C + sM) f_x), b = f_x + sa. The
  // complex product by Gauss's three real ones: with P₁ = Ar x_cos, Q = Ai x_sin,
  // P₃ = (Ar + Ai)(x_cos − x_sin): Re a = P₁ + Q, Im a = P₃ − P₁ + Q.
  const Eigen::Index N = rows(), n = n_, n2 = 2 * n_;
  const Eigen::Map<const Eigen::MatrixXd> x(X, N, k);
  for (int h = 0; h <= h_; ++h) {
    if (h == 0) {
      ad_[0].noalias() = Ar_[0] * x.topRows(n2);
      continue;
    }
    const auto xc = x.middleRows((2 * h - 1) * n2, n2), xs = x.middleRows(2 * h * n2, n2);
    ad_[h].resize(n2, k);
    auto re = ad_[h].topRows(n), im = ad_[h].bottomRows(n);
    product_.noalias() = Ar_[h] * xc;  // P₁
    re.noalias() = Ai_[h] * xs;        // Q
    difference_ = xc - xs;
    im.noalias() = As_[h] * difference_;  // P₃
    im += re - product_;
    re += product_;
  }
}

void TrainHillShiftSolve::finish(const double* X, double* Y, Eigen::Index k,
                                 double* at_zero) const {
  const Eigen::Index N = rows(), n = n_, n2 = 2 * n_;
  // X null: the comb 𝛅 (k = 2n), whose x rows are I on the constant, 2I on every cosine, 0 on
  // every sine. at_zero: only C y (2n × k, the Fourier series at t = 0), Y unused.
  const bool comb = X == nullptr;
  const Eigen::Map<const Eigen::MatrixXd> x(comb ? (at_zero ? at_zero : Y) : X, comb ? n2 : N, k);
  Eigen::Map<Eigen::MatrixXd> y(at_zero ? at_zero : Y, at_zero ? n2 : N, k);
  // e = 𝓒ᵀ g = Vᵀa per harmonic, coordinate-major real (cos: Re, sin: −Im).
  const Eigen::MatrixXd& V = p_->V;
  e_.resize(r_ * nc_, k);
  for (int h = 0; h <= h_; ++h) {
    d_.noalias() = V.transpose() * ad_[h].topRows(n);
    for (int m = 0; m < r_; ++m) e_.row(m * nc_ + (h == 0 ? 0 : 2 * h - 1)) = d_.row(m);
    if (h == 0) continue;
    d_.noalias() = V.transpose() * ad_[h].bottomRows(n);
    for (int m = 0; m < r_; ++m) e_.row(m * nc_ + 2 * h) = -d_.row(m);
  }
  // w = (I + 𝓖𝓢)⁻¹ 𝓒ᵀ g, z = 𝓢 w.
  w_.noalias() = capacitance().solve(e_);
  z_.setZero(r_ * nc_, k);
  for (const TrainHillProblem::Block& b : p_->slopes) {
    z_.middleRows(b.i * nc_, nc_).noalias() += b.galerkin * w_.middleRows(b.j * nc_, nc_);
  }
  // y = g − 𝓓⁻¹𝓑 z: 𝓑 z = (0, −M⁻¹V z) gives a −= D(s)⁻¹ V z, then b = f_x + s a.
  zc_.resize(2 * r_, k);  // (Re, Im) of a harmonic's z
  for (int h = 0; h <= h_; ++h) {
    if (h == 0) {
      for (int m = 0; m < r_; ++m) zc_.row(m) = z_.row(m * nc_);
      auto a = ad_[0].topRows(n);
      a.noalias() -= Z_[0] * zc_.topRows(r_);
      y.topRows(n) = a;
      y.middleRows(n, n) = sigma_ * a;
      if (comb) {
        y.middleRows(n, n).leftCols(n).diagonal().array() += 1.0;
      } else {
        y.middleRows(n, n) += x.topRows(n);
      }
      continue;
    }
    for (int m = 0; m < r_; ++m) {
      zc_.row(m) = z_.row(m * nc_ + 2 * h - 1);
      zc_.row(r_ + m) = -z_.row(m * nc_ + 2 * h);
    }
    ad_[h].noalias() -= Z_[h] * zc_;  // in place: ad_ is not read again
    const double hw = h * p_->omega;
    const auto ar = ad_[h].topRows(n), ai = ad_[h].bottomRows(n);
    const Eigen::Index c = (2 * h - 1) * n2, s = 2 * h * n2;
    // f_x = x_cos − i x_sin; b = f_x + (σ + ihω) a; outputs (Re, −Im) of (a, b).
    if (at_zero) {  // the cosine rows summed (the sines vanish at t = 0)
      y.topRows(n) += ar;
      y.bottomRows(n) += sigma_ * ar - hw * ai;
      if (comb) {
        y.bottomRows(n).leftCols(n).diagonal().array() += 2.0;
      } else {
        y.bottomRows(n) += x.middleRows(c, n);
      }
      continue;
    }
    y.middleRows(c, n) = ar;
    y.middleRows(c + n, n) = sigma_ * ar - hw * ai;
    y.middleRows(s, n) = -ai;
    y.middleRows(s + n, n) = -sigma_ * ai - hw * ar;
    if (comb) {
      y.middleRows(c + n, n).leftCols(n).diagonal().array() += 2.0;
    } else {
      y.middleRows(c + n, n) += x.middleRows(c, n);
      y.middleRows(s + n, n) += x.middleRows(s, n);
    }
  }
}

void TrainHillShiftSolve::perform_op(const double* x_in, double* y_out) const {
  // The steps of apply on one vector, with complex products (faster than the real block forms
  // on a single column), read off the block forms on first use after set_shift.
  const int n = n_, n2 = 2 * n_;
  if (!complex_ready_) {
    const Eigen::MatrixXd& V = p_->V;
    for (int h = 0; h <= h_; ++h) {
      complex_R_[h].resize(n + r_, n2);
      complex_Z_[h].resize(n, r_);
      complex_R_[h].topRows(n).real() = Ar_[h];
      complex_Z_[h].real() = Z_[h].topLeftCorner(n, r_);
      if (h == 0) {
        complex_R_[h].topRows(n).imag().setZero();
        complex_Z_[h].imag().setZero();
      } else {
        complex_R_[h].topRows(n).imag() = Ai_[h];
        complex_Z_[h].imag() = Z_[h].bottomLeftCorner(n, r_);
      }
      complex_R_[h].bottomRows(r_).noalias() =
          V.cast<Complex>().transpose() * complex_R_[h].topRows(n);
    }
    complex_ready_ = true;
  }
  for (int h = 0; h <= h_; ++h) {
    Eigen::VectorXcd& u = vector_u_[h];  // (f_x, f_v)
    if (h == 0) {
      for (int i = 0; i < n2; ++i) u(i) = x_in[i];
    } else {
      const double *c = x_in + (2 * h - 1) * n2, *s = x_in + 2 * h * n2;
      for (int i = 0; i < n2; ++i) u(i) = Complex(c[i], -s[i]);
    }
    vector_ad_[h].noalias() = complex_R_[h] * u;  // (a, Vᵀa) of g = 𝓓⁻¹f
    const auto d = vector_ad_[h].tail(r_);
    for (int m = 0; m < r_; ++m) {
      if (h == 0) {
        vector_e_(m * nc_) = d(m).real();
      } else {
        vector_e_(m * nc_ + 2 * h - 1) = d(m).real();
        vector_e_(m * nc_ + 2 * h) = -d(m).imag();
      }
    }
  }
  vector_w_.noalias() = capacitance().solve(vector_e_);
  vector_z_.setZero();
  for (const TrainHillProblem::Block& b : p_->slopes) {
    vector_z_.segment(b.i * nc_, nc_).noalias() += b.galerkin * vector_w_.segment(b.j * nc_, nc_);
  }
  for (int h = 0; h <= h_; ++h) {
    for (int m = 0; m < r_; ++m) {
      vector_zc_(m) = h == 0 ? Complex(vector_z_(m * nc_))
                             : Complex(vector_z_(m * nc_ + 2 * h - 1), -vector_z_(m * nc_ + 2 * h));
    }
    auto a = vector_ad_[h].head(n);
    a.noalias() -= complex_Z_[h] * vector_zc_;
    const Complex s = s_[h];
    double *yc = y_out + (h == 0 ? 0 : (2 * h - 1) * n2), *ys = y_out + 2 * h * n2;
    for (int i = 0; i < n; ++i) {
      const Complex b = vector_u_[h](i) + s * a(i);
      yc[i] = a(i).real();
      yc[n + i] = b.real();
      if (h > 0) ys[i] = -a(i).imag(), ys[n + i] = -b.imag();
    }
  }
}

void TrainHillShiftSolve::apply(const Eigen::MatrixXd& X, Eigen::MatrixXd& Y) const {
  Y.resize(X.rows(), X.cols());
  multiply(X.data(), X.cols());
  finish(X.data(), Y.data(), X.cols());
}

void TrainHillShiftSolve::applyAtZero(const Eigen::MatrixXd& X, Eigen::MatrixXd& S) const {
  S.resize(2 * n_, X.cols());
  multiply(X.data(), X.cols());
  finish(X.data(), nullptr, X.cols(), S.data());
}

void TrainHillShiftSolve::applyToComb(Eigen::MatrixXd& Y) const {
  const Eigen::Index n2 = 2 * n_;
  // R 𝛅 per harmonic: R's constant columns, twice its cosine columns (the sines are 0).
  ad_[0] = Ar_[0];
  for (int h = 1; h <= h_; ++h) {
    ad_[h].resize(n2, n2);
    ad_[h].topRows(n_) = 2.0 * Ar_[h];
    ad_[h].bottomRows(n_) = 2.0 * Ai_[h];
  }
  Y.resize(rows(), n2);
  finish(nullptr, Y.data(), n2);
}

}  // namespace geardyn::detail
