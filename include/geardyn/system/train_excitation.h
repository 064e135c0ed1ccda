#pragma once
/// \file
/// The excitations of a gear train beside its meshes' transmission errors (gear_train.h):
/// unbalances, gear runouts and prescribed relative displacements across bearings, each a
/// harmonic force on a few DOFs
///
///   f(t) = Re[(k(φ_m) S + i ψ̇ D + (ψ̇² − i ψ̈) U) e^{i ν α(t)}],   ψ̇ = ν |Ω|, ψ̈ = ν d|Ω|/dt,
///
/// with α(t) = ∫|Ω| dt the input shaft's rotation [rad] (Ω t at constant speed), ν the term's
/// order (its angular frequency per unit input speed; signed for an unbalance, which turns with
/// its shaft), and S, D, U the complex stiffness, damping and inertia parts over the term's DOFs:
///   - unbalance m e at ψ₀ on a body turning at r Ω: U = m e e^{iψ₀} (1, −i) on (y, z), ν = r
///     sign Ω (m e ψ̇² (cos ψ, sin ψ) at constant speed);
///   - prescribed relative displacement d = Re[Δ e^{iνα}] across a bearing with K_b, C_b (and the
///     Rayleigh β K_b) and Jacobian J: S = Jᵀ K_b Δ, D = Jᵀ (C_b + β K_b) Δ;
///   - runout w = Re[W e^{iνα}] of gear g on mesh m (it adds v_gᵀ w to the mesh deflection):
///     S = −v_m (v_gᵀ W) times k_m(φ_m) (the mesh's time-varying stiffness: `mesh` ≥ 0),
///     D = −c_m v_m (v_gᵀ W).
/// The constant parts (a prescribed mean displacement) are static loads (GearTrainModel's F₀).

#include <Eigen/Dense>
#include <complex>
#include <string>
#include <vector>

namespace geardyn {

class GearTrainModel;

struct TrainExcitationTerm {
  std::string name;  ///< "unbalances.u1", "runouts.r1@mesh", "bearing_excitations.e.order_16"
  /// ν [-]: the angular frequency per unit input speed |Ω| (for `follows_direction`, per unit
  /// signed Ω: the effective ν is ratio × sign Ω).
  double ratio = 0.0;
  bool follows_direction = false;
  int mesh = -1;  ///< ≥ 0: S is multiplied by that mesh's k(φ) (a runout)
  std::vector<int> dofs;
  Eigen::VectorXcd stiffness, damping, inertia;  ///< S [N/m·m or N], D [N s/m·m], U [kg m]
  /// ν for input speed Ω.
  double order(double input_speed) const {
    return follows_direction && input_speed < 0.0 ? -ratio : ratio;
  }
  /// The complex force amplitude F at constant speed Ω [rad/s] (meshes at k̄: `mesh_stiffness`).
  Eigen::VectorXcd amplitude(double input_speed, double mesh_stiffness = 1.0) const;
};

/// The excitation terms of a train (validated: InputError naming the key and its range), and
/// the static load of the prescribed mean displacements (added to `static_load`).
std::vector<TrainExcitationTerm> buildTrainExcitation(const GearTrainModel& model,
                                                      Eigen::VectorXd& static_load);

/// Adds Σ f(t) of `terms` to f (all the model's DOFs) at input rotation α [rad], speed |Ω|
/// [rad/s] (sign from `input_speed`) and d|Ω|/dt [rad/s²]; `mesh_stiffness[m]` is k_m(φ_m(t))
/// [N/m]. No allocation.
void addExcitationForce(const std::vector<TrainExcitationTerm>& terms, double input_angle,
                        double input_speed, double speed_rate, const double* mesh_stiffness,
                        Eigen::Ref<Eigen::VectorXd> f);

/// InputError naming the first excitation of `model` (unbalances.<name>, …) when it has any:
/// for the solvers that do not take them yet (`what`: "the nonlinear harmonic balance", …).
void refuseExcitations(const GearTrainModel& model, const std::string& what);

}  // namespace geardyn
