#pragma once
/// \file
/// Internals shared by the gear-train assembly files (gear_train_model.cpp, train_meshes.cpp,
/// train_loads.cpp): references by name, the kinematics of material points, frames.

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "geardyn/system/gear_train_model.h"

namespace geardyn::detail {

/// The in-plane displacement (y, z) of a material point: J q[dofs] [m].
struct PointJacobian {
  std::vector<int> dofs;
  Eigen::Matrix<double, 2, Eigen::Dynamic> J;
};

/// The body of the shaft called `name`; InputError naming `key` with a did-you-mean otherwise.
int shaftBodyOf(const GearTrainModel& model, const GearTrainSpec& spec, const std::string& name,
                const std::string& key);
/// The index in spec.gears of the gear called `name`; InputError naming `key` otherwise.
int gearIndexOf(const GearTrainSpec& spec, const std::string& name, const std::string& key);

/// sign × the translation of body b's centre. A planet with torsional DOFs only rides on its
/// carrier: its centre moves with the carrier's rotation (rigid pin).
PointJacobian translationJacobian(const GearTrainModel& model, int body, double sign);
/// sign × the displacement of the material point at `point` (y, z) [m] of body b:
/// u + θ × (point − centre).
PointJacobian pointJacobian(const GearTrainModel& model, int body, const Eigen::Vector2d& point,
                            double sign);
/// The sum of several point Jacobians over the union of their DOFs.
void stackJacobians(const std::vector<PointJacobian>& parts, std::vector<int>& dofs,
                    Eigen::MatrixXd& J);

/// A lateral connection between bodies formulated in different rotating frames is refused
/// (it would be time-varying): InputError naming `key`.
void requireSameFrame(const GearTrainModel& model, int a, int b, const std::string& key);

int carrierBody(const GearTrainModel& model, int stage);
double carrierSpeedRatio(const GearTrainModel& model, const GearTrainSpec& spec, int stage);

/// Input and output torques and the planet pins' position errors into F₀; the output torque
/// (lossless: T_out = −T_in Ω_in/Ω_out) [N m].
void applyOperatingLoads(const GearTrainModel& model, const GearTrainSpec& spec,
                         Eigen::VectorXd& F0, double& output_torque);

}  // namespace geardyn::detail
