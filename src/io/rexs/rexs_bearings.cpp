/// A REXS rolling bearing's inner geometry as the gearbox file's geometry keys (rexs_mapping.h):
/// `rolling_bearing_with_detailed_geometry` and catalogue bearings whose file gives their rows
/// (`rolling_bearing_row`: number_of_rolling_elements, pressure_angle, raceway radii, the pitch
/// diameter D_pw) and rolling elements (`rolling_element`: diameter_of_rolling_element,
/// length_of_rolling_element, roller_crowning_radius). Attribute ids from the REXS attribute
/// database, versions 1.0–2.0.0 (rexs-api-cpp models/rexs_schema_*_en.xml).

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "geardyn/io/rexs/rexs_reader.h"
#include "rexs_mapping.h"

namespace geardyn::io::rexs::detail {
namespace {

/// REXS bearing_type → the gearbox file's type; empty: no geometry model in geardyn.
std::string geardynType(const std::string& rexs_type) {
  static const std::map<std::string, std::string> kTypes = {
      {"radial_grooved_ball_bearing", "deep_groove_ball"},
      {"angular_contact_ball_bearing", "angular_contact_ball"},
      {"radial_roller_bearing", "cylindrical_roller"},
      {"radial_needle_roller_bearing", "cylindrical_roller"},
      {"radial_tapered_roller_bearing", "tapered_roller"},
      {"radial_self_aligning_roller_bearing", "spherical_roller"},
  };
  const auto it = kTypes.find(rexs_type);
  return it == kTypes.end() ? "" : it->second;
}

/// The parts of `id` of one component type, in relation order (a bearing's rows are an
/// ordered_assembly in the files of Bearinx and the FVA Workbench, plain assembly elsewhere).
std::vector<const Component*> partsOfType(Model& model, int id, const std::string& type) {
  std::vector<std::pair<int, const Component*>> found;
  for (const char* relation : {"ordered_assembly", "assembly"}) {
    for (const Relation* r : model.relations(relation)) {
      const auto part = r->ref("part");
      if (r->ref("assembly") == id && part && model.component(*part).type == type)
        found.emplace_back(r->order.value_or(0), &model.component(*part));
    }
  }
  std::stable_sort(found.begin(), found.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<const Component*> out;
  for (const auto& f : found) out.push_back(f.second);
  return out;
}

/// What the file gives of one bearing's inner geometry.
struct RexsBearingGeometry {
  std::string type;  // the gearbox file's
  int rows = 0;
  std::optional<long long> elements;
  std::optional<double> element_diameter, pitch_diameter, angle_deg, inner_radius, outer_radius,
      length, crowning_radius, clearance, row_spacing, rating;
  bool reversed = false;
};

RexsBearingGeometry readGeometry(Model& model, const Component& bearing,
                                 const std::vector<const Component*>& rows) {
  auto& read = model.read;
  RexsBearingGeometry g;
  g.rows = static_cast<int>(rows.size());
  if (auto n = read.integer(bearing, "number_of_bearing_rows")) g.rows = static_cast<int>(*n);
  const Component& row = *rows.front();
  g.elements = read.integer(row, "number_of_rolling_elements");
  g.angle_deg = read.real(row, "pressure_angle");
  g.inner_radius = read.real(row, "raceway_radius_of_inner_ring");
  g.outer_radius = read.real(row, "raceway_radius_of_outer_ring");
  // D_pw: reference_diameter in REXS 1.x, reference_diameter_rolling_bearing from 2.0.
  g.pitch_diameter = read.real(row, "reference_diameter_rolling_bearing");
  if (!g.pitch_diameter) g.pitch_diameter = read.real(row, "reference_diameter");
  // The rolling element: a part of the row, else of the bearing.
  auto elements = partsOfType(model, row.id, "rolling_element");
  if (elements.empty()) elements = partsOfType(model, bearing.id, "rolling_element");
  if (!elements.empty()) {
    g.element_diameter = read.real(*elements.front(), "diameter_of_rolling_element");
    g.length = read.real(*elements.front(), "length_of_rolling_element");
    g.crowning_radius = read.real(*elements.front(), "roller_crowning_radius");
  }
  // s_r: the operating clearance, else the mounted one, else the unmounted (REXS 1.0:
  // radial_backlash); the diametral play of ISO/TS 16281.
  for (const char* id : {"operating_radial_bearing_clearance", "mounted_radial_bearing_clearance",
                         "radial_bearing_clearance", "radial_backlash"}) {
    if (!g.clearance) g.clearance = read.real(bearing, id);
  }
  g.row_spacing = read.real(bearing, "distance_between_bearing_rows");
  g.rating = read.real(bearing, "radial_dynamic_load_rating");
  if (!g.rating) g.rating = read.real(bearing, "dynamic_capacity");
  // A single row loaded towards −u: a negative pressure angle or axial support "negative".
  g.reversed = (g.angle_deg && *g.angle_deg < 0) ||
               read.text(row, "axial_force_absorption_of_row").value_or("") == "negative";
  if (g.angle_deg) g.angle_deg = std::abs(*g.angle_deg);
  return g;
}

/// The attributes `g` lacks for a bearing of its type.
std::vector<std::string> missingAttributes(const RexsBearingGeometry& g) {
  std::vector<std::string> missing;
  if (!g.elements) missing.push_back("number_of_rolling_elements");
  if (!g.element_diameter) missing.push_back("diameter_of_rolling_element");
  if (!g.pitch_diameter) missing.push_back("reference_diameter (D_pw)");
  const bool ball = g.type == "deep_groove_ball" || g.type == "angular_contact_ball";
  if (ball && !g.inner_radius) missing.push_back("raceway_radius_of_inner_ring");
  if (ball && !g.outer_radius) missing.push_back("raceway_radius_of_outer_ring");
  if (!ball && !g.length) missing.push_back("length_of_rolling_element");
  const bool angled = g.type != "deep_groove_ball" && g.type != "cylindrical_roller";
  if (angled && !g.angle_deg) missing.push_back("pressure_angle");
  return missing;
}

}  // namespace

bool addRollingBearingGeometry(Model& model, const Component& bearing, TomlSection& t) {
  if (bearing.type != "rolling_bearing_with_detailed_geometry" &&
      bearing.type != "rolling_bearing_with_catalog_geometry")
    return false;
  auto& read = model.read;
  const auto rows = partsOfType(model, bearing.id, "rolling_bearing_row");
  if (rows.empty()) return false;  // a catalogue bearing by its designation only
  RexsBearingGeometry g = readGeometry(model, bearing, rows);
  // Rows with a pressure angle only (the FVA and SEW models' catalogue bearings): a bearing by
  // its designation, silently on its stiffness keys; a row that gives part of the geometry is
  // named below.
  if (!g.elements && !g.element_diameter && !g.pitch_diameter) return false;
  const std::string rexs_type = read.text(bearing, "bearing_type").value_or("");
  g.type = geardynType(rexs_type);
  if (g.type.empty()) {
    read.warn(
        fmt::format("{}: bearing_type \"{}\" has no geometry model in geardyn (deep-groove "
                    "and angular-contact ball, cylindrical, needle, tapered and spherical "
                    "roller bearings); its stiffness keys are used",
                    bearing.label(), rexs_type));
    return false;
  }
  const auto missing = missingAttributes(g);
  if (!missing.empty()) {
    std::string list;
    for (const auto& m : missing) list += (list.empty() ? "" : ", ") + m;
    read.warn(
        fmt::format("{}: its rows lack {} for a {} bearing from its geometry; its stiffness "
                    "keys are used",
                    bearing.label(), list, g.type));
    return false;
  }
  const std::string note = fmt::format("rolling_bearing_row {}", rows.front()->id);
  t.add("type", tomlString(g.type), fmt::format("bearing_type {}", rexs_type));
  t.add("elements", std::to_string(*g.elements), note + ": number_of_rolling_elements");
  t.add("element_diameter", tomlReal(*g.element_diameter), "diameter_of_rolling_element");
  t.add("pitch_diameter", tomlReal(*g.pitch_diameter), "reference_diameter D_pw");
  if (g.angle_deg) t.add("contact_angle_deg", tomlReal(*g.angle_deg), "pressure_angle");
  if (g.type == "deep_groove_ball" || g.type == "angular_contact_ball") {
    t.add("inner_groove_radius", tomlReal(*g.inner_radius), "raceway_radius_of_inner_ring");
    t.add("outer_groove_radius", tomlReal(*g.outer_radius), "raceway_radius_of_outer_ring");
  } else {
    t.add("roller_length", tomlReal(*g.length), "length_of_rolling_element");
    if (g.crowning_radius && *g.crowning_radius > 0) {
      // A circular crown of radius r over L: drop (L/2)² / (2 r) at the ends.
      t.add("profile", tomlString("crowned"), "roller_crowning_radius");
      t.add("crown_drop", tomlReal(0.125 * *g.length * *g.length / *g.crowning_radius),
            fmt::format("L^2 / (8 r), r = {} m", tomlReal(*g.crowning_radius)));
    }
  }
  if (g.rows == 2 && g.type != "spherical_roller") {
    t.add("arrangement", tomlString("back_to_back"), "number_of_bearing_rows = 2");
    t.add("row_spacing", tomlReal(g.row_spacing.value_or(0.0)), "distance_between_bearing_rows");
  } else if (g.reversed && g.rows == 1) {
    t.add("reversed", "true", "pressure_angle < 0 or axial_force_absorption_of_row = negative");
  }
  if (g.clearance) {
    t.add("radial_clearance", tomlReal(0.5 * *g.clearance),
          fmt::format("half the radial bearing clearance s_r = {} m", tomlReal(*g.clearance)));
  } else {
    t.add("radial_clearance", "0.0", "NOT IN THE FILE: no clearance");
    read.warn(
        fmt::format("{}: no radial bearing clearance in the file: taken as 0 (the "
                    "stiffness depends on it)",
                    bearing.label()));
  }
  if (g.rating && *g.rating > 0)
    t.add("dynamic_load_rating", tomlReal(*g.rating), "radial_dynamic_load_rating");
  if (const Component* m = model.material(bearing.id)) {
    const std::string from = fmt::format("material component {}", m->id);
    if (auto e = read.real(*m, "elastic_modulus")) t.add("youngs_modulus", tomlReal(*e), from);
    if (auto nu = read.real(*m, "poisson_ratio")) t.add("poisson_ratio", tomlReal(*nu), from);
  }
  if (auto kr = read.real(bearing, "radial_stiffness"))
    t.add("# radial_stiffness", tomlReal(*kr), "in the file; the geometry gives the stiffness");
  return true;
}

}  // namespace geardyn::io::rexs::detail
