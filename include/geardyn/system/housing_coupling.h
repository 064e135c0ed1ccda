#pragma once
/// \file
/// A gear train on a flexible housing (issue #37, item 3, first part): the train's linear
/// matrices joined to a reduced housing (models/housing_superelement.h) at the bearings' outer
/// rings. Each linked bearing acts between its shaft and its seat's interface node instead of
/// the ground: with J the bearing's Jacobian on the shaft DOFs (its relative displacement
/// d = J q_shaft today) and J_h the seat's rigid motion at the bearing point p,
///   d = J q_shaft − J_h q_seat,   J_h rows: u_y = u_cy + θ_z r_x − θ_x r_z,
///   u_z = u_cz + θ_x r_y − θ_y r_x, u_x = u_cx + θ_y r_z − θ_z r_y, tilt_y = θ_y, tilt_z = θ_z,
///   torsion = θ_x,   r = p − c (c: the seat's centre; r_x = 0 unless the DOFs are full: a
///   planar train has no axial positions, its bearings sit in their seats' planes),
/// so the bearing's stiffness k (and damping c) adds −Jᵀ k J_h, −J_hᵀ k J and J_hᵀ k J_h to the
/// coupled K (C); the housing's reduced K and M fill the housing block, its damping is
/// stiffness-proportional (β K_h). The machine itself holds a housing through
/// GearTrainSpec::housing (train_housing.h); this function builds that model and returns its
/// matrices.

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "geardyn/models/housing_superelement.h"
#include "geardyn/system/gear_train_model.h"
#include "geardyn/system/train_housing.h"

namespace geardyn {

/// The coupled linear matrices: the train's DOFs first (as in GearTrainModel), then the
/// housing's (interface DOFs, then modal coordinates).
struct HousedTrain {
  Eigen::MatrixXd M;  ///< [kg, ...]
  Eigen::MatrixXd K;  ///< GearTrainModel::meanStiffnessAt(Ω) joined to the housing's [N/m, ...]
  Eigen::MatrixXd C;  ///< GearTrainModel::dampingAt(Ω) joined to the housing's [N s/m, ...]
  int housing_first_dof = 0;
};

/// Joins `model` (at input speed Ω [rad/s]) to `housing` through `links`. `beta` [s]: the
/// housing's stiffness-proportional damping. InputError naming "housing.seats.<bearing>" when
/// the bearing does not exist, joins two shafts or is a rolling bearing (not yet), and when the
/// seat is not in the housing; "housing.seats" when a seat carries no bearing.
HousedTrain coupleHousing(const GearTrainModel& model, const ReducedHousing& housing,
                          const std::vector<HousingLink>& links, double input_speed = 0.0,
                          double beta = 0.0);

}  // namespace geardyn
