/// `geardyn ltca` on a mesh of a gearbox: the ltca file names the gearbox (`[gearbox] file`) and
/// one of its meshes (`mesh`); the mesh's gears become [pinion] and [gear], its centre distance
/// pair.centre_distance (the file's [pair] may give driver and speed_rpm), its flank
/// modifications [modifications] (unless the ltca file gives its own) and its static force at
/// the gearbox's operating point ltca.force (unless given). The result is the
/// configuration of a standalone pair, validated by the same schema: the tables are those of
/// `geardyn ltca` on that pair.

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "geardyn/config/did_you_mean.h"
#include "geardyn/config/gearbox_config.h"
#include "geardyn/config/ltca_config.h"
#include "geardyn/config/rexs_gearbox_config.h"
#include "geardyn/config/toml_parse.h"
#include "geardyn/error.h"
#include "geardyn/io/rexs/rexs_gearbox.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn::config {
namespace {

using Json = nlohmann::ordered_json;

toml::array tomlArray(const Json& values);

/// `value` as a TOML node under `key` of `table` (nulls skipped).
void insertJson(toml::table& table, const std::string& key, const Json& value) {
  if (value.is_null()) return;
  if (value.is_boolean()) {
    table.insert_or_assign(key, value.get<bool>());
  } else if (value.is_number_integer()) {
    table.insert_or_assign(key, value.get<std::int64_t>());
  } else if (value.is_number()) {
    table.insert_or_assign(key, value.get<double>());
  } else if (value.is_string()) {
    table.insert_or_assign(key, value.get<std::string>());
  } else if (value.is_array()) {
    table.insert_or_assign(key, tomlArray(value));
  } else if (value.is_object()) {
    toml::table sub;
    for (const auto& [k, v] : value.items()) insertJson(sub, k, v);
    table.insert_or_assign(key, std::move(sub));
  }
}

toml::array tomlArray(const Json& values) {
  toml::array out;
  for (const Json& v : values) {
    if (v.is_boolean()) out.push_back(v.get<bool>());
    if (v.is_number_integer()) out.push_back(v.get<std::int64_t>());
    if (v.is_number_float()) out.push_back(v.get<double>());
    if (v.is_string()) out.push_back(v.get<std::string>());
    if (v.is_array()) out.push_back(tomlArray(v));
  }
  return out;
}

/// The string at `key` ("gearbox.file") of the file's table, or of the last --set of it.
std::string keyOf(const toml::table& table, const std::string& key,
                  const std::vector<std::string>& overrides) {
  std::string value;
  if (auto node = table.at_path(key); node && node.is_string()) value = *node.value<std::string>();
  for (const std::string& o : overrides) {
    const auto eq = o.find('=');
    if (eq == std::string::npos) continue;
    std::string k = o.substr(0, eq), v = o.substr(eq + 1);
    k.erase(k.find_last_not_of(" \t") + 1);
    k.erase(0, k.find_first_not_of(" \t"));
    if (k != key) continue;
    v.erase(v.find_last_not_of(" \t") + 1);
    v.erase(0, v.find_first_not_of(" \t"));
    try {  // TOML ("stage1") or a bare word, as parseConfig reads it
      const toml::table parsed = parseToml("v = " + v, "--set");
      if (auto s = parsed["v"].value<std::string>()) v = *s;
    } catch (const toml::parse_error&) {
    }
    value = v;
  }
  return value;
}

/// The mesh's transmitted force along the transverse line of action [N] at the gearbox's
/// operating point: the static normal force (solveTrainStatic) × cos β_b.
double staticTransverseForce(const Config& gearbox, const std::string& mesh) {
  std::vector<std::string> warnings;
  const GearTrainModel model(gearTrainFromConfig(gearbox, warnings));
  const TrainStaticResult statics = solveTrainStatic(model, model.inputSpeed());
  for (std::size_t m = 0; m < model.meshes().size(); ++m) {
    if (model.meshes()[m].name != mesh) continue;
    const double force = statics.mesh_force[m] * std::cos(model.meshes()[m].base_helix_angle);
    if (!(force > 0.0)) {
      throw InputError("ltca.force",
                       fmt::format("{:g} N (mesh {} at the operating point)", force, mesh),
                       "a force > 0: the mesh transmits no load at the gearbox's operating point; "
                       "give ltca.force");
    }
    return force;
  }
  throw InputError("gearbox.mesh", mesh, "a mesh of the assembled gear train");
}

}  // namespace

Config loadLtcaOnGearboxMesh(const std::filesystem::path& file, const ConfigSchema& schema,
                             const std::vector<std::string>& overrides) {
  const std::string text = readConfigFile(file);
  toml::table table;
  try {
    table = parseToml(text, file.string());
  } catch (const toml::parse_error&) {
    return parseConfig(text, file.string(), schema, overrides);  // the syntax error, located
  }
  const std::string ref = keyOf(table, "gearbox.file", overrides);
  const std::string mesh = keyOf(table, "gearbox.mesh", overrides);
  if (mesh.empty()) {
    throw InputError("gearbox.mesh", "(missing)",
                     "the name of a mesh of the gearbox ([meshes.<name>]) with gearbox.file");
  }
  for (const char* section : {"pinion", "gear"}) {
    if (table.contains(section)) {
      throw InputError(section, fmt::format("[{}]", section),
                       "absent with gearbox.file: the pair is the gearbox mesh's gears");
    }
  }
  if (table.at_path("pair.centre_distance")) {
    throw InputError("pair.centre_distance", "(given)",
                     "absent with gearbox.file: the mesh's centre_distance (or the zero-backlash "
                     "distance) is used");
  }
  std::vector<std::string> warnings;
  const Config gearbox =
      config::loadGearboxConfig(file.parent_path() / ref, {}, std::nullopt, warnings);
  const std::vector<std::string> names = gearbox.names("meshes");
  if (std::find(names.begin(), names.end(), mesh) == names.end()) {
    std::string allowed = "a mesh of the gearbox's [meshes]:";
    for (const auto& n : names) allowed += " " + n;
    if (names.empty()) allowed += " (none; planetary meshes are not supported)";
    if (const auto match = closestMatch(mesh, names)) allowed += "; did you mean '" + *match + "'?";
    throw InputError("gearbox.mesh", "\"" + mesh + "\"", allowed);
  }
  const Json resolved = gearbox.resolved();
  const Json& m = resolved["meshes"][mesh];
  const auto gears = m["gears"].get<std::vector<std::string>>();
  const char* roles[] = {"pinion", "gear"};
  for (int i = 0; i < 2; ++i) {
    const Json& g = resolved["gears"][gears[i]];
    if (g.value("internal", false)) {
      throw InputError("gearbox.mesh", "\"" + mesh + "\"",
                       "an external mesh (gear " + gears[i] +
                           " is internal: the loaded contact of internal gears is not supported)");
    }
    toml::table gear;
    for (const auto& [k, v] : g.items()) {
      if (k != "shaft" && k != "internal" && k != "body" && k != "position") insertJson(gear, k, v);
    }
    table.insert_or_assign(roles[i], std::move(gear));
  }
  if (m.contains("centre_distance") && !m["centre_distance"].is_null()) {
    if (!table.contains("pair")) table.insert_or_assign("pair", toml::table{});
    if (toml::table* pair = table["pair"].as_table()) {
      pair->insert_or_assign("centre_distance", m["centre_distance"].get<double>());
    }
  }
  if (!table.contains("modifications") && m.contains("modifications")) {
    insertJson(table, "modifications", m["modifications"]);
  }
  const bool force_given =
      table.at_path("ltca.force") ||
      std::any_of(overrides.begin(), overrides.end(), [](const std::string& o) {
        std::string key = o.substr(0, o.find('='));
        key.erase(key.find_last_not_of(" \t") + 1);
        key.erase(0, key.find_first_not_of(" \t"));
        return key == "ltca.force";
      });
  if (!force_given) {
    if (!table.contains("ltca")) table.insert_or_assign("ltca", toml::table{});
    table["ltca"].as_table()->insert_or_assign("force", staticTransverseForce(gearbox, mesh));
  }
  std::ostringstream out;
  out << table;
  return parseConfig(out.str(), file.string(), schema, overrides);
}

}  // namespace geardyn::config
