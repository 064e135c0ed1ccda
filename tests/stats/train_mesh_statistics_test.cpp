// Gelman's mean-excitation statistics per train mesh (train_mesh_statistics.h): a one-pair
// torsional train gives `geardyn stats`'s SDOF numbers, and at every mesh of a two-stage reducer
// R agrees with its independent forms 1 + m₁(K E)/F_m (quadrature of the curves) and
// m₁(K δ)/F_m (the Newmark record).

#include "geardyn/stats/train_mesh_statistics.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/solvers/time_response.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "system/sample_trains.h"

namespace geardyn {
namespace {

std::shared_ptr<const MeshStiffness> smoothStiffness(double mean, double phase) {
  return std::make_shared<FourierMeshStiffness>(mean, std::vector<double>{0.12, 0.05, 0.02},
                                                std::vector<double>{phase, 0.3, 1.1}, 1.6);
}

TrainTimeOptions fineNewmark() {
  TrainTimeOptions o;
  o.steps_per_mesh_period = 512;
  o.record_periods = 2;
  return o;
}

TEST(TrainMeshStatistics, OnePairTorsionalTrainGivesTheSdofStatsNumbers) {
  GearTrainSpec spec;
  spec.dofs = TrainDofs::kTorsional;
  spec.shafts = {{"pinion_shaft", 0.0, 2e-3, {}, {}, {}, 7850.0},
                 {"gear_shaft", 0.0, 9e-3, {}, {}, {}, 7850.0}};
  spec.gears = {{"pinion", "pinion_shaft", testing::spurGear(25, 3e-3, 20.0, 0.02), false, false},
                {"gear", "gear_shaft", testing::spurGear(53, 3e-3, 20.0, 0.02), false, false}};
  TrainMeshSpec mesh{"pair", "pinion", "gear",      0.0, std::nullopt, smoothStiffness(3e8, 0.35),
                     {},     0.06,     std::nullopt};
  mesh.transmission_error.addFourier({4e-6, 1.5e-6}, {0.2, -0.4});
  spec.meshes = {mesh};
  const double speed = 2100.0 * std::numbers::pi / 30.0, torque = 80.0;
  spec.operating = {"pinion_shaft", speed, torque, "gear_shaft"};
  const GearTrainModel train(spec);
  const TrainMesh& m = train.meshes()[0];

  // `geardyn stats`'s SDOF pair (the TrainReduction test's mapping) at a baseload of 1.4 F.
  GearPairModelSpec sdof;
  sdof.mass = equivalentMass(2e-3, m.base_radius_a, 9e-3, m.base_radius_b);
  sdof.damping = m.damping;
  sdof.mean_force = torque / m.base_radius_a;
  sdof.stiffness = m.stiffness;
  sdof.mesh_frequency = m.frequency_ratio * speed;
  sdof.initial_phase = m.phase;
  sdof.transmission_error = m.transmission_error;
  const GearPairModel pair(sdof);
  const double scale = 1.4;
  const MeanExcitation expected = meanExcitationFromModel(pair, scale * sdof.mean_force);

  const TrainStaticResult statics = solveTrainStatic(train, speed);
  const TrainTimeResponse record = solveTrainTimeResponse(train, speed, fineNewmark());
  ASSERT_EQ(record.status, "completed");
  const auto stats = trainMeshStatistics(train, speed, record, statics.mesh_force, scale);
  ASSERT_EQ(stats.size(), 1u);
  ASSERT_TRUE(stats[0].excitation.has_value());
  const MeanExcitation& got = *stats[0].excitation;
  // The same quadrature on the same curves: equal to round-off of F = T/r_b (1e-12).
  EXPECT_NEAR(stats[0].static_force, sdof.mean_force, 1e-12 * sdof.mean_force);
  for (auto [a, b] : {std::pair{got.ratio, expected.ratio},
                      {got.ratio_eq15, expected.ratio_eq15},
                      {got.ratio_eq11, expected.ratio_eq11},
                      {got.a, expected.a},
                      {got.d_k, expected.d_k},
                      {got.d_e, expected.d_e},
                      {got.r_ke, expected.r_ke},
                      {got.zeta, expected.zeta},
                      {got.dynamic_mean_excitation, expected.dynamic_mean_excitation}}) {
    EXPECT_NEAR(a, b, 1e-12 * std::max(1.0, std::abs(b)));
  }
  EXPECT_GT(std::abs(got.ratio - 1.0), 1e-4);  // the error makes R depart from 1

  // The SDOF Newmark at the same Δt to its steady state: the relative coordinate of a
  // two-inertia train obeys the SDOF equation exactly, so the records agree to the transient
  // left after the train's derived duration (decayed by 1e-6) and the SDOF's steady tolerance.
  TimeResponseOptions options;
  options.steps_per_period = 512;
  options.output_points_per_period = 512;
  options.steady_tolerance = 1e-11;
  options.output_periods = 2;
  const TimeResponse ref = solveTimeResponse(pair, options);
  ASSERT_TRUE(ref.converged()) << ref.message;
  Eigen::VectorXd force(static_cast<Eigen::Index>(ref.t.size())), x(force.size());
  double mean_kx = 0.0;
  for (std::size_t j = 0; j < ref.t.size(); ++j) {
    const double k = pair.stiffness(ref.t[j]);
    force(static_cast<Eigen::Index>(j)) = k * (ref.x[j] - pair.error(ref.t[j]));
    x(static_cast<Eigen::Index>(j)) = ref.x[j];
    mean_kx += k * ref.x[j] / static_cast<double>(ref.t.size());
  }
  const RecordStatistics f = recordStatistics(force), dte = recordStatistics(x);
  constexpr double kRecordTolerance = 1e-6;  // relative to the record's peak-to-peak
  const double fp = f.peakToPeak(), xp = dte.peakToPeak();
  EXPECT_NEAR(stats[0].force.mean, f.mean, kRecordTolerance * fp);
  EXPECT_NEAR(stats[0].force.rms, f.rms, kRecordTolerance * fp);
  EXPECT_NEAR(stats[0].force.peakToPeak(), fp, kRecordTolerance * fp);
  EXPECT_NEAR(stats[0].dte.mean, dte.mean, kRecordTolerance * xp);
  EXPECT_NEAR(stats[0].dte.rms, dte.rms, kRecordTolerance * xp);
  EXPECT_NEAR(stats[0].dte.peakToPeak(), xp, kRecordTolerance * xp);
  EXPECT_NEAR(stats[0].dynamic_factor, std::max(f.max, -f.min) / sdof.mean_force,
              kRecordTolerance * fp / sdof.mean_force);
  // `geardyn stats --simulate`'s m₁(k y) = m₁(K x)/F₀, and L_d from the curves (eq. 5).
  const double simulated = mean_kx / (scale * sdof.mean_force);
  EXPECT_NEAR(stats[0].simulated_dynamic_mean_excitation, simulated, 1e-6 * simulated);
  EXPECT_NEAR(stats[0].simulated_dynamic_mean_excitation, expected.dynamic_mean_excitation,
              1e-6 * expected.dynamic_mean_excitation);
  const auto property = [](const char* name, double value) {
    ::testing::Test::RecordProperty(name, fmt::format("{:.3g}", value));
  };
  property("ratio_difference", std::abs(got.ratio - expected.ratio));
  property("force_rms_relative_difference", std::abs(stats[0].force.rms - f.rms) / f.rms);
  property("force_p2p_relative_difference", std::abs(stats[0].force.peakToPeak() - fp) / fp);
  property("dte_rms_relative_difference", std::abs(stats[0].dte.rms - dte.rms) / dte.rms);
  property("simulated_mean_excitation_relative_difference",
           std::abs(stats[0].simulated_dynamic_mean_excitation - simulated) / simulated);
}

TEST(TrainMeshStatistics, EveryMeshOfATwoStageReducerAgreesWithItsIndependentForms) {
  GearTrainSpec spec = testing::twoStageReducer(smoothStiffness(4e8, 0.0),
                                                smoothStiffness(6e8, 40.0 * testing::kDeg));
  spec.meshes[0].transmission_error.addFourier({5e-6, 1e-6}, {0.0, 0.5});
  spec.meshes[1].transmission_error.addFourier({2e-6}, {1.2});
  const GearTrainModel model(spec);
  const double speed = model.inputSpeed();
  const TrainStaticResult statics = solveTrainStatic(model, speed);
  const TrainTimeResponse record = solveTrainTimeResponse(model, speed, fineNewmark());
  ASSERT_EQ(record.status, "completed");
  const auto stats = trainMeshStatistics(model, speed, record, statics.mesh_force, 1.0);
  ASSERT_EQ(stats.size(), 2u);
  for (std::size_t i = 0; i < stats.size(); ++i) {
    const TrainMesh& mesh = model.meshes()[i];
    const TrainMeshStatistics& s = stats[i];
    ASSERT_TRUE(s.excitation) << s.mesh;
    // R = 1 + m₁(K E)/F_m (eqs. 7–9 with m₁(ė) = 0), by the midpoint rule on 4096 points (a
    // trigonometric polynomial of degree 5: exact to round-off).
    const int n = 4096;
    double mean_ke = 0.0;
    for (int j = 0; j < n; ++j) {
      const double phi = (j + 0.5) / n;
      mean_ke += mesh.stiffness->stiffness(phi) * mesh.transmission_error.value(phi) / n;
    }
    const double independent = 1.0 + mean_ke / s.static_force;
    EXPECT_NEAR(s.excitation->ratio, independent, 1e-10) << s.mesh;
    EXPECT_GT(std::abs(s.excitation->ratio - 1.0), 1e-5) << s.mesh;
    // The mean dynamic mesh force is the static one (torque balance of each shaft over whole
    // periods), so the record's m₁(K δ)/F_m is R up to Newmark's error (Δt = T_m/512).
    EXPECT_NEAR(s.force.mean, s.static_force, 1e-6 * s.static_force) << s.mesh;
    EXPECT_NEAR(s.simulated_ratio, s.excitation->ratio, 1e-6) << s.mesh;
    EXPECT_GE(s.dynamic_factor, s.force.max / s.static_force);
    EXPECT_GT(s.force.rms, s.force.mean);
  }
  // The intermediate shaft's torque balance: F₂ r_b(z3) = F₁ r_b(z2).
  EXPECT_NEAR(stats[1].static_force / stats[0].static_force,
              model.meshes()[0].base_radius_b / model.meshes()[1].base_radius_a, 1e-9);
}

TEST(TrainMeshStatistics, ANonPositiveDesignLoadIsAnInputError) {
  const GearTrainModel model(testing::twoStageReducer());
  TrainTimeResponse record;
  EXPECT_THROW(trainMeshStatistics(model, model.inputSpeed(), record, {1.0, 1.0}, 0.0), InputError);
}

}  // namespace
}  // namespace geardyn
