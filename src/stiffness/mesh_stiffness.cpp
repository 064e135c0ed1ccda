#include "geardyn/stiffness/mesh_stiffness.h"

#include <cmath>
#include <numbers>

namespace geardyn {

double MeshStiffness::pairStiffness(double /*phase*/, int /*pair*/) const {
  return 0.0;
}

double meshPhaseFromRollAngle(double roll_angle, int pinion_teeth) {
  return roll_angle * pinion_teeth / (2.0 * std::numbers::pi);
}

double rollAngleFromMeshPhase(double phase, int pinion_teeth) {
  return phase * 2.0 * std::numbers::pi / pinion_teeth;
}

double wrapPhase(double phase) {
  const double wrapped = phase - std::floor(phase);
  return wrapped >= 1.0 ? 0.0 : wrapped;  // floor rounding can leave exactly 1.0
}

}  // namespace geardyn
