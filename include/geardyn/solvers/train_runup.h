#pragma once
/// \file
/// Run-up (or run-down) of any gear train: Newmark integration (TrainNewmarkStepper along a
/// TrainSpeedRamp, train_time.h) while the input speed follows a linear ramp, every mesh phase
/// the integral of its mesh frequency, and the speed-dependent matrices refactorised within a
/// relative speed tolerance.
///
/// The prescribed rotation is kinematic: the DOFs are vibrations about it, as at constant
/// speed. The inertial torque of the ramp, Σ_b J_b r_b² dΩ/dt on the input (r_b = ω_b / Ω), and
/// the Euler force of an accelerating carrier frame are not applied: the static load F₀ stays
/// the operating point's. For the slow sweeps an order analysis needs they are small against
/// the operating torque; trainRampInertiaTorque gives the ratio so that a run can say so.
///
/// Defaults derived from the train (trainRunUpDefaults): the time step from the fastest mesh
/// period at the highest speed, the order-tracking window from the common period, and the
/// duration from the quasi-stationary sweep criterion of every resonance the meshes pass: a
/// mode of frequency f_n and damping ratio ζ responds within kSweepTimeConstants time
/// constants τ = 1 / (2π ζ f_n) while the exciting frequency crosses its half-power band
/// 2 ζ f_n, i.e. the order line's sweep rate ḟ <= 4π ζ² f_n² / kSweepTimeConstants.

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "geardyn/progress.h"
#include "geardyn/solvers/newmark.h"
#include "geardyn/solvers/train_time.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn {

/// Time constants of a mode spent in its half-power band during the derived sweep.
inline constexpr double kSweepTimeConstants = 5.0;
/// A mode is excited by the meshes (and sets the derived duration) when at least this
/// fraction of its strain energy is in the meshes.
inline constexpr double kExcitedMeshEnergy = 1e-3;
/// The derived window: this many common periods of the train at the mean speed, at most
/// kWindowSlowestMeshPeriods periods of the slowest mesh (trains whose meshes have no small
/// common period), and at least one input revolution there.
inline constexpr int kWindowCommonPeriods = 8;
inline constexpr int kWindowSlowestMeshPeriods = 32;
/// The derived duration holds at least this many windows.
inline constexpr int kMinRunUpWindows = 100;

struct TrainRunUpOptions {
  NewmarkParameters newmark = NewmarkParameters::averageAcceleration();
  TrainSpeedRamp ramp;             ///< Ω₀ → Ω₁ over the duration [rad/s, s]
  double time_step = 0.0;          ///< Δt [s]; 0: fastest mesh period at max |Ω| / steps_…
  int steps_per_mesh_period = 64;  ///< for the derived Δt (>= 8)
  double speed_tolerance = kTrainSpeedTolerance;  ///< relative; see train_time.h
  std::vector<int> dofs;  ///< DOFs whose displacement is recorded (any subset)
  /// q(0), q̇(0): the frequency-domain periodic steady state at Ω₀ (no start transient; the
  /// static deflection when the train's common period is too long for it), the static
  /// deflection at Ω₀, or rest.
  enum class Start { kSteadyState, kStatic, kRest } start = Start::kSteadyState;
  ProgressCallback progress;  ///< (steps done, steps)
  void validate() const;      ///< InputError naming the runup.* key
};

struct TrainRunUpResponse {
  Eigen::VectorXd t;             ///< every step, t = 0 included [s]
  Eigen::VectorXd speed;         ///< input speed Ω(t) [rad/s]
  Eigen::VectorXd angle;         ///< input rotation ∫|Ω| dt [rad]
  Eigen::MatrixXd mesh_force;    ///< rows: samples, cols: meshes [N]
  Eigen::MatrixXd displacement;  ///< rows: samples, cols: options.dofs [m, rad]
  double time_step = 0.0;        ///< [s]
  long long steps = 0;
  int factorisations = 0;
  std::string start;                 ///< "steady_state", "static" or "rest": how it started
  std::string status = "completed";  ///< or "diverged"
  std::string message;
};

TrainRunUpResponse solveTrainRunUp(const GearTrainModel& model, const TrainRunUpOptions& options);

/// Δt [s] of a run-up: the fastest mesh period at the ramp's largest |Ω| / steps_per_mesh_period.
double trainRunUpTimeStep(const GearTrainModel& model, const TrainSpeedRamp& ramp,
                          int steps_per_mesh_period);

/// A resonance a run-up passes: a mode crossed by a mesh-order line inside the speed range.
struct TrainRunUpResonance {
  int mode = 0;                 ///< tracked mode index (Campbell)
  std::string line;             ///< the order line ("mesh stage1", "2x mesh stage1")
  double speed = 0.0;           ///< input speed [rad/s]
  double frequency = 0.0;       ///< [Hz]
  double damping_ratio = 0.0;   ///< [-]
  double sweep_duration = 0.0;  ///< the quasi-stationary duration it asks for [s] (inf: ζ = 0)
};

struct TrainRunUpDefaults {
  double window = 0.0;    ///< order-tracking window [s]
  double duration = 0.0;  ///< quasi-stationary duration [s] (>= kMinRunUpWindows windows)
  std::vector<TrainRunUpResonance> resonances;  ///< ascending in speed
};

/// The derived window and duration of a run-up from |Ω₀| to |Ω₁| (`start`, `end` [rad/s]) whose
/// meshes excite harmonics 1..mesh_harmonics: the Campbell diagram over the range (`modes`
/// tracked modes, `speeds` speeds) gives the resonances (modes with >= kExcitedMeshEnergy of
/// their strain energy in the meshes). `window` > 0 is used as given.
TrainRunUpDefaults trainRunUpDefaults(const GearTrainModel& model, double start, double end,
                                      int mesh_harmonics, int modes, double window = 0.0,
                                      int speeds = 41);

/// Σ_b J_b r_b² |dΩ/dt| [N m]: the input torque the ramp's rigid acceleration would need (not
/// applied; see the file comment).
double trainRampInertiaTorque(const GearTrainModel& model, const TrainSpeedRamp& ramp);

}  // namespace geardyn
