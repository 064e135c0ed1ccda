/// A gear train joined to a reduced housing at its bearings (issue #37, item 3, first part):
/// against a hand-built lumped model, and a very stiff housing against the rigid one.

#include "geardyn/system/housing_coupling.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cstdio>
#include <numbers>

#include "geardyn/error.h"
#include "support/numeric_assertions.h"
#include "system/nonlinear_sample_trains.h"

namespace geardyn {
namespace {

using geardyn::testing::isClose;

/// The single spur pair of the clearance tests, planar, linear, on two bearings to the housing.
GearTrainSpec pairOnBearings() {
  GearTrainSpec spec = testing::nonlinear::singlePair(0.0);
  spec.dofs = TrainDofs::kPlanar;
  spec.shafts[0].mass = 1.5;
  spec.shafts[1].mass = 4.0;
  spec.meshes[0].contact = {};
  TrainBearingSpec pinion{"pinion_bearing", "pinion_shaft", "", 1e8, 1e8};
  pinion.cyy = pinion.czz = 300.0;
  TrainBearingSpec gear{"gear_bearing", "gear_shaft", "", 3e8, 3e8};
  gear.cyy = gear.czz = 600.0;
  spec.bearings = {pinion, gear};
  return spec;
}

/// Two seats, each a rigid block of mass m and rotary inertia j on springs k (translations)
/// and k_r (rotations) to the ground; centred at the bearing points plus `offset` [m].
ReducedHousing blocksOnSprings(const GearTrainModel& model, double k, double k_r, double m,
                               double j, const Eigen::Vector3d& offset) {
  ReducedHousing h;
  h.seats = {"SEAT_P", "SEAT_G"};
  for (int s = 0; s < 2; ++s) {
    const Eigen::Vector2d c = model.bodies()[static_cast<std::size_t>(s)].centre;
    h.centres.push_back(Eigen::Vector3d(0.0, c.x(), c.y()) + offset);
  }
  Eigen::VectorXd kd(12), md(12);
  kd << k, k, k, k_r, k_r, k_r, k, k, k, k_r, k_r, k_r;
  md << m, m, m, j, j, j, m, m, m, j, j, j;
  h.K = kd.asDiagonal();
  h.M = md.asDiagonal();
  return h;
}

const std::vector<HousingLink> kLinks = {{"pinion_bearing", "SEAT_P"}, {"gear_bearing", "SEAT_G"}};

TEST(HousingCoupling, MatchesAHandBuiltLumpedModel) {
  const GearTrainModel model(pairOnBearings());
  ASSERT_EQ(model.bodies().size(), 2u);
  // The seats' centres 20 mm below the bearings (r = p − c = (0, 0, r_z)): the seat's rotation
  // θ_x moves the bearing point by −θ_x r_z along y. They also lie 50 mm along the axis, which a
  // planar train ignores (its bearings sit in their seats' planes).
  const double rz = 0.02;
  const double k = 5e9, k_r = 2e6, m = 3.0, j = 0.02, beta = 1e-5;
  const ReducedHousing h = blocksOnSprings(model, k, k_r, m, j, {0.05, 0.0, -rz});
  const HousedTrain t = coupleHousing(model, h, kLinks, 0.0, beta);

  // By hand: the train's own matrices, the blocks, and for each bearing (k_b, c_b isotropic)
  // d_y = y_shaft − (u_y − θ_x r_z), d_z = z_shaft − u_z of its seat.
  const int n = model.dofCount();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n + 12, n + 12), M = K, C = K;
  K.topLeftCorner(n, n) = model.meanStiffnessAt(0.0);
  C.topLeftCorner(n, n) = model.dampingAt(0.0);
  M.topLeftCorner(n, n) = model.mass();
  K.bottomRightCorner(12, 12) = h.K;
  M.bottomRightCorner(12, 12) = h.M;
  C.bottomRightCorner(12, 12) = beta * h.K;
  const double kb[2] = {1e8, 3e8}, cb[2] = {300.0, 600.0};
  for (int s = 0; s < 2; ++s) {
    const int y = model.translationDof(s), z = y + 1, h0 = n + 6 * s;
    // Housing-side coefficients of d_y: u_y −1, θ_x +r_z; of d_z: u_z −1.
    const std::vector<std::pair<int, double>> dy = {{h0 + 1, -1.0}, {h0 + 3, rz}};
    const std::vector<std::pair<int, double>> dz = {{h0 + 2, -1.0}};
    for (auto [A, c] : {std::pair{&K, kb[s]}, std::pair{&C, cb[s]}}) {
      for (const auto& [row, coeffs] : {std::pair{y, dy}, std::pair{z, dz}}) {
        for (const auto& [a, va] : coeffs) {
          (*A)(row, a) += c * va;
          (*A)(a, row) += c * va;
          for (const auto& [b, vb] : coeffs) (*A)(a, b) += c * va * vb;
        }
      }
    }
  }
  // Sums of a few products of the same numbers: round-off of the largest entry.
  EXPECT_TRUE(isClose(t.K, K, 0.0, 1e-12 * K.cwiseAbs().maxCoeff()));
  EXPECT_TRUE(isClose(t.C, C, 0.0, 1e-12 * C.cwiseAbs().maxCoeff()));
  EXPECT_TRUE(isClose(t.M, M, 0.0, 0.0));
  EXPECT_EQ(t.housing_first_dof, n);
}

TEST(HousingCoupling, AVeryStiffHousingGivesTheRigidHousingsFrequencies) {
  const GearTrainModel model(pairOnBearings());
  const int n = model.dofCount();
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> rigid(model.meanStiffnessAt(0.0),
                                                                  model.mass());
  // Seats 1e4 × stiffer than the stiffest bearing (3e8 N/m), 1 kg: the bearings' deflection
  // takes all but k_b/k_h = 1e-4 of the load, so a frequency shifts by about half that, 5e-5.
  // The tolerance: 1e-4.
  const ReducedHousing h =
      blocksOnSprings(model, 3e12, 3e12 * 0.05 * 0.05, 1.0, 1e-3, {0.01, 0.0, 0.0});
  const HousedTrain t = coupleHousing(model, h, kLinks);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> housed(t.K, t.M);
  double worst = 0.0;
  for (int i = 0; i < n; ++i) {
    const double w0 = std::sqrt(std::max(rigid.eigenvalues()[i], 0.0));
    const double w = std::sqrt(std::max(housed.eigenvalues()[i], 0.0));
    if (w0 < 1.0) {  // the pair's free rotation
      EXPECT_LT(w, 1.0);
      continue;
    }
    worst = std::max(worst, std::abs(w / w0 - 1.0));
    EXPECT_TRUE(isClose(w, w0, 1e-4)) << "mode " << i;
    EXPECT_LE(w, w0 * (1.0 + 1e-12)) << "a flexible housing only softens";
  }
  std::printf("housing 1e4 x stiffer than the bearings: worst frequency error %.3g\n", worst);
  EXPECT_GT(worst, 0.0);  // the housing is there
}

TEST(HousingCoupling, NamesTheBearingOrSeat) {
  const GearTrainModel model(pairOnBearings());
  const ReducedHousing h = blocksOnSprings(model, 1e9, 1e6, 1.0, 1e-3, Eigen::Vector3d::Zero());
  auto keyOf = [&](const std::vector<HousingLink>& links) {
    try {
      coupleHousing(model, h, links);
    } catch (const InputError& e) {
      return std::string(e.key()) + " | " + e.what();
    }
    return std::string("(accepted)");
  };
  EXPECT_NE(keyOf({{"pinion_bearin", "SEAT_P"}, {"gear_bearing", "SEAT_G"}})
                .find("housing.seats.pinion_bearin | "),
            std::string::npos);
  EXPECT_NE(keyOf({{"pinion_bearin", "SEAT_P"}}).find("did you mean \"pinion_bearing\""),
            std::string::npos);
  EXPECT_NE(keyOf({{"pinion_bearing", "SEAT_X"}}).find("housing.seats.pinion_bearing"),
            std::string::npos);
  EXPECT_NE(keyOf({{"pinion_bearing", "SEAT_P"}}).find("housing.seats | "), std::string::npos)
      << "a seat without a bearing";
}

}  // namespace
}  // namespace geardyn
