#include "geardyn/config/geometry_config.h"

#include <numbers>

#include "geardyn/config/output_section.h"
#include "geardyn/error.h"
#include "geardyn/geometry/tooth_profile.h"
#include "geardyn/units.h"

namespace geardyn::config {
namespace {

using geardyn::units::kDegree;

}  // namespace

void addGearSection(ConfigSchema& schema, const std::string& name, const std::string& role,
                    bool required, const std::string& bore_default) {
  schema.section(name, "The " + role + ": an external involute cylindrical gear.");
  const auto key = [&](const char* field) { return name + "." + field; };
  // The keys without a default: required, or optional when the gear pair itself is optional.
  const auto need = [&](KeyBuilder builder) { required ? builder.required() : builder.optional(); };
  need(schema.integer(key("teeth")).min(3).doc("number of teeth z"));
  need(schema.real(key("module")).unit("m").positive().doc("normal module m_n"));
  schema.real(key("pressure_angle_deg"))
      .unit("deg")
      .greaterThan(0.0)
      .lessThan(45.0)
      .defaultValue(20.0)
      .doc("normal pressure angle α_n of the basic rack");
  schema.real(key("helix_angle_deg"))
      .unit("deg")
      .min(-60.0)
      .max(60.0)
      .defaultValue(0.0)
      .doc("helix angle β at the reference circle; > 0 right hand, opposite hands in a pair");
  need(schema.real(key("face_width")).unit("m").positive().doc("face width b"));
  schema.real(key("profile_shift"))
      .unit("-")
      .min(-2.0)
      .max(3.0)
      .defaultValue(0.0)
      .doc("profile shift coefficient x (normal)");
  schema.real(key("addendum_coefficient"))
      .unit("-")
      .greaterThan(0.0)
      .max(3.0)
      .defaultValue(1.0)
      .doc("addendum coefficient h_a* of the basic rack");
  schema.real(key("dedendum_coefficient"))
      .unit("-")
      .greaterThan(0.0)
      .max(3.0)
      .defaultValue(1.25)
      .doc("dedendum coefficient h_f* = h_a* + c* of the basic rack");
  schema.real(key("root_fillet_coefficient"))
      .unit("-")
      .min(0.0)
      .max(1.0)
      .defaultValue(0.38)
      .doc(
          "tip radius coefficient ρ_fP* of the generating rack (root fillet); with h_f* it sets "
          "where the generated involute starts (form circle, undercut)");
  schema.real(key("tip_radius_modification"))
      .unit("m")
      .defaultValue(0.0)
      .doc("change of the tip radius Δr_a (< 0: tip shortening, e.g. to keep the tip clearance)");
  if (bore_default.empty()) {
    schema.real(key("bore_diameter"))
        .unit("m")
        .min(0.0)
        .defaultValue(0.0)
        .doc("bore diameter of the body");
  } else {
    schema.real(key("bore_diameter"))
        .unit("m")
        .min(0.0)
        .optional()
        .doc("bore diameter of the body; absent: " + bore_default);
  }
  schema.real(key("youngs_modulus"))
      .unit("Pa")
      .positive()
      .defaultValue(206e9)
      .doc("Young's modulus E");
  schema.real(key("poisson_ratio"))
      .unit("-")
      .greaterThan(-1.0)
      .lessThan(0.5)
      .defaultValue(0.3)
      .doc("Poisson's ratio ν");
  schema.real(key("density")).unit("kg/m^3").positive().defaultValue(7850.0).doc("density ρ");
}

GearSpec gearSpecFromConfig(const Config& config, const std::string& name) {
  const auto key = [&](const char* field) { return name + "." + field; };
  for (const char* field : {"teeth", "module", "face_width"}) {
    if (!config.has(key(field))) {
      throw InputError(key(field), "",
                       "missing: a gear pair needs [pinion] and [gear] with teeth, "
                       "module and face_width");
    }
  }
  GearSpec gear;
  gear.teeth = static_cast<int>(config.integer(key("teeth")));
  gear.normal_module = config.real(key("module"));
  gear.normal_pressure_angle = config.real(key("pressure_angle_deg")) * kDegree;
  gear.helix_angle = config.real(key("helix_angle_deg")) * kDegree;
  gear.face_width = config.real(key("face_width"));
  gear.profile_shift = config.real(key("profile_shift"));
  gear.addendum_coefficient = config.real(key("addendum_coefficient"));
  gear.dedendum_coefficient = config.real(key("dedendum_coefficient"));
  gear.root_fillet_coefficient = config.real(key("root_fillet_coefficient"));
  gear.tip_radius_modification = config.real(key("tip_radius_modification"));
  gear.bore_diameter = config.has(key("bore_diameter")) ? config.real(key("bore_diameter")) : 0.0;
  gear.youngs_modulus = config.real(key("youngs_modulus"));
  gear.poisson_ratio = config.real(key("poisson_ratio"));
  gear.density = config.real(key("density"));
  return gear;
}

bool hasGearPair(const Config& config) {
  return config.has("pinion.teeth");
}

void addGearPairSections(ConfigSchema& schema, bool required) {
  addGearSection(schema, "pinion", "pinion (member 1, usually the smaller gear)", required);
  addGearSection(schema, "gear", "gear (member 2)", required);
  schema.section("pair", "How the two gears are mounted and run.");
  schema.real("pair.centre_distance")
      .unit("m")
      .positive()
      .optional()
      .doc(
          "operating centre distance a_w; not set: the zero-backlash distance of the profile "
          "shifts");
  schema.real("pair.speed_rpm").unit("rpm").min(0.0).optional().doc("pinion speed n_1");
  schema.string("pair.driver")
      .choices({"pinion", "gear"})
      .defaultValue("pinion")
      .doc("the driving member (the path of contact starts at the driven gear's tip)");
}

ConfigSchema geometrySchema() {
  ConfigSchema schema("geometry",
                      "Involute gear-pair geometry: radii, operating pressure angle, path of "
                      "contact, contact ratios, backlash, validity checks, mass properties.");
  schema.string("title").optional().doc("free text describing the study");
  addGearPairSections(schema);
  addOutputSection(schema);
  return schema;
}

GearPairSpec gearPairSpecFromConfig(const Config& config) {
  GearPairSpec spec;
  spec.pinion = gearSpecFromConfig(config, "pinion");
  spec.gear = gearSpecFromConfig(config, "gear");
  spec.centre_distance = config.optionalReal("pair.centre_distance");
  spec.pinion_speed_rpm = config.optionalReal("pair.speed_rpm");
  spec.driver = parseDriver(config.string("pair.driver"));
  return spec;
}

}  // namespace geardyn::config
