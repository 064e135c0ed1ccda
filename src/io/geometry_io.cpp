#include "geardyn/io/geometry_io.h"

#include <numbers>

#include "geardyn/error.h"
#include "geardyn/geometry/tooth_profile.h"
#include "geardyn/io/output_section.h"

namespace geardyn::io {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

}  // namespace

void addGearSection(ConfigSchema& schema, const std::string& name, const std::string& role,
                    bool required) {
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
  schema.real(key("bore_diameter"))
      .unit("m")
      .min(0.0)
      .defaultValue(0.0)
      .doc("bore diameter of the body");
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
  gear.bore_diameter = config.real(key("bore_diameter"));
  gear.youngs_modulus = config.real(key("youngs_modulus"));
  gear.poisson_ratio = config.real(key("poisson_ratio"));
  gear.density = config.real(key("density"));
  return gear;
}

namespace {

nlohmann::ordered_json memberJson(const GearGeometry& g, int teeth) {
  nlohmann::ordered_json json;
  json["teeth"] = teeth;
  json["pitch_radius"] = g.pitch_radius;
  json["base_radius"] = g.base_radius;
  json["tip_radius"] = g.tip_radius;
  json["root_radius"] = g.root_radius;
  json["operating_pitch_radius"] = g.operating_pitch_radius;
  json["form_radius"] = g.form_radius;
  json["active_profile_start_radius"] = g.active_profile_start_radius;
  json["tip_thickness_normal"] = g.tip_thickness_normal;
  json["tip_clearance"] = g.tip_clearance;
  json["undercut"] = g.undercut;
  json["mass"] = g.mass;
  json["polar_inertia"] = g.polar_inertia;
  json["diametral_inertia"] = g.diametral_inertia;
  return json;
}

}  // namespace

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

nlohmann::ordered_json toJson(const GearPair& pair) {
  nlohmann::ordered_json json;
  json["gear_ratio"] = pair.gearRatio();
  json["transverse_module"] = pair.pinion().transverse_module;
  json["transverse_pressure_angle"] = pair.transversePressureAngle();
  json["transverse_pressure_angle_deg"] = pair.transversePressureAngle() / kDegree;
  json["base_helix_angle"] = pair.baseHelixAngle();
  json["base_helix_angle_deg"] = pair.baseHelixAngle() / kDegree;
  json["base_pitch_transverse"] = pair.basePitchTransverse();
  json["base_pitch_normal"] = pair.basePitchNormal();
  json["reference_centre_distance"] = pair.referenceCentreDistance();
  json["tight_mesh_centre_distance"] = pair.tightMeshCentreDistance();
  json["centre_distance"] = pair.centreDistance();
  json["operating_pressure_angle"] = pair.operatingPressureAngle();
  json["operating_pressure_angle_deg"] = pair.operatingPressureAngle() / kDegree;
  json["backlash_circumferential"] = pair.backlashCircumferential();
  json["backlash_normal"] = pair.backlashNormal();
  json["line_of_action_length"] = pair.lineOfActionLength();
  json["path_of_contact_start"] = pair.pathOfContactStart();
  json["path_of_contact_end"] = pair.pathOfContactEnd();
  json["path_of_contact_length"] = pair.pathOfContactLength();
  json["contact_ratio_transverse"] = pair.contactRatioTransverse();
  json["overlap_ratio"] = pair.overlapRatio();
  json["contact_ratio_total"] = pair.contactRatioTotal();
  json["effective_face_width"] = pair.effectiveFaceWidth();
  if (auto f = pair.meshFrequency()) {
    json["mesh_frequency"] = *f;
    json["mesh_period"] = *f > 0.0 ? nlohmann::ordered_json(1.0 / *f) : nullptr;
  } else {
    json["mesh_frequency"] = nullptr;
    json["mesh_period"] = nullptr;
  }
  json["pinion"] = memberJson(pair.pinion(), pair.spec().pinion.teeth);
  json["gear"] = memberJson(pair.gear(), pair.spec().gear.teeth);
  return json;
}

CsvTable memberTable(const GearPair& pair) {
  CsvTable table({"member", "teeth", "pitch_radius_m", "base_radius_m", "tip_radius_m",
                  "root_radius_m", "operating_pitch_radius_m", "form_radius_m",
                  "active_profile_start_radius_m", "tip_thickness_normal_m", "tip_clearance_m",
                  "undercut", "mass_kg", "polar_inertia_kg_m2", "diametral_inertia_kg_m2"});
  const auto add = [&](const char* name, const GearGeometry& g, int teeth) {
    table.addRow({std::string(name), static_cast<long long>(teeth), g.pitch_radius, g.base_radius,
                  g.tip_radius, g.root_radius, g.operating_pitch_radius, g.form_radius,
                  g.active_profile_start_radius, g.tip_thickness_normal, g.tip_clearance,
                  static_cast<long long>(g.undercut), g.mass, g.polar_inertia,
                  g.diametral_inertia});
  };
  add("pinion", pair.pinion(), pair.spec().pinion.teeth);
  add("gear", pair.gear(), pair.spec().gear.teeth);
  return table;
}

CsvTable toothProfileTable(const GearPair& pair) {
  CsvTable table({"member", "x_m", "y_m"});
  for (Member member : {Member::kPinion, Member::kGear}) {
    const std::string name = member == Member::kPinion ? "pinion" : "gear";
    for (const auto& p : computeToothProfile(pair, member).points) {
      table.addRow({name, p.x(), p.y()});
    }
  }
  return table;
}

}  // namespace geardyn::io
