// The plane of k, F and the STE of a helical pair (docs/theory/mesh_stiffness.md, "Which
// plane"), on the 21/37 pair of issue 18 (m_n 3 mm, β 15°, 200 N m): the gear-pair commands
// work along the transverse line of action, the normal-plane values follow from
// F_n = F_t / cos β_b, δ_n = δ_t cos β_b, k_n = k_t / cos² β_b, helical_cos2_beta_b scales the
// slice sum by cos² β_b, and a gear train applies k along the contact normal (torsional
// stiffness k cos² β_b r_b²).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geardyn/analysis/analyses.h"
#include "geardyn/config/config.h"
#include "geardyn/geometry/gear_pair.h"
#include "geardyn/stiffness/mesh_stiffness_summary.h"
#include "geardyn/stiffness/potential_energy_stiffness.h"
#include "geardyn/system/gear_train_model.h"
#include "system/sample_trains.h"

namespace geardyn {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

GearPairSpec issuePair() {
  GearPairSpec spec;
  spec.pinion = testing::spurGear(21, 3e-3, 20.0, 0.03);
  spec.gear = testing::spurGear(37, 3e-3, 20.0, 0.03);
  spec.pinion.helix_angle = 15.0 * kDeg;
  spec.gear.helix_angle = -15.0 * kDeg;
  spec.pinion.bore_diameter = 0.03;
  spec.gear.bore_diameter = 0.05;
  return spec;
}

/// β_b by hand: tan α_t = tan α_n / cos β, tan β_b = tan β cos α_t (ISO 21771).
double baseHelixByHand() {
  const double alpha_t = std::atan(std::tan(20.0 * kDeg) / std::cos(15.0 * kDeg));
  return std::atan(std::tan(15.0 * kDeg) * std::cos(alpha_t));
}

TEST(HelicalPlane, Cos2BetaBOptionScalesTheSliceSumByCosSquaredOfTheBaseHelix) {
  const GearPair pair(issuePair());
  const double beta_b = baseHelixByHand();
  ASSERT_NEAR(pair.baseHelixAngle(), beta_b, 1e-14);
  const PotentialEnergyMeshStiffness transverse(pair);  // Wan 2015: the slices are k_t
  PotentialEnergyOptions normal_options;
  normal_options.helical_cos2_beta_b = true;
  const PotentialEnergyMeshStiffness projected(pair, normal_options);
  for (double phase : {0.0, 0.13, 0.5, 0.77}) {
    // The same tables, scaled: equal to round-off.
    EXPECT_NEAR(projected.stiffness(phase),
                std::pow(std::cos(beta_b), 2) * transverse.stiffness(phase),
                1e-12 * transverse.stiffness(phase));
  }
}

TEST(HelicalPlane, StiffnessResultsGiveTheNormalPlaneValuesOfTheTransverseOnes) {
  const char* toml = R"(
[pinion]
teeth = 21
module = 0.003
helix_angle_deg = 15.0
face_width = 0.03
bore_diameter = 0.03
[gear]
teeth = 37
module = 0.003
helix_angle_deg = -15.0
face_width = 0.03
bore_diameter = 0.05
[mesh_stiffness]
positions = 200
transmitted_force = 6000.0
)";
  const config::Config config =
      config::parseConfig(toml, "test", analysis::analysisSchema("stiffness"));
  analysis::AnalysisContext context;
  context.config_source = "test.toml";
  const analysis::AnalysisResult result = analysis::runAnalysis("stiffness", config, context);
  const auto& r = result.summary.results;
  const auto& plane = r["plane"];
  ASSERT_EQ(plane["plane"], "transverse");
  const double cb = std::cos(baseHelixByHand());
  EXPECT_NEAR(plane["base_helix_angle_deg"].get<double>(), baseHelixByHand() / kDeg, 1e-12);
  const double k_t = r["mesh_stiffness"]["mean"].get<double>();
  const auto& ste = r["static_transmission_error"];
  const double f_t = ste["force"].get<double>(), delta_t = ste["mean"].get<double>();
  const auto& normal = plane["normal"];
  const double k_n = normal["stiffness_mean"].get<double>();
  const double f_n = normal["force"].get<double>(), delta_n = normal["ste_mean"].get<double>();
  EXPECT_NEAR(f_n, f_t / cb, 1e-12 * f_n);
  EXPECT_NEAR(delta_n, delta_t * cb, 1e-12 * delta_n);
  EXPECT_NEAR(k_n, k_t / (cb * cb), 1e-12 * k_n);
  // The tooth force does the same work in either description: F_n δ_n = F_t δ_t.
  EXPECT_NEAR(f_n * delta_n, f_t * delta_t, 1e-12 * f_t * delta_t);
  // The normal stiffness is the larger one (5.9 % for β_b = 14.08°).
  EXPECT_NEAR(k_n / k_t - 1.0, 1.0 / (cb * cb) - 1.0, 1e-12);
  EXPECT_GT(k_n / k_t, 1.06);
  // The transverse STE is δ = F/k: its mean lies at F times the mean compliance, ≥ F / k̄.
  EXPECT_GE(delta_t, f_t / k_t);
  // The CSV names the plane and the unit of what it holds.
  ASSERT_EQ(result.table_names.front(), "mesh_stiffness.csv");
  const auto& columns = result.tables.front().names();
  EXPECT_NE(std::find(columns.begin(), columns.end(), "k_total_transverse_n_per_m"), columns.end());
  EXPECT_NE(std::find(columns.begin(), columns.end(), "ste_transverse_m"), columns.end());
}

TEST(HelicalPlane, AGearTrainAppliesKAlongTheContactNormal) {
  // One helical pair as a torsional gear train, with the transverse potential-energy k: its
  // torsional stiffness on the pinion is k̄ cos² β_b r_b1², which is the SDOF model's k̄_t r_b1²
  // when simulate reads the same slices with helical_cos2_beta_b = true (docs: to compare
  // simulate with train or fe_rotor on a helical pair).
  const GearPairSpec pair_spec = issuePair();
  const GearPair pair(pair_spec);
  const auto k = std::make_shared<PotentialEnergyMeshStiffness>(pair);
  GearTrainSpec spec;
  spec.dofs = TrainDofs::kTorsional;
  spec.shafts = {{"pinion_shaft", 0.0, 2e-3, {}, {}, {}, 7850.0},
                 {"gear_shaft", 0.0, 9e-3, {}, {}, {}, 7850.0}};
  spec.gears = {{"pinion", "pinion_shaft", pair_spec.pinion, false, false},
                {"gear", "gear_shaft", pair_spec.gear, false, false}};
  spec.meshes = {{"pair", "pinion", "gear", 0.0, std::nullopt, k, {}, 0.05, std::nullopt}};
  spec.operating = {"pinion_shaft", 300.0, 200.0, "gear_shaft"};
  const GearTrainModel train(spec);
  const TrainMesh& m = train.meshes()[0];
  EXPECT_NEAR(m.base_helix_angle, baseHelixByHand(), 1e-12);
  double torsional = 0.0;  // k̄ (∂δ/∂θ_pinion)²
  for (std::size_t i = 0; i < m.dofs.size(); ++i) {
    if (m.dofs[i] == 0) torsional = m.mean_stiffness * m.gradient[i] * m.gradient[i];
  }
  const double rb1 = pair.pinion().base_radius, cb = std::cos(baseHelixByHand());
  EXPECT_NEAR(torsional, m.mean_stiffness * cb * cb * rb1 * rb1, 1e-12 * torsional);
  PotentialEnergyOptions projected;
  projected.helical_cos2_beta_b = true;
  const double k_t_mean =
      summarizeMeshStiffness(PotentialEnergyMeshStiffness(pair, projected), 0).mean;
  EXPECT_NEAR(torsional, k_t_mean * rb1 * rb1, 1e-9 * torsional);
}

}  // namespace
}  // namespace geardyn
