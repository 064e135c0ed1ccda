/// Gear-train assembly: bodies, kinematics, layout, elements and matrices (gear_train_model.h).
/// The meshes are built in train_meshes.cpp.

#include "geardyn/system/gear_train_model.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "geardyn/error.h"
#include "geardyn/system/detail/train_building.h"

namespace geardyn {
namespace {

using detail::PointJacobian;

void requireNonNegative(double value, const std::string& key, const std::string& unit) {
  if (!std::isfinite(value) || value < 0.0) {
    throw InputError(key, fmt::format("{:g} {}", value, unit), "a finite number >= 0");
  }
}

}  // namespace

std::string toString(TrainDofs dofs) {
  switch (dofs) {
    case TrainDofs::kTorsional:
      return "torsional";
    case TrainDofs::kPlanar:
      return "planar";
    case TrainDofs::kFull:
      return "full";
  }
  return "?";
}

TrainDofs parseTrainDofs(const std::string& text, const std::string& key) {
  if (text == "planar") return TrainDofs::kPlanar;
  if (text == "torsional") return TrainDofs::kTorsional;
  if (text == "full") return TrainDofs::kFull;
  throw InputError(key, "\"" + text + "\"", "\"torsional\", \"planar\" or \"full\"");
}

std::string toString(TrainMeshKind kind) {
  switch (kind) {
    case TrainMeshKind::kExternal:
      return "external";
    case TrainMeshKind::kInternal:
      return "internal";
    case TrainMeshKind::kSunPlanet:
      return "sun_planet";
    case TrainMeshKind::kRingPlanet:
      return "ring_planet";
  }
  return "?";
}

double TrainMesh::phaseAt(double t, double input_speed) const {
  return frequency_ratio * std::abs(input_speed) * t + phase;
}

double TrainMesh::deflection(const Eigen::Ref<const Eigen::VectorXd>& q) const {
  double d = 0.0;
  for (std::size_t i = 0; i < dofs.size(); ++i) d += gradient[i] * q(dofs[i]);
  return d;
}

double TrainMesh::force(double t, double input_speed,
                        const Eigen::Ref<const Eigen::VectorXd>& q) const {
  const double phi = phaseAt(t, input_speed);
  return stiffness->stiffness(phi) *
         contactDeflection(deflection(q) - transmission_error.value(phi));
}

double TrainMesh::contactDeflection(double y, double* slope) const {
  double s = 1.0, g = y;
  if (contact.law == ContactLaw::kOneSided || contact.law == ContactLaw::kBacklash) {
    // Loaded flank for y > 0; free play down to −j; the back flank below (backlash only).
    const double back = contact.law == ContactLaw::kBacklash ? -contact.backlash : -HUGE_VAL;
    if (y > 0.0) {
      g = y;
    } else if (y < back) {
      g = y - back;
    } else {
      g = 0.0, s = 0.0;
    }
  }
  if (slope) *slope = s;
  return g;
}

bool GearTrainModel::hasNonlinearMeshes() const {
  return std::any_of(meshes_.begin(), meshes_.end(),
                     [](const TrainMesh& m) { return m.nonlinear(); });
}

GearTrainModel::GearTrainModel(GearTrainSpec spec, double memory_limit)
    : spec_(std::move(spec)), memory_limit_(memory_limit) {
  buildBodies();
  buildMeshes();
  buildElements();
  assemble();
}

int GearTrainModel::bodyIndex(const std::string& name) const {
  for (std::size_t i = 0; i < spec_.shafts.size(); ++i) {
    if (spec_.shafts[i].name == name) return shaft_body_[i];
  }
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    if (bodies_[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

int GearTrainModel::rotationDof(int body) const {
  return bodies_[body].first_dof + (spec_.dofs == TrainDofs::kTorsional ? 0 : 2);
}

int GearTrainModel::translationDof(int body) const {
  return spec_.dofs == TrainDofs::kTorsional ? -1 : bodies_[body].first_dof;
}

std::string GearTrainModel::dofName(int i) const {
  const int per = dofsPerBody();
  const int body = i / per;
  static constexpr const char* kNames[6] = {"y", "z", "theta", "x", "theta_y", "theta_z"};
  return bodies_[body].name + "." + (per == 1 ? "theta" : kNames[i % per]);
}

void GearTrainModel::buildBodies() {
  if (spec_.shafts.empty()) throw InputError("shafts", "", "at least one shaft");
  std::set<std::string> names;
  auto unique = [&](const std::string& name, const std::string& key) {
    if (name.empty()) throw InputError(key, "\"\"", "a non-empty name");
    if (!names.insert(name).second) {
      throw InputError(key, "\"" + name + "\"",
                       "a name used once: shafts, gears, meshes, bearings, couplings and stages "
                       "share one name space");
    }
  };
  for (const auto& s : spec_.shafts) unique(s.name, "shafts." + s.name);
  for (const auto& g : spec_.gears) unique(g.name, "gears." + g.name);
  for (const auto& m : spec_.meshes) unique(m.name, "meshes." + m.name);
  for (const auto& b : spec_.bearings) unique(b.name, "bearings." + b.name);
  for (const auto& c : spec_.couplings) unique(c.name, "couplings." + c.name);
  for (const auto& st : spec_.stages) unique(st.name, "planetary." + st.name);
  for (const auto& d : spec_.disks) unique(d.name, "disks." + d.name);

  const bool full = spec_.dofs == TrainDofs::kFull;
  shaft_nodes_.assign(spec_.shafts.size(), {});
  std::vector<detail::MassSum> rigid(spec_.shafts.size());
  for (std::size_t s = 0; s < spec_.shafts.size(); ++s) {
    const TrainShaftSpec& shaft = spec_.shafts[s];
    const std::string key = "shafts." + shaft.name;
    if (shaft.flexible && !full) {
      throw InputError(key + ".flexible", "true",
                       "false with dofs = \"" + toString(spec_.dofs) +
                           "\" (a flexible shaft needs gearbox.dofs = \"full\")");
    }
    requireNonNegative(shaft.mass, key + ".mass", "kg");
    requireNonNegative(shaft.polar_inertia, key + ".polar_inertia", "kg m^2");
    requireNonNegative(shaft.diametral_inertia, key + ".diametral_inertia", "kg m^2");
    if (!std::isfinite(shaft.axial_offset)) {
      throw InputError(key + ".axial_offset", fmt::format("{:g} m", shaft.axial_offset),
                       "a finite position");
    }
    if (shaft.flexible) {
      buildShaftNodes(static_cast<int>(s));
      shaft_body_.push_back(shaft_nodes_[s].front());
      continue;
    }
    TrainBody body;
    body.name = shaft.name;
    body.shaft = static_cast<int>(s);
    detail::addSectionMasses(detail::shaftSections(shaft), rigid[s]);
    shaft_body_.push_back(static_cast<int>(bodies_.size()));
    shaft_nodes_[s] = {static_cast<int>(bodies_.size())};
    bodies_.push_back(body);
  }
  // A mass mounted at `position` on shaft s: on the node there (flexible) or into the rigid
  // body's sums.
  auto mount = [&](int s, double position, const std::string& key, double mass, double polar,
                   double diametral) {
    const int b = bodyAt(s, position, key + ".position");
    if (spec_.shafts[s].flexible) {
      bodies_[b].mass += mass;
      bodies_[b].polar_inertia += polar;
      bodies_[b].diametral_inertia += diametral;
    } else {
      rigid[s].add(mass, polar, diametral, position);
    }
  };
  for (const auto& gear : spec_.gears) {
    const std::string key = "gears." + gear.name;
    const int s = detail::shaftIndexOf(spec_, gear.shaft, key + ".shaft");
    bodyAt(s, gear.position, key + ".position");
    gear.gear.validate(key);
    if (gear.body && !gear.internal) {
      const GearBodyMass m = gearBodyMass(gear.gear);
      mount(s, gear.position, key, m.mass, m.polar_inertia, m.diametral_inertia);
    }
  }
  for (const auto& disk : spec_.disks) {
    const std::string key = "disks." + disk.name;
    const int s = detail::shaftIndexOf(spec_, disk.shaft, key + ".shaft");
    requireNonNegative(disk.mass, key + ".mass", "kg");
    requireNonNegative(disk.polar_inertia, key + ".polar_inertia", "kg m^2");
    requireNonNegative(disk.diametral_inertia, key + ".diametral_inertia", "kg m^2");
    mount(s, disk.position, key, disk.mass, disk.polar_inertia, disk.diametral_inertia);
  }
  // A rigid shaft's reference point is its mass centre (its own mass and inertias are about
  // it); its parts' diametral inertias move there by the parallel-axis theorem.
  for (std::size_t s = 0; s < spec_.shafts.size(); ++s) {
    const TrainShaftSpec& shaft = spec_.shafts[s];
    if (shaft.flexible) continue;
    TrainBody& body = bodies_[shaft_body_[s]];
    body.mass = shaft.mass + rigid[s].mass;
    body.polar_inertia = shaft.polar_inertia + rigid[s].polar_inertia;
    body.diametral_inertia = shaft.diametral_inertia + rigid[s].diametralAboutCentre();
    body.axial = shaft.axial_offset + rigid[s].centre();
  }
  // Planets: one body each, in the stage's carrier frame.
  for (std::size_t s = 0; s < spec_.stages.size(); ++s) {
    const PlanetaryStageSpec& st = spec_.stages[s];
    const std::string key = "planetary." + st.name;
    if (st.planets < 1 || st.planets > 32) {
      throw InputError(key + ".planets", std::to_string(st.planets), "an integer in [1, 32]");
    }
    st.planet.validate(key + ".planet");
    requireNonNegative(st.planet_mass, key + ".planet_mass", "kg");
    requireNonNegative(st.planet_inertia, key + ".planet_inertia", "kg m^2");
    const GearBodyMass planet_body = gearBodyMass(st.planet);
    // Full DOFs: the planets turn in the sun gear's mid-face plane; the lumped part is a disk
    // of the face width b unless its diametral inertia is given.
    double axial = 0.0, diametral = 0.0;
    if (full) {
      const int sun = detail::gearIndexOf(spec_, st.sun, key + ".sun");
      const TrainGearSpec& g = spec_.gears[sun];
      axial = spec_.shafts[detail::shaftIndexOf(spec_, g.shaft, "gears." + g.name + ".shaft")]
                  .axial_offset +
              g.position;
      const double b = st.planet.face_width;
      diametral = st.planet_diametral_inertia >= 0.0
                      ? st.planet_diametral_inertia
                      : 0.5 * st.planet_inertia + st.planet_mass * b * b / 12.0;
      if (st.planet_body) diametral += planet_body.diametral_inertia;
    }
    for (int n = 0; n < st.planets; ++n) {
      TrainBody body;
      body.name = fmt::format("{}.planet{}", st.name, n + 1);
      body.kind = TrainBodyKind::kPlanet;
      body.stage = static_cast<int>(s);
      body.planet = n;
      body.mass = st.planet_mass + (st.planet_body ? planet_body.mass : 0.0);
      body.polar_inertia = st.planet_inertia + (st.planet_body ? planet_body.polar_inertia : 0.0);
      body.axial = axial;
      body.diametral_inertia = diametral;
      bodies_.push_back(body);
    }
    if (full && st.carrier_frame_terms) {
      warnings_.push_back(fmt::format(
          "{}: with gearbox.dofs = \"full\" the stage is the fixed-frame lumped model (planets "
          "held at their positions); the carrier-frame Coriolis and centripetal terms are "
          "formulated for planar DOFs (set carrier_frame_terms = false to silence this)",
          key));
    }
  }
  const int per = dofsPerBody();
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    bodies_[b].first_dof = static_cast<int>(b) * per;
    const int shaft = bodies_[b].shaft;
    if (shaft >= 0 && spec_.shafts[shaft].flexible) continue;  // the beams carry mass
    if (!(bodies_[b].polar_inertia > 0.0)) {
      throw InputError(bodies_[b].kind == TrainBodyKind::kPlanet
                           ? "planetary." + spec_.stages[bodies_[b].stage].name + ".planet_inertia"
                           : "shafts." + bodies_[b].name + ".polar_inertia",
                       "0 kg m^2",
                       "a body needs a polar inertia > 0 (its own, its sections' or its gears')");
    }
    if (spec_.dofs != TrainDofs::kTorsional && !(bodies_[b].mass > 0.0)) {
      throw InputError(bodies_[b].kind == TrainBodyKind::kPlanet
                           ? "planetary." + spec_.stages[bodies_[b].stage].name + ".planet_mass"
                           : "shafts." + bodies_[b].name + ".mass",
                       "0 kg", "planar and full DOFs need a mass > 0 on every body");
    }
    if (spec_.dofs == TrainDofs::kFull && !(bodies_[b].diametral_inertia > 0.0)) {
      throw InputError(
          bodies_[b].kind == TrainBodyKind::kPlanet
              ? "planetary." + spec_.stages[bodies_[b].stage].name + ".planet_diametral_inertia"
              : "shafts." + bodies_[b].name + ".diametral_inertia",
          "0 kg m^2",
          "full DOFs need a diametral inertia > 0 on every rigid shaft (its own, "
          "its sections', gears' or disks')");
    }
  }
  checkDenseFits(static_cast<double>(bodies_.size()) * per, "gearbox.dofs", toString(spec_.dofs));
  dof_count_ = static_cast<int>(bodies_.size()) * per;
}

void GearTrainModel::checkDenseFits(double dofs, const std::string& key,
                                    const std::string& value) const {
  const double bytes = kDenseMatrices * dofs * dofs * sizeof(double);
  if (bytes <= memory_limit_) return;
  throw InputError(
      key, value,
      fmt::format("a model that fits in memory: {:.0f} DOFs need {:.3g} GB for {} dense "
                  "{}×{} matrices, over the limit of {:.3g} GB (80 % of the "
                  "available memory, or GEARDYN_MEMORY_LIMIT)",
                  dofs, bytes / 1e9, kDenseMatrices, dofs, dofs, memory_limit_ / 1e9));
}

void GearTrainModel::checkClearance(const TrainBearingSpec& b, const std::string& key) const {
  const std::string ckey = key + ".radial_clearance";
  if (!(b.radial_clearance >= 0.0) || !std::isfinite(b.radial_clearance)) {
    throw InputError(ckey, fmt::format("{:g} m", b.radial_clearance),
                     "a finite radial clearance >= 0 m (0: a linear bearing)");
  }
  if (b.radial_clearance == 0.0) return;
  if (spec_.dofs == TrainDofs::kTorsional) {
    throw InputError(ckey, fmt::format("{:g} m", b.radial_clearance),
                     "0 with gearbox.dofs = \"torsional\": a torsional train has no radial "
                     "displacements (use \"planar\" or \"full\" DOFs for a clearance)");
  }
  if (!(b.kyy > 0.0) || b.kzz != b.kyy || b.kyz != 0.0 || b.kzy != 0.0) {
    throw InputError(key + (b.kyy > 0.0 ? ".kzz" : ".kyy"),
                     fmt::format("{:g} N/m", b.kyy > 0.0 ? b.kzz : b.kyy),
                     fmt::format("kyy = kzz > 0 without cross terms (kyy {:g} N/m, kyz {:g}, kzy "
                                 "{:g}): a bearing with radial_clearance {:g} m has one isotropic "
                                 "radial stiffness acting beyond the clearance",
                                 b.kyy, b.kyz, b.kzy, b.radial_clearance));
  }
}

void GearTrainModel::buildElements() {
  const bool planar = spec_.dofs == TrainDofs::kPlanar;
  const bool full = spec_.dofs == TrainDofs::kFull;
  const bool lateral = planar || full;
  addBeamElements();
  auto add = [&](std::string name, std::string kind, const std::vector<PointJacobian>& parts,
                 const Eigen::Matrix2d& k2, const Eigen::Matrix2d& c2) {
    // Relative displacement d = Σ J_i q: K = Jᵀ k J over the union of the DOFs.
    TrainElement e{std::move(name), std::move(kind), {}, {}, {}, k2};
    Eigen::MatrixXd J;
    detail::stackJacobians(parts, e.dofs, J);
    e.stiffness = J.transpose() * k2 * J;
    e.jacobian = J;
    const Eigen::MatrixXd c = J.transpose() * c2 * J;
    elements_.push_back(e);
    element_damping_.push_back(c);
  };
  auto add_torsion = [&](std::string name, std::string kind, std::vector<int> dofs,
                         std::vector<double> signs, double k, double c) {
    TrainElement e{std::move(name), std::move(kind), std::move(dofs), {}, {}, {}};
    Eigen::VectorXd s = Eigen::Map<Eigen::VectorXd>(signs.data(), signs.size());
    e.stiffness = k * s * s.transpose();
    e.jacobian = s.transpose();
    e.local_stiffness = Eigen::MatrixXd::Constant(1, 1, k);
    elements_.push_back(e);
    element_damping_.push_back(c * s * s.transpose());
  };

  for (const auto& b : spec_.bearings) {
    const std::string key = "bearings." + b.name;
    const int shaft = detail::shaftIndexOf(spec_, b.shaft, key + ".shaft");
    const int body = bodyAt(shaft, b.position, key + ".position");
    const int other_shaft = b.other_shaft.empty()
                                ? -1
                                : detail::shaftIndexOf(spec_, b.other_shaft, key + ".other_shaft");
    const int other =
        other_shaft < 0 ? -1 : bodyAt(other_shaft, b.other_position, key + ".other_position");
    const double dx = axialOffsetOf(body, shaft, b.position);
    const double other_dx = other < 0 ? 0.0 : axialOffsetOf(other, other_shaft, b.other_position);
    if (other_shaft == shaft) {
      throw InputError(key + ".other_shaft", "\"" + b.other_shaft + "\"",
                       "another shaft than `shaft` (or empty for the housing)");
    }
    for (auto [v, n] : {std::pair{b.kyy, "kyy"},
                        {b.kzz, "kzz"},
                        {b.cyy, "cyy"},
                        {b.czz, "czz"},
                        {b.k_torsion, "k_torsion"},
                        {b.c_torsion, "c_torsion"},
                        {b.k_axial, "k_axial"},
                        {b.c_axial, "c_axial"},
                        {b.k_tilt, "k_tilt"},
                        {b.c_tilt, "c_tilt"}}) {
      requireNonNegative(v, key + "." + n, n[0] == 'k' ? "N/m" : "N s/m");
    }
    if (!full && (b.k_axial > 0 || b.c_axial > 0 || b.k_tilt > 0 || b.c_tilt > 0)) {
      // One gearbox file, many analyses: a lumped model simply has no axial or tilt DOFs.
      warnings_.push_back(
          fmt::format("{}: the axial and tilt terms act only with gearbox.dofs = "
                      "\"full\"; ignored with \"{}\"",
                      key, toString(spec_.dofs)));
    }
    const bool isotropic =
        b.kyy == b.kzz && b.kyz == 0 && b.kzy == 0 && b.cyy == b.czz && b.cyz == 0 && b.czy == 0;
    if (planar && !isotropic &&
        (bodies_[body].stage >= 0 || (other >= 0 && bodies_[other].stage >= 0))) {
      throw InputError(key + ".kzz", fmt::format("{:g} N/m", b.kzz),
                       fmt::format("equal to kyy ({:g} N/m) without cross terms: the bearing "
                                   "holds a member formulated in a rotating carrier frame, where "
                                   "an anisotropic support would vary in time (set the stage's "
                                   "carrier_frame_terms = false for the fixed-frame model)",
                                   b.kyy));
    }
    checkClearance(b, key);
    if (lateral && (b.kyy > 0 || b.kzz > 0 || b.cyy > 0 || b.czz > 0 || b.kyz != 0 || b.kzy != 0)) {
      Eigen::Matrix2d k, c;
      k << b.kyy, b.kyz, b.kzy, b.kzz;
      c << b.cyy, b.cyz, b.czy, b.czz;
      std::vector<PointJacobian> parts{detail::translationJacobian(*this, body, 1.0, dx)};
      if (other >= 0) {
        detail::requireSameFrame(*this, body, other, key);
        parts.push_back(detail::translationJacobian(*this, other, -1.0, other_dx));
      }
      add(b.name, "bearing", parts, k, c);
      if (b.radial_clearance > 0.0) {
        clearance_bearings_.push_back(
            {b.name, elements_.back().dofs, elements_.back().jacobian, b.kyy, b.radial_clearance});
      }
    }
    // Axial spring on the axis, tilt springs about y and z (full DOFs).
    auto relative = [&](int offset) {
      std::vector<int> dofs{bodies_[body].first_dof + offset};
      if (other >= 0) dofs.push_back(bodies_[other].first_dof + offset);
      return dofs;
    };
    const std::vector<double> signs =
        other >= 0 ? std::vector<double>{1.0, -1.0} : std::vector<double>{1.0};
    if (full && (b.k_axial > 0 || b.c_axial > 0)) {
      add_torsion(b.name + ".axial", "bearing", relative(3), signs, b.k_axial, b.c_axial);
    }
    if (full && (b.k_tilt > 0 || b.c_tilt > 0)) {
      add_torsion(b.name + ".tilt_y", "bearing", relative(4), signs, b.k_tilt, b.c_tilt);
      add_torsion(b.name + ".tilt_z", "bearing", relative(5), signs, b.k_tilt, b.c_tilt);
    }
    if (b.k_torsion > 0 || b.c_torsion > 0) {
      std::vector<int> dofs{rotationDof(body)};
      std::vector<double> signs{1.0};
      if (other >= 0) dofs.push_back(rotationDof(other)), signs.push_back(-1.0);
      add_torsion(b.name + ".torsion", other >= 0 ? "coupling" : "support", dofs, signs,
                  b.k_torsion, b.c_torsion);
    }
  }
  for (const auto& c : spec_.couplings) {
    const std::string key = "couplings." + c.name;
    if (c.shaft_a == c.shaft_b) {
      throw InputError(key + ".shafts", "\"" + c.shaft_a + "\"", "two different shafts");
    }
    const auto [a, b] = detail::couplingBodies(*this, c);
    requireNonNegative(c.c_torsion, key + ".c_torsion", "N m s/rad");
    requireNonNegative(c.k_lateral, key + ".k_lateral", "N/m");
    requireNonNegative(c.c_lateral, key + ".c_lateral", "N s/m");
    if (!(c.k_torsion > 0.0)) {
      throw InputError(key + ".k_torsion", fmt::format("{:g} N m/rad", c.k_torsion),
                       "a torsional stiffness > 0 (a coupling transmits torque)");
    }
    add_torsion(c.name, "coupling", {rotationDof(a), rotationDof(b)}, {1.0, -1.0}, c.k_torsion,
                c.c_torsion);
    if (lateral && (c.k_lateral > 0 || c.c_lateral > 0)) {
      detail::requireSameFrame(*this, a, b, key);
      add(c.name + ".lateral", "coupling",
          {detail::translationJacobian(*this, a, 1.0), detail::translationJacobian(*this, b, -1.0)},
          c.k_lateral * Eigen::Matrix2d::Identity(), c.c_lateral * Eigen::Matrix2d::Identity());
    }
  }
  // Planet pins: the planet centre against the carrier's point at the planet's position,
  // radial and tangential springs (Lin & Parker 1999: k_p both ways); with full DOFs also an
  // axial and two tilting springs, the carrier's point in the planet's plane.
  if (lateral) {
    for (std::size_t p = 0; p < bodies_.size(); ++p) {
      const TrainBody& planet = bodies_[p];
      if (planet.kind != TrainBodyKind::kPlanet) continue;
      const PlanetaryStageSpec& st = spec_.stages[planet.stage];
      const std::string key = "planetary." + st.name;
      requireNonNegative(st.pin_radial_stiffness, key + ".pin_radial_stiffness", "N/m");
      requireNonNegative(st.pin_tangential_stiffness, key + ".pin_tangential_stiffness", "N/m");
      requireNonNegative(st.pin_damping, key + ".pin_damping", "N s/m");
      if (!(st.pin_radial_stiffness > 0.0 && st.pin_tangential_stiffness > 0.0)) {
        throw InputError(key + ".pin_radial_stiffness",
                         fmt::format("{:g} N/m", st.pin_radial_stiffness),
                         "pin stiffnesses > 0 radially and tangentially with planar or full "
                         "DOFs");
      }
      const int carrier = detail::carrierBody(*this, planet.stage);
      const Eigen::Vector2d r = planet.centre - bodies_[carrier].centre;
      const Eigen::Vector2d er = r.normalized(), et(-er.y(), er.x());
      const Eigen::Matrix2d k = st.pin_radial_stiffness * er * er.transpose() +
                                st.pin_tangential_stiffness * et * et.transpose();
      const double dx = planet.axial - bodies_[carrier].axial;  // 0 unless full DOFs
      add(planet.name + ".pin", "pin",
          {detail::translationJacobian(*this, static_cast<int>(p), 1.0),
           detail::pointJacobian(*this, carrier, planet.centre, -1.0, dx)},
          k, st.pin_damping * Eigen::Matrix2d::Identity());
      if (!full) continue;
      const double mean = 0.5 * (st.pin_radial_stiffness + st.pin_tangential_stiffness);
      const double b = st.planet.face_width;
      const double k_axial = st.pin_axial_stiffness >= 0.0 ? st.pin_axial_stiffness : mean;
      const double k_tilt =
          st.pin_tilt_stiffness >= 0.0 ? st.pin_tilt_stiffness : mean * b * b / 12.0;
      requireNonNegative(k_axial, key + ".pin_axial_stiffness", "N/m");
      requireNonNegative(k_tilt, key + ".pin_tilt_stiffness", "N m/rad");
      // Axial: u_x,p − (u_x,c + θ_y,c r_z − θ_z,c r_y), the carrier's point at (dx, r_y, r_z).
      const int pd = planet.first_dof, cd = bodies_[carrier].first_dof;
      add_torsion(planet.name + ".pin_axial", "pin", {pd + 3, cd + 3, cd + 4, cd + 5},
                  {1.0, -1.0, -r.y(), r.x()}, k_axial, st.pin_damping);
      add_torsion(planet.name + ".pin_tilt_y", "pin", {pd + 4, cd + 4}, {1.0, -1.0}, k_tilt,
                  st.pin_damping * b * b / 12.0);
      add_torsion(planet.name + ".pin_tilt_z", "pin", {pd + 5, cd + 5}, {1.0, -1.0}, k_tilt,
                  st.pin_damping * b * b / 12.0);
    }
  }
}

void GearTrainModel::assemble() {
  const int n = dof_count_;
  const bool planar = spec_.dofs == TrainDofs::kPlanar;
  M_ = Eigen::MatrixXd::Zero(n, n);
  K_ = M_, C_ = M_, G_ = M_, Komega_ = M_, Kmesh_ = M_;
  F0_ = Eigen::VectorXd::Zero(n);
  const bool full = spec_.dofs == TrainDofs::kFull;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const TrainBody& body = bodies_[b];
    M_(rotationDof(b), rotationDof(b)) = body.polar_inertia;
    if (!planar && !full) continue;
    const int y = body.first_dof;
    M_(y, y) = M_(y + 1, y + 1) = body.mass;
    if (full) {
      // Axial mass, diametral inertia and the disk's gyroscopic moments: with the spin ω = r Ω
      // about +x, I_d θ̈_y + ω I_p θ̇_z = M_y and I_d θ̈_z − ω I_p θ̇_y = M_z (the spin axis
      // x̂ + θ × x̂ = (1, θ_z, −θ_y) carries the angular momentum I_p ω).
      M_(y + 3, y + 3) = body.mass;
      M_(y + 4, y + 4) = M_(y + 5, y + 5) = body.diametral_inertia;
      G_(y + 4, y + 5) += body.speed_ratio * body.polar_inertia;
      G_(y + 5, y + 4) -= body.speed_ratio * body.polar_inertia;
    }
    const int frame = rotatingFrame(static_cast<int>(b));
    if (frame >= 0) {
      // Carrier frame turning at Ω_c = r_c Ω: m(ü + 2Ω_c J u̇ − Ω_c² u), J = [[0, −1], [1, 0]]
      // (Lin & Parker 1999 eq. 1; Ω_c about +x, (y, z) the carrier's axes).
      const double rc = detail::carrierSpeedRatio(*this, spec_, frame);
      G_(y, y + 1) -= 2.0 * body.mass * rc;
      G_(y + 1, y) += 2.0 * body.mass * rc;
      if (body.kind != TrainBodyKind::kPlanet) {
        Komega_(y, y) -= body.mass * rc * rc;
        Komega_(y + 1, y + 1) -= body.mass * rc * rc;
      } else {
        detail::addPlanetCentripetal(*this, static_cast<int>(b), rc, Komega_);
      }
    }
  }
  assembleBeams();
  Eigen::MatrixXd K_structure = Eigen::MatrixXd::Zero(n, n);
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    const auto& dofs = elements_[e].dofs;
    for (std::size_t i = 0; i < dofs.size(); ++i) {
      for (std::size_t j = 0; j < dofs.size(); ++j) {
        K_structure(dofs[i], dofs[j]) += elements_[e].stiffness(i, j);
        C_(dofs[i], dofs[j]) += element_damping_[e](i, j);
      }
    }
  }
  K_ = K_structure;
  for (const TrainMesh& m : meshes_) {
    const Eigen::VectorXd v = meshVector(static_cast<int>(&m - meshes_.data()));
    Kmesh_ += m.mean_stiffness * v * v.transpose();
    C_ += m.damping * v * v.transpose();
  }
  C_ += spec_.mass_proportional_damping * M_ + spec_.stiffness_proportional_damping * (K_ + Kmesh_);
  detail::applyOperatingLoads(*this, spec_, F0_, output_torque_);
  if (spec_.gravity != 0.0) {
    if (!std::isfinite(spec_.gravity) || spec_.dofs == TrainDofs::kTorsional) {
      throw InputError("gearbox.gravity", fmt::format("{:g} m/s^2", spec_.gravity),
                       "a finite value with planar or full DOFs (0 with torsional DOFs)");
    }
    // F = −g M e_z: the weight of every lumped and distributed mass along −z.
    Eigen::VectorXd ez = Eigen::VectorXd::Zero(n);
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
      if (rotatingFrame(static_cast<int>(b)) >= 0) {
        throw InputError("gearbox.gravity", fmt::format("{:g} m/s^2", spec_.gravity),
                         "0 with a planetary stage formulated in its rotating carrier frame "
                         "(gravity would turn in it); set carrier_frame_terms = false");
      }
      ez(bodies_[b].first_dof + 1) = 1.0;
    }
    F0_ -= spec_.gravity * (M_ * ez);
  }
}

int GearTrainModel::rotatingFrame(int body) const {
  const int stage = bodies_[body].stage;
  return spec_.dofs == TrainDofs::kPlanar && stage >= 0 && spec_.stages[stage].carrier_frame_terms
             ? stage
             : -1;
}

Eigen::VectorXd GearTrainModel::meshVector(int mesh) const {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(dof_count_);
  const TrainMesh& m = meshes_[mesh];
  for (std::size_t i = 0; i < m.dofs.size(); ++i) v(m.dofs[i]) += m.gradient[i];
  return v;
}

Eigen::MatrixXd GearTrainModel::nonlinearVectors() const {
  const int r = static_cast<int>(meshes_.size());
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(dof_count_, r + 2 * clearance_bearings_.size());
  for (int m = 0; m < r; ++m) W.col(m) = meshVector(m);
  for (std::size_t b = 0; b < clearance_bearings_.size(); ++b) {
    const TrainClearanceBearing& cb = clearance_bearings_[b];
    for (std::size_t i = 0; i < cb.dofs.size(); ++i) {
      W.block(cb.dofs[i], r + 2 * b, 1, 2) += cb.jacobian.col(i).transpose();
    }
  }
  return W;
}

Eigen::MatrixXd GearTrainModel::meanStiffnessAt(double input_speed) const {
  return K_ + Kmesh_ + input_speed * input_speed * Komega_;
}

Eigen::MatrixXd GearTrainModel::dampingAt(double input_speed) const {
  return C_ + input_speed * G_;
}

}  // namespace geardyn
