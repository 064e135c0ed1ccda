#include "geardyn/config/detail/gearbox_gear_defaults.h"

#include <algorithm>
#include <cmath>

namespace geardyn::config::detail {

double defaultBoreDiameter(const TrainGearSpec& gear, const std::vector<TrainShaftSpec>& shafts) {
  const auto shaft = std::find_if(shafts.begin(), shafts.end(),
                                  [&](const TrainShaftSpec& s) { return s.name == gear.shaft; });
  if (shaft == shafts.end() || shaft->section_lengths.empty() || shaft->outer_diameters.empty()) {
    return 0.0;
  }
  double start = 0.0;
  for (std::size_t i = 0; i < shaft->section_lengths.size(); ++i) {
    const double end = start + shaft->section_lengths[i];
    if (gear.position >= start && gear.position <= end) {
      const auto& od = shaft->outer_diameters;
      const double diameter = od.size() == 1 ? od[0] : i < od.size() ? od[i] : 0.0;
      const GearSpec& g = gear.gear;
      const double root_diameter =
          g.teeth * g.normal_module / std::cos(g.helix_angle) -
          2.0 * (g.dedendum_coefficient - g.profile_shift) * g.normal_module;
      return diameter > 0.0 && diameter < root_diameter ? diameter : 0.0;
    }
    start = end;
  }
  return 0.0;
}

}  // namespace geardyn::config::detail
