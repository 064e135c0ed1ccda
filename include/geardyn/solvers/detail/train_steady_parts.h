#pragma once
/// \file
/// Pieces shared by the linear steady-state solvers of a train: the common-period balance
/// (train_response.cpp) and the torus balance (train_torus.cpp). Internal.

#include <Eigen/Dense>
#include <complex>
#include <utility>
#include <vector>

#include "geardyn/system/gear_train_model.h"

namespace geardyn::detail {

/// x ≈ p/q by continued fractions (q <= 10⁶, |x − p/q| <= 1e-9 x): mesh events per input
/// revolution, a ratio of tooth counts.
std::pair<long long, long long> rationalApproximation(double x);

/// Mass-normalised rigid-body modes of (K, M): eigenvalues below 1e-10 of the largest.
Eigen::MatrixXd rigidModes(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M);

/// Element deformation d = J q[dofs].
Eigen::VectorXd elementDeformation(const TrainElement& e, const Eigen::VectorXd& q);

/// Fourier coefficients over one mesh period of k_m, k_m e_m and e_m, index L + l for
/// l = −L..L, with the mesh phase φ_m0 applied (c_l e^{i 2π l φ_m0}): the coefficients of the
/// harmonic l f_m t of k_m(f_m t + φ_m0).
struct MeshFourier {
  std::vector<std::complex<double>> k, ke, e;  ///< [N/m], [N], [m]
};
MeshFourier meshFourier(const TrainMesh& mesh, int harmonics);

}  // namespace geardyn::detail
