// Newmark integration of the FE geared rotor (the train's stepper over the rotor's DOFs):
// against the exact step response (matrix exponential) for a linear constant-stiffness case, its
// second-order convergence, the rank-1 mesh update against refactorising every step, the speed
// profile, and holding the axial DOFs of a spur rotor against integrating all of the train's.

#include "geardyn/solvers/fe_rotor_response.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <unsupported/Eigen/MatrixFunctions>

#include "geardyn/stiffness/fourier_stiffness.h"
#include "support/fe_rotor_cases.h"

namespace geardyn {
namespace {

using testing::constantMesh;
using testing::visnadiFeRotor;

/// The paper's rotor, helical, with constant mesh stiffness; the loads step on at t = 0.
FeRotorModel linearCase() {
  return visnadiFeRotor(constantMesh(3e8), 5.0).model();
}

/// Exact response from rest to the step load F₀: x(t) = ∫₀ᵗ e^{A s} ds b, b = [0; M⁻¹F₀], read
/// from the exponential of the augmented matrix [[A, b], [0, 0]] t (exact also for the rolling
/// rigid-body mode's defective zero eigenvalue, which an eigenvector basis cannot represent).
/// The state is [q; q̇/s] with s = 1e3 rad/s, which balances the blocks of A.
Eigen::MatrixXd exactStepResponse(const FeRotorModel& m, const std::vector<double>& times) {
  const double sv = 1e3;
  const int n = m.dofCount();
  const Eigen::VectorXd& w = m.meshVector();
  const Eigen::MatrixXd K = m.stiffness() + m.meanMeshStiffness() * w * w.transpose();
  const Eigen::MatrixXd D = m.damping() + m.speed().start * m.gyroscopic();
  const auto mass = m.mass().ldlt();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n + 1, 2 * n + 1);
  A.block(0, n, n, n).setIdentity();
  A.block(0, n, n, n) *= sv;
  A.block(n, 0, n, n) = -mass.solve(K) / sv;
  A.block(n, n, n, n) = -mass.solve(D);
  A.block(n, 2 * n, n, 1) = mass.solve(m.staticLoad()) / sv;
  Eigen::MatrixXd q(times.size(), n);
  for (std::size_t k = 0; k < times.size(); ++k) {
    const Eigen::MatrixXd E = (A * times[k]).exp();
    q.row(k) = E.block(0, 2 * n, n, 1).transpose();
  }
  return q;
}

double maxError(const FeTimeResponse& r, const Eigen::MatrixXd& exact, double* scale) {
  *scale = exact.cwiseAbs().maxCoeff();
  return (r.displacement - exact).cwiseAbs().maxCoeff();
}

// Tolerance 1e-6 of the largest displacement at Δt = 1e-7 s: the average-acceleration rule's
// period error (ωΔt)²/12 accumulated over ωt ≈ 20 radians of the lowest modes is ~2e-8; the
// high modes are overdamped by the β-damping 3e-5.
TEST(FeRotorNewmark, MatchesTheExactResponseForConstantStiffness) {
  const FeRotorModel m = linearCase();
  FeTimeOptions o;
  o.time_step = 1e-7;
  o.duration = 5e-3;
  o.record_every = 1000;
  const FeTimeResponse r = solveFeRotorTimeResponse(m, o);
  ASSERT_TRUE(r.converged()) << r.message;
  double scale = 0.0;
  const double error = maxError(r, exactStepResponse(m, r.t), &scale);
  EXPECT_LT(error, 1e-6 * scale) << "error " << error << " of " << scale;
  EXPECT_GT(scale, 1e-7);  // the loads really deflect the rotor
}

TEST(FeRotorNewmark, ConvergesAtSecondOrder) {
  const FeRotorModel m = linearCase();
  std::vector<double> errors;
  for (double dt : {4e-6, 2e-6}) {
    FeTimeOptions o;
    o.time_step = dt;
    o.duration = 4e-3;
    o.record_every = static_cast<int>(std::lround(1e-4 / dt));
    const FeTimeResponse r = solveFeRotorTimeResponse(m, o);
    double scale = 0.0;
    errors.push_back(maxError(r, exactStepResponse(m, r.t), &scale));
  }
  EXPECT_NEAR(std::log2(errors[0] / errors[1]), 2.0, 0.2);
}

// The Sherman–Morrison update (k(φ) − k̄) v vᵀ against a plain Newmark that assembles and
// factorises K + k(φ) v vᵀ at every step: the same scheme, so they agree to round-off.
TEST(FeRotorNewmark, RankOneMeshUpdateEqualsRefactorisingEveryStep) {
  testing::FeRotorCase c =
      visnadiFeRotor(std::make_shared<FourierMeshStiffness>(3e8, std::vector<double>{0.3, 0.1},
                                                            std::vector<double>{0.0, 1.0}, 1.6),
                     5.0);
  c.train.meshes.front().transmission_error.addFourier({5e-6}, {0.4});
  const FeRotorModel m = c.model();
  FeTimeOptions o;
  o.duration = 2e-3;
  const FeTimeResponse r = solveFeRotorTimeResponse(m, o);

  const int n = m.dofCount();
  const double dt = o.time_step, b = 0.25, g = 0.5;
  const Eigen::VectorXd& w = m.meshVector();
  const Eigen::MatrixXd D = m.damping() + m.speed().start * m.gyroscopic();
  Eigen::VectorXd q = Eigen::VectorXd::Zero(n), v = q, a = q;
  auto load = [&](double t, double* k) {
    const double phase = m.meshPhase(t);
    *k = m.meshStiffness(phase);
    return Eigen::VectorXd(m.staticLoad() + *k * m.transmissionError(phase) * w);
  };
  double k = 0;
  Eigen::VectorXd f = load(0.0, &k);
  a = m.mass().ldlt().solve(f - (m.stiffness() + k * w * w.transpose()) * q);
  double worst = 0.0;
  for (long long s = 1; s < static_cast<long long>(r.t.size()); ++s) {
    f = load(s * dt, &k);
    const Eigen::MatrixXd A =
        m.stiffness() + k * w * w.transpose() + m.mass() / (b * dt * dt) + g / (b * dt) * D;
    const Eigen::VectorXd rhs = f +
                                m.mass() * (q / (b * dt * dt) + v / (b * dt) + a * (0.5 / b - 1)) +
                                D * (g / (b * dt) * q + (g / b - 1) * v + dt / 2 * (g / b - 2) * a);
    const Eigen::VectorXd qn = A.partialPivLu().solve(rhs);
    const Eigen::VectorXd an = (qn - q) / (b * dt * dt) - v / (b * dt) - (0.5 / b - 1) * a;
    v += dt * ((1 - g) * a + g * an);
    a = an;
    q = qn;
    worst = std::max(worst, (r.displacement.row(s).transpose() - q).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(worst, 1e-9 * r.displacement.cwiseAbs().maxCoeff());
}

TEST(FeRotorNewmark, SpeedProfileIntegratesTheMeshAngleAndRefactorisesGyroscopics) {
  testing::FeRotorCase c = visnadiFeRotor(constantMesh(3e8));
  const SpeedProfile speed{0.0, 100.0, 0.01, 0.03};
  c.setSpeed(speed);
  EXPECT_DOUBLE_EQ(speed.angle(0.01), 0.0);
  EXPECT_NEAR(speed.angle(0.03), 0.5 * 100.0 * 0.02, 1e-15);
  EXPECT_NEAR(speed.angle(0.05), 1.0 + 100.0 * 0.02, 1e-15);
  const FeRotorModel m = c.model();
  FeTimeOptions o;
  o.duration = 0.05;
  o.record_every = 100;
  o.gyro_speed_tolerance = 1e-2;
  const FeTimeResponse r = solveFeRotorTimeResponse(m, o);
  // One factorisation at the start, then one each time the speed has moved by more than 1 % of
  // its maximum (1.05 rad/s at 0.05 rad/s per step): 1 + 95.
  EXPECT_GE(r.factorisations, 95);
  EXPECT_LE(r.factorisations, 102);
  EXPECT_DOUBLE_EQ(r.speed.back(), 100.0);
}

TEST(FeRotorNewmark, StartsFromTheStaticDeflection) {
  const FeRotorModel m = visnadiFeRotor(constantMesh(3e8)).model();
  FeTimeOptions o;
  o.duration = 1e-3;
  o.start_from_static = true;
  const FeTimeResponse r = solveFeRotorTimeResponse(m, o);
  const double scale = r.displacement.row(0).cwiseAbs().maxCoeff();
  EXPECT_GT(scale, 0.0);
  // Constant stiffness, no unbalance: the rotor stays where it is.
  EXPECT_LT((r.displacement.bottomRows(1) - r.displacement.topRows(1)).cwiseAbs().maxCoeff(),
            1e-9 * scale);
  EXPECT_NEAR(r.mesh_force.back(), m.nominalMeshForce(), 1e-8 * m.nominalMeshForce());
}

// The rotor's DOFs integrated with the train's axial DOFs held at zero (solveFeRotorTimeResponse)
// against the train's stepper over all its DOFs: a spur mesh, the shafts and the bearings load
// no axial DOF, so holding them is exact. Ten mesh periods from rest; the mesh force (elastic,
// free of the rolling rigid-body mode) agrees to 1e-9, the state to 1e-8 of its norm: the
// undamped rolling mode integrates the round-off of the two factorisations (60 vs 72 DOFs).
TEST(FeRotorNewmark, HoldingTheAxialDofsOfASpurRotorIsExact) {
  testing::FeRotorCase c =
      visnadiFeRotor(std::make_shared<FourierMeshStiffness>(3e8, std::vector<double>{0.3, 0.1},
                                                            std::vector<double>{0.0, 1.0}, 1.6),
                     0.0, 4);
  c.setGravity(0.0);
  const FeRotorModel m = c.model();
  FeTimeOptions o;
  o.duration = 1.0 / (m.speed().start * 25.0 / (2.0 * std::numbers::pi)) * 10.0;
  const FeTimeResponse r = solveFeRotorTimeResponse(m, o);
  ASSERT_TRUE(r.converged());
  const GearTrainModel& train = m.train();
  ASSERT_EQ(train.dofCount(), m.dofCount() + 10) << "one axial DOF per node held";
  TrainNewmarkStepper all(train, m.speed().start, o.time_step,
                          NewmarkParameters::averageAcceleration());
  all.reset(0.0, Eigen::VectorXd::Zero(train.dofCount()), Eigen::VectorXd::Zero(train.dofCount()));
  for (long long s = 0; s < r.steps; ++s) all.step();
  const std::vector<int>& map = m.trainDofs();
  Eigen::VectorXd q(map.size());
  for (std::size_t i = 0; i < map.size(); ++i) q(i) = all.displacement()(map[i]);
  const Eigen::VectorXd held = r.displacement.bottomRows(1).transpose();
  const double scale = held.norm();
  ASSERT_GT(scale, 0.0);
  EXPECT_LT((q - held).norm(), 1e-8 * scale);
  std::vector<bool> integrated(train.dofCount(), false);
  for (int i : map) integrated[i] = true;
  double axial = 0.0;
  for (int j = 0; j < train.dofCount(); ++j)
    if (!integrated[j]) axial = std::max(axial, std::abs(all.displacement()(j)));
  EXPECT_LT(axial, 1e-12 * scale) << "the axial DOFs stay at rest";
  EXPECT_NEAR(all.meshForce(0), r.mesh_force.back(), 1e-9 * std::abs(r.mesh_force.back()));
}

}  // namespace
}  // namespace geardyn
