#pragma once
/// \file
/// A mesh's force from a sampled displacement, for comparing time integration with the
/// frequency-domain steady state sample by sample: f = k(φ(t)) (vᵀq − e(φ(t))) [N], the linear
/// mesh law of the gear-train model (system/gear_train_model.h).

#include <Eigen/Core>

#include "geardyn/system/gear_train_model.h"

namespace geardyn::testing {

/// The force of `mesh` at time `t` [s] and input speed `speed` [rad/s] for the displacement row
/// `q` (all the model's DOFs) [N].
inline double meshForceAt(const TrainMesh& mesh, const Eigen::Ref<const Eigen::RowVectorXd>& q,
                          double t, double speed) {
  const double phi = mesh.phaseAt(t, speed);
  double d = 0.0;
  for (std::size_t i = 0; i < mesh.dofs.size(); ++i) d += mesh.gradient[i] * q(mesh.dofs[i]);
  return mesh.stiffness->stiffness(phi) * (d - mesh.transmission_error.value(phi));
}

}  // namespace geardyn::testing
