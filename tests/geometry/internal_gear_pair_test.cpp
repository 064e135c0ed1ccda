/// InternalGearPair refuses involute interference: a ring tip circle that meets the line of
/// action inside the pinion's base-circle tangent point (the ring's tip would cut the pinion
/// below its base circle). Hand calculation for the case below (m_n 2 mm, β 15°, z 25/73; a
/// separate script): α_t = 20.647°, r_bp = 24.220 mm, r_br = 70.721 mm; at the centre distance
/// of a 23-tooth sun (x 0.2/0.1), a_w = 50.271 mm, α_wt = 22.328° and a_w sin α_wt = 19.098 mm.
/// With x_r = 0.4 the ring's tip circle r_ar = r − (1 + 0.4) m_n = 72.775 mm gives
/// √(r_ar² − r_br²) = 17.168 mm < 19.098 mm: refused. With x_r = 0 (r_ar = 73.575 mm,
/// 20.294 mm) it meshes.

#include "geardyn/geometry/internal_gear_pair.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/geometry/gear_pair.h"

namespace geardyn {
namespace {

GearSpec gearOf(int teeth, double shift, double helix) {
  GearSpec g;
  g.teeth = teeth;
  g.normal_module = 2e-3;
  g.normal_pressure_angle = 20.0 * std::numbers::pi / 180.0;
  g.helix_angle = helix;
  g.face_width = 0.02;
  g.profile_shift = shift;
  return g;
}

TEST(InternalGearPair, RefusesARingTipInsideThePinionTangentPoint) {
  const double beta = 15.0 * std::numbers::pi / 180.0;
  GearPairSpec spec;
  spec.pinion = gearOf(23, 0.2, beta), spec.gear = gearOf(25, 0.1, -beta);
  const double a = makeGearPair(spec, "sun", "planet", "stage").centreDistance();
  EXPECT_NO_THROW(InternalGearPair(spec.gear, gearOf(73, 0.0, -beta), a, "stage"));
  try {
    InternalGearPair(spec.gear, gearOf(73, 0.4, -beta), a, "stage");
    FAIL() << "involute interference accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("profile_shift"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("interference"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace geardyn
