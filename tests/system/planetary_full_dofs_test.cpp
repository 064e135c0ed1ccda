/// Planetary stages with six DOFs per member (gearbox.dofs = "full"): the fixed-frame lumped
/// model of Lin & Parker's stage extended by axial and tilting motion. A spur stage in one plane
/// keeps the planar model's modes (the in-plane and out-of-plane motions decouple), and a
/// helical stage's static axial thrust is N F_t tan β_w on the sun and the ring, while each
/// planet's two thrusts cancel into a tilting moment on its pin.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "geardyn/error.h"
#include "geardyn/solvers/train_modal.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/system/gear_train_model.h"
#include "system/sample_trains.h"

namespace geardyn {
namespace {

using testing::linParker1999;

/// Lin & Parker's stage in the fixed frame with supports for the full DOFs: diametral inertias
/// of the central members, axial and tilt stiffness of their bearings.
GearTrainSpec stage(TrainDofs dofs, double helix_deg = 0.0) {
  GearTrainSpec spec = linParker1999(3, dofs);
  spec.stages[0].carrier_frame_terms = false;
  for (auto& shaft : spec.shafts) shaft.diametral_inertia = 0.6 * shaft.polar_inertia;
  for (auto& b : spec.bearings) {
    b.k_axial = 2e8;
    b.k_tilt = 3e5;
  }
  const double beta = helix_deg * testing::kDeg;
  for (auto& g : spec.gears) g.gear.helix_angle = beta;  // sun right hand, ring as the planets
  spec.stages[0].planet.helix_angle = -beta;
  for (auto& g : spec.gears) {
    if (g.internal) g.gear.helix_angle = -beta;
  }
  return spec;
}

TEST(PlanetaryFullDofs, ASpurStageInOnePlaneKeepsThePlanarModes) {
  // Spur gears, every member and pin in the plane x = 0: the in-plane block (y, z, θ) is the
  // planar model's, so each planar frequency is one of the full model's. Both come from the
  // symmetric eigensolver on the same springs: 1e-9 relative (round-off of 36 vs 18 DOFs).
  const GearTrainModel planar(stage(TrainDofs::kPlanar));
  const GearTrainModel full(stage(TrainDofs::kFull));
  ASSERT_EQ(full.dofCount(), 36);
  const auto in_plane = trainModes(planar, 0.0);
  const auto all = trainModes(full, 0.0);
  ASSERT_EQ(in_plane.size(), 18u);
  ASSERT_EQ(all.size(), 36u);
  for (const TrainMode& m : in_plane) {
    if (m.frequency == 0.0) continue;  // the rolling mode
    double nearest = HUGE_VAL;
    for (const TrainMode& f : all) nearest = std::min(nearest, std::abs(f.frequency - m.frequency));
    EXPECT_LT(nearest, 1e-9 * m.frequency) << m.frequency << " Hz";
  }
  // The 18 others are out of plane: no mesh strain energy (spur meshes act in the plane).
  int out_of_plane = 0;
  for (const TrainMode& f : all) {
    double mesh = 0.0;
    for (double e : f.mesh_strain_energy) mesh += e;
    out_of_plane += f.frequency > 0.0 && mesh < 1e-12;
    if (f.frequency > 0.0 && mesh < 1e-12) EXPECT_EQ(f.stage_type.at(0), "out_of_plane");
  }
  EXPECT_EQ(out_of_plane, 18);
  // The in-plane ones keep Lin & Parker's types (the rolling mode at 0 Hz aside).
  int lin_parker = 0;
  for (const TrainMode& f : all) {
    const std::string& type = f.stage_type.at(0);
    lin_parker += type == "rotational" || type == "translational" || type == "planet";
  }
  EXPECT_EQ(lin_parker, 18);
}

TEST(PlanetaryFullDofs, HelicalThrustIsTangentialForceTimesTanBetaW) {
  // T = 100 N m on the sun, shared by N = 3 equal planets: F_t = T / (N r_w) per sun mesh,
  // axial F_a = F_t tan β_w = F_t tan β_b / cos α_wt on the sun, and the same total on the ring
  // (each planet carries F_t to the ring; its two thrusts are opposite and cancel axially).
  // Statics of linear springs: exact up to the solve's round-off, 1e-8.
  GearTrainSpec spec = stage(TrainDofs::kFull, 15.0);
  spec.operating.input_torque = 100.0;
  const GearTrainModel model(spec);
  const TrainStaticResult st = solveTrainStatic(model, model.inputSpeed());
  ASSERT_EQ(st.status, "ok") << st.message;
  const TrainMesh& m = model.meshes()[0];
  ASSERT_EQ(m.kind, TrainMeshKind::kSunPlanet);
  const double rw = m.base_radius_a / std::cos(m.pressure_angle);
  const double fa = 100.0 / rw * std::tan(m.base_helix_angle) / std::cos(m.pressure_angle);
  double sun = 0, ring = 0, pins = 0, tilt = 0;
  for (std::size_t e = 0; e < model.elements().size(); ++e) {
    const std::string& name = model.elements()[e].name;
    if (name == "sun_bearing.axial") sun = st.element_load[e].force;
    if (name == "ring_support.axial") ring = st.element_load[e].force;
    if (name.find(".pin_axial") != std::string::npos) pins += st.element_load[e].force;
    if (name.find(".pin_tilt") != std::string::npos) tilt += st.element_load[e].moment;
  }
  // Element forces are magnitudes; the directions come from the axial displacements, opposite
  // for the sun and the ring.
  EXPECT_NEAR(sun, fa, 1e-8 * fa);
  EXPECT_NEAR(ring, fa, 1e-8 * fa);
  const auto axial = [&](const char* body) {
    return st.displacement(model.bodies()[model.bodyIndex(body)].first_dof + 3);
  };
  EXPECT_LT(axial("sun") * axial("ring"), 0.0);
  EXPECT_LT(pins, 1e-8 * fa);
  EXPECT_GT(tilt, 1e-3 * fa * rw);  // the planets' thrust couple, held by the pins in tilt
}

TEST(PlanetaryFullDofs, ARingOutOfThePlanetsPlaneIsRefusedNamingItsPosition) {
  GearTrainSpec spec = stage(TrainDofs::kFull);
  for (auto& g : spec.gears) {
    if (g.internal) g.position = 0.05;  // 50 mm from the sun's plane, face widths 20 mm
  }
  try {
    const GearTrainModel model(spec);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("gears.ring_gear.position"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace geardyn
