/// GearTrainModel::withParameters: a changed mesh stiffness or operating point reassembles only
/// what depends on it (issue 39: a design loop changes one stiffness and recomputes the modes).
///
/// What depends on what (the assembly in gear_train_model.cpp and train_meshes.cpp):
/// - a mesh's stiffness model k(φ): its mean k̄ (summarizeMeshStiffness, as setMeshModel), its
///   dashpot c = 2ζ √(k̄ m_e) when it follows from a damping ratio (else ζ = c / 2√(k̄ m_e)),
///   Σ k̄ v vᵀ and C (the dashpot and the stiffness-proportional β Σ k̄ v vᵀ): rank-one updates
///   (k̄_new − k̄_old) v vᵀ with the mesh's unchanged v. Its loaded flank follows from the
///   torsional load path, which depends on every k̄ in a statically indeterminate train: it is
///   checked below, and a change of flank rebuilds the train;
/// - the operating point's speed and torque: F₀ (the input and output torques); the speed is
///   only read through inputSpeed(). The torque's sign (or zero) decides the loaded flanks.

#include <fmt/format.h>

#include <cmath>
#include <map>

#include "geardyn/error.h"
#include "geardyn/stiffness/mesh_stiffness_summary.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn {
namespace {

/// The spec's stiffness model of mesh `index` (fixed-axis meshes first, in the spec's order,
/// then each planet's sun and ring meshes: createMeshes), and its key for messages.
const std::shared_ptr<const MeshStiffness>& specStiffness(const GearTrainSpec& spec,
                                                          const TrainMesh& m, std::size_t index,
                                                          std::string& key) {
  if (m.stage < 0) {
    key = "meshes." + spec.meshes[index].name + ".stiffness";
    return spec.meshes[index].stiffness;
  }
  const PlanetaryStageSpec& st = spec.stages[m.stage];
  const bool sun = m.kind == TrainMeshKind::kSunPlanet;
  key = "planetary." + st.name + (sun ? ".sun_planet" : ".ring_planet") + ".stiffness";
  return sun ? st.sun_planet_stiffness : st.ring_planet_stiffness;
}

/// Per mesh: +1 loaded on its flank of the model, −1 on the other one, 0 unloaded (the
/// classification of orientMeshesByLoad, on the model's oriented lines of action).
std::vector<int> flanks(const std::vector<double>& force) {
  double largest = 0.0;
  for (double f : force) largest = std::max(largest, std::abs(f));
  std::vector<int> out(force.size(), 0);
  for (std::size_t i = 0; i < force.size(); ++i) {
    if (largest == 0.0 || std::abs(force[i]) <= 1e-9 * largest) continue;
    out[i] = force[i] < 0.0 ? -1 : 1;
  }
  return out;
}

}  // namespace

GearTrainModel GearTrainModel::withParameters(GearTrainSpec spec) const {
  GearTrainModel out(*this);
  out.spec_ = std::move(spec);
  const OperatingPoint& was = spec_.operating;
  const OperatingPoint& now = out.spec_.operating;
  bool meshes_changed = false;
  std::map<const MeshStiffness*, double> means;  // one summary per new model (planets share it)
  for (std::size_t i = 0; i < meshes_.size(); ++i) {
    std::string key;
    const auto& k = specStiffness(out.spec_, meshes_[i], i, key);
    if (k == meshes_[i].stiffness) continue;
    if (!k) throw InputError(key, "", "a mesh-stiffness model");
    auto [it, fresh] = means.try_emplace(k.get(), 0.0);
    if (fresh) it->second = summarizeMeshStiffness(*k, 0).mean;
    const double mean = it->second;
    if (!(mean > 0.0) || !std::isfinite(mean)) {
      throw InputError(key, fmt::format("{:g} N/m mean", mean),
                       "a mesh stiffness with a positive mean");
    }
    TrainMesh& m = out.meshes_[i];
    const bool given = m.gear_a >= 0 && out.spec_.meshes[i].damping.has_value();
    const double root = std::sqrt(mean * m.equivalent_mass);
    double damping = m.damping;
    if (given) {
      m.damping_ratio = m.equivalent_mass > 0.0 ? m.damping / (2.0 * root) : 0.0;
    } else {
      damping = 2.0 * m.damping_ratio * root;
    }
    const Eigen::VectorXd v = meshVector(static_cast<int>(i));
    const double dk = mean - m.mean_stiffness;
    const double dc = (damping - m.damping) + out.spec_.stiffness_proportional_damping * dk;
    out.Kmesh_.noalias() += dk * v * v.transpose();
    if (dc != 0.0) out.C_.noalias() += dc * v * v.transpose();
    m.stiffness = k;
    m.mean_stiffness = mean;
    m.damping = damping;
    meshes_changed = true;
  }
  const bool torque_changed = now.input_torque != was.input_torque;
  // Unloaded before and after (a free-vibration study): every mesh force is zero whatever the
  // stiffnesses, so no flank changes (the two torsional solves cost ~2 µs of a ~10 µs set).
  const bool unloaded = now.input_torque == 0.0 && was.input_torque == 0.0;
  if ((meshes_changed || torque_changed) && !unloaded &&
      flanks(out.torsionalMeshForces()) != flanks(torsionalMeshForces())) {
    return GearTrainModel(std::move(out.spec_), memory_limit_);
  }
  if (torque_changed || now.input_speed != was.input_speed) out.assembleLoads();
  return out;
}

}  // namespace geardyn
