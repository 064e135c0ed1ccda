#include "geardyn/analysis/geometry_results.h"

#include <numbers>

#include "geardyn/config/geometry_config.h"
#include "geardyn/config/output_section.h"
#include "geardyn/error.h"
#include "geardyn/geometry/tooth_profile.h"
#include "geardyn/units.h"

namespace geardyn::analysis {
namespace {

using geardyn::units::kDegree;

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

io::CsvTable memberTable(const GearPair& pair) {
  io::CsvTable table({"member", "teeth", "pitch_radius_m", "base_radius_m", "tip_radius_m",
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

io::CsvTable toothProfileTable(const GearPair& pair) {
  io::CsvTable table({"member", "x_m", "y_m"});
  for (Member member : {Member::kPinion, Member::kGear}) {
    const std::string name = member == Member::kPinion ? "pinion" : "gear";
    for (const auto& p : computeToothProfile(pair, member).points) {
      table.addRow({name, p.x(), p.y()});
    }
  }
  return table;
}

}  // namespace geardyn::analysis
