#pragma once
/// \file
/// Gear pairs of the seed papers, shared by tests and benchmarks.

#include <numbers>

#include "geardyn/geometry/gear_pair.h"

namespace geardyn::testing {

/// Visnadi & de Castro (2021), Table 1: m = 3 mm, z = 25/30, α = 20°, L = 20 mm, E = 200 GPa,
/// ν = 0.3, on the 30 mm shafts of §4 (bore 30 mm). `module` scales every length.
inline GearPairSpec visnadiPairSpec(double helix_deg = 0.0, double module = 3e-3) {
  const double scale = module / 3e-3;
  GearPairSpec spec;
  for (GearSpec* g : {&spec.pinion, &spec.gear}) {
    g->normal_module = module;
    g->normal_pressure_angle = 20.0 * std::numbers::pi / 180.0;
    g->face_width = 20e-3 * scale;
    g->youngs_modulus = 200e9;
    g->poisson_ratio = 0.3;
    g->bore_diameter = 30e-3 * scale;
  }
  spec.pinion.teeth = 25;
  spec.gear.teeth = 30;
  spec.pinion.helix_angle = helix_deg * std::numbers::pi / 180.0;
  spec.gear.helix_angle = -spec.pinion.helix_angle;
  return spec;
}

}  // namespace geardyn::testing
