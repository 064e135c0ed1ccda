/// The radial clearance law of a bearing (bearing_clearance.h).

#include "geardyn/system/bearing_clearance.h"

namespace geardyn {

Eigen::Vector2d TrainClearanceBearing::contactForce(const Eigen::Vector2d& u,
                                                    Eigen::Matrix2d* J_f_u) const {
  const double rho = u.norm();
  if (!(rho > clearance)) {
    if (J_f_u) J_f_u->setZero();
    return Eigen::Vector2d::Zero();
  }
  const double ratio = clearance / rho;  // c/|u| < 1
  if (J_f_u) {
    *J_f_u = stiffness * ((1.0 - ratio) * Eigen::Matrix2d::Identity() +
                          (ratio / (rho * rho)) * (u * u.transpose()));
  }
  return stiffness * (1.0 - ratio) * u;
}

Eigen::Vector2d TrainClearanceBearing::correctionForce(const Eigen::Vector2d& u,
                                                       Eigen::Matrix2d* J_f_u) const {
  const Eigen::Vector2d f = contactForce(u, J_f_u) - stiffness * u;
  if (J_f_u) J_f_u->diagonal().array() -= stiffness;
  return f;
}

Eigen::Matrix2d TrainClearanceBearing::meanStiffness(const Eigen::Vector2d& u0,
                                                     const Eigen::Vector2d& u1) const {
  constexpr int kPoints = 16;
  Eigen::Matrix2d sum = Eigen::Matrix2d::Zero(), J;
  for (int i = 0; i < kPoints; ++i) {
    const double lambda = (i + 0.5) / kPoints;
    contactForce(u0 + lambda * (u1 - u0), &J);
    sum += J;
  }
  return sum / kPoints;
}

Eigen::Vector2d TrainClearanceBearing::displacement(
    const Eigen::Ref<const Eigen::VectorXd>& q) const {
  Eigen::Vector2d u = Eigen::Vector2d::Zero();
  for (std::size_t i = 0; i < dofs.size(); ++i) u += jacobian.col(i) * q(dofs[i]);
  return u;
}

}  // namespace geardyn
