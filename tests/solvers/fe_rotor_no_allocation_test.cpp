// The Newmark step of the FE geared rotor (the train's stepper over the rotor's DOFs, with its
// unbalance forces as the stepper's force) allocates nothing (issue #8: "no allocation in the
// loop"), counted by the interposed malloc of support/counting_malloc.h.

#include <gtest/gtest.h>

#include <vector>

#include "geardyn/solvers/fe_rotor_response.h"
#include "geardyn/stiffness/potential_energy_stiffness.h"
#include "support/counting_malloc.h"
#include "support/fe_rotor_cases.h"

namespace geardyn {
namespace {

TEST(FeRotorNewmarkAllocation, TheCounterSeesAllocations) {
  testing::AllocationCounter counter;
  Eigen::VectorXd v(1000);      // Eigen's heap storage goes through malloc
  std::vector<double> w(1000);  // and so does operator new
  EXPECT_GE(counter.count(), 2);
  EXPECT_EQ(v.size() + w.size(), 2000u);
}

TEST(FeRotorNewmarkAllocation, StepsAllocateNothingAtConstantSpeedOrAlongARunUp) {
  const GearPair pair(testing::visnadiPairSpec(5.0));
  testing::FeRotorCase c =
      testing::visnadiFeRotor(std::make_shared<PotentialEnergyMeshStiffness>(pair), 5.0, 4);
  c.addUnbalance(0, 1, 1e-5, 0.0);
  c.train.meshes.front().transmission_error.addFourier({2e-6}, {0.3});
  for (double end : {500.0, 3000.0}) {
    c.setSpeed({500.0 * 3.14159265358979 / 30, end * 3.14159265358979 / 30, 0.0, 0.01});
    const FeRotorModel model = c.model();
    FeTimeOptions o;
    o.gyro_speed_tolerance = 1e-2;
    TrainNewmarkStepper stepper = feRotorStepper(model, o);
    stepper.reset(0.0, Eigen::VectorXd::Zero(model.dofCount()),
                  Eigen::VectorXd::Zero(model.dofCount()));
    stepper.step();  // warm-up
    testing::AllocationCounter counter;
    for (int s = 0; s < 1000; ++s) stepper.step();  // 10 ms: the whole ramp when end > start
    EXPECT_EQ(counter.count(), 0) << "end speed " << end << " rpm";
    if (end != 500.0) {
      EXPECT_GT(stepper.factorisations(), 50);  // refactorising is allocation-free too
    }
    EXPECT_TRUE(std::isfinite(stepper.displacement().norm()));
  }
}

}  // namespace
}  // namespace geardyn
