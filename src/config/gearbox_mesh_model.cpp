/// The keys of a gearbox mesh's model and their readers (config/detail/gearbox_mesh_model.h).

#include "geardyn/config/detail/gearbox_mesh_model.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "geardyn/config/ltca_config.h"
#include "geardyn/config/stiffness_config.h"
#include "geardyn/contact/loaded_contact.h"
#include "geardyn/error.h"
#include "geardyn/models/scaled_contact_elements.h"
#include "geardyn/notes.h"
#include "geardyn/stiffness/api_stiffness.h"
#include "geardyn/stiffness/iso6336_stiffness.h"
#include "geardyn/stiffness/scaled_stiffness.h"
#include "geardyn/stiffness/tabulated_stiffness.h"
#include "geardyn/units.h"

namespace geardyn::config::detail {
namespace {

constexpr double kDeg = geardyn::units::kDegree;
using Json = nlohmann::ordered_json;

}  // namespace

namespace {
const std::vector<std::string> kStiffnessChoices = {
    "constant", "api", "potential_energy", "iso6336", "step", "fourier", "table"};
}  // namespace

void addMeshModelKeys(config::ConfigSchema& schema, const std::string& prefix,
                      const std::string& what) {
  schema.string(prefix + "stiffness")
      .choices(kStiffnessChoices)
      .optional()
      .doc("mesh-stiffness model of " + what +
           " (options in [mesh_stiffness.<model>]); default potential_energy on external "
           "meshes, iso6336 on ring meshes (which take constant, api, iso6336 or table)");
  schema.real(prefix + "stiffness_value")
      .unit("N/m")
      .positive()
      .optional()
      .doc(
          "k when stiffness = \"constant\"; every mesh model's k acts along the contact normal, "
          "inclined by β_b to the transverse plane (torsional stiffness k cos² β_b r_b²)");
  schema.realList(prefix + "stiffness_table_phases")
      .unit("-")
      .min(0.0)
      .lessThan(1.0)
      .defaultValue(Json::array())
      .doc(
          "k(φ) when stiffness = \"table\", linear between points: ascending mesh phases in [0, "
          "1)");
  schema.realList(prefix + "stiffness_table_values")
      .unit("N/m")
      .defaultValue(Json::array())
      .doc("the table's k at stiffness_table_phases (> 0)");
  schema.string(prefix + "stiffness_table_source")
      .defaultValue("table")
      .doc(
          "what the table is, the stiffness model's name in results (e.g. \"ltca\": the loaded "
          "tooth contact's tangent stiffness at the mean force, from a gear-pair file)");
  schema.real(prefix + "damping_ratio")
      .unit("-")
      .min(0.0)
      .defaultValue(0.05)
      .doc(
          "damping ratio of the mesh on its equivalent torsional mass and mean stiffness, "
          "c = 2 zeta sqrt(k m_e) (typical gear meshes: 0.02-0.1; >= 1: overdamped)");
  schema.realList(prefix + "te_amplitudes")
      .unit("m")
      .defaultValue(Json::array())
      .doc("transmission error e(φ) = Σ a_r cos(2π r φ + φ_r) over mesh orders r = 1, 2, …");
  schema.realList(prefix + "te_phases_deg")
      .unit("deg")
      .defaultValue(Json::array())
      .doc("phases φ_r of the TE orders (one per amplitude; empty: 0)");
  // The other forms of the gear-pair file's [model.transmission_error] (models/
  // transmission_error.h), added to the series.
  schema.real(prefix + "te_rectangular_amplitude")
      .unit("m")
      .defaultValue(0.0)
      .doc("rectangular wave added to e(φ): its value on the duty part of each mesh period");
  schema.real(prefix + "te_rectangular_duty")
      .unit("-")
      .greaterThan(0.0)
      .lessThan(1.0)
      .defaultValue(0.5)
      .doc("fraction of the mesh period the rectangular wave is on");
  schema.real(prefix + "te_rectangular_start")
      .unit("-")
      .defaultValue(0.0)
      .doc("mesh phase where the rectangular wave starts [mesh periods]");
  schema.realList(prefix + "te_table_phases")
      .unit("-")
      .min(0.0)
      .lessThan(1.0)
      .defaultValue(Json::array())
      .doc("table added to e(φ), linear between points: mesh phases in [0, 1)");
  schema.realList(prefix + "te_table_values")
      .unit("m")
      .defaultValue(Json::array())
      .doc("the table's e at te_table_phases");
  schema.string(prefix + "contact")
      .choices({"linear", "one_sided", "backlash", "tooth_pairs"})
      .optional()
      .doc("tooth contact of " + what +
           ": linear (never separates), one_sided (contact loss), backlash (free play, then "
           "the back flank) or tooth_pairs (external meshes: one one-sided contact element per "
           "tooth pair and face slice of the loaded tooth contact, potential-energy stiffness, "
           "the flank modifications as gaps); absent: backlash when the backlash key is given, "
           "else linear. The nonlinear analysis uses it; the linear ones keep the teeth in "
           "contact with the stiffness model's k(φ)");
  schema.real(prefix + "backlash")
      .unit("m")
      .positive()
      .optional()
      .doc("normal backlash j along the line of action (contact = \"backlash\")");
}

void addToothPairKeys(config::ConfigSchema& schema, const std::string& prefix) {
  schema.integer(prefix + "tooth_pair_slices")
      .min(1)
      .max(1000)
      .defaultValue(1)
      .doc(
          "contact = \"tooth_pairs\": face slices per tooth pair (helical gears and crowning "
          "need several; spur without crowning: 1). In its [modifications] pinion is the mesh's "
          "first gear (a sun), gear the second (a planet)");
  config::addModificationsSection(schema, prefix + "modifications");
}

namespace {

/// Whether the modifications under `prefix` differ from none (their defaults).
bool hasModifications(const config::Config& config, const std::string& prefix) {
  const std::string p = prefix + "modifications.";
  if (config.string(p + "relief") != "none" || config.has(p + "design_load")) return true;
  for (const char* gear : {"pinion", "gear"}) {
    for (const char* key :
         {"tip_relief", "tip_relief_length", "root_relief", "root_relief_length", "crowning",
          "slope_error", "helix_slope", "end_relief", "end_relief_length"}) {
      if (config.real(fmt::format("{}{}_{}", p, gear, key)) != 0.0) return true;
    }
    for (const char* key : {"pitch_errors", "lead_error_positions", "lead_errors"}) {
      if (!config.realList(fmt::format("{}{}_{}", p, gear, key)).empty()) return true;
    }
  }
  return false;
}

}  // namespace

TrainMeshContact contactFromConfig(const config::Config& config, const std::string& prefix,
                                   const GearPair* pair) {
  TrainMeshContact c;
  const bool has_backlash = config.has(prefix + "backlash");
  const std::string law = config.has(prefix + "contact") ? config.string(prefix + "contact")
                          : has_backlash                 ? "backlash"
                                                         : "linear";
  // The tooth-pair keys exist for external-capable meshes only (not planetary ring meshes).
  const nlohmann::ordered_json* node = &config.resolved();
  for (std::size_t begin = 0, end; (end = prefix.find('.', begin)) != std::string::npos;
       begin = end + 1) {
    const std::string part = prefix.substr(begin, end - begin);
    node = node->is_object() && node->contains(part) ? &(*node)[part] : nullptr;
    if (!node) break;
  }
  const bool tooth_keys = node && node->is_object() && node->contains("tooth_pair_slices");
  if (law == "tooth_pairs") {
    if (!pair || !tooth_keys) {
      throw InputError(prefix + "contact", "\"tooth_pairs\"",
                       "linear, one_sided or backlash on a ring (internal) mesh: the loaded tooth "
                       "contact is written for external pairs");
    }
    if (has_backlash) {
      throw InputError(prefix + "backlash", fmt::format("{:g} m", config.real(prefix + "backlash")),
                       "not with contact = \"tooth_pairs\": the tooth-pair elements are the "
                       "loaded flank's (no back flank); contact = \"backlash\" for free play");
    }
    c.law = ContactLaw::kOneSided;
    const auto contact = config::loadedContactFromConfig(
        config, *pair, static_cast<int>(config.integer(prefix + "tooth_pair_slices")),
        prefix + "modifications");
    c.tooth_pairs = std::make_shared<LoadedContactElements>(contact);
    return c;
  }
  const bool ltca_excitation =
      config.resolved().contains("meshes") && prefix.rfind("meshes.", 0) == 0 &&
      config.has(prefix + "excitation") && config.string(prefix + "excitation") == "ltca";
  if (tooth_keys && hasModifications(config, prefix) && !ltca_excitation) {
    throw InputError(prefix + "modifications", "(given)",
                     fmt::format("only with contact = \"tooth_pairs\" or excitation = \"ltca\" "
                                 "(contact = \"{}\")",
                                 law));
  }
  if (law == "backlash" && !has_backlash) {
    throw InputError(prefix + "backlash", "(absent)",
                     "the normal backlash along the line of action [m] when contact = "
                     "\"backlash\"");
  }
  if (law != "backlash" && has_backlash) {
    throw InputError(prefix + "backlash", fmt::format("{:g} m", config.real(prefix + "backlash")),
                     fmt::format("only with contact = \"backlash\" (contact = \"{}\")", law));
  }
  c.law = law == "backlash"    ? ContactLaw::kBacklash
          : law == "one_sided" ? ContactLaw::kOneSided
                               : ContactLaw::kLinear;
  if (has_backlash) c.backlash = config.real(prefix + "backlash");
  return c;
}

TransmissionError teFromConfig(const config::Config& config, const std::string& prefix) {
  TransmissionError te;
  const auto amplitudes = config.realList(prefix + "te_amplitudes");
  auto phases = config.realList(prefix + "te_phases_deg");
  for (double& p : phases) p *= kDeg;
  te.addFourier(amplitudes, phases, prefix + "te_amplitudes", prefix + "te_phases_deg");
  if (config.real(prefix + "te_rectangular_amplitude") != 0.0) {
    te.addRectangular(config.real(prefix + "te_rectangular_amplitude"),
                      config.real(prefix + "te_rectangular_duty"),
                      config.real(prefix + "te_rectangular_start"), prefix + "te_rectangular");
  }
  const auto table_phases = config.realList(prefix + "te_table_phases");
  const auto table_values = config.realList(prefix + "te_table_values");
  if (!table_phases.empty() || !table_values.empty()) {
    te.addTable(table_phases, table_values, prefix + "te_table");
  }
  return te;
}

std::shared_ptr<const MeshStiffness> stiffnessFromConfig(const config::Config& config,
                                                         const std::string& prefix,
                                                         const MeshStiffnessInputs& inputs,
                                                         std::vector<std::string>& warnings) {
  const GearPair* pair = inputs.external;
  const double contact_ratio = inputs.contact_ratio;
  const std::string model = config.has(prefix + "stiffness") ? config.string(prefix + "stiffness")
                            : pair                           ? "potential_energy"
                                                             : "iso6336";
  if (model == "constant") {
    if (!config.has(prefix + "stiffness_value")) {
      throw InputError(prefix + "stiffness_value", "",
                       "required with stiffness = \"constant\" [N/m]");
    }
    return std::make_shared<ConstantMeshStiffness>(
        "constant", config.real(prefix + "stiffness_value"), contact_ratio);
  }
  if (model == "table") {
    const auto phases = config.realList(prefix + "stiffness_table_phases");
    const auto values = config.realList(prefix + "stiffness_table_values");
    if (phases.size() < 2 || phases.size() != values.size()) {
      throw InputError(prefix + "stiffness_table_values",
                       fmt::format("{} phases, {} values", phases.size(), values.size()),
                       "as many values [N/m] as stiffness_table_phases, at least 2, with "
                       "stiffness = \"table\"");
    }
    return std::make_shared<TabulatedMeshStiffness>(
        phases, values, contact_ratio, config.string(prefix + "stiffness_table_source"));
  }
  if (model == "api") {
    return std::make_shared<ConstantMeshStiffness>(
        "api", apiMeshStiffness(inputs.face_width, inputs.helix), contact_ratio);
  }
  if (!pair && model == "iso6336" && inputs.internal) {
    const double k = iso6336Stiffness(*inputs.internal, *inputs.pinion, *inputs.ring,
                                      config::iso6336OptionsFromConfig(config))
                         .meshStiffness();
    return std::make_shared<ConstantMeshStiffness>("iso6336", k, contact_ratio);
  }
  if (!pair) {
    throw InputError(prefix + "stiffness", "\"" + model + "\"",
                     "\"constant\", \"api\", \"iso6336\" or \"table\" on a ring (internal) "
                     "mesh: the other tooth models are written for external pairs");
  }
  std::vector<std::string> own;
  std::shared_ptr<const MeshStiffness> k;
  try {
    k = config::buildMeshStiffnessModel(model, config, *pair, own);
  } catch (const InputError& error) {
    throw renamedForPair(error, inputs.keys);
  }
  const std::string where = prefix.substr(0, prefix.size() - 1);
  for (const auto& w : own) warnings.push_back(inContext(where + " (" + model + " model)", w));
  return k;
}

void transverseToNormal(TrainMeshSpec& mesh, double base_helix, const std::string& /*prefix*/) {
  const double cb = std::cos(base_helix);
  if (cb == 1.0) return;  // spur: the planes agree
  if (mesh.contact.tooth_pairs) {
    mesh.contact.tooth_pairs = scaledContactElements(mesh.contact.tooth_pairs, 1.0 / (cb * cb), cb);
  }
  mesh.stiffness = scaledMeshStiffness(mesh.stiffness, 1.0 / (cb * cb));
  if (mesh.damping) *mesh.damping /= cb * cb;  // a ratio ζ is the same in both planes
  mesh.transmission_error = mesh.transmission_error.scaled(cb);
  mesh.contact.backlash *= cb;
}

}  // namespace geardyn::config::detail
