#pragma once
/// The buffers of one thread's torus solves (TrainTorusWorkspace, train_torus.h): sized at the
/// first speed, reused after; and the thread's two latest solutions, which the next speed's
/// GMRES starts from. Internal to train_torus.cpp and train_torus_grid.cpp.

#include <Eigen/Dense>
#include <complex>
#include <vector>

#include "geardyn/numerics/preconditioned_gmres.h"
#include "geardyn/solvers/detail/modal_compliance.h"

namespace geardyn::detail {

/// P A = L U of a small dense block in place, partial pivoting by the squared modulus (the
/// same pivots as by the modulus up to ties, without a hypot per entry).
struct SmallLu {
  Eigen::MatrixXcd lu;
  std::vector<int> pivot;  // row exchanged with row k at step k
  void factor();           // lu holds A on entry, L\U on exit
  void solveInPlace(Eigen::Ref<Eigen::VectorXcd> x) const;
};

struct TorusWorkspace {
  const void* owner = nullptr;   // the solver whose solutions these are
  Eigen::MatrixXcd B;            // r × (T r): B_n of tone t in columns t r .. t r + r − 1
  Eigen::MatrixXcd DinvV;        // n × (pairs r): D(n·ω)⁻¹ V of the factorised tone pairs
  std::vector<char> modal_tone;  // per tone pair: B_n and D⁻¹V from `modal`
  bool modal_ok = false;
  ModalCompliance modal;
  Eigen::MatrixXcd phi;  // r × T: the mesh loads φ_n
  Eigen::VectorXcd DinvF0, rhs, delta;
  // The latest two solutions and their speeds (speed 0: none).
  Eigen::VectorXcd previous[2];
  double previous_speed[2] = {0.0, 0.0};
  std::vector<SmallLu> lines;  // the preconditioner's line factors
  // The speed they were factorised at, the GMRES iterations of that solve and of the latest
  // (speed 0: none; TrainTorusOptions::preconditioner_reuse_iterations).
  double factor_speed = 0.0;
  int factor_iterations = 0, latest_iterations = 0;
  GmresWorkspace gmres;
  Eigen::VectorXcd w, z, scratch;
  // The grid (train_torus_grid.cpp).
  Eigen::MatrixXcd C, half, spectrum;
  Eigen::MatrixXd fields, force;
};

}  // namespace geardyn::detail
