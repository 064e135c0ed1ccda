/// The 3-D deflection gradient of a mesh with six DOFs per body (system/gear_train_model.h),
/// for parallel-axis and planetary meshes.

#include <fmt/format.h>

#include <Eigen/Dense>
#include <cmath>
#include <string>
#include <utility>

#include "geardyn/error.h"
#include "geardyn/system/detail/train_building.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn {

/// The 3-D mesh deflection gradient (full DOFs). The contact normal of involute helicoids lies
/// in the plane of action and is perpendicular to the contact line, which runs along the base
/// helix: for the flank of an external gear g with hand h_g (+1 right) whose transverse normal
/// n_t turns g in the sense σ_g = sgn[((c − c_g) × n_t)·x̂], the contact line is
/// cos β_b x̂ + σ_g h_g sin β_b n_t and the normal n = cos β_b n_t − σ_g h_g sin β_b x̂
/// (docs/theory/gear_trains.md; a right-hand driver turning about +x pushes the driven gear
/// towards −x, Shigley's hand rule). Then δ = n·(u_a + θ_a × r_a) − n·(u_b + θ_b × r_b), r the
/// vectors from the bodies' reference points to the contact point c (axially between the two
/// gears' mid-faces), so v = [n, r_a × n] over (u_a, θ_a) and −[n, r_b × n] over (u_b, θ_b).
void GearTrainModel::fullMeshGradient(const TrainMesh& m, std::vector<int>& dofs,
                                      Eigen::VectorXd& v) const {
  // Each side: its gear, whether internal, its mid-face x, and its key. A planet (gear index
  // −1) is its stage's planet gear in the sun gear's plane (the planet body's axial position).
  struct Side {
    const GearSpec* gear;
    bool internal;
    double x;
    std::string key;
    double position;
  };
  const auto side = [&](int gear, int body) {
    if (bodies_[body].kind == TrainBodyKind::kPlanet) {
      const PlanetaryStageSpec& st = spec_.stages[bodies_[body].stage];
      return Side{&st.planet, false, bodies_[body].axial, "planetary." + st.name + ".planet",
                  bodies_[body].axial};
    }
    if (gear < 0) {  // the sun or ring of a planetary mesh
      const PlanetaryStageSpec& st = spec_.stages[m.stage];
      const bool sun = m.kind == TrainMeshKind::kSunPlanet;
      gear = detail::gearIndexOf(spec_, sun ? st.sun : st.ring,
                                 "planetary." + st.name + (sun ? ".sun" : ".ring"));
    }
    const TrainGearSpec& g = spec_.gears[gear];
    const double x =
        spec_.shafts[detail::shaftIndexOf(spec_, g.shaft, "gears." + g.name + ".shaft")]
            .axial_offset +
        g.position;
    return Side{&g.gear, g.internal, x, "gears." + g.name, g.position};
  };
  const Side A = side(m.gear_a, m.body_a), B = side(m.gear_b, m.body_b);
  const double xa = A.x, xb = B.x;
  if (std::abs(xa - xb) >= 0.5 * (A.gear->face_width + B.gear->face_width)) {
    // A planetary mesh: the planets sit in the sun's plane, so the ring gear is the one placed.
    const bool planetary = bodies_[m.body_b].kind == TrainBodyKind::kPlanet;
    const Side& placed = planetary ? A : B;
    const Side& other = planetary ? B : A;
    throw InputError(placed.key + ".position", fmt::format("{:g} m", placed.position),
                     fmt::format("a position where its face overlaps {} of {} (their "
                                 "mid-faces are {:g} mm apart along x)",
                                 other.key, m.name, 1e3 * std::abs(xa - xb)));
  }
  const double cb = std::cos(m.base_helix_angle), sb = std::sin(std::abs(m.base_helix_angle));
  const auto cross_x = [](const Eigen::Vector2d& r, const Eigen::Vector2d& n) {
    return r.x() * n.y() - r.y() * n.x();
  };
  double nx;
  if (!A.internal) {
    const double sigma = cross_x(m.pitch_point - bodies_[m.body_a].centre, m.normal) >= 0 ? 1 : -1;
    const double hand = A.gear->helix_angle > 0 ? 1.0 : A.gear->helix_angle < 0 ? -1.0 : 0.0;
    nx = -sigma * hand * sb;
  } else {  // b is the external member; its flank normal is −n
    const double sigma = cross_x(m.pitch_point - bodies_[m.body_b].centre, -m.normal) >= 0 ? 1 : -1;
    const double hand = B.gear->helix_angle > 0 ? 1.0 : B.gear->helix_angle < 0 ? -1.0 : 0.0;
    nx = sigma * hand * sb;
  }
  const Eigen::Vector3d n(nx, cb * m.normal.x(), cb * m.normal.y());  // (x, y, z)
  const Eigen::Vector3d c(0.5 * (xa + xb), m.pitch_point.x(), m.pitch_point.y());
  dofs.clear();
  v.resize(12);
  int k = 0;
  for (auto [body, sign] : {std::pair{m.body_a, 1.0}, std::pair{m.body_b, -1.0}}) {
    const TrainBody& b = bodies_[body];
    const Eigen::Vector3d r = c - Eigen::Vector3d(b.axial, b.centre.x(), b.centre.y());
    const Eigen::Vector3d rn = r.cross(n);
    const double entries[6] = {n.y(), n.z(), rn.x(), n.x(), rn.y(), rn.z()};
    for (int d = 0; d < 6; ++d) {
      dofs.push_back(b.first_dof + d);
      v(k++) = sign * entries[d];
    }
  }
}

}  // namespace geardyn
