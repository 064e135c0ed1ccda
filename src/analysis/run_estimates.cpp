/// Resource estimates of the long-running commands (see run_estimates.h). The constants are
/// per-item costs measured with a Release build on the 2-core reference machine (ns per step,
/// bytes per kept sample, including the CSV tables and summaries built from them), rounded up.

#include "geardyn/analysis/run_estimates.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "geardyn/config/rotor_config.h"
#include "geardyn/solvers/train_time.h"

namespace geardyn::analysis {
namespace {

// Measured with the Release build on the 2-core reference machine while two other builds ran
// (wall time), then rounded up:
// simulate: one Newmark step of the SDOF pair (8.2e6 steps in 1.67 s: 204 ns wall, 130 ns CPU).
constexpr double kNewmarkStepSeconds = 150e-9;
// simulate: one Dormand-Prince output point (51 200 points in 0.23 s: 4.5 us).
constexpr double kDormandPrinceOutputSeconds = 5e-6;
// simulate: one kept output sample (t, x, v, channels, time_response.csv): 490 B measured.
constexpr double kTimeSampleBytes = 600.0;
// stats: one tooth of a Monte Carlo revolution (20 000 samples × 25 teeth in 18.8 s: 38 us).
constexpr double kMonteCarloToothSeconds = 40e-6;
// stats: one Monte Carlo sample (the sample, its copies in the statistics, monte_carlo.csv):
// 640 B measured (peak RSS, 2e4 against 2e5 samples).
constexpr double kMonteCarloSampleBytes = 700.0;
// hbm: one floating-point operation of the dense linear algebra (LU, Hill's eigenproblem);
// H = 64, N = 4096: 86 ms per point measured, 170 ms estimated.
constexpr double kHbmFlopSeconds = 1e-9;
// hbm: one real FFT per sample and log2(N) [s].
constexpr double kHbmFftSecondsPerSample = 5e-9;
// hbm: Newton iterations per continuation point (typical).
constexpr double kHbmIterationsPerPoint = 5.0;
// rotor (Rao): one time sample (2.7 us measured, 2^15 against 2^18 samples) and one simulated
// second of Dormand-Prince (3.7 s for the 15 s of Table 4.1: 0.25 s).
constexpr double kRotorSampleSeconds = 3e-6;
constexpr double kRotorSecondsPerSimulatedSecond = 0.3;
// rotor (Rao): one time sample (both responses, probe records, spectra, CSV tables): 405 B.
constexpr double kRotorSampleBytes = 600.0;
// rotor (FE): one Newmark step per DOF (40 000 steps of 30 DOFs in 0.27 s with start-up).
constexpr double kFeStepSecondsPerDof = 100e-9;

// train runup: one Newmark step of a dense train per DOF² (matrix-vector products and the LU
// back-substitution dominate; a 12-DOF reducer step is about 1 us) plus the mesh updates.
constexpr double kTrainStepSecondsPerDof2 = 5e-9;
constexpr double kTrainStepSeconds = 1e-6;
// train time, sparse (flexible shafts): 36 us a step for the 270-DOF two-stage flexible example
// with two other builds running: 0.13 us per DOF, rounded up.
constexpr double kTrainSparseStepSecondsPerDof = 0.2e-6;

std::string shown(const config::Config& config, const std::string& key) {
  return fmt::format("{}", config.integer(key));
}

}  // namespace

RunEstimate estimateTimeResponse(const config::Config& config) {
  const double steps_per_period = static_cast<double>(config.integer("solver.steps_per_period"));
  const double max_periods = static_cast<double>(config.integer("solver.max_periods"));
  const double points = static_cast<double>(config.integer("solver.output_points_per_period"));
  const double kept = points * static_cast<double>(config.integer("solver.output_periods"));
  const bool newmark = config.string("solver.method") == "newmark";
  RunEstimate e;
  e.bytes = kept * kTimeSampleBytes + 2.0 * points * 2.0 * sizeof(double);
  if (newmark) {
    e.key = "solver.steps_per_period";
    e.value = shown(config, e.key);
    e.seconds = steps_per_period * max_periods * kNewmarkStepSeconds;
    e.basis = fmt::format("up to {:g} periods × {:g} Newmark steps; {:g} samples kept", max_periods,
                          steps_per_period, kept);
  } else {
    e.key = "solver.max_periods";
    e.value = shown(config, e.key);
    e.seconds = points * max_periods * kDormandPrinceOutputSeconds;
    e.basis = fmt::format("up to {:g} periods × {:g} output points; {:g} samples kept", max_periods,
                          points, kept);
  }
  if (kept * kTimeSampleBytes > 0.5 * e.bytes + 1e8) {  // memory, not time, is the issue
    e.key = "solver.output_periods";
    e.value = shown(config, e.key);
  }
  return e;
}

RunEstimate estimateMonteCarlo(const config::Config& config, int threads) {
  const double samples = static_cast<double>(config.integer("monte_carlo.samples"));
  const double teeth = static_cast<double>(config.integer("monte_carlo.teeth"));
  RunEstimate e;
  e.key = "monte_carlo.samples";
  e.value = shown(config, e.key);
  e.bytes = samples * kMonteCarloSampleBytes;
  e.seconds = samples * teeth * kMonteCarloToothSeconds / std::max(1, threads);
  e.basis = fmt::format("{:g} samples × {:g} B, {:g} teeth each on {} thread(s)", samples,
                        kMonteCarloSampleBytes, teeth, std::max(1, threads));
  return e;
}

RunEstimate estimateHarmonicBalance(const config::Config& config) {
  const double n = 2.0 * static_cast<double>(config.integer("hbm.harmonics")) + 1.0;
  const double samples = static_cast<double>(config.integer("hbm.samples"));
  const double range = std::abs(config.real("sweep.stop") - config.real("sweep.start"));
  const double sweeps = config.string("sweep.direction") == "both" ? 2.0 : 1.0;
  // The step adapts between min_step and max_step; near resonances it stays small: the initial
  // step is the typical one (the Saletti example: 426 points over 400 Hz with steps of 5 Hz).
  // Derived steps (no keys): at most range / 50, about 150 points a sweep on the examples.
  double step = range / 150.0;
  if (config.has("sweep.initial_step")) step = config.real("sweep.initial_step");
  if (config.has("sweep.max_step")) step = std::min(step, config.real("sweep.max_step"));
  const double points = sweeps * std::max(1.0, range / step);
  RunEstimate e;
  e.key = "hbm.harmonics";
  e.value = shown(config, e.key);
  // AFT sample arrays (phase, stiffness, errors, force and its derivative, FFT buffers), the
  // Jacobians (n + 1)² and Hill's complex 2n × 2n eigenproblem with its workspaces.
  e.bytes = 8.0 * 10.0 * samples + 8.0 * 4.0 * n * n + 16.0 * 3.0 * 4.0 * n * n;
  // Per Newton iteration: two real FFTs of N samples and the LU of the (n + 1)² Jacobian; per
  // point Hill's eigenproblem (~10 (2n)³ flops) when stability is asked for.
  const double iteration = kHbmFftSecondsPerSample * samples * std::log2(std::max(2.0, samples)) +
                           kHbmFlopSeconds * n * n * n / 3.0;
  const bool hill = config.string("sweep.stability_method") == "hill";
  const double stability = !config.boolean("sweep.stability") ? 0.0
                           : hill ? kHbmFlopSeconds * 10.0 * 8.0 * n * n * n
                                  : kHbmFlopSeconds * 100.0 * samples;
  e.seconds = points * (kHbmIterationsPerPoint * iteration + stability);
  e.basis = fmt::format(
      "about {:g} points (range / step) of {:g} Newton iterations with 2H+1 = {:g} "
      "unknowns and N = {:g} samples",
      points, kHbmIterationsPerPoint, n, samples);
  return e;
}

RunEstimate estimateRotorTime(const config::Config& config) {
  RunEstimate e;
  if (!config.boolean("time.enabled")) return e;
  const double samples = static_cast<double>(
      config::rotorTimeSamples(config, config::lateralRotorSpecFromConfig(config)));
  e.key = "time.samples";
  e.value = config.has(e.key)
                ? shown(config, e.key)
                : fmt::format("{:g} (derived from the highest mesh harmonic)", samples);
  e.bytes = samples * kRotorSampleBytes;
  e.seconds = samples * kRotorSampleSeconds +
              config.real("time.duration") * kRotorSecondsPerSimulatedSecond;
  e.basis = fmt::format("{:g} samples × {:g} B", samples, kRotorSampleBytes);
  return e;
}

RunEstimate estimateFeRotorTime(const config::Config& config, int dofs) {
  const double steps = std::ceil(config.real("time.duration") / config.real("time.time_step"));
  const double channels = 16.0;  // default channels; spectra use every step
  RunEstimate e;
  e.key = "time.time_step";
  e.value = fmt::format("{:g} s", config.real("time.time_step"));
  e.bytes = steps * (4.0 + 3.0 * channels) * 8.0 * 2.0;
  e.seconds = steps * dofs * kFeStepSecondsPerDof;
  e.basis =
      fmt::format("{:g} Newmark steps (time.duration / time.time_step) × {} DOFs", steps, dofs);
  return e;
}

RunEstimate estimateTrainRunUp(double steps, int dofs, int channels, int meshes,
                               const std::string& key, const std::string& value) {
  RunEstimate e;
  e.key = key;
  e.value = value;
  // Per kept sample: t, speed, angle, the mesh forces and channels, and the copy of the
  // channels the order tracking reads.
  e.bytes = (steps + 1.0) * (3.0 + meshes + 2.0 * channels) * 8.0;
  const double n = static_cast<double>(dofs);
  e.seconds = steps * (kTrainStepSeconds + kTrainStepSecondsPerDof2 * n * n);
  e.basis = fmt::format("{:g} Newmark steps of {} DOFs, every step kept for {} channel(s)", steps,
                        dofs, channels + meshes);
  return e;
}

RunEstimate estimateTrainTime(double steps, int dofs, double recorded, bool rates, int meshes,
                              const std::string& key, const std::string& value) {
  RunEstimate e;
  e.key = key;
  e.value = value;
  const double n = static_cast<double>(dofs);
  // Per kept step: t, q (q̇, q̈), the mesh forces, and the table and comparison built from them.
  e.bytes = recorded * ((rates ? 3.0 : 1.0) * n + 2.0 * meshes + 1.0) * 8.0 * 2.0;
  // Flexible trains step with sparse matrices (train_time.h): linear in the DOFs.
  e.seconds =
      steps * (kTrainStepSeconds + (dofs >= kSparseTrainDofs ? kTrainSparseStepSecondsPerDof * n
                                                             : kTrainStepSecondsPerDof2 * n * n));
  e.basis = fmt::format("{:g} Newmark steps of {} DOFs, {:g} kept", steps, dofs, recorded);
  return e;
}

RunEstimate estimateStage(const std::string& stage, long long size, const config::Config& config) {
  if (stage == "simulate" || stage == "stats_time") return estimateTimeResponse(config);
  if (stage == "hbm") return estimateHarmonicBalance(config);
  if (stage == "rotor_time") return estimateRotorTime(config);
  if (stage == "rotor_fe_time") return estimateFeRotorTime(config, static_cast<int>(size));
  if (stage == "stats_monte_carlo") return estimateMonteCarlo(config, static_cast<int>(size));
  return {};
}

RunEstimate estimateCommand(const std::string& command, const config::Config& config) {
  if (command == "simulate") return estimateTimeResponse(config);
  if (command == "stats" && config.string("stats.source") == "model" &&
      config.integer("monte_carlo.samples") > 0)
    return estimateMonteCarlo(config, 1);
  if (command == "hbm") return estimateHarmonicBalance(config);
  if (command == "rotor" && !config.resolved().contains("model")) return estimateRotorTime(config);
  return {};
}

}  // namespace geardyn::analysis
