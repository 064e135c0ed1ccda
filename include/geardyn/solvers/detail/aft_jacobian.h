#pragma once
/// \file
/// The Jacobian of alternating-frequency-time (AFT) force coefficients with respect to the
/// deflection coefficients (a₀, a₁, b₁, …, a_H, b_H) for a force f(t, y) sampled at N points:
/// with D_k = (1/N) Σ f′ cos kτ, E_k = (1/N) Σ f′ sin kτ (the FFT of df/dy at the samples),
/// products of trigonometric functions give a Toeplitz + Hankel structure (Krack & Gross 2019,
/// §3.3): ∂a_h/∂a_l = D_{h−l} + D_{h+l}, ∂a_h/∂b_l = E_{h+l} + E_{l−h}, ∂b_h/∂a_l = E_{h+l} +
/// E_{h−l}, ∂b_h/∂b_l = D_{h−l} − D_{h+l}; row 0 and column 0 from D_l, E_l.

#include <fftw3.h>

#include <vector>

namespace geardyn::detail {

/// D_k, E_k for k = −2H..2H at index k + 2H, from the real-to-complex FFT X of the N samples of
/// df/dy (X_{N−k} = conj X_k; D even, E odd, periodic in N).
inline void aftSlopeTables(const fftw_complex* X, int samples, int harmonics,
                           std::vector<double>& D, std::vector<double>& E) {
  const int span = 2 * harmonics;
  D.resize(2 * span + 1);
  E.resize(2 * span + 1);
  for (int k = -span; k <= span; ++k) {
    int bin = ((k % samples) + samples) % samples;
    double sign = 1.0;
    if (bin > samples / 2) bin = samples - bin, sign = -1.0;
    D[k + span] = X[bin][0] / samples;
    E[k + span] = -sign * X[bin][1] / samples;
  }
}

/// Fills the (2H + 1)² Jacobian J (any Eigen matrix expression) from the tables.
template <class Matrix>
void aftJacobian(const std::vector<double>& Dt, const std::vector<double>& Et, int harmonics,
                 Matrix&& J) {
  const int H = harmonics;
  const double* D = Dt.data() + 2 * H;
  const double* E = Et.data() + 2 * H;
  J(0, 0) = D[0];
  for (int l = 1; l <= H; ++l) {
    J(0, 2 * l - 1) = D[l];
    J(0, 2 * l) = E[l];
    J(2 * l - 1, 0) = 2.0 * D[l];
    J(2 * l, 0) = 2.0 * E[l];
    for (int h = 1; h <= H; ++h) {
      J(2 * h - 1, 2 * l - 1) = D[h - l] + D[h + l];
      J(2 * h - 1, 2 * l) = E[h + l] + E[l - h];
      J(2 * h, 2 * l - 1) = E[h + l] + E[h - l];
      J(2 * h, 2 * l) = D[h - l] - D[h + l];
    }
  }
}

}  // namespace geardyn::detail
