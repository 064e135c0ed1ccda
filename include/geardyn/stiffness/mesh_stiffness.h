#pragma once
/// \file
/// The mesh stiffness of a gear pair over one mesh period: the interface every model implements
/// (API constant, step, Fourier, potential-energy beam, ISO 6336), and the conversions between
/// mesh phase, pinion roll angle and time.
///
/// Mesh phase φ counts mesh periods: k(φ + 1) = k(φ). φ = 0 is the instant a new tooth pair
/// enters contact at the start of the path of contact; the pinion turns by one angular pitch
/// 2π/z₁ per mesh period.

#include <memory>
#include <string>
#include <vector>

namespace geardyn {

class MeshStiffness {
 public:
  virtual ~MeshStiffness() = default;

  /// The model's name ("api", "step", "fourier", "potential_energy", "iso6336").
  virtual std::string model() const = 0;

  /// Mesh stiffness k at mesh phase φ (any real; periodic with period 1) [N/m]. Where k jumps
  /// the value is the right-hand limit. Evaluation is allocation-free and thread-safe.
  virtual double stiffness(double phase) const = 0;

  /// Phases in [0, 1) where k may jump, ascending (empty for continuous models). Statistics
  /// and Fourier coefficients integrate piecewise between them, so they are exact.
  virtual std::vector<double> discontinuities() const { return {}; }

  /// Number of tooth pairs the model resolves (0 for models without pairs). Pair j is the one
  /// that entered contact j mesh periods before the current one.
  virtual int pairCount() const { return 0; }

  /// Stiffness of pair j at phase φ (0 when that pair is out of contact) [N/m].
  virtual double pairStiffness(double phase, int pair) const;

  /// The contact ratio the model uses (for models without kinematics, the pair's) [-].
  virtual double contactRatio() const = 0;
};

/// Mesh phase of a pinion roll angle θ [rad] for z₁ pinion teeth: φ = θ z₁ / (2π).
double meshPhaseFromRollAngle(double roll_angle, int pinion_teeth);

/// Pinion roll angle [rad] of a mesh phase.
double rollAngleFromMeshPhase(double phase, int pinion_teeth);

/// The fractional part of a phase, in [0, 1).
double wrapPhase(double phase);

}  // namespace geardyn
