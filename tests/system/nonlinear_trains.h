#pragma once
/// \file
/// The comparison of the train harmonic balance with nonlinear Newmark at given frequencies
/// (issue 17), on the trains of nonlinear_sample_trains.h.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "geardyn/solvers/continuation.h"
#include "geardyn/solvers/train_harmonic_balance.h"
#include "geardyn/solvers/train_nonlinear_time.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "system/nonlinear_sample_trains.h"

namespace geardyn::testing::nonlinear {

struct NewmarkCheck {
  int stable = 0, unstable = 0, contact_loss = 0;
  double worst = 0.0;  ///< largest |p2p_newmark / p2p_hbm − 1| over meshes and solutions
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
  }
  return out;
}

}  // namespace geardyn::testing::nonlinear
