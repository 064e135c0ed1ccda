#pragma once
/// \file
/// The nonlinear static deflection of a train with bearings from their geometry
/// (train_response.h, solveTrainStatic).

#include <Eigen/Dense>

#include "geardyn/solvers/train_response.h"

namespace geardyn::detail {

/// K̄ q + Σ_b J_bᵀ F_b(J_b q) = F by damped Newton (Levenberg–Marquardt on the bearings'
/// reference stiffness, minimum-norm steps on the train's rigid-body modes), from the linear
/// solution with every bearing at its reference stiffness. Fills r's displacement, residual,
/// rigid_modes (of the tangent at the solution), iterations, rolling_bearings, and status and
/// message when it does not converge.
void solveRollingBearingStatics(const GearTrainModel& model, const Eigen::MatrixXd& K,
                                const Eigen::VectorXd& F, TrainStaticResult& r);

}  // namespace geardyn::detail
