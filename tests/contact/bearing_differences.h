#pragma once
/// The rolling-bearing tests' check of the analytic 5×5 tangent against central differences of
/// the load–deflection relation (rolling_bearing_test.cpp, spherical_roller_bearing_test.cpp).

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "geardyn/contact/rolling_bearing.h"
#include "support/numeric_assertions.h"

namespace geardyn::testing {

/// ∂F/∂q by central differences, steps h (translations) and h/R (tilts).
inline RollingBearing::Matrix5 centralDifferences(const RollingBearing& b,
                                                  const RollingBearing::Vector5& q, double h) {
  const double R = 0.5 * b.geometry().pitch_diameter;
  RollingBearing::Matrix5 K;
  for (int i = 0; i < 5; ++i) {
    const double step = i < 3 ? h : h / R;
    RollingBearing::Vector5 plus = q, minus = q, fp, fm;
    plus(i) += step, minus(i) -= step;
    b.evaluate(plus, fp, nullptr);
    b.evaluate(minus, fm, nullptr);
    K.col(i) = (fp - fm) / (2.0 * step);
  }
  return K;
}

/// Tolerance of the tangent against central differences: truncation (h/δ)² ≈ 1e-8 and
/// round-off ε δ/h ≈ 1e-11 for h = 1e-4 × the contact deflections; 1e-6 of the largest entry.
constexpr double kCentralDifference = 1e-6;

inline void expectTangentMatchesDifferences(const RollingBearing& b,
                                            const RollingBearing::Vector5& q) {
  RollingBearing::Vector5 F;
  RollingBearing::Matrix5 K;
  b.evaluate(q, F, &K);
  const RollingBearing::Matrix5 fd = centralDifferences(b, q, 1e-4 * b.referenceDeflection());
  EXPECT_CLOSE(K, fd, 0.0, kCentralDifference * K.cwiseAbs().maxCoeff());
  EXPECT_CLOSE(K, RollingBearing::Matrix5(K.transpose()), 0.0, 1e-12 * K.cwiseAbs().maxCoeff());
  // The Hessian of the contacts' strain energy is positive semi-definite where every loaded
  // contact is in compression (δ > 0): Hertz's δ^{3/2} and the slices' δ^{10/9} are convex.
  const Eigen::SelfAdjointEigenSolver<RollingBearing::Matrix5> eig(K);
  EXPECT_GE(eig.eigenvalues().minCoeff(), -1e-12 * eig.eigenvalues().maxCoeff());
}

}  // namespace geardyn::testing
