/// The lateral geared rotor (Rao 2023 ch. 2): the force vector against Lagrange's equations
/// evaluated numerically from the energies 2.11–2.13, and against its whirl decomposition.

#include "geardyn/system/lateral_rotor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "geardyn/error.h"

namespace geardyn {
namespace {

using Complex = std::complex<double>;

/// Energies of eqs. 2.11–2.13 written from their definitions (gear centres x_p, y_p, x_g, y_g of
/// eq. 2.3, mesh deflections δ = (pinion centre − gear centre) − e), independent of the model's
/// force(): T(η̇, t), U(η, t), D(η̇, t).
struct Energies {
  const LateralRotorModel& model;

  Eigen::Vector4d offsets(double t) const {  // w(t)
    const auto& s = model.spec();
    const double p = model.pinionOmega() * t + s.pinion_runout_phase;
    const double g = model.gearOmega() * t + s.gear_runout_phase;
    return {s.pinion_runout * std::cos(p), -s.pinion_runout * std::sin(p),
            s.gear_runout * std::cos(g), s.gear_runout * std::sin(g)};
  }
  Eigen::Vector4d offsetRates(double t) const {   // ẇ by central differences of w
    const double h = 1e-4 / model.pinionOmega();  // truncation ~(ωh)²/6 ≈ 2e-9
    return (offsets(t + h) - offsets(t - h)) / (2 * h);
  }
  Eigen::Vector2d te(double t) const {
    double ex, ey, dex, dey;
    model.transmissionError(t, ex, ey, dex, dey);
    return {ex, ey};
  }
  double kinetic(const Eigen::Vector4d& rate, double t) const {
    const Eigen::Vector4d v = rate + offsetRates(t);
    const auto& s = model.spec();
    return 0.5 * s.pinion_mass * (v(0) * v(0) + v(1) * v(1)) +
           0.5 * s.gear_mass * (v(2) * v(2) + v(3) * v(3));
  }
  double potential(const Eigen::Vector4d& eta, double t) const {
    const Eigen::Vector4d c = eta + offsets(t);
    const auto& s = model.spec();
    const Eigen::Vector2d d = Eigen::Vector2d(c(0) - c(2), c(1) - c(3)) - te(t);
    return 0.5 * s.pinion_shaft_stiffness * (c(0) * c(0) + c(1) * c(1)) +
           0.5 * s.gear_shaft_stiffness * (c(2) * c(2) + c(3) * c(3)) +
           0.5 * s.mesh_stiffness * d.squaredNorm();
  }
  double dissipation(const Eigen::Vector4d& rate, double t) const {
    const Eigen::Vector4d v = rate + offsetRates(t);
    const auto& s = model.spec();
    const double h = 1e-4 / (model.meshOmega() * model.harmonics());
    const Eigen::Vector2d dte = (te(t + h) - te(t - h)) / (2 * h);
    const Eigen::Vector2d dd = Eigen::Vector2d(v(0) - v(2), v(1) - v(3)) - dte;
    return 0.5 * s.pinion_shaft_damping * (v(0) * v(0) + v(1) * v(1)) +
           0.5 * s.gear_shaft_damping * (v(2) * v(2) + v(3) * v(3)) +
           0.5 * s.mesh_damping * dd.squaredNorm();
  }
};

Eigen::Vector4d gradient(const std::function<double(const Eigen::Vector4d&)>& f,
                         const Eigen::Vector4d& at, double h) {
  Eigen::Vector4d g;
  for (int i = 0; i < 4; ++i) {
    Eigen::Vector4d a = at, b = at;
    a(i) += h;
    b(i) -= h;
    g(i) = (f(a) - f(b)) / (2 * h);
  }
  return g;
}

TEST(LateralRotor, ForceVectorSatisfiesLagrangesEquationsOfTheEnergies) {
  // Along a trajectory η(t) = η0 + η̇0 τ + η̈0 τ²/2, Lagrange's equations (2.18 with P of 2.17)
  // d/dt ∂T/∂η̇ − ∂T/∂η + ∂U/∂η + ∂D/∂η̇ = P must equal M η̈ + C η̇ + K η − f(t) + P, i.e.
  // the model's equations of motion. Derivatives by central differences (step sizes chosen
  // for ~1e-7 relative truncation + round-off on forces of ~1e4 N).
  const LateralRotorModel model(raoTable41Spec());
  const Energies e{model};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 5; ++trial) {
    const double t0 = 0.3 + 0.01 * trial;
    const Eigen::Vector4d eta(u(rng) * 1e-4, u(rng) * 1e-4, u(rng) * 1e-4, u(rng) * 1e-4);
    const Eigen::Vector4d rate(u(rng) * 1e-2, u(rng) * 1e-2, u(rng) * 1e-2, u(rng) * 1e-2);
    const Eigen::Vector4d acc(u(rng) * 10, u(rng) * 10, u(rng) * 10, u(rng) * 10);
    const double dt = 1e-3 / model.pinionOmega();  // momentum varies at ω_p only
    const auto momentum = [&](double tau) {
      const Eigen::Vector4d v = rate + acc * tau;
      return gradient([&](const Eigen::Vector4d& q) { return e.kinetic(q, t0 + tau); }, v, 1e-3);
    };
    const Eigen::Vector4d dpdt = (momentum(dt) - momentum(-dt)) / (2 * dt);
    const Eigen::Vector4d du =
        gradient([&](const Eigen::Vector4d& q) { return e.potential(q, t0); }, eta, 1e-6);
    const Eigen::Vector4d dd =
        gradient([&](const Eigen::Vector4d& q) { return e.dissipation(q, t0); }, rate, 1e-3);
    const auto& s = model.spec();
    const Eigen::Vector4d weights(0.0, -s.pinion_mass * s.gravity, 0.0, -s.gear_mass * s.gravity);
    const Eigen::Vector4d lagrange = dpdt + du + dd - weights;
    const Eigen::Vector4d ours =
        model.mass() * acc + model.damping() * rate + model.stiffness() * eta - model.force(t0);
    const double scale =
        (model.stiffness() * eta).cwiseAbs().maxCoeff() + model.force(t0).cwiseAbs().maxCoeff();
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(lagrange(i), ours(i), 1e-6 * scale) << i;
  }
}

TEST(LateralRotor, ForceMatchesCorrectedPrintedEquations) {
  // Eqs. 2.30–2.33 as printed, with ė_y (not ė_x) in the y rows: an independent transcription.
  LateralRotorSpec spec = raoTable41Spec();
  spec.gear_shaft_damping = 3.0 * spec.pinion_shaft_damping;  // tells c_s1 from c_s2 apart
  const LateralRotorModel model(spec);
  const auto& s = model.spec();
  const double wp = model.pinionOmega(), wg = model.gearOmega();
  for (double t : {0.0, 0.0123, 1.7, 14.2}) {
    const double cp = std::cos(wp * t + s.pinion_runout_phase);
    const double sp = std::sin(wp * t + s.pinion_runout_phase);
    const double cg = std::cos(wg * t + s.gear_runout_phase);
    const double sg = std::sin(wg * t + s.gear_runout_phase);
    const double ep = s.pinion_runout, eg = s.gear_runout, km = s.mesh_stiffness,
                 cm = s.mesh_damping;
    double ex, ey, dex, dey;
    model.transmissionError(t, ex, ey, dex, dey);
    const double fx1 = s.pinion_mass * ep * wp * wp * cp + s.pinion_shaft_damping * ep * wp * sp -
                       s.pinion_shaft_stiffness * ep * cp +
                       cm * (ep * wp * sp - eg * wg * sg + dex) + km * (-ep * cp + eg * cg + ex);
    const double fy1 = -s.pinion_mass * s.gravity - s.pinion_mass * ep * wp * wp * sp +
                       s.pinion_shaft_damping * ep * wp * cp + s.pinion_shaft_stiffness * ep * sp +
                       cm * (ep * wp * cp + eg * wg * cg + dey) + km * (ep * sp + eg * sg + ey);
    const double fx2 = s.gear_mass * eg * wg * wg * cg + s.gear_shaft_damping * eg * wg * sg -
                       s.gear_shaft_stiffness * eg * cg - cm * (ep * wp * sp - eg * wg * sg + dex) -
                       km * (-ep * cp + eg * cg + ex);
    const double fy2 = -s.gear_mass * s.gravity + s.gear_mass * eg * wg * wg * sg -
                       s.gear_shaft_damping * eg * wg * cg - s.gear_shaft_stiffness * eg * sg -
                       cm * (ep * wp * cp + eg * wg * cg + dey) - km * (ep * sp + eg * sg + ey);
    const Eigen::Vector4d f = model.force(t);
    const double tol = 1e-12 * f.cwiseAbs().maxCoeff();
    EXPECT_NEAR(f(0), fx1, tol);
    EXPECT_NEAR(f(1), fy1, tol);
    EXPECT_NEAR(f(2), fx2, tol);
    EXPECT_NEAR(f(3), fy2, tol);
  }
}

TEST(LateralRotor, WhirlForcingSumsToTheForceVector) {
  const LateralRotorModel model(raoTable41Spec());
  const auto parts = model.whirlForcing();
  ASSERT_EQ(parts.size(), 1u + 2u * 5u + 4u);
  for (double t : {0.0, 0.004, 0.31, 7.77}) {
    Complex z1 = 0.0, z2 = 0.0;
    for (const auto& p : parts) {
      z1 += p.force(0) * std::polar(1.0, p.omega * t);
      z2 += p.force(1) * std::polar(1.0, p.omega * t);
    }
    const Eigen::Vector4d f = model.force(t);
    const double tol = 1e-11 * f.cwiseAbs().maxCoeff();
    EXPECT_NEAR(z1.real(), f(0), tol);
    EXPECT_NEAR(z1.imag(), f(1), tol);
    EXPECT_NEAR(z2.real(), f(2), tol);
    EXPECT_NEAR(z2.imag(), f(3), tol);
  }
}

TEST(LateralRotor, FrequenciesAndDampingMapping) {
  const LateralRotorModel model(raoTable41Spec());
  EXPECT_NEAR(model.meshOmega() / (2 * M_PI), 176.0, 1e-12);           // Table 4.1
  EXPECT_NEAR(model.gearOmega() / (2 * M_PI), 11.0 * 16 / 35, 1e-12);  // 5.03 Hz (§4.4)
  EXPECT_NEAR(model.commonPeriod(), 35.0 / 11.0, 1e-12);
  const auto& s = model.spec();
  EXPECT_NEAR(s.pinion_shaft_damping, 2 * 0.01 * std::sqrt(1e6 * 0.31), 1e-12);
  EXPECT_NEAR(s.gear_shaft_damping, 2 * 0.01 * std::sqrt(1e6 * 1.27), 1e-12);
  EXPECT_NEAR(s.mesh_damping, 2 * 0.01 * std::sqrt(6e8 * 0.31 * 1.27 / 1.58), 1e-9);  // eq. 4.9
  LateralRotorSpec e = s;
  lateralRotorDamping(e, 0.01, 0.01, MeshDampingMass::kArithmeticMean);
  EXPECT_NEAR(e.mesh_damping, 2 * 0.01 * std::sqrt(6e8 * 0.79), 1e-9);
}

TEST(LateralRotor, RejectsNonPhysicalData) {
  LateralRotorSpec s = raoTable41Spec();
  s.mesh_stiffness = -1.0;
  EXPECT_THROW({ LateralRotorModel m(s); }, InputError);
  s = raoTable41Spec();
  s.te_y.pop_back();
  EXPECT_THROW({ LateralRotorModel m(s); }, InputError);
  s = raoTable41Spec();
  s.pinion_runout = NAN;
  EXPECT_THROW({ LateralRotorModel m(s); }, InputError);
  s = raoTable41Spec();
  s.gear_teeth = 1;
  EXPECT_THROW({ LateralRotorModel m(s); }, InputError);
}

}  // namespace
}  // namespace geardyn
