#pragma once
/// \file
/// How long a gear train's transient lasts and which of its modes have no damping: the derived
/// duration of a time run (train_time.h) and the warnings about undamped modes.

#include <string>
#include <vector>

#include "geardyn/solvers/train_modal.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn {

/// A mode with no damping: |ζ| within round-off of 0 (1e-9), so its free vibration never decays.
struct TrainUndampedMode {
  double frequency = 0.0;  ///< [Hz]
  /// The forcing excites it: its share of strain energy in the meshes, or the cosine between
  /// its shape and an unbalance's, runout's or prescribed displacement's force pattern, is above
  /// round-off, so its modal force is not zero (see TrainTransient).
  bool excited = false;
  /// The elements (TrainElement::name) and meshes holding 10 % or more of its strain energy:
  /// where damping would act on it (neither: its strain is in flexible shafts).
  std::vector<std::string> elements, meshes;
};

/// The transient of a time run at constant speed started from the mean static deflection.
/// The excitation (stiffness variation and transmission error) acts through the mesh
/// deflections v_mᵀq only, so mode j starts with an amplitude proportional to its modal force
/// Σ_m v_mᵀφ_j (…), and (v_mᵀφ_j)² = s_mj φ_jᴴK̄φ_j / k̄_m with s_mj its strain-energy share in
/// mesh m: relative to the modes the meshes drive, mode j starts at about √s_j (s_j = Σ_m
/// s_mj). Modes with √s_j ≤ 1e-6 start below the 1e-6 the transient must fall to and are not
/// waited for (a shaft's lateral mode between undamped bearings, orthogonal to every line of
/// action, has s_j at round-off). Every other mode is waited for until it has decayed by 1e-6,
/// ln(1e6) / σ_j (σ_j = −Re λ_j): √s_j is only the modal amplitude, and a probe's velocity or
/// acceleration weights a high mode by its frequency, so its start is not discounted. The other
/// excitations (unbalances, runouts, prescribed bearing displacements) start mode j at about
/// the cosine between its shape and their force patterns; a mode orthogonal to all of them and
/// to the meshes (to 1e-6) is not waited for either.
struct TrainTransient {
  /// The longest of those times [s]; +inf when a mode the forcing excites has no damping, 0 when
  /// no mode needs one.
  double decay_time = 0.0;
  double slowest_frequency = 0.0;      ///< [Hz] of the mode that sets decay_time
  double slowest_damping_ratio = 0.0;  ///< [-]
  std::vector<TrainUndampedMode> undamped;
};

/// `mode` with the elements and meshes holding 10 % or more of its strain energy (where damping
/// would act on it) and whether the forcing `excited` it.
TrainUndampedMode dampingPlacesOf(const GearTrainModel& model, const TrainMode& mode, bool excited);

/// The undamped elastic modes among `modes` (rigid-body and divergent modes left out).
std::vector<TrainUndampedMode> trainUndampedModes(const GearTrainModel& model,
                                                  const std::vector<TrainMode>& modes);

/// The transient estimate from the damped modes at input speed Ω [rad/s].
TrainTransient trainTransient(const GearTrainModel& model, double input_speed);

}  // namespace geardyn
