#pragma once
/// \file
/// Identification of the gear-mesh dynamic transmission-error (DTE) parameters of the lateral
/// geared rotor (system/lateral_rotor.h) from full-spectrum whirl peaks (Rao 2023 §4.6–4.7,
/// ch. 5): mesh stiffness k_m, mean TE e_m, mesh damping c_m, the TE harmonics (amplitude and
/// phase in x and y) and the pinion and gear runouts with their phases.
///
/// Two estimators:
///   - three_step: the thesis's algorithm, with its equations re-derived from our model's
///     frequency-domain form (see src/identify/three_step_identification.cpp);
///   - joint: one weighted nonlinear least-squares fit of every component of every speed
///     (output error: measured − modelled peaks, weighted by each shaft's peak noise), in ln k_m
///     and ln c_m, with 95 % intervals from the estimator's covariance and an identifiability
///     verdict per parameter; priors (or fixed values) for k_m and c_m.
///
/// Phases are referred to the spectra's phase reference (t = 0 of a simulation, or the first
/// keyphasor pulse of a record); the data are in the probe frame.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "geardyn/progress.h"
#include "geardyn/signal/full_spectrum.h"
#include "geardyn/solvers/rotor_response.h"
#include "geardyn/system/lateral_rotor.h"

namespace geardyn {

/// The whirl peaks of both shafts at one speed, in the probe frame, named as
/// gearWhirlComponents() (static, mesh_i_fwd/bwd, pinion_1x_fwd/bwd, gear_1x_fwd/bwd).
struct MeasuredWhirlPeaks {
  double pinion_speed = 0.0;  ///< [rev/s]
  std::array<std::vector<WhirlComponent>, 2> peaks;
  /// Standard deviation of a complex peak value, per shaft [m] (0: unknown, noise-free).
  std::array<double, 2> coefficient_sigma{0.0, 0.0};
};

enum class IdentificationMethod { kThreeStep, kJoint };

/// A prior on a positive parameter: log-normal with the given relative standard deviation; a
/// relative_sd of 0 fixes the parameter at `value`.
struct PositivePrior {
  std::optional<double> value;
  double relative_sd = 0.0;
};

struct IdentificationOptions {
  IdentificationMethod method = IdentificationMethod::kJoint;
  int harmonics = -1;  ///< mesh harmonics used (−1: every one present in the data)
  /// three_step: c_m = 2 ζ_m √(k_m m₁m₂/(m₁ + m₂)) (eqs. 4.9–4.10). joint: the centre of the
  /// default prior on ζ_m (used when no mesh_damping prior is given).
  double mesh_damping_ratio = 0.01;
  /// joint: relative standard deviation (log-normal) of the default prior on ζ_m. The peaks
  /// barely see c_m: a common factor (1 + jΩc_m/k_m) of each harmonic's forcing is absorbed by
  /// the TE phasors, so only the mesh's relative motion (~k_s/k_m of the response) carries it.
  double mesh_damping_ratio_sd = 1.0;
  PositivePrior mesh_stiffness;  ///< joint only
  PositivePrior mesh_damping;    ///< joint only; replaces the ζ_m prior when given
  /// A parameter is identifiable when its 95 % half-width is at most this fraction of its
  /// value (amplitudes, k_m, c_m, e_m) or this many radians (phases).
  double identifiable_width = 0.5;
  int max_iterations = 200;
  /// Called with the work done: joint, iterations of max_iterations; three_step, harmonics.
  ProgressCallback progress;
};

/// One identified quantity with its 95 % confidence interval.
struct IdentifiedValue {
  double value = 0.0;
  double low = 0.0, high = 0.0;  ///< 95 % interval (±inf when not determined)
  bool identifiable = true;
};

struct IdentifiedPhasor {
  IdentifiedValue amplitude;  ///< [m]
  IdentifiedValue phase;      ///< [rad]
};

struct DteIdentification {
  IdentificationMethod method = IdentificationMethod::kJoint;
  IdentifiedValue mesh_stiffness;            ///< [N/m]
  IdentifiedValue mean_te;                   ///< [m]
  IdentifiedValue mesh_damping;              ///< [N s/m]
  std::vector<IdentifiedPhasor> te_x, te_y;  ///< harmonic i = index + 1
  IdentifiedPhasor pinion_runout, gear_runout;
  /// The known parameters with the identified ones: the model to re-simulate the spectra.
  LateralRotorSpec spec;
  double chi_square = 0.0;  ///< weighted residual sum of squares (joint)
  int degrees_of_freedom = 0;
  int iterations = 0;
  bool converged = true;
  std::string message;
};

/// Identifies the DTE parameters. `known` supplies the masses, shaft stiffnesses and dampers,
/// gravity and teeth (its DTE fields are ignored). Throws InputError for data that cannot
/// support the estimate (no speeds, a missing component, fewer equations than unknowns).
DteIdentification identifyDte(const LateralRotorSpec& known,
                              const std::vector<MeasuredWhirlPeaks>& data,
                              const IdentificationOptions& options);

/// The frequency-domain solution as whirl peaks of both shafts (probe frame, Hz), in
/// gearWhirlComponents order.
std::array<std::vector<WhirlComponent>, 2> whirlPeaksOf(
    const std::vector<RotorWhirlResponse>& parts);

/// The model's exact peaks at one speed for a spec: whirlPeaksOf its frequency-domain solution.
std::array<std::vector<WhirlComponent>, 2> modelWhirlPeaks(const LateralRotorSpec& spec);

}  // namespace geardyn
