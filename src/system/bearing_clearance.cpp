/// The radial clearance law of a bearing (bearing_clearance.h).

#include "geardyn/system/bearing_clearance.h"

#include <cmath>

#include "geardyn/contact/rolling_bearing.h"

namespace geardyn {

Eigen::Vector2d TrainClearanceBearing::contactForce(const Eigen::Vector2d& u,
                                                    Eigen::Matrix2d* J_f_u) const {
  if (rolling) {  // the full law at (u_y, u_z), the axial and tilt rows held (planar DOFs)
    RollingBearing::Vector5 q = RollingBearing::Vector5::Zero(), F;
    q.head<2>() = u;
    RollingBearing::Matrix5 K;
    rolling->evaluate(q, F, J_f_u ? &K : nullptr);
    if (J_f_u) *J_f_u = K.topLeftCorner<2, 2>();
    return F.head<2>();
  }
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
  const Eigen::Matrix2d k = linearStiffness();
  const Eigen::Vector2d f = contactForce(u, J_f_u) - k * u;
  if (J_f_u) *J_f_u -= k;
  return f;
}

Eigen::Vector2d TrainClearanceBearing::loadedDisplacement(const Eigen::Vector2d& u_lin) const {
  const double radius = u_lin.norm();
  if (!(radius > 0.0)) return u_lin;  // unloaded: no direction to move along
  if (!rolling) return u_lin * (1.0 + clearance / radius);
  // Newton on f(u) = K_s u_lin, halving a step that does not lower the residual (the law
  // stiffens: a full step from a point with few elements loaded overshoots).
  const Eigen::Vector2d target = linear * u_lin;
  Eigen::Vector2d u = u_lin * (1.0 + clearance / radius);
  Eigen::Matrix2d J;
  Eigen::Vector2d r = contactForce(u, &J) - target;
  for (int it = 0; it < 60 && r.norm() > 1e-12 * target.norm(); ++it) {
    if (!(std::abs(J.determinant()) > 0.0)) J = linear;  // no element loaded yet
    const Eigen::Vector2d step = J.partialPivLu().solve(r);
    double lambda = 1.0;
    Eigen::Vector2d trial = u - step, r_trial = contactForce(trial) - target;
    while (r_trial.norm() >= r.norm() && lambda > 1e-6) {
      lambda *= 0.5;
      trial = u - lambda * step;
      r_trial = contactForce(trial) - target;
    }
    if (!(r_trial.norm() < r.norm())) break;
    u = trial;
    r = contactForce(u, &J) - target;
  }
  return u;
}

bool TrainClearanceBearing::touching(const Eigen::Vector2d& u) const {
  if (!rolling) return u.norm() > clearance;
  Eigen::Matrix2d J;
  contactForce(u, &J);
  return J.trace() > 0.0;
}

Eigen::Matrix2d TrainClearanceBearing::meanStiffness(const Eigen::Vector2d& u0,
                                                     const Eigen::Vector2d& u1) const {
  constexpr int kPoints = 16;  // midpoint rule
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
  // (u_y, u_z): a full-DOF rolling bearing's first two rows of five (bearing_law.h).
  for (std::size_t i = 0; i < dofs.size(); ++i) u += jacobian.col(i).head<2>() * q(dofs[i]);
  return u;
}

}  // namespace geardyn
