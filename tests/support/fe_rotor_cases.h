#pragma once
/// \file
/// The finite-element geared rotor of Visnadi & de Castro (2021) §4, shared by tests and
/// benchmarks: two shafts of `elements` equal elements (the paper: 2 elements of 100 mm,
/// 30 mm diameter), bearings at the shaft ends (7e7 N/m, 150 N s/m), gears at the centre node
/// with their bodies as disks, E = 200 GPa, G = 80 GPa, ρ = 7800 kg/m³, β-damping 3e-5, pinion at
/// 500 rpm, gravity. Built as a user's file is (config::feRotorFromConfig of a `rotor` file)
/// and then given the test's own mesh stiffness; tests change the gearbox or the layout.

#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include "geardyn/config/config.h"
#include "geardyn/config/fe_rotor_config.h"
#include "geardyn/stiffness/api_stiffness.h"
#include "geardyn/system/fe_rotor_model.h"
#include "support/reference_pairs.h"

namespace geardyn::testing {

/// A gearbox and the file's numbering of it, to change before building the model.
struct FeRotorCase {
  GearTrainSpec train;
  FeRotorLayout layout;
  FeRotorModel model() const { return FeRotorModel(train, layout); }
  /// Position of `node` of shaft `s` [m].
  double position(int s, int node) const {
    double x = 0.0;
    for (int i = 0; i < node; ++i) x += train.shafts[s].section_lengths[i];
    return x;
  }
  void addUnbalance(int s, int node, double mass_eccentricity, double phase) {
    train.unbalances.push_back({fmt::format("u{}", train.unbalances.size()), train.shafts[s].name,
                                position(s, node), mass_eccentricity, phase});
  }
  void setSpeed(const SpeedProfile& speed) {
    layout.speed = speed;
    train.operating.input_speed = speed.start;
  }
  void setGravity(double g) { train.gravity = g; }
};

/// The `rotor` file of the Visnadi rotor.
inline std::string visnadiFeRotorToml(double helix_deg, int elements, double torque) {
  std::string lengths, gear;
  for (int e = 0; e < elements; ++e) lengths += fmt::format("{}{}", e ? ", " : "", 0.2 / elements);
  std::string text = "[model]\ntype = \"fe_geared_rotor\"\n";
  for (const char* member : {"pinion", "gear"}) {
    const bool pinion = std::string(member) == "pinion";
    text += fmt::format(
        "[{}]\nteeth = {}\nmodule = 0.003\nface_width = 0.020\nyoungs_modulus = 200e9\n"
        "poisson_ratio = 0.3\nbore_diameter = 0.030\nhelix_angle_deg = {}\n",
        member, pinion ? 25 : 30, pinion ? helix_deg : -helix_deg);
  }
  for (const char* shaft : {"pinion_shaft", "gear_shaft"}) {
    text += fmt::format(
        "[{0}]\nelement_lengths = [{1}]\nouter_diameters = [0.03]\ngear_node = {2}\n"
        "youngs_modulus = 200e9\nshear_modulus = 80e9\ndensity = 7800.0\n"
        "[{0}.bearings]\nnodes = [0, {3}]\nkyy = [7e7]\nkzz = [7e7]\ncyy = [150.0]\n"
        "czz = [150.0]\n",
        shaft, lengths, elements / 2, elements);
  }
  text += fmt::format(
      "[damping]\nstiffness_proportional = 3e-5\n[load]\ntorque = {}\ndrive_node = 0\n"
      "load_node = {}\ngravity = 9.81\n[speed]\nspeed_rpm = 500.0\n",
      torque, elements);
  return text;
}

inline FeRotorCase visnadiFeRotor(std::shared_ptr<const MeshStiffness> stiffness,
                                  double helix_deg = 0.0, int elements = 2, double torque = 50.0) {
  const config::Config config = config::parseConfig(visnadiFeRotorToml(helix_deg, elements, torque),
                                                    "visnadi", config::feRotorSchema());
  config::FeRotorBuild build = config::feRotorFromConfig(config);
  build.train.meshes.front().stiffness = std::move(stiffness);
  return {std::move(build.train), std::move(build.layout)};
}

inline std::shared_ptr<const MeshStiffness> constantMesh(double k) {
  return std::make_shared<ConstantMeshStiffness>("constant", k, 1.6);
}

}  // namespace geardyn::testing
