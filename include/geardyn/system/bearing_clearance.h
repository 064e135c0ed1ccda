#pragma once
/// \file
/// A bearing with radial clearance (issue 17, docs/theory/nonlinear_gear_trains.md): the journal
/// floats freely within a circle of radius c and the bearing's isotropic radial stiffness k acts
/// on the penetration beyond it,
///
///   f(u) = k (|u| − c) u / |u|   for |u| > c,   0 otherwise,
///
/// on the relative radial displacement u = (u_y, u_z) of the bearing (shaft vs housing, or vs the
/// other shaft) [m], f the force on the shaft [N] (restoring: it enters the equations as +f).
/// The assembled model keeps the linear bearing k Jᵀ J in K (so K̄ stays nonsingular when the
/// shaft floats) and the nonlinear solvers add f̃(u) = f(u) − k u, the meshes' f̃ = k g − k̄ δ
/// counterpart; c = 0 gives f̃ ≡ 0, the linear bearing. The Jacobian
///
///   ∂f/∂u = k [(1 − c/|u|) I + (c/|u|³) u uᵀ]   for |u| > c,   0 otherwise,
///
/// couples u_y and u_z (radial stiffness k, tangential k (1 − c/|u|)). Damping stays linear.
///
/// A rolling bearing from its geometry with `bearings.<name>.model = "nonlinear"` (issue 35,
/// docs/theory/rolling_bearings.md) takes the same place with its full load–deflection law:
/// f(u) = (F_y, F_z)(u_y, u_z, 0, 0, 0) of RollingBearing::evaluate (every element a Hertzian
/// contact, the clearance s_r included: elements leave contact), ∂f/∂u its tangent's (y, z)
/// block, and the linear part kept in K is the tangent K_s at the static deflection
/// (GearTrainModel::linearisedAt), so f̃(u) = f(u) − K_s u. Planar DOFs only (the axial and tilt
/// rows of a planar bearing are held at 0).

#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

namespace geardyn {

class RollingBearing;

struct TrainClearanceBearing {
  std::string name;          ///< the bearing's name (key bearings.<name>)
  std::vector<int> dofs;     ///< the DOFs u depends on
  Eigen::MatrixXd jacobian;  ///< u = J q[dofs] (2 rows: y, z)
  double stiffness = 0.0;    ///< k = kyy = kzz [N/m]
  double clearance = 0.0;    ///< c [m] (rolling: the radial play s_r / 2, ≥ 0, for reports)
  /// The full law of a rolling bearing (null: the clearance law above).
  std::shared_ptr<const RollingBearing> rolling;
  /// A rolling bearing's tangent over (u_y, u_z) at the static deflection, kept in K [N/m].
  Eigen::Matrix2d linear = Eigen::Matrix2d::Zero();
  /// The stiffness kept in K over (u_y, u_z) [N/m]: k I, or a rolling bearing's `linear`.
  Eigen::Matrix2d linearStiffness() const {
    return rolling ? linear : Eigen::Matrix2d(stiffness * Eigen::Matrix2d::Identity());
  }

  /// The contact force f(u) [N] and ∂f/∂u [N/m] in *J_f_u.
  Eigen::Vector2d contactForce(const Eigen::Vector2d& u, Eigen::Matrix2d* J_f_u = nullptr) const;
  /// f̃(u) = f(u) − k u [N] (what the nonlinear solvers add to the linear bearing in K) and
  /// ∂f̃/∂u = ∂f/∂u − k I in *J_f_u (rolling: K_s = `linear` in place of k I).
  Eigen::Vector2d correctionForce(const Eigen::Vector2d& u, Eigen::Matrix2d* J_f_u = nullptr) const;
  /// ∂f/∂u averaged along the straight segment from u0 to u1 (midpoint rule, 16 points): the
  /// slope held over a sampling interval of the monodromy matrix [N/m].
  Eigen::Matrix2d meanStiffness(const Eigen::Vector2d& u0, const Eigen::Vector2d& u1) const;
  /// The displacement at which the law carries the force K u_lin that the linear bearing
  /// carries at u_lin [m]: u_lin (1 + c/|u_lin|) for the clearance law (exact); a rolling
  /// bearing's by Newton on f(u) = linear u_lin from u_lin. Where the nonlinear solvers start.
  Eigen::Vector2d loadedDisplacement(const Eigen::Vector2d& u_lin) const;
  /// Some contact carries load at u (the journal touches; a rolling element is compressed).
  bool touching(const Eigen::Vector2d& u) const;
  /// u of a state q (all the model's DOFs) [m].
  Eigen::Vector2d displacement(const Eigen::Ref<const Eigen::VectorXd>& q) const;
};

}  // namespace geardyn
