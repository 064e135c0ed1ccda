/// Dormand–Prince for trains (train_dormand_prince.h, train_periodic_record.h):
///   - Rao's lateral rotor as the gearbox it is (config/rotor_gearbox.h) recorded from rest
///     converges to the 4-DOF closed form (solvers/rotor_response.h), component by component:
///     the general model against the special case it generalises;
///   - a train with time-varying mesh stiffness and transmission error (the two-stage reducer
///     example): Newmark from rest converges to the Dormand–Prince solution at second order;
///   - the exact reduction integrates only the loaded DOFs.

#include "geardyn/solvers/train_dormand_prince.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geardyn/config/rotor_gearbox.h"
#include "geardyn/error.h"
#include "geardyn/signal/full_spectrum.h"
#include "geardyn/solvers/rotor_response.h"
#include "geardyn/solvers/train_periodic_record.h"
#include "geardyn/solvers/train_time.h"
#include "torus/torus_newmark_comparison.h"

namespace geardyn {
namespace {

using Complex = std::complex<double>;

/// Rao's Table 4.1 rotor as its gearbox, with the probe DOFs x₁, y₁, x₂, y₂.
struct RaoGearbox {
  explicit RaoGearbox(const LateralRotorSpec& spec = raoTable41Spec())
      : rotor(spec),
        train(config::lateralRotorGearTrain(spec, "test", warnings)),
        probes(config::lateralRotorProbeDofs(train)) {}
  LateralRotorModel rotor;
  std::vector<std::string> warnings;
  GearTrainModel train;
  std::vector<int> probes;
  TrainRecord record(const TrainRecordOptions& options) const {
    return recordTrainFromRest(train, train.inputSpeed(), probes, rotor.commonPeriod(), options);
  }
};

Eigen::Vector4d row(const TrainRecord& r, long long k) {
  return r.displacement.row(static_cast<Eigen::Index>(k)).transpose();
}

TEST(TrainDormandPrince, RaoRotorConvergesToTheFourDofClosedForm) {
  // Table 4.1, the thesis's 15 s from rest: after the detected transient the gearbox's time
  // history equals the 4-DOF model's exact steady state to the integrator's tolerance (rtol
  // 1e-8 over ~2e6 steps: 1e-5 of the response bounds the accumulated error).
  const RaoGearbox rao;
  TrainRecordOptions options;  // 15 s, 2^15 samples, rtol 1e-8
  const TrainRecord r = rao.record(options);
  ASSERT_TRUE(r.converged()) << r.message;
  EXPECT_GE(r.window_periods, 3);
  EXPECT_NEAR(r.sample_rate, 32767 / 15.0, 1.0);
  const auto parts = solveRotorFrequencyResponse(rao.rotor);
  std::vector<double> times(r.t.begin() + r.window_begin, r.t.begin() + r.window_end);
  const auto exact = superposeWhirlResponse(parts, times);
  double scale = 0.0, error = 0.0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    scale = std::max(scale, exact[i].cwiseAbs().maxCoeff());
    error = std::max(error, (row(r, r.window_begin + i) - exact[i]).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(error, 1e-5 * scale);
  // The transient is detected, not guessed: before its end the history is far from the steady
  // state, after it close (steady_tolerance 1e-6 of the response, × 2 for the comparison).
  const auto at = [&](long long k) {
    return (row(r, k) - superposeWhirlResponse(parts, {r.t[k]})[0]).cwiseAbs().maxCoeff();
  };
  EXPECT_GT(at(r.transient_end / 2), 1e-4 * scale);
  EXPECT_LT(at(r.transient_end), 2e-6 * scale + 1e-5 * scale);

  // Whirl components by exact FFT bins of the steady window: within 0.5 % and 0.01 rad of the
  // frequency-domain values (the thesis's criterion; measured: far better).
  for (int shaft = 0; shaft < 2; ++shaft) {
    std::vector<double> x, y;
    for (long long k = r.window_begin; k < r.window_end; ++k) {
      x.push_back(r.displacement(k, 2 * shaft));
      y.push_back(r.displacement(k, 2 * shaft + 1));
    }
    std::vector<WhirlComponent> components;
    for (const auto& p : parts) components.push_back({p.name, p.omega / (2 * M_PI), 0.0});
    EXPECT_EQ(extractWhirlComponents(x, y, r.sample_rate, components), WhirlExtraction::kExactBins);
    const double t0 = r.t[r.window_begin];
    for (std::size_t i = 0; i < parts.size(); ++i) {
      // The window starts at t0: the exact value there is p e^{jΩ t0}.
      const Complex expected = parts[i].response(shaft) * std::polar(1.0, parts[i].omega * t0);
      const double amplitude = std::abs(expected);
      if (amplitude < 1e-12) {
        EXPECT_LT(std::abs(components[i].value), 1e-5 * scale) << parts[i].name;
        continue;
      }
      EXPECT_NEAR(std::abs(components[i].value), amplitude, 5e-3 * amplitude) << parts[i].name;
      EXPECT_LT(std::abs(std::arg(components[i].value / expected)), 0.01) << parts[i].name;
    }
  }
}

TEST(TrainDormandPrince, UnalignedGridDetectsTheTransientFromDenseOutput) {
  // The thesis's exact linspace grid (not a whole number of samples per common period): the
  // periodicity check uses the integrator's dense output at t + T_c; the least-squares peaks
  // agree with the frequency domain to 1e-6 of the largest (the integrator's tolerance).
  const RaoGearbox rao;
  TrainRecordOptions options;
  options.align_to_common_period = false;
  const TrainRecord r = rao.record(options);
  ASSERT_TRUE(r.converged()) << r.message;
  EXPECT_NEAR(r.sample_rate, 32767 / 15.0, 1e-9);
  EXPECT_NEAR(r.t[r.transient_end], 1.25, 0.05);
  std::vector<double> x, y;
  for (long long k = r.window_begin; k < r.window_end; ++k) {
    x.push_back(r.displacement(k, 0));
    y.push_back(r.displacement(k, 1));
  }
  const auto parts = solveRotorFrequencyResponse(rao.rotor);
  std::vector<WhirlComponent> components;
  for (const auto& p : parts) components.push_back({p.name, p.omega / (2 * M_PI), 0.0});
  EXPECT_EQ(extractWhirlComponents(x, y, r.sample_rate, components),
            WhirlExtraction::kLeastSquares);
  double largest = 0.0;
  for (const auto& p : parts) largest = std::max(largest, std::abs(p.response(0)));
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const Complex expected =
        parts[i].response(0) * std::polar(1.0, parts[i].omega * r.t[r.window_begin]);
    EXPECT_LT(std::abs(components[i].value - expected), 1e-6 * largest) << parts[i].name;
  }
}

TEST(TrainDormandPrince, TooShortARecordIsReportedNotHidden) {
  const RaoGearbox rao;
  TrainRecordOptions options;
  options.duration = 2.0;  // shorter than the common period 35/11 s
  options.samples = 4096;
  const TrainRecord r = rao.record(options);
  EXPECT_FALSE(r.converged());
  EXPECT_NE(r.message.find("common period"), std::string::npos);
}

TEST(TrainDormandPrince, IntegratesOnlyTheDofsAForceReaches) {
  // The lateral rotor's rotations are coupled to nothing it loads: they stay at rest, exactly,
  // and only the four lateral DOFs are integrated.
  const RaoGearbox rao;
  const int pinion_rotation = rao.train.rotationDof(rao.train.bodyIndex("pinion"));
  std::vector<double> times{0.01, 0.02};
  std::vector<int> dofs = rao.probes;
  dofs.push_back(pinion_rotation);
  std::vector<Eigen::VectorXd> seen;
  const TrainDormandPrinceRun run =
      integrateTrainDormandPrince(rao.train, rao.train.inputSpeed(), times, dofs, {},
                                  [&](std::size_t, const Eigen::VectorXd& q, const Eigen::VectorXd&,
                                      const Eigen::VectorXd&) { seen.push_back(q); });
  EXPECT_EQ(rao.train.dofCount(), 6);
  EXPECT_EQ(run.integrated_dofs, 4);
  ASSERT_EQ(seen.size(), 2u);
  EXPECT_EQ(seen[1](4), 0.0);
  EXPECT_GT(seen[1].head(4).cwiseAbs().maxCoeff(), 0.0);
}

TEST(TrainDormandPrince, NewmarkConvergesToItAtSecondOrderOnAMeshedTrain) {
  // The two-stage reducer (Fourier mesh stiffness, transmission error at stage 1, weights,
  // torque): every coefficient the Newmark stepper handles. From rest over 5 stage-1 mesh
  // periods, the average-acceleration Newmark's error is O(h²): its distance to Dormand–Prince
  // (rtol 1e-11) falls by 4 ± 0.6 when h halves, and is below 1e-3 of the response at the finer
  // step — Dormand–Prince is the limit Newmark converges to.
  const GearTrainModel model(testing::exampleGearbox("two_stage_reducer.toml"));
  const double speed = model.inputSpeed();
  const double mesh_period = 1.0 / (model.meshes()[0].frequency_ratio * std::abs(speed));
  const double end = 5.0 * mesh_period;
  std::vector<int> dofs;
  for (int i = 0; i < model.dofCount(); ++i) dofs.push_back(i);
  TrainDormandPrinceOptions options;
  options.relative_tolerance = 1e-11;
  options.absolute_tolerance = 1e-11;
  Eigen::VectorXd dp;
  const TrainDormandPrinceRun run =
      integrateTrainDormandPrince(model, speed, {end}, dofs, options,
                                  [&](std::size_t, const Eigen::VectorXd& q, const Eigen::VectorXd&,
                                      const Eigen::VectorXd&) { dp = q; });
  ASSERT_TRUE(run.finite);
  EXPECT_EQ(run.integrated_dofs, model.dofCount());
  // Compared on the mesh deflections (the rigid rotation, common to both, is excluded).
  const auto deflections = [&](const Eigen::VectorXd& q) {
    Eigen::Vector2d d;
    for (int m = 0; m < 2; ++m) d(m) = model.meshes()[m].deflection(q);
    return d;
  };
  std::vector<double> errors;
  for (int steps : {400, 800}) {
    TrainNewmarkStepper stepper(model, speed, end / steps,
                                NewmarkParameters::averageAcceleration());
    stepper.reset(0.0, Eigen::VectorXd::Zero(model.dofCount()),
                  Eigen::VectorXd::Zero(model.dofCount()));
    for (int k = 0; k < steps; ++k) stepper.step();
    errors.push_back((deflections(stepper.displacement()) - deflections(dp)).cwiseAbs().maxCoeff());
  }
  const double scale = deflections(dp).cwiseAbs().maxCoeff();
  EXPECT_NEAR(errors[0] / errors[1], 4.0, 0.6) << errors[0] << " " << errors[1];
  EXPECT_LT(errors[1], 1e-3 * scale);
}

TEST(TrainDormandPrince, TimeRecordAgreesWithNewmarksOnTheSameWindow) {
  // `time` with method = kDormandPrince: the Newmark run's record (same times) of the two-stage
  // reducer from its static deflection, with q̇ and q̈. Newmark (average acceleration, 256
  // steps per stage-1 mesh period) differs from the exact solution by its period error
  // (ωΔt)²/12 ≈ 5e-5 per cycle, accumulated over the ~60 periods of the derived duration; its
  // mesh forces, velocities and accelerations agree with Dormand–Prince's within 2 % of their
  // p2p, and halving Δt brings them 4× closer (second order: ratio 4 ± 0.8).
  const GearTrainModel model(testing::exampleGearbox("two_stage_reducer.toml"));
  const double speed = model.inputSpeed();
  TrainTimeOptions options;
  options.record_periods = 1;
  options.record_rates = true;
  std::vector<double> errors;
  TrainTimeResponse dp;
  for (int steps : {256, 512}) {
    options.steps_per_mesh_period = steps;
    options.method = TrainTimeMethod::kNewmark;
    const TrainTimeResponse newmark = solveTrainTimeResponse(model, speed, options);
    options.method = TrainTimeMethod::kDormandPrince;
    dp = solveTrainTimeResponse(model, speed, options);
    ASSERT_EQ(dp.status, "completed") << dp.message;
    ASSERT_EQ(dp.t.size(), newmark.t.size());
    // Newmark's clock adds Δt at every step (~1e5 roundings of 1e-16 relative), Dormand–Prince
    // samples k Δt: equal to 1e-10 of the end time.
    EXPECT_LT((dp.t - newmark.t).cwiseAbs().maxCoeff(), 1e-10 * dp.t(dp.t.size() - 1));
    EXPECT_GT(dp.integrator_steps, 0);
    EXPECT_EQ(dp.steps, newmark.steps);
    const auto relative = [](const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
      double worst = 0.0;
      for (Eigen::Index c = 0; c < a.cols(); ++c) {
        const double p2p = a.col(c).maxCoeff() - a.col(c).minCoeff();
        if (p2p > 0.0) worst = std::max(worst, (a.col(c) - b.col(c)).cwiseAbs().maxCoeff() / p2p);
      }
      return worst;
    };
    const double force = relative(dp.mesh_force, newmark.mesh_force);
    errors.push_back(force);
    EXPECT_LT(force, 2e-2) << steps;
    // Rates on the mesh deflections' DOFs: compared through the mesh vectors.
    Eigen::MatrixXd V(model.dofCount(), 2);
    for (int m = 0; m < 2; ++m) V.col(m) = model.meshVector(m);
    EXPECT_LT(relative(dp.velocity * V, newmark.velocity * V), 2e-2) << steps;
    EXPECT_LT(relative(dp.acceleration * V, newmark.acceleration * V), 2e-2) << steps;
  }
  EXPECT_NEAR(errors[0] / errors[1], 4.0, 0.8) << errors[0] << " " << errors[1];
}

TEST(TrainDormandPrince, RefusesNonlinearTrainsAndBadTimes) {
  GearTrainSpec spec = testing::exampleGearbox("two_stage_reducer.toml");
  const GearTrainModel linear(spec);
  EXPECT_THROW(integrateTrainDormandPrince(linear, linear.inputSpeed(), {0.2, 0.1}, {0}, {},
                                           [](std::size_t, const Eigen::VectorXd&,
                                              const Eigen::VectorXd&, const Eigen::VectorXd&) {}),
               InputError);
  spec.meshes[0].contact.backlash = 20e-6;
  spec.meshes[0].contact.law = ContactLaw::kBacklash;
  const GearTrainModel nonlinear(spec);
  try {
    integrateTrainDormandPrince(
        nonlinear, nonlinear.inputSpeed(), {0.1}, {0}, {},
        [](std::size_t, const Eigen::VectorXd&, const Eigen::VectorXd&, const Eigen::VectorXd&) {});
    ADD_FAILURE() << "a nonlinear mesh was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("meshes.stage1"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace geardyn
