/// Lateral geared rotor (Rao 2023 Table 4.1): 15 s of Dormand–Prince at rtol 1e-8 from rest
/// (the target: >= 50x faster than scipy's solve_ivp RK45 at the same tolerances, see
/// bench/rotor_scipy_compare.py), the exact frequency-domain solution (target: microseconds),
/// and the whirl components of the steady window by exact FFT bins.

#include <benchmark/benchmark.h>

#include "geardyn/config/rotor_gearbox.h"
#include "geardyn/identify/dte_identification.h"
#include "geardyn/signal/full_spectrum.h"
#include "geardyn/solvers/rotor_response.h"
#include "geardyn/solvers/train_periodic_record.h"
#include "geardyn/solvers/train_response.h"

namespace {

/// The thesis's 15 s run: Table 4.1's rotor as the gearbox it is, recorded from rest by the
/// train's Dormand–Prince (what `geardyn rotor` runs; issue #31's bound: within 10 % of the
/// former 4-DOF integrator, 1680 ms CPU on main c81ab40 in the same bench).
void BM_RotorDormandPrince15s(benchmark::State& state) {
  const geardyn::LateralRotorSpec spec = geardyn::raoTable41Spec();
  std::vector<std::string> warnings;
  const geardyn::GearTrainModel train(
      geardyn::config::lateralRotorGearTrain(spec, "bench", warnings));
  const std::vector<int> probes = geardyn::config::lateralRotorProbeDofs(train);
  const double period = geardyn::LateralRotorModel(spec).commonPeriod();
  geardyn::TrainRecordOptions options;  // 15 s, 2^15 samples, rtol 1e-8
  long long steps = 0;
  for (auto _ : state) {
    const auto r = geardyn::recordTrainFromRest(train, train.inputSpeed(), probes, period, options);
    steps = r.steps;
    benchmark::DoNotOptimize(r.displacement.data());
  }
  state.counters["steps"] = static_cast<double>(steps);
}
BENCHMARK(BM_RotorDormandPrince15s)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_RotorFrequencyDomain(benchmark::State& state) {
  const geardyn::LateralRotorModel model(geardyn::raoTable41Spec());
  for (auto _ : state) benchmark::DoNotOptimize(geardyn::solveRotorFrequencyResponse(model));
}
BENCHMARK(BM_RotorFrequencyDomain)->Unit(benchmark::kMicrosecond);

/// The same steady state from the gearbox the rotor is (config/rotor_gearbox.h): the train's
/// harmonic balance over the common period (2800 harmonics of f_p/35, 6 DOFs), what
/// `geardyn rotor` now reports as its frequency domain.
void BM_RotorGearboxSteadyState(benchmark::State& state) {
  std::vector<std::string> warnings;
  const geardyn::GearTrainModel train(
      geardyn::config::lateralRotorGearTrain(geardyn::raoTable41Spec(), "bench", warnings));
  for (auto _ : state) {
    benchmark::DoNotOptimize(geardyn::solveTrainSteadyState(train, train.inputSpeed()));
  }
}
BENCHMARK(BM_RotorGearboxSteadyState)->Unit(benchmark::kMillisecond);

void BM_RotorForceEvaluation(benchmark::State& state) {
  const geardyn::LateralRotorModel model(geardyn::raoTable41Spec());
  double t = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(model.force(t));
    t += 1e-5;
  }
}
BENCHMARK(BM_RotorForceEvaluation);

void BM_WhirlComponentsExactBins(benchmark::State& state) {
  const geardyn::LateralRotorModel model(geardyn::raoTable41Spec());
  const auto parts = geardyn::solveRotorFrequencyResponse(model);
  std::vector<double> t, x, y;
  const int n = 6950 * 4;  // four common periods at the default sample rate
  for (int k = 0; k < n; ++k) t.push_back(4 * model.commonPeriod() * k / n);
  for (const auto& e : geardyn::superposeWhirlResponse(parts, t)) {
    x.push_back(e(0));
    y.push_back(e(1));
  }
  std::vector<geardyn::WhirlComponent> components;
  for (const auto& p : parts) components.push_back({p.name, p.omega / (2 * M_PI), 0.0});
  const double fs = n / (4 * model.commonPeriod());
  for (auto _ : state) {
    geardyn::extractWhirlComponents(x, y, fs, components);
    benchmark::DoNotOptimize(components.front().value);
  }
}
BENCHMARK(BM_WhirlComponentsExactBins)->Unit(benchmark::kMillisecond);

}  // namespace

namespace {

/// DTE identification from exact Table 4.1 peaks (target: milliseconds).
void BM_IdentifyDte(benchmark::State& state) {
  const geardyn::LateralRotorSpec truth = geardyn::raoTable41Spec();
  geardyn::MeasuredWhirlPeaks m;
  m.pinion_speed = truth.pinion_speed;
  m.peaks = geardyn::modelWhirlPeaks(truth);
  geardyn::IdentificationOptions o;
  o.method = state.range(0) ? geardyn::IdentificationMethod::kJoint
                            : geardyn::IdentificationMethod::kThreeStep;
  for (auto _ : state) benchmark::DoNotOptimize(geardyn::identifyDte(truth, {m}, o));
}
BENCHMARK(BM_IdentifyDte)->ArgName("joint")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
