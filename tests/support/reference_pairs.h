#pragma once
/// \file
/// Gear pairs and dynamic models of the seed papers and of textbook cases, shared by tests and
/// benchmarks.

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "geardyn/geometry/gear_pair.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "geardyn/stiffness/step_stiffness.h"
#include "geardyn/system/gear_pair_model.h"

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

/// Saletti et al. (2025), Table 1: m = I/(2r²), C = 4038.2 N s/m, contact elements of
/// k_c = 2.6e8 N/m with ε = 1.75 (k alternates k_c and 2k_c), one-sided contact, F = T/r.
inline GearPairModelSpec salettiModelSpec(double torque) {
  GearPairModelSpec spec;
  spec.mass = 0.0158 / (2 * 0.0705 * 0.0705);
  spec.damping = 4038.2;
  spec.mean_force = torque / 0.0705;
  spec.contact = ContactLaw::kOneSided;
  spec.stiffness = std::make_shared<StepMeshStiffness>(2.6e8, 5.2e8, 1.75);
  return spec;
}

/// The SDOF gear pair of issue #4 and examples/simulate_gear_pair_backlash.toml, linear contact:
/// m = 1.589 kg, k = 4.55e8 (1 − 0.2 cos Ωt − 0.1 cos 2Ωt) N/m, ζ = 0.05, F = 1418.4 N, a 1 µm
/// first-order error, f_m = 1000 Hz.
inline GearPairModelSpec issue4ExampleSpec() {
  GearPairModelSpec spec;
  spec.mass = 1.589;
  spec.damping = 2 * 0.05 * std::sqrt(4.55e8 * 1.589);
  spec.mean_force = 1418.4;
  spec.stiffness = std::make_shared<FourierMeshStiffness>(
      4.55e8, std::vector<double>{0.2, 0.1},
      std::vector<double>{std::numbers::pi, std::numbers::pi}, 1.6);
  spec.transmission_error.addFourier({1e-6}, {0.0});
  spec.mesh_frequency = 1000.0;
  return spec;
}

/// The Mathieu-type oscillator x″ + 0.02 x′ + (1 + 0.3 cos Ωt) x = 1 (nondimensional, linear
/// contact): the principal parametric resonance opens around Ω = 2.
inline GearPairModelSpec mathieuModelSpec() {
  GearPairModelSpec spec;
  spec.mass = 1.0;
  spec.damping = 0.02;
  spec.mean_force = 1.0;
  spec.stiffness = std::make_shared<FourierMeshStiffness>(1.0, std::vector<double>{0.3},
                                                          std::vector<double>{0.0}, 1.5);
  return spec;
}

/// The Kahraman & Singh (1990)-type backlash pair of issue 17, nondimensional (Gelman's units:
/// m = 1, k̄ = 1, ω_n = 1): half backlash b = 1, ζ = 0.05, mean force 0.1,
/// k = 1 − 0.2 cos Ωt − 0.1 cos 2Ωt − 0.05 cos 3Ωt, e = 0.01 cos Ωt + 0.004 cos 2Ωt
/// + 0.002 cos 3Ωt.
inline GearPairModelSpec kahramanSinghIssue17Spec() {
  GearPairModelSpec spec;
  spec.mass = 1.0;
  spec.damping = 0.1;
  spec.mean_force = 0.1;
  spec.contact = ContactLaw::kBacklash;
  spec.backlash = 1.0;
  const double pi = std::numbers::pi;
  spec.stiffness = std::make_shared<FourierMeshStiffness>(1.0, std::vector<double>{0.2, 0.1, 0.05},
                                                          std::vector<double>{pi, pi, pi}, 1.6);
  spec.transmission_error.addFourier({0.01, 0.004, 0.002}, {0.0, 0.0, 0.0});
  return spec;
}

/// Peak to peak of a signal.
inline double peakToPeak(const std::vector<double>& x) {
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  return *hi - *lo;
}

}  // namespace geardyn::testing
