#pragma once
/// \file
/// Trains with a rolling bearing's full law in the nonlinear analyses (issue 35,
/// bearings.<name>.model = "nonlinear"): the spur pair of train_bearing_clearance_test on a
/// 6208-like deep-groove ball bearing (planar DOFs), and its helical full-DOF variant on a
/// back-to-back angular-contact pair.

#include <memory>
#include <numbers>

#include "geardyn/contact/rolling_bearing.h"
#include "geardyn/solvers/train_harmonic_balance.h"
#include "geardyn/solvers/train_nonlinear_time.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/stiffness/api_stiffness.h"
#include "system/nonlinear_sample_trains.h"
#include "system/rolling_bearing_trains.h"

namespace geardyn::testing {

/// The spur pair of train_bearing_clearance_test (planar DOFs, 25/53 teeth of 3 mm, a linear
/// mesh, gravity, 10 N m: ~290 N on the pinion bearing), the pinion shaft on a 6208-like
/// deep-groove ball bearing (9 balls of 12.7 mm) with diametral clearance s_r and its full law,
/// linear damping 300 N s/m; the gear shaft on a linear bearing. The transmission error is
/// `te` × (6, 2) µm; `smooth`: the Fourier k(φ), else a constant 3e8 N/m.
inline GearTrainSpec rollingPair(double s_r, double te, bool smooth) {
  GearTrainSpec spec = nonlinear::singlePair(0.0);
  spec.dofs = TrainDofs::kPlanar;
  spec.shafts[0].mass = 1.5;
  spec.shafts[1].mass = 4.0;
  TrainMeshSpec& mesh = spec.meshes[0];
  mesh.contact = {};
  if (!smooth) mesh.stiffness = std::make_shared<ConstantMeshStiffness>("constant", 3e8, 1.6);
  mesh.transmission_error = {};
  mesh.transmission_error.addFourier({6e-6 * te, 2e-6 * te}, {0.2, -0.4});
  spec.gravity = 9.81;
  TrainBearingSpec pinion{"pinion_bearing", "pinion_shaft"};
  pinion.cyy = pinion.czz = 300.0;
  RollingBearingGeometry g = deepGroove6208()->geometry();
  g.clearance = s_r;
  pinion.rolling = std::make_shared<const RollingBearing>(g);
  pinion.full_law = true;
  TrainBearingSpec gear{"gear_bearing", "gear_shaft", "", 3e8, 3e8};
  gear.cyy = gear.czz = 600.0;
  spec.bearings = {pinion, gear};
  spec.operating.input_torque = 10.0;
  return spec;
}

/// rollingPair with full DOFs: helical gears (β = 15°: the mesh force has an axial part and,
/// at the pitch radius, a tilting moment), the pinion on a back-to-back pair of 25°
/// angular-contact rows (9 balls of 12.7 mm each on 60 mm, f 0.52/0.53, rows 20 mm apart,
/// radial play s_r) with its full law over (u_y, u_z, u_x, θ_y, θ_z), damped 300 N s/m
/// radially and axially and 30 N m s/rad in tilt; the gear shaft on a linear bearing stiff in
/// all five directions. 40 N m: the helix's axial force loads one row more than the other.
inline GearTrainSpec rollingPairFullDofs(double s_r, double te, bool smooth) {
  GearTrainSpec spec = rollingPair(s_r, te, smooth);
  spec.dofs = TrainDofs::kFull;
  spec.shafts[0].diametral_inertia = 1e-3;
  spec.shafts[1].diametral_inertia = 4.5e-3;
  const double beta = 15.0 * std::numbers::pi / 180.0;
  spec.gears[0].gear.helix_angle = beta;
  spec.gears[1].gear.helix_angle = -beta;
  TrainBearingSpec& pinion = spec.bearings[0];
  RollingBearingGeometry g = pinion.rolling->geometry();
  g.type = RollingBearingType::kAngularContactBall;
  g.arrangement = BearingArrangement::kBackToBack;
  g.contact_angle = 25.0 * std::numbers::pi / 180.0;
  g.row_spacing = 20e-3;
  pinion.rolling = std::make_shared<const RollingBearing>(g);
  pinion.c_axial = 300.0;
  pinion.c_tilt = 30.0;
  TrainBearingSpec& gear = spec.bearings[1];
  gear.k_axial = 3e8;
  gear.k_tilt = 3e6;
  gear.c_axial = 600.0;
  gear.c_tilt = 60.0;
  spec.operating.input_torque = 40.0;
  return spec;
}

/// Nonlinear Newmark started on the balance's solution p (average acceleration, 512 steps a
/// mesh period, steady to 1e-8): the reference the balance is checked against.
inline TrainNonlinearTimeResponse newmarkOnBalance(const GearTrainModel& model,
                                                   TrainHarmonicBalance& hbm,
                                                   const HarmonicBalancePoint& p) {
  auto [q0, v0] = hbm.initialState(p);
  TrainNonlinearTimeOptions newmark;
  newmark.steps_per_mesh_period = 512;
  newmark.steady_tolerance = 1e-8;
  return solveTrainNonlinearTime(model, hbm.inputSpeed(p.omega), newmark, q0, v0);
}

/// The train the nonlinear analyses run: linearised at its nonlinear static deflection, each
/// full-law bearing a block of nonlinear coordinates.
inline GearTrainModel linearisedAtStatics(const GearTrainSpec& spec) {
  const GearTrainModel model(spec);
  return model.linearisedAt(solveTrainStatic(model, model.inputSpeed()).displacement);
}

}  // namespace geardyn::testing
