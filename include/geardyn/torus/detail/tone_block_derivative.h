#pragma once
/// \file
/// The speed derivative of a harmonic block as sparse real operators: for the torus balance
/// (train_torus_balance.h), D(ω_p) = K̄(Ω) − ω_p² M + i ω_p C(Ω) with ω_p = ρ_p ω and Ω ∝ ω, so
///
///   dD/dω = dΩ/dω (2Ω K_Ω + i ω_p G₁) − 2 ω_p ρ_p M + i ρ_p C(Ω)
///
/// (K̄ = K + Ω²K_Ω + Σ k̄_m v_m v_mᵀ, C(Ω) = C + ΩG₁; gear_train_model.h). dD/dω Z is applied
/// through M, K_Ω, G₁ and C (banded on FE trains) to the real and imaginary parts of Z: no
/// dense n × n complex matrix per tone (docs/theory/torus_harmonic_balance.md, "Cost of the
/// nonlinear sweep").

#include <Eigen/Dense>
#include <Eigen/SparseCore>

namespace geardyn::detail {

class ToneBlockDerivative {
 public:
  /// M [kg], K_Ω per Ω² [kg], G₁ per Ω [kg] (K_Ω and G₁ may be empty: no speed dependence).
  ToneBlockDerivative(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K_omega,
                      const Eigen::MatrixXd& G);
  /// C(Ω) [N s/m] at the input speed Ω [rad/s]; dΩ/dω [-].
  void setSpeed(const Eigen::MatrixXd& C, double speed, double dspeed_domega);
  /// dD/dω Z for the tone of angular frequency w = ρ ω [rad/s] and ratio ρ [-] (the zero tone:
  /// w = ρ = 0, dK̄/dω Z).
  Eigen::MatrixXcd times(const Eigen::MatrixXcd& Z, double w, double rate) const;
  /// dK̄/dω x [N/m per rad/s · m].
  Eigen::VectorXd stiffnessTimes(const Eigen::VectorXd& x) const;
  /// K̄ depends on the speed (K_Ω ≠ 0).
  bool stiffnessMoves() const noexcept { return K_omega_.nonZeros() > 0; }

 private:
  using Sparse = Eigen::SparseMatrix<double>;
  Eigen::MatrixXd applyReal(double w, double rate, const Eigen::MatrixXd& x) const;
  Sparse M_, K_omega_, G_, C_;
  double speed_ = 0.0, dspeed_ = 0.0;
};

}  // namespace geardyn::detail
