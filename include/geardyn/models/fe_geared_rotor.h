#pragma once
/// \file
/// The finite-element two-shaft geared rotor of Visnadi & de Castro (2021) §3, after Rao et al.
/// (1998) and Kubur et al. (2004): Timoshenko shafts, rigid disks, linear bearings, gyroscopic
/// coupling and a gear mesh between a pinion node and a gear node,
///
///   M q̈ + (C + Ω_p G₁) q̇ + (K + k_m(φ) v vᵀ) q = F + k_m(φ) e(φ) v + F_u(t)        (eq. 10)
///
/// with q the nodal DOFs [u_x, u_y, u_z, θ_x, θ_y, θ_z] of every node (axial DOFs removed unless
/// `axial`), k_m the mesh stiffness of any MeshStiffness model at the mesh phase φ = z_p θ_p/2π,
/// e the transmission error (mesh deflection the teeth impose; the mesh force is
/// k_m (vᵀq − e)), v the mesh deflection gradient (gear_mesh_coupling.h), Ω_p the pinion speed
/// and G₁ the gyroscopic matrix per unit pinion speed (the gear shaft spins at −z_p/z_g Ω_p,
/// in the opposite sense). C = α M + β K_shafts + bearing dashpots + c_m v vᵀ.
///
/// The drive torque T acts about +x at a pinion-shaft node and the load torque T r_bg/r_bp about
/// +x at a gear-shaft node (the gear turns about −x), so the rolling rigid-body mode is in
/// equilibrium; gravity acts along −z. Models do not know solvers: this class only assembles.

#include <Eigen/Dense>
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "geardyn/models/gear_mesh_coupling.h"
#include "geardyn/models/timoshenko_shaft_element.h"
#include "geardyn/models/transmission_error.h"
#include "geardyn/stiffness/mesh_stiffness.h"

namespace geardyn {

/// A linear bearing (or support) at a node: translational springs and dashpots with cross terms
/// [N/m, N s/m], optional tilt and torsional springs [N m/rad] and dashpots [N m s/rad].
struct FeBearing {
  int node = 0;
  double kxx = 0, kyy = 0, kzz = 0, kyz = 0, kzy = 0;
  double cxx = 0, cyy = 0, czz = 0, cyz = 0, czy = 0;
  double k_tilt = 0, c_tilt = 0, k_torsion = 0, c_torsion = 0;
};

/// A rigid disk at a node: mass [kg], polar and diametral moments of inertia [kg m²].
struct FeDisk {
  int node = 0;
  double mass = 0, polar_inertia = 0, diametral_inertia = 0;
};

/// A mass unbalance at a node: m e [kg m] at angle `phase` [rad] from +y towards +z at t = 0,
/// turning with its shaft.
struct FeUnbalance {
  int node = 0;
  double amount = 0, phase = 0;
};

/// One shaft: elements from node 0 to node n, bearings, disks (the gear body included),
/// unbalances and the node carrying the gear.
struct FeShaftSpec {
  std::string name;
  std::vector<ShaftSegment> elements;
  std::vector<FeBearing> bearings;
  std::vector<FeDisk> disks;
  std::vector<FeUnbalance> unbalances;
  int gear_node = 0;
  int nodeCount() const { return static_cast<int>(elements.size()) + 1; }
};

/// Pinion speed Ω_p(t) [rad/s]: constant `start` before `ramp_start`, a linear ramp to `end` at
/// `ramp_end`, then constant. start = end is a constant speed.
struct SpeedProfile {
  double start = 0.0, end = 0.0;
  double ramp_start = 0.0, ramp_end = 0.0;  ///< [s]
  double speed(double t) const;
  double acceleration(double t) const;
  /// θ_p(t) = ∫₀ᵗ Ω_p dt [rad], exact for the piecewise-linear speed.
  double angle(double t) const;
  bool constant() const { return start == end; }
  double maxSpeed() const;
};

struct FeGearedRotorSpec {
  std::array<FeShaftSpec, 2> shafts;  ///< [0] pinion shaft, [1] gear shaft
  MeshCouplingGeometry mesh;
  int pinion_teeth = 0, gear_teeth = 0;
  std::shared_ptr<const MeshStiffness> mesh_stiffness;  ///< k_m(φ) [N/m]
  TransmissionError transmission_error;                 ///< e(φ) [m]
  double mesh_damping = 0.0;                            ///< c_m along the line of action [N s/m]
  double mass_proportional = 0.0;                       ///< α [1/s]
  double stiffness_proportional = 0.0;                  ///< β [s] (shaft elements)
  double drive_torque = 0.0;                            ///< T on the pinion shaft [N m]
  int drive_node = 0;                                   ///< pinion-shaft node of T
  int load_node = 0;                                    ///< gear-shaft node of the load torque
  double gravity = 0.0;                                 ///< [m/s²] along −z
  bool axial = false;  ///< keep the axial DOFs (needs axial bearing stiffness)
  SpeedProfile speed;
};

class FeGearedRotor {
 public:
  /// Validates (InputError naming the config key) and assembles.
  explicit FeGearedRotor(FeGearedRotorSpec spec);

  const FeGearedRotorSpec& spec() const noexcept { return spec_; }
  int dofCount() const noexcept { return static_cast<int>(active_.size()); }
  /// Active index of a node DOF, or −1 when the DOF is removed (axial without `axial`).
  int dofIndex(int shaft, int node, int dof) const;
  /// "pinion_shaft.1.uy"-style name of an active DOF.
  std::string dofName(int index) const;
  /// Shaft (0/1) and DOF type (NodeDof) of an active DOF.
  int shaftOf(int index) const { return dof_shaft_[index]; }
  int typeOf(int index) const { return dof_type_[index]; }
  int nodeOf(int index) const { return dof_node_[index]; }

  const Eigen::MatrixXd& mass() const noexcept { return M_; }
  /// Structural stiffness K (shafts, bearings), without the mesh [N/m …].
  const Eigen::MatrixXd& stiffness() const noexcept { return K_; }
  /// Damping C (proportional, bearings, mesh dashpot) without the gyroscopic part.
  const Eigen::MatrixXd& damping() const noexcept { return C_; }
  /// G₁: the gyroscopic matrix per unit pinion speed (skew) [kg m²].
  const Eigen::MatrixXd& gyroscopic() const noexcept { return G_; }
  /// The mesh deflection gradient v over the active DOFs.
  const Eigen::VectorXd& meshVector() const noexcept { return v_; }
  /// Constant loads: drive and load torques, gravity [N, N m].
  const Eigen::VectorXd& staticLoad() const noexcept { return F0_; }

  double meshStiffness(double phase) const { return spec_.mesh_stiffness->stiffness(phase); }
  double meanMeshStiffness() const noexcept { return k_mean_; }
  double transmissionError(double phase) const { return spec_.transmission_error.value(phase); }
  /// φ at time t: z_p θ_p(t) / 2π.
  double meshPhase(double t) const;
  /// Spin of a shaft per unit pinion speed: 1 and −z_p/z_g.
  double spinRatio(int shaft) const;
  /// The transmitted force along the line of action T/r_bp (with β_b: T/(r_bp cos β_b)) [N].
  double nominalMeshForce() const;

  /// Adds the unbalance forces at time t to f (f sized dofCount()).
  void addUnbalanceForce(double t, Eigen::Ref<Eigen::VectorXd> f) const;
  bool hasUnbalance() const noexcept { return !unbalance_dofs_.empty(); }

 private:
  FeGearedRotorSpec spec_;
  std::vector<int> active_;          // full index of each active DOF
  std::vector<int> full_to_active_;  // −1 when removed
  std::vector<int> dof_shaft_, dof_node_, dof_type_;
  std::array<int, 2> node_offset_{};  // first full index of each shaft's node 0
  Eigen::MatrixXd M_, K_, C_, G_;
  Eigen::VectorXd v_, F0_;
  double k_mean_ = 0.0;
  struct UnbalanceDofs {
    int y, z, shaft;
    double amount, phase;
  };
  std::vector<UnbalanceDofs> unbalance_dofs_;
};

}  // namespace geardyn
