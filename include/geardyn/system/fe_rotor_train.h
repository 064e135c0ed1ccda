#pragma once
/// \file
/// The two-shaft finite-element geared rotor (models/fe_geared_rotor.h, Visnadi & de Castro
/// 2021 §3) as a gear-train description: two flexible shafts with full DOFs, their elements as
/// sections, bearings and disks at their nodes' positions, one mesh whose position angle puts
/// the line of action where the FE rotor's angle ψ does, and the drive and load torques at the
/// same nodes. GearTrainModel of the result reproduces FeGearedRotor's M, K, G₁, the mesh
/// vector, F₀ and, for β = 0, C (tests/system/fe_rotor_reduction_test.cpp). Not carried over:
/// unbalances (refused), gravity on the shaft elements (the train also weighs the beams, the
/// FE rotor only its disks), β K (the train applies β to bearings and meshes too).

#include "geardyn/geometry/gear_pair.h"
#include "geardyn/models/fe_geared_rotor.h"
#include "geardyn/system/gear_train.h"

namespace geardyn {

/// `pair` is the gear pair the FE rotor was built from (teeth, modules, widths, hands).
GearTrainSpec gearTrainFromFeRotor(const FeGearedRotorSpec& rotor, const GearPairSpec& pair);

}  // namespace geardyn
