// The configuration loader against the geometry schema: every kind of bad input is rejected
// with a message naming the key, the value and what is allowed; good input resolves fully.
#include "geardyn/config/config.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "geardyn/config/geometry_config.h"
#include "geardyn/error.h"
#include "geardyn/geometry/gear_pair.h"
#include "geardyn/io/atomic_file.h"

namespace geardyn::config {
namespace {

const char* const kValid = R"(
[pinion]
teeth = 25
module = 0.003
face_width = 0.02

[gear]
teeth = 30
module = 0.003
face_width = 0.02

[pair]
speed_rpm = 1200
)";

/// The message of the InputError that parsing `text` (with overrides) throws.
std::string errorOf(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    const Config config = parseConfig(text, "pair.toml", geometrySchema(), overrides);
    GearPair pair(gearPairSpecFromConfig(config));
  } catch (const InputError& error) {
    return error.what();
  }
  return "(no error)";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

#define EXPECT_HAS(haystack, needle) \
  EXPECT_NE((haystack).find(needle), std::string::npos) << "message: " << (haystack)

TEST(Config, ResolvesDefaultsAndKeepsSchemaOrder) {
  const Config config = parseConfig(kValid, "pair.toml", geometrySchema());
  EXPECT_EQ(config.integer("pinion.teeth"), 25);
  EXPECT_DOUBLE_EQ(config.real("pinion.pressure_angle_deg"), 20.0);
  EXPECT_DOUBLE_EQ(config.real("gear.dedendum_coefficient"), 1.25);
  EXPECT_DOUBLE_EQ(config.real("pair.speed_rpm"), 1200.0);  // an integer is a number
  EXPECT_FALSE(config.has("pair.centre_distance"));
  EXPECT_TRUE(config.resolved()["pair"]["centre_distance"].is_null());
  EXPECT_EQ(config.string("pair.driver"), "pinion");
  // Sections in schema order, keys in schema order.
  auto it = config.resolved().begin();
  ++it;  // "title"
  EXPECT_EQ(it.key(), "pinion");
  EXPECT_EQ(config.resolved()["pinion"].begin().key(), "teeth");
  EXPECT_NEAR(GearPair(gearPairSpecFromConfig(config)).contactRatioTransverse(), 1.6325826, 1e-7);
}

TEST(Config, TeethMustBeAPositiveInteger) {
  EXPECT_HAS(errorOf(replaced(kValid, "teeth = 25", "teeth = 0")),
             "pinion.teeth = 0: must be an integer >= 3");
  EXPECT_HAS(errorOf(replaced(kValid, "teeth = 25", "teeth = 0")), "pair.toml line 3");
  EXPECT_HAS(errorOf(replaced(kValid, "teeth = 25", "teeth = 3.5")),
             "pinion.teeth = 3.5: expected an integer");
  EXPECT_EQ(errorOf(replaced(kValid, "teeth = 25", "teeth = 25.0")), "(no error)");
}

TEST(Config, ModuleMustBePositive) {
  EXPECT_HAS(errorOf(replaced(kValid, "module = 0.003\nface", "module = -0.003\nface")),
             "pinion.module = -0.003: must be a number > 0 [m]");
}

TEST(Config, PressureAngleMustBeBetween0And45Degrees) {
  const std::string zero = replaced(kValid, "teeth = 30", "teeth = 30\npressure_angle_deg = 0");
  EXPECT_HAS(errorOf(zero), "gear.pressure_angle_deg = 0: must be a number in (0, 45) [deg]");
  const std::string at45 = replaced(kValid, "teeth = 30", "teeth = 30\npressure_angle_deg = 45.0");
  EXPECT_HAS(errorOf(at45), "gear.pressure_angle_deg = 45");
}

TEST(Config, ContactRatioBelowOneIsRejected) {
  const std::string text =
      replaced(replaced(kValid, "teeth = 25", "teeth = 25\naddendum_coefficient = 0.5"),
               "teeth = 30", "teeth = 30\naddendum_coefficient = 0.5");
  EXPECT_HAS(errorOf(text), "cannot mesh continuously");
}

TEST(Config, MisspeltKeySuggestsTheRightOne) {
  const std::string message =
      errorOf(replaced(kValid, "module = 0.003\nface", "modul = 0.003\nface"));
  EXPECT_HAS(message, "pinion.modul");
  EXPECT_HAS(message, "did you mean \"pinion.module\"?");
  EXPECT_HAS(message, "pair.toml line 4");
}

TEST(Config, KeyInTheWrongSectionSuggestsWhereItBelongs) {
  EXPECT_HAS(errorOf(replaced(kValid, "speed_rpm", "face_width = 0.01\nspeed_rpm")),
             "did you mean \"pinion.face_width\" or \"gear.face_width\"?");
}

TEST(Config, MisspeltSectionSuggestsTheRightOne) {
  EXPECT_HAS(errorOf(replaced(kValid, "[pinion]", "[pinon]")), "did you mean [pinion]?");
}

// For overrides that go to several files (train): keys only, against every key they may take.
TEST(Config, CheckOverrideKeysNamesAnUnknownKeyOnly) {
  EXPECT_NO_THROW(checkOverrideKeys(geometrySchema(), {"pinion.teeth=-3", "pair.speed_rpm=1"}));
  try {
    checkOverrideKeys(geometrySchema(), {"pinion.teeth=20", "pinon.module=0.003"});
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.key(), "pinon.module");
    EXPECT_HAS(std::string(error.what()), "did you mean \"pinion.module\"");
  }
}

TEST(Config, MissingRequiredKeyIsNamed) {
  EXPECT_HAS(errorOf(replaced(kValid, "face_width = 0.02\n\n[pair]", "\n[pair]")),
             "gear.face_width: missing required key");
}

TEST(Config, StringWhereANumberIsExpected) {
  EXPECT_HAS(errorOf(replaced(kValid, "face_width = 0.02", "face_width = \"wide\"")),
             "pinion.face_width = \"wide\": expected a number > 0 [m]");
}

TEST(Config, NanAndInfAreRejected) {
  EXPECT_HAS(errorOf(replaced(kValid, "face_width = 0.02", "face_width = nan")),
             "pinion.face_width = nan: must be finite");
  EXPECT_HAS(errorOf(replaced(kValid, "speed_rpm = 1200", "speed_rpm = inf")),
             "pair.speed_rpm = inf: must be finite");
}

TEST(Config, CentreDistanceBelowBaseRadii) {
  EXPECT_HAS(errorOf(replaced(kValid, "speed_rpm = 1200", "centre_distance = 0.07")),
             "pair.centre_distance = 0.07 m: must exceed the sum of the base radii");
}

TEST(Config, InvalidTomlGivesTheLine) {
  EXPECT_HAS(errorOf(replaced(kValid, "teeth = 30", "teeth = = 30")), "pair.toml line 8");
  EXPECT_HAS(errorOf(replaced(kValid, "teeth = 30", "teeth = = 30")), "not valid TOML");
}

TEST(Config, ChoicesSuggestTheClosest) {
  EXPECT_HAS(errorOf(replaced(kValid, "speed_rpm = 1200", "driver = \"pinon\"")),
             "pair.driver = \"pinon\": must be one of \"pinion\", \"gear\"");
  EXPECT_HAS(errorOf(replaced(kValid, "speed_rpm = 1200", "driver = \"pinon\"")),
             "did you mean \"pinion\"?");
}

TEST(Config, OverridesAreValidatedLikeTheFile) {
  const Config config =
      parseConfig(kValid, "pair.toml", geometrySchema(),
                  {"pinion.teeth=20", "pair.driver=gear", "gear.profile_shift = 0.25"});
  EXPECT_EQ(config.integer("pinion.teeth"), 20);
  EXPECT_EQ(config.string("pair.driver"), "gear");  // a bare word is a string
  EXPECT_DOUBLE_EQ(config.real("gear.profile_shift"), 0.25);
  EXPECT_HAS(errorOf(kValid, {"pinion.modul=0.002"}), "did you mean \"pinion.module\"?");
  EXPECT_HAS(errorOf(kValid, {"pinion.teeth=0"}), "pinion.teeth = 0: must be an integer >= 3");
  EXPECT_HAS(errorOf(kValid, {"pinion.teeth=0"}), "--set");
  EXPECT_HAS(errorOf(kValid, {"pinion.teeth"}), "expected section.key=value");
  EXPECT_HAS(errorOf(kValid, {"pinion.teeth=many"}), "expected an integer");
}

TEST(Config, SectionGivenAsAValue) {
  EXPECT_HAS(errorOf(std::string("pair = 3\n") + replaced(kValid, "[pair]\nspeed_rpm = 1200", "")),
             "[pair] is a section");
}

TEST(Config, MissingFileIsAnInputError) {
  try {
    loadConfigFile("/nonexistent/pair.toml", geometrySchema());
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_HAS(std::string(error.what()),
               "config = /nonexistent/pair.toml: no such configuration file");
  }
}

TEST(Config, LoadsAFile) {
  const auto path = std::filesystem::temp_directory_path() / "geardyn_config_test.toml";
  io::writeFileAtomic(path, kValid);
  EXPECT_EQ(loadConfigFile(path, geometrySchema()).integer("gear.teeth"), 30);
  std::filesystem::remove(path);
}

TEST(ConfigSchema, ReferenceListsEveryKey) {
  const auto schema = geometrySchema();
  const std::string markdown = schema.referenceMarkdown();
  for (const auto& key : schema.keys()) EXPECT_HAS(markdown, "`" + key.name() + "`");
  EXPECT_HAS(markdown, "## [pinion]");
}

}  // namespace
}  // namespace geardyn::config
