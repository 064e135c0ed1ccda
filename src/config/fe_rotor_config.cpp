/// Configuration of the finite-element geared rotor (see fe_rotor_io.h).

#include "geardyn/config/fe_rotor_config.h"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <cmath>
#include <numbers>

#include "geardyn/config/geometry_config.h"
#include "geardyn/config/output_section.h"
#include "geardyn/config/stiffness_config.h"
#include "geardyn/config/toml_parse.h"
#include "geardyn/error.h"
#include "geardyn/geometry/gear_pair.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "geardyn/units.h"

namespace geardyn::config {
namespace {

constexpr double kDeg = geardyn::units::kDegree;
using geardyn::units::kRpm;
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

int nodeIndex(double value, const std::string& key) {
  if (!std::isfinite(value) || value < 0 || value != std::floor(value)) {
    throw InputError(key, fmt::format("{:g}", value), "a node index (integer >= 0)");
  }
  return static_cast<int>(value);
}

/// Element i of a list that holds one value for all or one per item.
double itemOf(const std::vector<double>& values, std::size_t i, std::size_t count,
              const std::string& key) {
  if (values.size() == 1) return values[0];
  if (values.size() != count) {
    throw InputError(key, fmt::format("{} values", values.size()),
                     fmt::format("one value or {} (one per item)", count));
  }
  return values[i];
}

FeShaftSpec shaftFromConfig(const Config& config, const std::string& s, const GearGeometry& gear) {
  FeShaftSpec shaft;
  shaft.name = s;
  const auto lengths = config.realList(s + ".element_lengths");
  const auto outer = config.realList(s + ".outer_diameters");
  const auto inner = config.realList(s + ".inner_diameters");
  if (lengths.empty()) throw InputError(s + ".element_lengths", "[]", "at least one element");
  for (std::size_t e = 0; e < lengths.size(); ++e) {
    ShaftSegment seg;
    seg.length = lengths[e];
    seg.outer_diameter = itemOf(outer, e, lengths.size(), s + ".outer_diameters");
    seg.inner_diameter = itemOf(inner, e, lengths.size(), s + ".inner_diameters");
    seg.youngs_modulus = config.real(s + ".youngs_modulus");
    seg.shear_modulus = config.real(s + ".shear_modulus");
    seg.density = config.real(s + ".density");
    if (!(seg.length > 0) || !std::isfinite(seg.length))
      throw InputError(s + ".element_lengths", fmt::format("{:g}", seg.length), "lengths > 0 m");
    if (!(seg.outer_diameter > 0))
      throw InputError(s + ".outer_diameters", fmt::format("{:g}", seg.outer_diameter),
                       "diameters > 0 m");
    if (!(seg.inner_diameter >= 0 && seg.inner_diameter < seg.outer_diameter))
      throw InputError(s + ".inner_diameters", fmt::format("{:g}", seg.inner_diameter),
                       "0 <= bore < outer diameter");
    shaft.elements.push_back(seg);
  }
  shaft.gear_node = static_cast<int>(config.integer(s + ".gear_node"));
  if (shaft.gear_node >= shaft.nodeCount())
    throw InputError(s + ".gear_node", std::to_string(shaft.gear_node),
                     fmt::format("a node in [0, {}]", shaft.nodeCount() - 1));
  if (config.boolean(s + ".gear_disk")) {
    shaft.disks.push_back({shaft.gear_node, gear.mass, gear.polar_inertia, gear.diametral_inertia});
  }
  const std::string b = s + ".bearings";
  const auto nodes = config.realList(b + ".nodes");
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    FeBearing bearing;
    bearing.node = nodeIndex(nodes[i], b + ".nodes");
    auto get = [&](const char* key) {
      return itemOf(config.realList(b + "." + key), i, nodes.size(), b + "." + key);
    };
    bearing.kyy = get("kyy"), bearing.kzz = get("kzz"), bearing.kyz = get("kyz");
    bearing.kzy = get("kzy"), bearing.cyy = get("cyy"), bearing.czz = get("czz");
    bearing.cyz = get("cyz"), bearing.czy = get("czy"), bearing.kxx = get("k_axial");
    bearing.cxx = get("c_axial"), bearing.k_tilt = get("k_tilt"), bearing.c_tilt = get("c_tilt");
    bearing.k_torsion = get("k_torsion"), bearing.c_torsion = get("c_torsion");
    shaft.bearings.push_back(bearing);
  }
  const std::string d = s + ".disks";
  const auto disk_nodes = config.realList(d + ".nodes");
  for (std::size_t i = 0; i < disk_nodes.size(); ++i) {
    auto get = [&](const char* key) {
      return itemOf(config.realList(d + "." + key), i, disk_nodes.size(), d + "." + key);
    };
    shaft.disks.push_back({nodeIndex(disk_nodes[i], d + ".nodes"), get("mass"),
                           get("polar_inertia"), get("diametral_inertia")});
  }
  const std::string u = s + ".unbalance";
  const auto u_nodes = config.realList(u + ".nodes");
  for (std::size_t i = 0; i < u_nodes.size(); ++i) {
    auto get = [&](const char* key) {
      return itemOf(config.realList(u + "." + key), i, u_nodes.size(), u + "." + key);
    };
    shaft.unbalances.push_back(
        {nodeIndex(u_nodes[i], u + ".nodes"), get("amount"), get("phase_deg") * kDeg});
  }
  return shaft;
}

}  // namespace

std::string peekConfigString(const std::filesystem::path& file, const std::string& key) {
  try {
    const toml::table table = parseTomlFile(file);
    if (auto node = table.at_path(key); node && node.is_string()) return *node.value<std::string>();
  } catch (const std::exception&) {
    // The real load reports the error with its location.
  }
  return "";
}

/// The model, the gear pair, its mesh and mesh-stiffness models, the two shafts.
static void addFeRotorModelSections(ConfigSchema& schema) {
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
static void addFeRotorLoadSections(ConfigSchema& schema) {
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
static void addFeRotorTimeSections(ConfigSchema& schema) {
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
static void addFeRotorModalSections(ConfigSchema& schema) {
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

FeRotorBuild feRotorSpecFromConfig(const Config& config, const std::string& stiffness_model) {
  FeRotorBuild b;
  const GearPair pair(gearPairSpecFromConfig(config));
  b.warnings = pair.warnings();
  b.stiffness_model = stiffness_model.empty() ? config.string("mesh.stiffness") : stiffness_model;
  FeGearedRotorSpec& spec = b.spec;
  if (b.stiffness_model == "fourier_beam_mean") {
    nlohmann::ordered_json resolved = config.resolved();
    resolved["mesh_stiffness"]["fourier"]["fit"] = "potential_energy";
    resolved["mesh_stiffness"]["fourier"]["mean"] = "fit";
    spec.mesh_stiffness =
        buildMeshStiffnessModel("fourier", Config(resolved, config.source()), pair, b.warnings);
  } else {
    spec.mesh_stiffness = buildMeshStiffnessModel(b.stiffness_model, config, pair, b.warnings);
  }
  spec.shafts[0] = shaftFromConfig(config, kShafts[0], pair.pinion());
  spec.shafts[1] = shaftFromConfig(config, kShafts[1], pair.gear());
  MeshCouplingGeometry& g = spec.mesh;
  g.line_of_action_angle = config.has("mesh.line_of_action_angle_deg")
                               ? config.real("mesh.line_of_action_angle_deg") * kDeg
                               : pair.operatingPressureAngle();
  // The hand sets the axial component of the normal: the contact line of a right-hand flank
  // runs along the base helix cos β_b x̂ + sin β_b t (t the pinion's sense of rotation, the
  // direction the line of action takes here), so the normal is cos β_b t − sin β_b x̂: β_b < 0
  // for a right-hand pinion (a right-hand driver turning about +x pushes the gear towards −x;
  // docs/theory/gear_trains.md). Before 2026-11 this sign was the opposite.
  g.base_helix_angle = -std::copysign(pair.baseHelixAngle(), pair.spec().pinion.helix_angle);
  g.pinion_base_radius = pair.pinion().base_radius;
  g.gear_base_radius = pair.gear().base_radius;
  g.line_of_action_length = pair.lineOfActionLength();
  g.pitch_point_distance = pair.pinion().base_radius * std::tan(pair.operatingPressureAngle());
  g.contact_point = config.string("model.contact_point") == "pitch_point"
                        ? MeshContactPoint::kPitchPoint
                        : MeshContactPoint::kBaseTangentPoints;
  spec.pinion_teeth = pair.spec().pinion.teeth;
  spec.gear_teeth = pair.spec().gear.teeth;
  std::vector<double> phases = config.realList("mesh.te_phases_deg");
  for (double& p : phases) p *= kDeg;
  spec.transmission_error.addFourier(config.realList("mesh.te_amplitudes"), phases,
                                     "mesh.te_amplitudes", "mesh.te_phases_deg");
  spec.mesh_damping = config.real("mesh.damping");
  spec.stiffness_proportional = config.real("damping.stiffness_proportional");
  spec.mass_proportional = config.real("damping.mass_proportional");
  spec.drive_torque = config.real("load.torque");
  spec.drive_node = static_cast<int>(config.integer("load.drive_node"));
  const long long load_node = config.integer("load.load_node");
  spec.load_node = load_node < 0 ? spec.shafts[1].nodeCount() - 1 : static_cast<int>(load_node);
  spec.gravity = config.real("load.gravity");
  spec.axial = config.boolean("model.axial");
  const double start = config.real("speed.speed_rpm") * kRpm;
  const double end =
      config.has("speed.end_speed_rpm") ? config.real("speed.end_speed_rpm") * kRpm : start;
  const double ramp_start = config.real("speed.ramp_start");
  const double ramp_end =
      config.has("speed.ramp_end") ? config.real("speed.ramp_end") : config.real("time.duration");
  if (end != start && !(ramp_end > ramp_start)) {
    throw InputError("speed.ramp_end", fmt::format("{:g}", ramp_end),
                     fmt::format("a time after speed.ramp_start ({:g} s)", ramp_start));
  }
  spec.speed = {start, end, ramp_start, ramp_end};
  return b;
}

void checkRecordLength(const Config& config, const FeGearedRotor& model, double duration) {
  const auto& speed = model.spec().speed;
  if (speed.constant() && speed.start > 0.0) {
    // The steady window holds time.window_mesh_periods whole mesh periods: the mesh-order
    // harmonics are fitted over it and its last two periods measure the periodicity. A shorter
    // record cannot hold it (the least squares of the orders is then rank-deficient).
    const double mesh_period = 2.0 * std::numbers::pi / (speed.start * model.spec().pinion_teeth);
    const long long periods = config.integer("time.window_mesh_periods");
    const double minimum = static_cast<double>(periods) * mesh_period;
    if (duration < minimum * (1.0 - 1e-9)) {
      throw InputError(
          "time.duration", fmt::format("{:g} s", duration),
          fmt::format("at least {:.4g} s, the steady window of time.window_mesh_periods = {} mesh "
                      "periods of {:.4g} ms ({:g} rpm, {} pinion teeth); lengthen time.duration "
                      "or lower time.window_mesh_periods",
                      minimum, periods, mesh_period * 1e3, speed.start / kRpm,
                      model.spec().pinion_teeth));
    }
  } else if (!speed.constant()) {
    const double window = config.real("time.runup_window");
    if (duration < window) {
      throw InputError("time.duration", fmt::format("{:g} s", duration),
                       fmt::format("at least time.runup_window = {:g} s, one order-tracking "
                                   "window of the run-up",
                                   window));
    }
  }
}

FeTimeOptions feTimeOptionsFromConfig(const Config& config, const FeGearedRotor& model) {
  FeTimeOptions o;
  o.time_step = config.real("time.time_step");
  o.duration = config.real("time.duration");
  o.start_from_static = config.boolean("time.start_from_static");
  o.gyro_speed_tolerance = config.real("time.gyro_speed_tolerance");
  o.channels = feOutputChannels(config, model);
  o.validate();
  checkRecordLength(config, model, o.duration);
  return o;
}

std::vector<int> feOutputChannels(const Config& config, const FeGearedRotor& model) {
  std::vector<int> channels;
  const auto names = config.stringList("time.outputs");
  if (names.empty()) {
    const auto& spec = model.spec();
    for (int s = 0; s < 2; ++s) {
      for (int d : {kUy, kUz}) channels.push_back(model.dofIndex(s, spec.shafts[s].gear_node, d));
    }
    for (int s = 0; s < 2; ++s) {
      if (spec.shafts[s].bearings.empty()) continue;
      for (int d : {kUy, kUz})
        channels.push_back(model.dofIndex(s, spec.shafts[s].bearings.front().node, d));
    }
    return channels;
  }
  std::vector<std::string> all;
  for (int i = 0; i < model.dofCount(); ++i) all.push_back(model.dofName(i));
  for (const auto& name : names) {
    const auto it = std::find(all.begin(), all.end(), name);
    if (it == all.end()) {
      throw InputError(
          "time.outputs", "\"" + name + "\"",
          fmt::format("a DOF \"<shaft>.<node>.<dof>\" of the model, e.g. \"{}\"{}", all[1],
                      name.ends_with(".ux") ? " (axial DOFs need model.axial)" : ""));
    }
    channels.push_back(static_cast<int>(it - all.begin()));
  }
  return channels;
}

std::vector<double> campbellSpeedsFromConfig(const Config& config) {
  const double start = config.real("campbell.speed_min_rpm") * kRpm;
  const double end = (config.has("campbell.speed_max_rpm") ? config.real("campbell.speed_max_rpm")
                                                           : 4.0 * config.real("speed.speed_rpm")) *
                     kRpm;
  if (!(end > start)) {
    throw InputError("campbell.speed_max_rpm", fmt::format("{:g} rpm", end / kRpm),
                     fmt::format("a speed above campbell.speed_min_rpm = {:g} rpm", start / kRpm));
  }
  const auto points = config.integer("campbell.points");
  std::vector<double> speeds;
  for (long long i = 0; i < points; ++i) speeds.push_back(start + (end - start) * i / (points - 1));
  return speeds;
}

}  // namespace geardyn::config
