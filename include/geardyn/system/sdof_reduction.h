#pragma once
/// \file
/// The single-degree-of-freedom gear pair as the fast path of a one-mesh train: a train of two
/// rigid shafts with torsional DOFs and one external mesh, and nothing else, IS the model
/// of system/gear_pair_model.h along the line of action (docs/theory/gear_trains.md; checked by
/// tests/system/train_response_test.cpp, TrainReduction.SinglePairTorsionalIsTheSdofGearPairModel):
///
///   m_e = 1 / (r_a²/I_a + r_b²/I_b),  F = T / r_a,  f_m = z_a |Ω_a| / 2π,  c = c_m,
///   k(φ), e(φ) and the mesh phase of the train's mesh,
///
/// with the contact law kept and the backlash converted: the train's `backlash` j is the full
/// normal clearance (free play −j ≤ δ − e ≤ 0), the SDOF model's b the half clearance
/// (−b ≤ y ≤ b), so b = j / 2 and y = δ − e + b.
///
/// A helical mesh acts along the contact normal, inclined by β_b; the gear-pair model along the
/// transverse line of action, δ_n = δ_t cos β_b (docs/theory/mesh_stiffness.md, "Which plane"):
/// m_t = m_n cos² β_b (= 1 / (r_a²/I_a + r_b²/I_b) again), k_t = k_n cos² β_b,
/// c_t = c_n cos² β_b, F_t = F_n cos β_b (= T / r_a), e_t = e_n / cos β_b, j_t = j_n / cos β_b.
/// Tooth-pair contact elements: k_t = k_n cos² β_b, g_t = g_n / cos β_b.

#include <string>

#include "geardyn/system/gear_pair_model.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn {

/// Why `train` is not a single rigid external pair with torsional DOFs (empty: it is one).
std::string sdofReductionObstacle(const GearTrainModel& train);

/// The gear-pair model of a single-pair train at its operating point (speed and input torque).
/// Throws InputError naming what stands in the way (sdofReductionObstacle).
GearPairModelSpec sdofReduction(const GearTrainModel& train);

}  // namespace geardyn
