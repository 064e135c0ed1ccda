/// Spherical roller bearings (two rows of barrel rollers on a spherical outer raceway): the
/// tangent stiffness against central differences, self-alignment (no tilt stiffness, exactly),
/// the axial closed form, Sjövall's radial integral for the half load zone (Harris &
/// Kotzalas's J_r(0.5) = 0.2453 for line contact) and the geometry checks.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "contact/bearing_differences.h"
#include "geardyn/contact/rolling_bearing.h"
#include "geardyn/error.h"
#include "support/numeric_assertions.h"

namespace geardyn {
namespace {

using Vector5 = RollingBearing::Vector5;
using Matrix5 = RollingBearing::Matrix5;
constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

/// A 22208-like spherical roller bearing (d 40 mm, D 80 mm): 15 rollers per row of D_we 10 mm
/// and L_we 9.5 mm on a 60 mm pitch circle, contact angle 11°, s_r 20 µm, logarithmic profile.
/// Like the catalogue bearing's size, not a manufacturer's data.
RollingBearingGeometry spherical() {
  RollingBearingGeometry g;
  g.type = RollingBearingType::kSphericalRoller;
  g.elements = 15;
  g.element_diameter = 10e-3;
  g.pitch_diameter = 60e-3;
  g.contact_angle = 11.0 * kDeg;
  g.roller_length = 9.5e-3;
  g.slices = 12;
  g.clearance = 20e-6;
  g.dynamic_load_rating = 96.5e3;
  return g;
}

TEST(SphericalRollerBearing, TangentStiffnessMatchesCentralDifferences) {
  // 1e-6 of the largest entry, symmetry and semi-definiteness (bearing_differences.h).
  for (RollerProfile profile :
       {RollerProfile::kLogarithmic, RollerProfile::kCrowned, RollerProfile::kStraight}) {
    RollingBearingGeometry g = spherical();
    g.profile = profile;
    g.crown_drop = 6e-6;
    Vector5 q;
    q << 25e-6, -9e-6, 7e-6, 3e-4, -2e-4;
    testing::expectTangentMatchesDifferences(RollingBearing(g), q);
  }
}

TEST(SphericalRollerBearing, TiltsLoadNoContact) {
  // Every contact normal passes through the bearing's centre, so a tilt moves the inner ring's
  // contact points along the sphere: F(q) does not depend on θ_y, θ_z, and K's tilt rows and
  // columns are zero (Harris & Kotzalas 2006, vol. 1 §1.3: the bearing is self-aligning).
  // The slices' gradients' tilt entries cancel only if every contact point and normal lie on
  // the sphere about the centre (x_p = σ R_e sin φ, r_p = R_e cos φ): to round-off ε R_e,
  // 1e-12 of the largest entry.
  const RollingBearing b(spherical());
  Vector5 q, tilted;
  q << 30e-6, 10e-6, -6e-6, 0.0, 0.0;
  tilted = q;
  tilted(3) = 2e-3, tilted(4) = -1.5e-3;  // 0.1°: a large misalignment
  const RollingBearingState a = b.state(q), t = b.state(tilted);
  EXPECT_CLOSE(t.load, a.load, 1e-12);
  EXPECT_CLOSE(t.max_element_load, a.max_element_load, 1e-12);
  const double scale = a.stiffness.cwiseAbs().maxCoeff();
  EXPECT_GT(scale, 0.0);
  const double tilt_columns = t.stiffness.rightCols<2>().cwiseAbs().maxCoeff();
  const double tilt_rows = t.stiffness.bottomRows<2>().cwiseAbs().maxCoeff();
  EXPECT_LT(tilt_columns, 1e-12 * scale);
  EXPECT_LT(tilt_rows, 1e-12 * scale);
  // Tilts are wired: the bearing's tapered twin (one row at the same angle) has tilt stiffness.
  RollingBearingGeometry twin = spherical();
  twin.type = RollingBearingType::kTaperedRoller;
  Matrix5 K;
  Vector5 F;
  RollingBearing(twin).evaluate(q, F, &K);
  EXPECT_GT(K(3, 3), 0.0);
}

TEST(SphericalRollerBearing, AxialDisplacementIsTheClosedForm) {
  // Zero clearance, straight rollers, q = (0, 0, u, 0, 0): only the row at +x touches, slice k
  // of every roller at φ_k = α₀ + s_k/R_e approaches by u sin φ_k, so
  // F_x = Z c_s Σ_k (u sin φ_k)^{10/9} sin φ_k and F_y = F_z = 0 (ISO/TS 16281 eq. 40 per
  // slice). R_e = d_m/(2 cos α₀) + D_we/2. Closed form evaluated another way: 1e-12.
  RollingBearingGeometry g = spherical();
  g.clearance = 0.0;
  g.profile = RollerProfile::kStraight;
  const RollingBearing b(g);
  const double u = 12e-6;
  Vector5 q = Vector5::Zero();
  q(2) = u;
  const RollingBearingState s = b.state(q);
  const double R = 0.5 * g.pitch_diameter / std::cos(g.contact_angle) + 0.5 * g.element_diameter;
  EXPECT_CLOSE(g.outerRacewayRadius(), R, 1e-15);
  double sum = 0.0, roller = 0.0;  // Σ_k δ_k^{10/9} sin φ_k and Σ_k δ_k^{10/9}
  for (int k = 0; k < g.slices; ++k) {
    const double phi =
        g.contact_angle + (k - 0.5 * g.slices + 0.5) * g.roller_length / g.slices / R;
    sum += std::pow(u * std::sin(phi), 10.0 / 9.0) * std::sin(phi);
    roller += std::pow(u * std::sin(phi), 10.0 / 9.0);
  }
  EXPECT_CLOSE(s.load(2), g.elements * b.sliceStiffness() * sum, 1e-12);
  EXPECT_LT(s.load.head<2>().norm(), 1e-12 * s.load(2));
  for (const RollingElementState& e : s.elements) {
    if (e.row == 0) EXPECT_EQ(e.load, 0.0);
    if (e.row == 1) EXPECT_CLOSE(e.load, b.sliceStiffness() * roller, 1e-12);
  }
}

TEST(SphericalRollerBearing, HalfLoadZoneIsSjovallsRadialIntegral) {
  // Zero clearance, one slice, pure radial displacement δ_r: roller j of each row is loaded
  // Q_j = Q_max cos^{10/9} ψ_j over half the circle, and F_r = 2 Z Q_max cos α₀ J_r(0.5) with
  // J_r(0.5) = (1/2π) ∫ cos^{n+1} ψ dψ over the loaded half = Γ((n+2)/2) / (2√π Γ((n+3)/2)).
  // With Harris's line-contact exponent n = 1.1 the formula gives his printed 0.2453 (Harris &
  // Kotzalas 2006, vol. 1 Table 7.1, ε = 0.5; ± 5e-5 printed precision); the bearing with 200
  // rollers gives the integral for ISO's n = 10/9 to 5e-5 (the kink of cos^n at ±90°). The
  // rows' axial forces cancel (an X pair symmetric about the centre).
  auto jr = [](double n) {
    return std::tgamma((n + 2) / 2) / (2.0 * std::sqrt(kPi) * std::tgamma((n + 3) / 2));
  };
  EXPECT_NEAR(jr(1.1), 0.2453, 5e-5);
  RollingBearingGeometry g = spherical();
  g.elements = 200;
  g.element_diameter = 2e-3;
  g.pitch_diameter = 200e-3;
  g.roller_length = 2e-3;
  g.clearance = 0.0;
  g.profile = RollerProfile::kStraight;
  g.slices = 1;
  const RollingBearing b(g);
  Vector5 q = Vector5::Zero();
  q(0) = 20e-6;
  const RollingBearingState s = b.state(q);
  const double q_max = b.sliceStiffness() * std::pow(q(0) * std::cos(g.contact_angle), 10.0 / 9.0);
  EXPECT_CLOSE(s.max_element_load, q_max, 1e-12);
  EXPECT_CLOSE(s.load(0) / (2.0 * g.elements * q_max * std::cos(g.contact_angle)), jr(10.0 / 9.0),
               5e-5);
  EXPECT_LT(std::abs(s.load(2)), 1e-12 * s.load(0));
}

TEST(SphericalRollerBearing, SolveFindsTheLoadedState) {
  const RollingBearing b(spherical());
  Vector5 load;
  load << 8e3, -3e3, 2.5e3, 0.0, 0.0;  // radial 8.5 kN, axial 2.5 kN (e ≈ 0.3 of a 222 series)
  const RollingBearingSolveResult r = b.solve(load);
  ASSERT_EQ(r.status, "converged") << r.residual;
  EXPECT_CLOSE(r.state.load, load, 0.0, 1e-9 * load.norm());
  EXPECT_GT(r.state.rating_life, 0.0);
  // The +x row takes the thrust: it carries more than the −x row (which, with the clearance,
  // may carry nothing).
  double row_load[2] = {0.0, 0.0};
  for (const RollingElementState& e : r.state.elements) row_load[e.row] += e.load;
  EXPECT_GT(row_load[1], row_load[0]);
}

TEST(SphericalRollerBearing, ArrangementOtherThanSingleNamesTheKey) {
  RollingBearingGeometry g = spherical();
  g.arrangement = BearingArrangement::kBackToBack;
  try {
    RollingBearing b(g, "bearings.s");
    FAIL() << "accepted a paired spherical roller bearing";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "bearings.s.arrangement");
  }
  g = spherical();
  g.contact_angle = 0.0;
  EXPECT_THROW(RollingBearing(g, "bearings.s"), InputError);
}

}  // namespace
}  // namespace geardyn
