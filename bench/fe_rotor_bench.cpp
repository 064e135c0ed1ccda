// The finite-element geared rotor (issue #8): one Newmark step of the ~60-DOF rotor (the train's
// stepper, issue #31) with the potential-energy TVMS evaluated every step (ROSS, the Python peer,
// takes 2.5 ms per step on this machine for its 60-DOF TVMS two-shaft rotor: target ≤ 10 µs), the
// same step refactorising the effective matrix every step (what the rank-1 update saves), and a
// run-up against the same run at constant speed (target ≤ 1.2×).

#include <benchmark/benchmark.h>

#include <memory>
#include <numbers>

#include "geardyn/solvers/fe_rotor_response.h"
#include "geardyn/solvers/train_time.h"
#include "geardyn/stiffness/potential_energy_stiffness.h"
#include "geardyn/system/gear_train_model.h"
#include "support/fe_rotor_cases.h"

namespace geardyn {
namespace {

constexpr double kRpm = std::numbers::pi / 30.0;

/// The Visnadi rotor with `elements` per shaft (5 → 6 nodes × 5 DOFs × 2 shafts = 60 DOFs).
FeRotorModel rotor(int elements, double start_rpm, double end_rpm, double duration) {
  static const GearPair pair(testing::visnadiPairSpec(0.0));
  static const auto pe = std::make_shared<PotentialEnergyMeshStiffness>(pair);
  testing::FeRotorCase c = testing::visnadiFeRotor(pe, 0.0, elements);
  c.setSpeed({start_rpm * kRpm, end_rpm * kRpm, 0.0, duration});
  return c.model();
}

/// Steps `stepper` from rest, one step per benchmark iteration.
template <class Stepper>
void timeSteps(benchmark::State& state, Stepper& stepper, int dofs) {
  stepper.reset(0.0, Eigen::VectorXd::Zero(dofs), Eigen::VectorXd::Zero(dofs));
  for (auto _ : state) {
    stepper.step();
    benchmark::DoNotOptimize(stepper.displacement().data());
  }
  state.counters["dofs"] = dofs;
}

/// The FE rotor's time response step: the train's stepper over the rotor's own DOFs (60 for 5
/// elements per shaft: the train's axial DOFs held), fe_rotor_response.h.
void BM_FeNewmarkStep(benchmark::State& state) {
  const FeRotorModel model = rotor(static_cast<int>(state.range(0)), 500, 500, 1.0);
  TrainNewmarkStepper stepper = feRotorStepper(model, FeTimeOptions{});
  timeSteps(state, stepper, model.dofCount());
}
BENCHMARK(BM_FeNewmarkStep)
    ->ArgName("elements_per_shaft")
    ->Arg(2)
    ->Arg(5)
    ->Arg(10)
    ->Unit(benchmark::kMicrosecond);

/// The same rotor as a whole gear train (system/fe_rotor_model.h: full DOFs, so 72 DOFs for 60,
/// the axial ones integrated too) stepped by the train's Newmark stepper (dense path), against
/// BM_FeNewmarkStep in the same run (issue #31: ≤ 2.1 µs for the 60-DOF rotor).
void BM_FeRotorTrainNewmarkStep(benchmark::State& state) {
  const FeRotorModel fe = rotor(static_cast<int>(state.range(0)), 500, 500, 1.0);
  const GearTrainModel& model = fe.train();
  TrainNewmarkStepper stepper(model, fe.speed().start, FeTimeOptions{}.time_step,
                              NewmarkParameters::averageAcceleration(), false);
  timeSteps(state, stepper, model.dofCount());
}
BENCHMARK(BM_FeRotorTrainNewmarkStep)
    ->ArgName("elements_per_shaft")
    ->Arg(5)
    ->Unit(benchmark::kMicrosecond);

/// The textbook step: assemble K + k(φ) v vᵀ and the effective matrix, LU-factorise, solve.
void BM_FeNewmarkStepRefactorising(benchmark::State& state) {
  const FeRotorModel model = rotor(static_cast<int>(state.range(0)), 500, 500, 1.0);
  const int n = model.dofCount();
  const double dt = 1e-5, b = 0.25, g = 0.5;
  const Eigen::MatrixXd D = model.damping() + model.speed().start * model.gyroscopic();
  const Eigen::VectorXd& w = model.meshVector();
  Eigen::VectorXd q = Eigen::VectorXd::Zero(n), v = q, a = q;
  double t = 0.0;
  for (auto _ : state) {
    t += dt;
    const double k = model.meshStiffness(model.meshPhase(t));
    const Eigen::MatrixXd A =
        model.stiffness() + k * w * w.transpose() + model.mass() / (b * dt * dt) + g / (b * dt) * D;
    const Eigen::VectorXd rhs = model.staticLoad() +
                                model.mass() * (q / (b * dt * dt) + v / (b * dt) + a) +
                                D * (g / (b * dt) * q + v);
    const Eigen::VectorXd qn = A.partialPivLu().solve(rhs);
    const Eigen::VectorXd an = (qn - q) / (b * dt * dt) - v / (b * dt) - a;
    v += dt * 0.5 * (a + an);
    a = an;
    q = qn;
    benchmark::DoNotOptimize(q.data());
  }
  state.counters["dofs"] = n;
}
BENCHMARK(BM_FeNewmarkStepRefactorising)
    ->ArgName("elements_per_shaft")
    ->Arg(5)
    ->Unit(benchmark::kMicrosecond);

/// 0.5 s (50,000 steps) of the 60-DOF rotor: constant 1500 rpm (arg 0) against a run-up
/// 1000 → 2000 rpm (arg 1) with the same mean speed, PE TVMS on the fly, gyroscopics refactorised
/// every 0.1 % of the top speed.
void BM_FeRun(benchmark::State& state) {
  const bool runup = state.range(0) == 1;
  const FeRotorModel model = rotor(5, runup ? 1000 : 1500, runup ? 2000 : 1500, 0.5);
  FeTimeOptions o;
  o.duration = 0.5;
  o.channels = {0};
  for (auto _ : state) {
    const FeTimeResponse r = solveFeRotorTimeResponse(model, o);
    benchmark::DoNotOptimize(r.displacement.data());
    state.counters["factorisations"] = r.factorisations;
  }
}
BENCHMARK(BM_FeRun)->ArgName("runup")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(5);

}  // namespace
}  // namespace geardyn
