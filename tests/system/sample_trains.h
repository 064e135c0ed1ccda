#pragma once
/// \file
/// Reference gear trains built in code (Pinocchio's sample-models pattern): the Lin & Parker
/// (1999) planetary example and a two-stage parallel reducer.

#include <map>
#include <numbers>
#include <string>

#include "geardyn/stiffness/api_stiffness.h"
#include "geardyn/system/gear_train.h"

namespace geardyn::testing {

inline constexpr double kDeg = std::numbers::pi / 180.0;

inline GearSpec spurGear(int teeth, double module, double pressure_angle_deg, double face_width) {
  GearSpec g;
  g.teeth = teeth;
  g.normal_module = module;
  g.normal_pressure_angle = pressure_angle_deg * kDeg;
  g.face_width = face_width;
  return g;
}

/// Lin & Parker (1999) Table 1 example (as transcribed in Lin's thesis, Table C.1): masses
/// [kg] sun 0.40, ring 2.35, carrier 5.43, planet 0.66; I/r² [kg] 0.39, 3.00, 6.29, 0.61;
/// k_sp = k_rp = 5e8 N/m; bearings k_s = k_r = k_c = k_p = 1e8 N/m; ring held torsionally with
/// k_ru = 1e9 N/m on u_r = r θ_r; α_s = α_r = 24.6°. The paper works in u = r θ with I/r²; here
/// θ with I = (I/r²) r² on base radii of a geometry that gives exactly α = 24.6° (spur, no
/// profile shift, z_s = z_p = 30, z_r = 90, so (z_s + z_r)/N is an integer for N = 3, 4, 5); the
/// carrier radius is the planet-centre radius. Frequencies depend only on I/r², k and α.
inline GearTrainSpec linParker1999(int planets, TrainDofs dofs = TrainDofs::kPlanar) {
  const double m = 2e-3, alpha = 24.6, b = 20e-3;
  const int zs = 30, zp = 30, zr = 90;
  const double rbs = 0.5 * zs * m * std::cos(alpha * kDeg);
  const double rbp = 0.5 * zp * m * std::cos(alpha * kDeg);
  const double rbr = 0.5 * zr * m * std::cos(alpha * kDeg);
  const double rc = 0.5 * (zs + zp) * m;
  GearTrainSpec spec;
  spec.name = "Lin & Parker 1999";
  spec.dofs = dofs;
  spec.shafts = {{"sun", 0.40, 0.39 * rbs * rbs, {}, {}, {}, 7850.0},
                 {"ring", 2.35, 3.00 * rbr * rbr, {}, {}, {}, 7850.0},
                 {"carrier", 5.43, 6.29 * rc * rc, {}, {}, {}, 7850.0}};
  TrainGearSpec sun{"sun_gear", "sun", spurGear(zs, m, alpha, b), false, false};
  TrainGearSpec ring{"ring_gear", "ring", spurGear(zr, m, alpha, b), true, false};
  spec.gears = {sun, ring};
  TrainBearingSpec bs{"sun_bearing", "sun", "", 1e8, 1e8};
  TrainBearingSpec br{"ring_support", "ring", "", 1e8, 1e8};
  br.k_torsion = 1e9 * rbr * rbr;
  TrainBearingSpec bc{"carrier_bearing", "carrier", "", 1e8, 1e8};
  spec.bearings = {bs, br, bc};
  PlanetaryStageSpec st;
  st.name = "stage";
  st.sun = "sun_gear";
  st.ring = "ring_gear";
  st.carrier = "carrier";
  st.planet = spurGear(zp, m, alpha, b);
  st.planets = planets;
  st.planet_body = false;
  st.planet_mass = 0.66;
  st.planet_inertia = 0.61 * rbp * rbp;
  st.pin_radial_stiffness = st.pin_tangential_stiffness = 1e8;
  st.sun_planet_stiffness = std::make_shared<ConstantMeshStiffness>("constant", 5e8, 1.5);
  st.ring_planet_stiffness = std::make_shared<ConstantMeshStiffness>("constant", 5e8, 1.5);
  spec.stages = {st};
  spec.operating = {"sun", 0.0, 0.0, "carrier"};
  return spec;
}

/// A two-stage parallel-axis reducer: motor → coupling → input shaft (z₁ = 23) → intermediate
/// (z₂ = 51, z₃ = 17) → output (z₄ = 47), two bearings on each of the three gearbox shafts
/// (6 bearings), ratio 51/23 · 47/17 = 6.13. Mesh frequencies 23 and 23·17/51 = 23/3 per input
/// revolution: a common period of three stage-1 mesh periods. `stiffness` gives each mesh's
/// k(φ) (nullptr: constant 4e8 and 6e8 N/m).
inline GearTrainSpec twoStageReducer(std::shared_ptr<const MeshStiffness> k1 = nullptr,
                                     std::shared_ptr<const MeshStiffness> k2 = nullptr,
                                     TrainDofs dofs = TrainDofs::kPlanar) {
  GearTrainSpec spec;
  spec.name = "two-stage reducer";
  spec.dofs = dofs;
  spec.shafts = {{"motor", 15.0, 0.04, {}, {}, {}, 7850.0},
                 {"input", 0.0, 0.0, {0.25}, {0.04}, {}, 7850.0},
                 {"intermediate", 0.0, 0.0, {0.3}, {0.055}, {}, 7850.0},
                 {"output", 0.0, 0.0, {0.35}, {0.075}, {}, 7850.0}};
  spec.gears = {{"z1", "input", spurGear(23, 3e-3, 20.0, 0.03), false, true},
                {"z2", "intermediate", spurGear(51, 3e-3, 20.0, 0.028), false, true},
                {"z3", "intermediate", spurGear(17, 4.5e-3, 20.0, 0.045), false, true},
                {"z4", "output", spurGear(47, 4.5e-3, 20.0, 0.042), false, true}};
  spec.gears[0].gear.bore_diameter = 0.03;
  spec.gears[1].gear.bore_diameter = 0.045;
  spec.gears[3].gear.bore_diameter = 0.06;
  if (!k1) k1 = std::make_shared<ConstantMeshStiffness>("constant", 4e8, 1.6);
  if (!k2) k2 = std::make_shared<ConstantMeshStiffness>("constant", 6e8, 1.6);
  TrainMeshSpec m1{"stage1", "z1", "z2", 0.0, std::nullopt, k1, {}, 0.05, std::nullopt};
  TrainMeshSpec m2{"stage2", "z3", "z4", -30.0 * kDeg, std::nullopt, k2, {}, 0.05, std::nullopt};
  spec.meshes = {m1, m2};
  for (const char* shaft : {"input", "intermediate", "output"}) {
    for (const char* end : {"a", "b"}) {
      TrainBearingSpec b{std::string(shaft) + "_" + end, shaft, "", 4e8, 5e8};
      b.cyy = b.czz = 2e3;
      spec.bearings.push_back(b);
    }
  }
  spec.couplings = {{"motor_coupling", "motor", "input", 2.5e4, 5.0, 1e7, 100.0}};
  spec.operating = {"motor", 1500.0 * std::numbers::pi / 30.0, 200.0, "output"};
  return spec;
}

/// The two-stage reducer with full DOFs: flexible shafts (elements no longer than
/// `max_element` [m]), gears and bearings placed along them, helical gears of `helix_deg`
/// (z1, z3 right hand for > 0), axial and tilt support on every shaft, a rigid motor on its own
/// bearings. E scales the shafts' Young's modulus (a large E approaches rigid shafts).
inline GearTrainSpec flexibleReducer(double helix_deg = 0.0, double max_element = 0.03,
                                     double youngs_modulus = 2.1e11, bool flexible = true) {
  GearTrainSpec spec = twoStageReducer(nullptr, nullptr, TrainDofs::kFull);
  spec.name = "flexible two-stage reducer";
  for (auto& s : spec.shafts) {
    if (s.name == "motor") {
      s.diametral_inertia = 0.05;
      continue;
    }
    s.flexible = flexible;
    s.youngs_modulus = youngs_modulus;
    s.max_element_length = max_element;
  }
  const double beta = helix_deg * kDeg;
  spec.gears[0].position = 0.08, spec.gears[0].gear.helix_angle = beta;
  spec.gears[1].position = 0.08, spec.gears[1].gear.helix_angle = -beta;
  spec.gears[2].position = 0.20, spec.gears[2].gear.helix_angle = beta;
  spec.gears[3].position = 0.20, spec.gears[3].gear.helix_angle = -beta;
  const std::map<std::string, double> length = {
      {"input", 0.25}, {"intermediate", 0.3}, {"output", 0.35}};
  for (auto& b : spec.bearings) {
    const bool a = b.name.back() == 'a';
    b.position = a ? 0.02 : length.at(b.shaft) - 0.02;
    if (a) b.k_axial = 2e8, b.c_axial = 1e3;
    b.k_tilt = 1e4;
  }
  for (const char* end : {"a", "b"}) {
    TrainBearingSpec b{std::string("motor_") + end, "motor", "", 2e8, 2e8};
    b.k_axial = 1e8;
    b.k_tilt = 2e5;
    spec.bearings.push_back(b);
  }
  return spec;
}

/// A chain of `stages` helical parallel-axis stages on stages + 1 flexible shafts of 0.3 m
/// (50 mm, elements of at most `max_element` [m]): 25/38 teeth, 3 mm, 10 deg, stage k at
/// x = 0.2 m (odd k) or 0.08 m, two bearings per shaft (axial at one). With 4 stages and
/// 20 mm elements about 500 DOFs: the benchmark of a large FE gearbox.
inline GearTrainSpec flexibleChain(int stages, double max_element,
                                   std::shared_ptr<const MeshStiffness> k = nullptr) {
  GearTrainSpec spec;
  spec.name = "flexible chain";
  spec.dofs = TrainDofs::kFull;
  spec.stiffness_proportional_damping = 2e-6;
  if (!k) k = std::make_shared<ConstantMeshStiffness>("constant", 4e8, 1.6);
  for (int s = 0; s <= stages; ++s) {
    TrainShaftSpec shaft;
    shaft.name = "s" + std::to_string(s);
    shaft.section_lengths = {0.3};
    shaft.outer_diameters = {0.05};
    shaft.flexible = true;
    shaft.max_element_length = max_element;
    spec.shafts.push_back(shaft);
    for (const char* end : {"a", "b"}) {
      TrainBearingSpec b{shaft.name + "_" + end, shaft.name, "", 4e8, 5e8};
      b.cyy = b.czz = 2e3;
      b.position = end[0] == 'a' ? 0.02 : 0.28;
      b.k_tilt = 1e4;
      if (end[0] == 'a') b.k_axial = 3e8;
      spec.bearings.push_back(b);
    }
  }
  for (int st = 1; st <= stages; ++st) {
    const double x = st % 2 ? 0.2 : 0.08;
    TrainGearSpec pinion{"p" + std::to_string(st), "s" + std::to_string(st - 1),
                         spurGear(25, 3e-3, 20.0, 0.03)};
    TrainGearSpec gear{"g" + std::to_string(st), "s" + std::to_string(st),
                       spurGear(38, 3e-3, 20.0, 0.03)};
    pinion.gear.helix_angle = (st % 2 ? 10.0 : -10.0) * kDeg;
    gear.gear.helix_angle = -pinion.gear.helix_angle;
    pinion.gear.bore_diameter = gear.gear.bore_diameter = 0.05;
    pinion.position = gear.position = x;
    spec.gears.push_back(pinion);
    spec.gears.push_back(gear);
    spec.meshes.push_back({"stage" + std::to_string(st),
                           pinion.name,
                           gear.name,
                           (st % 2 ? 0.0 : 60.0) * kDeg,
                           std::nullopt,
                           k,
                           {},
                           0.05,
                           std::nullopt});
  }
  spec.operating = {"s0", 1500.0 * std::numbers::pi / 30.0, 100.0, "s" + std::to_string(stages)};
  return spec;
}

}  // namespace geardyn::testing
