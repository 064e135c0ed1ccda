#pragma once
/// \file
/// Reference rolling bearings and the two-stage reducer on them (tests and benchmarks):
/// 6208-like deep-groove ball bearings on the input shaft, 30208-like tapered roller bearings
/// on the intermediate and output shafts.

#include <memory>

#include "geardyn/contact/rolling_bearing.h"
#include "system/sample_trains.h"

namespace geardyn::testing {

/// 6208-like deep-groove ball bearing (9 × 12.7 mm on 60 mm, f 0.52/0.53, s_r 15 µm).
inline std::shared_ptr<const RollingBearing> deepGroove6208() {
  RollingBearingGeometry g;
  g.elements = 9;
  g.element_diameter = 12.7e-3;
  g.pitch_diameter = 60e-3;
  g.inner_groove_radius = 0.52 * 12.7e-3;
  g.outer_groove_radius = 0.53 * 12.7e-3;
  g.clearance = 15e-6;
  g.dynamic_load_rating = 32.5e3;
  return std::make_shared<const RollingBearing>(g);
}

/// 30208-like tapered roller bearing (17 × 9.5 mm, L_we 14 mm, 15°, logarithmic profile).
inline std::shared_ptr<const RollingBearing> tapered30208(bool reversed = false) {
  RollingBearingGeometry g;
  g.reversed = reversed;
  g.type = RollingBearingType::kTaperedRoller;
  g.elements = 17;
  g.element_diameter = 9.5e-3;
  g.pitch_diameter = 62e-3;
  g.contact_angle = 15.0 * kDeg;
  g.roller_length = 14e-3;
  g.slices = 10;
  g.dynamic_load_rating = 63e3;
  return std::make_shared<const RollingBearing>(g);
}

/// The reducer's six bearings replaced by 6208 (input) and 30208 (intermediate, output; the
/// "b" ends reversed: each shaft's pair holds it axially both ways).
inline GearTrainSpec withRollingBearings(GearTrainSpec spec) {
  for (TrainBearingSpec& b : spec.bearings) {
    if (b.shaft == "motor") continue;
    b.kyy = b.kzz = b.k_axial = b.k_tilt = 0.0;
    b.rolling = b.shaft == "input" ? deepGroove6208() : tapered30208(b.name.back() == 'b');
  }
  return spec;
}

}  // namespace geardyn::testing
