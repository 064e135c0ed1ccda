/// A clearance bearing's law over its 2 or 5 nonlinear coordinates (bearing_law.h).

#include "geardyn/system/bearing_law.h"

#include <stdexcept>

#include "geardyn/contact/rolling_bearing.h"

namespace geardyn {

TrainBearingLaw::TrainBearingLaw(const GearTrainModel& model, const TrainClearanceBearing& bearing)
    : bearing_(&bearing), width_(static_cast<int>(bearing.jacobian.rows())) {
  if (width_ == 2) {
    linear_ = bearing.linearStiffness();
    return;
  }
  // A full-DOF rolling bearing: K keeps its linearised element, the 5 × 5 tangent at the static
  // deflection (GearTrainModel::linearisedAt, train_rolling_bearings.cpp).
  for (const TrainElement& e : model.elements()) {
    if (e.kind == "bearing" && e.name == bearing.name && e.local_stiffness.rows() == 5) {
      linear_ = e.local_stiffness;
      return;
    }
  }
  throw std::logic_error("bearing " + bearing.name + ": no linearised 5 x 5 element in K");
}

TrainBearingLaw::Vector TrainBearingLaw::contactForce(const Vector& u, Matrix* J_f_u) const {
  if (width_ == 2) {
    Eigen::Matrix2d J;
    const Eigen::Vector2d f = bearing_->contactForce(Eigen::Vector2d(u), J_f_u ? &J : nullptr);
    if (J_f_u) *J_f_u = J;
    return f;
  }
  // The whole law over (u_y, u_z, u_x, θ_y, θ_z).
  RollingBearing::Vector5 F;
  RollingBearing::Matrix5 K;
  bearing_->rolling->evaluate(RollingBearing::Vector5(u), F, J_f_u ? &K : nullptr);
  if (J_f_u) *J_f_u = K;
  return F;
}

TrainBearingLaw::Vector TrainBearingLaw::correctionForce(const Vector& u, Matrix* J_f_u) const {
  Vector f = contactForce(u, J_f_u);
  f.noalias() -= linear_ * u;
  if (J_f_u) *J_f_u -= linear_;
  return f;
}

TrainBearingLaw::Matrix TrainBearingLaw::meanStiffness(const Vector& u0, const Vector& u1) const {
  if (width_ == 2) return bearing_->meanStiffness(Eigen::Vector2d(u0), Eigen::Vector2d(u1));
  constexpr int kPoints = 16;  // midpoint rule, as TrainClearanceBearing::meanStiffness
  Matrix sum = Matrix::Zero(width_, width_), J(width_, width_);
  for (int i = 0; i < kPoints; ++i) {
    const double lambda = (i + 0.5) / kPoints;
    contactForce(Vector(u0 + lambda * (u1 - u0)), &J);
    sum += J;
  }
  return sum / kPoints;
}

TrainBearingLaw::Vector TrainBearingLaw::loadedDisplacement(const Vector& u_lin) const {
  if (width_ == 2) return bearing_->loadedDisplacement(Eigen::Vector2d(u_lin));
  // Newton on f(u) = K_s u_lin, halving a step that does not lower the residual, from u_lin
  // moved out radially by the play (as the 2-D rolling case).
  const Vector target = linear_ * u_lin;
  Vector u = u_lin;
  const double radius = u_lin.head<2>().norm();
  if (radius > 0.0) u.head<2>() *= 1.0 + bearing_->clearance / radius;
  Matrix J(width_, width_);
  Vector r = contactForce(u, &J) - target;
  for (int it = 0; it < 60 && r.norm() > 1e-12 * target.norm(); ++it) {
    const Eigen::FullPivLU<Matrix> lu(J);
    const Vector step =
        lu.isInvertible() ? Vector(lu.solve(r)) : Vector(linear_.fullPivLu().solve(r));
    double lambda = 1.0;
    Vector trial = u - step, r_trial = contactForce(trial, nullptr) - target;
    while (r_trial.norm() >= r.norm() && lambda > 1e-6) {
      lambda *= 0.5;
      trial = u - lambda * step;
      r_trial = contactForce(trial, nullptr) - target;
    }
    if (!(r_trial.norm() < r.norm())) break;
    u = trial;
    r = contactForce(u, &J) - target;
  }
  return u;
}

bool TrainBearingLaw::touching(const Vector& u) const {
  if (width_ == 2) return bearing_->touching(Eigen::Vector2d(u));
  Matrix J(width_, width_);
  contactForce(u, &J);
  return J.trace() > 0.0;
}

std::vector<TrainBearingLaw> trainBearingLaws(const GearTrainModel& model) {
  std::vector<TrainBearingLaw> laws;
  for (const TrainClearanceBearing& b : model.clearanceBearings()) laws.emplace_back(model, b);
  return laws;
}

}  // namespace geardyn
