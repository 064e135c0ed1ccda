/// Issue #31: one vocabulary for the input files. The converting renames (a radian key read as
/// degrees, the half clearance read as the full one) give the model the same numbers as the new
/// keys, and the Rao rotor's gravity acts along the common vertical (−z of a gearbox, the
/// thesis's −y).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "geardyn/config/config.h"
#include "geardyn/config/fe_rotor_config.h"
#include "geardyn/config/hbm_config.h"
#include "geardyn/config/rotor_config.h"
#include "geardyn/config/simulate_config.h"
#include "geardyn/error.h"
#include "geardyn/system/lateral_rotor.h"

namespace geardyn::config {
namespace {

constexpr double kPi = std::numbers::pi;
// Degrees ↔ radians round trips: a few ulps.
constexpr double kRoundTrip = 1e-14;

bool hasNote(const Config& config, const std::string& text) {
  for (const auto& note : config.notes())
    if (note.find(text) != std::string::npos) return true;
  return false;
}

const char* const kPair = R"(
[model]
mass = 1.0
damping_ratio = 0.05
mean_force = 100.0
contact = "backlash"
extra_force_amplitudes = [1.0]
extra_force_frequencies = [10.0]
extra_force_phases_deg = [0.0]
[model.stiffness]
mean = 1e8
[excitation]
mesh_frequency = 500.0
)";

TEST(InputConventions, HalfBacklashIsReadAsTheFullClearance) {
  const Config old_key = parseConfig(kPair, "old", simulateSchema(), {"model.backlash=1e-4"});
  const Config new_key =
      parseConfig(kPair, "new", simulateSchema(), {"model.normal_backlash=2e-4"});
  EXPECT_DOUBLE_EQ(old_key.real("model.normal_backlash"), 2e-4);
  EXPECT_TRUE(hasNote(old_key, "model.normal_backlash")) << "the warning names the new key";
  EXPECT_DOUBLE_EQ(buildGearPairModel(old_key).spec.backlash, 1e-4);  // the law's b = j/2
  EXPECT_DOUBLE_EQ(buildGearPairModel(new_key).spec.backlash, 1e-4);
}

TEST(InputConventions, HalfBacklashInTheFileIsConverted) {
  const std::string file = std::string(kPair).replace(std::string(kPair).find("contact"), 0,
                                                      "backlash = 3\n");  // an integer
  const Config config = parseConfig(file, "old", simulateSchema());
  EXPECT_DOUBLE_EQ(config.real("model.normal_backlash"), 6.0);
  EXPECT_TRUE(hasNote(config, "model.backlash is deprecated: write model.normal_backlash"));
  const std::string both =
      std::string(file).replace(file.find("contact"), 0, "normal_backlash = 6.0\n");
  try {
    parseConfig(both, "both", simulateSchema());
    ADD_FAILURE() << "both spellings given";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("model.normal_backlash"), std::string::npos);
  }
}

TEST(InputConventions, RadianPhasesAreReadAsDegrees) {
  const std::string te = "\n[model.transmission_error]\namplitudes = [1e-6, 2e-6]\n";
  const Config old_key =
      parseConfig(std::string(kPair) + te + "phases = [0.5, -1]\n", "old", simulateSchema(),
                  {"model.extra_force_phases=[0.25]", "model.normal_backlash=2e-4"});
  const Config new_key = parseConfig(
      std::string(kPair) + te + "phases_deg = [28.64788975654116, -57.29577951308232]\n", "new",
      simulateSchema(),
      {"model.extra_force_phases_deg=[14.32394487827058]", "model.normal_backlash=2e-4"});
  EXPECT_TRUE(hasNote(old_key, "model.transmission_error.phases_deg"));
  EXPECT_TRUE(hasNote(old_key, "model.extra_force_phases_deg"));
  const auto a = buildGearPairModel(old_key).spec, b = buildGearPairModel(new_key).spec;
  EXPECT_NEAR(a.extra_forces.at(0).phase, 0.25, kRoundTrip);
  EXPECT_NEAR(b.extra_forces.at(0).phase, 0.25, kRoundTrip);
  for (double t : {0.0, 1.3e-4, 7.7e-4}) {
    EXPECT_NEAR(a.transmission_error.value(t), b.transmission_error.value(t), 1e-20);
  }
  EXPECT_NEAR(a.transmission_error.value(0.0), 1e-6 * std::cos(0.5) + 2e-6 * std::cos(-1.0), 1e-20);
}

TEST(InputConventions, HbmSamplesIsTheOldSamplesPerPeriod) {
  const std::string hbm = std::string(kPair) + "[sweep]\nstart = 100.0\nstop = 200.0\n";
  const Config old_key = parseConfig(hbm + "[hbm]\nsamples_per_period = 64\n", "old", hbmSchema());
  EXPECT_EQ(old_key.integer("hbm.samples"), 64);
  EXPECT_TRUE(hasNote(old_key, "hbm.samples_per_period is deprecated: write hbm.samples"));
}

TEST(InputConventions, RaoRotorPhasesInDegreesAndGravityAlongTheVertical) {
  const Config config = parseConfig("[rotor]\ngravity = 9.81\n", "rotor", rotorSchema());
  const LateralRotorSpec spec = lateralRotorSpecFromConfig(config);
  // The thesis's phases (Table 4.1), now given in degrees.
  EXPECT_NEAR(spec.te_x.at(0).phase, 0.785, kRoundTrip);
  EXPECT_NEAR(spec.pinion_runout_phase, 1.047, kRoundTrip);
  const Config old_key = parseConfig("[runout]\ngear_phase = 0.5\n[mesh]\nte_y_phase = [1.0]\n",
                                     "rotor", rotorSchema());
  EXPECT_NEAR(lateralRotorSpecFromConfig(old_key).gear_runout_phase, 0.5, kRoundTrip);
  EXPECT_NEAR(lateralRotorSpecFromConfig(old_key).te_y.at(0).phase, 1.0, kRoundTrip);
  EXPECT_TRUE(hasNote(old_key, "runout.gear_phase_deg"));

  // Gravity: the common input convention is g along −z (the vertical of a gearbox and of the FE
  // rotor); the Rao model's vertical is its y (thesis Fig. 2.1, shaft along z), so the weights
  // are −m g on y₁, y₂ and nothing on x.
  LateralRotorSpec still = spec;
  still.pinion_runout = still.gear_runout = 0.0;
  still.mean_te = 0.0;
  for (auto& h : still.te_x) h.amplitude = 0.0;
  for (auto& h : still.te_y) h.amplitude = 0.0;
  const LateralRotorModel model(still);
  const Eigen::Vector4d f = model.force(0.123);
  EXPECT_NEAR(f(0), 0.0, 1e-12);
  EXPECT_NEAR(f(2), 0.0, 1e-12);
  EXPECT_NEAR(f(1), -spec.pinion_mass * 9.81, 1e-12);
  EXPECT_NEAR(f(3), -spec.gear_mass * 9.81, 1e-12);
}

TEST(InputConventions, FeRotorBearingAxialStiffnessAndCampbellRange) {
  const ConfigSchema schema = feRotorSchema();
  ASSERT_NE(schema.aliasTarget("pinion_shaft.bearings.kxx"), nullptr);
  EXPECT_EQ(*schema.aliasTarget("pinion_shaft.bearings.kxx"), "pinion_shaft.bearings.k_axial");
  EXPECT_EQ(*schema.aliasTarget("campbell.start_speed_rpm"), "campbell.speed_min_rpm");
  EXPECT_EQ(*schema.aliasTarget("campbell.end_rpm"), "campbell.speed_max_rpm");
}

// time.samples of `geardyn rotor`: as given, else the smallest power of two with 2.2 samples
// per period of the highest mesh harmonic over time.duration (rotorTimeSamples).
TEST(InputConventions, RaoRotorSamplesFollowTheHighestMeshHarmonic) {
  // Table 4.1: 5 TE harmonics of 16 × 11 Hz = 176 Hz, 880 Hz over 15 s: 29 040 -> 2^15, the
  // thesis's own choice.
  const Config thesis = parseConfig("", "rotor", rotorSchema());
  EXPECT_EQ(rotorTimeSamples(thesis, lateralRotorSpecFromConfig(thesis)), 32768);
  // 23 teeth at 1450 rpm, 2 harmonics: 1111.67 Hz, 2.2 × 1111.67 × 15 = 36 685 -> 2^16; over
  // 1 s: 2446 -> 2^12.
  const std::string rig =
      "[rotor]\npinion_teeth = 23\ngear_teeth = 61\nspeed_rpm = 1450.0\n"
      "[mesh]\nte_x = [20e-6, 8e-6]\nte_y = [15e-6, 6e-6]\n";
  const Config fast = parseConfig(rig, "rotor", rotorSchema());
  EXPECT_EQ(rotorTimeSamples(fast, lateralRotorSpecFromConfig(fast)), 65536);
  const Config short_run = parseConfig(rig, "rotor", rotorSchema(), {"time.duration=1.0"});
  EXPECT_EQ(rotorTimeSamples(short_run, lateralRotorSpecFromConfig(short_run)), 4096);
  // Capped at the largest power of two the key allows (2^27 <= 2e8); the analysis then names
  // time.samples as too few for the duration.
  const Config long_run = parseConfig(rig, "rotor", rotorSchema(), {"time.duration=1e6"});
  EXPECT_EQ(rotorTimeSamples(long_run, lateralRotorSpecFromConfig(long_run)), 134217728);
  // Given: as given, even when it aliases (the analysis refuses it, naming the key).
  const Config given = parseConfig(rig, "rotor", rotorSchema(), {"time.samples=1000"});
  EXPECT_EQ(rotorTimeSamples(given, lateralRotorSpecFromConfig(given)), 1000);
  EXPECT_EQ(rotorTimeOptionsFromConfig(given, lateralRotorSpecFromConfig(given)).samples, 1000);
}

}  // namespace
}  // namespace geardyn::config
