#pragma once
/// \file
/// The finite-element geared rotor of Visnadi & de Castro (2021) §4, shared by tests and
/// benchmarks: two shafts of `elements` equal elements (the paper: 2 elements of 100 mm,
/// 30 mm diameter), bearings at the shaft ends (7e7 N/m, 150 N s/m), gears at the centre node
/// with the mass properties of Table 1's gears, β-damping 3e-5, pinion at 500 rpm.

#include <cmath>
#include <memory>
#include <numbers>

#include "geardyn/geometry/gear_pair.h"
#include "geardyn/models/fe_geared_rotor.h"
#include "geardyn/stiffness/api_stiffness.h"
#include "support/reference_pairs.h"

namespace geardyn::testing {

inline FeGearedRotorSpec visnadiFeRotorSpec(std::shared_ptr<const MeshStiffness> stiffness,
                                            double helix_deg = 0.0, int elements = 2,
                                            double torque = 50.0) {
  const GearPair pair(visnadiPairSpec(helix_deg));
  FeGearedRotorSpec spec;
  const std::array<const GearGeometry*, 2> gears{&pair.pinion(), &pair.gear()};
  for (int s = 0; s < 2; ++s) {
    FeShaftSpec& shaft = spec.shafts[s];
    shaft.name = s == 0 ? "pinion_shaft" : "gear_shaft";
    ShaftSegment seg;
    seg.length = 0.2 / elements;
    seg.outer_diameter = 0.03;
    seg.youngs_modulus = 200e9;
    seg.shear_modulus = 80e9;
    seg.density = 7800;
    shaft.elements.assign(elements, seg);
    shaft.gear_node = elements / 2;
    for (int node : {0, elements}) {
      FeBearing b;
      b.node = node;
      b.kyy = b.kzz = 7e7;
      b.cyy = b.czz = 150;
      shaft.bearings.push_back(b);
    }
    shaft.disks.push_back(
        {shaft.gear_node, gears[s]->mass, gears[s]->polar_inertia, gears[s]->diametral_inertia});
  }
  spec.mesh.line_of_action_angle = pair.operatingPressureAngle();  // horizontal centre line
  // Right-hand pinion (helix_deg > 0): β_b < 0, as in fe_rotor_io.cpp.
  spec.mesh.base_helix_angle = -std::copysign(pair.baseHelixAngle(), helix_deg);
  spec.mesh.pinion_base_radius = pair.pinion().base_radius;
  spec.mesh.gear_base_radius = pair.gear().base_radius;
  spec.mesh.line_of_action_length = pair.lineOfActionLength();
  spec.mesh.pitch_point_distance =
      pair.pinion().base_radius * std::tan(pair.operatingPressureAngle());
  spec.pinion_teeth = 25;
  spec.gear_teeth = 30;
  spec.mesh_stiffness = std::move(stiffness);
  spec.stiffness_proportional = 3e-5;
  spec.drive_torque = torque;
  spec.drive_node = 0;
  spec.load_node = elements;
  spec.gravity = 9.81;
  const double omega = 500.0 * 2.0 * std::numbers::pi / 60.0;
  spec.speed = {omega, omega, 0.0, 0.0};
  return spec;
}

inline std::shared_ptr<const MeshStiffness> constantMesh(double k) {
  return std::make_shared<ConstantMeshStiffness>("constant", k, 1.6);
}

}  // namespace geardyn::testing
