// The gearbox of a gear-pair file (config/gear_pair_gearbox.h) reduced back to the gear-pair
// model (system/sdof_reduction.h) is the model the file's keys describe: the same keys
// assembled directly into the gear-pair model (config/gear_pair_keys.h, directGearPairModel)
// are the independent reference.

#include "geardyn/config/gear_pair_gearbox.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include "geardyn/config/gearbox_config.h"
#include "geardyn/config/hbm_config.h"
#include "geardyn/config/simulate_config.h"
#include "geardyn/config/stats_config.h"
#include "geardyn/config/translated_gearbox.h"
#include "geardyn/error.h"
#include "geardyn/stiffness/step_stiffness.h"
#include "geardyn/system/sdof_reduction.h"
#include "support/numeric_assertions.h"

namespace geardyn {
namespace {

namespace fs = std::filesystem;

// The translation writes every double in its shortest round-trip form; what remains is the
// round-off of I = 2 m_e r_b² → 1 / (r_a²/I_a + r_b²/I_b), of F r_b / r_b, of 60 f_m / z and
// back, and of phases in degrees and back: a few ulps.
constexpr double kTranslationTolerance = 1e-12;

/// Every field the solvers read, the old reading against the gearbox's reduction.
void expectSameModel(const GearPairModelSpec& reduced, const GearPairModelSpec& old,
                     const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_CLOSE(reduced.mass, old.mass, kTranslationTolerance);
  EXPECT_CLOSE(reduced.mean_force, old.mean_force, kTranslationTolerance);
  EXPECT_CLOSE(reduced.damping, old.damping, kTranslationTolerance);
  EXPECT_CLOSE(reduced.mesh_frequency, old.mesh_frequency, kTranslationTolerance);
  EXPECT_CLOSE(reduced.initial_phase, old.initial_phase, kTranslationTolerance);
  EXPECT_EQ(reduced.contact, old.contact);
  EXPECT_CLOSE(reduced.backlash, old.backlash, kTranslationTolerance);
  EXPECT_EQ(reduced.extra_forces.size(), old.extra_forces.size());
  ASSERT_EQ(reduced.contact_elements == nullptr, old.contact_elements == nullptr);
  if (old.contact_elements) {
    ASSERT_EQ(reduced.contact_elements->count(), old.contact_elements->count());
    for (int i = 0; i < 41; ++i) {
      const double phi = i / 41.0;
      for (int j = 0; j < old.contact_elements->count(); ++j) {
        double k_new = 0, g_new = 0, k_old = 0, g_old = 0;
        reduced.contact_elements->element(phi, j, k_new, g_new);
        old.contact_elements->element(phi, j, k_old, g_old);
        EXPECT_CLOSE(k_new, k_old, kTranslationTolerance, 1e-3) << "element " << j << " at " << phi;
        EXPECT_CLOSE(g_new, g_old, kTranslationTolerance, 1e-18)
            << "element " << j << " at " << phi;
      }
    }
  }
  ASSERT_TRUE(reduced.stiffness && old.stiffness);
  EXPECT_EQ(reduced.stiffness->model(), old.stiffness->model());
  EXPECT_CLOSE(reduced.stiffness->contactRatio(), old.stiffness->contactRatio(),
               kTranslationTolerance);
  double k_scale = 0.0, e_scale = 0.0;
  for (int i = 0; i < 97; ++i) {
    const double phi = i / 97.0;
    k_scale = std::max(k_scale, std::abs(old.stiffness->stiffness(phi)));
    e_scale = std::max(e_scale, std::abs(old.transmission_error.value(phi)));
  }
  for (int i = 0; i < 97; ++i) {
    const double phi = -0.3 + 2.1 * i / 97.0;  // over two periods and a negative phase
    EXPECT_CLOSE(reduced.stiffness->stiffness(phi), old.stiffness->stiffness(phi), 0.0,
                 kTranslationTolerance * k_scale)
        << "k at phase " << phi;
    EXPECT_CLOSE(reduced.transmission_error.value(phi), old.transmission_error.value(phi), 0.0,
                 kTranslationTolerance * e_scale)
        << "e at phase " << phi;
  }
}

config::ConfigSchema schemaOf(const std::string& stem) {
  if (stem.rfind("hbm_", 0) == 0) return config::hbmSchema();
  if (stem.rfind("stats_", 0) == 0) return config::statsSchema();
  return config::simulateSchema();
}

TEST(GearPairGearbox, EveryExampleReducesToItsModel) {
  int translated = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(GEARDYN_SOURCE_DIR) / "examples")) {
    const std::string stem = entry.path().stem().string();
    if (entry.path().extension() != ".toml") continue;
    if (stem.rfind("simulate_", 0) != 0 && stem.rfind("hbm_", 0) != 0 &&
        stem.rfind("stats_", 0) != 0) {
      continue;
    }
    SCOPED_TRACE(stem);
    const config::Config config = config::loadConfigFile(entry.path(), schemaOf(stem));
    if (config.resolved().contains("stats") && config.string("stats.source") != "model") {
      EXPECT_THROW(config::gearPairGearbox(config), InputError);  // no [model]: no gear pair
      continue;
    }
    const config::GearPairKeys keys = config::readGearPairKeys(config, false);
    std::vector<std::string> warnings;
    const GearPairModelSpec direct = config::directGearPairModel(config, keys, warnings);
    const std::string toml = config::gearPairGearbox(config);
    expectSameModel(config::gearPairFromGearbox(toml, stem), direct, stem);
    // What the commands run on is the reduction.
    expectSameModel(config::buildGearPairModel(config, false).spec, direct, stem + " (build)");
    ++translated;
  }
  EXPECT_GE(translated, 5);
}

/// Forms the examples do not show, written inline.
GearPairModelSpec reducedOf(const std::string& toml, GearPairModelSpec* old_spec = nullptr) {
  const config::Config config = config::parseConfig(toml, "inline", config::simulateSchema());
  std::vector<std::string> warnings;
  const GearPairModelSpec direct =
      config::directGearPairModel(config, config::readGearPairKeys(config, false), warnings);
  if (old_spec) *old_spec = direct;
  return config::gearPairFromGearbox(config::gearPairGearbox(config), "inline");
}

TEST(GearPairGearbox, OtherFormsReduceToTheirModel) {
  const std::string pair = R"(
[pinion]
teeth = 23
module = 0.004
face_width = 0.025
bore_diameter = 0.03
[gear]
teeth = 41
module = 0.004
face_width = 0.025
bore_diameter = 0.05
)";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"step levels, damping value, one-sided, rectangular and table TE", R"(
[model]
mass = 2.5
damping = 800.0
torque = 120.0
pinion_base_radius = 0.05
contact = "one_sided"
[model.stiffness]
type = "step"
k_min = 3e8
k_max = 4.5e8
contact_ratio = 1.63
[model.transmission_error]
rectangular_amplitude = 3e-6
rectangular_duty = 0.3
rectangular_start = 0.6
table_phases = [0.0, 0.25, 0.7]
table_values = [1e-6, -2e-6, 5e-7]
[excitation]
mesh_frequency = 612.5
initial_phase = 0.37
)"},
      {"Saletti contact elements", R"(
[model]
type = "gear_pair_contacts"
pinion_inertia = 0.0158
gear_inertia = 0.03
pinion_base_radius = 0.0705
gear_base_radius = 0.09
damping = 4038.2
torque = 100.0
contact_stiffness = 2.6e8
contact = "one_sided"
[model.stiffness]
contact_ratio = 1.75
[excitation]
mesh_frequency = 1234.5
)"},
      {"nondimensional step from the mean", R"(
[model]
units = "nondimensional"
damping_ratio = 0.07
mean_force = 0.4
[model.stiffness]
type = "step"
contact_ratio = 1.4
[excitation]
mesh_frequency = 0.9
)"},
      {"gear pair, Fourier with sines, backlash, speed of the pair", R"(
[model]
damping_ratio = 0.03
torque = 60.0
contact = "backlash"
normal_backlash = 6e-5
[model.stiffness]
type = "fourier"
mean = 5e8
cos = [-0.1, 0.02]
sin = [0.05, -0.01]
[model.transmission_error]
amplitudes = [2e-6, -5e-7]
phases_deg = [17.188733853924695, -68.75493541569878]
[pair]
speed_rpm = 2400.0
)" + pair},
      {"gear pair, potential-energy stiffness, linear", R"(
[model]
damping_ratio = 0.05
torque = 80.0
pinion_inertia = 1e-3
gear_inertia = 4e-3
[model.stiffness]
type = "potential_energy"
[excitation]
speed_rpm = 900.0
)" + pair},
      {"gear pair, API stiffness", R"(
[model]
damping_ratio = 0.05
torque = 80.0
[model.stiffness]
type = "api"
[excitation]
speed_rpm = 900.0
)" + pair},
      {"gear pair, ISO 6336 stiffness", R"(
[model]
damping_ratio = 0.05
torque = 80.0
[model.stiffness]
type = "iso6336"
[excitation]
speed_rpm = 900.0
)" + pair},
  };
  for (const auto& [what, toml] : cases) {
    GearPairModelSpec old;
    const GearPairModelSpec reduced = reducedOf(toml, &old);
    expectSameModel(reduced, old, what);
  }
}

TEST(GearPairGearbox, BacklashIsTheFullClearanceInTheGearbox) {
  const std::string toml = R"(
title = "a \"quoted\"\ttitle \\ with a tab"
[model]
mass = 1.0
damping_ratio = 0.05
mean_force = 100.0
contact = "backlash"
normal_backlash = 2e-4
[model.stiffness]
mean = 1e8
[excitation]
mesh_frequency = 500.0
)";
  const config::Config config = config::parseConfig(toml, "inline", config::simulateSchema());
  const std::string text = config::gearPairGearbox(config);
  EXPECT_NE(text.find("backlash = 0.0002"), std::string::npos) << text;
  std::vector<std::string> warnings;
  const GearTrainSpec train = config::gearTrainFromConfig(
      config::parseConfig(text, "printed", config::gearboxSchema()), warnings);
  EXPECT_EQ(train.meshes.at(0).contact.backlash, 2e-4);
  EXPECT_EQ(train.name, config.string("title"));
  EXPECT_EQ(config::gearPairFromGearbox(text, "printed").backlash, 1e-4);
}

TEST(GearPairGearbox, UntranslatedFormsAndCommandsAreNamed) {
  const config::Config config = config::parseConfig(R"(
[model]
mass = 1.0
damping_ratio = 0.05
mean_force = 100.0
extra_force_amplitudes = [1.0]
extra_force_frequencies = [10.0]
extra_force_phases_deg = [0.0]
[model.stiffness]
mean = 1e8
[excitation]
mesh_frequency = 500.0
)",
                                                    "inline", config::simulateSchema());
  try {
    config::gearPairGearbox(config);
    ADD_FAILURE() << "extra forces have no gearbox form";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("model.extra_force_amplitudes"), std::string::npos)
        << error.what();
  }
  // The gear-pair commands add them to the gearbox's reduced model.
  const config::GearPairModelBuild build = config::buildGearPairModel(config);
  ASSERT_EQ(build.spec.extra_forces.size(), 1u);
  EXPECT_EQ(build.spec.extra_forces[0].amplitude, 1.0);
  EXPECT_FALSE(config::translatedGearbox("geometry", config).has_value());
  EXPECT_THROW(config::translatedGearbox("simulate", config), InputError);
}

/// A helical pair (β = ±15°), optionally with more [model] keys and pair keys.
std::string helicalPair(const std::string& model, const std::string& more_pair = "") {
  return model + R"(
[pinion]
teeth = 23
module = 0.004
face_width = 0.025
helix_angle_deg = 15.0
bore_diameter = 0.03
[gear]
teeth = 41
module = 0.004
face_width = 0.025
helix_angle_deg = -15.0
bore_diameter = 0.05
)" + more_pair;
}

/// The same pair, spur.
std::string spurPair(const std::string& model, const std::string& more_pair = "") {
  std::string toml = helicalPair(model, more_pair);
  for (const char* line : {"helix_angle_deg = 15.0\n", "helix_angle_deg = -15.0\n"}) {
    toml.erase(toml.find(line), std::string(line).size());
  }
  return toml;
}

TEST(GearPairGearbox, HelicalPairsReduceToTheirTransverseModel) {
  // The gearbox mesh acts along the contact normal; with stiffness_plane = "transverse" it
  // takes the file's k, c, e, j as transverse (k_n = k_t / cos² β_b, ...) and the reduction
  // projects back (k_t = k_n cos² β_b, ...): the direct gear-pair model up to the round-off of
  // cos² β_b times its inverse, within kTranslationTolerance.
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"Fourier, damping value, backlash, series and rectangular TE", R"(
[model]
damping = 900.0
torque = 60.0
contact = "backlash"
normal_backlash = 6e-5
[model.stiffness]
mean = 5e8
cos = [-0.1, 0.02]
[model.transmission_error]
amplitudes = [2e-6]
phases_deg = [30.0]
rectangular_amplitude = 1e-6
[excitation]
speed_rpm = 1200.0
)"},
      {"potential-energy stiffness, table TE, one-sided", R"(
[model]
damping_ratio = 0.05
torque = 80.0
contact = "one_sided"
[model.stiffness]
type = "potential_energy"
[model.transmission_error]
table_phases = [0.0, 0.5]
table_values = [1e-6, -1e-6]
[excitation]
speed_rpm = 900.0
)"},
      {"ISO 6336 stiffness", R"(
[model]
damping_ratio = 0.05
torque = 80.0
[model.stiffness]
type = "iso6336"
[excitation]
speed_rpm = 900.0
)"},
  };
  for (const auto& [what, model] : cases) {
    GearPairModelSpec direct;
    const std::string toml = helicalPair(model);
    const GearPairModelSpec reduced = reducedOf(toml, &direct);
    expectSameModel(reduced, direct, what);
    const config::Config config = config::parseConfig(toml, "inline", config::simulateSchema());
    EXPECT_NE(config::gearPairGearbox(config).find("stiffness_plane = \"transverse\""),
              std::string::npos);
  }
}

TEST(GearPairGearbox, HelicalNormalPlaneMeshIsCosSquaredSofterInTorsion) {
  // docs/theory/mesh_stiffness.md: the same k read along the contact normal (the gearbox's
  // default plane) is k_t = k cos² β_b on the transverse line of action, with
  // tan β_b = tan β cos α_t and tan α_t = tan α_n / cos β (closed form). m_e = 1/(r_a²/I_a +
  // r_b²/I_b) and F = T / r_a are those of the transverse model in both planes.
  const config::Config config = config::parseConfig(helicalPair(R"(
[model]
damping_ratio = 0.05
torque = 60.0
[model.stiffness]
type = "step"
k_min = 4e8
k_max = 6e8
contact_ratio = 2.3
[excitation]
speed_rpm = 1200.0
)"),
                                                    "inline", config::simulateSchema());
  std::string text = config::gearPairGearbox(config);
  const GearPairModelSpec transverse = config::gearPairFromGearbox(text, "transverse");
  const std::string transverse_key = "stiffness_plane = \"transverse\"";
  text.replace(text.find(transverse_key), transverse_key.size(), "stiffness_plane = \"normal\"");
  const GearPairModelSpec normal = config::gearPairFromGearbox(text, "normal");
  const double beta = 15.0 * std::numbers::pi / 180.0, alpha_n = 20.0 * std::numbers::pi / 180.0;
  const double alpha_t = std::atan(std::tan(alpha_n) / std::cos(beta));
  const double beta_b = std::atan(std::tan(beta) * std::cos(alpha_t));
  const double cb2 = std::cos(beta_b) * std::cos(beta_b);
  for (const double phi : {0.1, 0.5, 0.9}) {
    EXPECT_CLOSE(transverse.stiffness->stiffness(phi),
                 StepMeshStiffness(4e8, 6e8, 2.3).stiffness(phi), kTranslationTolerance);
    EXPECT_CLOSE(normal.stiffness->stiffness(phi), cb2 * transverse.stiffness->stiffness(phi),
                 kTranslationTolerance);
  }
  EXPECT_CLOSE(normal.mass, transverse.mass, kTranslationTolerance);
  EXPECT_CLOSE(normal.mean_force, transverse.mean_force, kTranslationTolerance);
  EXPECT_CLOSE(transverse.mean_force,
               60.0 / config::readGearPairKeys(config, true).pinion_base_radius,
               kTranslationTolerance);
}

TEST(GearPairGearbox, DrivingGearIsTheMeshDriver) {
  // pair.driver = "gear" reverses the path of contact of the potential-energy model; the
  // gearbox's meshes.mesh.driver = "gear" does the same (the direct model is the reference), and
  // the curve differs from the pinion-driven one (the key is not ignored).
  const std::string model = R"(
[model]
damping_ratio = 0.05
torque = 80.0
[model.stiffness]
type = "potential_energy"
[excitation]
speed_rpm = 900.0
)";
  GearPairModelSpec direct;
  for (const auto& toml : {spurPair(model, "[pair]\ndriver = \"gear\"\n"),
                           helicalPair(model, "[pair]\ndriver = \"gear\"\n")}) {
    expectSameModel(reducedOf(toml, &direct), direct, "driving gear");
  }
  const GearPairModelSpec reduced = reducedOf(spurPair(model, "[pair]\ndriver = \"gear\"\n"));
  const GearPairModelSpec pinion_driven = reducedOf(spurPair(model));
  double largest = 0.0;
  for (int i = 0; i < 50; ++i) {
    largest = std::max(largest, std::abs(reduced.stiffness->stiffness(i / 50.0) -
                                         pinion_driven.stiffness->stiffness(i / 50.0)));
  }
  EXPECT_GT(largest, 1e-3 * pinion_driven.stiffness->stiffness(0.0));
}

TEST(GearPairGearbox, HelicalToothPairsReduceToTheirTransverseModel) {
  // The gearbox's tooth-pair elements act along the contact normal: with stiffness_plane =
  // "transverse" their stiffnesses are k/cos² β_b and their gaps g cos β_b, and the reduction
  // projects them back (k cos² β_b, g / cos β_b): the direct gear-pair elements, element by
  // element, within kTranslationTolerance (expectSameModel).
  GearPairModelSpec direct;
  const GearPairModelSpec reduced = reducedOf(helicalPair(R"(
[model]
type = "gear_pair_ltca"
damping_ratio = 0.05
torque = 60.0
[model.stiffness]
ltca_slices = 4
[modifications]
pinion_tip_relief = 5e-6
pinion_tip_relief_length = 2e-3
[excitation]
speed_rpm = 1200.0
)"),
                                              &direct);
  ASSERT_TRUE(reduced.contact_elements != nullptr);
  expectSameModel(reduced, direct, "helical tooth pairs");
}

TEST(GearPairGearbox, MeshDriverAndPlaneAreChecked) {
  const config::Config config = config::parseConfig(helicalPair(R"(
[model]
damping_ratio = 0.05
torque = 60.0
[model.stiffness]
mean = 5e8
[excitation]
speed_rpm = 1200.0
)"),
                                                    "inline", config::simulateSchema());
  std::string text = config::gearPairGearbox(config);
  text.insert(text.find("stiffness_plane"), "driver = \"idler\"\n");
  try {
    config::gearPairFromGearbox(text, "bad driver");
    ADD_FAILURE() << "a driver that is not a gear of the mesh";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("meshes.mesh.driver"), std::string::npos)
        << error.what();
  }
}

TEST(SdofReduction, RefusesWhatIsNotOneTorsionalPair) {
  const config::Config config = config::parseConfig(R"(
[model]
mass = 1.0
damping_ratio = 0.05
mean_force = 100.0
[model.stiffness]
mean = 1e8
[excitation]
mesh_frequency = 500.0
)",
                                                    "inline", config::simulateSchema());
  std::string text = config::gearPairGearbox(config);
  text.replace(text.find("dofs = \"torsional\""), 18, "dofs = \"planar\"");
  text += "\n[bearings.a]\nshaft = \"pinion_shaft\"\nkyy = 1e9\nkzz = 1e9\n";
  text += "\n[bearings.b]\nshaft = \"gear_shaft\"\nkyy = 1e9\nkzz = 1e9\n";
  try {
    config::gearPairFromGearbox(text, "planar");
    ADD_FAILURE() << "a planar train is not the torsional gear-pair model";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("planar"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace geardyn
