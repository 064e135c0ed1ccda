/// Gear-train statics, frequency-domain steady state (linear harmonic balance) and Newmark,
/// checked against closed forms and against each other.

#include "geardyn/solvers/train_response.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/solvers/detail/train_steady_parts.h"
#include "geardyn/solvers/time_response.h"
#include "geardyn/solvers/train_element_orders.h"
#include "geardyn/solvers/train_time.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "geardyn/system/gear_pair_model.h"
#include "system/mesh_force_sample.h"
#include "system/sample_trains.h"

namespace geardyn {
namespace {

using testing::kDeg;
using testing::linParker1999;
using testing::twoStageReducer;

TEST(TrainKinematics, TwoStageReducerRatiosAndMeshFrequencies) {
  const GearTrainModel model(twoStageReducer());
  const auto& b = model.bodies();
  EXPECT_DOUBLE_EQ(b[model.bodyIndex("input")].speed_ratio, 1.0);
  EXPECT_NEAR(b[model.bodyIndex("intermediate")].speed_ratio, -23.0 / 51.0, 1e-14);
  EXPECT_NEAR(b[model.bodyIndex("output")].speed_ratio, 23.0 / 51.0 * 17.0 / 47.0, 1e-14);
  EXPECT_NEAR(model.meshes()[0].frequency_ratio * 2 * std::numbers::pi, 23.0, 1e-12);
  EXPECT_NEAR(model.meshes()[1].frequency_ratio * 2 * std::numbers::pi, 23.0 / 3.0, 1e-12);
  const TrainBaseFrequency base = trainBaseFrequency(model, 10, 4000);
  EXPECT_NEAR(base.ratio * 2 * std::numbers::pi, 23.0 / 3.0, 1e-12);
  EXPECT_EQ(base.mesh_multiple, (std::vector<int>{3, 1}));
}

TEST(TrainStatics, MeshForcesFollowTheTorqueFlow) {
  const GearTrainModel model(twoStageReducer());
  const TrainStaticResult r = solveTrainStatic(model, model.inputSpeed());
  ASSERT_EQ(r.status, "ok") << r.message;
  EXPECT_EQ(r.rigid_modes, 1);  // the rolling of the whole train
  // F₁ = T / r_b1, F₂ = T (r_b2 / r_b1) / r_b3 (lossless), to round-off.
  const double T = 200.0;
  const auto& m = model.meshes();
  const double f1 = T / m[0].base_radius_a;
  const double f2 = T * m[0].base_radius_b / m[0].base_radius_a / m[1].base_radius_a;
  EXPECT_NEAR(r.mesh_force[0], f1, 1e-9 * f1);
  EXPECT_NEAR(r.mesh_force[1], f2, 1e-9 * f2);
  EXPECT_NEAR(model.outputTorque(), -T * 51.0 / 23.0 * 47.0 / 17.0, 1e-9 * T);
  // The input shaft's two bearings carry the stage-1 mesh force (the coupling carries torque
  // and no lateral load at equilibrium): |Σ F_bearings| = F₁.
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (std::size_t e = 0; e < model.elements().size(); ++e) {
    const TrainElement& el = model.elements()[e];
    if (el.name.rfind("input_", 0) != 0) continue;
    Eigen::VectorXd local(el.dofs.size());
    for (std::size_t i = 0; i < el.dofs.size(); ++i) local(i) = r.displacement(el.dofs[i]);
    sum += el.local_stiffness * el.jacobian * local;
  }
  EXPECT_NEAR(sum.norm(), f1, 1e-8 * f1);
}

TEST(TrainStatics, PlanetLoadSharingWithPinErrors) {
  GearTrainSpec spec = linParker1999(3);
  spec.operating.input_torque = 500.0;
  const TrainStaticResult even = solveTrainStatic(GearTrainModel(spec), 0.0);
  ASSERT_EQ(even.load_sharing.size(), 1u);
  EXPECT_NEAR(even.load_sharing[0].load_sharing_factor, 1.0, 1e-9);
  // Each planet carries a third of the sun torque: F = T / (3 r_bs).
  const GearTrainModel model(spec);
  const double f = 500.0 / (3.0 * model.meshes()[0].base_radius_a);
  for (double force : even.load_sharing[0].sun_planet_force) EXPECT_NEAR(force, f, 1e-8 * f);
  // A tangential pin error on one planet changes its load and the others' (the factor rises
  // above 1), linearly in the error, while the planets together still carry the sun torque.
  auto forces = [&](double error) {
    spec.stages[0].pin_position_errors = {error, 0.0, 0.0};
    return solveTrainStatic(GearTrainModel(spec), 0.0).load_sharing[0];
  };
  const TrainStageLoadSharing e1 = forces(20e-6), e2 = forces(40e-6);
  EXPECT_GT(e1.load_sharing_factor, 1.005);
  for (int n = 0; n < 3; ++n) {
    const double d1 = e1.sun_planet_force[n] - f, d2 = e2.sun_planet_force[n] - f;
    EXPECT_NEAR(d2, 2.0 * d1, 1e-8 * f) << "planet " << n + 1;
  }
  double total = 0.0;
  for (double force : e1.sun_planet_force) total += force;
  EXPECT_NEAR(total, 3 * f, 1e-8 * f);
}

std::shared_ptr<const MeshStiffness> smoothStiffness(double mean, double phase_deg) {
  // Smooth k (three harmonics), so that the harmonic balance converges spectrally and the
  // comparison is not limited by Gibbs oscillations of a step.
  return std::make_shared<FourierMeshStiffness>(mean, std::vector<double>{0.12, 0.05, 0.02},
                                                std::vector<double>{phase_deg * kDeg, 0.3, 1.1},
                                                1.6);
}

/// Newmark (Δt = mesh period / 512) against the harmonic-balance steady state (20 harmonics of
/// each mesh) over one common period: mesh forces sample by sample. The tolerance 0.5 % of the
/// peak-to-peak is the acceptance of the gear-train issue; the Newmark period error at the
/// tenth mesh harmonic is (ω Δt)²/12 ≈ 1.5e-3 of a percent, the truncation of the balance at
/// 20 harmonics of a three-harmonic stiffness below 1e-6.
void compareTimeAndFrequencyDomain(const GearTrainModel& model, double speed) {
  TrainSteadyOptions steady;
  steady.mesh_harmonics = 20;
  const TrainSteadyState hbm = solveTrainSteadyState(model, speed, steady);
  TrainTimeOptions time;
  time.steps_per_mesh_period = 512;
  const TrainTimeResponse newmark = solveTrainTimeResponse(model, speed, time);
  ASSERT_EQ(newmark.status, "completed") << newmark.message;
  // Shift Newmark's window to the balance's time origin (both are one common period).
  const double period = 1.0 / hbm.base_frequency;
  const Eigen::VectorXd t = newmark.t.array() - period * std::floor(newmark.t(0) / period);
  const Eigen::MatrixXd q = hbm.displacement(t);
  for (std::size_t m = 0; m < model.meshes().size(); ++m) {
    const TrainMesh& mesh = model.meshes()[m];
    const double p2p = hbm.mesh_force_max[m] - hbm.mesh_force_min[m];
    ASSERT_GT(p2p, 1e-3 * std::abs(hbm.mesh_force_mean[m])) << "no dynamics to compare";
    double worst = 0.0;
    for (Eigen::Index k = 0; k < t.size(); ++k) {
      const double f = testing::meshForceAt(mesh, q.row(k), t(k), speed);
      worst = std::max(worst, std::abs(f - newmark.mesh_force(k, m)));
    }
    EXPECT_LT(worst, 5e-3 * p2p) << mesh.name << ": worst " << worst / p2p << " of p2p";
    ::testing::Test::RecordProperty(mesh.name + "_relative_difference",
                                    std::to_string(worst / p2p));
  }
}

TEST(TrainSteadyState, NewmarkAgreesWithHarmonicBalanceTwoStage) {
  GearTrainSpec spec = twoStageReducer(smoothStiffness(4e8, 0.0), smoothStiffness(6e8, 40.0));
  spec.meshes[0].transmission_error.addFourier({5e-6, 1e-6}, {0.0, 0.5});
  const GearTrainModel model(spec);
  compareTimeAndFrequencyDomain(model, model.inputSpeed());
}

TEST(TrainSteadyState, NewmarkAgreesWithHarmonicBalancePlanetary) {
  GearTrainSpec spec = linParker1999(3);
  spec.stages[0].sun_planet_stiffness = smoothStiffness(5e8, 0.0);
  spec.stages[0].ring_planet_stiffness = smoothStiffness(5e8, 70.0);
  spec.stages[0].sun_planet_damping_ratio = spec.stages[0].ring_planet_damping_ratio = 0.04;
  spec.bearings[0].cyy = spec.bearings[0].czz = 2e3;
  spec.bearings[2].cyy = spec.bearings[2].czz = 2e3;
  spec.stages[0].pin_damping = 2e3;
  spec.bearings[1].c_torsion = 50.0;
  spec.operating.input_torque = 300.0;
  spec.operating.input_speed = 300.0;  // carrier at 75 rad/s: Coriolis terms on
  const GearTrainModel model(spec);
  compareTimeAndFrequencyDomain(model, model.inputSpeed());
}

TEST(TrainSteadyState, ConstantStiffnessWithoutErrorIsStatic) {
  const GearTrainModel model(twoStageReducer());
  const TrainSteadyState s = solveTrainSteadyState(model, model.inputSpeed());
  const TrainStaticResult st = solveTrainStatic(model, model.inputSpeed());
  for (std::size_t m = 0; m < model.meshes().size(); ++m) {
    EXPECT_NEAR(s.mesh_force_max[m], st.mesh_force[m], 1e-9 * st.mesh_force[m]);
    EXPECT_NEAR(s.dynamic_factor[m], 1.0, 1e-9);
  }
}

// The flexible reducer (full DOFs, FE shafts, a rolling mode): the sparse harmonic blocks
// (bordered h = 0 block) and the dense ones (penalty) are two factorisations of one system, so
// the steady states agree to round-off amplified by the blocks' conditioning: 1e-9 of the
// largest harmonic amplitude.
TEST(TrainSteadyState, SparseAndDenseHarmonicBlocksAgree) {
  const GearTrainModel model(testing::flexibleReducer(12.0, 0.05));
  TrainSteadyOptions options;
  options.mesh_harmonics = 4;
  ASSERT_GE(model.dofCount(), options.sparse_dofs);
  const TrainSteadyState sparse = solveTrainSteadyState(model, model.inputSpeed(), options);
  options.sparse_dofs = model.dofCount() + 1;
  const TrainSteadyState dense = solveTrainSteadyState(model, model.inputSpeed(), options);
  const double scale = dense.harmonic.cwiseAbs().maxCoeff();
  EXPECT_LT((sparse.harmonic - dense.harmonic).cwiseAbs().maxCoeff(), 1e-9 * scale);
  for (std::size_t m = 0; m < model.meshes().size(); ++m) {
    EXPECT_NEAR(sparse.dynamic_factor[m], dense.dynamic_factor[m], 1e-9) << m;
  }
}

// Issue #39: the sparse path factorises one harmonic block at a time in a pattern analysed once
// per speed and recovers X_h from the kept D(h)⁻¹V and D(h)⁻¹F_h; the dense path keeps every LU
// and solves again. On the flexible reducer (222 DOFs, FE shafts, a rolling mode) with both
// meshes' stiffness varying (L = 8 harmonics, so the condensation couples 2H + 1 = 49 blocks),
// at three speeds around the operating one: the harmonics agree to 1e-10 of the largest (two
// factorisations of the same well-conditioned blocks: round-off, measured 6.1e-13), and so do
// the peaks. The element forces, now one product per element, equal the definition
// k J q(t_k) sample by sample (elementDeformation at q(t_k)) to 1e-12.
TEST(TrainSteadyState, SparseBlockByBlockEqualsTheDensePath) {
  GearTrainSpec spec = testing::flexibleReducer(12.0, 0.03);
  spec.meshes[0].stiffness = std::make_shared<FourierMeshStiffness>(
      4e8, std::vector<double>{0.12, 0.05, 0.02}, std::vector<double>{0.0, 0.3, 1.1}, 1.6);
  spec.meshes[1].stiffness = std::make_shared<FourierMeshStiffness>(
      6e8, std::vector<double>{0.1, 0.04}, std::vector<double>{0.2, 0.7}, 1.5);
  const GearTrainModel model(spec);
  TrainSteadyOptions options;
  options.mesh_harmonics = 8;
  ASSERT_GE(model.dofCount(), options.sparse_dofs);
  const TrainSteadySolver sparse_solver(model, options);
  options.sparse_dofs = model.dofCount() + 1;
  const TrainSteadySolver dense_solver(model, options);
  double worst = 0.0, worst_element = 0.0;
  for (const double factor : {0.6, 1.0, 1.7}) {
    const double speed = factor * model.inputSpeed();
    const TrainSteadyState sparse = sparse_solver.solve(speed);
    const TrainSteadyState dense = dense_solver.solve(speed);
    ASSERT_EQ(sparse.harmonics, dense.harmonics);
    ASSERT_GE(sparse.harmonics, 16);
    const double scale = dense.harmonic.cwiseAbs().maxCoeff();
    worst = std::max(worst, (sparse.harmonic - dense.harmonic).cwiseAbs().maxCoeff() / scale);
    for (std::size_t m = 0; m < model.meshes().size(); ++m) {
      EXPECT_NEAR(sparse.mesh_force_max[m], dense.mesh_force_max[m],
                  1e-10 * std::abs(dense.mesh_force_max[m]));
      EXPECT_NEAR(sparse.dynamic_factor[m], dense.dynamic_factor[m], 1e-10);
    }
    const Eigen::MatrixXd q = sparse.displacement(sparse.t);
    for (std::size_t e = 0; e < model.elements().size(); ++e) {
      const TrainElement& element = model.elements()[e];
      Eigen::MatrixXd f(q.rows(), element.local_stiffness.rows());
      for (Eigen::Index k = 0; k < q.rows(); ++k) {
        f.row(k) =
            (element.local_stiffness * detail::elementDeformation(element, q.row(k).transpose()))
                .transpose();
      }
      const Eigen::RowVectorXd mean = f.colwise().mean();
      double peak = 0.0;
      for (Eigen::Index k = 0; k < q.rows(); ++k) peak = std::max(peak, (f.row(k) - mean).norm());
      worst_element = std::max(
          worst_element, std::abs(sparse.element_dynamic_force[e] - peak) / std::max(peak, 1e-300));
    }
  }
  std::printf("sparse vs dense: harmonics within %.3g of the largest; element peaks within %.3g\n",
              worst, worst_element);
  EXPECT_LT(worst, 1e-10);
  EXPECT_LT(worst_element, 1e-12);
}

/// Parker (2000) in the forced response: a sun–planet transmission error of one order l,
/// phased planet by planet, moves the central members only as the rule says — rotation only
/// (l z_s / N integer), translation only ((l z_s ± 1)/N integer), or not at all.
TEST(PlanetPhasing, ForcedResponseFollowsParkerRules) {
  const int planets = 4, zs = 21, zp = 27;
  for (int l = 1; l <= 4; ++l) {
    GearTrainSpec spec = linParker1999(planets);
    spec.gears[0].gear.teeth = zs;
    spec.gears[1].gear.teeth = zs + 2 * zp;
    spec.stages[0].planet.teeth = zp;
    std::vector<double> amplitudes(l, 0.0), phases(l, 0.0);
    amplitudes[l - 1] = 1e-6;
    spec.stages[0].sun_planet_error.addFourier(amplitudes, phases);
    spec.stages[0].sun_planet_damping_ratio = spec.stages[0].ring_planet_damping_ratio = 0.03;
    spec.operating.input_speed = 100.0;
    const GearTrainModel model(spec);
    TrainSteadyOptions options;
    options.mesh_harmonics = 4;
    const TrainSteadyState s = solveTrainSteadyState(model, 100.0, options);
    const int h = l * s.mesh_multiple[0];
    double central_rotation = 0.0, central_translation = 0.0, planet_motion = 0.0;
    for (std::size_t b = 0; b < model.bodies().size(); ++b) {
      const TrainBody& body = model.bodies()[b];
      const int y = model.translationDof(static_cast<int>(b));
      const int r = model.rotationDof(static_cast<int>(b));
      const double rot = std::abs(s.harmonic(r, h)) * 0.05;  // ~ radius: metres at the teeth
      const double trans = std::hypot(std::abs(s.harmonic(y, h)), std::abs(s.harmonic(y + 1, h)));
      if (body.kind == TrainBodyKind::kPlanet) {
        planet_motion = std::max(planet_motion, std::max(rot, trans));
      } else {
        central_rotation = std::max(central_rotation, rot);
        central_translation = std::max(central_translation, trans);
      }
    }
    const bool rotational = (l * zs) % planets == 0;
    const bool translational = (l * zs + 1) % planets == 0 || (l * zs - 1) % planets == 0;
    ASSERT_GT(planet_motion, 0.0);
    const double zero = 1e-9 * planet_motion;  // exact cancellation leaves round-off
    if (rotational) {
      EXPECT_LT(central_translation, zero) << "l = " << l;
      EXPECT_GT(central_rotation, 1e-3 * planet_motion) << "l = " << l;
    } else if (translational) {
      EXPECT_LT(central_rotation, zero) << "l = " << l;
      EXPECT_GT(central_translation, 1e-3 * planet_motion) << "l = " << l;
    } else {
      EXPECT_LT(central_rotation, zero) << "l = " << l;
      EXPECT_LT(central_translation, zero) << "l = " << l;
    }
  }
}

TEST(TrainInput, BadTrainsNameTheComponent) {
  auto key_of = [](GearTrainSpec spec) {
    try {
      GearTrainModel model(std::move(spec));
    } catch (const InputError& e) {
      return e.key() + " | " + e.what();
    }
    return std::string("accepted");
  };
  GearTrainSpec a = twoStageReducer();
  a.gears[1].shaft = "input";  // both gears of stage 1 on one shaft
  EXPECT_NE(key_of(a).find("meshes.stage1.gears"), std::string::npos) << key_of(a);
  GearTrainSpec b = twoStageReducer();
  b.gears[1].gear.normal_module = 3.5e-3;
  EXPECT_NE(key_of(b).find("gears.z2"), std::string::npos) << key_of(b);
  GearTrainSpec c = twoStageReducer();
  c.bearings[0].shaft = "inptu";
  EXPECT_NE(key_of(c).find("did you mean \"input\""), std::string::npos) << key_of(c);
  GearTrainSpec d = twoStageReducer();  // a third shaft meshing with both: a locked loop
  d.shafts.push_back({"idler", 1.0, 1e-3, {}, {}, {}, 7850.0});
  d.gears.push_back({"zi", "idler", testing::spurGear(30, 3e-3, 20.0, 0.03), false, true});
  d.meshes.push_back({"loop_a",
                      "z1",
                      "zi",
                      120 * kDeg,
                      std::nullopt,
                      d.meshes[0].stiffness,
                      {},
                      0.05,
                      std::nullopt});
  d.meshes.push_back(
      {"loop_b", "zi", "z2", 0.0, std::nullopt, d.meshes[0].stiffness, {}, 0.05, std::nullopt});
  const std::string locked = key_of(d);
  EXPECT_NE(locked.find("locked"), std::string::npos) << locked;
  EXPECT_NE(locked.find("loop_a"), std::string::npos) << locked;
  GearTrainSpec e = twoStageReducer();
  e.meshes[0].centre_distance = 0.1;  // not the distance the teeth need
  EXPECT_NE(key_of(e).find("meshes.stage1.centre_distance"), std::string::npos) << key_of(e);
}

}  // namespace
}  // namespace geardyn

namespace geardyn {
namespace {

/// Reduction: one external pair with torsional DOFs is the SDOF gear-pair model
/// m_e ẍ + c ẋ + k(t)(x − e) = F (Gelman 2005) with x = r_b1 θ₁ + r_b2 θ₂,
/// m_e = I₁I₂/(I₁r_b2² + I₂r_b1²), F = T/r_b1 and the same c. The train's steady state (harmonic
/// balance, 40 harmonics of a three-harmonic k) against the SDOF model's Dormand–Prince steady
/// state (relative tolerance 1e-10): mesh forces agree to 1e-7 of the mean force (the
/// integrator's tolerance, accumulated over the transient, and the balance's truncation, below
/// 1e-10 for this smooth k, are the limits).
TEST(TrainReduction, SinglePairTorsionalIsTheSdofGearPairModel) {
  GearTrainSpec spec;
  spec.dofs = TrainDofs::kTorsional;
  spec.shafts = {{"pinion_shaft", 0.0, 2e-3, {}, {}, {}, 7850.0},
                 {"gear_shaft", 0.0, 9e-3, {}, {}, {}, 7850.0}};
  spec.gears = {{"pinion", "pinion_shaft", testing::spurGear(25, 3e-3, 20.0, 0.02), false, false},
                {"gear", "gear_shaft", testing::spurGear(53, 3e-3, 20.0, 0.02), false, false}};
  const auto k = smoothStiffness(3e8, 20.0);
  TrainMeshSpec mesh{"pair", "pinion", "gear", 0.0, std::nullopt, k, {}, 0.06, std::nullopt};
  mesh.transmission_error.addFourier({4e-6, 1.5e-6}, {0.2, -0.4});
  spec.meshes = {mesh};
  const double speed = 2100.0 * std::numbers::pi / 30.0, torque = 80.0;
  spec.operating = {"pinion_shaft", speed, torque, "gear_shaft"};
  const GearTrainModel train(spec);
  const TrainMesh& m = train.meshes()[0];

  GearPairModelSpec sdof;
  sdof.mass = equivalentMass(2e-3, m.base_radius_a, 9e-3, m.base_radius_b);
  EXPECT_NEAR(sdof.mass, m.equivalent_mass, 1e-12 * sdof.mass);
  sdof.damping = m.damping;
  sdof.mean_force = torque / m.base_radius_a;
  sdof.stiffness = k;
  sdof.mesh_frequency = m.frequency_ratio * speed;
  sdof.transmission_error = m.transmission_error;
  const GearPairModel pair(sdof);
  TimeResponseOptions options;
  options.method = TimeIntegrator::kDormandPrince;
  options.relative_tolerance = 1e-10;
  options.steady_tolerance = 1e-9;
  const TimeResponse reference = solveTimeResponse(pair, options);
  ASSERT_TRUE(reference.converged()) << reference.message;

  TrainSteadyOptions steady;
  steady.mesh_harmonics = 40;
  const TrainSteadyState s = solveTrainSteadyState(train, speed, steady);
  Eigen::VectorXd t(static_cast<Eigen::Index>(reference.t.size()));
  for (std::size_t i = 0; i < reference.t.size(); ++i) t(i) = reference.t[i];
  const Eigen::MatrixXd q = s.displacement(t);
  double worst = 0.0;
  for (Eigen::Index i = 0; i < t.size(); ++i) {
    double x = 0.0;
    for (std::size_t d = 0; d < m.dofs.size(); ++d) x += m.gradient[d] * q(i, m.dofs[d]);
    const double phi = m.phaseAt(t(i), speed);
    const double f_train = k->stiffness(phi) * (x - m.transmission_error.value(phi));
    const double f_sdof = k->stiffness(phi) * (reference.x[i] - m.transmission_error.value(phi));
    worst = std::max(worst, std::abs(f_train - f_sdof));
  }
  EXPECT_LT(worst, 1e-7 * sdof.mean_force);
  ::testing::Test::RecordProperty("relative_difference", std::to_string(worst / sdof.mean_force));
}

// Whine through the bearings (issue #36): elementForceHarmonic gives a bearing's force at one
// harmonic straight from X_h; here it is checked against the DFT of the sampled spring force
// k J q(t_k) over one base period (64 H samples: the DFT of a trigonometric polynomial of degree
// H is exact above 2H samples), for every bearing of the flexible helical reducer with varying
// mesh stiffness, at each mesh's orders 1..3. Both are exact evaluations of the same harmonic:
// 1e-9 of the largest (round-off of the 64 H-term sums).
TEST(TrainSteadyState, BearingForceHarmonicsEqualTheDftOfTheSampledForce) {
  GearTrainSpec spec = testing::flexibleReducer(12.0, 0.05);
  spec.meshes[0].stiffness = std::make_shared<FourierMeshStiffness>(
      4e8, std::vector<double>{0.12, 0.05}, std::vector<double>{0.0, 0.3}, 1.6);
  spec.meshes[1].stiffness = std::make_shared<FourierMeshStiffness>(6e8, std::vector<double>{0.1},
                                                                    std::vector<double>{0.2}, 1.5);
  const GearTrainModel model(spec);
  TrainSteadyOptions options;
  options.mesh_harmonics = 4;
  const TrainSteadyState s = solveTrainSteadyState(model, model.inputSpeed(), options);
  const int samples = 64 * s.harmonics;
  const Eigen::VectorXd t =
      Eigen::VectorXd::LinSpaced(samples, 0.0, (samples - 1.0) / samples / s.base_frequency);
  const Eigen::MatrixXd q = s.displacement(t);
  int checked = 0;
  double largest = 0.0;
  std::vector<std::pair<double, double>> pairs;  // (from X_h, from the DFT)
  for (const TrainElement& e : model.elements()) {
    if (e.kind != "bearing") continue;
    Eigen::MatrixXd local(samples, static_cast<Eigen::Index>(e.dofs.size()));
    for (std::size_t i = 0; i < e.dofs.size(); ++i) local.col(i) = q.col(e.dofs[i]);
    const Eigen::MatrixXd force = local * (e.local_stiffness * e.jacobian).transpose();
    for (std::size_t m = 0; m < model.meshes().size(); ++m) {
      for (int l = 1; l <= 3; ++l) {
        const int h = l * s.mesh_multiple[m];
        if (h > s.harmonics) continue;
        double sum = 0.0;
        for (Eigen::Index r = 0; r < force.cols(); ++r) {
          if (e.moment_rows[static_cast<std::size_t>(r)]) continue;
          std::complex<double> c = 0.0;
          for (int k = 0; k < samples; ++k)
            c += force(k, r) * std::polar(1.0, -2.0 * std::numbers::pi * h * k / samples);
          sum += std::norm(2.0 * c / static_cast<double>(samples));
        }
        pairs.emplace_back(elementForceHarmonic(e, s, h), std::sqrt(sum));
        largest = std::max(largest, std::sqrt(sum));
        ++checked;
      }
    }
  }
  ASSERT_GT(checked, 0);
  ASSERT_GT(largest, 0.0);
  for (const auto& [ours, dft] : pairs) EXPECT_NEAR(ours, dft, 1e-9 * largest);
}

// q(t) of a steady state over a record longer than its evaluation block (1024 times), with
// harmonics present at uneven gaps (1, 2, 5, 9, 10: three distinct gaps), against the direct sum
// X₀ + Σ 2 Re(X_h e^{i h ω₀ t}) with one sincos per term. Tolerance: the products
// e^{i h θ} = Π e^{i g θ} lose about h ε each, 1e-13 of the largest coefficient sum.
TEST(TrainSteadyState, DisplacementRecordEqualsTheDirectSum) {
  TrainSteadyState s;
  s.base_frequency = 37.5;
  s.harmonics = 12;
  s.harmonic = Eigen::MatrixXcd::Zero(3, 13);
  s.harmonic.col(0).real() << 1e-6, -2e-6, 3e-7;
  double scale = s.harmonic.col(0).cwiseAbs().sum();
  for (int h : {1, 2, 5, 9, 10}) {
    for (int d = 0; d < 3; ++d) s.harmonic(d, h) = std::polar(1e-6 / (h + d), 0.3 * h - d);
    scale += 2.0 * s.harmonic.col(h).cwiseAbs().sum();
  }
  const Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(2500, -0.01, 3.7);
  const Eigen::MatrixXd q = s.displacement(t);
  ASSERT_EQ(q.rows(), t.size());
  ASSERT_EQ(q.cols(), 3);
  for (Eigen::Index k = 0; k < t.size(); ++k) {
    for (int d = 0; d < 3; ++d) {
      double direct = s.harmonic(d, 0).real();
      for (int h = 1; h <= s.harmonics; ++h)
        direct += 2.0 * (s.harmonic(d, h) *
                         std::polar(1.0, h * 2.0 * std::numbers::pi * s.base_frequency * t(k)))
                            .real();
      ASSERT_NEAR(q(k, d), direct, 1e-13 * scale) << "t = " << t(k) << ", DOF " << d;
    }
  }
}

}  // namespace
}  // namespace geardyn
