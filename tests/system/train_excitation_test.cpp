/// Excitations of a gear train beside its meshes (system/train_excitation.h) against closed forms
/// and against Rao's 4-DOF lateral rotor (system/lateral_rotor.h):
///   - an unbalance m e on a Jeffcott rotor (mass m on an isotropic support k, c): the whirl
///     y + i z = m e Ω² e^{i(Ωt + ϕ)} / (k − m Ω² + i Ω c), in both senses of rotation;
///   - a prescribed displacement d across that support (base excitation of a single DOF per
///     direction): X = (k + i ω c) / (k − m ω² + i ω c) Δ at ω = order × |Ω|, the mean statically;
///   - a gear runout on the two-stage reducer (constant mesh stiffness): the load
///     −v_m (k̄ + iω c_m) v_gᵀ W on its mesh, solved directly with D(ω) = K̄ − ω² M + iω C;
///   - the same unbalance by the train's Newmark stepper after the transient (average
///     acceleration: forced-response error O((ω Δt)²));
///   - the gearbox Rao's rotor translates to (config/rotor_gearbox.h): its force is eq. 2.34 of
///     the 4-DOF model at every t, and its steady state that model's exact frequency-domain
///     response (thesis eqs. 3.135–3.138).
///
/// Tolerances: the closed forms and the 4-DOF model are the same linear algebra evaluated another
/// way, 1e-10 of the largest amplitude (the steady state's harmonic solves are 6 × 6); the force
/// of the 4-DOF model and of the gearbox differ by the degrees written in the gearbox text and
/// read back (1e-16 relative per phase), 1e-12 of the largest force; Newmark with 256 steps per
/// revolution, 5e-4 of the amplitude (the average-acceleration rule's relative error
/// (ωΔt)²/12 = 5e-5 amplified below resonance by less than 10).

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "geardyn/config/rotor_gearbox.h"
#include "geardyn/error.h"
#include "geardyn/solvers/rotor_response.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/solvers/train_time.h"
#include "geardyn/solvers/train_transient.h"
#include "geardyn/system/gear_train_model.h"
#include "geardyn/system/lateral_rotor.h"
#include "sample_trains.h"

namespace geardyn {
namespace {

using Complex = std::complex<double>;
constexpr Complex kJ(0.0, 1.0);
constexpr double kMass = 2.0, kStiffness = 1e6, kZeta = 0.05;

double damping() {
  return 2.0 * kZeta * std::sqrt(kStiffness * kMass);
}

/// The Jeffcott rotor: "rotor" (mass m) on the isotropic support k, c, coupled torsionally to a
/// "load" shaft held laterally by a stiff bearing (it takes the output).
GearTrainSpec jeffcott(double speed) {
  GearTrainSpec s;
  s.dofs = TrainDofs::kPlanar;
  s.shafts = {{"rotor", kMass, 1e-3}, {"load", 1.0, 1e-3}};
  TrainBearingSpec support{"support", "rotor", "", kStiffness, kStiffness};
  support.cyy = support.czz = damping();
  s.bearings = {support, {"load_support", "load", "", 1e9, 1e9}};
  s.couplings = {{"coupling", "rotor", "load", 1e3}};
  s.operating = {"rotor", speed, 0.0, "load"};
  return s;
}

Eigen::VectorXd times(double period, int n) {
  return Eigen::VectorXd::LinSpaced(n, 0.0, period * (n - 1.0) / n);
}

TEST(TrainExcitation, UnbalanceOnAJeffcottRotorIsItsClosedForm) {
  for (double speed : {300.0, -300.0}) {
    GearTrainSpec spec = jeffcott(speed);
    const double me = 1e-4, phase = 0.5;
    spec.unbalances = {{"u", "rotor", 0.0, me, phase}};
    const GearTrainModel model(spec);
    ASSERT_EQ(model.excitations().size(), 1u);
    const TrainSteadyState s = solveTrainSteadyState(model, speed);
    const Complex Y = me * speed * speed * std::polar(1.0, phase) /
                      (kStiffness - kMass * speed * speed + kJ * speed * damping());
    const Eigen::VectorXd t = times(2.0 * std::numbers::pi / std::abs(speed), 16);
    const Eigen::MatrixXd q = s.displacement(t);
    const int y = model.translationDof(model.bodyIndex("rotor"));
    for (Eigen::Index k = 0; k < t.size(); ++k) {
      const Complex e = Y * std::polar(1.0, speed * t(k));
      EXPECT_NEAR(q(k, y), e.real(), 1e-10 * std::abs(Y)) << "speed " << speed;
      EXPECT_NEAR(q(k, y + 1), (-kJ * e).real(), 1e-10 * std::abs(Y)) << "speed " << speed;
    }
  }
}

TEST(TrainExcitation, PrescribedBearingDisplacementIsABaseExcitation) {
  const double speed = 200.0, order = 3.0, w = order * speed;
  GearTrainSpec spec = jeffcott(speed);
  TrainBearingExcitationSpec e;
  e.name = "base";
  e.bearing = "support";
  e.reference = "rotor";
  e.mean_y = 3e-6;
  e.orders = {order};
  e.amplitude_y = {1e-5}, e.phase_y = {0.4};
  e.amplitude_z = {2e-5}, e.phase_z = {-1.0};
  spec.bearing_excitations = {e};
  const GearTrainModel model(spec);
  const int y = model.translationDof(model.bodyIndex("rotor"));
  // The mean statically: k (q − d̄) = 0.
  EXPECT_NEAR(solveTrainStatic(model, speed).displacement(y), e.mean_y, 1e-12 * e.mean_y);
  const Complex H =
      (kStiffness + kJ * w * damping()) / (kStiffness - kMass * w * w + kJ * w * damping());
  const Complex Dy = 1e-5 * std::polar(1.0, 0.4), Dz = 2e-5 * std::polar(1.0, -1.0);
  const Eigen::VectorXd t = times(2.0 * std::numbers::pi / speed, 32);
  const Eigen::MatrixXd q = solveTrainSteadyState(model, speed).displacement(t);
  const double scale = std::abs(H) * 2e-5;
  for (Eigen::Index k = 0; k < t.size(); ++k) {
    const Complex rot = std::polar(1.0, w * t(k));
    EXPECT_NEAR(q(k, y), e.mean_y + (H * Dy * rot).real(), 1e-10 * scale);
    EXPECT_NEAR(q(k, y + 1), (H * Dz * rot).real(), 1e-10 * scale);
  }
}

TEST(TrainExcitation, GearRunoutExcitesItsMeshAlongTheLineOfAction) {
  const GearTrainModel plain(testing::twoStageReducer());
  GearTrainSpec spec = testing::twoStageReducer();
  const double a = 20e-6, phase = 0.7;
  spec.runouts = {{"z1_runout", "z1", a, phase}};
  const GearTrainModel model(spec);
  const double speed = model.inputSpeed(), w = speed;  // z1 turns with the input
  TrainSteadyOptions options;
  options.mesh_harmonics = 1;  // constant mesh stiffness: one harmonic is exact
  const TrainSteadyState with = solveTrainSteadyState(model, speed, options);
  const TrainSteadyState without = solveTrainSteadyState(plain, speed, options);
  // The load of the runout w = a (cos ψ, sin ψ) = Re[a e^{iϕ} (1, −i) e^{iωt}] on stage 1.
  const Eigen::VectorXd v = model.meshVector(0);
  const int y = model.translationDof(model.bodyIndex("input"));
  const Complex vw = a * std::polar(1.0, phase) * Complex(v(y), -v(y + 1));
  const TrainMesh& mesh = model.meshes()[0];
  const Eigen::VectorXcd F =
      -(mesh.mean_stiffness + kJ * w * mesh.damping) * vw * v.cast<Complex>();
  const Eigen::MatrixXcd D = (model.meanStiffnessAt(speed) - w * w * model.mass()).cast<Complex>() +
                             kJ * w * model.dampingAt(speed).cast<Complex>();
  const Eigen::VectorXcd X = D.partialPivLu().solve(F);
  const Eigen::VectorXd t = times(2.0 * std::numbers::pi / speed, 8);
  const Eigen::MatrixXd dq = with.displacement(t) - without.displacement(t);
  const double scale = X.cwiseAbs().maxCoeff();
  for (Eigen::Index k = 0; k < t.size(); ++k) {
    const Eigen::VectorXd expected = (X * std::polar(1.0, w * t(k))).real();
    for (Eigen::Index i = 0; i < expected.size(); ++i)
      EXPECT_NEAR(dq(k, i), expected(i), 1e-9 * scale) << model.dofName(static_cast<int>(i));
  }
}

TEST(TrainExcitation, NewmarkReachesTheUnbalanceSteadyState) {
  const double speed = 300.0, me = 1e-4;
  GearTrainSpec spec = jeffcott(speed);
  spec.unbalances = {{"u", "rotor", 0.0, me, 0.0}};
  const GearTrainModel model(spec);
  const double period = 2.0 * std::numbers::pi / speed;
  TrainNewmarkStepper stepper(model, speed, period / 256, NewmarkParameters::averageAcceleration());
  stepper.reset(0.0, Eigen::VectorXd::Zero(model.dofCount()),
                Eigen::VectorXd::Zero(model.dofCount()));
  // ln(1e6) / (ζ ω_n) = 0.39 s for the transient; 0.6 s is 28 periods more.
  const int steps = 256 * static_cast<int>(std::ceil(0.6 / period));
  for (int k = 0; k < steps; ++k) stepper.step();
  const Complex Y =
      me * speed * speed / (kStiffness - kMass * speed * speed + kJ * speed * damping());
  const int y = model.translationDof(model.bodyIndex("rotor"));
  const Complex e = Y * std::polar(1.0, speed * stepper.time());
  EXPECT_NEAR(stepper.displacement()(y), e.real(), 5e-4 * std::abs(Y));
  EXPECT_NEAR(stepper.displacement()(y + 1), (-kJ * e).real(), 5e-4 * std::abs(Y));
}

/// A mode orthogonal to every excitation's force pattern is not excited by it: under an
/// unbalance on the Jeffcott rotor, the undamped torsional mode (rotor against load through the
/// coupling) and the load's lateral modes (on their undamped stiff bearing) neither set the time
/// run's duration nor are called excited; the rotor's own lateral mode, damped, sets it to
/// ln(1e6) / (ζ ω_n) (σ = ζ ω_n exactly: y and z are uncoupled single DOFs), and undamped it is
/// excited (an endless transient). Tolerance 1e-9: the eigenvalues of a 6-DOF model.
TEST(TrainExcitation, OnlyTheModesAnExcitationDrivesAreWaitedFor) {
  const double speed = 300.0;
  GearTrainSpec spec = jeffcott(speed);
  spec.unbalances = {{"u", "rotor", 0.0, 1e-4, 0.0}};
  const GearTrainModel model(spec);
  const TrainTransient transient = trainTransient(model, speed);
  ASSERT_FALSE(transient.undamped.empty());
  for (const TrainUndampedMode& mode : transient.undamped)
    EXPECT_FALSE(mode.excited) << mode.frequency << " Hz";
  const double omega_n = std::sqrt(kStiffness / kMass);
  EXPECT_NEAR(transient.decay_time, std::log(1e6) / (kZeta * omega_n), 1e-9 * transient.decay_time);

  spec.bearings[0].cyy = spec.bearings[0].czz = 0.0;
  const TrainTransient undamped = trainTransient(GearTrainModel(spec), speed);
  bool lateral_excited = false;
  for (const TrainUndampedMode& mode : undamped.undamped) {
    const bool lateral =
        std::abs(mode.frequency - omega_n / (2.0 * std::numbers::pi)) < 1e-9 * mode.frequency;
    EXPECT_EQ(mode.excited, lateral) << mode.frequency << " Hz";
    lateral_excited = lateral_excited || (lateral && mode.excited);
  }
  EXPECT_TRUE(lateral_excited);
  EXPECT_TRUE(std::isinf(undamped.decay_time));
}

TEST(TrainExcitation, RefusedWhereTheyDoNotApply) {
  GearTrainSpec spec = jeffcott(300.0);
  spec.unbalances = {{"u", "rotor", 0.0, -1.0, 0.0}};
  EXPECT_THROW(GearTrainModel{spec}, InputError);
  spec.unbalances.clear();
  TrainBearingExcitationSpec e;
  e.name = "base";
  e.bearing = "nowhere";
  spec.bearing_excitations = {e};
  EXPECT_THROW(GearTrainModel{spec}, InputError);
  e.bearing = "support";
  e.reference = "rotor";
  e.orders = {2.0};
  e.amplitude_y = {1e-6};  // no phase_y, amplitude_z, phase_z for it
  spec.bearing_excitations = {e};
  try {
    GearTrainModel model(spec);
    ADD_FAILURE() << "a harmonic without its phases was accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("bearing_excitations.base.phase_y_deg"),
              std::string::npos)
        << error.what();
  }
}

/// Table 4.1 as the 4-DOF model and as the train of the gearbox it translates to, with the
/// train's DOFs of (x₁, y₁, x₂, y₂): (pinion.y, pinion.z, gear.y, gear.z).
struct RaoTable41 {
  LateralRotorModel model{raoTable41Spec()};
  std::vector<std::string> warnings;
  GearTrainModel train{config::lateralRotorGearTrain(raoTable41Spec(), "Table 4.1", warnings)};
  int p = train.translationDof(train.bodyIndex("pinion"));
  int g = train.translationDof(train.bodyIndex("gear"));
  std::array<int, 4> map{p, p + 1, g, g + 1};
};

TEST(TrainExcitation, RaoRotorAsAGearboxHasTheFourDofForce) {
  const RaoTable41 rao;
  const double speed = rao.train.inputSpeed();
  EXPECT_NEAR(speed, -rao.model.pinionOmega(), 1e-15 * rao.model.pinionOmega());
  Eigen::VectorXd f(rao.train.dofCount());
  for (double t : {0.0, 0.0123, 0.377, 1.9, 14.2}) {
    f = rao.train.staticLoad();
    addExcitationForce(rao.train.excitations(), std::abs(speed) * t, speed, 0.0, nullptr, f);
    const Eigen::Vector4d expected = rao.model.force(t);
    const double scale = expected.cwiseAbs().maxCoeff();
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(f(rao.map[i]), expected(i), 1e-12 * scale) << t;
  }
}

TEST(TrainExcitation, RaoRotorAsAGearboxHasTheFourDofSteadyState) {
  const RaoTable41 rao;
  const double period = rao.model.commonPeriod();
  const TrainSteadyState s = solveTrainSteadyState(rao.train, rao.train.inputSpeed());
  EXPECT_NEAR(1.0 / s.base_frequency, period, 1e-12 * period);
  std::vector<double> t;
  for (int k = 0; k < 64; ++k) t.push_back(period * k / 64.0 + 1e-4 * k);
  const auto exact = superposeWhirlResponse(solveRotorFrequencyResponse(rao.model), t);
  const Eigen::MatrixXd q = s.displacement(
      Eigen::Map<const Eigen::VectorXd>(t.data(), static_cast<Eigen::Index>(t.size())));
  double scale = 0.0;
  for (const auto& e : exact) scale = std::max(scale, e.cwiseAbs().maxCoeff());
  for (std::size_t k = 0; k < t.size(); ++k)
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(q(k, rao.map[i]), exact[k](i), 1e-10 * scale) << t[k];
}

}  // namespace
}  // namespace geardyn
