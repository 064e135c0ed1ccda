// Rolling bearings from their geometry (issue 35): the load–deflection relation and 5×5 tangent
// stiffness of a 20-element ball bearing (target ≤ 5 µs) and of a 20-roller tapered bearing
// with 10 slices per roller, and the nonlinear static deflection of the two-stage reducer on
// its six rolling bearings (target ≤ 5 ms), planar and with full DOFs on flexible shafts.

#include <benchmark/benchmark.h>

#include "geardyn/contact/rolling_bearing.h"
#include "geardyn/solvers/train_response.h"
#include "system/rolling_bearing_trains.h"

namespace geardyn {
namespace {

RollingBearing::Vector5 loadedState() {
  RollingBearing::Vector5 q;
  q << 12e-6, -5e-6, 8e-6, 1.5e-4, -0.8e-4;  // radial, axial and tilt: most elements loaded
  return q;
}

/// F and K of `geometry` with 20 elements on a pitch circle of `pitch_diameter` [m].
void loadAndStiffness(benchmark::State& state, RollingBearingGeometry geometry,
                      double pitch_diameter) {
  geometry.elements = 20;
  geometry.pitch_diameter = pitch_diameter;
  const RollingBearing bearing(geometry);
  const RollingBearing::Vector5 q = loadedState();
  RollingBearing::Vector5 F;
  RollingBearing::Matrix5 K;
  for (auto _ : state) {
    bearing.evaluate(q, F, &K);
    benchmark::DoNotOptimize(K.data());
  }
}

void BM_BallBearing20LoadAndStiffness(benchmark::State& state) {
  loadAndStiffness(state, testing::deepGroove6208()->geometry(), 100e-3);
}
BENCHMARK(BM_BallBearing20LoadAndStiffness)->Unit(benchmark::kMicrosecond);

void BM_TaperedRoller20LoadAndStiffness(benchmark::State& state) {
  loadAndStiffness(state, testing::tapered30208()->geometry(), 80e-3);
}
BENCHMARK(BM_TaperedRoller20LoadAndStiffness)->Unit(benchmark::kMicrosecond);

void BM_ReducerNonlinearStatic(benchmark::State& state) {
  const bool full = state.range(0) != 0;
  const GearTrainModel model(
      testing::withRollingBearings(full ? testing::flexibleReducer() : testing::twoStageReducer()));
  for (auto _ : state) {
    const TrainStaticResult r = solveTrainStatic(model, model.inputSpeed());
    benchmark::DoNotOptimize(r.displacement.data());
  }
  state.counters["dofs"] = model.dofCount();
}
BENCHMARK(BM_ReducerNonlinearStatic)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace geardyn
