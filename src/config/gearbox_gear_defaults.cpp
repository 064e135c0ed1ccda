#include "geardyn/config/detail/gearbox_gear_defaults.h"

#include <algorithm>

#include "geardyn/geometry/gear_mounting.h"

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
      return diameter > 0.0 && diameter < rootDiameter(gear.gear) ? diameter : 0.0;
    }
    start = end;
  }
  return 0.0;
}

}  // namespace geardyn::config::detail
