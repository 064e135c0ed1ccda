#pragma once
/// \file
/// Restarted GMRES with right preconditioning for complex systems A x = b (Saad & Schultz
/// 1986; Saad, Iterative Methods for Sparse Linear Systems, 2nd ed., Alg. 9.5): the residual
/// ‖b − A x‖ is minimised over the Krylov space of A P⁻¹, so the stopping test is on the true
/// residual of the unpreconditioned system. Internal (the torus balance's condensed system).

#include <Eigen/Dense>
#include <functional>

namespace geardyn::detail {

struct GmresResult {
  int iterations = 0;
  double residual = 0.0;  ///< ‖b − A x‖ / ‖b‖ at the end
  bool converged = false;
};

/// y = A x and y = P⁻¹ x (y is sized by the caller: x.size()).
using ComplexOperator =
    std::function<void(const Eigen::Ref<const Eigen::VectorXcd>& x, Eigen::VectorXcd& y)>;

/// GMRES's buffers (the Arnoldi basis, Hessenberg matrix, rotations), reused between solves of
/// the same size without allocating.
struct GmresWorkspace {
  Eigen::MatrixXcd Q, H;
  Eigen::VectorXcd g, cs, sn, z, w, r, y;
};

/// Solves A x = b from x = 0 to ‖b − A x‖ <= tolerance ‖b‖ within max_iterations.
GmresResult preconditionedGmres(const ComplexOperator& apply, const ComplexOperator& precondition,
                                const Eigen::VectorXcd& b, Eigen::VectorXcd& x, double tolerance,
                                int restart, int max_iterations);
/// The same from the initial guess x when `initial_guess` (sized as b; else from 0), in the
/// buffers of `workspace`.
GmresResult preconditionedGmres(const ComplexOperator& apply, const ComplexOperator& precondition,
                                const Eigen::VectorXcd& b, Eigen::VectorXcd& x, double tolerance,
                                int restart, int max_iterations, bool initial_guess,
                                GmresWorkspace& workspace);

}  // namespace geardyn::detail
