#pragma once
/// \file
/// The comparison of the train harmonic balance with nonlinear Newmark at given frequencies
/// (issue 17), on the trains of nonlinear_sample_trains.h.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "geardyn/solvers/continuation.h"
#include "geardyn/solvers/harmonic_balance.h"
#include "geardyn/solvers/train_harmonic_balance.h"
#include "geardyn/solvers/train_nonlinear_time.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "geardyn/system/gear_pair_model.h"
#include "system/nonlinear_sample_trains.h"

namespace geardyn::testing::nonlinear {

/// ∂R/∂u and ∂R/∂ω₀ of the train harmonic balance at (u, ω₀) against central differences
/// (steps 1e-12 in u, 1e-6 ω₀ in ω₀): every column within 1e-5 of its norm (or of 1). At states
/// whose samples are off the contact kinks the differences are exact to round-off (piecewise
/// linear meshes) or to O(h²) (the smooth clearance law beyond contact).
inline void expectJacobianMatchesCentralDifferences(TrainHarmonicBalance& hbm,
                                                    const Eigen::VectorXd& u, double omega,
                                                    const std::string& label = "") {
  Eigen::VectorXd r, dw, rp, rm;
  Eigen::MatrixXd J;
  hbm.residual(u, omega, r, &J, &dw);
  const double step = 1e-12;
  for (int c = 0; c < hbm.size(); ++c) {
    Eigen::VectorXd up = u, um = u;
    up[c] += step;
    um[c] -= step;
    hbm.residual(up, omega, rp, nullptr, nullptr);
    hbm.residual(um, omega, rm, nullptr, nullptr);
    const Eigen::VectorXd fd = (rp - rm) / (2 * step);
    EXPECT_LT((J.col(c) - fd).norm(), 1e-5 * std::max(1.0, J.col(c).norm())) << label << c;
  }
  const double h = 1e-6 * omega;
  hbm.residual(u, omega + h, rp, nullptr, nullptr);
  hbm.residual(u, omega - h, rm, nullptr, nullptr);
  EXPECT_LT((dw - (rp - rm) / (2 * h)).norm(), 1e-5 * dw.norm()) << label;
}

/// The periodic solution at base frequency ω [rad/s] by Newton from the closed-contact guess
/// (point.converged says whether it was found).
inline HarmonicBalancePoint solvedFromTheLinearGuess(TrainHarmonicBalance& hbm, double omega) {
  HarmonicBalancePoint p;
  p.omega = omega;
  p.q = hbm.startingGuess(omega);
  hbm.solve(p);
  return p;
}

/// Continuation in the base (mesh) frequency from `from` to `to` [Hz], without stability, the
/// steps derived for ζ = 0.05 (deriveContinuationSteps).
inline ContinuationResult sweepUp(TrainHarmonicBalance& hbm, double from, double to) {
  ContinuationOptions c;
  c.start = 2 * std::numbers::pi * from;
  c.stop = 2 * std::numbers::pi * to;
  c.stability = false;
  deriveContinuationSteps(c, 0.0, 0.05, hbm.harmonics());
  return continueInFrequency(hbm, c);
}

/// The largest difference between the real Fourier coefficients X of every DOF (column 0 the
/// mean, 2h − 1 and 2h cos and sin) and TrainSteadySolver's complex ones, h = 0..H.
inline double linearSteadyStateDifference(const Eigen::MatrixXd& X, const TrainSteadyState& linear,
                                          int harmonics) {
  double worst = 0.0;
  for (int h = 0; h <= harmonics; ++h) {
    // TrainSteadyState: q = Re[X₀ + 2 Σ X_h e^{ihτ}] → cos = 2 Re X_h, sin = −2 Im X_h.
    const Eigen::VectorXd c = h == 0 ? linear.harmonic.col(0).real()
                                     : Eigen::VectorXd(2.0 * linear.harmonic.col(h).real());
    worst = std::max(worst, (X.col(h == 0 ? 0 : 2 * h - 1) - c).norm());
    if (h > 0) {
      worst = std::max(worst, (X.col(2 * h) + 2.0 * linear.harmonic.col(h).imag()).norm());
    }
  }
  return worst;
}

/// The 1-DOF gear pair of a single-mesh torsional train: its mesh's m_e, c, k(φ) and e(φ), the
/// mean force `mean_force` [N]; the contact law (or elements) is the caller's.
inline GearPairModelSpec sdofOfSingleMesh(const GearTrainModel& train, double mean_force) {
  const TrainMesh& m = train.meshes()[0];
  GearPairModelSpec sdof;
  sdof.mass = m.equivalent_mass;
  sdof.damping = m.damping;
  sdof.mean_force = mean_force;
  sdof.stiffness = m.stiffness;
  sdof.transmission_error = m.transmission_error;
  sdof.mesh_frequency = 1000.0;  // the balance works in ω; any f_m
  return sdof;
}

/// The 1-DOF gear pair that one pair with torsional DOFs and backlash j reduces to (issue 17):
/// half clearance b = j/2 (its deflection x = δ + b), mass m_e, mean force T/r_b1, the same c, k
/// and e.
inline GearPairModelSpec reducedPair(const GearTrainModel& train, double j) {
  const TrainMesh& m = train.meshes()[0];
  GearPairModelSpec sdof =
      sdofOfSingleMesh(train, train.spec().operating.input_torque / m.base_radius_a);
  sdof.contact = ContactLaw::kBacklash;
  sdof.backlash = 0.5 * j;
  return sdof;
}

/// The 1-DOF balance of the reduction tests: H = 15, N = 256 (the train's defaults), 1e-12.
inline HarmonicBalanceOptions sdofReductionOptions() {
  HarmonicBalanceOptions o;
  o.harmonics = 15;
  o.samples_per_period = 256;
  o.tolerance = 1e-12;
  return o;
}

struct ReductionCheck {
  int compared = 0, separated = 0;
  double worst = 0.0;     ///< largest ‖q_1DOF − q_train‖ / ‖q_train‖
  double residual = 0.0;  ///< largest relative 1-DOF residual at the train's solutions
};

/// Every `stride`th point of a single-mesh train's sweep refined by the train balance: the
/// 1-DOF residual at its solution (the mean shifted by `shift` [m]: the 1-DOF deflection's
/// origin), and the 1-DOF Newton started 1e-6 (relative) away from it; `separated(d)` says
/// whether the sampled mesh deflections d lose contact somewhere.
inline ReductionCheck compareWithSdof(
    TrainHarmonicBalance& hbm, HarmonicBalance& reference, const ContinuationResult& sweep,
    std::size_t stride, double shift,
    const std::function<bool(const Eigen::MatrixXd&)>& separated) {
  ReductionCheck out;
  for (std::size_t i = 0; i < sweep.points.size(); i += stride) {
    HarmonicBalancePoint point = sweep.points[i].solution;
    hbm.solve(point);
    EXPECT_TRUE(point.converged) << point.residual;
    out.separated += separated(hbm.meshDeflections(point.q));
    HarmonicBalancePoint same = point;
    same.q[0] += shift;
    const Eigen::VectorXd expected = same.q;
    Eigen::VectorXd r;
    reference.residual(expected, point.omega, r, nullptr, nullptr);
    out.residual = std::max(out.residual, reference.residualNorm(expected, r, point.omega));
    same.q += 1e-6 * expected.norm() * Eigen::VectorXd::Ones(expected.size()) /
              std::sqrt(static_cast<double>(expected.size()));
    reference.solve(same);
    EXPECT_TRUE(same.converged);
    out.worst = std::max(out.worst, (same.q - expected).norm() / expected.norm());
    ++out.compared;
  }
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", out.worst);
  ::testing::Test::RecordProperty("worst_relative_difference", text);
  std::snprintf(text, sizeof text, "%.3g", out.residual);
  ::testing::Test::RecordProperty("worst_sdof_residual", text);
  return out;
}

/// A sweep of a single-mesh train from `from` to `to` times its mesh's natural frequency
/// ω_n = √(k̄/m_e) [rad/s], steps derived from ω_n, its damping ratio and H.
inline ContinuationOptions meshResonanceSweep(const TrainMesh& m, double from, double to,
                                              int harmonics, bool stability) {
  const double wn = std::sqrt(m.mean_stiffness / m.equivalent_mass);
  ContinuationOptions sweep;
  sweep.start = from * wn;
  sweep.stop = to * wn;
  sweep.stability = stability;
  deriveContinuationSteps(sweep, wn, m.damping_ratio, harmonics);
  return sweep;
}

/// A single-mesh train, the 1-DOF pair it reduces to (`sdof`), both balances (the 1-DOF one with
/// sdofReductionOptions(), the train's with its defaults H = 15, N = 256 at tolerance 1e-12)
/// and the train's sweep without stability from `from` to `to` times its mesh's natural
/// frequency (meshResonanceSweep).
struct ReductionPair {
  GearPairModel pair;
  HarmonicBalance reference;
  TrainHarmonicBalance hbm;
  ContinuationResult sweep;
  ReductionPair(const GearTrainModel& train, const GearPairModelSpec& sdof, double from, double to)
      : pair(sdof),
        reference(pair, sdofReductionOptions()),
        hbm(train, trainReductionOptions()),
        sweep(continueInFrequency(
            hbm, meshResonanceSweep(train.meshes()[0], from, to, hbm.harmonics(), false))) {}
  static TrainHarmonicBalanceOptions trainReductionOptions() {
    TrainHarmonicBalanceOptions options;
    options.tolerance = 1e-12;
    return options;
  }
};

/// Base-frequency sweep [Hz] with steps of at most 1/100 of the range, the rest derived
/// (ζ = 0.05), without stability.
inline ContinuationOptions baseSweep(double start_hz, double stop_hz, int harmonics) {
  ContinuationOptions c;
  c.start = 2 * std::numbers::pi * start_hz;
  c.stop = 2 * std::numbers::pi * stop_hz;
  c.stability = false;
  c.max_step = (c.stop - c.start) / 100;
  deriveContinuationSteps(c, 0.0, 0.05, harmonics);
  return c;
}

struct NewmarkCheck {
  int stable = 0, unstable = 0, contact_loss = 0;
  int frequencies = 0;  ///< frequencies with at least one stable solution confirmed
  double worst = 0.0;   ///< largest |p2p_newmark / p2p_hbm − 1| over meshes and solutions
};

/// At each ω: every solution on the sweep there (solved from the neighbours), its stability,
/// and Newmark started from it (unstable ones perturbed by 1e-3 of their p2p on mesh 0 and run
/// for at least 400 common periods: a multiplier of 1.02 grows that 2700-fold): stable ones must
/// persist (p2p of every mesh deflection within 1 %), unstable ones must be left (some mesh's
/// p2p changes by > 5 %).
inline NewmarkCheck checkAgainstNewmark(const GearTrainModel& model, TrainHarmonicBalance& hbm,
                                        const ContinuationResult& sweep,
                                        const std::vector<double>& omegas) {
  NewmarkCheck out;
  TrainNonlinearTimeOptions newmark;
  newmark.steps_per_mesh_period = 256;
  newmark.steady_tolerance = 1e-7;
  for (double omega : omegas) {
    bool confirmed = false;
    for (HarmonicBalancePoint p : solutionsAtFrequency(hbm, {&sweep}, omega)) {
      const Eigen::MatrixXd d = hbm.meshDeflections(p.q);
      const double p2p0 = d.col(0).maxCoeff() - d.col(0).minCoeff();
      hbm.classify(p, StabilityMethod::kMonodromy, false);
      auto [q0, v0] = hbm.initialState(p);
      const Eigen::VectorXd v_mesh = model.meshVector(0);
      if (!p.stable) q0 += 1e-3 * p2p0 * v_mesh / v_mesh.squaredNorm();
      newmark.min_periods = p.stable ? 3 : 400;
      const TrainNonlinearTimeResponse r =
          solveTrainNonlinearTime(model, hbm.inputSpeed(omega), newmark, q0, v0);
      if (p.stable) EXPECT_EQ(r.status, "steady_state") << omega << ": " << r.message;
      double change = 0.0;
      bool open = false;
      for (int m = 0; m < hbm.meshCount(); ++m) {
        const double p2p = d.col(m).maxCoeff() - d.col(m).minCoeff();
        change = std::max(change, std::abs(r.meshPeakToPeak(m) / p2p - 1.0));
        const TrainMesh& mesh = model.meshes()[m];
        for (int k = 0; k < d.rows(); ++k) {
          const double phase = mesh.phase + hbm.meshMultiples()[m] * k / double(d.rows());
          open = open || d(k, m) < mesh.transmission_error.value(phase);
        }
      }
      if (p.stable) {
        ++out.stable;
        confirmed = confirmed || change < 0.01;
        out.contact_loss += open;
        out.worst = std::max(out.worst, change);
        EXPECT_LT(change, 0.01) << "stable solution at " << omega / (2 * std::numbers::pi)
                                << " Hz, p2p " << p2p0;
      } else {
        ++out.unstable;
        EXPECT_GT(change, 0.05) << "unstable solution at " << omega / (2 * std::numbers::pi)
                                << " Hz kept by Newmark, multiplier " << p.critical_multiplier;
      }
    }
    out.frequencies += confirmed;
  }
  return out;
}

}  // namespace geardyn::testing::nonlinear
