/// The FE rotor file's modes through the gear train's modal solver (fe_rotor_modes.h).

#include "geardyn/analysis/fe_rotor_modes.h"

#include <algorithm>
#include <numbers>

#include "geardyn/config/fe_rotor_gearbox.h"

namespace geardyn::analysis {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
bool axialMode(const FeRotorTrain& train, const TrainMode& mode) {
  return train.without_axial && mode.axial_fraction > 0.5;
}

TrainModalOptions options(int modes, double max_damping_ratio) {
  TrainModalOptions o;
  o.modes = modes;
  o.max_damping_ratio = max_damping_ratio;
  o.keep_rigid = false;
  return o;
}

/// The axial DOFs the train has and the file has not (0 with model.axial).
int extraAxialDofs(const FeRotorTrain& train) {
  return train.without_axial ? static_cast<int>(train.model->bodies().size()) : 0;
}

}  // namespace

FeRotorTrain feRotorTrain(const config::Config& config, const FeRotorModel& fe,
                          std::vector<std::string>& warnings) {
  FeRotorTrain t;
  t.model = std::make_unique<GearTrainModel>(config::feRotorGearTrain(config, warnings));
  t.without_axial = !fe.axial();
  t.train_dof = fe.trainDofs();  // the translated train is fe's: the same DOFs
  return t;
}

std::vector<TrainMode> feRotorModes(const FeRotorTrain& train, double pinion_speed, int modes,
                                    double max_damping_ratio) {
  std::vector<TrainMode> found = trainModes(
      *train.model, pinion_speed, options(modes + extraAxialDofs(train), max_damping_ratio));
  found.erase(
      std::remove_if(found.begin(), found.end(),
                     [&](const TrainMode& m) { return m.divergent || axialMode(train, m); }),
      found.end());
  if (static_cast<int>(found.size()) > modes) found.resize(modes);
  return found;
}

std::vector<TrainOrderLine> feRotorOrderLines(const FeRotorModel& fe) {
  return {{"1x pinion", 1.0 / kTwoPi},
          {"1x gear", std::abs(fe.spinRatio(1)) / kTwoPi},
          {"mesh", static_cast<double>(fe.pinionTeeth()) / kTwoPi}};
}

TrainCampbell feRotorCampbell(const FeRotorTrain& train, const FeRotorModel& fe,
                              const std::vector<double>& speeds, int modes,
                              double max_damping_ratio) {
  // The tracks start from the lowest modes at the first speed: as many more as there are
  // uncoupled axial modes among them, which are then dropped.
  int extra = 0;
  if (train.without_axial && !speeds.empty()) {
    int kept = 0;
    for (const TrainMode& m :
         trainModes(*train.model, speeds.front(),
                    options(modes + extraAxialDofs(train), max_damping_ratio))) {
      if (m.divergent) continue;
      if (kept == modes) break;
      axialMode(train, m) ? ++extra : ++kept;
    }
  }
  TrainCampbell d = trainCampbell(*train.model, speeds, options(modes + extra, max_damping_ratio),
                                  feRotorOrderLines(fe));
  if (extra == 0 || d.modes.empty()) return d;
  std::vector<int> index(d.modes.front().size(), -1);  // old track → new track (−1: dropped)
  int next = 0;
  for (std::size_t j = 0; j < index.size(); ++j) {
    if (!axialMode(train, d.modes.front()[j]) && next < modes) index[j] = next++;
  }
  for (auto& row : d.modes) {
    std::vector<TrainMode> kept;
    for (std::size_t j = 0; j < row.size(); ++j)
      if (index[j] >= 0) kept.push_back(std::move(row[j]));
    row = std::move(kept);
  }
  std::vector<TrainCriticalSpeed> critical;
  for (TrainCriticalSpeed c : d.critical_speeds) {
    if (index[c.mode] < 0) continue;
    c.mode = index[c.mode];
    critical.push_back(std::move(c));
  }
  d.critical_speeds = std::move(critical);
  return d;
}

}  // namespace geardyn::analysis
