// Nonlinear gear trains (issue 17): cost of one continuation point of the train harmonic
// balance on the 3-planet stage with backlash at its 6 meshes (H = 15, N = 256; target <= 1 ms),
// without and with the monodromy stability, of one nonlinear Newmark step of that stage, and a
// whole HBM sweep against a stepped Newmark sweep over the same range (target: HBM >= 100x
// faster), and the cost of the stability (monodromy, Hill's method) against the Newton solve of
// a point.

#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <numbers>

#include "geardyn/solvers/continuation.h"
#include "geardyn/solvers/detail/train_hill.h"
#include "geardyn/solvers/train_harmonic_balance.h"
#include "geardyn/solvers/train_nonlinear_time.h"
#include "geardyn/solvers/train_response.h"
#include "system/nonlinear_sample_trains.h"
#include "system/pump_drive.h"

namespace geardyn {
namespace {

void BM_TrainHbmContinuationPoint(benchmark::State& state) {
  const GearTrainModel model(testing::nonlinear::planetary(4e-6));
  TrainHarmonicBalance hbm(model, testing::nonlinear::planetaryHbmOptions());
  const ContinuationOptions c = testing::nonlinear::planetarySweep(state.range(0) > 0);
  long long points = 0;
  for (auto _ : state) {
    const ContinuationResult r = continueInFrequency(hbm, c);
    points += static_cast<long long>(r.points.size());
    benchmark::DoNotOptimize(r.points.data());
  }
  state.counters["points"] = benchmark::Counter(static_cast<double>(points) / state.iterations());
  state.counters["per_point"] = benchmark::Counter(
      static_cast<double>(points), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_TrainHbmContinuationPoint)
    ->Arg(0)
    ->Arg(1)
    ->ArgName("stability")
    ->Unit(benchmark::kMillisecond);

void BM_TrainNonlinearNewmarkStep(benchmark::State& state) {
  const GearTrainModel model(testing::nonlinear::planetary(4e-6));
  const double speed = model.inputSpeed();
  TrainNonlinearNewmark stepper(model, speed, 1e-6, NewmarkParameters::averageAcceleration());
  stepper.reset(0.0, solveTrainStatic(model, speed).displacement,
                Eigen::VectorXd::Zero(model.dofCount()));
  for (auto _ : state) {
    stepper.step(1e-13, 50);
    benchmark::DoNotOptimize(stepper.displacement().data());
  }
}
BENCHMARK(BM_TrainNonlinearNewmarkStep);

// The whole sweep, mesh frequency 4–13 kHz, both ways: the HBM continuation (no stability, as
// a Newmark sweep has none) against a stepped Newmark sweep that resolves the curve as finely
// — one steady state per HBM point, each started from the previous one (stepped sine, the
// cheapest start), 512 steps a mesh period, steady to 1e-9 (the settings at which the two
// agree within 4.4e-4 of p2p in TrainNonlinearLong) or, looser, 1e-5 (second argument: the
// exponent). Newmark runs at `newmark_points` evenly
// spaced frequencies and its cost per frequency is scaled to the HBM's point count: counter
// `ratio` = Newmark sweep time / HBM sweep time.
void BM_TrainSweepHbmAgainstNewmark(benchmark::State& state) {
  const GearTrainModel model(testing::nonlinear::planetary(4e-6));
  TrainHarmonicBalance hbm(model, testing::nonlinear::planetaryHbmOptions());
  const ContinuationOptions c = testing::nonlinear::planetarySweep(false);
  const int newmark_points = static_cast<int>(state.range(0));
  double hbm_seconds = 0.0, newmark_seconds = 0.0;
  long long points = 0, periods = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    const ContinuationResult r = continueInFrequency(hbm, c);
    const auto t1 = std::chrono::steady_clock::now();
    points = static_cast<long long>(r.points.size());
    TrainNonlinearTimeOptions o;
    o.steady_tolerance = std::pow(10.0, -static_cast<double>(state.range(1)));
    // Fixed steps (as the defaults give here: this stage's k(φ) is smooth, so its force never
    // jumps; refining its contact changes buys no accuracy, docs/theory/nonlinear_gear_trains.md).
    o.event_refinement = o.contact_refinement = 0;
    Eigen::VectorXd q, v;
    periods = 0;
    for (int k = 0; k < newmark_points; ++k) {
      const double omega = c.start + (c.stop - c.start) * k / (newmark_points - 1);
      const TrainNonlinearTimeResponse n =
          solveTrainNonlinearTime(model, hbm.inputSpeed(omega), o, q, v);
      // The next frequency starts from this one's last state (velocity by a backward
      // difference over the last step: any start close to the orbit serves).
      const Eigen::Index last = n.displacement.rows() - 1;
      q = n.displacement.row(last).transpose();
      v = (n.displacement.row(last) - n.displacement.row(last - 1)).transpose() /
          (n.t(last) - n.t(last - 1));
      periods += n.periods;
      benchmark::DoNotOptimize(n.mesh_deflection.data());
    }
    const auto t2 = std::chrono::steady_clock::now();
    hbm_seconds = std::chrono::duration<double>(t1 - t0).count();
    newmark_seconds = std::chrono::duration<double>(t2 - t1).count();
  }
  const double newmark_sweep = newmark_seconds / newmark_points * static_cast<double>(points);
  state.counters["hbm_points"] = static_cast<double>(points);
  state.counters["hbm_sweep_s"] = hbm_seconds;
  state.counters["newmark_per_frequency_s"] = newmark_seconds / newmark_points;
  state.counters["newmark_periods_per_frequency"] = static_cast<double>(periods) / newmark_points;
  state.counters["newmark_sweep_s"] = newmark_sweep;
  state.counters["ratio"] = newmark_sweep / hbm_seconds;
  // A coarser stepped sweep of 100 frequencies (misses the folds' detail the HBM resolves).
  state.counters["ratio_100_frequencies"] = 100.0 * newmark_seconds / newmark_points / hbm_seconds;
}
BENCHMARK(BM_TrainSweepHbmAgainstNewmark)
    ->Args({8, 9})
    ->Args({8, 5})
    ->ArgNames({"newmark_points", "steady_tolerance_exp"})
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

/// This thread's CPU time [s]: on the shared machine the wall clock of a millisecond section
/// counts other processes' time slices, its CPU time does not.
double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Stability cost per point against the point's Newton solve (issue 17: stability at most 2x the
// Newton solve; issue 39: Hill's method too), on the 3-planet stage at H = 15, N = 256: at every
// 8th point of the 4–13 kHz sweep, Newton at the point's frequency from the previous point's
// solution (as a corrector starts from a predictor; includes the condensation at the new ω),
// then the monodromy and Hill's method (the classification: the resolvent projection, the
// Arnoldi run where it declines) on the converged point, and the Arnoldi run on the strip alone
// (the Hill eigenvalues: the fallback's cost). Hill takes Newton's last factors of ∂R/∂q as
// its capacitance where that step left every contact state as it was (a continuation's
// corrector factors at the same ω too). Counters: mean times per point [ms] and the
// ratios, thread CPU time beside the wall clock.
void BM_TrainStabilityCostPerPoint(benchmark::State& state) {
  const GearTrainModel model(testing::nonlinear::planetary(4e-6));
  TrainHarmonicBalance hbm(model, testing::nonlinear::planetaryHbmOptions());
  const ContinuationResult sweep =
      continueInFrequency(hbm, testing::nonlinear::planetarySweep(false));
  using Clock = std::chrono::steady_clock;
  double newton = 0.0, monodromy = 0.0, hill = 0.0;
  double newton_cpu = 0.0, monodromy_cpu = 0.0, hill_cpu = 0.0, arnoldi_cpu = 0.0;
  int points = 0, iterations = 0, operations = 0, dimension = 0, restart_free = 0, projected = 0;
  int reused = 0;
  for (auto _ : state) {
    newton = monodromy = hill = newton_cpu = monodromy_cpu = hill_cpu = arnoldi_cpu = 0.0;
    points = iterations = operations = dimension = restart_free = projected = reused = 0;
    for (std::size_t i = 8; i < sweep.points.size(); i += 8) {
      HarmonicBalancePoint p;
      p.omega = sweep.points[i].solution.omega;
      p.q = sweep.points[i - 1].solution.q;
      const double c0 = threadCpuSeconds();
      const auto t0 = Clock::now();
      hbm.solve(p);
      const auto t1 = Clock::now();
      const double c1 = threadCpuSeconds();
      if (!p.converged) continue;
      HarmonicBalancePoint h = p;
      hbm.classify(p, StabilityMethod::kMonodromy, true);
      const double c2 = threadCpuSeconds();
      const auto t2 = Clock::now();
      // The samples are the converged point's (Newton's last residual; the monodromy used them
      // too), as a continuation classifies its corrected points.
      hbm.classify(h, StabilityMethod::kHill, true);
      const auto t3 = Clock::now();
      const double c3 = threadCpuSeconds();
      const detail::TrainHillProblem problem = hbm.hillProblem(h, false);
      const double c4 = threadCpuSeconds();
      const detail::TrainHillResult r = detail::trainHillExponents(problem);
      arnoldi_cpu += threadCpuSeconds() - c4;
      newton_cpu += c1 - c0;
      monodromy_cpu += c2 - c1;
      hill_cpu += c3 - c2;
      benchmark::DoNotOptimize(h.max_floquet_real + p.max_floquet_real);
      newton += std::chrono::duration<double>(t1 - t0).count();
      monodromy += std::chrono::duration<double>(t2 - t1).count();
      hill += std::chrono::duration<double>(t3 - t2).count();
      iterations += p.iterations;
      ++points;
      // Untimed: whether the projection took the point, the Arnoldi run's applications and basis.
      const detail::TrainHillProblem current = hbm.hillProblem(h, true);
      const std::optional<detail::TrainHillResult> projection =
          detail::trainHillProjection(current);
      projected += projection.has_value();
      reused += projection && projection->reused_jacobian;
      operations += r.operations;
      dimension += r.restart_free ? r.computed : 0;
      restart_free += r.restart_free;
    }
  }
  state.counters["points"] = points;
  state.counters["newton_iterations"] = static_cast<double>(iterations) / points;
  state.counters["newton_ms"] = 1e3 * newton / points;
  state.counters["monodromy_ms"] = 1e3 * monodromy / points;
  state.counters["hill_ms"] = 1e3 * hill / points;
  state.counters["monodromy_over_newton"] = monodromy / newton;
  state.counters["hill_over_newton"] = hill / newton;
  state.counters["newton_cpu_ms"] = 1e3 * newton_cpu / points;
  state.counters["monodromy_cpu_ms"] = 1e3 * monodromy_cpu / points;
  state.counters["hill_cpu_ms"] = 1e3 * hill_cpu / points;
  state.counters["hill_over_newton_cpu"] = hill_cpu / newton_cpu;
  state.counters["monodromy_over_newton_cpu"] = monodromy_cpu / newton_cpu;
  state.counters["hill_projected_fraction"] = static_cast<double>(projected) / points;
  state.counters["hill_reused_jacobian_fraction"] = static_cast<double>(reused) / points;
  state.counters["arnoldi_cpu_ms"] = 1e3 * arnoldi_cpu / points;
  state.counters["arnoldi_over_newton_cpu"] = arnoldi_cpu / newton_cpu;
  state.counters["arnoldi_operations"] = static_cast<double>(operations) / points;
  state.counters["arnoldi_restart_free_fraction"] = static_cast<double>(restart_free) / points;
  state.counters["arnoldi_basis"] =
      restart_free > 0 ? static_cast<double>(dimension) / restart_free : 0.0;
}
BENCHMARK(BM_TrainStabilityCostPerPoint)->Iterations(1)->Unit(benchmark::kSecond);

// Hill's method below what the balance's harmonics resolve (issue 39): a 29/47 pump drive
// (system/pump_drive.h) at 1450, 1535, 1600 and 1700 rpm (700–820 Hz base), where its shafts'
// lateral modes lie beyond 15 ω₀/2, so the classification projects with 16–18 harmonics
// (TrainHarmonicBalance::classifyHill), against the Arnoldi run at H = 15 it took before, the
// monodromy and the point's Newton solve from the linear guess. Counters: mean thread CPU time
// per point [ms] and ratios.
void BM_TrainHillBelowTheResolvedFrequency(benchmark::State& state) {
  const GearTrainModel model(testing::pumpDrive());
  TrainHarmonicBalanceOptions options;
  options.harmonics = 15;
  options.samples = 256;
  TrainHarmonicBalance hbm(model, options);
  constexpr int kRepeat = 50;
  double newton = 0.0, monodromy = 0.0, hill = 0.0, arnoldi = 0.0;
  int points = 0;
  for (auto _ : state) {
    for (const double rpm : {1450.0, 1535.0, 1600.0, 1700.0}) {
      HarmonicBalancePoint p;
      p.omega = hbm.baseFrequency(rpm * std::numbers::pi / 30.0);
      p.q = hbm.startingGuess(p.omega);
      const double c0 = threadCpuSeconds();
      hbm.solve(p);
      newton += threadCpuSeconds() - c0;
      if (!p.converged) continue;
      ++points;
      const double c1 = threadCpuSeconds();
      for (int k = 0; k < kRepeat; ++k) {
        HarmonicBalancePoint h = p;
        hbm.classify(h, StabilityMethod::kMonodromy, false);
      }
      const double c2 = threadCpuSeconds();
      for (int k = 0; k < kRepeat; ++k) {
        HarmonicBalancePoint h = p;
        hbm.classify(h, StabilityMethod::kHill, false);
      }
      const double c3 = threadCpuSeconds();
      const detail::TrainHillProblem problem = hbm.hillProblem(p, false);
      const double c4 = threadCpuSeconds();
      for (int k = 0; k < kRepeat; ++k) {
        benchmark::DoNotOptimize(detail::trainHillExponents(problem).exponents.front());
      }
      arnoldi += threadCpuSeconds() - c4;
      monodromy += c2 - c1;
      hill += c3 - c2;
    }
  }
  const double per = 1e3 / (static_cast<double>(points) * kRepeat);
  state.counters["points"] = points;
  state.counters["newton_cpu_ms"] = 1e3 * newton / points;
  state.counters["monodromy_cpu_ms"] = per * monodromy;
  state.counters["hill_cpu_ms"] = per * hill;
  state.counters["arnoldi_cpu_ms"] = per * arnoldi;
  state.counters["hill_over_arnoldi"] = hill / arnoldi;
  state.counters["hill_over_monodromy"] = hill / monodromy;
}
BENCHMARK(BM_TrainHillBelowTheResolvedFrequency)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
}  // namespace geardyn
