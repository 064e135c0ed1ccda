#include "geardyn/config/identify_config.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "geardyn/config/geometry_config.h"
#include "geardyn/config/output_section.h"
#include "geardyn/config/rotor_config.h"
#include "geardyn/error.h"
#include "geardyn/signal/gear_whirl.h"
#include "geardyn/stiffness/iso6336_stiffness.h"

namespace geardyn::config {

ConfigSchema identifySchema() {
  ConfigSchema schema("identify",
                      "Identification of the gear-mesh dynamic transmission-error parameters "
                      "(k_m, e_m, c_m, TE harmonics in x and y, runouts) from full-spectrum "
                      "whirl peaks of one or several speeds (Rao 2023 §4.6-4.7, ch. 5).");
  schema.string("title").optional().doc("free text describing the study");
  schema.section("input", "The spectra: result folders of `geardyn rotor` or `geardyn spectrum`.");
  schema.stringList("input.spectra")
      .required()
      .doc(
          "folders (relative to the config) holding summary.json and spectrum_peaks.csv (or "
          "frequency_components.csv); one per speed");
  addRotorSection(schema, false);
  schema.section("identify", "The estimator.");
  schema.string("identify.method")
      .choices({"joint", "three_step"})
      .defaultValue("joint")
      .doc(
          "joint: weighted least squares of every component and speed with 95 % intervals; "
          "three_step: the thesis's algorithm (eqs. 4.3-4.20)");
  schema.integer("identify.harmonics")
      .min(1)
      .max(1000)
      .optional()
      .doc("mesh harmonics used; default every one in the spectra");
  schema.real("identify.mesh_damping_ratio")
      .unit("-")
      .greaterThan(0.0)
      .lessThan(1.0)
      .defaultValue(0.01)
      .doc(
          "zeta_m: three_step sets c_m = 2 zeta_m sqrt(k_m m1 m2/(m1 + m2)) (eqs. 4.9-4.10); "
          "joint centres its prior on zeta_m here");
  schema.real("identify.mesh_damping_ratio_sd")
      .unit("-")
      .greaterThan(0.0)
      .defaultValue(1.0)
      .doc("joint: relative (log-normal) standard deviation of the zeta_m prior");
  schema.real("identify.identifiable_width")
      .unit("-")
      .greaterThan(0.0)
      .defaultValue(0.5)
      .doc(
          "identifiable when the 95 % half-width is at most this fraction of the value (this "
          "many rad for phases)");
  schema.section("prior",
                 "Knowledge the lateral probes lack (joint): e.g. k_m from `geardyn stiffness` "
                 "for the gear geometry. A relative sd of 0 fixes the value.");
  schema.real("prior.mesh_stiffness").unit("N/m").positive().optional().doc("k_m prior centre");
  schema.string("prior.mesh_stiffness_from")
      .choices({"none", "iso6336"})
      .defaultValue("none")
      .doc(
          "iso6336: centre the k_m prior on c_gamma_alpha b (ISO 6336-1 method B) of the gear "
          "pair in [pinion], [gear], [pair]");
  schema.real("prior.mesh_stiffness_rsd")
      .unit("-")
      .min(0.0)
      .defaultValue(0.5)
      .doc("relative standard deviation of the k_m prior");
  schema.real("prior.mesh_damping")
      .unit("N s/m")
      .positive()
      .optional()
      .doc("c_m prior centre (replaces the zeta_m prior)");
  schema.real("prior.mesh_damping_rsd")
      .unit("-")
      .min(0.0)
      .defaultValue(0.5)
      .doc("relative standard deviation of the c_m prior");
  schema.section("truth", "Known true values, for the comparison table (simulated input).");
  schema.string("truth.rotor_config")
      .optional()
      .doc(
          "a `geardyn rotor` configuration holding the truth; default: the configuration of an "
          "input folder written by `geardyn rotor`");
  addGearPairSections(schema, false);
  addOutputSection(schema);
  return schema;
}

IdentificationOptions identificationOptionsFromConfig(const Config& config) {
  IdentificationOptions o;
  o.method = config.string("identify.method") == "joint" ? IdentificationMethod::kJoint
                                                         : IdentificationMethod::kThreeStep;
  o.harmonics = config.has("identify.harmonics")
                    ? static_cast<int>(config.integer("identify.harmonics"))
                    : -1;
  o.mesh_damping_ratio = config.real("identify.mesh_damping_ratio");
  o.mesh_damping_ratio_sd = config.real("identify.mesh_damping_ratio_sd");
  o.identifiable_width = config.real("identify.identifiable_width");
  if (auto k = config.optionalReal("prior.mesh_stiffness")) {
    o.mesh_stiffness.value = *k;
    o.mesh_stiffness.relative_sd = config.real("prior.mesh_stiffness_rsd");
  }
  if (config.string("prior.mesh_stiffness_from") == "iso6336") {
    if (o.mesh_stiffness.value) {
      throw InputError("prior.mesh_stiffness_from", "iso6336",
                       "give either prior.mesh_stiffness or prior.mesh_stiffness_from, not both");
    }
    if (!hasGearPair(config)) {
      throw InputError(
          "prior.mesh_stiffness_from", "iso6336",
          "needs the gear pair: [pinion], [gear] and [pair] (as for geardyn geometry)");
    }
    const GearPair pair(gearPairSpecFromConfig(config));
    if (pair.spec().pinion.teeth != config.integer("rotor.pinion_teeth") ||
        pair.spec().gear.teeth != config.integer("rotor.gear_teeth")) {
      throw InputError(
          "pinion.teeth", fmt::format("{}/{}", pair.spec().pinion.teeth, pair.spec().gear.teeth),
          fmt::format("must match rotor.pinion_teeth/gear_teeth ({}/{})",
                      config.integer("rotor.pinion_teeth"), config.integer("rotor.gear_teeth")));
    }
    o.mesh_stiffness.value = iso6336Stiffness(pair).meshStiffness();
    o.mesh_stiffness.relative_sd = config.real("prior.mesh_stiffness_rsd");
  }
  if (auto c = config.optionalReal("prior.mesh_damping")) {
    o.mesh_damping.value = *c;
    o.mesh_damping.relative_sd = config.real("prior.mesh_damping_rsd");
  }
  return o;
}

}  // namespace geardyn::config
