#pragma once
/// \file
/// Harmonic balance for the gear-pair model (Saletti, Battiato & Zucca 2025, eqs. 9–12, in
/// the coupled static/dynamic form: the mean term is an unknown like the harmonics):
///
///   y(τ) = a₀ + Σ_{h=1..H} a_h cos hτ + b_h sin hτ,   τ = ω t = 2π φ,
///   R(q, ω) = L(ω) q + F_nl(q) − F_ext(ω) = 0,   q = [a₀, a₁, b₁, …, a_H, b_H],
///
/// with the linear part of m y″ + c y′ and the Fourier coefficients of the mesh force
/// k(φ) g(y − e(φ)) computed by AFT (inverse real FFT to N samples, the force in the time
/// domain, forward real FFT; FFTW plans made once). The Jacobian of the scalar nonlinearity is
/// assembled from the FFT of df/dy at the samples (its Toeplitz + Hankel structure), never by
/// finite differences. Newton–Raphson, pseudo-arclength continuation in ω through folds
/// (continuation.h), and stability by the sampled monodromy matrix (the default, O(N)) or
/// Hill's method (sorted Floquet exponents, the cross-check).

#include <fftw3.h>

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "geardyn/solvers/continuation.h"
#include "geardyn/system/gear_pair_model.h"

namespace geardyn {

struct HarmonicBalanceOptions {
  int harmonics = 14;            ///< H
  int samples_per_period = 256;  ///< N (> 2H)
  double tolerance = 1e-10;  ///< ‖R‖ / (|F̄| + ‖F_ext‖ + k̄ ‖q‖) (relative, see residualNorm)
  int max_iterations = 40;
  void validate() const;
};

class HarmonicBalance final : public ContinuationProblem {
 public:
  HarmonicBalance(const GearPairModel& model, const HarmonicBalanceOptions& options);
  ~HarmonicBalance();
  HarmonicBalance(const HarmonicBalance&) = delete;
  HarmonicBalance& operator=(const HarmonicBalance&) = delete;

  int size() const noexcept override { return n_; }
  int harmonics() const noexcept { return h_; }
  int samples() const noexcept { return samples_; }

  /// R(q, ω) and, if wanted, ∂R/∂q and ∂R/∂ω (analytic through the AFT).
  void residual(const Eigen::VectorXd& q, double omega, Eigen::VectorXd& r, Eigen::MatrixXd* dr_dq,
                Eigen::VectorXd* dr_domega) override;
  /// The relative residual norm used for convergence: ‖R‖ / scale, scale = |F| + k̄ ‖q‖ + ‖F_ext‖.
  double residualNorm(const Eigen::VectorXd& q, const Eigen::VectorXd& r,
                      double omega) const override;

  /// Newton at fixed ω from the guess in point.q.
  void solve(HarmonicBalancePoint& point) override;
  Eigen::VectorXd startingGuess(double omega) override { return linearGuess(omega); }
  /// Stability by `method` (stability() or stabilityMonodromy()).
  void classify(HarmonicBalancePoint& point, StabilityMethod method, bool samples_current) override;

  /// Stability by Hill's method: the quadratic eigenproblem (λ² m + λ (c + 2m D) + J) p = 0 in the
  /// Fourier basis; the two exponents with the smallest |Im λ| are the Floquet exponents.
  void stability(HarmonicBalancePoint& point);

  /// Stability from the monodromy matrix of the variational equation m δ″ + c δ′ + f′(t) δ = 0
  /// along the solution, with f′ = ∂f/∂y held at its sample value over each of the N intervals:
  /// the product of N exact 2×2 matrix exponentials (O(N), ~100× cheaper than Hill's method;
  /// first order in the switching instants of a piecewise-linear contact).
  /// `samples_current`: the last residual() call was at point.q (its df samples are reused).
  void stabilityMonodromy(HarmonicBalancePoint& point, bool samples_current = false);

  /// x(τ) at N samples over one period from coefficients.
  std::vector<double> timeSignal(const Eigen::VectorXd& q) const;
  /// Fourier coefficients (a₀, a₁, b₁, …) of N samples over one period (forward real FFT).
  void coefficientsOf(const std::vector<double>& samples, Eigen::VectorXd& coefficients) {
    forward(samples.data(), coefficients, n_);
  }
  /// The mesh force at the same samples.
  std::vector<double> meshForceSignal(const Eigen::VectorXd& q, double omega) const;
  /// Fourier coefficients of the external force F + c e′(t) at ω, and their ω-derivative.
  void externalForce(double omega, Eigen::VectorXd& f, Eigen::VectorXd* df_domega) const;
  /// A guess: the exact response with the teeth held in contact (the contact law replaced by
  /// its loaded-flank branch), i.e. the linear time-varying solution.
  Eigen::VectorXd linearGuess(double omega);

 private:
  void forward(const double* samples, Eigen::VectorXd& coefficients, int count);
  void inverseToBuffer(const Eigen::VectorXd& q);

  const GearPairModel& model_;
  HarmonicBalanceOptions options_;
  int h_, n_, samples_;
  double k_mean_;
  std::vector<double> phases_, error_, error_rate_, stiffness_;  // per sample (fixed phases)
  // Contact elements (model.hasContactElements()): stiffness and gap of element j at sample i,
  // at [i * elements_ + j].
  int elements_ = 0;
  std::vector<double> element_stiffness_, element_gap_;
  /// The mesh force at sample i for the deflection y, and dF/dy in *slope.
  double sampleForce(int i, double y, double* slope) const;
  // FFTW workspaces and plans (created once).
  double* real_buffer_;
  fftw_complex* complex_buffer_;
  fftw_plan forward_plan_, inverse_plan_;
  std::vector<double> f_, df_;
  Eigen::VectorXd error_coefficients_, error_rate_coefficients_;  // of e(φ) and de/dφ
  Eigen::VectorXd fnl_, fext_, dfext_;                            // residual workspace
  std::vector<double> de_d_, de_e_;  // FFT of df/dy at −2H..2H (the Jacobian's entries)
  bool linearized_ = false;          // linearGuess: g(y) = y − linear_shift_
  double linear_shift_ = 0.0;
};

}  // namespace geardyn
