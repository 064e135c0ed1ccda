/// Transient duration and undamped modes of a gear train (see train_transient.h).

#include "geardyn/solvers/train_transient.h"

#include <algorithm>
#include <cmath>

namespace geardyn {

namespace {
constexpr double kUndamped = 1e-9;  // |ζ| below this is round-off of an undamped mode
// Each mode the meshes excite decays by this; a mode whose relative start √s_j is below it is
// not excited (train_transient.h).
constexpr double kDecay = 1e-6;

/// √s_j: mode j's starting amplitude relative to the modes the meshes drive (TrainTransient).
/// With unbalances, runouts or prescribed bearing displacements (GearTrainModel::excitations())
/// every mode counts as excited (1): conservative, the duration waits for the slowest one.
double meshExcitation(const GearTrainModel& model, const TrainMode& mode) {
  if (!model.excitations().empty()) return 1.0;
  double share = 0.0;
  for (double s : mode.mesh_strain_energy) share += s;
  return std::sqrt(std::max(share, 0.0));
}
}  // namespace

std::vector<TrainUndampedMode> trainUndampedModes(const GearTrainModel& model,
                                                  const std::vector<TrainMode>& modes) {
  constexpr double kShare = 0.1;  // elements named for an undamped mode
  double highest = 0.0;
  for (const TrainMode& m : modes) highest = std::max(highest, m.frequency);
  std::vector<TrainUndampedMode> out;
  for (const TrainMode& mode : modes) {
    if (mode.divergent || mode.frequency <= 1e-6 * highest) continue;  // rigid or divergent
    if (std::abs(mode.damping_ratio) > kUndamped) continue;
    TrainUndampedMode u{mode.frequency, meshExcitation(model, mode) > kDecay, {}, {}};
    for (std::size_t e = 0; e < model.elements().size(); ++e) {
      if (mode.element_strain_energy[e] >= kShare) u.elements.push_back(model.elements()[e].name);
    }
    for (std::size_t m = 0; m < model.meshes().size(); ++m) {
      if (mode.mesh_strain_energy[m] >= kShare) u.meshes.push_back(model.meshes()[m].name);
    }
    out.push_back(std::move(u));
  }
  return out;
}

TrainTransient trainTransient(const GearTrainModel& model, double input_speed) {
  const std::vector<TrainMode> modes = trainModes(model, input_speed, {0, -1.0, false});
  TrainTransient t;
  t.undamped = trainUndampedModes(model, modes);
  for (const TrainUndampedMode& u : t.undamped) {
    if (u.excited) t.decay_time = HUGE_VAL;
  }
  for (const TrainMode& mode : modes) {
    const double start = meshExcitation(model, mode);
    const double sigma = -mode.eigenvalue.real();
    if (mode.divergent || std::abs(mode.damping_ratio) <= kUndamped || start <= kDecay ||
        !(sigma > 0.0)) {
      continue;
    }
    const double time = -std::log(kDecay) / sigma;
    if (time > t.decay_time) {
      t.decay_time = time;
      t.slowest_frequency = mode.frequency;
      t.slowest_damping_ratio = mode.damping_ratio;
    }
  }
  return t;
}

}  // namespace geardyn
