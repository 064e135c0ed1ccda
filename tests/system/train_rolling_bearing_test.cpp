/// Rolling bearings from their geometry in a gear train: the nonlinear static deflection
/// against the single-bearing solver, the linearised train against central differences of the
/// internal force, and the input checks.

#include <gtest/gtest.h>

#include <memory>

#include "geardyn/error.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/system/gear_train_model.h"
#include "support/numeric_assertions.h"
#include "system/rolling_bearing_trains.h"

namespace geardyn {
namespace {

using testing::withRollingBearings;

/// R(q) = K̄ q + Σ Jᵀ F_b(J q) (without the loads).
Eigen::VectorXd internalForce(const GearTrainModel& model, const Eigen::VectorXd& q) {
  Eigen::VectorXd R = model.meanStiffnessAt(model.inputSpeed()) * q;
  for (const TrainRollingBearing& b : model.rollingBearings()) {
    RollingBearing::Vector5 F;
    b.bearing->evaluate(b.displacement(q), F, nullptr);
    for (std::size_t i = 0; i < b.dofs.size(); ++i) {
      R(b.dofs[i]) += b.jacobian.col(static_cast<Eigen::Index>(i)).dot(F);
    }
  }
  return R;
}

TEST(TrainRollingBearings, StaticDeflectionAgreesWithTheSingleBearingSolver) {
  // Planar reducer: the two bearings of a rigid shaft sit at one body, so each carries half its
  // reaction; the bearing alone, solved for that load (RollingBearing::solve, a second
  // solver), must sit at the train's bearing deflection. Both converge to 1e-10 of their loads;
  // the deflection then agrees to the stiffness' conditioning, 1e-7.
  const GearTrainModel model(withRollingBearings(testing::twoStageReducer()));
  ASSERT_EQ(model.rollingBearings().size(), 6u);
  const TrainStaticResult r = solveTrainStatic(model, model.inputSpeed());
  ASSERT_EQ(r.status, "ok") << r.message;
  EXPECT_LT(r.residual, 1e-10);
  EXPECT_GT(r.iterations, 1);
  ASSERT_EQ(r.rolling_bearings.size(), 6u);
  for (std::size_t i = 0; i < 6; ++i) {
    const RollingBearingState& s = r.rolling_bearings[i];
    EXPECT_GT(std::hypot(s.load(0), s.load(1)), 100.0);  // the meshes load every shaft
    const RollingBearingSolveResult alone = model.rollingBearings()[i].bearing->solve(s.load);
    ASSERT_EQ(alone.status, "converged");
    EXPECT_CLOSE(alone.state.displacement.head<2>(), s.displacement.head<2>(), 1e-7,
                 1e-7 * s.displacement.head<2>().norm());
  }
  // Static equilibrium of the input shaft: its two bearings react the stage-1 mesh force.
  const double bearings = std::hypot(r.rolling_bearings[0].load(0) + r.rolling_bearings[1].load(0),
                                     r.rolling_bearings[0].load(1) + r.rolling_bearings[1].load(1));
  EXPECT_CLOSE(bearings, std::abs(r.mesh_force[0]), 1e-8);
}

TEST(TrainRollingBearings, LinearisedTrainIsTheTangentOfTheNonlinearOne) {
  // Full DOFs, flexible shafts, bearings along them: the linearised model's stiffness equals
  // the central differences of the internal force at the static deflection. Step 1e-10 m
  // against deflections of ~10 µm: truncation 1e-10, round-off ε × 1e5; 1e-6 of the largest
  // entry.
  GearTrainSpec spec = withRollingBearings(testing::flexibleReducer());
  const GearTrainModel model(spec);
  const TrainStaticResult r = solveTrainStatic(model, model.inputSpeed());
  ASSERT_EQ(r.status, "ok") << r.message;
  const GearTrainModel linear = model.linearisedAt(r.displacement);
  EXPECT_TRUE(linear.rollingBearings().empty());
  const Eigen::MatrixXd K = linear.meanStiffnessAt(linear.inputSpeed());
  const Eigen::Index n = K.rows();
  Eigen::MatrixXd fd(n, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const double h =
        model.dofName(static_cast<int>(j)).find("theta") != std::string::npos ? 3e-9 : 1e-10;
    Eigen::VectorXd plus = r.displacement, minus = r.displacement;
    plus(j) += h, minus(j) -= h;
    fd.col(j) = (internalForce(model, plus) - internalForce(model, minus)) / (2.0 * h);
  }
  EXPECT_CLOSE(K, fd, 0.0, 1e-6 * K.cwiseAbs().maxCoeff());
}

TEST(TrainRollingBearings, StiffnessKeysWithGeometryNameTheKey) {
  GearTrainSpec spec = withRollingBearings(testing::twoStageReducer());
  spec.bearings[2].kyy = 4e8;
  try {
    const GearTrainModel model(spec);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "bearings.intermediate_a.kyy");
  }
}

}  // namespace
}  // namespace geardyn
