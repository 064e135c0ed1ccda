// Timoshenko shaft element: structure of the matrices, rigid-body modes, the cantilever with
// shear against closed form, and the simply supported shaft's first bending frequency against
// the analytic Timoshenko value.

#include "geardyn/models/timoshenko_shaft_element.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>

namespace geardyn {
namespace {

ShaftSegment steelSegment(double length, double outer = 0.03, double inner = 0.0) {
  return {length, outer, inner, 200e9, 80e9, 7800};
}

/// The six rigid-body motions of an element from x = 0 to x = L.
std::array<Eigen::Matrix<double, 12, 1>, 6> rigidModes(double L) {
  std::array<Eigen::Matrix<double, 12, 1>, 6> r;
  for (auto& m : r) m.setZero();
  for (int n = 0; n < 2; ++n) {
    const double x = n * L;
    const int o = n * kNodeDofs;
    r[0](o + kUx) = 1;
    r[1](o + kUy) = 1;
    r[2](o + kUz) = 1;
    r[3](o + kRx) = 1;                      // rotation about x (points on the axis stay)
    r[4](o + kRy) = 1, r[4](o + kUz) = -x;  // rotation about y: u = θ × X → u_z = −θ x
    r[5](o + kRz) = 1, r[5](o + kUy) = x;   // rotation about z: u_y = θ x
  }
  return r;
}

TEST(TimoshenkoShaftElement, MatricesAreSymmetricSkewAndDefinite) {
  for (double inner : {0.0, 0.02}) {
    const ShaftSegment s = steelSegment(0.1, 0.03, inner);
    const ElementMatrix K = shaftElementStiffness(s), M = shaftElementMass(s);
    const ElementMatrix G = shaftElementGyroscopic(s);
    EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
    EXPECT_LT((M - M.transpose()).norm(), 1e-14 * M.norm());
    EXPECT_LT((G + G.transpose()).norm(), 1e-14 * G.norm());
    const Eigen::SelfAdjointEigenSolver<ElementMatrix> ek(K), em(M);
    EXPECT_GT(em.eigenvalues().minCoeff(), 0.0);
    // Six zero eigenvalues (rigid-body modes), the rest clearly positive.
    int zeros = 0;
    for (int i = 0; i < 12; ++i) {
      EXPECT_GT(ek.eigenvalues()(i), -1e-9 * ek.eigenvalues().maxCoeff());
      if (ek.eigenvalues()(i) < 1e-10 * ek.eigenvalues().maxCoeff()) ++zeros;
    }
    EXPECT_EQ(zeros, 6);
  }
}

TEST(TimoshenkoShaftElement, RigidBodyModesCarryNoStrainAndTheMassIsRight) {
  const ShaftSegment s = steelSegment(0.1);
  const ElementMatrix K = shaftElementStiffness(s), M = shaftElementMass(s);
  const auto modes = rigidModes(s.length);
  for (const auto& r : modes) EXPECT_LT((K * r).norm(), 1e-6 * K.norm() * r.norm());
  const double mass = s.density * s.area() * s.length;
  for (int t : {0, 1, 2}) EXPECT_NEAR(modes[t].dot(M * modes[t]), mass, 1e-12 * mass);
  const double polar = s.density * s.polarMomentOfArea() * s.length;
  EXPECT_NEAR(modes[3].dot(M * modes[3]), polar, 1e-12 * polar);
  // Rotation about y through x = 0: ∫ρA x² + ρI dx = ρA L³/3 + ρ I L.
  const double tilt =
      s.density * (s.area() * std::pow(s.length, 3) / 3 + s.secondMomentOfArea() * s.length);
  EXPECT_NEAR(modes[4].dot(M * modes[4]), tilt, 1e-12 * tilt);
  EXPECT_NEAR(modes[5].dot(M * modes[5]), tilt, 1e-12 * tilt);
}

// A cantilever clamped at node 0 under an end load P: one element reproduces the Timoshenko
// closed form δ = PL³/(3EI) + PL/(κGA) exactly (the shape functions solve the static beam).
TEST(TimoshenkoShaftElement, CantileverTipDeflectionWithShearIsExact) {
  for (double length : {0.3, 0.05}) {  // slender and stubby (shear ~ 20 % of the deflection)
    const ShaftSegment s = steelSegment(length, 0.04, 0.01);
    const ElementMatrix K = shaftElementStiffness(s);
    const Eigen::Matrix<double, 6, 6> K11 = K.bottomRightCorner<6, 6>();
    const double P = 1000.0, T = 50.0, L = length, EI = s.youngs_modulus * s.secondMomentOfArea();
    const double kGA = s.shearCoefficient() * s.shear_modulus * s.area();
    Eigen::Matrix<double, 6, 1> f;
    f << P, P, P, T, 0, 0;
    const Eigen::Matrix<double, 6, 1> u = K11.ldlt().solve(f);
    const double bending = P * L * L * L / (3 * EI), shear = P * L / kGA;
    EXPECT_NEAR(u(kUx), P * L / (s.youngs_modulus * s.area()), 1e-9 * u(kUx));
    EXPECT_NEAR(u(kUy), bending + shear, 1e-9 * (bending + shear));
    EXPECT_NEAR(u(kUz), bending + shear, 1e-9 * (bending + shear));
    EXPECT_NEAR(u(kRx), T * L / (s.shear_modulus * s.polarMomentOfArea()), 1e-9 * u(kRx));
    EXPECT_NEAR(u(kRz), P * L * L / (2 * EI), 1e-9 * u(kRz));   // slope du_y/dx = θ_z
    EXPECT_NEAR(u(kRy), -P * L * L / (2 * EI), 1e-9 * u(kRz));  // du_z/dx = −θ_y
    if (length < 0.1) EXPECT_GT(shear / (bending + shear), 0.1);
  }
}

// First bending frequency of a simply supported stubby shaft (L/D = 5, where shear and rotary
// inertia lower it by several per cent) against the Timoshenko characteristic equation
//   (ρAω² − κGAα²)(ρIω² − EIα² − κGA) = (κGAα)², α = π/L.
TEST(TimoshenkoShaftElement, SimplySupportedShaftMatchesAnalyticTimoshenkoFrequency) {
  const double L = 0.5, D = 0.1;
  const int elements = 20;
  const ShaftSegment s = steelSegment(L / elements, D);
  const int n = (elements + 1) * kNodeDofs;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n), M = K;
  for (int e = 0; e < elements; ++e) {
    K.block<12, 12>(e * kNodeDofs, e * kNodeDofs) += shaftElementStiffness(s);
    M.block<12, 12>(e * kNodeDofs, e * kNodeDofs) += shaftElementMass(s);
  }
  // Keep only the x–y bending DOFs, with u_y = 0 at both ends.
  std::vector<int> keep;
  for (int node = 0; node <= elements; ++node) {
    if (node != 0 && node != elements) keep.push_back(node * kNodeDofs + kUy);
    keep.push_back(node * kNodeDofs + kRz);
  }
  const int m = static_cast<int>(keep.size());
  Eigen::MatrixXd k(m, m), mm(m, m);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) k(i, j) = K(keep[i], keep[j]), mm(i, j) = M(keep[i], keep[j]);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(k, mm);
  const double omega_fe = std::sqrt(eig.eigenvalues()(0));

  const double A = s.area(), I = s.secondMomentOfArea(), rho = s.density, E = s.youngs_modulus;
  const double kGA = s.shearCoefficient() * s.shear_modulus * A, a = std::numbers::pi / L;
  // Quadratic in w = ω²: (ρA w − κGAα²)(ρI w − EIα² − κGA) − (κGAα)² = 0.
  const double qa = rho * A * rho * I;
  const double qb = -(rho * A * (E * I * a * a + kGA) + rho * I * kGA * a * a);
  const double qc = kGA * a * a * (E * I * a * a + kGA) - kGA * kGA * a * a;
  const double w = (-qb - std::sqrt(qb * qb - 4 * qa * qc)) / (2 * qa);
  const double omega_exact = std::sqrt(w);
  const double omega_euler = a * a * std::sqrt(E * I / (rho * A));
  EXPECT_NEAR(omega_fe / omega_exact, 1.0, 0.005);
  EXPECT_LT(omega_exact / omega_euler, 0.97);  // the shear/rotary effect the test must resolve
}

}  // namespace
}  // namespace geardyn
