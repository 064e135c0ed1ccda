#pragma once
/// \file
/// The gearbox Rao's lateral geared rotor is (issue #31): a `geardyn rotor` file with a lateral
/// [rotor] (rotor_config.h; Rao 2023 thesis, Fig. 2.1, eqs. 2.1–2.38) translated into gearbox
/// description text (gearbox_config.h). Planar DOFs, two rigid shafts "pinion" and "gear" with
/// the gears' masses, each on an isotropic bearing to the housing (the shaft's lateral stiffness
/// k_s and dashpot c_s), and the thesis's "mesh" as what it is: an isotropic bearing between
/// the shafts (k_m, c_m in y and in z), across which the transmission error is a prescribed
/// relative displacement. Axes: the thesis's (x, y, z) are the gearbox's (y, z, x); gravity acts
/// along −z (the thesis's −y); the pinion turns about −x (the thesis's −φ_z1), so the input
/// speed is negative, and a kinematic coupling of ratio −t_p/t_g turns the gear. Excitations
/// (train_excitation.h), with φ_p = ω_p t + ϕ_p, φ_g = ω_g t + ϕ_g and the runout offsets
/// w_p = e_p (cos φ_p, −sin φ_p), w_g = e_g (cos φ_g, sin φ_g) of eq. 2.3:
///   - bearing "mesh": d = e − w_p + w_g, e_x,y = e_m + Σ a_i sin(i t_p ω_p t + ϕ_i) (eqs.
///     2.8–2.9; sin x = cos(x − 90°)) at pinion orders i t_p, the runouts at 1× each shaft;
///   - bearings "pinion_shaft", "gear_shaft": d = −w_p, −w_g (the shafts act on the gear centres);
///   - unbalances m₁ e_p, m₂ e_g at the runout phases (the −M ẅ of the gear centres).
/// The polar inertias (1e-3 kg m²) and the coupling's torsional spring (1 N m/rad) and dashpot
/// (0.1 N m s/rad, above critical) only keep the rotations regular: nothing couples them to the
/// lateral DOFs. Doubles are printed so that
/// they read back exactly (fmt "{}"); angles in degrees.

#include <optional>
#include <string>
#include <vector>

#include "geardyn/config/config.h"
#include "geardyn/system/gear_train.h"
#include "geardyn/system/gear_train_model.h"
#include "geardyn/system/lateral_rotor.h"

namespace geardyn::config {

/// The gearbox description text of the lateral rotor `spec`; `source` names where it came from.
std::string lateralRotorGearboxToml(const LateralRotorSpec& spec, const std::string& source);

/// `rotor FILE --print-gearbox` for a lateral [rotor] file (rotorSchema()).
std::string lateralRotorGearbox(const Config& config);

/// The gear train of the lateral rotor `spec`, read from its translated text by the gearbox
/// reader (gearTrainFromConfig); the reader's warnings are appended.
GearTrainSpec lateralRotorGearTrain(const LateralRotorSpec& spec, const std::string& source,
                                    std::vector<std::string>& warnings);

/// The DOFs of the thesis's probes (x₁, y₁, x₂, y₂) in the lateral rotor's gear train: the
/// (y, z) translations of the bodies "pinion" and "gear".
std::vector<int> lateralRotorProbeDofs(const GearTrainModel& train);

}  // namespace geardyn::config
