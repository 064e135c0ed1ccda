#pragma once
/// \file
/// A clearance bearing's law over its nonlinear coordinates (bearing_clearance.h), as the
/// nonlinear solvers apply it: 2 coordinates u = (u_y, u_z) for the clearance law and for a
/// rolling bearing's full law with planar DOFs; 5, u = (u_y, u_z, u_x, θ_y, θ_z), for a rolling
/// bearing's full law with full DOFs (bearings.<name>.model = "nonlinear", issue 35:
/// docs/theory/rolling_bearings.md), whose force is the bearing's whole F(q), its slope the
/// 5 × 5 tangent, and whose stiffness kept in K is the linearised bearing's 5 × 5 tangent at the
/// static deflection (its element in GearTrainModel::elements()). Fixed-capacity vectors and
/// matrices: no heap allocation in the solvers' loops.

#include <Eigen/Dense>
#include <vector>

#include "geardyn/system/gear_train_model.h"

namespace geardyn {

class TrainBearingLaw {
 public:
  using Vector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 5, 1>;
  using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 5, 5>;

  /// `bearing` one of model.clearanceBearings() (both must outlive the law).
  TrainBearingLaw(const GearTrainModel& model, const TrainClearanceBearing& bearing);
  const TrainClearanceBearing& bearing() const noexcept { return *bearing_; }
  /// The number of coordinates u (rows of the bearing's Jacobian): 2 or 5.
  int width() const noexcept { return width_; }
  /// The stiffness kept in K over u [N/m, N/rad, N m/m, N m/rad].
  const Matrix& linear() const noexcept { return linear_; }
  /// The contact force f(u) [N, N m] and ∂f/∂u in *J_f_u (may be null).
  Vector contactForce(const Vector& u, Matrix* J_f_u) const;
  /// f̃(u) = f(u) − K_lin u and ∂f̃/∂u = ∂f/∂u − K_lin in *J_f_u (may be null).
  Vector correctionForce(const Vector& u, Matrix* J_f_u) const;
  /// ∂f/∂u averaged along the straight segment from u0 to u1 (midpoint rule, 16 points).
  Matrix meanStiffness(const Vector& u0, const Vector& u1) const;
  /// The displacement carrying the force K_lin u_lin (TrainClearanceBearing::loadedDisplacement;
  /// width 5: Newton on f(u) = K_lin u_lin from u_lin moved out radially by the play).
  Vector loadedDisplacement(const Vector& u_lin) const;
  /// Some contact carries load at u.
  bool touching(const Vector& u) const;

 private:
  const TrainClearanceBearing* bearing_;
  int width_;
  Matrix linear_;
};

/// The laws of model.clearanceBearings(), in order.
std::vector<TrainBearingLaw> trainBearingLaws(const GearTrainModel& model);

}  // namespace geardyn
