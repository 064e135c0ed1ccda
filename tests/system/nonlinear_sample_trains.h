#pragma once
/// \file
/// Gear trains with nonlinear meshes built in code for the tests and benchmarks of issue 17:
/// the fixtures of sample_trains.h with damping, transmission errors, a smooth k and backlash.

#include <memory>
#include <numbers>

#include "geardyn/solvers/continuation.h"
#include "geardyn/solvers/train_harmonic_balance.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "system/sample_trains.h"

namespace geardyn::testing::nonlinear {

inline std::shared_ptr<const MeshStiffness> smooth(double mean, double phase_deg) {
  return std::make_shared<FourierMeshStiffness>(mean, std::vector<double>{0.12, 0.05, 0.02},
                                                std::vector<double>{phase_deg * kDeg, 0.3, 1.1},
                                                1.6);
}

inline TrainMeshContact backlash(double j) {
  return {ContactLaw::kBacklash, j};
}

/// One external pair with torsional DOFs (as in train_response_test's reduction), backlash j.
inline GearTrainSpec singlePair(double j) {
  GearTrainSpec spec;
  spec.dofs = TrainDofs::kTorsional;
  spec.shafts = {{"pinion_shaft", 0.0, 2e-3, {}, {}, {}, 7850.0},
                 {"gear_shaft", 0.0, 9e-3, {}, {}, {}, 7850.0}};
  spec.gears = {{"pinion", "pinion_shaft", spurGear(25, 3e-3, 20.0, 0.02), false, false},
                {"gear", "gear_shaft", spurGear(53, 3e-3, 20.0, 0.02), false, false}};
  TrainMeshSpec mesh{"pair", "pinion", "gear",      0.0, std::nullopt, smooth(3e8, 20.0),
                     {},     0.05,     std::nullopt};
  mesh.transmission_error.addFourier({6e-6, 2e-6}, {0.2, -0.4});
  mesh.contact = backlash(j);
  spec.meshes = {mesh};
  spec.operating = {"pinion_shaft", 2100.0 * std::numbers::pi / 30.0, 40.0, "gear_shaft"};
  return spec;
}

/// The Lin & Parker stage with 3 planets, damped, loaded, smooth k and errors, backlash j at
/// all 6 meshes.
inline GearTrainSpec planetary(double j) {
  GearTrainSpec spec = linParker1999(3);
  auto& st = spec.stages[0];
  st.sun_planet_stiffness = smooth(5e8, 0.0);
  st.ring_planet_stiffness = smooth(5e8, 70.0);
  st.sun_planet_damping_ratio = st.ring_planet_damping_ratio = 0.05;
  st.sun_planet_error.addFourier({3e-6}, {0.0});
  st.ring_planet_error.addFourier({2e-6}, {0.8});
  st.sun_planet_contact = st.ring_planet_contact = backlash(j);
  spec.bearings[0].cyy = spec.bearings[0].czz = 2e3;
  spec.bearings[2].cyy = spec.bearings[2].czz = 2e3;
  st.pin_damping = 2e3;
  spec.bearings[1].c_torsion = 50.0;
  spec.operating.input_torque = 100.0;
  spec.operating.input_speed = 300.0;
  // The classic lumped model. (It was chosen when Lin & Parker's carrier-frame terms made the
  // rolling mode diverge at speed; that is fixed (docs/theory/gear_trains.md), but the long
  // tests' and benchmarks' numbers are for this model.)
  st.carrier_frame_terms = false;
  return spec;
}

/// The harmonic balance of the planetary case: H = 15, N = 256.
inline TrainHarmonicBalanceOptions planetaryHbmOptions() {
  TrainHarmonicBalanceOptions options;
  options.harmonics = 15;
  options.samples = 256;
  return options;
}

/// Its sweep over mesh frequencies 4–13 kHz (two softening loops with contact loss, 4 folds):
/// steps of at most 1/100 of the range, the rest derived (ζ = 0.05, H = 15).
inline ContinuationOptions planetarySweep(bool stability) {
  ContinuationOptions c;
  c.start = 2 * std::numbers::pi * 4000;
  c.stop = 2 * std::numbers::pi * 13000;
  c.max_step = (c.stop - c.start) / 100;
  c.stability = stability;
  deriveContinuationSteps(c, 0.0, 0.05, planetaryHbmOptions().harmonics);
  return c;
}

/// The two-stage reducer (planar, 4 shafts, 6 bearings, a coupling) with smooth k, transmission
/// errors at both meshes and backlash j at both; the mesh frequencies are 3:1 (common period:
/// three stage-1 mesh periods).
inline GearTrainSpec twoStage(double j) {
  GearTrainSpec spec = twoStageReducer(smooth(4e8, 0.0), smooth(6e8, 40.0));
  spec.meshes[0].transmission_error.addFourier({8e-6, 2e-6}, {0.0, 0.5});
  spec.meshes[1].transmission_error.addFourier({6e-6}, {0.3});
  spec.meshes[0].contact = spec.meshes[1].contact = backlash(j);
  return spec;
}

}  // namespace geardyn::testing::nonlinear
