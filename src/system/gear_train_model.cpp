/// Gear-train assembly: bodies and matrices (gear_train_model.h). The meshes are built in
/// train_meshes.cpp, the elements (bearings, couplings, planet pins) in train_elements.cpp.

#include "geardyn/system/gear_train_model.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "geardyn/error.h"
#include "geardyn/system/detail/train_building.h"
#include "geardyn/system/train_housing.h"
#include "geardyn/system/train_tooth_pairs.h"

namespace geardyn {
namespace {

using detail::PointJacobian;
using detail::requireNonNegative;

/// Every name is used once: shafts, gears, meshes, bearings, couplings, stages and disks share
/// one name space.
void checkUniqueNames(const GearTrainSpec& spec) {
  std::set<std::string> names;
  auto unique = [&](const std::string& name, const std::string& key) {
    if (name.empty()) throw InputError(key, "\"\"", "a non-empty name");
    if (!names.insert(name).second) {
      throw InputError(key, "\"" + name + "\"",
                       "a name used once: shafts, gears, meshes, bearings, couplings and stages "
                       "share one name space");
    }
  };
  for (const auto& s : spec.shafts) unique(s.name, "shafts." + s.name);
  for (const auto& g : spec.gears) unique(g.name, "gears." + g.name);
  for (const auto& m : spec.meshes) unique(m.name, "meshes." + m.name);
  for (const auto& b : spec.bearings) unique(b.name, "bearings." + b.name);
  for (const auto& c : spec.couplings) unique(c.name, "couplings." + c.name);
  for (const auto& st : spec.stages) unique(st.name, "planetary." + st.name);
  for (const auto& d : spec.disks) unique(d.name, "disks." + d.name);
}

/// A shaft's own mass, inertias, axial offset and beam damping are physical.
void checkShaftSpec(const TrainShaftSpec& shaft, const std::string& key) {
  requireNonNegative(shaft.mass, key + ".mass", "kg");
  requireNonNegative(shaft.polar_inertia, key + ".polar_inertia", "kg m^2");
  requireNonNegative(shaft.diametral_inertia, key + ".diametral_inertia", "kg m^2");
  if (!std::isfinite(shaft.axial_offset)) {
    throw InputError(key + ".axial_offset", fmt::format("{:g} m", shaft.axial_offset),
                     "a finite position");
  }
  if (!(shaft.stiffness_proportional_damping >= 0.0) ||
      !std::isfinite(shaft.stiffness_proportional_damping) ||
      (!shaft.flexible && shaft.stiffness_proportional_damping != 0.0)) {
    throw InputError(key + ".stiffness_proportional_damping",
                     fmt::format("{:g} s", shaft.stiffness_proportional_damping),
                     shaft.flexible ? "a finite β >= 0 s"
                                    : "0 on a rigid shaft (it damps beam elements: flexible = "
                                      "true)");
  }
}

/// The planets of stage s: one body each, in the stage's carrier frame (full DOFs: in the sun
/// gear's mid-face plane, the lumped part a disk of the face width unless its diametral inertia
/// is given).
std::vector<TrainBody> planetBodies(const GearTrainSpec& spec, std::size_t s,
                                    std::vector<std::string>& warnings) {
  const bool full = spec.dofs == TrainDofs::kFull;
  const PlanetaryStageSpec& st = spec.stages[s];
  std::vector<TrainBody> bodies;
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
    const int sun = detail::gearIndexOf(spec, st.sun, key + ".sun");
    const TrainGearSpec& g = spec.gears[sun];
    axial = spec.shafts[detail::shaftIndexOf(spec, g.shaft, "gears." + g.name + ".shaft")]
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
    bodies.push_back(body);
  }
  if (full && st.carrier_frame_terms) {
    warnings.push_back(fmt::format(
        "{}: with gearbox.dofs = \"full\" the stage is the fixed-frame lumped model (planets "
        "held at their positions); the carrier-frame Coriolis and centripetal terms are "
        "formulated for planar DOFs (set carrier_frame_terms = false to silence this)",
        key));
  }
  return bodies;
}

/// A rigid body (a rigid shaft's, a planet's) has the inertias its DOFs need, naming the key
/// that would give them.
void checkRigidBodyInertia(const GearTrainSpec& spec, const TrainBody& body) {
  if (!(body.polar_inertia > 0.0)) {
    throw InputError(body.kind == TrainBodyKind::kPlanet
                         ? "planetary." + spec.stages[body.stage].name + ".planet_inertia"
                         : "shafts." + body.name + ".polar_inertia",
                     "0 kg m^2",
                     "a body needs a polar inertia > 0 (its own, its sections' or its gears')");
  }
  if (spec.dofs != TrainDofs::kTorsional && !(body.mass > 0.0)) {
    throw InputError(body.kind == TrainBodyKind::kPlanet
                         ? "planetary." + spec.stages[body.stage].name + ".planet_mass"
                         : "shafts." + body.name + ".mass",
                     "0 kg", "planar and full DOFs need a mass > 0 on every body");
  }
  if (spec.dofs == TrainDofs::kFull && !(body.diametral_inertia > 0.0)) {
    throw InputError(body.kind == TrainBodyKind::kPlanet
                         ? "planetary." + spec.stages[body.stage].name + ".planet_diametral_inertia"
                         : "shafts." + body.name + ".diametral_inertia",
                     "0 kg m^2",
                     "full DOFs need a diametral inertia > 0 on every rigid shaft (its own, "
                     "its sections', gears' or disks')");
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

double TrainMesh::nonlinearForce(double phase, double y, double* slope) const {
  if (!contact.tooth_pairs) {
    double s = 1.0;
    const double k = stiffness->stiffness(phase), g = contactDeflection(y, &s);
    if (slope) *slope = k * s;
    return k * g;
  }
  ToothPairTable table;  // Σ_j k_j max(0, y − g_j) at this one phase
  table.tabulate(*contact.tooth_pairs, &phase, 1);
  return table.force(0, y, slope);
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
  if (spec_.housing) attachHousing();
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
  if (housing_first_dof_ >= 0 && i >= housing_first_dof_) {
    return housingDofName(spec_.housing->reduced, i - housing_first_dof_);
  }
  const int per = dofsPerBody();
  const int body = i / per;
  static constexpr const char* kNames[6] = {"y", "z", "theta", "x", "theta_y", "theta_z"};
  return bodies_[body].name + "." + (per == 1 ? "theta" : kNames[i % per]);
}

void GearTrainModel::buildBodies() {
  if (spec_.shafts.empty()) throw InputError("shafts", "", "at least one shaft");
  checkUniqueNames(spec_);
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
    checkShaftSpec(shaft, key);
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
    for (TrainBody& body : planetBodies(spec_, s, warnings_)) bodies_.push_back(std::move(body));
  }
  const int per = dofsPerBody();
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    bodies_[b].first_dof = static_cast<int>(b) * per;
    const int shaft = bodies_[b].shaft;
    if (shaft >= 0 && spec_.shafts[shaft].flexible) continue;  // the beams carry mass
    checkRigidBodyInertia(spec_, bodies_[b]);
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

void GearTrainModel::assemble() {
  const int n = dof_count_;
  const bool planar = spec_.dofs == TrainDofs::kPlanar;
  M_ = Eigen::MatrixXd::Zero(n, n);
  K_ = M_, C_ = M_, G_ = M_, Komega_ = M_, Kmesh_ = M_;
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
  assembleLoads();
}

void GearTrainModel::assembleLoads() {
  const int n = dof_count_;
  F0_ = Eigen::VectorXd::Zero(n);
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
  excitations_ = buildTrainExcitation(*this, F0_);
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
  int columns = r;
  // 2 coordinates per bearing; 5 for a full-DOF rolling bearing's full law (bearing_law.h).
  for (const TrainClearanceBearing& cb : clearance_bearings_) columns += cb.jacobian.rows();
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(dof_count_, columns);
  for (int m = 0; m < r; ++m) W.col(m) = meshVector(m);
  int first = r;
  for (const TrainClearanceBearing& cb : clearance_bearings_) {
    const auto width = cb.jacobian.rows();
    for (std::size_t i = 0; i < cb.dofs.size(); ++i) {
      W.block(cb.dofs[i], first, 1, width) += cb.jacobian.col(i).transpose();
    }
    first += width;
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
