#pragma once
/// \file
/// Newmark time integration of a gear train at constant input speed with the time-varying
/// stiffness of every mesh:
///
///   M q̈ + (C + Ω G₁) q̇ + (K + Ω² K_Ω + Σ_m k_m(φ_m(t)) v_m v_mᵀ) q
///       = F₀ + Σ_m (k_m e_m + c_m ė_m) v_m
/// (the mesh dashpot acts on the rate of the tooth deformation (δ − e)˙, as in the SDOF model).
///
/// Cost: the effective matrix A = K̄ + a₀ M + a₁ (C + Ω G₁) (K̄ with the mean meshes) is
/// factorised once; the r meshes vary it by V D(t) Vᵀ with D = diag(k_m(t) − k̄_m), which the
/// Woodbury identity solves with the precomputed Z = A⁻¹ V and one r × r system per step:
///   x = y − Z (I + D Vᵀ Z)⁻¹ D Vᵀ y,   y = A⁻¹ b.
/// A step is one back-substitution, a few matrix–vector products and an r × r LU, and allocates
/// nothing: small trains use dense matrices; from kSparseTrainDofs DOFs on (flexible shafts)
/// M, C + ΩG₁ and A are sparse and A is factorised by Eigen's SparseLU, whose factors are
/// solved with in a preallocated vector (detail::SparseLuFactors).

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <optional>
#include <string>
#include <vector>

#include "geardyn/solvers/detail/sparse_lu_factors.h"
#include "geardyn/solvers/newmark.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn {

struct TrainTimeOptions {
  NewmarkParameters newmark = NewmarkParameters::averageAcceleration();
  double time_step = 0.0;  ///< Δt [s]; 0: the fastest mesh period / steps_per_mesh_period
  int steps_per_mesh_period = 128;
  double duration = 0.0;  ///< [s]; 0: derived (transient decay + `record_periods`)
  /// Common periods recorded at the end (the steady-state window).
  int record_periods = 1;
  bool start_from_static = true;  ///< q(0) from the mean static deflection, else rest
  void validate() const;
};

struct TrainTimeResponse {
  Eigen::VectorXd t;             ///< recorded times [s]
  Eigen::MatrixXd displacement;  ///< rows: recorded samples, cols: DOFs
  Eigen::MatrixXd mesh_force;    ///< rows: samples, cols: meshes [N]
  double time_step = 0.0;
  long long steps = 0;
  std::string status = "completed";  ///< or "diverged"
  std::string message;
};

/// One Newmark step at a time (for benchmarks, and the building block of the solver).
/// DOF count from which the Newmark stepper works with sparse matrices.
inline constexpr int kSparseTrainDofs = 64;

class TrainNewmarkStepper {
 public:
  /// `sparse`: force the sparse (true) or dense (false) path; absent: sparse from
  /// kSparseTrainDofs DOFs on.
  TrainNewmarkStepper(const GearTrainModel& model, double input_speed, double time_step,
                      NewmarkParameters newmark, std::optional<bool> sparse = std::nullopt);
  void reset(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot);
  void step();  ///< allocation-free
  double time() const noexcept { return t_; }
  const Eigen::VectorXd& displacement() const noexcept { return q_; }
  /// k_m(t)(v_mᵀ q − e_m) [N] at the current state.
  double meshForce(int mesh) const;

 private:
  void meshState(double t);  // fills dk_ (k − k̄) and ke_ (k e + c ė) of every mesh at t

  const GearTrainModel& model_;
  double speed_, dt_, gamma_, t_ = 0.0;
  NewmarkCoefficients nm_;
  bool sparse_ = false;
  Eigen::MatrixXd Cg_, K0_, V_, Z_, S_, small_matrix_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_, small_;
  Eigen::SparseMatrix<double> Msp_, Cgsp_;
  detail::SparseLuFactors slu_;
  Eigen::VectorXd q_, v_, a_, f_, rhs_, y_, w_, w_solved_, dk_, ke_, k_;
};

TrainTimeResponse solveTrainTimeResponse(const GearTrainModel& model, double input_speed,
                                         const TrainTimeOptions& options);

}  // namespace geardyn
