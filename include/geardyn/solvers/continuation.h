#pragma once
/// \file
/// Pseudo-arclength continuation of periodic solutions in their base angular frequency ω
/// (Seydel 2010, ch. 4; Krack & Gross 2019, §4.4), shared by the 1-DOF gear-pair harmonic
/// balance (harmonic_balance.h) and the multi-mesh gear-train harmonic balance
/// (train_harmonic_balance.h): a problem is R(q, ω) = 0 with analytic ∂R/∂q and ∂R/∂ω.
///
/// Folds (turning points in ω) are detected by a sign change of the ω component of the tangent
/// and *confirmed*: the branch must go back in ω by more than `fold_tolerance` before the
/// tangent turns again. The AFT samples a non-smooth contact law, so the discretised residual is
/// only piecewise smooth and its solution curve can zigzag by a few 1e-4 of ω where a sample
/// changes contact state; such zigzags are not folds. Stability changes away from folds are
/// reported with their type from the critical Floquet multiplier.

#include <Eigen/Dense>
#include <complex>
#include <string>
#include <vector>

#include "geardyn/progress.h"

namespace geardyn {

enum class StabilityMethod { kHill, kMonodromy };

/// Floquet multipliers within this of the unit circle (|μ| <= 1 + kNeutralMultiplier, or an
/// exponent's Re λ T <= kNeutralMultiplier) are neutral, not unstable: an undamped mode of a
/// train (a bearing without damping, a shaft mode the meshes do not drive) has |μ| = 1, and
/// the monodromy matrix's round-off puts it 1e-9 to 1e-8 above (Newmark's product over N steps,
/// then a non-symmetric eigenproblem whose error on a near-double eigenvalue is O(√ε)). A
/// growth of 1e-6 per period e-folds only after 1e6 periods.
inline constexpr double kNeutralMultiplier = 1e-6;

/// One periodic solution.
struct HarmonicBalancePoint {
  double omega = 0.0;  ///< base angular frequency ω [rad/s] (nondimensional models: Ω)
  Eigen::VectorXd q;   ///< Fourier coefficients of the unknowns
  bool converged = false;
  int iterations = 0;
  double residual = 0.0;  ///< relative residual at the end
  bool stable = true;
  double max_floquet_real = 0.0;  ///< largest real part of the selected Floquet exponents [1/s]
  /// The Floquet multiplier of largest modulus (monodromy), or exp(λ T) of the exponent with the
  /// largest real part (Hill). Its position at a loss of stability gives the bifurcation type.
  std::complex<double> critical_multiplier = 0.0;
};

/// What continuation needs from a periodic problem.
class ContinuationProblem {
 public:
  virtual ~ContinuationProblem() = default;
  virtual int size() const = 0;
  /// R(q, ω) and, if wanted, ∂R/∂q and ∂R/∂ω.
  virtual void residual(const Eigen::VectorXd& q, double omega, Eigen::VectorXd& r,
                        Eigen::MatrixXd* dr_dq, Eigen::VectorXd* dr_domega) = 0;
  /// Relative residual norm used for convergence.
  virtual double residualNorm(const Eigen::VectorXd& q, const Eigen::VectorXd& r,
                              double omega) const = 0;
  /// A starting guess at ω (the response with every contact held closed).
  virtual Eigen::VectorXd startingGuess(double omega) = 0;
  /// Newton at fixed ω from the guess in point.q.
  virtual void solve(HarmonicBalancePoint& point) = 0;
  /// Stability of a converged point. `samples_current`: the last residual() call was at
  /// point.q (its AFT samples may be reused).
  virtual void classify(HarmonicBalancePoint& point, StabilityMethod method,
                        bool samples_current) = 0;
  /// True when a residual at a new ω costs much more than one at the last ω (the gear train's
  /// condensation refactorises D(h) for every harmonic). Continuation then corrects at the
  /// predicted ω wherever the branch runs mostly in ω (locally parametrised continuation),
  /// with the Jacobian of the first iteration held (chord Newton) while it contracts.
  virtual bool frequencyChangeIsCostly() const { return false; }
  /// Factorises ∂R/∂q for Newton's steps at fixed ω; `dr_dq` must be the last residual() call's
  /// (at its q and ω). The problem keeps the factors until the next call, so that it may reuse
  /// them: the gear train's Hill's method takes them as its capacitance (train_hill.h).
  virtual const Eigen::PartialPivLU<Eigen::MatrixXd>& factorJacobian(const Eigen::MatrixXd& dr_dq) {
    jacobian_lu_.compute(dr_dq);
    return jacobian_lu_;
  }

 protected:
  Eigen::PartialPivLU<Eigen::MatrixXd> jacobian_lu_;  ///< factorJacobian's last factors
};

/// Newton–Raphson at the fixed ω of `point` from the guess in point.q, with backtracking (the
/// full step unless it raises the residual norm); converged when problem.residualNorm <=
/// tolerance.
void solveAtFixedFrequency(ContinuationProblem& problem, HarmonicBalancePoint& point,
                           double tolerance, int max_iterations);

/// A continuation point with what the sweep reports.
struct SweepPoint {
  HarmonicBalancePoint solution;
  int branch = 0;  ///< increases at every confirmed fold
  double arclength = 0.0;
  int step_cuts = 0;  ///< corrector failures (step halved) between the previous point and this
};

enum class BifurcationType {
  kFold,            ///< turning point in ω (saddle-node of the periodic orbit)
  kBranchPoint,     ///< a real multiplier crosses +1 away from a fold (symmetry breaking)
  kPeriodDoubling,  ///< a real multiplier crosses −1
  kNeimarkSacker,   ///< a complex pair leaves the unit circle (quasi-periodic response)
};
std::string toString(BifurcationType type);

struct Bifurcation {
  BifurcationType type = BifurcationType::kFold;
  std::size_t index = 0;  ///< the point at (or just past) it
  double omega = 0.0;     ///< [rad/s]
};

struct ContinuationOptions {
  double start = 0.0, stop = 0.0;  ///< ω range [rad/s]
  /// Steps along the scaled arc, in ω units; 0: derived by deriveContinuationSteps (call it, or
  /// continueInFrequency does with the scales below).
  double initial_step = 0.0, min_step = 0.0, max_step = 0.0;
  /// ω reversal that confirms a fold [rad/s]; 0: 1e-3 of the sweep range.
  double fold_tolerance = 0.0;
  int max_points = 20000;
  /// The Fourier coefficients Newton starts from at `start` (problem.size() long); empty: the
  /// problem's startingGuess (every contact closed).
  Eigen::VectorXd initial_guess;
  bool stability = true;
  StabilityMethod stability_method = StabilityMethod::kMonodromy;
  ProgressCallback progress;  ///< (|ω − start|, |stop − start|) after every point [rad/s]
  /// Messages show frequencies as ω / display_scale in display_unit (the unit of the user's
  /// keys: 2π and "Hz" for a dimensional model).
  double display_scale = 1.0;
  std::string display_unit = "rad/s";
  void validate() const;
};

/// Continuation steps from the problem's scales: the narrowest resonance in the range is the
/// superharmonic j ω = ω_n of the highest order j <= H whose frequency ω_n / j lies in it (the
/// primary, j = 1, when none), with a half-power width 2 ζ ω_n / j. The largest step is the
/// smaller of half that width (ζ ω_n / j) and 1/50 of the range; the first step is a fifth of
/// it, the smallest 1e-6 of it. Fills only the steps that are 0 (a given step bounds the derived
/// ones: the first step is clamped into [min, max]).
/// `natural_frequency` [rad/s] (ω units), `damping_ratio` ζ [-] (floored at 1e-3), H harmonics.
void deriveContinuationSteps(ContinuationOptions& options, double natural_frequency,
                             double damping_ratio, int harmonics);

struct ContinuationResult {
  std::vector<SweepPoint> points;
  std::vector<std::size_t> folds;  ///< indices of the points at confirmed turning points in ω
  std::vector<Bifurcation> bifurcations;  ///< folds and stability changes, in sweep order
  int failures = 0;                       ///< corrector failures (step cut back)
  bool completed = false;                 ///< reached `stop`
  std::string message;
};

/// Pseudo-arclength continuation from `start` to `stop` (either direction).
ContinuationResult continueInFrequency(ContinuationProblem& problem,
                                       const ContinuationOptions& options);

/// Every distinct periodic solution at ω [rad/s] on the given sweeps: Newton (problem.solve)
/// from the linear interpolation of each pair of consecutive points that brackets ω. Unconverged
/// ones are skipped, and so is a solution within 1e-6 (relative, in q) of one already found.
std::vector<HarmonicBalancePoint> solutionsAtFrequency(
    ContinuationProblem& problem, const std::vector<const ContinuationResult*>& sweeps,
    double omega);

}  // namespace geardyn
