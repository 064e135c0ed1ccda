/// Transient duration and undamped modes of a gear train (see train_transient.h).

#include "geardyn/solvers/train_transient.h"

#include <algorithm>
#include <cmath>
#include <complex>

namespace geardyn {

namespace {
constexpr double kUndamped = 1e-9;  // |ζ| below this is round-off of an undamped mode
// Each mode the forcing excites decays by this; a mode whose relative start (modalExcitation) is
// below it is not excited (train_transient.h).
constexpr double kDecay = 1e-6;

/// Mode j's starting amplitude relative to the modes the forcing drives (TrainTransient): √s_j
/// from the meshes (s_j its strain-energy share in them) and, for every other excitation term
/// (unbalances, runouts, prescribed bearing displacements: GearTrainModel::excitations()), the
/// cosine |φ_jᴴ P| / (‖P‖ max|φ_j|) between the mode shape and each nonzero part P (S, D, U of
/// train_excitation.h) of the term's force pattern: a mode orthogonal to every force pattern
/// to round-off (a Jeffcott rotor's torsional and axial modes under an unbalance) is not
/// excited by it, whatever the speed.
double modalExcitation(const GearTrainModel& model, const TrainMode& mode) {
  double share = 0.0;
  for (double s : mode.mesh_strain_energy) share += s;
  double start = std::sqrt(std::max(share, 0.0));
  const double largest = mode.shape.cwiseAbs().maxCoeff();
  if (!(largest > 0.0)) return start;
  for (const TrainExcitationTerm& term : model.excitations()) {
    for (const Eigen::VectorXcd* part : {&term.stiffness, &term.damping, &term.inertia}) {
      const double size = part->size() > 0 ? part->norm() : 0.0;
      if (!(size > 0.0)) continue;
      std::complex<double> force = 0.0;
      for (std::size_t i = 0; i < term.dofs.size(); ++i)
        force += std::conj(mode.shape(term.dofs[i])) * (*part)(static_cast<Eigen::Index>(i));
      start = std::max(start, std::abs(force) / (size * largest));
    }
  }
  return start;
}
}  // namespace

TrainUndampedMode dampingPlacesOf(const GearTrainModel& model, const TrainMode& mode,
                                  bool excited) {
  constexpr double kShare = 0.1;  // elements and meshes named for a mode
  TrainUndampedMode u{mode.frequency, excited, {}, {}};
  for (std::size_t e = 0; e < model.elements().size(); ++e) {
    if (mode.element_strain_energy[e] >= kShare) u.elements.push_back(model.elements()[e].name);
  }
  for (std::size_t m = 0; m < model.meshes().size(); ++m) {
    if (mode.mesh_strain_energy[m] >= kShare) u.meshes.push_back(model.meshes()[m].name);
  }
  return u;
}

std::vector<TrainUndampedMode> trainUndampedModes(const GearTrainModel& model,
                                                  const std::vector<TrainMode>& modes) {
  double highest = 0.0;
  for (const TrainMode& m : modes) highest = std::max(highest, m.frequency);
  std::vector<TrainUndampedMode> out;
  for (const TrainMode& mode : modes) {
    if (mode.divergent || mode.frequency <= 1e-6 * highest) continue;  // rigid or divergent
    if (std::abs(mode.damping_ratio) > kUndamped) continue;
    out.push_back(dampingPlacesOf(model, mode, modalExcitation(model, mode) > kDecay));
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
    const double start = modalExcitation(model, mode);
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
