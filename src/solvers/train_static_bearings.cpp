/// Nonlinear static deflection with rolling bearings from their geometry
/// (detail/train_static_bearings.h).

#include "geardyn/solvers/detail/train_static_bearings.h"

#include <fmt/format.h>

#include <cmath>

namespace geardyn::detail {
namespace {

/// R = K q − F + Σ Jᵀ F_b(J q) and, when T is not null, its tangent K + Σ Jᵀ K_b J.
void residual(const GearTrainModel& model, const Eigen::MatrixXd& K, const Eigen::VectorXd& F,
              const Eigen::VectorXd& q, Eigen::VectorXd& R, Eigen::MatrixXd* T) {
  R.noalias() = K * q;
  R -= F;
  if (T) *T = K;
  RollingBearing::Vector5 Fb;
  RollingBearing::Matrix5 Kb;
  for (const TrainRollingBearing& b : model.rollingBearings()) {
    b.bearing->evaluate(b.displacement(q), Fb, T ? &Kb : nullptr);
    const auto n = static_cast<Eigen::Index>(b.dofs.size());
    for (Eigen::Index i = 0; i < n; ++i) {
      R(b.dofs[i]) += b.jacobian.col(i).dot(Fb);
      if (!T) continue;
      const RollingBearing::Vector5 KJ = Kb * b.jacobian.col(i);
      for (Eigen::Index j = 0; j < n; ++j) (*T)(b.dofs[j], b.dofs[i]) += b.jacobian.col(j).dot(KJ);
    }
  }
}

Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> factorise(const Eigen::MatrixXd& A) {
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(A);
  cod.setThreshold(1e-12);  // rigid-body modes: relative to the largest pivot
  return cod;
}

}  // namespace

void solveRollingBearingStatics(const GearTrainModel& model, const Eigen::MatrixXd& K,
                                const Eigen::VectorXd& F, TrainStaticResult& r) {
  const Eigen::Index n = K.rows();
  // D: every bearing's reference stiffness in the train's DOFs (RollingBearing::
  // referenceStiffness); the start is the linear train with the bearings at D.
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(n, n);
  for (const TrainRollingBearing& b : model.rollingBearings()) {
    const Eigen::MatrixXd JDJ =
        b.jacobian.transpose() * b.bearing->referenceStiffness().asDiagonal() * b.jacobian;
    for (std::size_t i = 0; i < b.dofs.size(); ++i) {
      for (std::size_t j = 0; j < b.dofs.size(); ++j) D(b.dofs[i], b.dofs[j]) += JDJ(i, j);
    }
  }
  Eigen::VectorXd q = factorise(K + D).solve(F), R, trial_R;
  Eigen::MatrixXd T, trial_T;
  residual(model, K, F, q, R, &T);
  const double scale = F.norm() > 0.0 ? F.norm() : 1.0;  // [N]: an unloaded train
  // Converged at 1e-10 of the load: the contact sums' round-off is ~1e-13 of it.
  constexpr double kTolerance = 1e-10;
  constexpr int kMaxIterations = 100;
  double norm = R.norm(), mu = 1e-2;
  int it = 0;
  for (; it < kMaxIterations && norm > kTolerance * scale; ++it) {
    const Eigen::VectorXd trial = q - factorise(T + mu * D).solve(R);
    residual(model, K, F, trial, trial_R, &trial_T);
    const double trial_norm = trial_R.norm();
    if (trial_norm < norm) {
      q = trial, R = trial_R, T = trial_T, norm = trial_norm;
      mu = mu > 1e-12 ? mu / 10.0 : 0.0;  // pure Newton near the solution
    } else {
      mu = std::max(10.0 * mu, 1e-6);
      if (mu > 1e12) break;
    }
  }
  r.iterations = it;
  r.displacement = q;
  r.residual = norm / scale;
  const auto cod = factorise(T);
  r.rigid_modes = static_cast<int>(n - cod.rank());
  if (norm > kTolerance * scale && r.residual > 1e-8) {
    // Loads on a rigid-body mode leave the residual there; otherwise Newton stalled.
    const Eigen::VectorXd projected = T * cod.solve(R) - R;
    if (projected.norm() < 0.5 * norm) {
      r.status = "max_iterations";
      r.message = fmt::format(
          "the nonlinear static deflection with the rolling bearings did not converge in {} "
          "iterations (relative residual {:.3g})",
          it, r.residual);
    }
  }
  r.rolling_bearings.clear();
  for (const TrainRollingBearing& b : model.rollingBearings()) {
    r.rolling_bearings.push_back(b.bearing->state(b.displacement(q)));
  }
}

}  // namespace geardyn::detail
