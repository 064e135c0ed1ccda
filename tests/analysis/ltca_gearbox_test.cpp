// `geardyn ltca` on a mesh of a gearbox (ltca_config.h, loadLtcaOnGearboxMesh): a gearbox whose
// mesh is the pair of examples/ltca_visnadi2021_long_relief.toml, at that example's 3 kN (the
// operating torque 3000 N × r_b1), gives the standalone example's tables to 1e-9; an unknown
// mesh is an InputError naming gearbox.mesh with a did-you-mean.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <variant>

#include "geardyn/analysis/analyses.h"
#include "geardyn/error.h"

namespace geardyn {
namespace {

namespace fs = std::filesystem;

const fs::path kExample =
    fs::path(GEARDYN_SOURCE_DIR) / "examples" / "ltca_visnadi2021_long_relief.toml";

/// The example's pair as a torsional gearbox (its gear and [modifications] keys under
/// [gears.*] and [meshes.pair.modifications]) driven at `torque` [N m].
std::string gearboxText(double torque) {
  return fmt::format(R"(
[gearbox]
name = "Visnadi 2021 pair"
dofs = "torsional"
[shafts.pinion_shaft]
mass = 1.0
polar_inertia = 1e-3
[shafts.gear_shaft]
mass = 1.5
polar_inertia = 2e-3
[gears.pinion]
shaft = "pinion_shaft"
teeth = 25
module = 0.003
face_width = 0.020
youngs_modulus = 200e9
poisson_ratio = 0.3
bore_diameter = 0.030
[gears.wheel]
shaft = "gear_shaft"
teeth = 30
module = 0.003
face_width = 0.020
youngs_modulus = 200e9
poisson_ratio = 0.3
bore_diameter = 0.030
[meshes.pair]
gears = ["pinion", "wheel"]
stiffness = "potential_energy"
contact = "tooth_pairs"
[meshes.pair.modifications]
relief = "long"
design_load = 3000.0
shape = "linear"
[operating_point]
input = "pinion_shaft"
speed_rpm = 1000.0
torque = {:.17g}
output = "gear_shaft"
)",
                     torque);
}

class LtcaGearbox : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        fs::temp_directory_path() /
        ("ltca_gearbox_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
         "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    // r_b1 = m z cos α / 2 with α = 20°: 3 kN along the line of action.
    const double rb1 = 0.5 * 0.003 * 25 * std::cos(20.0 * std::numbers::pi / 180.0);
    std::ofstream(dir_ / "pair_gearbox.toml") << gearboxText(3000.0 * rb1);
    std::ofstream(dir_ / "ltca_mesh.toml") << R"(
[gearbox]
file = "pair_gearbox.toml"
mesh = "pair"
[ltca]
positions = 200
[harris]
compare_reliefs = ["none", "short"]
)";
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

void expectTablesEqual(const analysis::AnalysisResult& a, const analysis::AnalysisResult& b,
                       double tolerance) {
  ASSERT_EQ(a.table_names, b.table_names);
  for (std::size_t t = 0; t < a.tables.size(); ++t) {
    const auto& x = a.tables[t];
    const auto& y = b.tables[t];
    const std::string& name = a.table_names[t];
    ASSERT_EQ(x.names(), y.names()) << name;
    ASSERT_EQ(x.rows(), y.rows()) << name;
    for (std::size_t c = 0; c < x.columns().size(); ++c) {
      const auto& u = x.columns()[c];
      const auto& v = y.columns()[c];
      if (const auto* p = std::get_if<std::vector<double>>(&u)) {
        const auto* q = std::get_if<std::vector<double>>(&v);
        ASSERT_NE(q, nullptr) << name << " " << x.names()[c];
        // Relative to the column's scale (a force in N, an STE in m).
        double scale = 0.0;
        for (double w : *q) scale = std::max(scale, std::abs(w));
        for (std::size_t r = 0; r < p->size(); ++r) {
          EXPECT_NEAR((*p)[r], (*q)[r], tolerance * scale)
              << name << " " << x.names()[c] << " " << r;
        }
      } else {
        EXPECT_EQ(u, v) << name << " " << x.names()[c];
      }
    }
  }
}

TEST_F(LtcaGearbox, MeshOfAGearboxGivesTheStandalonePairsTables) {
  const config::Config standalone = analysis::loadAnalysisConfig("ltca", kExample, {});
  const config::Config on_mesh = analysis::loadAnalysisConfig("ltca", dir_ / "ltca_mesh.toml", {});
  EXPECT_NEAR(on_mesh.real("ltca.force"), 3000.0, 1e-9 * 3000.0);  // the static mesh force
  EXPECT_EQ(on_mesh.string("modifications.relief"), "long");       // the mesh's
  const auto a = analysis::runAnalysis("ltca", standalone, {});
  const auto b = analysis::runAnalysis("ltca", on_mesh, {});
  ASSERT_GE(a.tables.size(), 3u);  // ltca, harris, harris_designs, load_statistics
  expectTablesEqual(b, a, 1e-9);
  EXPECT_EQ(b.summary.results["ltca"]["gearbox_mesh"], "pair");
  EXPECT_NEAR(b.summary.results["ltca"]["ste_peak_to_peak"].get<double>(),
              a.summary.results["ltca"]["ste_peak_to_peak"].get<double>(), 1e-9 * 1e-6);
}

TEST_F(LtcaGearbox, UnknownMeshIsAnInputErrorWithDidYouMean) {
  try {
    analysis::loadAnalysisConfig("ltca", dir_ / "ltca_mesh.toml", {"gearbox.mesh=\"pairr\""});
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "gearbox.mesh");
    EXPECT_NE(std::string(e.what()).find("did you mean 'pair'"), std::string::npos) << e.what();
  }
}

TEST_F(LtcaGearbox, AGivenForceAndModificationsOverrideTheMeshs) {
  const config::Config c = analysis::loadAnalysisConfig(
      "ltca", dir_ / "ltca_mesh.toml", {"ltca.force=1500.0", "modifications.relief=\"short\""});
  EXPECT_EQ(c.real("ltca.force"), 1500.0);
  EXPECT_EQ(c.string("modifications.relief"), "short");
  EXPECT_EQ(c.integer("pinion.teeth"), 25);
  EXPECT_EQ(c.integer("gear.teeth"), 30);
}

}  // namespace
}  // namespace geardyn
