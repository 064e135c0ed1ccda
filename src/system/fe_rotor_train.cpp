/// The FE geared rotor as a gear train (fe_rotor_train.h).

#include "geardyn/system/fe_rotor_train.h"

#include <fmt/format.h>

#include <cmath>

#include "geardyn/error.h"

namespace geardyn {

GearTrainSpec gearTrainFromFeRotor(const FeGearedRotorSpec& rotor, const GearPairSpec& pair) {
  GearTrainSpec spec;
  spec.name = "fe_geared_rotor";
  spec.dofs = TrainDofs::kFull;
  spec.mass_proportional_damping = rotor.mass_proportional;
  // β K_shafts of the FE rotor: the shafts' material damping, not the gearbox's β (which would
  // also damp the bearings and the mesh).
  spec.stiffness_proportional_damping = 0.0;
  spec.gravity = rotor.gravity;
  const char* gear_names[2] = {"pinion", "gear"};
  for (int s = 0; s < 2; ++s) {
    const FeShaftSpec& fe = rotor.shafts[s];
    if (!fe.unbalances.empty()) {
      throw InputError(fe.name + ".unbalance.nodes",
                       fmt::format("{} unbalance(s)", fe.unbalances.size()),
                       "none: a gearbox description carries no unbalance forces (the modes do "
                       "not depend on them)");
    }
    if (fe.elements.empty()) throw InputError(fe.name + ".element_lengths", "[]", "elements");
    TrainShaftSpec shaft;
    shaft.name = fe.name;
    shaft.flexible = true;
    shaft.stiffness_proportional_damping = rotor.stiffness_proportional;
    const ShaftSegment& first = fe.elements.front();
    shaft.density = first.density;
    shaft.youngs_modulus = first.youngs_modulus;
    shaft.poisson_ratio = first.youngs_modulus / (2.0 * first.shear_modulus) - 1.0;
    std::vector<double> node_x{0.0};
    for (const ShaftSegment& e : fe.elements) {
      if (e.density != first.density || e.youngs_modulus != first.youngs_modulus ||
          e.shear_modulus != first.shear_modulus) {
        throw InputError(fe.name, "", "one material per shaft");
      }
      shaft.section_lengths.push_back(e.length);
      shaft.outer_diameters.push_back(e.outer_diameter);
      shaft.inner_diameters.push_back(e.inner_diameter);
      node_x.push_back(node_x.back() + e.length);
    }
    spec.shafts.push_back(shaft);
    TrainGearSpec gear;
    gear.name = gear_names[s];
    gear.shaft = fe.name;
    gear.gear = s == 0 ? pair.pinion : pair.gear;
    gear.body = false;  // the FE rotor's gear body is one of its disks
    gear.position = node_x[fe.gear_node];
    spec.gears.push_back(gear);
    for (std::size_t i = 0; i < fe.disks.size(); ++i) {
      const FeDisk& d = fe.disks[i];
      spec.disks.push_back({fe.name + "_disk" + std::to_string(i), fe.name, node_x[d.node], d.mass,
                            d.polar_inertia, d.diametral_inertia});
    }
    for (std::size_t i = 0; i < fe.bearings.size(); ++i) {
      const FeBearing& b = fe.bearings[i];
      TrainBearingSpec t;
      t.name = fe.name + "_bearing" + std::to_string(i);
      t.shaft = fe.name;
      t.position = node_x[b.node];
      t.kyy = b.kyy, t.kzz = b.kzz, t.kyz = b.kyz, t.kzy = b.kzy;
      t.cyy = b.cyy, t.czz = b.czz, t.cyz = b.cyz, t.czy = b.czy;
      t.k_axial = b.kxx, t.c_axial = b.cxx, t.k_tilt = b.k_tilt, t.c_tilt = b.c_tilt;
      t.k_torsion = b.k_torsion, t.c_torsion = b.c_torsion;
      spec.bearings.push_back(t);
    }
  }
  TrainMeshSpec mesh;
  mesh.name = "mesh";
  mesh.gear_a = "pinion";
  mesh.gear_b = "gear";
  const Eigen::Vector2d offset = gearCentreOffset(rotor.mesh);
  mesh.position_angle = std::atan2(offset.y(), offset.x());
  mesh.centre_distance = pair.centre_distance;
  mesh.stiffness = rotor.mesh_stiffness;
  mesh.transmission_error = rotor.transmission_error;
  mesh.damping = rotor.mesh_damping;
  spec.meshes.push_back(mesh);
  double x = 0.0;
  std::vector<double> load_x{0.0};
  for (const ShaftSegment& e : rotor.shafts[0].elements) load_x.push_back(x += e.length);
  spec.operating.input_shaft = rotor.shafts[0].name;
  spec.operating.output_shaft = rotor.shafts[1].name;
  spec.operating.input_speed = rotor.speed.start;
  spec.operating.input_torque = rotor.drive_torque;
  spec.operating.input_position = load_x[rotor.drive_node];
  x = 0.0;
  std::vector<double> gear_x{0.0};
  for (const ShaftSegment& e : rotor.shafts[1].elements) gear_x.push_back(x += e.length);
  spec.operating.output_position = gear_x[rotor.load_node];
  return spec;
}

std::vector<int> feRotorTrainDofs(const FeGearedRotor& fe, const GearTrainModel& train) {
  // FE node DOF type (NodeDof) → offset in the train's node order.
  constexpr int kTrainOffset[kNodeDofs] = {3, 0, 1, 2, 4, 5};
  std::vector<int> map(fe.dofCount());
  for (int i = 0; i < fe.dofCount(); ++i) {
    const int body = train.shaftNodes(fe.shaftOf(i))[fe.nodeOf(i)];
    map[i] = train.bodies()[body].first_dof + kTrainOffset[fe.typeOf(i)];
  }
  return map;
}

}  // namespace geardyn
