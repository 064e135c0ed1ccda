// Gear trains (issue #16): the modal analysis of the 3-planet lumped stage of Lin & Parker
// (1999) as one whole library call from the description (target < 1 ms), one Newmark step of
// the two-stage reducer with both meshes' stiffness varying, and its frequency-domain steady
// state at one speed (harmonic balance condensed onto the mesh deflections).

#include <benchmark/benchmark.h>

#include <memory>

#include "geardyn/analysis/gear_train_session.h"
#include "geardyn/config/train_analysis.h"
#include "geardyn/solvers/train_modal.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/solvers/train_time.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "system/sample_trains.h"

namespace geardyn {
namespace {

std::shared_ptr<const MeshStiffness> smooth(double mean) {
  return std::make_shared<FourierMeshStiffness>(mean, std::vector<double>{0.12, 0.05, 0.02},
                                                std::vector<double>{0.0, 0.3, 1.1}, 1.6);
}

void BM_PlanetaryModalWholeCall(benchmark::State& state) {
  const GearTrainSpec spec = testing::linParker1999(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const GearTrainModel model(spec);
    auto modes = trainModes(model, 0.0);
    benchmark::DoNotOptimize(modes.data());
  }
}
BENCHMARK(BM_PlanetaryModalWholeCall)->Arg(3)->Arg(5)->Unit(benchmark::kMicrosecond);

void BM_TrainNewmarkStep(benchmark::State& state) {
  const GearTrainModel model(testing::twoStageReducer(smooth(4e8), smooth(6e8)));
  TrainNewmarkStepper stepper(model, model.inputSpeed(), 1e-5,
                              NewmarkParameters::averageAcceleration());
  stepper.reset(0.0, Eigen::VectorXd::Zero(model.dofCount()),
                Eigen::VectorXd::Zero(model.dofCount()));
  for (auto _ : state) {
    stepper.step();
    benchmark::DoNotOptimize(stepper.displacement().data());
  }
  state.counters["dofs"] = model.dofCount();
}
BENCHMARK(BM_TrainNewmarkStep);

// A 500-DOF FE gearbox (4 helical stages on 5 flexible shafts, six DOFs per node) with every
// mesh's stiffness varying: target ≤ 50 µs per step (issue #16).
void BM_FlexibleTrainNewmarkStep(benchmark::State& state) {
  const GearTrainModel model(
      testing::flexibleChain(static_cast<int>(state.range(0)), 0.018, smooth(4e8)));
  TrainNewmarkStepper stepper(model, model.inputSpeed(), 1e-5,
                              NewmarkParameters::averageAcceleration(), state.range(1) != 0);
  stepper.reset(0.0, Eigen::VectorXd::Zero(model.dofCount()),
                Eigen::VectorXd::Zero(model.dofCount()));
  for (auto _ : state) {
    stepper.step();
    benchmark::DoNotOptimize(stepper.displacement().data());
  }
  state.counters["dofs"] = model.dofCount();
  state.counters["meshes"] = static_cast<double>(model.meshes().size());
}
// Second argument: 1 sparse (the default at this size), 0 dense (for the ratio).
BENCHMARK(BM_FlexibleTrainNewmarkStep)->Args({4, 1})->Args({4, 0})->Unit(benchmark::kMicrosecond);

// Campbell diagram of the 500-DOF FE gearbox over 200 speeds, 12 tracked modes: target < 2 s
// (shift-invert Arnoldi on sparse matrices, Spectra).
void BM_FlexibleTrainCampbell(benchmark::State& state) {
  const GearTrainModel model(testing::flexibleChain(4, 0.018));
  TrainModalOptions options;
  options.modes = 12;
  std::vector<double> speeds;
  for (int i = 0; i < state.range(0); ++i) speeds.push_back(10.0 + 2.0 * i);
  const auto lines = trainOrderLines(model, 2);
  for (auto _ : state) {
    auto campbell = trainCampbell(model, speeds, options, lines);
    benchmark::DoNotOptimize(campbell.modes.data());
  }
  state.counters["dofs"] = model.dofCount();
}
BENCHMARK(BM_FlexibleTrainCampbell)->Arg(2)->Arg(200)->Unit(benchmark::kMillisecond);

void BM_TrainSteadyStatePerSpeed(benchmark::State& state) {
  const GearTrainModel model(testing::twoStageReducer(smooth(4e8), smooth(6e8)));
  TrainSteadyOptions options;
  options.mesh_harmonics = static_cast<int>(state.range(0));
  const TrainSteadySolver solver(model, options);
  double speed = model.inputSpeed();
  for (auto _ : state) {
    auto s = solver.solve(speed);
    benchmark::DoNotOptimize(s.harmonic.data());
  }
}
BENCHMARK(BM_TrainSteadyStatePerSpeed)->Arg(8)->Arg(20)->Unit(benchmark::kMillisecond);

// Forced response per speed of the flexible two-stage reducer (full DOFs, 30 mm elements,
// ~270 DOFs): 2H + 1 harmonic blocks of the common period, 8 mesh harmonics.
void BM_FlexibleTrainSteadyStatePerSpeed(benchmark::State& state) {
  const GearTrainModel model(testing::flexibleReducer(12.0, 0.03));
  TrainSteadyOptions options;
  options.mesh_harmonics = 8;
  const TrainSteadySolver solver(model, options);
  for (auto _ : state) {
    auto s = solver.solve(model.inputSpeed());
    benchmark::DoNotOptimize(s.harmonic.data());
  }
  state.counters["dofs"] = model.dofCount();
}
BENCHMARK(BM_FlexibleTrainSteadyStatePerSpeed)->Unit(benchmark::kMillisecond);

// Issue #39: the forced response per speed of the example itself
// (examples/train_two_stage_flexible.toml, 270 DOFs, its [forced] options: 8 mesh harmonics,
// H = 24 over the common period; target <= 50 ms a speed), at the operating speed and, to
// vary the harmonic blocks' frequencies as a sweep does, at 0.5 and 1.5 times it.
void BM_FlexibleExampleForcedPerSpeed(benchmark::State& state) {
  auto session = analysis::GearTrainSession::fromFile(GEARDYN_SOURCE_DIR
                                                      "/examples/train_two_stage_flexible.toml");
  const GearTrainModel& model = session.linearModel();
  const TrainSteadySolver solver(model,
                                 config::trainSteadyOptionsFromConfig(session.inputs().analysis));
  const double speed = model.inputSpeed();
  int i = 0;
  for (auto _ : state) {
    auto s = solver.solve(speed * (0.5 + 0.5 * (i++ % 3)));
    benchmark::DoNotOptimize(s.harmonic.data());
  }
  state.counters["dofs"] = model.dofCount();
}
BENCHMARK(BM_FlexibleExampleForcedPerSpeed)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace geardyn
