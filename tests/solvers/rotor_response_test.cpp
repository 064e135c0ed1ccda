/// Lateral geared rotor responses: the frequency-domain solution satisfies the equations of
/// motion exactly and the runout response is the closed form η = −w (its time domain, the
/// gearbox recorded by Dormand–Prince, is tested against it in train_dormand_prince_test.cpp).

#include "geardyn/solvers/rotor_response.h"

#include <gtest/gtest.h>

#include <cmath>

namespace geardyn {
namespace {

using Complex = std::complex<double>;

const RotorWhirlResponse& find(const std::vector<RotorWhirlResponse>& parts,
                               const std::string& name) {
  for (const auto& p : parts)
    if (p.name == name) return p;
  throw std::runtime_error("no component " + name);
}

TEST(RotorFrequencyResponse, SatisfiesTheEquationsOfMotion) {
  // Residual M η̈ + C η̇ + K η − f(t) of the superposed solution, derivatives exact (jΩ p).
  const LateralRotorModel model(raoTable41Spec());
  const auto parts = solveRotorFrequencyResponse(model);
  for (double t : {0.0, 0.0021, 0.5, 3.3}) {
    Eigen::Vector4d eta = Eigen::Vector4d::Zero(), rate = eta, acc = eta;
    for (const auto& p : parts) {
      const Complex e = std::polar(1.0, p.omega * t);
      for (int s = 0; s < 2; ++s) {
        const Complex z = p.response(s) * e, dz = Complex(0, p.omega) * z,
                      ddz = -p.omega * p.omega * z;
        eta(2 * s) += z.real(), eta(2 * s + 1) += z.imag();
        rate(2 * s) += dz.real(), rate(2 * s + 1) += dz.imag();
        acc(2 * s) += ddz.real(), acc(2 * s + 1) += ddz.imag();
      }
    }
    const Eigen::Vector4d f = model.force(t);
    const Eigen::Vector4d r =
        model.mass() * acc + model.damping() * rate + model.stiffness() * eta - f;
    // Forces of ~1e4 N (k_m e_m) cancel: relative round-off of a few 1e-16 × condition.
    EXPECT_LT(r.cwiseAbs().maxCoeff(), 1e-9 * f.cwiseAbs().maxCoeff()) << t;
  }
}

TEST(RotorFrequencyResponse, RunoutResponseIsTheOffsetCircle) {
  // Shafts, dampers and masses act on the gear centres, so the runout response is η = −w
  // exactly: a pinion circle −e_p e^{−jφ_p} (backward in the probe frame) and a gear circle
  // −e_g e^{jφ_g} (forward); none on the other shaft (thesis §4.4, Fig. 4.2).
  const LateralRotorModel model(raoTable41Spec());
  const auto& s = model.spec();
  const auto parts = solveRotorFrequencyResponse(model);
  const auto& p = find(parts, "pinion_1x_bwd");
  const auto& g = find(parts, "gear_1x_fwd");
  EXPECT_LT(std::abs(p.response(0) + s.pinion_runout * std::polar(1.0, -s.pinion_runout_phase)),
            1e-15);
  EXPECT_LT(std::abs(p.response(1)), 1e-12 * s.pinion_runout);
  EXPECT_LT(std::abs(g.response(1) + s.gear_runout * std::polar(1.0, s.gear_runout_phase)), 1e-15);
  EXPECT_LT(std::abs(g.response(0)), 1e-12 * s.gear_runout);
  EXPECT_EQ(std::abs(find(parts, "pinion_1x_fwd").response(0)), 0.0);
  EXPECT_EQ(std::abs(find(parts, "gear_1x_bwd").response(1)), 0.0);
}

TEST(RotorFrequencyResponse, StaticDeflectionClosedForm) {
  // Gravity only: y = −K₂⁻¹ (m₁g, m₂g); mean TE only: x₁ − x₂ follows from the series springs.
  LateralRotorSpec spec = raoTable41Spec();
  spec.mean_te = 0.0;
  const auto& st = find(solveRotorFrequencyResponse(LateralRotorModel(spec)), "static");
  const double k1 = spec.pinion_shaft_stiffness, k2 = spec.gear_shaft_stiffness,
               km = spec.mesh_stiffness, g = spec.gravity;
  const double det = (k1 + km) * (k2 + km) - km * km;
  const double y1 = -((k2 + km) * spec.pinion_mass * g + km * spec.gear_mass * g) / det;
  const double y2 = -(km * spec.pinion_mass * g + (k1 + km) * spec.gear_mass * g) / det;
  EXPECT_NEAR(st.response(0).imag(), y1, 1e-12 * std::abs(y1));
  EXPECT_NEAR(st.response(1).imag(), y2, 1e-12 * std::abs(y2));
  EXPECT_NEAR(st.response(0).real(), 0.0, 1e-20);
  spec = raoTable41Spec();
  spec.gravity = 0.0;
  const auto& te = find(solveRotorFrequencyResponse(LateralRotorModel(spec)), "static");
  // F = k_m (e_m − (x₁ − x₂)) on the pinion, x₁ = F/k₁, x₂ = −F/k₂.
  const double f = km * spec.mean_te / (1.0 + km / k1 + km / k2);
  EXPECT_NEAR(te.response(0).real(), f / k1, 1e-12 * f / k1);
  EXPECT_NEAR(te.response(1).real(), -f / k2, 1e-12 * f / k2);
  EXPECT_NEAR(te.response(0).imag(), f / k1, 1e-12 * f / k1);
}

}  // namespace
}  // namespace geardyn
