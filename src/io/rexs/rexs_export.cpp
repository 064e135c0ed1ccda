/// Gearbox description → REXS JSON (rexs_gearbox.h), in the structure the importer reads, so
/// that import → export → import gives the same description.

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>

#include "geardyn/io/rexs/rexs_gearbox.h"
#include "geardyn/version.h"

namespace geardyn::io::rexs {
namespace {

using Json = nlohmann::ordered_json;
constexpr double kPi = std::numbers::pi;

Json real(const std::string& id, const std::string& unit, double v) {
  return {{"id", id}, {"unit", unit}, {"floating_point", v}};
}
Json vec(const std::string& id, const std::string& unit, std::vector<double> v) {
  return {{"id", id}, {"unit", unit}, {"floating_point_array", v}};
}

class Writer {
 public:
  int add(const std::string& type, const std::string& name, Json attributes) {
    const int id = next_++;
    components_.push_back({{"id", id}, {"type", type}, {"name", name}, {"attributes", attributes}});
    return id;
  }
  void relate(const std::string& type,
              std::vector<std::tuple<int, std::string, std::string>> refs) {
    Json r = {
        {"id", static_cast<int>(relations_.size()) + 1}, {"type", type}, {"refs", Json::array()}};
    for (const auto& [id, role, hint] : refs)
      r["refs"].push_back({{"id", id}, {"role", role}, {"hint", hint}});
    relations_.push_back(r);
  }
  void part(int assembly, const std::string& a_hint, int part, const std::string& p_hint) {
    relate("assembly", {{assembly, "assembly", a_hint}, {part, "part", p_hint}});
  }
  Json components_ = Json::array(), relations_ = Json::array();

 private:
  int next_ = 1;
};

Json material(double e, double nu, double rho) {
  return Json::array({real("elastic_modulus", "MPa", e / 1e6), real("poisson_ratio", "none", nu),
                      real("density", "kg / dm^3", rho / 1000)});
}

/// REXS bearing_type of the gearbox file's geometric bearing types (the importer's table,
/// rexs_bearings.cpp, read backwards).
const char* rexsBearingType(const std::string& type) {
  if (type == "deep_groove_ball") return "radial_grooved_ball_bearing";
  if (type == "angular_contact_ball") return "angular_contact_ball_bearing";
  if (type == "cylindrical_roller") return "radial_roller_bearing";
  if (type == "tapered_roller") return "radial_tapered_roller_bearing";
  return "radial_self_aligning_roller_bearing";
}

/// A bearing from its geometry as rolling_bearing_with_detailed_geometry with one
/// rolling_bearing_row (ordered_assembly) holding one rolling_element; what REXS cannot hold
/// (the slice count, a logarithmic or straight profile, a face-to-face pair, other materials) is
/// warned about. Returns the bearing's id.
int addRollingBearing(Writer& w, const std::string& name, const Json& b, Json attrs,
                      std::vector<std::string>& warnings) {
  const std::string type = b["type"];
  const bool ball = type == "deep_groove_ball" || type == "angular_contact_ball";
  const std::string arrangement = b.value("arrangement", "single");
  const bool pair = arrangement != "single";
  attrs.push_back({{"id", "bearing_type"}, {"unit", "none"}, {"enum", rexsBearingType(type)}});
  attrs.push_back(
      real("operating_radial_bearing_clearance", "mum", 2e6 * b.value("radial_clearance", 0.0)));
  attrs.push_back({{"id", "number_of_bearing_rows"}, {"unit", "none"}, {"integer", pair ? 2 : 1}});
  if (pair)
    attrs.push_back(
        real("distance_between_bearing_rows", "mm", 1000 * b.value("row_spacing", 0.0)));
  if (b.value("dynamic_load_rating", 0.0) > 0)
    attrs.push_back(
        real("radial_dynamic_load_rating", "kN", b["dynamic_load_rating"].get<double>() / 1000));
  const int id = w.add("rolling_bearing_with_detailed_geometry", name, attrs);
  const double angle = b.value("contact_angle_deg", 0.0) * (b.value("reversed", false) ? -1 : 1);
  Json row = {
      {{"id", "number_of_rolling_elements"}, {"unit", "none"}, {"integer", b["elements"]}},
      real("pressure_angle", "deg", angle),
      real("reference_diameter_rolling_bearing", "mm", 1000 * b["pitch_diameter"].get<double>())};
  Json element = {
      real("diameter_of_rolling_element", "mm", 1000 * b["element_diameter"].get<double>())};
  if (ball) {
    row.push_back(
        real("raceway_radius_of_inner_ring", "mm", 1000 * b["inner_groove_radius"].get<double>()));
    row.push_back(
        real("raceway_radius_of_outer_ring", "mm", 1000 * b["outer_groove_radius"].get<double>()));
  } else {
    const double length = b["roller_length"];
    element.push_back(real("length_of_rolling_element", "mm", 1000 * length));
    const std::string profile = b.value("profile", "logarithmic");
    // ISO/TS 16281's logarithmic profile is the importer's default; a crown is its radius.
    if (profile == "crowned" && b.value("crown_drop", 0.0) > 0)
      element.push_back(real("roller_crowning_radius", "mm",
                             1000 * length * length / (8 * b["crown_drop"].get<double>())));
    else if (profile != "logarithmic")
      warnings.push_back("bearings." + name +
                         ": REXS holds a roller's crowning radius, not a straight profile; the "
                         "importer gives it the logarithmic one");
    if (b.value("slices", 20) != 20)
      warnings.push_back("bearings." + name + ": the slice count is geardyn's; not exported");
  }
  if (arrangement == "face_to_face")
    warnings.push_back("bearings." + name +
                       ": REXS's two rows are read back to back; the face-to-face pair is not "
                       "exported as such");
  if (b.value("youngs_modulus", 2.1e11) != 2.1e11 || b.value("poisson_ratio", 0.3) != 0.3 ||
      b.contains("element_youngs_modulus") || b.contains("element_poisson_ratio"))
    warnings.push_back("bearings." + name +
                       ": the rings' and elements' materials are not exported");
  const int r = w.add("rolling_bearing_row", name + " row", row);
  w.relate("ordered_assembly", {{id, "assembly", "rolling_bearing_with_detailed_geometry"},
                                {r, "part", "rolling_bearing_row"}});
  w.part(r, "rolling_bearing_row", w.add("rolling_element", name + " rolling element", element),
         "rolling_element");
  return id;
}

/// One export (exportRexsJson): the configuration read, the REXS components written so far with
/// the ids of the shafts and gears they refer to, and the warnings about what REXS cannot hold.
/// Each step writes one kind of component, in the order the relations need them.
class Exporter {
 public:
  Exporter(const Json& cfg, std::vector<std::string>& warnings)
      : cfg(cfg), warnings(warnings), op(cfg["operating_point"]) {
    unit = w.add("gear_unit", cfg["gearbox"]["name"].get<std::string>(), Json::array());
    casing = w.add("gear_casing", "casing", Json::array());
    w.part(unit, "gear_unit", casing, "gear_casing");
  }
  /// Every component, then the operating point as the one load case: the REXS JSON text.
  std::string json() {
    shafts();
    gearsAndMeshes();
    planetaryStages();
    bearings();
    couplingsAndDisks();
    return document();
  }

 private:
  Json shaftAttributes(double x, bool input) const;
  /// The shaft's sections from the gearbox's section lists (one diameter: every section).
  void addSections(int shaft, const std::vector<double>& l, const std::vector<double>& o,
                   const std::vector<double>& in, const std::string& name);
  /// A gear (or ring gear) on `shaft` at u [m] with its two flanks and material.
  int addGear(const std::string& name, const Json& g, int shaft, bool ring, double u);
  void shafts();
  void gearsAndMeshes();
  void planetaryStages();
  void bearings();
  void couplingsAndDisks();
  std::string document();

  const Json& cfg;
  std::vector<std::string>& warnings;
  const Json& op;
  Writer w;
  int unit = 0, casing = 0;
  std::map<std::string, int> shaft_id, gear_id;
};

Json Exporter::shaftAttributes(double x, bool input) const {
  return Json::array({vec("support_vector", "mm", {x * 1000, 0.0, 0.0}),
                      vec("u_axis_vector", "none", {1.0, 0.0, 0.0}),
                      {{"id", "defines_speed"}, {"unit", "none"}, {"boolean", input}}});
}

void Exporter::addSections(int shaft, const std::vector<double>& l, const std::vector<double>& o,
                           const std::vector<double>& in, const std::string& name) {
  double u = 0.0;
  for (std::size_t i = 0; i < l.size(); ++i) {
    const double d = o.size() == 1 ? o[0] : o[i];
    const double di = in.empty() ? 0.0 : in.size() == 1 ? in[0] : in[i];
    const int s = w.add(
        "shaft_section", fmt::format("{} section {}", name, i + 1),
        {real("u_coordinate_on_shaft", "mm", u * 1000), real("length", "mm", l[i] * 1000),
         real("outer_diameter_begin", "mm", d * 1000), real("outer_diameter_end", "mm", d * 1000),
         real("inner_diameter_begin", "mm", di * 1000),
         real("inner_diameter_end", "mm", di * 1000)});
    w.part(shaft, "shaft", s, "shaft_section");
    u += l[i];
  }
}

int Exporter::addGear(const std::string& name, const Json& g, int shaft, bool ring, double u) {
  const int id = w.add(ring ? "ring_gear" : "cylindrical_gear", name,
                       {{{"id", "number_of_teeth"}, {"unit", "none"}, {"integer", g["teeth"]}},
                        real("normal_module", "mm", g["module"].get<double>() * 1000),
                        real("helix_angle_reference_diameter", "deg", g["helix_angle_deg"]),
                        real("face_width", "mm", g["face_width"].get<double>() * 1000),
                        real("u_coordinate_on_shaft", "mm", u * 1000)});
  w.part(shaft, "shaft", id, ring ? "ring_gear" : "cylindrical_gear");
  const Json flank_attrs = {real("normal_pressure_angle", "deg", g["pressure_angle_deg"]),
                            real("addendum_modification_coefficient", "none", g["profile_shift"])};
  const int left = w.add("cylindrical_gear_flank", name + " left flank", flank_attrs);
  const int right = w.add("cylindrical_gear_flank", name + " right flank", flank_attrs);
  w.relate("flank", {{id, "gear", ""}, {left, "left", ""}, {right, "right", ""}});
  const int m = w.add("material", name + " material",
                      material(g["youngs_modulus"], g["poisson_ratio"], g["density"]));
  w.relate("reference", {{id, "origin", ""}, {m, "referenced", "material"}});
  return id;
}

void Exporter::shafts() {
  for (const auto& [name, s] : cfg["shafts"].items()) {
    const int id =
        w.add("shaft", name, shaftAttributes(s["axial_offset"].get<double>(), name == op["input"]));
    shaft_id[name] = id;
    w.part(unit, "gear_unit", id, "shaft");
    addSections(id, s["section_lengths"], s["outer_diameters"], s["inner_diameters"], name);
    const int m = w.add("material", name + " material",
                        material(s["youngs_modulus"], s["poisson_ratio"], s["density"]));
    w.relate("reference", {{id, "origin", "shaft"}, {m, "referenced", "material"}});
    bool carrier = false;
    for (const auto& [_, p] : cfg["planetary"].items()) carrier |= p["carrier"] == name;
    // The shaft's own lumped mass and inertia (a motor's rotor, a hub) as an additional mass
    // at its mid-length, the import's disk (a carrier's go to its side plate below).
    if (!carrier && (s["mass"].get<double>() != 0 || s["polar_inertia"].get<double>() != 0 ||
                     s["diametral_inertia"].get<double>() != 0)) {
      double length = 0.0;
      for (const auto& l : s["section_lengths"]) length += l.get<double>();
      const int lumped =
          w.add("additional_mass", name + " lumped mass",
                {real("u_coordinate_on_shaft", "mm", 0.5 * length * 1000),
                 real("mass_of_component", "kg", s["mass"]),
                 real("moment_of_inertia_u_axis", "kg m^2", s["polar_inertia"]),
                 real("moment_of_inertia_v_axis", "kg m^2", s["diametral_inertia"]),
                 real("moment_of_inertia_w_axis", "kg m^2", s["diametral_inertia"])});
      w.part(id, "shaft", lumped, "additional_mass");
    }
  }
}

void Exporter::gearsAndMeshes() {
  for (const auto& [name, g] : cfg["gears"].items())
    gear_id[name] = addGear(name, g, shaft_id.at(g["shaft"]), g["internal"], g["position"]);
  for (const auto& [name, m] : cfg["meshes"].items()) {
    const double angle = m["position_angle_deg"].get<double>() * kPi / 180;
    Json attrs = {real("rotating_angle_around_neg_u_axis", "deg",
                       std::atan2(std::cos(angle), std::sin(angle)) * 180 / kPi)};
    if (!m["centre_distance"].is_null())
      attrs.push_back(real("center_distance", "mm", m["centre_distance"].get<double>() * 1000));
    const int st = w.add("cylindrical_stage", name, attrs);
    w.part(unit, "gear_unit", st, "cylindrical_stage");
    w.relate("stage", {{st, "stage", "cylindrical_stage"},
                       {gear_id.at(m["gears"][0]), "gear_1", ""},
                       {gear_id.at(m["gears"][1]), "gear_2", ""}});
    // An absent stiffness is the external mesh's default, potential_energy.
    const bool own_stiffness = m.contains("stiffness") && !m["stiffness"].is_null() &&
                               m["stiffness"] != "potential_energy";
    if (own_stiffness || !m["te_amplitudes"].empty() ||
        m.value("te_rectangular_amplitude", 0.0) != 0.0 ||
        !m.value("te_table_phases", Json::array()).empty())
      warnings.push_back("meshes." + name +
                         ": the mesh-stiffness model and transmission error "
                         "are geardyn's; not exported");
  }
}

void Exporter::planetaryStages() {
  for (const auto& [name, p] : cfg["planetary"].items()) {
    const int st = w.add("planetary_stage", name, Json::array());
    w.part(unit, "gear_unit", st, "planetary_stage");
    const int carrier = shaft_id.at(p["carrier"]);
    w.relate("planet_carrier_shaft", {{st, "planetary_stage", ""}, {carrier, "shaft", ""}});
    // The carrier's own mass and inertia (e.g. merged carrier members) as a side plate of its
    // planet carrier: an annulus with that mass and inertia (ro² + ri² = 2 J / m).
    const double cm = cfg["shafts"][p["carrier"].get<std::string>()]["mass"];
    const double cj = cfg["shafts"][p["carrier"].get<std::string>()]["polar_inertia"];
    if (cm > 0 && cj > 0) {
      const int pc = w.add("planet_carrier", name + " carrier", Json::array());
      w.part(st, "planetary_stage", pc, "planet_carrier");
      double length = 0.01, ri2 = (2 * cj / cm - cm / (7850.0 * kPi * length)) / 2;
      if (ri2 < 0) ri2 = 0, length = cm / (7850.0 * kPi * 2 * cj / cm);
      const double ro2 = 2 * cj / cm - ri2;
      const int plate = w.add(
          "side_plate", name + " carrier mass",
          {real("length", "mm", length * 1000), real("outer_diameter", "mm", 2000 * std::sqrt(ro2)),
           real("inner_diameter", "mm", 2000 * std::sqrt(ri2))});
      w.part(pc, "planet_carrier", plate, "side_plate");
    }
    const Json& planet = p["planet"];
    const int n = p["planets"];
    std::vector<double> angles = p["planet_angles_deg"];
    if (angles.empty())
      for (int i = 0; i < n; ++i) angles.push_back(360.0 * i / n);
    const double r = planet["module"].get<double>() * 1000 * 10;  // any radius: only ψ is read
    const double mass = p["planet_mass"], inertia = p["planet_inertia"];
    for (int i = 0; i < n; ++i) {
      const double psi = angles[i] * kPi / 180;
      const int ps =
          w.add("shaft", fmt::format("{} planet {}", name, i + 1),
                {vec("support_vector", "mm", {0.0, r * std::cos(psi), r * std::sin(psi)})});
      w.relate("planet_shaft", {{st, "planetary_stage", ""}, {ps, "shaft", ""}});
      if (mass > 0) {  // one section with the planet's extra mass and inertia; bore = its outer
        const double ro2 = std::pow(planet["bore_diameter"].get<double>() / 2, 2),
                     ratio = 2 * inertia / mass;
        double ri2 = ratio - ro2, outer2 = ro2;
        if (!(ri2 >= 0 && ri2 < ro2)) outer2 = ratio, ri2 = 0;
        const double length = mass / (7850.0 * kPi * (outer2 - ri2));
        addSections(ps, {length}, {2 * std::sqrt(outer2)}, {2 * std::sqrt(ri2)}, name);
      }
      const int g = addGear(fmt::format("{} planet gear {}", name, i + 1), planet, ps, false, 0.0);
      const int sp =
          w.add("cylindrical_stage", fmt::format("{} sun-planet {}", name, i + 1), Json::array());
      const int rp =
          w.add("cylindrical_stage", fmt::format("{} ring-planet {}", name, i + 1), Json::array());
      w.part(st, "planetary_stage", sp, "cylindrical_stage");
      w.part(st, "planetary_stage", rp, "cylindrical_stage");
      w.relate("stage",
               {{sp, "stage", ""}, {gear_id.at(p["sun"]), "gear_1", ""}, {g, "gear_2", ""}});
      w.relate("stage",
               {{rp, "stage", ""}, {g, "gear_1", ""}, {gear_id.at(p["ring"]), "gear_2", ""}});
      const int b = w.add("concept_bearing", fmt::format("{} planet bearing {}", name, i + 1),
                          {real("radial_stiffness", "N / m", p["pin_radial_stiffness"])});
      w.relate(
          "side",
          {{b, "assembly", ""}, {carrier, "inner_part", "shaft"}, {ps, "outer_part", "shaft"}});
    }
    if (p["pin_tangential_stiffness"] != p["pin_radial_stiffness"])
      warnings.push_back("planetary." + name +
                         ".pin_tangential_stiffness: REXS bearings are "
                         "isotropic; the radial value is exported");
  }
}

void Exporter::bearings() {
  for (const auto& [name, b] : cfg["bearings"].items()) {
    const bool held = b["k_torsion"].get<double>() > 0 && b["other_shaft"] == "";
    Json attrs = {
        real("radial_stiffness", "N / m", b["kyy"]),
        real("u_coordinate_on_shaft_inner_side", "mm", b["position"].get<double>() * 1000),
        real("u_coordinate_on_shaft_outer_side", "mm", b["other_position"].get<double>() * 1000)};
    if (b["k_axial"].get<double>() > 0)
      attrs.push_back(real("axial_stiffness", "N / m", b["k_axial"]));
    if (b["k_tilt"].get<double>() > 0)
      attrs.push_back(real("bending_stiffness", "N mm / rad", b["k_tilt"].get<double>() * 1000));
    if (held)
      attrs.push_back(
          real("rotational_stiffness", "N mm / rad", b["k_torsion"].get<double>() * 1000));
    const bool geometric = b.value("type", "stiffness") != "stiffness";
    if (geometric) attrs.erase(0);  // its stiffness follows from the geometry
    const int id = geometric ? addRollingBearing(w, name, b, attrs, warnings)
                             : w.add(held ? "coupling" : "concept_bearing", name, attrs);
    const int outer = b["other_shaft"] == "" ? casing : shaft_id.at(b["other_shaft"]);
    w.relate("side", {{id, "assembly", ""},
                      {shaft_id.at(b["shaft"]), "inner_part", "shaft"},
                      {outer, "outer_part", ""}});
    if ((!geometric && b["kyy"] != b["kzz"]) || b["kyz"].get<double>() != 0 ||
        b["kzy"].get<double>() != 0 || b["cyy"].get<double>() != 0 || b["czz"].get<double>() != 0 ||
        b["c_torsion"].get<double>() != 0)
      warnings.push_back("bearings." + name +
                         ": REXS holds one radial stiffness and no damping; "
                         "kyy exported, kzz, cross terms and damping not");
  }
}

void Exporter::couplingsAndDisks() {
  for (const auto& [name, c] : cfg["couplings"].items()) {
    const int id =
        w.add("coupling", name,
              {real("rotational_stiffness", "N mm / rad", c["k_torsion"].get<double>() * 1000),
               real("radial_stiffness", "N / m", c["k_lateral"])});
    w.relate("side", {{id, "assembly", ""},
                      {shaft_id.at(c["shafts"][0]), "inner_part", "shaft"},
                      {shaft_id.at(c["shafts"][1]), "outer_part", "shaft"}});
  }
  for (const auto& [name, d] : cfg["disks"].items()) {
    const int id = w.add("additional_mass", name,
                         {real("u_coordinate_on_shaft", "mm", d["position"].get<double>() * 1000),
                          real("mass_of_component", "kg", d["mass"]),
                          real("moment_of_inertia_u_axis", "kg m^2", d["polar_inertia"]),
                          real("moment_of_inertia_v_axis", "kg m^2", d["diametral_inertia"]),
                          real("moment_of_inertia_w_axis", "kg m^2", d["diametral_inertia"])});
    w.part(shaft_id.at(d["shaft"]), "shaft", id, "additional_mass");
  }
}

std::string Exporter::document() {
  // The operating point as the one load case.
  const int in_load = w.add("external_load", "input load",
                            {{{"id", "defines_torque"}, {"unit", "none"}, {"boolean", true}},
                             {{"id", "transmits_torque"}, {"unit", "none"}, {"boolean", true}}});
  w.part(shaft_id.at(op["input"]), "shaft", in_load, "external_load");
  const int out_load = w.add("external_load", "output load",
                             {{{"id", "transmits_torque"}, {"unit", "none"}, {"boolean", true}}});
  w.part(shaft_id.at(op["output"]), "shaft", out_load, "external_load");
  Json load_case = {{"id", 1}, {"components", Json::array()}};
  load_case["components"].push_back(
      {{"id", shaft_id.at(op["input"])},
       {"type", "shaft"},
       {"name", op["input"]},
       {"attributes", {real("rotational_speed", "1 / min", op["speed_rpm"])}}});
  load_case["components"].push_back(
      {{"id", in_load},
       {"type", "external_load"},
       {"name", "input load"},
       {"attributes", {real("torque_around_u_axis", "N m", op["torque"])}}});
  Json model = {{"version", kRexsExportVersion},
                {"applicationId", "geardyn"},
                {"applicationVersion", kVersion},
                {"relations", w.relations_},
                {"components", w.components_},
                {"load_spectrum", {{"id", 1}, {"load_cases", Json::array({load_case})}}}};
  return Json{{"model", model}}.dump(2) + "\n";
}

}  // namespace

std::string exportRexsJson(const Json& cfg, std::vector<std::string>& warnings) {
  return Exporter(cfg, warnings).json();
}

}  // namespace geardyn::io::rexs
