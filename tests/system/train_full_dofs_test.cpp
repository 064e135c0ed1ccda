/// Gear trains with six DOFs per node: the helical mesh normal against the involute helicoid,
/// the axial thrust of a helical stage against F_a = F_t tan β_w, flexible shafts against
/// rigid ones as E grows, and the bad input of positions along shafts.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "geardyn/error.h"
#include "geardyn/solvers/train_modal.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/solvers/train_time.h"
#include "geardyn/system/gear_train_model.h"
#include "system/sample_trains.h"

namespace geardyn {
namespace {

using testing::flexibleReducer;

/// The unit normal of a right-hand involute helicoid by finite differences of its surface
/// S(a, x) = (x, r_b r̂(a) − r_b (a − a₀(x)) t̂(a)), a₀(x) = x tan β_b / r_b (a right-hand
/// helix turns positively about +x as x grows, ISO 21771), oriented along +t̂(a) transversally.
Eigen::Vector3d helicoidNormal(double rb, double beta_b, double a, double x) {
  auto S = [&](double a_, double x_) {
    const double a0 = x_ * std::tan(beta_b) / rb;
    const Eigen::Vector2d r(std::cos(a_), std::sin(a_)), t(-std::sin(a_), std::cos(a_));
    const Eigen::Vector2d p = rb * r - rb * (a_ - a0) * t;
    return Eigen::Vector3d(x_, p.x(), p.y());
  };
  const double h = 1e-6;
  const Eigen::Vector3d da = (S(a + h, x) - S(a - h, x)) / (2 * h);
  const Eigen::Vector3d dx = (S(a, x + h) - S(a, x - h)) / (2 * h);
  Eigen::Vector3d n = da.cross(dx).normalized();
  const Eigen::Vector3d t(0.0, -std::sin(a), std::cos(a));
  return n.dot(t) > 0 ? n : Eigen::Vector3d(-n);
}

TEST(TrainFullDofs, HelicalMeshNormalIsTheInvoluteHelicoidNormal) {
  const GearTrainModel model(flexibleReducer(15.0, 0.05));
  const TrainMesh& m = model.meshes()[0];  // z1 (right hand) drives z2 about +x
  const int a0 = model.bodies()[m.body_a].first_dof;
  Eigen::Vector3d n(0, 0, 0);
  for (std::size_t i = 0; i < m.dofs.size(); ++i) {
    if (m.dofs[i] == a0 + 3) n.x() = m.gradient[i];
    if (m.dofs[i] == a0) n.y() = m.gradient[i];
    if (m.dofs[i] == a0 + 1) n.z() = m.gradient[i];
  }
  // The flank turns z1 positively: its transverse normal is +t̂ at the base tangent point.
  const Eigen::Vector2d r = m.pitch_point - model.bodies()[m.body_a].centre;
  ASSERT_GT(r.x() * m.normal.y() - r.y() * m.normal.x(), 0.0);
  const double a = std::atan2(-m.normal.x(), m.normal.y());  // t̂(a) = n_t
  const Eigen::Vector3d expected = helicoidNormal(m.base_radius_a, m.base_helix_angle, a, 0.01);
  // Finite differences of step 1e-6 on O(1) functions: 1e-8.
  EXPECT_NEAR(n.normalized().x(), expected.x(), 1e-8);
  EXPECT_NEAR(n.normalized().y(), expected.y(), 1e-8);
  EXPECT_NEAR(n.normalized().z(), expected.z(), 1e-8);
  EXPECT_LT(n.x(), 0.0) << "a right-hand driver pushes the driven gear towards -x";
}

TEST(TrainFullDofs, AxialThrustIsTangentialForceTimesTanBetaW) {
  const GearTrainModel model(flexibleReducer(15.0, 0.05));
  const TrainStaticResult st = solveTrainStatic(model, model.inputSpeed());
  ASSERT_EQ(st.status, "ok") << st.message;
  // Stage 1: T = 200 N m on z1; F_t = T / r_w1; F_a = F_t tan β_w, tan β_w = tan β_b / cos α_wt.
  const TrainMesh& m = model.meshes()[0];
  const double rw1 = m.base_radius_a / std::cos(m.pressure_angle);
  const double fa = 200.0 / rw1 * std::tan(m.base_helix_angle) / std::cos(m.pressure_angle);
  // The intermediate shaft: z2 (left hand, driven by z1 turning about +x) is pushed towards
  // −x; z3 (right hand) drives z4 turning about −x, and by the hand rule its own thrust is
  // along −x too: the two add (gears of one hand on the intermediate shaft would cancel).
  const TrainMesh& m2 = model.meshes()[1];
  const double t2 = 200.0 * 51.0 / 23.0;
  const double fa2 = t2 / (m2.base_radius_a / std::cos(m2.pressure_angle)) *
                     std::tan(m2.base_helix_angle) / std::cos(m2.pressure_angle);
  double input_axial = 0, output_axial = 0, intermediate_axial = 0;
  for (std::size_t e = 0; e < model.elements().size(); ++e) {
    const auto& el = model.elements()[e];
    if (el.name == "input_a.axial") input_axial = st.element_load[e].force;
    if (el.name == "intermediate_a.axial") intermediate_axial = st.element_load[e].force;
    if (el.name == "output_a.axial") output_axial = st.element_load[e].force;
  }
  // Statics of linear springs: exact up to the solve's round-off.
  EXPECT_NEAR(input_axial, fa, 1e-8 * fa);
  EXPECT_NEAR(output_axial, fa2, 1e-8 * fa2);
  EXPECT_NEAR(intermediate_axial, fa + fa2, 1e-8 * fa);
  // Direction: z2 (driven by right-hand z1 turning about +x) is pushed towards −x.
  const int z2 = model.bodyAt(2, 0.08, "test");
  EXPECT_LT(st.displacement(model.bodies()[z2].first_dof + 3), 0.0);
}

TEST(TrainFullDofs, StiffFlexibleShaftsApproachRigidOnes) {
  // E × 10⁴: the shafts' bending is 10⁴ times stiffer than the bearings and meshes that set
  // the modes, so the frequencies approach the rigid model's to ~1e-4 (bound 1e-3).
  const GearTrainModel rigid(flexibleReducer(10.0, 0.05, 2.1e11, false));
  const GearTrainModel stiff(flexibleReducer(10.0, 0.05, 2.1e15, true));
  TrainModalOptions options;
  options.modes = 14;
  const auto a = trainModes(rigid, 0.0, options);
  const auto b = trainModes(stiff, 0.0, options);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t j = 0; j < a.size(); ++j) {
    if (a[j].frequency < 1e-3) continue;  // the rolling mode
    EXPECT_NEAR(b[j].frequency, a[j].frequency, 1e-3 * a[j].frequency) << "mode " << j;
  }
}

TEST(TrainFullDofs, ModesOfAFlexibleTrainAtSpeedAreFiniteAndSplitByGyroscopics) {
  const GearTrainModel model(flexibleReducer(15.0, 0.03));
  EXPECT_GT(model.dofCount(), 200);
  TrainModalOptions options;
  options.modes = 20;
  const auto rest = trainModes(model, 0.0, options);
  const auto fast = trainModes(model, 10.0 * model.inputSpeed(), options);
  ASSERT_EQ(rest.size(), 20u);
  for (const auto& m : fast) EXPECT_TRUE(std::isfinite(m.frequency));
  // The gyroscopic matrix is skew and nonzero at speed.
  EXPECT_GT(model.gyroscopic().norm(), 0.0);
  EXPECT_LT((model.gyroscopic() + model.gyroscopic().transpose()).norm(),
            1e-12 * model.gyroscopic().norm());
}

TEST(TrainFullDofs, ShiftInvertModesAreTheDenseSolversLowestModes) {
  const GearTrainModel model(flexibleReducer(12.0, 0.04));
  ASSERT_GE(model.dofCount(), kSparseModalDofs);
  for (double speed : {0.0, 3.0 * model.inputSpeed()}) {
    TrainModalOptions few;
    few.modes = 12;
    const auto sparse = trainModes(model, speed, few);
    const auto dense = trainModes(model, speed);  // all modes: the dense solver
    ASSERT_EQ(sparse.size(), 12u);
    // Both converge to round-off of the eigenproblem (Arnoldi tolerance 1e-12): 1e-8.
    for (std::size_t j = 0; j < sparse.size(); ++j) {
      EXPECT_NEAR(sparse[j].frequency, dense[j].frequency, 1e-8 * dense[j].frequency)
          << "mode " << j << " at " << speed << " rad/s";
      EXPECT_NEAR(sparse[j].damping_ratio, dense[j].damping_ratio, 1e-8) << "mode " << j;
    }
  }
}

// Without axial support a spur train has a free axial translation per shaft: with the
// rolling mode, 5 rigid-body modes (10 eigenvalues at λ = 0) come before the elastic ones, more
// than the first Arnoldi run's margin, so the shift-invert path must ask again.
TEST(TrainFullDofs, ShiftInvertModesSkipManyRigidBodyModes) {
  GearTrainSpec spec = flexibleReducer(0.0, 0.04);
  for (auto& b : spec.bearings) b.k_axial = 0.0, b.c_axial = 0.0;
  const GearTrainModel model(spec);
  ASSERT_GE(model.dofCount(), kSparseModalDofs);
  TrainModalOptions few;
  few.modes = 8;
  const auto sparse = trainModes(model, 0.0, few);
  const auto dense = trainModes(model, 0.0);
  ASSERT_EQ(sparse.size(), 8u);
  for (std::size_t j = 0; j < sparse.size(); ++j) {
    EXPECT_NEAR(sparse[j].frequency, dense[j].frequency, 1e-8 * dense[j].frequency) << j;
  }
  // A Campbell diagram takes the same path with each Arnoldi run started from the previous
  // speed's eigenvectors (and afresh when the margin widens): at its last speed, the dense
  // solver's lowest modes to the same 1e-8.
  const std::vector<double> speeds{0.0, 0.5 * model.inputSpeed(), model.inputSpeed()};
  const TrainCampbell campbell = trainCampbell(model, speeds, few, {});
  const auto last = trainModes(model, speeds.back());
  ASSERT_EQ(campbell.modes.back().size(), 8u);
  std::vector<double> tracked;
  for (const auto& m : campbell.modes.back()) tracked.push_back(m.frequency);
  std::sort(tracked.begin(), tracked.end());
  for (std::size_t j = 0; j < tracked.size(); ++j) {
    EXPECT_NEAR(tracked[j], last[j].frequency, 1e-8 * last[j].frequency) << j;
  }
}

// The memory check comes before the nodes and matrices are allocated: the model's own size
// is the limit's boundary (10 dense n×n doubles), on either side of it.
TEST(TrainFullDofs, AModelOverTheMemoryLimitIsRefusedNamingTheKey) {
  const GearTrainModel fits(flexibleReducer(0.0, 0.04));
  const double n = fits.dofCount();
  const double bytes = GearTrainModel::kDenseMatrices * n * n * sizeof(double);
  EXPECT_NO_THROW(GearTrainModel(flexibleReducer(0.0, 0.04), bytes));
  try {
    GearTrainModel(flexibleReducer(0.0, 0.04), 0.99 * bytes);
    ADD_FAILURE() << "accepted over the limit";
  } catch (const InputError& e) {
    // The last flexible shaft's nodes push the count over; rigid ones are checked as a whole.
    EXPECT_EQ(e.key(), "shafts.output.max_element_length") << e.what();
    EXPECT_NE(std::string(e.what()).find("0.04 m"), std::string::npos) << e.what();
  }
  try {
    GearTrainModel(flexibleReducer(0.0, 0.04, 2.1e11, false), 1e3);
    ADD_FAILURE() << "accepted over the limit";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "gearbox.dofs") << e.what();
  }
}

TEST(TrainFullDofs, SparseAndDenseNewmarkStepsAgree) {
  const GearTrainModel model(testing::flexibleReducer(12.0, 0.05));
  ASSERT_GE(model.dofCount(), kSparseTrainDofs);
  const double dt = 2e-5;
  TrainNewmarkStepper sparse(model, model.inputSpeed(), dt,
                             NewmarkParameters::averageAcceleration());
  TrainNewmarkStepper dense(model, model.inputSpeed(), dt, NewmarkParameters::averageAcceleration(),
                            false);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model.dofCount());
  sparse.reset(0.0, zero, zero);
  dense.reset(0.0, zero, zero);
  for (int k = 0; k < 300; ++k) sparse.step(), dense.step();
  // Two LU factorisations of one matrix: round-off, accumulated by the rolling mode (1e-9).
  EXPECT_LT((sparse.displacement() - dense.displacement()).norm(),
            1e-9 * dense.displacement().norm());
  EXPECT_NEAR(sparse.meshForce(0), dense.meshForce(0), 1e-9 * std::abs(dense.meshForce(0)));
}

void expectInputError(GearTrainSpec spec, const std::string& key) {
  try {
    GearTrainModel model(std::move(spec));
    ADD_FAILURE() << "accepted; expected an error naming " << key;
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), key) << e.what();
  }
}

TEST(TrainFullDofs, PositionsOutsideTheShaftAndNonOverlappingGearsAreRefused) {
  auto spec = flexibleReducer();
  spec.gears[0].position = 0.26;  // the input shaft is 0.25 m long
  expectInputError(spec, "gears.z1.position");
  spec = flexibleReducer();
  spec.bearings[0].position = -0.01;
  expectInputError(spec, "bearings.input_a.position");
  spec = flexibleReducer();
  spec.gears[1].position = 0.15;  // z2 no longer faces z1
  expectInputError(spec, "gears.z2.position");
  spec = flexibleReducer();
  spec.dofs = TrainDofs::kPlanar;
  expectInputError(spec, "shafts.input.flexible");
  spec = flexibleReducer();
  spec.shafts[0].diametral_inertia = 0.0;  // the rigid motor
  expectInputError(spec, "shafts.motor.diametral_inertia");
}

}  // namespace
}  // namespace geardyn
