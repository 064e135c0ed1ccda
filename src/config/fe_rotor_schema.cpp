/// The schema of the finite-element geared rotor file (fe_rotor_config.h).

#include <fmt/format.h>

#include <array>

#include "geardyn/config/fe_rotor_config.h"
#include "geardyn/config/geometry_config.h"
#include "geardyn/config/output_section.h"
#include "geardyn/config/stiffness_config.h"

namespace geardyn::config {
namespace {

constexpr std::array<const char*, 2> kShafts = {"pinion_shaft", "gear_shaft"};

void addShaftSections(ConfigSchema& schema, const std::string& s, const std::string& member) {
  schema.section(s, fmt::format("The {} shaft along x: Timoshenko elements from node 0 to node "
                                "n (6 DOFs a node, axial removed unless model.axial).",
                                member));
  schema.realList(s + ".element_lengths").unit("m").required().doc("length of each element");
  schema.realList(s + ".outer_diameters")
      .unit("m")
      .required()
      .doc("outer diameter: one value for every element or one per element");
  schema.realList(s + ".inner_diameters")
      .unit("m")
      .defaultValue(nlohmann::ordered_json::array({0.0}))
      .doc("bore: one value or one per element (0: solid)");
  schema.real(s + ".youngs_modulus").unit("Pa").positive().defaultValue(200e9).doc("E");
  schema.real(s + ".shear_modulus").unit("Pa").positive().defaultValue(80e9).doc("G");
  schema.real(s + ".density").unit("kg/m^3").positive().defaultValue(7800.0).doc("ρ");
  schema.integer(s + ".gear_node").min(0).required().doc("node carrying the " + member);
  schema.boolean(s + ".gear_disk")
      .defaultValue(true)
      .doc("add the " + member +
           " body (mass, polar and diametral inertia from the gear geometry) at gear_node");
  const std::string b = s + ".bearings";
  schema.section(b,
                 "Linear bearings: one entry per node in `nodes`; every other list holds one value "
                 "for all bearings or one per bearing.");
  schema.realList(b + ".nodes").defaultValue(nlohmann::ordered_json::array()).doc("bearing nodes");
  for (auto [key, unit, doc] : std::initializer_list<std::array<const char*, 3>>{
           {"kyy", "N/m", "horizontal stiffness"},
           {"kzz", "N/m", "vertical stiffness"},
           {"kyz", "N/m", "cross stiffness (force y per displacement z)"},
           {"kzy", "N/m", "cross stiffness (force z per displacement y)"},
           {"cyy", "N s/m", "horizontal damping"},
           {"czz", "N s/m", "vertical damping"},
           {"cyz", "N s/m", "cross damping"},
           {"czy", "N s/m", "cross damping"},
           {"k_axial", "N/m", "axial stiffness (model.axial), as a gearbox bearing's k_axial"},
           {"c_axial", "N s/m", "axial damping (model.axial)"},
           {"k_tilt", "N m/rad", "tilt (angular) stiffness about y and z"},
           {"c_tilt", "N m s/rad", "tilt damping"},
           {"k_torsion", "N m/rad", "torsional stiffness to ground (coupling, motor)"},
           {"c_torsion", "N m s/rad", "torsional damping to ground"}}) {
    schema.realList(b + "." + key)
        .unit(unit)
        .defaultValue(nlohmann::ordered_json::array({0.0}))
        .doc(doc);
  }
  schema.alias(b + ".kxx", b + ".k_axial");
  schema.alias(b + ".cxx", b + ".c_axial");
  const std::string d = s + ".disks";
  schema.section(d, "Extra rigid disks (the gear body is added by gear_disk).");
  schema.realList(d + ".nodes").defaultValue(nlohmann::ordered_json::array()).doc("disk nodes");
  schema.realList(d + ".mass").unit("kg").defaultValue(nlohmann::ordered_json::array()).doc("m");
  schema.realList(d + ".polar_inertia")
      .unit("kg m^2")
      .defaultValue(nlohmann::ordered_json::array())
      .doc("I_p");
  schema.realList(d + ".diametral_inertia")
      .unit("kg m^2")
      .defaultValue(nlohmann::ordered_json::array())
      .doc("I_d");
  const std::string u = s + ".unbalance";
  schema.section(u, "Mass unbalances turning with the shaft (1× excitation).");
  schema.realList(u + ".nodes").defaultValue(nlohmann::ordered_json::array()).doc("nodes");
  schema.realList(u + ".amount")
      .unit("kg m")
      .defaultValue(nlohmann::ordered_json::array())
      .doc("m e");
  schema.realList(u + ".phase_deg")
      .unit("deg")
      .defaultValue(nlohmann::ordered_json::array({0.0}))
      .doc("angle from +y towards +z at t = 0");
}

/// The model, the gear pair, its mesh and mesh-stiffness models, the two shafts.
void addFeRotorModelSections(ConfigSchema& schema) {
  schema.section("model", "The model.");
  schema.string("model.type")
      .choices({"fe_geared_rotor"})
      .required()
      .doc("fe_geared_rotor selects this schema (without [model], `rotor` is Rao's 4-DOF rotor)");
  schema.boolean("model.axial")
      .defaultValue(false)
      .doc("keep the axial DOFs (the paper removes them); needs bearings k_axial on each shaft");
  schema.string("model.contact_point")
      .choices({"pitch_point", "base_tangent_points"})
      .defaultValue("pitch_point")
      .doc(
          "where the helical mesh force's axial component acts: one physical point (exact "
          "rigid-body modes) or each gear's base tangent point (the paper's eq. 11)");
  addGearPairSections(schema);
  schema.section("mesh", "The gear mesh between pinion_shaft.gear_node and gear_shaft.gear_node.");
  schema.string("mesh.stiffness")
      .choices(meshStiffnessModelNames())
      .defaultValue("potential_energy")
      .doc(
          "mesh-stiffness model of the time, modal and campbell analyses ([mesh_stiffness.*]); "
          "its k acts along the contact normal, inclined by β_b to the transverse plane");
  schema.real("mesh.line_of_action_angle_deg")
      .unit("deg")
      .optional()
      .doc(
          "ψ, the transverse line of action from the vertical z axis; default the operating "
          "pressure angle (gear centre level with the pinion's, at +y)");
  schema.real("mesh.damping")
      .unit("N s/m")
      .min(0.0)
      .defaultValue(0.0)
      .doc("dashpot c_m along the contact normal");
  schema.realList("mesh.te_amplitudes")
      .unit("m")
      .defaultValue(nlohmann::ordered_json::array())
      .doc("transmission error e(φ) = Σ a_r cos(2π r φ + φ_r), r = 1, 2, …");
  schema.realList("mesh.te_phases_deg")
      .unit("deg")
      .defaultValue(nlohmann::ordered_json::array())
      .doc("phases φ_r of the transmission error (one per amplitude; empty: 0)");
  schema.section("mesh_stiffness", "Options of the mesh-stiffness models.");
  addMeshStiffnessModelSections(schema);
  addShaftSections(schema, kShafts[0], "pinion");
  addShaftSections(schema, kShafts[1], "gear");
}

/// Damping, constant loads and the pinion speed (constant or a ramp).
void addFeRotorLoadSections(ConfigSchema& schema) {
  schema.section("damping", "Proportional damping C = α M + β K_shafts.");
  schema.real("damping.stiffness_proportional")
      .unit("s")
      .min(0.0)
      .defaultValue(0.0)
      .doc("β (the paper: 3e-5)");
  schema.real("damping.mass_proportional").unit("1/s").min(0.0).defaultValue(0.0).doc("α");
  schema.section("load", "Constant loads.");
  schema.real("load.torque")
      .unit("N m")
      .defaultValue(0.0)
      .doc("drive torque T on the pinion shaft (about +x); the gear shaft carries T r_bg/r_bp");
  schema.integer("load.drive_node").min(0).defaultValue(0).doc("pinion-shaft node of T");
  schema.integer("load.load_node")
      .min(-1)
      .defaultValue(-1)
      .doc("gear-shaft node of the load torque (-1: the last node)");
  schema.real("load.gravity")
      .unit("m/s^2")
      .min(0.0)
      .defaultValue(9.81)
      .doc("gravity along -z (0: none)");
  schema.section("speed", "Pinion speed: constant, or a linear ramp (run-up / run-down).");
  schema.real("speed.speed_rpm")
      .unit("rpm")
      .min(0.0)
      .required()
      .doc("pinion speed (ramp: at the start)");
  schema.real("speed.end_speed_rpm")
      .unit("rpm")
      .min(0.0)
      .optional()
      .doc("pinion speed at the end of the ramp (absent: constant speed)");
  schema.alias("speed.rpm", "speed.speed_rpm");
  schema.alias("speed.end_rpm", "speed.end_speed_rpm");
  schema.real("speed.ramp_start").unit("s").min(0.0).defaultValue(0.0).doc("ramp start");
  schema.real("speed.ramp_end")
      .unit("s")
      .positive()
      .optional()
      .doc("ramp end (default: time.duration)");
}

/// What to compute and the Newmark time response.
void addFeRotorTimeSections(ConfigSchema& schema) {
  schema.section("analysis", "What to compute.");
  schema.string("analysis.type")
      .choices({"time", "modal", "campbell", "compare_stiffness"})
      .defaultValue("time")
      .doc(
          "time: Newmark response; modal: damped modes at speed.speed_rpm; campbell: modes over a "
          "speed range; compare_stiffness: the time response with each mesh-stiffness model");
  schema.section("time", "Newmark time integration (γ = 1/2, β = 1/4).");
  schema.real("time.time_step").unit("s").positive().defaultValue(1e-5).doc("Δt (the paper: 1e-5)");
  schema.real("time.duration")
      .unit("s")
      .positive()
      .defaultValue(0.5)
      .doc(
          "simulated time; at constant speed at least time.window_mesh_periods mesh periods, "
          "along a run-up at least time.runup_window (checked before the run)");
  schema.boolean("time.start_from_static")
      .defaultValue(false)
      .doc("start from the static deflection instead of rest (the paper starts from rest)");
  schema.integer("time.output_every")
      .min(1)
      .defaultValue(10)
      .doc("write every n-th step to time_history.csv (spectra use every step)");
  schema.stringList("time.outputs")
      .defaultValue(nlohmann::ordered_json::array())
      .doc(
          "DOFs to record, \"<shaft>.<node>.<dof>\" with dof ux, uy, uz, rx, ry, rz; default the "
          "gear nodes' uy, uz and the first bearing node of each shaft");
  schema.integer("time.window_mesh_periods")
      .min(1)
      .defaultValue(20)
      .doc("steady window for spectra and harmonics: the last whole mesh periods");
  schema.integer("time.harmonics")
      .min(1)
      .max(200)
      .defaultValue(10)
      .doc("mesh orders in harmonics.csv");
  schema.real("time.spectrum_max_frequency")
      .unit("Hz")
      .positive()
      .optional()
      .doc("highest frequency in spectrum.csv (default 1.25 × the highest mesh order)");
  schema.real("time.gyro_speed_tolerance")
      .greaterThan(0.0)
      .lessThan(1.0)
      .defaultValue(1e-3)
      .doc("run-up: refactorise when the speed moved by this fraction of the largest speed");
  schema.real("time.runup_window")
      .unit("s")
      .positive()
      .defaultValue(0.02)
      .doc("run-up: window of the order tracking and waterfall");
}

/// Modal analysis, Campbell diagram and the paper's comparison of mesh-stiffness models.
void addFeRotorModalSections(ConfigSchema& schema) {
  schema.section("modal", "Modal analysis (mean mesh stiffness).");
  schema.integer("modal.modes").min(1).max(500).defaultValue(12).doc("modes reported");
  schema.real("modal.speed_rpm")
      .unit("rpm")
      .min(0.0)
      .optional()
      .doc("pinion speed of the modes (default speed.speed_rpm)");
  schema.real("modal.max_damping_ratio")
      .greaterThan(0.0)
      .max(1.0)
      .defaultValue(0.99)
      .doc("modes more damped than this are skipped (overdamped pairs)");
  schema.section("campbell", "Campbell diagram: modes tracked over pinion speeds.");
  schema.real("campbell.speed_min_rpm")
      .unit("rpm")
      .min(0.0)
      .defaultValue(0.0)
      .doc("lowest pinion speed of the range (as a gearbox's nonlinear.speed_min_rpm)");
  schema.real("campbell.speed_max_rpm")
      .unit("rpm")
      .positive()
      .optional()
      .doc("highest pinion speed of the range (default 4 × speed.speed_rpm)");
  schema.alias("campbell.start_speed_rpm", "campbell.speed_min_rpm");
  schema.alias("campbell.end_speed_rpm", "campbell.speed_max_rpm");
  schema.alias("campbell.start_rpm", "campbell.speed_min_rpm");
  schema.alias("campbell.end_rpm", "campbell.speed_max_rpm");
  schema.integer("campbell.points").min(2).max(10000).defaultValue(41).doc("speeds");
  schema.integer("campbell.modes").min(1).max(200).defaultValue(8).doc("modes tracked");
  schema.section("compare", "The paper's study: one time response per mesh-stiffness model.");
  schema.stringList("compare.models")
      .choices({"api", "step", "fourier", "potential_energy", "iso6336", "fourier_beam_mean"})
      .defaultValue(nlohmann::ordered_json::array({"api", "step", "fourier", "potential_energy"}))
      .doc(
          "models compared ([mesh_stiffness.*] options; fourier_beam_mean: one-term sinusoid of "
          "the beam model around its own mean, Fig. 7); the first is the reference of ratios");
  schema.string("compare.reference")
      .choices({"api", "step", "fourier", "potential_energy", "iso6336", "fourier_beam_mean"})
      .defaultValue("potential_energy")
      .doc("model the others are compared with (ratios in compare_ratios.csv)");
}

}  // namespace

ConfigSchema feRotorSchema() {
  ConfigSchema schema(
      "rotor",
      "Finite-element two-shaft geared rotor (Visnadi & de Castro 2021 §3-4): Timoshenko shafts, "
      "bearings, disks, gyroscopics and a spur/helical mesh k_m(t) v v^T with any mesh-stiffness "
      "model; Newmark time response at constant speed or along a run-up, modal analysis, "
      "Campbell diagram, and the paper's comparison of mesh-stiffness models.");
  schema.string("title").defaultValue("").doc("free text copied into the summary");
  addFeRotorModelSections(schema);
  addFeRotorLoadSections(schema);
  addFeRotorTimeSections(schema);
  addFeRotorModalSections(schema);
  addOutputSection(schema);
  return schema;
}

}  // namespace geardyn::config
