#pragma once
/// \file
/// The warning about a train's undamped modes (train_undamped_modes.cpp): which modes have no
/// damping, whether the meshes excite them, and the gearbox keys that would damp them.

#include <string>
#include <vector>

#include "geardyn/solvers/train_transient.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn::analysis::detail {

/// The gearbox key that damps element `element` (a TrainElement::name): "bearings.b1.cyy/czz",
/// "couplings.motor.c_torsion", "planetary.stage1.pin_damping", ...
std::string dampingKeyOf(const GearTrainModel& model, const std::string& element);

/// The keys that would damp `mode`: its meshes' damping ratios, then its elements' keys.
std::vector<std::string> dampingKeysOf(const GearTrainModel& model, const TrainUndampedMode& mode);

/// One warning line for the undamped modes at `speed_rpm` (empty when there are none): their
/// frequencies, whether the meshes excite them and the keys that would damp them.
/// What drives the train, for messages: "the meshes", "the meshes and the unbalances", "the
/// runouts" … (its meshes, then the sections of its other excitation terms); "" when nothing.
std::string forcingOf(const GearTrainModel& model);

std::string undampedModesWarning(const GearTrainModel& model,
                                 const std::vector<TrainUndampedMode>& modes, double speed_rpm);

}  // namespace geardyn::analysis::detail
