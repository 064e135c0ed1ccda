#pragma once
/// \file
/// Gear trains with nonlinear meshes built in code for the tests of issue 17 (the fixtures of
/// sample_trains.h with damping, errors, a smooth k and backlash), and the comparison of the
/// train harmonic balance with nonlinear Newmark at given frequencies.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <utility>
#include <vector>

#include "geardyn/solvers/continuation.h"
#include "geardyn/solvers/train_harmonic_balance.h"
#include "geardyn/solvers/train_nonlinear_time.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "system/sample_trains.h"

namespace geardyn::testing::nonlinear {

inline std::shared_ptr<const MeshStiffness> smooth(double mean, double phase_deg) {
  return std::make_shared<FourierMeshStiffness>(mean, std::vector<double>{0.12, 0.05, 0.02},
                                                std::vector<double>{phase_deg * kDeg, 0.3, 1.1},
                                                1.6);
}

inline TrainMeshContact backlash(double j) {
  return {ContactLaw::kBacklash, j};
}

/// One external pair with torsional DOFs (as in train_response_test's reduction), backlash j.
inline GearTrainSpec singlePair(double j) {
  GearTrainSpec spec;
  spec.dofs = TrainDofs::kTorsional;
  spec.shafts = {{"pinion_shaft", 0.0, 2e-3, {}, {}, {}, 7850.0},
                 {"gear_shaft", 0.0, 9e-3, {}, {}, {}, 7850.0}};
  spec.gears = {{"pinion", "pinion_shaft", spurGear(25, 3e-3, 20.0, 0.02), false, false},
                {"gear", "gear_shaft", spurGear(53, 3e-3, 20.0, 0.02), false, false}};
  TrainMeshSpec mesh{"pair", "pinion", "gear",      0.0, std::nullopt, smooth(3e8, 20.0),
                     {},     0.05,     std::nullopt};
  mesh.transmission_error.addFourier({6e-6, 2e-6}, {0.2, -0.4});
  mesh.contact = backlash(j);
  spec.meshes = {mesh};
  spec.operating = {"pinion_shaft", 2100.0 * std::numbers::pi / 30.0, 40.0, "gear_shaft"};
  return spec;
}

/// The Lin & Parker stage with 3 planets, damped, loaded, smooth k and errors, backlash j at
/// all 6 meshes.
inline GearTrainSpec planetary(double j) {
  GearTrainSpec spec = linParker1999(3);
  auto& st = spec.stages[0];
  st.sun_planet_stiffness = smooth(5e8, 0.0);
  st.ring_planet_stiffness = smooth(5e8, 70.0);
  st.sun_planet_damping_ratio = st.ring_planet_damping_ratio = 0.05;
  st.sun_planet_error.addFourier({3e-6}, {0.0});
  st.ring_planet_error.addFourier({2e-6}, {0.8});
  st.sun_planet_contact = st.ring_planet_contact = backlash(j);
  spec.bearings[0].cyy = spec.bearings[0].czz = 2e3;
  spec.bearings[2].cyy = spec.bearings[2].czz = 2e3;
  st.pin_damping = 2e3;
  spec.bearings[1].c_torsion = 50.0;
  spec.operating.input_torque = 100.0;
  spec.operating.input_speed = 300.0;
  // The classic lumped model: with the carrier-frame terms the train's rolling mode gets a
  // negative stiffness at speed (K + Ω²K_Ω has an eigenvalue −1e3 against 5e9: a static
  // divergence of the rolling mode, growth e^{31.7 t}); see the report of issue 17.
  st.carrier_frame_terms = false;
  return spec;
}

/// The two-stage reducer (planar, 4 shafts, 6 bearings, a coupling) with smooth k, transmission
/// errors at both meshes and backlash j at both; the mesh frequencies are 3:1 (common period:
/// three stage-1 mesh periods).
inline GearTrainSpec twoStage(double j) {
  GearTrainSpec spec = twoStageReducer(smooth(4e8, 0.0), smooth(6e8, 40.0));
  spec.meshes[0].transmission_error.addFourier({8e-6, 2e-6}, {0.0, 0.5});
  spec.meshes[1].transmission_error.addFourier({6e-6}, {0.3});
  spec.meshes[0].contact = spec.meshes[1].contact = backlash(j);
  return spec;
}

/// The state (q, q̇) at t = 0 of a periodic solution from its recovered coefficients.
inline std::pair<Eigen::VectorXd, Eigen::VectorXd> initialState(TrainHarmonicBalance& hbm,
                                                                const HarmonicBalancePoint& p) {
  const Eigen::MatrixXd X = hbm.displacementCoefficients(p);
  Eigen::VectorXd q = X.col(0), v = Eigen::VectorXd::Zero(X.rows());
  for (int h = 1; h <= hbm.harmonics(); ++h) {
    q += X.col(2 * h - 1);
    v += h * p.omega * X.col(2 * h);
  }
  return {q, v};
}

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
    std::vector<double> seen;
    for (std::size_t i = 1; i < sweep.points.size(); ++i) {
      const auto& a = sweep.points[i - 1].solution;
      const auto& b = sweep.points[i].solution;
      if ((a.omega - omega) * (b.omega - omega) > 0.0) continue;
      HarmonicBalancePoint p;
      p.omega = omega;
      p.q = a.q + (omega - a.omega) / (b.omega - a.omega) * (b.q - a.q);
      hbm.solve(p);
      if (!p.converged) continue;
      const Eigen::MatrixXd d = hbm.meshDeflections(p.q);
      const double p2p0 = d.col(0).maxCoeff() - d.col(0).minCoeff();
      bool duplicate = false;
      for (double s : seen) duplicate = duplicate || std::abs(s - p2p0) < 1e-6 * p2p0;
      if (duplicate) continue;
      seen.push_back(p2p0);
      hbm.classify(p, StabilityMethod::kMonodromy, false);
      auto [q0, v0] = initialState(hbm, p);
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
