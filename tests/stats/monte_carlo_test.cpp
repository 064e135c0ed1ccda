// Monte Carlo of the mean excitation ratio: reproducibility across thread counts, the
// deterministic limit, and the spread a per-tooth pitch error must produce.
#include "geardyn/stats/monte_carlo.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <thread>

#include "geardyn/stiffness/fourier_stiffness.h"
#include "support/numeric_assertions.h"
#include "support/reference_pairs.h"

namespace geardyn {
namespace {

GearPairModel model() {
  return GearPairModel(testing::issue4ExampleSpec());
}

/// A Monte Carlo of `samples` revolutions of 7 teeth with a 5 % tooth stiffness scatter.
MonteCarloOptions scatteredStiffness(int samples, int threads) {
  MonteCarloOptions o;
  o.samples = samples;
  o.teeth = 7;
  o.stiffness_std = 0.05;
  o.baseload = 1418.4;
  o.threads = threads;
  return o;
}

TEST(MonteCarlo, BitIdenticalWhateverTheThreads) {
  const GearPairModel m = model();
  MonteCarloOptions o = scatteredStiffness(101, 1);
  o.seed = 42;
  o.pitch_error_std = 1e-6;
  o.profile_error_std = 1e-6;
  const auto one = runMeanExcitationMonteCarlo(m, o);
  o.threads = 2;
  const auto two = runMeanExcitationMonteCarlo(m, o);
  o.threads = 5;
  const auto five = runMeanExcitationMonteCarlo(m, o);
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].ratio, two[i].ratio) << i;  // bit for bit
    EXPECT_EQ(one[i].ratio, five[i].ratio) << i;
    EXPECT_EQ(one[i].phase, five[i].phase) << i;
  }
  o.seed = 43;
  EXPECT_NE(runMeanExcitationMonteCarlo(m, o)[0].ratio, one[0].ratio);
}

// An interrupted run (Python's Ctrl-C: the progress callback throws on the calling thread)
// stops every worker and leaves promptly, not after the last sample.
TEST(MonteCarlo, ProgressRunsOnTheCallingThreadAndAThrowStopsTheWorkers) {
  const GearPairModel m = model();
  MonteCarloOptions o = scatteredStiffness(4000, 4);
  const std::thread::id caller = std::this_thread::get_id();
  int calls = 0;
  bool other_thread = false;
  o.progress = [&](double done, double) {
    other_thread = other_thread || std::this_thread::get_id() != caller;
    if (++calls == 5) throw std::runtime_error("interrupted at " + std::to_string(done));
  };
  EXPECT_THROW(runMeanExcitationMonteCarlo(m, o), std::runtime_error);
  EXPECT_FALSE(other_thread);
  EXPECT_EQ(calls, 5);  // the calling thread's chunk stopped at the throw
  calls = 0;
  o.progress = [&](double, double) { ++calls; };
  o.samples = 8;
  runMeanExcitationMonteCarlo(m, o);
  EXPECT_EQ(calls, 2);  // the caller's chunk: samples 0 and 1 of 8 on 4 threads
}

TEST(MonteCarlo, WithoutRandomnessEverySampleIsTheDeterministicRatio) {
  const GearPairModel m = model();
  MonteCarloOptions o;
  o.samples = 5;
  o.teeth = 3;
  o.random_phase = false;
  o.baseload = 1418.4;
  const double deterministic = meanExcitationFromModel(m, 1418.4).ratio;
  for (const auto& s : runMeanExcitationMonteCarlo(m, o))
    EXPECT_CLOSE(s.ratio, deterministic, 1e-12);
}

TEST(MonteCarlo, PitchErrorsSpreadTheRatioAsTheirMeanDoes) {
  // Pitch errors p_j shift e_f by p_j / x₀ in period j, so L_d moves by the revolution mean of
  // p_j/x₀ (weighted by k, whose period mean is 1): std(R) = σ / (x₀ √z) / a. With σ = 1 µm,
  // x₀ = F/K̄ = 3.117 µm, z = 25, a = 1: 0.0642. 4000 samples estimate a std to ±2.2 % (1σ);
  // 8 % is a 3.6σ band.
  const GearPairModel m = model();
  MonteCarloOptions o;
  o.samples = 4000;
  o.teeth = 25;
  o.random_phase = false;
  o.pitch_error_std = 1e-6;
  o.baseload = 1418.4;
  o.threads = 2;
  std::vector<double> ratios;
  for (const auto& s : runMeanExcitationMonteCarlo(m, o)) ratios.push_back(s.ratio);
  const Distribution d = describe(ratios);
  const double x0 = 1418.4 / 4.55e8;
  EXPECT_NEAR(d.std, 1e-6 / (x0 * 5.0), 0.08 * 1e-6 / (x0 * 5.0));
  EXPECT_NEAR(d.mean, meanExcitationFromModel(m, 1418.4).ratio, 4 * d.std / std::sqrt(4000.0));
  EXPECT_LT(d.q05, d.q50);
  EXPECT_LT(d.q50, d.q95);
}

TEST(MonteCarlo, DescribeQuantiles) {
  const Distribution d = describe({4, 1, 3, 2, 5});
  EXPECT_EQ(d.mean, 3.0);
  EXPECT_EQ(d.q50, 3.0);
  EXPECT_CLOSE(d.q05, 1.2, 1e-15);
  EXPECT_CLOSE(d.q95, 4.8, 1e-15);
  EXPECT_CLOSE(d.std, std::sqrt(2.5), 1e-15);
}

}  // namespace
}  // namespace geardyn
