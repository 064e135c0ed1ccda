/// Mesh misalignment from the static deflection (system/mesh_misalignment.h) against a hand
/// calculation: each shaft of the flexible two-stage reducer's second stage as a beam on two
/// elastic supports (the bearings' radial and tilt springs), loaded by the mesh forces of the
/// static solution; closed-form (Macaulay) bending with the Timoshenko shear term.

#include "geardyn/system/mesh_misalignment.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "geardyn/config/gearbox_config.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn {
namespace {

GearTrainSpec flexibleExample() {
  const config::Config config = config::loadConfigFile(
      std::string(GEARDYN_SOURCE_DIR "/examples/gearboxes/two_stage_reducer_flexible.toml"),
      config::gearboxSchema());
  std::vector<std::string> warnings;
  return config::gearTrainFromConfig(config, warnings);
}

/// A point force P [N] (along +w) or couple C [N m] (turning in the +dw/dx sense) at distance
/// a from the left support.
struct BeamLoad {
  double a = 0.0, P = 0.0, C = 0.0;
};

/// A uniform beam between supports at 0 and L with translational springs k_a, k_b [N/m] and
/// tilt springs k_t [N m/rad] at both: the section rotation θ(x) and the deflection w(x).
/// Macaulay: EI w_EB'' = R_a x + Σ P⟨x−a⟩ − Σ C H(x−a) with the reactions from equilibrium
/// (R_b = −(Σ P a + Σ C)/L, R_a = −Σ P − R_b) and w_EB(0) = w_EB(L) = 0; Timoshenko's section
/// rotation θ = w_EB' + ∫₀ᴸ V dx / (κGA L) (w' = θ − V/κGA, V = R_a + Σ_{a<x} P), plus the rigid
/// motion of the spring supports (w_s = −R/k). The tilt springs' couples C_a = −k_t θ(0),
/// C_b = −k_t θ(L) are solved for (the problem is linear in them).
struct ElasticBeam {
  double L, EI, kGA, k_a, k_b, k_t;

  void evaluate(std::vector<BeamLoad> loads, double Ca, double Cb, double x, double& theta,
                double& w) const {
    loads.push_back({0.0, 0.0, Ca});
    loads.push_back({L, 0.0, Cb});
    double sum_p = 0, sum_pa = 0, sum_c = 0;
    for (const auto& l : loads) sum_p += l.P, sum_pa += l.P * l.a, sum_c += l.C;
    const double Rb = -(sum_pa + sum_c) / L, Ra = -sum_p - Rb;
    const auto mac = [](double v, int n) { return v > 0.0 ? std::pow(v, n) : 0.0; };
    double wL = Ra * L * L * L / 6, shear_integral = Ra * L;
    for (const auto& l : loads) {
      wL += l.P * mac(L - l.a, 3) / 6 - l.C * mac(L - l.a, 2) / 2;
      shear_integral += l.P * (L - l.a);
    }
    const double e = -wL / L;
    double slope = Ra * x * x / 2 + e, defl = Ra * x * x * x / 6 + e * x, shear = Ra * x;
    for (const auto& l : loads) {
      slope += l.P * mac(x - l.a, 2) / 2 - l.C * mac(x - l.a, 1);
      defl += l.P * mac(x - l.a, 3) / 6 - l.C * mac(x - l.a, 2) / 2;
      shear += l.P * mac(x - l.a, 1);
    }
    const double k0 = shear_integral / (kGA * L);
    const double wa = -Ra / k_a, wb = -Rb / k_b;
    theta = slope / EI + k0 + (wb - wa) / L;
    w = defl / EI + k0 * x - shear / kGA + wa + (wb - wa) * x / L;
  }

  void solve(const std::vector<BeamLoad>& loads, double x, double& theta, double& w) const {
    // θ at the supports is affine in (C_a, C_b): three evaluations give it.
    double t0[2], t1[2], t2[2], dummy;
    evaluate(loads, 0, 0, 0.0, t0[0], dummy), evaluate(loads, 0, 0, L, t0[1], dummy);
    evaluate(loads, 1, 0, 0.0, t1[0], dummy), evaluate(loads, 1, 0, L, t1[1], dummy);
    evaluate(loads, 0, 1, 0.0, t2[0], dummy), evaluate(loads, 0, 1, L, t2[1], dummy);
    // C_a + k_t θ(0) = 0, C_b + k_t θ(L) = 0.
    Eigen::Matrix2d A;
    A << 1 + k_t * (t1[0] - t0[0]), k_t * (t2[0] - t0[0]), k_t * (t1[1] - t0[1]),
        1 + k_t * (t2[1] - t0[1]);
    const Eigen::Vector2d c = A.lu().solve(Eigen::Vector2d(-k_t * t0[0], -k_t * t0[1]));
    evaluate(loads, c(0), c(1), x, theta, w);
  }
};

TEST(MeshMisalignment, TwoStageFlexibleExampleMatchesBeamHandCalculation) {
  const GearTrainModel model(flexibleExample());
  const TrainStaticResult st = solveTrainStatic(model, model.inputSpeed());
  ASSERT_EQ(st.status, "ok") << st.message;
  const auto mis = meshMisalignment(model, st.displacement);
  ASSERT_EQ(mis.size(), 2u);
  const GearTrainSpec& spec = model.spec();

  // The loads each mesh puts on a node: −F_m v over its DOFs (y, z, θ_x, x, θ_y, θ_z).
  const auto loadsOn = [&](const std::string& shaft, double x0, int plane) {
    std::vector<BeamLoad> loads;
    for (std::size_t m = 0; m < model.meshes().size(); ++m) {
      const TrainMesh& mesh = model.meshes()[m];
      for (std::size_t i = 0; i < mesh.dofs.size(); ++i) {
        const int body = mesh.dofs[i] / 6, d = mesh.dofs[i] % 6;
        const TrainBody& b = model.bodies()[body];
        EXPECT_EQ(b.first_dof, mesh.dofs[i] - d);
        if (b.shaft < 0 || spec.shafts[b.shaft].name != shaft) continue;
        const double f = -st.mesh_force[m] * mesh.gradient[i];
        // Plane y: w = u_y, couple M_z; plane z: w = u_z, couple −M_y (θ_y = −du_z/dx).
        if (plane == 0 && d == 0) loads.push_back({b.axial - x0, f, 0.0});
        if (plane == 0 && d == 5) loads.push_back({b.axial - x0, 0.0, f});
        if (plane == 1 && d == 1) loads.push_back({b.axial - x0, f, 0.0});
        if (plane == 1 && d == 4) loads.push_back({b.axial - x0, 0.0, -f});
      }
    }
    return loads;
  };
  // Slope (du_y/dx, du_z/dx) and displacement (u_y, u_z) of shaft `name` at x.
  const auto shaftAt = [&](const std::string& name, double x, Eigen::Vector2d& s,
                           Eigen::Vector2d& u) {
    const TrainShaftSpec* shaft = nullptr;
    for (const auto& sh : spec.shafts) {
      if (sh.name == name) shaft = &sh;
    }
    std::vector<const TrainBearingSpec*> bearings;
    for (const auto& b : spec.bearings) {
      if (b.shaft == name) bearings.push_back(&b);
    }
    ASSERT_TRUE(shaft && bearings.size() == 2u);
    const double d = shaft->outer_diameters[0], nu = shaft->poisson_ratio;
    const double E = shaft->youngs_modulus, G = E / (2 * (1 + nu));
    const double area = std::numbers::pi * d * d / 4, I = std::numbers::pi * std::pow(d, 4) / 64;
    const double kappa = 6 * (1 + nu) / (7 + 6 * nu);  // solid circle (Cowper 1966)
    const double xa = bearings[0]->position, xb = bearings[1]->position;
    for (int plane = 0; plane < 2; ++plane) {
      const double ka = plane == 0 ? bearings[0]->kyy : bearings[0]->kzz;
      const double kb = plane == 0 ? bearings[1]->kyy : bearings[1]->kzz;
      const ElasticBeam beam{xb - xa, E * I, kappa * G * area, ka, kb, bearings[0]->k_tilt};
      ASSERT_EQ(bearings[0]->k_tilt, bearings[1]->k_tilt);
      beam.solve(loadsOn(name, xa, plane), x - xa, s(plane), u(plane));
    }
  };

  // Stage 2: z3 on the intermediate shaft (a) drives z4 on the output shaft (b), both at 0.20 m.
  const TrainMesh& m = model.meshes()[1];
  ASSERT_EQ(m.name, "stage2");
  Eigen::Vector2d sa, ua, sb, ub;
  shaftAt("intermediate", 0.20, sa, ua);
  shaftAt("output", 0.20, sb, ub);
  const double b = mis[1].face_width;
  EXPECT_NEAR(b, 0.042, 1e-12);  // the overlap of 45 and 42 mm faces at one position
  const double fma = b * m.normal.dot(sa - sb);
  const Eigen::Vector2d p(-m.normal.y(), m.normal.x());
  const double fout = b * p.dot(sa - sb);
  const Eigen::Vector2d ab = model.bodies()[m.body_b].centre - model.bodies()[m.body_a].centre;
  const double da = ab.normalized().dot(ub - ua);
  RecordProperty("f_ma_um", std::to_string(1e6 * mis[1].mismatch));
  RecordProperty("f_ma_hand_um", std::to_string(1e6 * fma));
  // 2 %: the hand calculation is exact for the beam model up to the FE discretisation (cubic
  // Timoshenko elements are nodally exact for point loads) and the gyroscopic/centripetal
  // terms, absent at a fixed frame's statics: the difference is round-off-level in practice.
  EXPECT_NEAR(mis[1].mismatch, fma, 0.02 * std::abs(fma));
  EXPECT_NEAR(mis[1].mismatch_out_of_plane, fout, 0.02 * std::abs(fout));
  EXPECT_NEAR(mis[1].centre_distance_change, da, 0.02 * std::abs(da));
  EXPECT_GT(std::abs(fma), 1e-6) << "a misalignment of some micrometres is expected";
}

}  // namespace
}  // namespace geardyn
