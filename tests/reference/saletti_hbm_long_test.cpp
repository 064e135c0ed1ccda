// Label long: Saletti, Battiato & Zucca (2025), Table 1 at T = 100, 200 and 300 N m, H = 14,
// 500–3500 Hz. Harmonic balance (continued up and down through every fold) against Newmark
// time integration swept up and down, each point starting from the previous state: peak to
// peak within 1 % on the stable branches at >= 20 frequencies including 1250, 1850, 3250 Hz,
// and the jump frequencies within 1 % of the folds. Prints the timings of both methods.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "geardyn/solvers/harmonic_balance.h"
#include "geardyn/solvers/time_response.h"
#include "geardyn/stiffness/step_stiffness.h"
#include "support/reference_pairs.h"

namespace geardyn {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

GearPairModelSpec saletti(double torque) {
  return testing::salettiModelSpec(torque);
}
using testing::peakToPeak;

struct Branch {
  std::vector<double> f, p2p;
  std::vector<bool> stable;
  std::vector<Eigen::VectorXd> q;
};

Branch trace(HarmonicBalance& hbm, double from, double to, std::vector<double>& folds) {
  ContinuationOptions sweep;
  sweep.start = kTwoPi * from;
  sweep.stop = kTwoPi * to;
  sweep.initial_step = kTwoPi * 5;
  sweep.min_step = kTwoPi * 0.01;
  sweep.max_step = kTwoPi * 200;
  sweep.stability_method = StabilityMethod::kMonodromy;  // Hill's agreement: unit tests
  const ContinuationResult result = continueInFrequency(hbm, sweep);
  EXPECT_TRUE(result.completed) << result.message;
  Branch b;
  for (const auto& p : result.points) {
    const auto x = hbm.timeSignal(p.solution.q);
    b.f.push_back(p.solution.omega / kTwoPi);
    b.p2p.push_back(peakToPeak(x));
    b.stable.push_back(p.solution.stable);
    b.q.push_back(p.solution.q);
  }
  for (std::size_t i : result.folds) folds.push_back(b.f[i]);
  return b;
}

/// The stable HBM solutions at f: on every stable segment of the curve that brackets f, solved
/// exactly at f from the neighbours' interpolated coefficients.
std::vector<double> stableAt(HarmonicBalance& hbm, const Branch& b, double f) {
  std::vector<double> out;
  for (std::size_t i = 1; i < b.f.size(); ++i) {
    if (!b.stable[i] || !b.stable[i - 1] || (b.f[i - 1] - f) * (b.f[i] - f) > 0 ||
        b.f[i] == b.f[i - 1]) {
      continue;
    }
    HarmonicBalancePoint point;
    point.omega = kTwoPi * f;
    point.q = b.q[i - 1] + (f - b.f[i - 1]) / (b.f[i] - b.f[i - 1]) * (b.q[i] - b.q[i - 1]);
    hbm.solve(point);
    if (!point.converged) continue;
    hbm.stabilityMonodromy(point);
    if (!point.stable) continue;
    const auto x = hbm.timeSignal(point.q);
    out.push_back(peakToPeak(x));
  }
  return out;
}

TEST(SalettiValidation, HarmonicBalanceAgainstNewmarkSweeps) {
  double hbm_seconds = 0, newmark_seconds = 0;
  for (double torque : {100.0, 200.0, 300.0}) {
    GearPairModelSpec spec = saletti(torque);
    const GearPairModel model(spec);
    HarmonicBalanceOptions options;
    options.harmonics = 14;
    options.samples_per_period = 256;
    HarmonicBalance hbm(model, options);
    std::vector<double> folds_up, folds_down;
    const auto t0 = std::chrono::steady_clock::now();
    const Branch up = trace(hbm, 500, 3500, folds_up);
    const Branch down = trace(hbm, 3500, 500, folds_down);
    hbm_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    // Newmark sweeps: 25 Hz grid, 5 Hz within 60 Hz of every fold.
    std::vector<double> grid;
    for (double f = 500; f <= 3500 + 1e-9; f += 25) grid.push_back(f);
    for (double fold : folds_up) {
      for (double f = fold - 60; f <= fold + 60; f += 5) grid.push_back(std::round(f));
    }
    for (double f : {1250.0, 1850.0, 3250.0}) grid.push_back(f);
    std::sort(grid.begin(), grid.end());
    grid.erase(std::unique(grid.begin(), grid.end()), grid.end());

    for (const bool upward : {true, false}) {
      std::vector<double> frequencies = grid;
      if (!upward) std::reverse(frequencies.begin(), frequencies.end());
      TimeResponseOptions newmark;
      newmark.steps_per_period = 1024;
      newmark.output_points_per_period = 256;
      newmark.steady_tolerance = 1e-7;
      newmark.max_periods = 6000;
      newmark.output_periods = 1;
      std::vector<double> p2p(frequencies.size(), NAN);
      const auto t1 = std::chrono::steady_clock::now();
      int agree = 0, compared = 0;
      bool key[3] = {false, false, false};
      for (std::size_t i = 0; i < frequencies.size(); ++i) {
        spec.mesh_frequency = frequencies[i];
        const GearPairModel at(spec);
        const TimeResponse r = solveTimeResponse(at, newmark);
        newmark.start_from_static = false;  // the next point starts from this state
        newmark.initial_displacement = r.x.back();
        newmark.initial_velocity = r.v.back();
        if (!r.converged()) continue;
        p2p[i] = peakToPeak(r.x);
        const auto candidates = stableAt(hbm, upward ? up : down, frequencies[i]);
        if (candidates.empty()) continue;
        double best = candidates[0];
        for (double c : candidates) {
          if (std::abs(c - p2p[i]) < std::abs(best - p2p[i])) best = c;
        }
        ++compared;
        const bool ok = std::abs(best / p2p[i] - 1) < 0.01;
        agree += ok;
        for (int k = 0; k < 3; ++k) {
          if (frequencies[i] == std::array{1250.0, 1850.0, 3250.0}[k]) key[k] = ok;
        }
      }
      newmark_seconds +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
      EXPECT_GE(agree, 20) << torque << (upward ? " up" : " down");
      EXPECT_GE(agree, compared * 95 / 100)
          << torque << (upward ? " up" : " down") << ": " << agree << "/" << compared;
      EXPECT_TRUE(key[0] && key[1] && key[2]) << torque << (upward ? " up" : " down");
      // Jumps: the largest relative change of p2p between neighbouring frequencies near each
      // fold of the primary resonance, against the fold the sweep direction meets.
      const double fold = upward ? *std::max_element(folds_up.begin(), folds_up.end()) : [&] {
        double f = 0;
        for (double v : folds_down) {
          if (v > 1400 && (f == 0 || v < f)) f = v;
        }
        return f;
      }();
      double jump = 0, biggest = 0;
      for (std::size_t i = 1; i < frequencies.size(); ++i) {
        if (std::isnan(p2p[i]) || std::isnan(p2p[i - 1]) || std::abs(frequencies[i] - fold) > 80)
          continue;
        const double change = std::abs(std::log(p2p[i] / p2p[i - 1]));
        if (change > biggest) {
          biggest = change;
          jump = 0.5 * (frequencies[i] + frequencies[i - 1]);
        }
      }
      EXPECT_NEAR(jump / fold, 1.0, 0.01)
          << torque << (upward ? " up" : " down") << ": jump " << jump << ", fold " << fold;
      std::printf(
          "T = %3.0f N m, %s: %d of %d Newmark points within 1 %%; jump at %.1f Hz, fold at %.1f "
          "Hz\n",
          torque, upward ? "up  " : "down", agree, compared, jump, fold);
    }
  }
  std::printf(
      "harmonic balance (both sweeps, 3 torques): %.2f s; Newmark sweeps: %.2f s; ratio %.0f\n",
      hbm_seconds, newmark_seconds, newmark_seconds / hbm_seconds);
}

TEST(SalettiValidation, TimeIntegrationLeavesAnUnstableSolution) {
  GearPairModelSpec spec = saletti(100.0);
  spec.mesh_frequency = 1850.0;
  const GearPairModel model(spec);
  HarmonicBalanceOptions options;
  HarmonicBalance hbm(model, options);
  std::vector<double> folds;
  const Branch b = trace(hbm, 3500, 1500, folds);
  // The unstable branch's point at 1850 Hz: rebuild it by solving from the interpolated sweep.
  ContinuationOptions sweep;
  sweep.start = kTwoPi * 3500;
  sweep.stop = kTwoPi * 1500;
  sweep.initial_step = kTwoPi * 5;
  sweep.min_step = kTwoPi * 0.01;
  sweep.max_step = kTwoPi * 40;
  const ContinuationResult result = continueInFrequency(hbm, sweep);
  const HarmonicBalancePoint* unstable = nullptr;
  for (std::size_t i = 1; i < result.points.size(); ++i) {
    const auto& p = result.points[i].solution;
    const auto& q = result.points[i - 1].solution;
    if (!p.stable && !q.stable && (p.omega - kTwoPi * 1850) * (q.omega - kTwoPi * 1850) <= 0)
      unstable = &p;
  }
  ASSERT_NE(unstable, nullptr);
  const auto x = hbm.timeSignal(unstable->q);
  const double p2p_unstable = peakToPeak(x);
  // Start on it: x(0) and v(0) = Σ h ω b_h.
  double v0 = 0;
  for (int h = 1; h <= hbm.harmonics(); ++h) v0 += h * unstable->omega * unstable->q[2 * h];
  spec.mesh_frequency = unstable->omega / kTwoPi;
  TimeResponseOptions newmark;
  newmark.steps_per_period = 1024;
  newmark.start_from_static = false;
  newmark.initial_displacement = x[0];
  newmark.initial_velocity = v0;
  newmark.max_periods = 6000;
  const TimeResponse r = solveTimeResponse(GearPairModel(spec), newmark);
  ASSERT_TRUE(r.converged());
  const double p2p = peakToPeak(r.x);
  EXPECT_GT(std::abs(p2p / p2p_unstable - 1), 0.05) << p2p << " vs unstable " << p2p_unstable;
  (void)b;
}

}  // namespace
}  // namespace geardyn
