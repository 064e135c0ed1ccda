/// Mesh misalignment from a static deflection (system/mesh_misalignment.h).

#include "geardyn/system/mesh_misalignment.h"

#include <algorithm>
#include <cmath>

#include "geardyn/system/detail/train_building.h"

namespace geardyn {
namespace {

/// A gear's axial extent: mid-face x and face width [m].
struct Face {
  double x = 0.0, width = 0.0;
};

/// The face of side `gear` (index in spec().gears; −1: a planetary stage's sun, ring or planet)
/// on body `body` of mesh m.
Face faceOf(const GearTrainModel& model, const TrainMesh& m, int gear, int body) {
  const GearTrainSpec& spec = model.spec();
  const TrainBody& b = model.bodies()[body];
  if (b.kind == TrainBodyKind::kPlanet) return {b.axial, spec.stages[b.stage].planet.face_width};
  if (gear < 0) {
    const PlanetaryStageSpec& st = spec.stages[m.stage];
    const bool sun = m.kind == TrainMeshKind::kSunPlanet;
    gear = detail::gearIndexOf(spec, sun ? st.sun : st.ring,
                               "planetary." + st.name + (sun ? ".sun" : ".ring"));
  }
  const TrainGearSpec& g = spec.gears[gear];
  const int shaft = detail::shaftIndexOf(spec, g.shaft, "gears." + g.name + ".shaft");
  return {spec.shafts[shaft].axial_offset + g.position, g.gear.face_width};
}

/// Translation (y, z) of body `body`'s axis at global x, and the slope of its axis (θ_z, −θ_y).
void axisAt(const GearTrainModel& model, int body, double x,
            const Eigen::Ref<const Eigen::VectorXd>& q, Eigen::Vector2d& u, Eigen::Vector2d& s) {
  const TrainBody& b = model.bodies()[body];
  const int d = b.first_dof;
  u = Eigen::Vector2d(q(d), q(d + 1));
  s.setZero();
  if (model.dofsPerBody() == 6) {
    s = Eigen::Vector2d(q(d + 5), -q(d + 4));  // d(u_y, u_z)/dx = (θ_z, −θ_y)
    u += (x - b.axial) * s;
  }
}

}  // namespace

std::vector<MeshMisalignment> meshMisalignment(const GearTrainModel& model,
                                               const Eigen::Ref<const Eigen::VectorXd>& q) {
  std::vector<MeshMisalignment> out;
  if (model.dofsPerBody() == 1) return out;
  out.reserve(model.meshes().size());
  for (const TrainMesh& m : model.meshes()) {
    const Face fa = faceOf(model, m, m.gear_a, m.body_a);
    const Face fb = faceOf(model, m, m.gear_b, m.body_b);
    const double lo = std::max(fa.x - 0.5 * fa.width, fb.x - 0.5 * fb.width);
    const double hi = std::min(fa.x + 0.5 * fa.width, fb.x + 0.5 * fb.width);
    MeshMisalignment r;
    r.mesh = m.name;
    r.face_width = std::max(0.0, hi - lo);
    r.mid_face = 0.5 * (lo + hi);
    r.contact_x = 0.5 * (fa.x + fb.x);
    Eigen::Vector2d ua, sa, ub, sb;
    axisAt(model, m.body_a, r.mid_face, q, ua, sa);
    axisAt(model, m.body_b, r.mid_face, q, ub, sb);
    const Eigen::Vector2d n = m.normal;
    const Eigen::Vector2d p(-n.y(), n.x());  // x̂ × n_t
    r.tilt_in_plane = n.dot(sa - sb);
    r.tilt_out_of_plane = p.dot(sa - sb);
    r.mismatch = r.face_width * r.tilt_in_plane;
    r.mismatch_out_of_plane = r.face_width * r.tilt_out_of_plane;
    r.approach = n.dot(ua - ub);
    const Eigen::Vector2d ab = model.bodies()[m.body_b].centre - model.bodies()[m.body_a].centre;
    if (ab.norm() > 0.0) r.centre_distance_change = ab.normalized().dot(ub - ua);
    out.push_back(r);
  }
  return out;
}

}  // namespace geardyn
