#pragma once
/// \file
/// Hill's method for the variational equation of a gear train whose periodic part is low rank
/// (docs/theory/nonlinear_gear_trains.md, "Stability: Hill's method"):
///
///   M x″ + C x′ + (K̄ + V S(t) Vᵀ) x = 0,   x ∈ ℝⁿ (the elastic subspace), V n × r,
///
/// S(t) the r × r slopes of the nonlinear coordinates (a mesh's df̃/dδ, a clearance bearing's
/// 2 × 2 ∂f̃/∂u), T-periodic, ω = 2π/T. With the state y = (x, x′) and y = e^{λt} p(t), p
/// T-periodic and truncated to H harmonics in the real basis (1, cos hωt, sin hωt), the
/// first-order Hill eigenproblem is (Lazarus & Thomas 2010, C. R. Mécanique 338, eq. 12)
///
///   𝓗 p = λ p,   𝓗 = 𝓐₀ − 𝓓ₜ + 𝓑 𝓢 𝓒ᵀ,
///
/// 𝓐₀ = I ⊗ [0 I; −M⁻¹K̄ −M⁻¹C], 𝓓ₜ the derivative (a_h, b_h) → hω (b_h, −a_h), 𝓢 the
/// Galerkin (AFT) matrix of the multiplication by S(t) on the r coordinates (the blocks of the
/// harmonic balance Jacobian), 𝓑 z = (0, −M⁻¹V z), 𝓒ᵀ y = Vᵀx. 𝓗 is 2n(2H + 1) wide but its
/// periodic part has rank r(2H + 1): (𝓗 − σ)⁻¹ is applied by Woodbury with one n × n complex LU
/// of D(s) = s²M + sC + K̄ per harmonic (s = σ + ihω) and one r(2H + 1) real LU of the
/// capacitance I + 𝓖 𝓢, 𝓖 = blockdiag(Vᵀ D(s_h)⁻¹ V) (at σ = 0: the harmonic balance Jacobian
/// I + B ∂F̃/∂δ itself; train_hill_operator.h). The exponents come from (𝓗 − 0)⁻¹ applied to a
/// Dirac comb (trainHillProjection, what the classification uses), or, where that declines, from
/// the eigenvalues of 𝓗 by shift-invert Arnoldi (trainHillExponents): one run without restarts
/// first (strip_arnoldi.h), Spectra's restarted Arnoldi when it gives up.

#include <Eigen/Dense>
#include <complex>
#include <memory>
#include <optional>
#include <vector>

#include "geardyn/numerics/floquet_strip.h"

namespace geardyn::detail {

struct TrainHillProblem {
  Eigen::MatrixXd M, C, K;  ///< n × n on the elastic subspace [kg, N s/m, N/m (and rad forms)]
  Eigen::MatrixXd V;        ///< n × r: the nonlinear coordinates' vectors
  /// The Galerkin matrices of S_ij(t) on (1, cos, sin, …) ((2H + 1)², aftJacobian), with
  /// their coordinate pair (i, j): 𝓢's nonzero blocks.
  struct Block {
    int i = 0, j = 0;
    Eigen::MatrixXd galerkin;
  };
  std::vector<Block> slopes;
  double omega = 0.0;  ///< ω [rad/s]: the base angular frequency
  int harmonics = 0;   ///< H
  /// The harmonic balance's factors of its Jacobian ∂R/∂q = I + 𝓑 𝓢 at these very slopes and
  /// ω (factorJacobian, continuation.h), when it has them, and its condensation blocks B(h) =
  /// Vᵀ D(ihω)⁻¹ V (full coordinates, the rigid-body modes held at h = 0). At σ = 0 Hill's
  /// capacitance I + 𝓖 𝓢 is that matrix, entry by entry, when the rigid-body modes decouple
  /// from V (then 𝓖 = 𝓑): the operator reuses the factors where its own 𝓖 agrees with
  /// `jacobian_blocks`, instead of assembling and factorising the capacitance again. Both null:
  /// it does.
  const Eigen::PartialPivLU<Eigen::MatrixXd>* jacobian = nullptr;
  const std::vector<Eigen::MatrixXcd>* jacobian_blocks = nullptr;
};

struct TrainHillResult {
  /// The selected Floquet exponents λ [1/s], largest real part first: floquetStrip of the Hill
  /// eigenvalues computed (the `computed` nearest 0).
  std::vector<std::complex<double>> exponents;
  int computed = 0;           ///< Hill eigenvalues computed (nearest σ = 0; the basis size when
                              ///< `restart_free`)
  bool restart_free = false;  ///< certified by the one Arnoldi run (strip_arnoldi.h)
  /// |λ| of the farthest computed: every eigenvalue nearer was found (the farthest converged
  /// strip value when `restart_free`: no such guarantee, none needed)
  double radius = 0.0;
  int operations = 0;      ///< applications of (𝓗 − σ)⁻¹ (columns, for the projection)
  bool projected = false;  ///< by trainHillProjection (all 2n exponents; no selection)
  bool reused_jacobian = false;  ///< the capacitance was the balance's (TrainHillProblem::jacobian)
  int harmonics = 0;             ///< Hill's truncation H the exponents come from
};

/// The Floquet exponents of the Hill eigenproblem by shift-invert Arnoldi at σ = 0: the
/// restart-free run until its converged Ritz values hold the 2n strip values (all exponents);
/// when it gives up, Spectra on the 2n + 8 nearest 0 and, if their strip lacks some, the 4n
/// nearest 0 (every exponent whose central copy has |λ| < ω/√2, in particular every one with
/// Re λ >= −ω/2, is among them: a disc of radius < ω holds at most two copies of each of the 2n
/// exponents). std::runtime_error when Arnoldi does not converge.
TrainHillResult trainHillExponents(const TrainHillProblem& problem);

/// The Floquet exponents from Hill's matrix by its resolvent projection (issue #39;
/// docs/theory/nonlinear_gear_trains.md "Hill's method: the resolvent projection"): no
/// eigenvalues of 𝓗 are computed and none are sorted. With the Floquet form of the fundamental
/// matrix Φ(t) = P(t) e^{Bt}, P T-periodic, P(0) = I, the Hill matrix of A(t) is 𝓟 𝓗_B 𝓟⁻¹,
/// 𝓗_B = blockdiag(B − ikω) and 𝓟 the multiplication by P(t) (the similarity behind Bayer &
/// Leine's Koopman–Hill projection C(t) e^{𝓗t} W, 2023, Nonlinear Dyn. 111, 8439), so
///   C 𝓗⁻ᵖ 𝛅 = Σₖ (B − ikω)⁻ᵖ = g_p(B),   g₂(z) = (T/2)² csch²(Tz/2),  g₃(z) = (T/2)³ csch² coth,
/// where 𝛅 holds the Fourier coefficients of the Dirac comb T Σⱼ δ(t − jT) I (2n columns: 1 on
/// the constant, 2 on every cosine), which 𝓟⁻¹ leaves as it is (P⁻¹(0) = I), and C evaluates a
/// Fourier series at t = 0.
/// Hence M₂⁻¹M₃ = (T/2) coth(TB/2), 2n × 2n, whose eigenvalues give the multipliers
/// μ = (c + 1)/(c − 1), c = coth(λT/2): three block applications of (𝓗 − 0)⁻¹ to 2n columns and
/// one small eigenproblem. The truncation to H harmonics is corrected exactly for a
/// time-invariant A (then M_p = Σ_{|k|<=H}(A − ikω)⁻ᵖ): each λ is polished by Newton on
/// f₃(λ)/f₂(λ) = ν, f_p(λ) = Σ_{|k|<=H}(λ − ikω)⁻ᵖ, ν the small eigenvalue. Exponents in the
/// strip |Im| <= ω/2, largest real part first. std::nullopt when the projection cannot resolve
/// them: a mean-system mode beyond Hω/2 (TrainHillSolver::resolvingHarmonics says how many
/// harmonics would), M₂ = g₂(B) near singular (reciprocal condition below 1e-9: an exponent
/// with |Re λ| T beyond about 20, whose csch² underflows against the others'), a multiplier at
/// 0 or ∞, a polish that does not converge, or exponents whose sum is more than 0.02 ω from
/// −tr(M⁻¹C) (Liouville's formula); trainHillExponents is then the method.
std::optional<TrainHillResult> trainHillProjection(const TrainHillProblem& problem);

class TrainHillShiftSolve;

/// Hill's method's working state, kept from point to point of a sweep (TrainHarmonicBalance
/// holds one): the operator's factors and the block applications' buffers stay allocated.
class TrainHillSolver {
 public:
  TrainHillSolver();
  ~TrainHillSolver();
  TrainHillSolver(const TrainHillSolver&) = delete;
  TrainHillSolver& operator=(const TrainHillSolver&) = delete;

  /// trainHillProjection with this state's buffers.
  std::optional<TrainHillResult> projection(const TrainHillProblem& problem);
  /// The truncation H the last projection needed to resolve the mean system's fastest mode:
  /// more than the problem's when that is why it declined (then a problem with these many
  /// harmonics may be projected instead), the problem's otherwise.
  int resolvingHarmonics() const { return resolving_harmonics_; }
  /// Whether projecting with `extended` harmonics costs fewer floating-point operations than
  /// the Arnoldi run at `harmonics` (n DOFs, r nonlinear coordinates), by the dominant terms of
  /// each (train_hill_projection.cpp): a small r (a capacitance r(2H + 1) wide) extends far.
  static bool extensionPays(int n, int r, int harmonics, int extended);
  /// trainHillExponents with this state's operator.
  TrainHillResult arnoldi(const TrainHillProblem& problem);

 private:
  std::unique_ptr<TrainHillShiftSolve> op_;
  Eigen::MatrixXd first_, second_, third_;  // 𝓗⁻¹𝛅, 𝓗⁻²𝛅 and C 𝓗⁻³𝛅
  int resolving_harmonics_ = 0;
};

/// The dense real Hill matrix (2n(2H + 1) square; coefficient-major) for tests, similar to 𝓗
/// (the same eigenvalues) in the balanced state (W z, z′) of the mass-normalised undamped modes
/// x = Φz: its full eigendecomposition is the reference for trainHillExponents.
Eigen::MatrixXd trainHillMatrix(const TrainHillProblem& problem);

}  // namespace geardyn::detail
