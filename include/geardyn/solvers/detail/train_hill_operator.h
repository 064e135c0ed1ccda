#pragma once
/// \file
/// y = (𝓗 − σ)⁻¹x for the gear train's Hill matrix 𝓗 = 𝓐₀ − 𝓓ₜ + 𝓑𝓢𝓒ᵀ (train_hill.h), on one
/// vector (Spectra's and the Arnoldi runs' operator interface) or on a block of columns (the
/// resolvent projection, train_hill.h). Per harmonic h the block A₀ − s_h (s_h = σ + ihω) through
/// D(s_h) = s²M + sC + K̄, the periodic part by Woodbury:
///   (𝓓 + 𝓑𝓢𝓒ᵀ)⁻¹ = 𝓓⁻¹ − 𝓓⁻¹𝓑𝓢 (I + 𝓒ᵀ𝓓⁻¹𝓑𝓢)⁻¹ 𝓒ᵀ𝓓⁻¹,  𝓒ᵀ𝓓⁻¹𝓑 = blockdiag(Vᵀ D(s_h)⁻¹ V).
/// Real vectors: coefficient-major (0, cos 1, sin 1, …), the state (x, x′) within; a
/// coefficient pair (a_h, b_h) is the complex a_h − i b_h of Re[(a − ib) e^{ihωt}]. A block of
/// columns goes through real matrix products (a harmonic's complex product as Gauss's three
/// real ones), one vector through complex ones.

#include <Eigen/Dense>
#include <complex>
#include <vector>

#include "geardyn/solvers/detail/train_hill.h"

namespace geardyn::detail {

class TrainHillShiftSolve {
 public:
  using Scalar = double;

  TrainHillShiftSolve() = default;
  /// reset(problem).
  explicit TrainHillShiftSolve(const TrainHillProblem& problem) { reset(problem); }

  /// The operator of `problem` (kept by reference until the next reset: it must outlive the
  /// use), unshifted; the buffers stay allocated, so that a sweep reuses them point to point.
  void reset(const TrainHillProblem& problem);

  Eigen::Index rows() const { return 2 * n_ * nc_; }
  Eigen::Index cols() const { return rows(); }

  /// The factors the operator applies (set once, so that applying only multiplies): per
  /// harmonic R = −D(s)⁻¹[C + sM, M] (n × 2n, complex: its real and imaginary parts) and
  /// Z = D(s)⁻¹V, and the capacitance's LU (at σ = 0 the harmonic balance's, when the problem
  /// carries it and its blocks agree: reusesJacobian()). σ [1/s] real.
  void set_shift(double sigma);
  /// The capacitance is the problem's TrainHillProblem::jacobian (set_shift(0) took it).
  bool reusesJacobian() const { return jacobian_ != nullptr; }

  /// y = (𝓗 − σ)⁻¹x, x and y rows() long (Spectra's interface). Allocation-free after the
  /// first call.
  void perform_op(const double* x_in, double* y_out) const;

  /// Y = (𝓗 − σ)⁻¹X for the k columns of X (rows() × k; Y is resized).
  void apply(const Eigen::MatrixXd& X, Eigen::MatrixXd& Y) const;

  /// S = C (𝓗 − σ)⁻¹X (2n × k): the result's Fourier series at t = 0, the constant and every
  /// cosine coefficient summed, without forming it (S is resized).
  void applyAtZero(const Eigen::MatrixXd& X, Eigen::MatrixXd& S) const;

  /// Y = (𝓗 − σ)⁻¹𝛅 for the 2n columns of the Dirac comb 𝛅 (1 on the constant, 2 on every
  /// cosine coefficient of each state coordinate): the first step needs no product.
  void applyToComb(Eigen::MatrixXd& Y) const;

 private:
  /// The common steps from ad_ (−R X per harmonic) on: Y (rows() × k) from X's state rows (X
  /// null: the comb 𝛅, k = 2n).
  void finish(const double* X, double* Y, Eigen::Index k, double* at_zero = nullptr) const;
  void multiply(const double* X, Eigen::Index k) const;  // ad_ = −R X
  /// 𝓖 = 𝓑 within kJacobianAgreement: the balance's factors are the capacitance's.
  bool jacobianAgrees() const;
  const Eigen::PartialPivLU<Eigen::MatrixXd>& capacitance() const {
    return jacobian_ ? *jacobian_ : capacitance_;
  }

  const TrainHillProblem* p_ = nullptr;
  int n_ = 0, r_ = 0, h_ = 0, nc_ = 1;
  bool shifted_ = false;
  double sigma_ = 0.0;
  // a = R u, R = −D⁻¹[C + sM, M] = Ar + iAi per harmonic, As = Ar + Ai (h = 0: Ar, real); Z
  // = D⁻¹V in real block form (h = 0 real).
  std::vector<Eigen::MatrixXd> Ar_, Ai_, As_, Z_;
  // The complex R and Z per harmonic (one vector: a complex product beats the block form's).
  mutable std::vector<Eigen::MatrixXcd> complex_R_, complex_Z_;
  mutable bool complex_ready_ = false;
  std::vector<std::complex<double>> s_;
  std::vector<Eigen::MatrixXcd> G_;  // Vᵀ D(s_h)⁻¹ V per harmonic
  Eigen::MatrixXd harmonic_matrix_;  // [A −B; B A] of D(s_h) = A + iB
  Eigen::PartialPivLU<Eigen::MatrixXd> harmonic_lu_;
  Eigen::MatrixXd capacitance_matrix_;
  Eigen::PartialPivLU<Eigen::MatrixXd> capacitance_;
  const Eigen::PartialPivLU<Eigen::MatrixXd>* jacobian_ = nullptr;  // the balance's, reused
  // Workspace, sized to the block's width on first use: a harmonic's Vᵀ(Re a) or Vᵀ(Im a), the
  // capacitance's right-hand sides, solution and 𝓢w, a harmonic's (Re, Im) of 𝓢w, and Gauss's
  // P₁ and x_cos − x_sin.
  mutable std::vector<Eigen::MatrixXd> ad_;  // per harmonic (Re a; Im a)
  mutable Eigen::MatrixXd d_, e_, w_, z_, zc_, product_, difference_;
  mutable std::vector<Eigen::VectorXcd> vector_ad_, vector_u_;  // perform_op's workspace
  mutable Eigen::VectorXcd vector_zc_;
  mutable Eigen::VectorXd vector_e_, vector_w_, vector_z_;
};

}  // namespace geardyn::detail
