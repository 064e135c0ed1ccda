#pragma once
/// \file
/// Responses of the lateral geared rotor (models/lateral_rotor.h, Rao 2023 ch. 2–4):
///   - time domain: Dormand–Prince 5(4) (Boost.Odeint, as the thesis's ode45) from rest, on a
///     uniform grid; the end of the transient is detected by comparing the response with itself
///     one common period later, and the steady window is a whole number of common periods;
///   - frequency domain: the exact steady state, one 2×2 complex solve (K − Ω²M + jΩC) p = s per
///     whirl component (thesis eqs. 3.135–3.138), superposed to a time history on request.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "geardyn/models/lateral_rotor.h"
#include "geardyn/progress.h"

namespace geardyn {

struct RotorTimeOptions {
  double duration = 15.0;     ///< [s] (thesis §4.2: 15 s)
  long long samples = 32768;  ///< requested samples over the duration (thesis: 2¹⁵)
  /// Snap the sample interval so that one common period holds a whole number of samples
  /// (exact FFT bins for every component); false keeps duration/(samples − 1) as linspace does.
  bool align_to_common_period = true;
  double relative_tolerance = 1e-8;
  /// In units of the response scale L (rotorResponseScale) for displacements and L ω_max
  /// (rotorVelocityFrequency) for velocities: the integrator's state is scaled by them.
  double absolute_tolerance = 1e-8;
  double steady_tolerance = 1e-6;  ///< |z(t + T_c) − z(t)| ≤ tol · max|z| marks steady state
  ProgressCallback progress;       ///< (simulated time, duration) [s] while integrating

  void validate() const;
};

enum class RotorTimeStatus {
  kSteadyState,  ///< the transient decayed and at least one common period follows it
  kTransient,    ///< the record ends before a whole steady common period
  kNonFinite,    ///< the integration produced NaN or Inf
};
std::string toString(RotorTimeStatus status);

struct RotorTimeResponse {
  std::vector<double> t;             ///< [s], uniform
  std::vector<Eigen::Vector4d> eta;  ///< (x₁, y₁, x₂, y₂) [m] at each t
  double sample_rate = 0.0;          ///< [Hz]
  double common_period = 0.0;        ///< [s]
  long long samples_per_period = 0;  ///< per common period (0 when not aligned)
  long long transient_end = 0;       ///< first steady sample
  long long window_begin = 0;        ///< the steady window [window_begin, window_end)
  long long window_end = 0;          ///<   holds `window_periods` common periods
  int window_periods = 0;
  long long steps = 0;  ///< accepted Dormand–Prince steps
  long long rhs_evaluations = 0;
  RotorTimeStatus status = RotorTimeStatus::kSteadyState;
  std::string message;
  bool converged() const { return status == RotorTimeStatus::kSteadyState; }
};

/// The displacement scale L of the response: the largest of e_m, the TE amplitudes, the runouts
/// and the gravity sags m g / k_s [m].
double rotorResponseScale(const LateralRotorModel& model);
/// The velocity scale's frequency: the highest mesh harmonic n ω_e [rad/s].
double rotorVelocityFrequency(const LateralRotorModel& model);

/// Integrates M η̈ + C η̇ + K η = f(t) from η = η̇ = 0 at t = 0.
RotorTimeResponse solveRotorTimeResponse(const LateralRotorModel& model,
                                         const RotorTimeOptions& options);

/// Integrates and samples at arbitrary increasing times `times` (e.g. a 5 kS/s "measurement"),
/// from rest at t = 0; no transient analysis.
std::vector<Eigen::Vector4d> sampleRotorTimeResponse(const LateralRotorModel& model,
                                                     const std::vector<double>& times,
                                                     double relative_tolerance,
                                                     double absolute_tolerance);

/// One steady whirl component of the response: z_s(t) ∋ p_s e^{jΩt}, s = 1 (pinion), 2 (gear).
struct RotorWhirlResponse {
  std::string name;           ///< as in LateralRotorModel::whirlForcing(), probe frame
  double omega = 0.0;         ///< signed [rad/s]
  Eigen::Vector2cd response;  ///< complex 0-peak radius at t = 0 of (z₁, z₂) [m]
};

/// The exact steady state, component by component.
std::vector<RotorWhirlResponse> solveRotorFrequencyResponse(const LateralRotorModel& model);

/// Σ p e^{jΩt} at the given times: (x₁, y₁, x₂, y₂) per time.
std::vector<Eigen::Vector4d> superposeWhirlResponse(const std::vector<RotorWhirlResponse>& parts,
                                                    const std::vector<double>& times);

}  // namespace geardyn
