#include "geardyn/geometry/gear_mounting.h"

#include <cmath>

namespace geardyn {

double rootDiameter(const GearSpec& gear) {
  return gear.teeth * gear.normal_module / std::cos(gear.helix_angle) -
         2.0 * (gear.dedendum_coefficient - gear.profile_shift) * gear.normal_module;
}

}  // namespace geardyn
