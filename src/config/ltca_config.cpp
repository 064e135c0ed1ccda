#include "geardyn/config/ltca_config.h"

#include <fmt/format.h>

#include "geardyn/config/geometry_config.h"
#include "geardyn/config/output_section.h"
#include "geardyn/config/stiffness_config.h"
#include "geardyn/error.h"

namespace geardyn::config {

namespace {

/// The lead (across the face) modifications of one gear (issue 36).
void addLeadKeys(ConfigSchema& schema, const std::string& prefix, const char* gear) {
  schema.real(fmt::format("{}.{}_helix_slope", prefix, gear))
      .unit("m")
      .defaultValue(0.0)
      .doc(
          "helix slope deviation f_Hbeta: separation f_Hbeta z/b across the face (z from the "
          "mid-face, along +x of a train)");
  schema.real(fmt::format("{}.{}_end_relief", prefix, gear))
      .unit("m")
      .min(0.0)
      .defaultValue(0.0)
      .doc("end relief C_I at both face ends (modifications shape: linear or parabolic)");
  schema.real(fmt::format("{}.{}_end_relief_length", prefix, gear))
      .unit("m")
      .min(0.0)
      .defaultValue(0.0)
      .doc("its length across the face from each end");
  schema.realList(fmt::format("{}.{}_lead_error_positions", prefix, gear))
      .unit("m")
      .defaultValue(nlohmann::ordered_json::array())
      .doc("face positions z in [-b/2, b/2] of a measured lead error table (ascending)");
  schema.realList(fmt::format("{}.{}_lead_errors", prefix, gear))
      .unit("m")
      .defaultValue(nlohmann::ordered_json::array())
      .doc("lead errors (separations) at those positions, interpolated linearly");
}

}  // namespace

void addModificationsSection(ConfigSchema& schema, const std::string& prefix) {
  schema.section(prefix,
                 "Flank modifications and errors (separations along the line of "
                 "action).");
  schema.string(prefix + ".relief")
      .choices({"none", "long", "short"})
      .defaultValue("none")
      .doc("tip relief of both gears designed for " + prefix +
           ".design_load: long = over the "
           "two-pair zone (eps - 1) p_b, short = half of it; amount = one pair's deflection");
  schema.real(prefix + ".design_load")
      .unit("N")
      .positive()
      .optional()
      .doc("F0, the load the relief is designed for (also the baseload of the statistics)");
  schema.string(prefix + ".shape").choices({"linear", "parabolic"}).defaultValue("linear");
  for (const char* gear : {"pinion", "gear"}) {
    for (const char* end : {"tip", "root"}) {
      schema.real(fmt::format("{}.{}_{}_relief", prefix, gear, end))
          .unit("m")
          .min(0.0)
          .defaultValue(0.0)
          .doc(fmt::format("{} {} relief amount (added to a preset)", gear, end));
      schema.real(fmt::format("{}.{}_{}_relief_length", prefix, gear, end))
          .unit("m")
          .min(0.0)
          .defaultValue(0.0)
          .doc("its length along the line of action");
    }
    schema.real(fmt::format("{}.{}_crowning", prefix, gear))
        .unit("m")
        .min(0.0)
        .defaultValue(0.0)
        .doc("lead crowning C_beta: separation C_beta (2z/b)^2");
    schema.real(fmt::format("{}.{}_slope_error", prefix, gear))
        .unit("m")
        .defaultValue(0.0)
        .doc("profile slope error f_Halpha over the active profile");
    schema.realList(fmt::format("{}.{}_pitch_errors", prefix, gear))
        .unit("m")
        .defaultValue(nlohmann::ordered_json::array())
        .doc("pitch error of each tooth (cyclic)");
    addLeadKeys(schema, prefix, gear);
  }
}

ConfigSchema ltcaSchema() {
  ConfigSchema schema("ltca",
                      "Loaded tooth contact analysis: the static transmission error under load "
                      "with flank modifications, the load sharing, secant and tangent mesh "
                      "stiffness, a Harris map and Gelman's mean-excitation statistics against "
                      "load.");
  schema.string("title").optional().doc("free text describing the study");
  addGearPairSections(schema, true);
  schema.section("gearbox",
                 "A mesh of a gearbox file instead of [pinion], [gear] and [pair]: its gears, "
                 "centre distance, modifications and static force (loadLtcaOnGearboxMesh).");
  schema.string("gearbox.file")
      .optional()
      .doc("the gearbox description (TOML or REXS), relative to this file");
  schema.string("gearbox.mesh")
      .optional()
      .doc(
          "the mesh of its [meshes] analysed (gear a is the pinion); ltca.force defaults to its "
          "static force at the gearbox's operating point, [modifications] to the mesh's");
  schema.section("ltca", "The analysis.");
  schema.real("ltca.force")
      .unit("N")
      .positive()
      .required()
      .doc(
          "transmitted force F = T₁/r_b1 along the transverse line of action (helical: the normal "
          "tooth force is F / cos β_b); the STE and stiffnesses are transverse too");
  schema.integer("ltca.positions")
      .min(8)
      .max(100000)
      .defaultValue(200)
      .doc("mesh positions per period");
  schema.integer("ltca.periods")
      .min(1)
      .max(100000)
      .defaultValue(1)
      .doc("mesh periods analysed (pitch errors: the teeth change from period to period)");
  schema.integer("ltca.slices")
      .min(1)
      .max(10000)
      .defaultValue(1)
      .doc(
          "face slices per tooth pair (helical gears, crowning and lead modifications need "
          "several)");
  schema.real("ltca.misalignment")
      .unit("m")
      .defaultValue(0.0)
      .doc(
          "mesh misalignment f_ma in the plane of action: the flanks approach by f_ma more at "
          "z = b/2 than at -b/2 (ISO 6336-1 f_ma; `train` computes it from the deflection)");
  addModificationsSection(schema);
  schema.section("harris", "Peak-to-peak loaded STE against load.");
  schema.stringList("harris.compare_reliefs")
      .choices({"none", "short", "long"})
      .defaultValue(nlohmann::ordered_json::array())
      .doc(
          "also map these tip-relief designs for modifications.design_load (with its shape) on "
          "the same loads: harris_designs.csv");
  schema.realList("harris.load_factors")
      .unit("-")
      .defaultValue(nlohmann::ordered_json::array())
      .doc(
          "loads as multiples of the design load (default 0.1 .. 2.0 in 20 steps when one is "
          "given); empty and no design load: no map");
  schema.section("statistics", "Gelman's statistics against load (needs a design load).");
  schema.realList("statistics.load_factors")
      .unit("-")
      .defaultValue(nlohmann::ordered_json::array({0.25, 0.5, 0.75, 1.0, 1.25, 1.5}))
      .doc("a = F/F0");
  addOutputSection(schema);
  return schema;
}

std::shared_ptr<const LoadedToothContact> loadedContactFromConfig(const Config& config,
                                                                  const GearPair& pair, int slices,
                                                                  const std::string& prefix) {
  PotentialEnergyOptions pe;
  if (config.resolved().contains("mesh_stiffness")) pe = potentialEnergyOptionsFromConfig(config);
  if (pair.baseHelixAngle() > 0.0) pe.slices = slices;
  auto k = std::make_shared<const PotentialEnergyMeshStiffness>(pair, pe);
  return std::make_shared<const LoadedToothContact>(
      k, pairModificationsFromConfig(config, *k, prefix), slices);
}

PairModifications pairModificationsFromConfig(const Config& config,
                                              const PotentialEnergyMeshStiffness& stiffness,
                                              const std::string& prefix) {
  const std::string p = prefix + ".";
  const ReliefShape shape =
      config.string(p + "shape") == "linear" ? ReliefShape::kLinear : ReliefShape::kParabolic;
  PairModifications m;
  const std::string relief = config.string(p + "relief");
  if (relief != "none") {
    if (!config.has(p + "design_load")) {
      throw InputError(p + "design_load", "(not set)",
                       fmt::format("needed by {}relief = \"{}\"", p, relief));
    }
    m = designedTipRelief(stiffness, config.real(p + "design_load"), relief == "long", shape);
  }
  for (const char* gear : {"pinion", "gear"}) {
    ToothModification& t = std::string(gear) == "pinion" ? m.pinion : m.gear;
    for (const char* end : {"tip", "root"}) {
      const double amount = config.real(fmt::format("{}{}_{}_relief", p, gear, end));
      const double length = config.real(fmt::format("{}{}_{}_relief_length", p, gear, end));
      if (amount == 0.0 && length == 0.0) continue;
      Relief& r = std::string(end) == "tip" ? t.tip : t.root;
      if (r.amount > 0.0) {
        throw InputError(fmt::format("{}{}_{}_relief", p, gear, end), fmt::format("{:g}", amount),
                         "conflicts with " + p + "relief");
      }
      r = {amount, length, shape};
      r.validate(fmt::format("{}{}_{}_relief", p, gear, end).c_str());
    }
    t.crowning = config.real(fmt::format("{}{}_crowning", p, gear));
    t.profile_slope_error = config.real(fmt::format("{}{}_slope_error", p, gear));
    t.pitch_errors = config.realList(fmt::format("{}{}_pitch_errors", p, gear));
    t.helix_slope = config.real(fmt::format("{}{}_helix_slope", p, gear));
    t.end_relief = {config.real(fmt::format("{}{}_end_relief", p, gear)),
                    config.real(fmt::format("{}{}_end_relief_length", p, gear)), shape};
    t.end_relief.validate(fmt::format("{}{}_end_relief", p, gear).c_str());
    t.lead_error_positions = config.realList(fmt::format("{}{}_lead_error_positions", p, gear));
    t.lead_errors = config.realList(fmt::format("{}{}_lead_errors", p, gear));
    if (t.lead_errors.size() != t.lead_error_positions.size()) {
      throw InputError(fmt::format("{}{}_lead_errors", p, gear),
                       fmt::format("{} values", t.lead_errors.size()),
                       fmt::format("one per {}{}_lead_error_positions ({})", p, gear,
                                   t.lead_error_positions.size()));
    }
  }
  return m;
}

}  // namespace geardyn::config
