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

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace geardyn {

struct TrainClearanceBearing {
  std::string name;          ///< the bearing's name (key bearings.<name>)
  std::vector<int> dofs;     ///< the DOFs u depends on
  Eigen::MatrixXd jacobian;  ///< u = J q[dofs] (2 rows: y, z)
  double stiffness = 0.0;    ///< k = kyy = kzz [N/m]
  double clearance = 0.0;    ///< c [m]

  /// The contact force f(u) [N] and ∂f/∂u [N/m] in *J_f_u.
  Eigen::Vector2d contactForce(const Eigen::Vector2d& u, Eigen::Matrix2d* J_f_u = nullptr) const;
  /// f̃(u) = f(u) − k u [N] (what the nonlinear solvers add to the linear bearing in K) and
  /// ∂f̃/∂u = ∂f/∂u − k I in *J_f_u.
  Eigen::Vector2d correctionForce(const Eigen::Vector2d& u, Eigen::Matrix2d* J_f_u = nullptr) const;
  /// ∂f/∂u averaged along the straight segment from u0 to u1 (midpoint rule, 16 points): the
  /// slope held over a sampling interval of the monodromy matrix [N/m].
  Eigen::Matrix2d meanStiffness(const Eigen::Vector2d& u0, const Eigen::Vector2d& u1) const;
  /// u of a state q (all the model's DOFs) [m].
  Eigen::Vector2d displacement(const Eigen::Ref<const Eigen::VectorXd>& q) const;
};

}  // namespace geardyn
