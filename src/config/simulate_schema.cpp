#include <nlohmann/json.hpp>

#include "geardyn/config/geometry_config.h"
#include "geardyn/config/ltca_config.h"
#include "geardyn/config/output_section.h"
#include "geardyn/config/simulate_config.h"
#include "geardyn/config/stiffness_config.h"

/// The configuration schema of the gear-pair dynamics commands (simulate, stats).

namespace geardyn::config {
namespace {
using Json = nlohmann::ordered_json;
}  // namespace

/// The SDOF model's mesh stiffness k(t): its models and their keys.
static void addGearPairStiffnessSection(ConfigSchema& schema) {
  schema.section("model.stiffness", "Mesh stiffness k(t).");
  schema.string("model.stiffness.type")
      .choices({"fourier", "step", "potential_energy", "api", "iso6336", "ltca"})
      .defaultValue("fourier")
      .doc(
          "given Fourier series or step, or a model of the gear pair ([mesh_stiffness.*] options); "
          "ltca: the loaded tooth contact at the mean force with [modifications] - its tangent "
          "stiffness as k(t) and delta - F/k as a table error");
  schema.real("model.stiffness.mean")
      .unit("N/m")
      .positive()
      .optional()
      .doc("k̄ (fourier; step from a mean); nondimensional default 1");
  schema.realList("model.stiffness.cos")
      .unit("-")
      .defaultValue(Json::array())
      .doc("k = k̄ (1 + Σ cos_i cos(iΩt) + sin_i sin(iΩt))");
  schema.realList("model.stiffness.sin")
      .unit("-")
      .defaultValue(Json::array())
      .doc("see cos (empty: zeros)");
  schema.real("model.stiffness.k_min")
      .unit("N/m")
      .positive()
      .optional()
      .doc("step: stiffness with n pairs");
  schema.real("model.stiffness.k_max")
      .unit("N/m")
      .positive()
      .optional()
      .doc("step: stiffness with n + 1 pairs");
  schema.real("model.stiffness.contact_ratio")
      .unit("-")
      .min(1.0)
      .optional()
      .doc("step/fourier without a gear pair");
}

/// The static transmission error e(t) and the speed (`excitation`).
static void addGearPairErrorAndSpeedSections(ConfigSchema& schema) {
  schema.section("model.transmission_error", "Static transmission error / gear error e(t).");
  schema.realList("model.transmission_error.amplitudes")
      .unit("m")
      .defaultValue(Json::array())
      .doc("e = Σ a_r cos(rΩt + φ_r), r = 1, 2, ...");
  schema.realList("model.transmission_error.phases_deg")
      .unit("deg")
      .defaultValue(Json::array())
      .doc("φ_r, one per amplitude; empty: 0 (as a gearbox's meshes.*.te_phases_deg)");
  schema.alias("model.transmission_error.phases",
               "model.transmission_error.phases_deg");  // value converted (config/renamed_keys.h)
  schema.real("model.transmission_error.rectangular_amplitude")
      .unit("m")
      .defaultValue(0.0)
      .doc("rectangular wave: value on its duty part");
  schema.real("model.transmission_error.rectangular_duty")
      .unit("-")
      .greaterThan(0.0)
      .lessThan(1.0)
      .defaultValue(0.5)
      .doc("fraction of the mesh period");
  schema.real("model.transmission_error.rectangular_start")
      .unit("-")
      .defaultValue(0.0)
      .doc("mesh phase where it starts");
  schema.realList("model.transmission_error.table_phases")
      .unit("-")
      .min(0.0)
      .lessThan(1.0)
      .defaultValue(Json::array())
      .doc("table: mesh phases in [0, 1)");
  schema.realList("model.transmission_error.table_values")
      .unit("m")
      .defaultValue(Json::array())
      .doc("table: e at those phases");

  schema.section("excitation", "Speed.");
  schema.real("excitation.mesh_frequency")
      .unit("Hz")
      .min(0.0)
      .optional()
      .doc("f_m (nondimensional: Ω = ω_m/ω_n)");
  schema.real("excitation.speed_rpm")
      .unit("rpm")
      .min(0.0)
      .optional()
      .doc("pinion speed (f_m = z₁ n₁ / 60)");
  schema.real("excitation.initial_phase").unit("-").defaultValue(0.0).doc("mesh phase at t = 0");
}

void addGearPairModelSections(ConfigSchema& schema) {
  schema.section(
      "model",
      "The dynamic model: a single-DOF gear pair along the transverse line of action (Gelman "
      "2005): x = r_b1θ₁ − r_b2θ₂ [m], the force F = T₁/r_b1 [N] and the mesh stiffness k [N/m] "
      "are transverse-plane quantities (helical: the normal tooth force is F / cos β_b, the "
      "normal stiffness k / cos² β_b).");
  schema.string("model.type")
      .choices({"gear_pair", "gear_pair_contacts", "gear_pair_ltca"})
      .defaultValue("gear_pair")
      .doc(
          "gear_pair, or gear_pair_contacts: Saletti's tooth-pair contact elements of stiffness "
          "contact_stiffness (step gaps), or gear_pair_ltca: one contact element per tooth pair "
          "(and face slice) of the loaded tooth contact, potential-energy stiffness and the "
          "[modifications] as gaps");
  schema.real("model.contact_stiffness")
      .unit("N/m")
      .positive()
      .optional()
      .doc("gear_pair_contacts: penalty stiffness k_c of each tooth-pair element");
  schema.string("model.units")
      .choices({"SI", "nondimensional"})
      .defaultValue("SI")
      .doc("SI, or Gelman's nondimensional form (m = 1, c = 2ζ, k̄ = 1, F = a, time ω_n t)");
  schema.real("model.mass")
      .unit("kg")
      .positive()
      .optional()
      .doc("equivalent mass m (or inertias and base radii)");
  schema.real("model.pinion_inertia")
      .unit("kg m^2")
      .positive()
      .optional()
      .doc("polar inertia I₁ (default: [pinion] body)");
  schema.real("model.gear_inertia")
      .unit("kg m^2")
      .positive()
      .optional()
      .doc("polar inertia I₂ (default: [gear] body)");
  schema.real("model.pinion_base_radius")
      .unit("m")
      .positive()
      .optional()
      .doc("R₁ (default: from [pinion])");
  schema.real("model.gear_base_radius")
      .unit("m")
      .positive()
      .optional()
      .doc("R₂ (default: from [gear])");
  schema.real("model.damping_ratio").unit("-").min(0.0).optional().doc("ζ = c / (2 √(k̄ m))");
  schema.real("model.damping")
      .unit("N s/m")
      .min(0.0)
      .optional()
      .doc("c (instead of damping_ratio)");
  schema.real("model.mean_force")
      .unit("N")
      .optional()
      .doc("F = T₁/R₁ along the transverse line of action (nondimensional: a = F/F₀)");
  schema.real("model.torque")
      .unit("N m")
      .optional()
      .doc("pinion torque T₁ (instead of mean_force)");
  schema.alias("model.pinion_torque", "model.torque");
  schema.realList("model.extra_force_amplitudes")
      .unit("N")
      .defaultValue(Json::array())
      .doc("extra forces Σ f_j cos(ω_j t + ψ_j): amplitudes (nondimensional: in F₀)");
  schema.realList("model.extra_force_frequencies")
      .unit("Hz")
      .min(0.0)
      .defaultValue(Json::array())
      .doc("their frequencies ω_j/2π (nondimensional: ω_j/ω_n)");
  schema.realList("model.extra_force_phases_deg")
      .unit("deg")
      .defaultValue(Json::array())
      .doc("their phases ψ_j");
  schema.alias("model.extra_force_phases",
               "model.extra_force_phases_deg");  // value converted (config/renamed_keys.h)
  schema.string("model.contact")
      .choices({"linear", "one_sided", "backlash"})
      .defaultValue("linear")
      .doc("contact law g(y) of the relative deflection y = x − e");
  schema.real("model.normal_backlash")
      .unit("m")
      .min(0.0)
      .defaultValue(0.0)
      .doc(
          "backlash j, the FULL clearance along the line of action, as a gearbox's "
          "meshes.*.backlash (contact = \"backlash\"; the law's half clearance is b = j/2)");
  schema.alias("model.backlash",
               "model.normal_backlash");  // value converted (config/renamed_keys.h)

  addGearPairStiffnessSection(schema);
  addGearPairErrorAndSpeedSections(schema);
}

void addTimeSolverSection(ConfigSchema& schema) {
  schema.section("solver", "Time integration to the periodic steady state.");
  schema.string("solver.method")
      .choices({"newmark", "dormand_prince"})
      .defaultValue("newmark")
      .doc("integrator");
  schema.string("solver.newmark")
      .choices({"average_acceleration", "linear_acceleration", "custom"})
      .defaultValue("average_acceleration")
      .doc("Newmark preset (custom: beta, gamma)");
  schema.real("solver.beta")
      .unit("-")
      .greaterThan(0.0)
      .max(0.5)
      .defaultValue(0.25)
      .doc("Newmark β (custom)");
  schema.real("solver.gamma")
      .unit("-")
      .min(0.5)
      .max(1.0)
      .defaultValue(0.5)
      .doc("Newmark γ (custom)");
  schema.integer("solver.steps_per_period")
      .min(4)
      .max(10000000)
      .defaultValue(512)
      .doc("Newmark steps per mesh period");
  schema.integer("solver.output_points_per_period")
      .min(4)
      .max(1000000)
      .defaultValue(128)
      .doc("samples per period in the output");
  schema.real("solver.relative_tolerance")
      .unit("-")
      .positive()
      .defaultValue(1e-9)
      .doc("Dormand–Prince");
  schema.real("solver.absolute_tolerance")
      .unit("-")
      .positive()
      .defaultValue(1e-12)
      .doc("Dormand–Prince, relative to the static deflection");
  schema.real("solver.steady_tolerance")
      .unit("-")
      .positive()
      .defaultValue(1e-7)
      .doc("steady when consecutive periods differ by less (relative)");
  schema.integer("solver.min_periods")
      .min(2)
      .defaultValue(3)
      .doc("periods before checking for steady state");
  schema.integer("solver.max_periods")
      .min(2)
      .max(100000000)
      .defaultValue(5000)
      .doc("give up after this many periods (status max_periods)");
  schema.integer("solver.output_periods")
      .min(1)
      .max(100000)
      .defaultValue(4)
      .doc("steady periods written out");
  schema.integer("solver.harmonics").min(0).max(1000).defaultValue(10).doc("mesh orders reported");
  schema.string("solver.start")
      .choices({"static", "rest"})
      .defaultValue("static")
      .doc("initial state: static deflection, or x = v = 0");
}

ConfigSchema simulateSchema() {
  ConfigSchema schema("simulate",
                      "Time integration of the gear-pair model to its periodic steady state: "
                      "dynamic transmission error, mesh force, harmonics, contact loss.");
  schema.string("title").optional().doc("free text describing the study");
  addGearPairDynamicsSections(schema);
  return schema;
}

void addGearPairDynamicsSections(ConfigSchema& schema) {
  addGearPairModelSections(schema);
  schema.integer("model.stiffness.ltca_positions")
      .min(16)
      .max(100000)
      .defaultValue(400)
      .doc("ltca: table points per mesh period");
  schema.integer("model.stiffness.ltca_slices")
      .min(1)
      .max(10000)
      .defaultValue(1)
      .doc("ltca: face slices per tooth pair");
  addTimeSolverSection(schema);
  addGearPairSections(schema, false);
  schema.section("mesh_stiffness",
                 "Options of the mesh-stiffness models (when [model.stiffness] type names one).");
  addMeshStiffnessModelSections(schema);
  addModificationsSection(schema);
  addOutputSection(schema);
}

}  // namespace geardyn::config
