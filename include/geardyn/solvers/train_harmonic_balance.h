#pragma once
/// \file
/// Harmonic balance of a gear train with nonlinear meshes (contact loss, backlash) and bearings
/// with radial clearance, condensed exactly onto the nonlinear coordinates: the mesh deflections
/// and the bearings' radial displacements (docs/theory/nonlinear_gear_trains.md).
///
/// Clearance bearings (bearing_clearance.h) add two coordinates each, u = (u_y, u_z) = J q: V
/// below becomes W = [V, J_1ᵀ, …] (GearTrainModel::nonlinearVectors), f̃ gains the bearings'
/// f(u) − k u (the linear bearing stays in K̄, so D(h) is regular when the journal floats), and
/// the Jacobian their 2 × 2 blocks ∂f̃/∂u (u_y, u_z coupled), by the same AFT per pair.
///
/// With the mean meshes in K̄ = K + Ω²K_Ω + Σ k̄ v vᵀ, the train reads
///   M q̈ + (C + ΩG₁) q̇ + K̄ q + V f̃(t, Vᵀq) = F₀ + V c ė,  f̃_m = k_m g_m(δ_m − e_m) − k̄_m δ_m,
/// periodic over the common period of the meshes (ω₀ = 2π f₀, f₀ the base frequency of
/// trainBaseFrequency; mesh m repeats P_m times a period). Per harmonic h of ω₀ the linear part
/// is D(h) = K̄ − (hω₀)² M + i hω₀ (C + ΩG₁); eliminating q (X_h = D(h)⁻¹ (F_h − V F̃_h)) leaves
///   R_h(δ) = δ_h − B(h) d_h − b₀ δ_h0 + B(h) F̃_h(δ) = 0,   B(h) = Vᵀ D(h)⁻¹ V (r × r),
/// on the r (2H + 1) real Fourier coefficients of the mesh deflections δ = Vᵀq only (d_h: the
/// dashpot forcing c ė, b₀ = Vᵀ D(0)⁻¹ F₀). F̃ comes from AFT per mesh (inverse real FFT to N
/// samples of the base period, the force at the samples, forward FFT); the Jacobian
/// I + B ∂F̃/∂δ is analytic (∂F̃_m/∂δ_m from the FFT of df̃/dδ at the samples, Toeplitz + Hankel),
/// and ∂R/∂ω₀ too (through dD/dω₀, including the speed dependence of K_Ω and G₁). Every DOF is
/// recovered after convergence. Stability: the monodromy matrix of the variational equation
/// along the solution, by Newmark (average acceleration) with the condensed mesh slopes held over
/// each of the N sample intervals (Woodbury on the r meshes), or Hill's method
/// (detail/train_hill.h).

#include <fftw3.h>

#include <Eigen/Dense>
#include <array>
#include <complex>
#include <memory>
#include <utility>
#include <vector>

#include "geardyn/solvers/continuation.h"
#include "geardyn/system/bearing_law.h"
#include "geardyn/system/gear_train_model.h"
#include "geardyn/system/train_tooth_pairs.h"

namespace geardyn {
namespace detail {
struct TrainHillProblem;
class TrainHillSolver;
}  // namespace detail

struct TrainHarmonicBalanceOptions {
  int harmonics = 15;        ///< H: harmonics of the base (common) frequency
  int samples = 256;         ///< N: AFT samples per base period (> 2H, no aliasing)
  double tolerance = 1e-10;  ///< ‖R‖ / (‖δ‖ + ‖b‖)
  int max_iterations = 40;
  void validate() const;
};

class TrainHarmonicBalance final : public ContinuationProblem {
 public:
  /// InputError when the mesh frequencies have no common period within H harmonics (key
  /// "nonlinear.harmonics": every mesh needs at least one harmonic of its own frequency).
  TrainHarmonicBalance(const GearTrainModel& model, const TrainHarmonicBalanceOptions& options);
  ~TrainHarmonicBalance() override;
  TrainHarmonicBalance(const TrainHarmonicBalance&) = delete;
  TrainHarmonicBalance& operator=(const TrainHarmonicBalance&) = delete;

  int size() const override { return r_ * n_; }
  int meshCount() const noexcept { return meshes_; }
  /// Clearance bearings (model.clearanceBearings()); their (u_y, u_z) follow the meshes' δ in u
  /// (a full-DOF rolling bearing's five coordinates (u_y, u_z, u_x, θ_y, θ_z)).
  int bearingCount() const noexcept { return bearings_; }
  /// The first coordinate of clearance bearing b (its width() follow).
  int bearingCoordinate(int b) const { return bearing_first_[b]; }
  /// Nonlinear coordinates r = meshes + Σ widths of the clearance bearings (2 each, 5 for a
  /// full-DOF rolling bearing; u holds r blocks of 2H + 1).
  int coordinateCount() const noexcept { return r_; }
  int harmonics() const noexcept { return h_; }
  int samples() const noexcept { return samples_; }
  /// ω₀ [rad/s] at input speed Ω [rad/s], and back (Ω takes the model's sign).
  double baseFrequency(double input_speed) const;
  double inputSpeed(double omega) const;
  const std::vector<int>& meshMultiples() const noexcept { return multiple_; }

  void residual(const Eigen::VectorXd& u, double omega, Eigen::VectorXd& r, Eigen::MatrixXd* dr_du,
                Eigen::VectorXd* dr_domega) override;
  double residualNorm(const Eigen::VectorXd& u, const Eigen::VectorXd& r,
                      double omega) const override;
  /// The response with every mesh held in contact (g(y) = y) and every clearance bearing linear:
  /// the linear time-varying solution. Then each clearance bearing's mean displacement ū is
  /// moved by its clearance c along itself, ū (1 + c/|ū|): the static equilibrium of the
  /// isotropic law f = k (|u| − c) u/|u| under the load k ū that the linear bearing carries, so
  /// Newton starts with the journal on the bearing surface. (Left inside the clearance, a
  /// journal whose shaft no other support holds makes the Jacobian singular there.)
  Eigen::VectorXd startingGuess(double omega) override;
  void solve(HarmonicBalancePoint& point) override;
  /// Stability: the monodromy matrix (kMonodromy), or Hill's method (kHill, train_hill.cpp:
  /// the Floquet exponents from the Hill eigenproblem, its low-rank periodic part by Woodbury).
  void classify(HarmonicBalancePoint& point, StabilityMethod method, bool samples_current) override;
  /// A new ω refactorises D(h) at every harmonic (prepare): continuation holds ω where it can.
  bool frequencyChangeIsCostly() const override { return true; }
  /// Also records the ω and the slopes the factors are of: Hill's method reuses them as its
  /// capacitance where a point's slopes are the same (hillProblem).
  const Eigen::PartialPivLU<Eigen::MatrixXd>& factorJacobian(const Eigen::MatrixXd& dr_du) override;
  /// The variational equation at a solution on the elastic subspace, for Hill's method
  /// (detail/train_hill.h): M, C, K̄, V and the Galerkin matrices of the slopes at the samples,
  /// and the last factorJacobian's factors when they are of the same ω and slopes. `harmonics`:
  /// Hill's truncation H (0: the balance's; more resolves faster modes, from the same samples:
  /// at most N/4, so that the slopes' 2H harmonics do not alias).
  detail::TrainHillProblem hillProblem(const HarmonicBalancePoint& point, bool samples_current,
                                       int harmonics = 0);

  /// Every DOF: real Fourier coefficients over the base period, column 0 the mean, 2h − 1 and 2h
  /// the cosine and sine of harmonic h (rows: DOFs), q(τ) = Σ columns · (1, cos hτ, sin hτ).
  Eigen::MatrixXd displacementCoefficients(const HarmonicBalancePoint& point);
  /// The state (q, q̇) at t = 0 of a periodic solution from its recovered coefficients [m, rad;
  /// m/s, rad/s]: where a time integration started on the solution begins.
  std::pair<Eigen::VectorXd, Eigen::VectorXd> initialState(const HarmonicBalancePoint& point);
  /// δ_m at the N samples of one base period (rows: samples, cols: meshes) [m].
  Eigen::MatrixXd meshDeflections(const Eigen::VectorXd& u);
  /// (u_y, u_z) of every clearance bearing at the N samples (rows: samples, cols: y then z of
  /// bearing 0, 1, …) [m].
  Eigen::MatrixXd bearingDisplacements(const Eigen::VectorXd& u);
  /// The contact force k_m(φ) g_m(δ_m − e_m) of every mesh at the N samples of one base period
  /// (rows: samples, cols: meshes) [N]: 0 where the teeth are apart, < 0 on the back flank.
  Eigen::MatrixXd meshContactForces(const Eigen::VectorXd& u);

 private:
  void prepare(double omega);  // the per-harmonic condensation at ω₀ (cached)
  void classifyHill(HarmonicBalancePoint& point, bool samples_current);  // train_hill.cpp
  void forward(const double* samples, double* coefficients);
  void inverse(const double* coefficients, double* samples);
  void meshForceSamples(const Eigen::VectorXd& u);  // f̃ and df̃/dδ at the samples
  Eigen::MatrixXd forceCoefficients(double omega);  // F̃ − d from the last samples [coef, coord]

  const GearTrainModel& model_;
  TrainHarmonicBalanceOptions options_;
  int h_, n_, samples_, r_, dofs_, meshes_, bearings_;
  double base_ratio_, speed_sign_;
  std::vector<int> multiple_;
  Eigen::MatrixXd V_, rigid_, elastic_;  // V_: W = [V, bearing columns]; rigid_: M × modes
  Eigen::MatrixXd k_, e_, slope_;        // [sample, mesh]
  Eigen::MatrixXd force_, delta_;        // f̃ and the coordinates [sample, coordinate]
  Eigen::MatrixXd bearing_slope_;      // ∂f̃/∂u column-major per bearing [sample, Σ width²]
  std::vector<TrainBearingLaw> laws_;  // per clearance bearing: its law over its coordinates
  std::vector<int> bearing_first_;     // per bearing: its first coordinate
  // Every entry of the bearings' slopes: (coordinate i, coordinate j, column of bearing_slope_).
  std::vector<std::array<int, 3>> bearing_blocks_;
  Eigen::MatrixXd rate_coefficients_;  // de/dφ per mesh, real layout [coef, mesh]
  // Tooth-pair elements per mesh at the samples (no elements: k g).
  std::vector<ToothPairTable> tooth_pairs_;
  bool linearized_ = false;
  // Condensation at the cached ω₀: B(h), dB/dω₀, D(h) factors, b₀ and its derivative.
  double cached_omega_ = -1.0;
  std::vector<Eigen::MatrixXcd> B_, dB_;
  std::vector<Eigen::PartialPivLU<Eigen::MatrixXcd>> lu_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu0_;
  Eigen::VectorXd b0_, db0_;
  double* real_buffer_;
  fftw_complex* complex_buffer_;
  fftw_plan forward_plan_, inverse_plan_;
  std::unique_ptr<detail::TrainHillSolver> hill_;  // Hill's method's buffers, on first use
  // What the last factorJacobian's factors are of: ω (−1: none) and the slopes' samples.
  double factored_omega_ = -1.0;
  Eigen::MatrixXd factored_slope_, factored_bearing_slope_;
};

}  // namespace geardyn
