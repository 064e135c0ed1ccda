/// The mesh deflection gradient v (see the header for the derivation).

#include "geardyn/models/gear_mesh_coupling.h"

#include <cmath>

namespace geardyn {
namespace {

struct Frame {
  Eigen::Vector3d n, m, nt;  // contact normal, transverse unit vectors (x, y, z)
};

Frame frameOf(const MeshCouplingGeometry& g) {
  const double s = std::sin(g.line_of_action_angle), c = std::cos(g.line_of_action_angle);
  Frame f;
  f.nt = {0.0, s, c};
  f.m = {0.0, c, -s};
  f.n =
      std::sin(g.base_helix_angle) * Eigen::Vector3d::UnitX() + std::cos(g.base_helix_angle) * f.nt;
  return f;
}

}  // namespace

Eigen::Vector2d gearCentreOffset(const MeshCouplingGeometry& g) {
  const Frame f = frameOf(g);
  const Eigen::Vector3d centre =
      (g.pinion_base_radius + g.gear_base_radius) * f.m + g.line_of_action_length * f.nt;
  return {centre.y(), centre.z()};
}

MeshVector meshDeflectionGradient(const MeshCouplingGeometry& g) {
  const Frame f = frameOf(g);
  const Eigen::Vector3d gear_centre =
      (g.pinion_base_radius + g.gear_base_radius) * f.m + g.line_of_action_length * f.nt;
  const Eigen::Vector3d t1 = g.pinion_base_radius * f.m;
  const Eigen::Vector3d t2 = t1 + g.line_of_action_length * f.nt;
  const Eigen::Vector3d pitch = t1 + g.pitch_point_distance * f.nt;
  const bool same_point = g.contact_point == MeshContactPoint::kPitchPoint;
  const Eigen::Vector3d arm_p = same_point ? pitch : t1;
  const Eigen::Vector3d arm_g = (same_point ? pitch : t2) - gear_centre;

  MeshVector v;
  v.segment<3>(kUx) = f.n;
  v.segment<3>(kRx) = arm_p.cross(f.n);
  v.segment<3>(kNodeDofs + kUx) = -f.n;
  v.segment<3>(kNodeDofs + kRx) = -arm_g.cross(f.n);
  return v;
}

}  // namespace geardyn
