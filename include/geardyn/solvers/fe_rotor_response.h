#pragma once
/// \file
/// Newmark time integration of the finite-element geared rotor (Visnadi 2021 §4: γ = 1/2,
/// β = 1/4, Δt = 1e-5 s) with the mesh stiffness updated at every step, at constant speed or
/// along a speed profile (run-up / run-down: mesh angle integrated from the speed).
///
/// Cost: the effective matrix A = K + k̄ v vᵀ + M/(βΔt²) + γ/(βΔt) (C + Ω G₁) is factorised once
/// (LU; G₁ makes it unsymmetric) and the time-varying mesh enters as the rank-1 correction
/// (k(φ) − k̄) v vᵀ by Sherman–Morrison, so a step costs one LU back-substitution and two
/// matrix–vector products, with no allocation. Along a speed profile the gyroscopic term is
/// refactorised whenever the speed has moved by more than `gyro_speed_tolerance` × the largest
/// speed since the last factorisation (the gyroscopic matrix is then within that tolerance of
/// its exact value; the mesh phase and unbalance forces use the exact speed).

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "geardyn/models/fe_geared_rotor.h"
#include "geardyn/progress.h"
#include "geardyn/solvers/newmark.h"

namespace geardyn {

struct FeTimeOptions {
  NewmarkParameters newmark = NewmarkParameters::averageAcceleration();
  double time_step = 1e-5;             ///< Δt [s]
  double duration = 0.5;               ///< [s]
  double gyro_speed_tolerance = 1e-3;  ///< relative speed change that triggers refactorisation
  int record_every = 1;                ///< record one step in this many
  std::vector<int> channels;           ///< active DOFs to record; empty: all
  /// q(0) from the static equilibrium at t = 0 (mesh stiffness and loads at t = 0) instead of
  /// rest; the minimum-norm solution leaves the rolling rigid-body mode at zero.
  bool start_from_static = false;
  ProgressCallback progress;  ///< (steps done, steps) every 1000 steps
  void validate() const;
};

enum class FeTimeStatus { kCompleted, kDiverged };
std::string toString(FeTimeStatus status);

struct FeTimeResponse {
  std::vector<int> channels;                             ///< recorded active DOFs
  std::vector<double> t;                                 ///< [s]
  std::vector<double> speed;                             ///< pinion speed [rad/s]
  std::vector<double> mesh_stiffness;                    ///< k_m at t [N/m]
  std::vector<double> mesh_force;                        ///< k_m (vᵀq − e) [N]
  Eigen::MatrixXd displacement, velocity, acceleration;  ///< rows: samples, cols: channels
  long long steps = 0;
  int factorisations = 0;
  FeTimeStatus status = FeTimeStatus::kCompleted;
  std::string message;
  bool converged() const { return status == FeTimeStatus::kCompleted; }
};

/// One Newmark step at a time: for benchmarks, and the building block of the solver.
class FeNewmarkStepper {
 public:
  FeNewmarkStepper(const FeGearedRotor& model, const FeTimeOptions& options);

  /// Sets the state at time t and computes the consistent acceleration.
  void reset(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot);
  /// Advances by one time step; allocation-free.
  void step();

  double time() const noexcept { return t_; }
  const Eigen::VectorXd& displacement() const noexcept { return q_; }
  const Eigen::VectorXd& velocity() const noexcept { return v_; }
  const Eigen::VectorXd& acceleration() const noexcept { return a_; }
  double meshStiffness() const noexcept { return k_; }
  double meshForce() const;
  int factorisations() const noexcept { return factorisations_; }

 private:
  void factorise(double speed);
  void force(double t, Eigen::VectorXd& f);

  const FeGearedRotor& model_;
  double dt_, gamma_, gyro_tolerance_;
  NewmarkCoefficients nm_;
  double t_ = 0.0, k_ = 0.0, e_ = 0.0, speed_factorised_ = 0.0, k_ref_ = 0.0, s_ = 0.0;
  int factorisations_ = 0;
  Eigen::MatrixXd A_, Cg_, K0_;  // effective, C + ΩG₁, K + k̄ v vᵀ
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  Eigen::VectorXd q_, v_, a_, z_, rhs_, y_, p_, c_, f_;
};

/// Integrates from t = 0 to `duration`, recording every `record_every` steps (t = 0 included).
FeTimeResponse solveFeRotorTimeResponse(const FeGearedRotor& model, const FeTimeOptions& options);

/// The static deflection under the constant loads with the mesh stiffness k and TE e [m]
/// (minimum-norm: rigid-body modes left at zero).
Eigen::VectorXd feStaticDeflection(const FeGearedRotor& model, double mesh_stiffness,
                                   double transmission_error = 0.0);

}  // namespace geardyn
