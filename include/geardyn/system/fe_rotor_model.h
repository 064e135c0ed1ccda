#pragma once
/// \file
/// The two-shaft finite-element geared rotor of Visnadi & de Castro (2021) §3 (after Rao et al.
/// 1998 and Kubur et al. 2004) as what it is: a gearbox (GearTrainSpec) with two flexible
/// shafts, full DOFs, bearings and disks at the shafts' nodes, one mesh, and unbalances — plus the
/// FE rotor file's own numbering of it. There is no second assembly: every matrix is the gear
/// train's (GearTrainModel), restricted to the DOFs the FE rotor keeps,
///
///   M q̈ + (C + Ω_p G₁) q̇ + (K + k_m(φ) v vᵀ) q = F₀ + k_m(φ) e(φ) v + F_u(t)        (eq. 10)
///
/// with q the nodal DOFs [u_x, u_y, u_z, θ_x, θ_y, θ_z] of every node, shaft after shaft (the
/// axial u_x removed unless `axial`: held at zero), the mesh at the gears' nodes.
///
/// The loads are the train's too: the drive torque T about +x at the pinion shaft's drive node,
/// the load torque T r_bg/r_bp about +x at the gear shaft's load node, and gravity along −z
/// (the beams' consistent load w L/2 and ± w L²/12 at the end nodes, the disks' weight), written
/// in closed form (the train's −g M e_z to round-off).

#include <Eigen/Dense>
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "geardyn/models/timoshenko_shaft_element.h"
#include "geardyn/system/gear_train.h"
#include "geardyn/system/gear_train_model.h"
#include "geardyn/system/speed_profile.h"

namespace geardyn {

/// How the FE rotor file numbers its gearbox's stations (node i of a shaft is the end of its
/// i-th section; node 0 its start).
struct FeRotorLayout {
  std::array<int, 2> gear_nodes{};                ///< node of each shaft's gear
  std::array<std::vector<int>, 2> bearing_nodes;  ///< node of each bearing, in the file's order
  int drive_node = 0;                             ///< pinion-shaft node of the drive torque
  int load_node = 0;                              ///< gear-shaft node of the load torque
  bool axial = false;                             ///< keep the axial DOFs (otherwise held at zero)
  /// ψ, the transverse line of action from the vertical z axis as [mesh] gives it [rad]
  /// (reported; the train's mesh holds the same line as its position angle).
  double line_of_action_angle = 0.0;
  SpeedProfile speed;  ///< pinion speed [rad/s]
};

class FeRotorModel {
 public:
  /// `train`: shafts[0] the pinion shaft and shafts[1] the gear shaft (flexible, one section
  /// per element), gears[0] the pinion on shafts[0], one mesh, full DOFs. Assembles the train
  /// (its InputErrors name the train's keys) and the FE rotor's DOF numbering.
  FeRotorModel(GearTrainSpec train, FeRotorLayout layout);

  const GearTrainModel& train() const noexcept { return *train_; }
  const FeRotorLayout& layout() const noexcept { return layout_; }
  const SpeedProfile& speed() const noexcept { return layout_.speed; }
  bool axial() const noexcept { return layout_.axial; }
  int pinionTeeth() const noexcept { return train_->meshes().front().teeth_a; }
  int gearTeeth() const noexcept { return train_->meshes().front().teeth_b; }
  const std::string& shaftName(int shaft) const { return train_->spec().shafts[shaft].name; }
  int nodeCount(int shaft) const { return static_cast<int>(train_->shaftNodes(shaft).size()); }

  int dofCount() const noexcept { return static_cast<int>(train_dofs_.size()); }
  /// Index of a node DOF (NodeDof: ux, uy, uz, rx, ry, rz), or −1 when the DOF is removed or out of
  /// range.
  int dofIndex(int shaft, int node, int dof) const;
  /// "pinion_shaft.1.uy"-style name of a DOF.
  std::string dofName(int index) const;
  int shaftOf(int index) const { return dof_shaft_[index]; }
  int typeOf(int index) const { return dof_type_[index]; }
  int nodeOf(int index) const { return dof_node_[index]; }
  /// The train DOF of each of the FE rotor's DOFs (TrainStepperSetup::dofs).
  const std::vector<int>& trainDofs() const noexcept { return train_dofs_; }

  /// The train's matrices over the FE rotor's DOFs: M, K without the mesh, C (proportional,
  /// bearings, mesh dashpot) and G₁ per unit pinion speed [SI].
  const Eigen::MatrixXd& mass() const noexcept { return M_; }
  const Eigen::MatrixXd& stiffness() const noexcept { return K_; }
  const Eigen::MatrixXd& damping() const noexcept { return C_; }
  const Eigen::MatrixXd& gyroscopic() const noexcept { return G_; }
  /// The mesh deflection gradient v over the FE rotor's DOFs.
  const Eigen::VectorXd& meshVector() const noexcept { return v_; }
  /// The train's constant loads F₀ (torques, gravity) over the FE rotor's DOFs [N, N m].
  const Eigen::VectorXd& staticLoad() const noexcept { return F0_; }

  /// k_m(φ) [N/m] and e(φ) [m] of the mesh at mesh phase φ [mesh periods].
  double meshStiffness(double phase) const;
  double transmissionError(double phase) const;
  double meanMeshStiffness() const { return train_->meshes().front().mean_stiffness; }
  /// φ at time t: z_p θ_p(t) / 2π.
  double meshPhase(double t) const;
  /// Spin of a shaft per unit pinion speed: 1 and −z_p/z_g.
  double spinRatio(int shaft) const;
  /// The transmitted force along the contact normal |T|/(r_bp cos β_b) [N], on the loaded flank
  /// (the train orients the mesh by the load: with T < 0 the other flank carries it).
  double nominalMeshForce() const;
  bool hasUnbalance() const noexcept { return !train_->spec().unbalances.empty(); }

 private:
  void addLoads();

  std::unique_ptr<const GearTrainModel> train_;
  FeRotorLayout layout_;
  std::vector<int> train_dofs_;
  std::vector<int> dof_shaft_, dof_node_, dof_type_;
  std::array<std::vector<int>, 2> index_;  // node * 6 + dof → index, −1 when removed
  Eigen::MatrixXd M_, K_, C_, G_;
  Eigen::VectorXd v_, F0_;
};

}  // namespace geardyn
