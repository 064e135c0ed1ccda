// The Newmark step of a gear train allocates nothing, on the dense path (lumped trains) and on
// the sparse one (FE gearboxes: detail::SparseLuFactors instead of SparseLU's solve, whose
// supernodal sweep allocates an n-vector per call), counted by the interposed malloc of
// support/counting_malloc.h.

#include <gtest/gtest.h>

#include <Eigen/Sparse>
#include <memory>
#include <numbers>
#include <vector>

#include "geardyn/numerics/sparse_lu_factors.h"
#include "geardyn/solvers/train_nonlinear_time.h"
#include "geardyn/solvers/train_time.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "support/counting_malloc.h"
#include "system/sample_trains.h"
#include "system/tooth_pair_trains.h"

namespace geardyn {
namespace {

std::shared_ptr<const MeshStiffness> varying(double mean) {
  return std::make_shared<FourierMeshStiffness>(mean, std::vector<double>{0.12, 0.05},
                                                std::vector<double>{0.0, 0.3}, 1.6);
}

long allocationsOverSteps(const GearTrainModel& model, bool sparse) {
  TrainNewmarkStepper stepper(model, model.inputSpeed(), 1e-5,
                              NewmarkParameters::averageAcceleration(), sparse);
  stepper.reset(0.0, Eigen::VectorXd::Zero(model.dofCount()),
                Eigen::VectorXd::Zero(model.dofCount()));
  stepper.step();  // warm-up
  testing::AllocationCounter counter;
  for (int s = 0; s < 500; ++s) stepper.step();
  const long count = counter.count();
  EXPECT_TRUE(std::isfinite(stepper.displacement().norm()));
  return count;
}

TEST(TrainNewmarkAllocation, DenseStepsAllocateNothing) {
  const GearTrainModel model(testing::twoStageReducer(varying(4e8), varying(6e8)));
  EXPECT_EQ(allocationsOverSteps(model, false), 0);
}

TEST(TrainNewmarkAllocation, SparseStepsAllocateNothing) {
  // 4 helical stages on 5 flexible shafts, six DOFs per node, every mesh varying.
  const GearTrainModel model(testing::flexibleChain(4, 0.03, varying(4e8)));
  ASSERT_GE(model.dofCount(), kSparseTrainDofs);
  EXPECT_EQ(allocationsOverSteps(model, true), 0);
}

// Along a run-up (TrainSpeedRamp): the mesh phases from the ramp's angle, and, on the dense
// path, the refactorisations of the speed-dependent matrices (a planetary stage's carrier-frame
// G₁ and K_Ω) allocate nothing. The sparse path's refactorisation allocates (SparseLU's
// analysis, train_time.h); its steps between refactorisations do not.
TEST(TrainNewmarkAllocation, RunUpStepsAndRefactorisationsAllocateNothing) {
  GearTrainSpec spec = testing::linParker1999(3);
  for (auto& stage : spec.stages)
    stage.sun_planet_stiffness = stage.ring_planet_stiffness = varying(5e8);
  const GearTrainModel model(spec);
  ASSERT_GT(model.gyroscopic().cwiseAbs().maxCoeff(), 0.0);
  const double speed = 2000.0 * std::numbers::pi / 30.0;
  TrainNewmarkStepper stepper(model, TrainSpeedRamp{0.5 * speed, speed, 5e-3}, 1e-5,
                              NewmarkParameters::averageAcceleration(), 1e-3, false);
  stepper.reset(0.0, Eigen::VectorXd::Zero(model.dofCount()),
                Eigen::VectorXd::Zero(model.dofCount()));
  stepper.step();  // warm-up
  testing::AllocationCounter counter;
  for (int s = 0; s < 500; ++s) stepper.step();  // the whole ramp
  EXPECT_EQ(counter.count(), 0);
  EXPECT_GT(stepper.factorisations(), 400);  // a 50 % speed change, 0.1 % per factorisation
  EXPECT_TRUE(std::isfinite(stepper.displacement().norm()));
}

TEST(TrainNewmarkAllocation, SparseRunUpStepsAllocateNothing) {
  const GearTrainModel model(testing::flexibleChain(4, 0.03, varying(4e8)));
  ASSERT_GE(model.dofCount(), kSparseTrainDofs);
  const double speed = model.inputSpeed();
  // Tolerance 0.5: no refactorisation in the counted steps (1 % speed change).
  TrainNewmarkStepper stepper(model, TrainSpeedRamp{speed, 1.01 * speed, 5e-3}, 1e-5,
                              NewmarkParameters::averageAcceleration(), 0.5, true);
  stepper.reset(0.0, Eigen::VectorXd::Zero(model.dofCount()),
                Eigen::VectorXd::Zero(model.dofCount()));
  stepper.step();  // warm-up
  testing::AllocationCounter counter;
  for (int s = 0; s < 500; ++s) stepper.step();
  EXPECT_EQ(counter.count(), 0);
  EXPECT_TRUE(std::isfinite(stepper.displacement().norm()));
}

// The nonlinear Newmark step with tooth-pair meshes: the elements are refilled per step into the
// tables sized at construction (train_tooth_pairs.h), Newton works in preallocated storage, and
// steps taken again in halves at events reuse the factorisations and saved states built at
// construction (some must happen in the counted steps: pairs enter and leave contact).
TEST(TrainNonlinearNewmarkAllocation, ToothPairStepsAllocateNothing) {
  GearTrainSpec spec = testing::nonlinear::withToothPairs(
      testing::twoStageReducer(varying(4e8), varying(6e8)), {6000.0, 12000.0});
  const GearTrainModel model(spec);
  TrainNonlinearNewmark stepper(model, model.inputSpeed(), 1e-6,
                                NewmarkParameters::averageAcceleration(), 6, 2);
  stepper.reset(0.0, Eigen::VectorXd::Zero(model.dofCount()),
                Eigen::VectorXd::Zero(model.dofCount()));
  stepper.step(1e-13, 50);  // warm-up
  const long long refined = stepper.refinedSteps();
  testing::AllocationCounter counter;
  for (int s = 0; s < 500; ++s) stepper.step(1e-13, 50);
  EXPECT_EQ(counter.count(), 0);
  EXPECT_GT(stepper.refinedSteps(), refined);  // measured: 8 halvings
  EXPECT_TRUE(std::isfinite(stepper.displacement().norm()));
}

TEST(SparseLuFactorsAllocation, SolvesAllocateNothing) {
  Eigen::SparseMatrix<double> A(50, 50);
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < 50; ++i) {
    t.emplace_back(i, i, 4.0 + i);
    t.emplace_back(i, (i + 7) % 50, 1.0);
    t.emplace_back((i + 3) % 50, i, -0.5);
  }
  A.setFromTriplets(t.begin(), t.end());
  detail::SparseLuFactors lu;
  ASSERT_TRUE(lu.factorize(A));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(50, -1.0, 1.0);
  Eigen::VectorXd x(50);
  testing::AllocationCounter counter;
  for (int k = 0; k < 10; ++k) lu.solve(b, x);
  EXPECT_EQ(counter.count(), 0);
  EXPECT_LT((A * x - b).norm(), 1e-13 * b.norm());
}

}  // namespace
}  // namespace geardyn
