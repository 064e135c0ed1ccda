#pragma once
/// \file
/// The two-shaft finite-element geared rotor (models/fe_geared_rotor.h, Visnadi & de Castro
/// 2021 §3) as a gear-train description: two flexible shafts with full DOFs, their elements as
/// sections, bearings and disks at their nodes' positions, one mesh whose position angle puts
/// the line of action where the FE rotor's angle ψ does, and the drive and load torques at the
/// same nodes. GearTrainModel of the result reproduces FeGearedRotor's M, K, G₁, the mesh
/// vector, F₀ (without gravity) and C, whose β K_shafts is each flexible shaft's
/// stiffness_proportional_damping (tests/system/fe_rotor_reduction_test.cpp). Differences:
/// unbalances are refused (InputError naming <shaft>.unbalance: a gear train has no unbalance
/// forces); gravity is carried as the gearbox's, which weighs the beam elements as well as the
/// disks (the FE rotor weighs its disks only), so F₀ differs by the shafts' own weight when
/// gravity ≠ 0 — the modes and the Campbell diagram do not depend on it.

#include <vector>

#include "geardyn/geometry/gear_pair.h"
#include "geardyn/models/fe_geared_rotor.h"
#include "geardyn/system/gear_train.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn {

/// `pair` is the gear pair the FE rotor was built from (teeth, modules, widths, hands).
GearTrainSpec gearTrainFromFeRotor(const FeGearedRotorSpec& rotor, const GearPairSpec& pair);

/// The train DOF of each of `fe`'s active DOFs, in `fe`'s order (`train` assembled from
/// gearTrainFromFeRotor of fe's spec): the node DOFs [u_x, u_y, u_z, θ_x, θ_y, θ_z] of the FE
/// rotor are the train's (y, z, θ_x, x, θ_y, θ_z) order (gear_train_model.h) at the same node.
std::vector<int> feRotorTrainDofs(const FeGearedRotor& fe, const GearTrainModel& train);

}  // namespace geardyn
