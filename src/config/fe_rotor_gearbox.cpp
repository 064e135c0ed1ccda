/// The gearbox an FE geared rotor file is (fe_rotor_gearbox.h).

#include "geardyn/config/fe_rotor_gearbox.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "geardyn/config/config_schema.h"
#include "geardyn/config/detail/toml_text.h"
#include "geardyn/config/fe_rotor_config.h"
#include "geardyn/config/gearbox_config.h"
#include "geardyn/config/geometry_config.h"
#include "geardyn/error.h"

namespace geardyn::config {
namespace {

using Json = nlohmann::ordered_json;

using detail::tomlReal;
using detail::tomlReals;

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

/// A resolved configuration value as TOML (strings, booleans, numbers and lists of them).
std::string value(const Json& j) {
  if (j.is_string()) return quoted(j.get<std::string>());
  if (j.is_boolean()) return j.get<bool>() ? "true" : "false";
  if (j.is_number_integer()) return fmt::format("{}", j.get<long long>());
  if (j.is_number()) return tomlReal(j.get<double>());
  if (j.is_array()) {
    std::string out = "[";
    for (std::size_t i = 0; i < j.size(); ++i) out += (i ? ", " : "") + value(j[i]);
    return out + "]";
  }
  return quoted(j.dump());
}

/// The keys of a resolved table (nulls, i.e. absent optional keys, and subtables left out).
void addTable(std::string& out, const Json& table) {
  for (const auto& [key, v] : table.items()) {
    if (v.is_null() || v.is_object()) continue;
    out += fmt::format("{} = {}\n", key, value(v));
  }
}

/// Every resolved [mesh_stiffness.<model>] table, as the gearbox's shared model options.
void addMeshStiffnessTables(std::string& out, const Json& table, const std::string& prefix) {
  for (const auto& [key, v] : table.items()) {
    if (!v.is_object()) continue;
    out += fmt::format("\n[{}.{}]\n", prefix, key);
    addTable(out, v);
    addMeshStiffnessTables(out, v, prefix + "." + key);
  }
}

/// Refuses what a gearbox description cannot say, naming the FE rotor file's key.
void checkTranslatable(const Config& config, const FeRotorLayout& layout) {
  const bool helical = config.real("pinion.helix_angle_deg") != 0.0;
  if (helical && !layout.axial) {
    throw InputError("model.axial", "false",
                     "true for a helical pair in a gearbox description: a gearbox keeps the "
                     "axial DOFs the helical mesh loads (model.axial = false holds them "
                     "rigidly); give each shaft's bearings k_axial");
  }
  if (config.string("pair.driver") != "pinion") {
    throw InputError("pair.driver", quoted(config.string("pair.driver")),
                     "\"pinion\" in a gearbox description (the mesh's first gear drives)");
  }
}

std::string gearboxText(const Config& config, const FeRotorLayout& layout,
                        const GearTrainSpec& train) {
  const Json& resolved = config.resolved();
  std::string out = fmt::format(
      "# The gearbox of {} (`geardyn rotor --print-gearbox`): its finite-element geared rotor\n"
      "# as a gearbox description (docs/guide/fe_rotor.md, \"Which gearbox this file is\").\n"
      "# Gravity weighs the shafts as well as the disks here (the FE rotor: the disks only).\n",
      config.source());
  out += "\n[gearbox]\n";
  const std::string title = config.string("title");
  out += fmt::format("name = {}\n", quoted(title.empty() ? "fe_geared_rotor" : title));
  out += "dofs = \"full\"\n";
  out += fmt::format("gravity = {}   # m/s^2\n", tomlReal(train.gravity));
  out += fmt::format("mass_proportional_damping = {}   # 1/s\n",
                     tomlReal(train.mass_proportional_damping));
  out += fmt::format("stiffness_proportional_damping = {}   # s (the shafts' own below)\n",
                     tomlReal(train.stiffness_proportional_damping));
  for (const TrainShaftSpec& s : train.shafts) {
    out += fmt::format("\n[shafts.{}]\n", s.name);
    out += fmt::format("section_lengths = {}   # m, one section per FE element\n",
                       tomlReals(s.section_lengths));
    out += fmt::format("outer_diameters = {}   # m\n", tomlReals(s.outer_diameters));
    out += fmt::format("inner_diameters = {}   # m\n", tomlReals(s.inner_diameters));
    out += fmt::format("density = {}   # kg/m^3\n", tomlReal(s.density));
    out += "flexible = true\n";
    out += fmt::format("youngs_modulus = {}   # Pa\n", tomlReal(s.youngs_modulus));
    out += fmt::format("poisson_ratio = {}   # E / 2G - 1\n", tomlReal(s.poisson_ratio));
    out +=
        fmt::format("stiffness_proportional_damping = {}   # s, damping.stiffness_proportional\n",
                    tomlReal(s.stiffness_proportional_damping));
  }
  const char* members[2] = {"pinion", "gear"};
  for (int g = 0; g < 2; ++g) {
    const TrainGearSpec& gear = train.gears[g];
    out += fmt::format("\n[gears.{}]\n", gear.name);
    out += fmt::format("shaft = {}\n", quoted(gear.shaft));
    out += fmt::format("position = {}   # m, node {}\n", tomlReal(gear.position),
                       layout.gear_nodes[g]);
    out += "body = false   # its body is one of the disks\n";
    addTable(out, resolved.at(members[g]));
  }
  for (const TrainDiskSpec& d : train.disks) {
    out += fmt::format("\n[disks.{}]\n", d.name);
    out += fmt::format("shaft = {}\n", quoted(d.shaft));
    out += fmt::format("position = {}   # m\n", tomlReal(d.position));
    out += fmt::format("mass = {}   # kg\n", tomlReal(d.mass));
    out += fmt::format("polar_inertia = {}   # kg m^2\n", tomlReal(d.polar_inertia));
    out += fmt::format("diametral_inertia = {}   # kg m^2\n", tomlReal(d.diametral_inertia));
  }
  for (const TrainBearingSpec& b : train.bearings) {
    out += fmt::format("\n[bearings.{}]\n", b.name);
    out += fmt::format("shaft = {}\n", quoted(b.shaft));
    out += fmt::format("position = {}   # m\n", tomlReal(b.position));
    for (auto [key, v] :
         std::initializer_list<std::pair<const char*, double>>{{"kyy", b.kyy},
                                                               {"kzz", b.kzz},
                                                               {"kyz", b.kyz},
                                                               {"kzy", b.kzy},
                                                               {"cyy", b.cyy},
                                                               {"czz", b.czz},
                                                               {"cyz", b.cyz},
                                                               {"czy", b.czy},
                                                               {"k_axial", b.k_axial},
                                                               {"c_axial", b.c_axial},
                                                               {"k_tilt", b.k_tilt},
                                                               {"c_tilt", b.c_tilt},
                                                               {"k_torsion", b.k_torsion},
                                                               {"c_torsion", b.c_torsion}}) {
      out += fmt::format("{} = {}\n", key, tomlReal(v));
    }
  }
  for (const TrainUnbalanceSpec& u : train.unbalances) {
    out += fmt::format("\n[unbalances.{}]\n", u.name);
    out += fmt::format("shaft = {}\n", quoted(u.shaft));
    out += fmt::format("position = {}   # m\n", tomlReal(u.position));
    out += fmt::format("mass_eccentricity = {}   # kg m\n", tomlReal(u.mass_eccentricity));
    out += fmt::format("phase_deg = {}   # deg\n", tomlReal(u.phase * 180.0 / std::numbers::pi));
  }
  const TrainMeshSpec& m = train.meshes.front();
  out += fmt::format("\n[meshes.{}]\n", m.name);
  out += fmt::format("gears = [{}, {}]\n", quoted(m.gear_a), quoted(m.gear_b));
  out += fmt::format("position_angle_deg = {}   # deg, the line of action of [mesh]\n",
                     tomlReal(m.position_angle * 180.0 / std::numbers::pi));
  if (m.centre_distance)
    out += fmt::format("centre_distance = {}   # m\n", tomlReal(*m.centre_distance));
  out += "phase = 0.0\n";
  out += fmt::format("stiffness = {}\n", quoted(config.string("mesh.stiffness")));
  out += fmt::format("damping = {}   # N s/m\n", tomlReal(config.real("mesh.damping")));
  out +=
      fmt::format("te_amplitudes = {}   # m\n", tomlReals(config.realList("mesh.te_amplitudes")));
  out +=
      fmt::format("te_phases_deg = {}   # deg\n", tomlReals(config.realList("mesh.te_phases_deg")));
  out += "\n[operating_point]\n";
  out += fmt::format("input = {}\n", quoted(train.operating.input_shaft));
  out += fmt::format("output = {}\n", quoted(train.operating.output_shaft));
  out += fmt::format("speed_rpm = {}   # rpm\n", tomlReal(config.real("speed.speed_rpm")));
  out += fmt::format("torque = {}   # N m\n", tomlReal(train.operating.input_torque));
  out += fmt::format("input_position = {}   # m, load.drive_node\n",
                     tomlReal(*train.operating.input_position));
  out += fmt::format("output_position = {}   # m, load.load_node\n",
                     tomlReal(*train.operating.output_position));
  addMeshStiffnessTables(out, resolved.at("mesh_stiffness"), "mesh_stiffness");
  return out;
}

}  // namespace

std::string feRotorGearboxToml(const Config& config) {
  const FeRotorBuild build = feRotorFromConfig(config);
  checkTranslatable(config, build.layout);
  return gearboxText(config, build.layout, build.train);
}

std::optional<std::string> feRotorGearbox(const Config& config) {
  if (!config.resolved().contains("model") || !config.has("model.type") ||
      config.string("model.type") != "fe_geared_rotor") {
    return std::nullopt;
  }
  return feRotorGearboxToml(config);
}

GearTrainSpec feRotorGearTrain(const Config& config, std::vector<std::string>& warnings) {
  const Config gearbox =
      parseConfig(feRotorGearboxToml(config), config.source() + " (as a gearbox)", gearboxSchema());
  return gearTrainFromConfig(gearbox, warnings);
}

}  // namespace geardyn::config
