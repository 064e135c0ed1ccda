/// The finite-element geared rotor file read into its gearbox (fe_rotor_config.h); its schema
/// is fe_rotor_schema.cpp.

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
#include "geardyn/models/gear_mesh_coupling.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "geardyn/units.h"

namespace geardyn::config {
namespace {

constexpr double kDeg = geardyn::units::kDegree;
using geardyn::units::kRpm;
constexpr std::array<const char*, 2> kShafts = {"pinion_shaft", "gear_shaft"};

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

/// The finite number `value` of a bearing, disk or unbalance list, >= 0 unless `signed_value`.
double checkedValue(double value, const std::string& key, bool signed_value = false) {
  if (!std::isfinite(value) || (!signed_value && value < 0.0)) {
    throw InputError(key, fmt::format("{:g}", value),
                     signed_value ? "a finite number" : "a finite number >= 0");
  }
  return value;
}

/// The file's shaft `s` as the gearbox's shaft with its gear, disks, bearings and unbalances at
/// its nodes' positions (node i ends element i − 1), and its nodes in b.layout.
void addShaft(const Config& config, int index, const GearGeometry& gear, const GearSpec& gear_spec,
              FeRotorBuild& b) {
  const std::string s = kShafts[index];
  GearTrainSpec& train = b.train;
  FeRotorLayout& layout = b.layout;
  TrainShaftSpec shaft;
  shaft.name = s;
  shaft.flexible = true;
  shaft.density = config.real(s + ".density");
  shaft.youngs_modulus = config.real(s + ".youngs_modulus");
  shaft.poisson_ratio = shaft.youngs_modulus / (2.0 * config.real(s + ".shear_modulus")) - 1.0;
  // β K_shafts of the FE rotor: the shafts' material damping, not the gearbox's β (which would
  // also damp the bearings and the mesh).
  shaft.stiffness_proportional_damping = config.real("damping.stiffness_proportional");
  const auto lengths = config.realList(s + ".element_lengths");
  const auto outer = config.realList(s + ".outer_diameters");
  const auto inner = config.realList(s + ".inner_diameters");
  if (lengths.empty()) throw InputError(s + ".element_lengths", "[]", "at least one element");
  std::vector<double> node_x{0.0};
  for (std::size_t e = 0; e < lengths.size(); ++e) {
    const double length = lengths[e];
    const double d_o = itemOf(outer, e, lengths.size(), s + ".outer_diameters");
    const double d_i = itemOf(inner, e, lengths.size(), s + ".inner_diameters");
    if (!(length > 0) || !std::isfinite(length))
      throw InputError(s + ".element_lengths", fmt::format("{:g}", length), "lengths > 0 m");
    if (!(d_o > 0) || !std::isfinite(d_o))
      throw InputError(s + ".outer_diameters", fmt::format("{:g}", d_o), "diameters > 0 m");
    if (!(d_i >= 0 && d_i < d_o))
      throw InputError(s + ".inner_diameters", fmt::format("{:g}", d_i),
                       "0 <= bore < outer diameter");
    shaft.section_lengths.push_back(length);
    shaft.outer_diameters.push_back(d_o);
    shaft.inner_diameters.push_back(d_i);
    node_x.push_back(node_x.back() + length);
  }
  const int nodes = static_cast<int>(node_x.size());
  auto nodeAt = [&](double value, const std::string& key) {
    const int node = nodeIndex(value, key);
    if (node >= nodes)
      throw InputError(key, std::to_string(node), fmt::format("a node in [0, {}]", nodes - 1));
    return node;
  };
  const int gear_node =
      nodeAt(static_cast<double>(config.integer(s + ".gear_node")), s + ".gear_node");
  layout.gear_nodes[index] = gear_node;
  train.shafts.push_back(shaft);
  TrainGearSpec g;
  g.name = index == 0 ? "pinion" : "gear";
  g.shaft = s;
  g.gear = gear_spec;
  g.body = false;  // the FE rotor's gear body is one of its disks
  g.position = node_x[gear_node];
  train.gears.push_back(g);
  auto addDisk = [&](int node, double mass, double polar, double diametral) {
    std::size_t count = 0;
    for (const TrainDiskSpec& disk : train.disks) count += disk.shaft == s;
    train.disks.push_back(
        {s + "_disk" + std::to_string(count), s, node_x[node], mass, polar, diametral});
  };
  if (config.boolean(s + ".gear_disk")) {
    addDisk(gear_node, gear.mass, gear.polar_inertia, gear.diametral_inertia);
  }
  const std::string d = s + ".disks";
  const auto disk_nodes = config.realList(d + ".nodes");
  for (std::size_t i = 0; i < disk_nodes.size(); ++i) {
    auto get = [&](const char* key) {
      return checkedValue(
          itemOf(config.realList(d + "." + key), i, disk_nodes.size(), d + "." + key),
          d + "." + key);
    };
    addDisk(nodeAt(disk_nodes[i], d + ".nodes"), get("mass"), get("polar_inertia"),
            get("diametral_inertia"));
  }
  const std::string bk = s + ".bearings";
  const auto bearing_nodes = config.realList(bk + ".nodes");
  for (std::size_t i = 0; i < bearing_nodes.size(); ++i) {
    auto get = [&](const char* key, bool signed_value = false) {
      return checkedValue(
          itemOf(config.realList(bk + "." + key), i, bearing_nodes.size(), bk + "." + key),
          bk + "." + key, signed_value);
    };
    const int node = nodeAt(bearing_nodes[i], bk + ".nodes");
    TrainBearingSpec t;
    t.name = s + "_bearing" + std::to_string(i);
    t.shaft = s;
    t.position = node_x[node];
    t.kyy = get("kyy"), t.kzz = get("kzz"), t.kyz = get("kyz", true), t.kzy = get("kzy", true);
    t.cyy = get("cyy"), t.czz = get("czz"), t.cyz = get("cyz", true), t.czy = get("czy", true);
    t.k_axial = get("k_axial"), t.c_axial = get("c_axial");
    t.k_tilt = get("k_tilt"), t.c_tilt = get("c_tilt");
    t.k_torsion = get("k_torsion"), t.c_torsion = get("c_torsion");
    train.bearings.push_back(t);
    layout.bearing_nodes[index].push_back(node);
  }
  const std::string u = s + ".unbalance";
  const auto u_nodes = config.realList(u + ".nodes");
  for (std::size_t i = 0; i < u_nodes.size(); ++i) {
    auto get = [&](const char* key, bool signed_value = false) {
      return checkedValue(itemOf(config.realList(u + "." + key), i, u_nodes.size(), u + "." + key),
                          u + "." + key, signed_value);
    };
    train.unbalances.push_back({s + "_unbalance" + std::to_string(i), s,
                                node_x[nodeAt(u_nodes[i], u + ".nodes")], get("amount"),
                                get("phase_deg", true) * kDeg});
  }
  if (b.layout.axial) {
    double axial = 0.0;
    for (const TrainBearingSpec& bearing : train.bearings)
      if (bearing.shaft == s) axial += bearing.k_axial;
    if (!(axial > 0.0)) {
      throw InputError(s + ".bearings.k_axial", "0",
                       "an axial stiffness > 0 on at least one bearing when model.axial = true "
                       "(otherwise the shaft floats axially)");
    }
  }
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

namespace {

/// Position of `node` along a shaft of the gearbox [m]: the end of its node-th section.
double nodePosition(const TrainShaftSpec& shaft, int node) {
  double x = 0.0;
  for (int i = 0; i < node; ++i) x += shaft.section_lengths[i];
  return x;
}

/// The mesh between the gears: where [mesh] puts the line of action, its stiffness model,
/// dashpot and transmission error.
TrainMeshSpec meshFromConfig(const Config& config, const GearPair& pair,
                             std::shared_ptr<const MeshStiffness> stiffness) {
  MeshCouplingGeometry g;
  g.line_of_action_angle = config.has("mesh.line_of_action_angle_deg")
                               ? config.real("mesh.line_of_action_angle_deg") * kDeg
                               : pair.operatingPressureAngle();
  // The hand sets the axial component of the normal: the contact line of a right-hand flank
  // runs along the base helix cos β_b x̂ + sin β_b t (t the pinion's sense of rotation, the
  // direction the line of action takes here), so the normal is cos β_b t − sin β_b x̂: β_b < 0
  // for a right-hand pinion (a right-hand driver turning about +x pushes the gear towards −x;
  // docs/theory/gear_trains.md).
  g.base_helix_angle = -std::copysign(pair.baseHelixAngle(), pair.spec().pinion.helix_angle);
  g.pinion_base_radius = pair.pinion().base_radius;
  g.gear_base_radius = pair.gear().base_radius;
  g.line_of_action_length = pair.lineOfActionLength();
  g.pitch_point_distance = pair.pinion().base_radius * std::tan(pair.operatingPressureAngle());
  if (pair.baseHelixAngle() != 0.0 && config.string("model.contact_point") != "pitch_point") {
    throw InputError("model.contact_point", "\"" + config.string("model.contact_point") + "\"",
                     "\"pitch_point\" for a helical pair: the gearbox's mesh force acts at one "
                     "physical point (the rigid-body modes are then exact)");
  }
  TrainMeshSpec mesh;
  mesh.name = "mesh";
  mesh.gear_a = "pinion";
  mesh.gear_b = "gear";
  const Eigen::Vector2d offset = gearCentreOffset(g);
  mesh.position_angle = std::atan2(offset.y(), offset.x());
  mesh.centre_distance = pair.spec().centre_distance;
  mesh.stiffness = std::move(stiffness);
  std::vector<double> phases = config.realList("mesh.te_phases_deg");
  for (double& p : phases) p *= kDeg;
  mesh.transmission_error.addFourier(config.realList("mesh.te_amplitudes"), phases,
                                     "mesh.te_amplitudes", "mesh.te_phases_deg");
  mesh.damping = config.real("mesh.damping");
  return mesh;
}

/// The pinion speed: constant, or a linear ramp over [speed.ramp_start, speed.ramp_end].
SpeedProfile speedFromConfig(const Config& config) {
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
  return {start, end, ramp_start, ramp_end};
}

}  // namespace

FeRotorBuild feRotorFromConfig(const Config& config, const std::string& stiffness_model) {
  FeRotorBuild b;
  const GearPair pair(gearPairSpecFromConfig(config));
  b.warnings = pair.warnings();
  b.stiffness_model = stiffness_model.empty() ? config.string("mesh.stiffness") : stiffness_model;
  std::shared_ptr<const MeshStiffness> stiffness;
  if (b.stiffness_model == "fourier_beam_mean") {
    nlohmann::ordered_json resolved = config.resolved();
    resolved["mesh_stiffness"]["fourier"]["fit"] = "potential_energy";
    resolved["mesh_stiffness"]["fourier"]["mean"] = "fit";
    stiffness =
        buildMeshStiffnessModel("fourier", Config(resolved, config.source()), pair, b.warnings);
  } else {
    stiffness = buildMeshStiffnessModel(b.stiffness_model, config, pair, b.warnings);
  }
  GearTrainSpec& train = b.train;
  FeRotorLayout& layout = b.layout;
  train.name = "fe_geared_rotor";
  train.dofs = TrainDofs::kFull;
  train.mass_proportional_damping = config.real("damping.mass_proportional");
  train.stiffness_proportional_damping = 0.0;  // the shafts' own β (addShaft)
  layout.axial = config.boolean("model.axial");
  train.gravity = config.real("load.gravity");
  addShaft(config, 0, pair.pinion(), pair.spec().pinion, b);
  addShaft(config, 1, pair.gear(), pair.spec().gear, b);
  train.meshes.push_back(meshFromConfig(config, pair, std::move(stiffness)));
  layout.line_of_action_angle = config.has("mesh.line_of_action_angle_deg")
                                    ? config.real("mesh.line_of_action_angle_deg") * kDeg
                                    : pair.operatingPressureAngle();
  layout.speed = speedFromConfig(config);
  layout.drive_node = static_cast<int>(config.integer("load.drive_node"));
  const long long load_node = config.integer("load.load_node");
  const int gear_nodes = static_cast<int>(train.shafts[1].section_lengths.size()) + 1;
  layout.load_node = load_node < 0 ? gear_nodes - 1 : static_cast<int>(load_node);
  const int pinion_nodes = static_cast<int>(train.shafts[0].section_lengths.size()) + 1;
  if (layout.drive_node >= pinion_nodes)
    throw InputError("load.drive_node", std::to_string(layout.drive_node),
                     fmt::format("a node in [0, {}]", pinion_nodes - 1));
  if (layout.load_node >= gear_nodes)
    throw InputError("load.load_node", std::to_string(layout.load_node),
                     fmt::format("a node in [0, {}]", gear_nodes - 1));
  OperatingPoint& op = train.operating;
  op.input_shaft = kShafts[0];
  op.output_shaft = kShafts[1];
  op.input_speed = layout.speed.start;
  op.input_torque = config.real("load.torque");
  op.input_position = nodePosition(train.shafts[0], layout.drive_node);
  op.output_position = nodePosition(train.shafts[1], layout.load_node);
  return b;
}

FeRotorModel feRotorModelFromConfig(const Config& config, const std::string& stiffness_model) {
  FeRotorBuild b = feRotorFromConfig(config, stiffness_model);
  return FeRotorModel(std::move(b.train), std::move(b.layout));
}

void checkRecordLength(const Config& config, const FeRotorModel& model, double duration) {
  const SpeedProfile& speed = model.speed();
  if (speed.constant() && speed.start > 0.0) {
    // The steady window holds time.window_mesh_periods whole mesh periods: the mesh-order
    // harmonics are fitted over it and its last two periods measure the periodicity. A shorter
    // record cannot hold it (the least squares of the orders is then rank-deficient).
    const double mesh_period = 2.0 * std::numbers::pi / (speed.start * model.pinionTeeth());
    const long long periods = config.integer("time.window_mesh_periods");
    const double minimum = static_cast<double>(periods) * mesh_period;
    if (duration < minimum * (1.0 - 1e-9)) {
      throw InputError(
          "time.duration", fmt::format("{:g} s", duration),
          fmt::format("at least {:.4g} s, the steady window of time.window_mesh_periods = {} mesh "
                      "periods of {:.4g} ms ({:g} rpm, {} pinion teeth); lengthen time.duration "
                      "or lower time.window_mesh_periods",
                      minimum, periods, mesh_period * 1e3, speed.start / kRpm,
                      model.pinionTeeth()));
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

FeTimeOptions feTimeOptionsFromConfig(const Config& config, const FeRotorModel& model) {
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

std::vector<int> feOutputChannels(const Config& config, const FeRotorModel& model) {
  std::vector<int> channels;
  const auto names = config.stringList("time.outputs");
  if (names.empty()) {
    const FeRotorLayout& layout = model.layout();
    for (int s = 0; s < 2; ++s) {
      for (int d : {kUy, kUz}) channels.push_back(model.dofIndex(s, layout.gear_nodes[s], d));
    }
    for (int s = 0; s < 2; ++s) {
      if (layout.bearing_nodes[s].empty()) continue;
      for (int d : {kUy, kUz})
        channels.push_back(model.dofIndex(s, layout.bearing_nodes[s].front(), d));
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
