#include "geardyn/stiffness/iso6336_stiffness.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "geardyn/error.h"

namespace geardyn {
namespace {

/// ISO 6336-1:2006 Table 8 (eq. 71): q′ = C1 + C2/z_n1 + C3/z_n2 + C4 x1 + C5 x1/z_n1 + C6 x2 +
/// C7 x2/z_n2 + C8 x1² + C9 x2².
constexpr double kC[9] = {0.04723,  0.15551,  0.25791, -0.00635, -0.11654,
                          -0.00193, -0.24188, 0.00529, 0.00182};
constexpr double kSteelModulus = 206e9;  // [Pa], ISO's reference

}  // namespace

Iso6336Stiffness iso6336Stiffness(int z1, double z2, double x1, double x2, double helix_angle,
                                  double base_helix_angle, double pressure_angle,
                                  double dedendum_coefficient, double normal_module,
                                  double face_width, double contact_ratio_transverse,
                                  double youngs1, double youngs2, const Iso6336Options& options) {
  Iso6336Stiffness s;
  const double beta = std::abs(helix_angle);
  const double cb2 = std::pow(std::cos(base_helix_angle), 2);
  s.zn1 = z1 / (cb2 * std::cos(beta));
  s.zn2 = z2 / (cb2 * std::cos(beta));
  s.q_prime = kC[0] + kC[1] / s.zn1 + kC[2] / s.zn2 + kC[3] * x1 + kC[4] * x1 / s.zn1 + kC[5] * x2 +
              kC[6] * x2 / s.zn2 + kC[7] * x1 * x1 + kC[8] * x2 * x2;
  s.c_prime_th = 1.0 / s.q_prime;
  s.c_m = options.c_m;
  s.c_r = 1.0;
  if (options.web_width && options.rim_thickness) {
    // ISO eq. 78 with b_s/b limited to [0.2, 1.2] and s_R/m_n to [1, ∞).
    const double ratio = std::clamp(*options.web_width / face_width, 0.2, 1.2);
    const double rim = std::max(*options.rim_thickness / normal_module, 1.0);
    s.c_r = 1.0 + std::log(ratio) / (5.0 * std::exp(rim / 5.0));
  }
  const double alpha_deg = pressure_angle * 180.0 / std::numbers::pi;
  s.c_b = (1.0 + 0.5 * (1.2 - dedendum_coefficient)) * (1.0 - 0.02 * (20.0 - alpha_deg));
  s.material_factor = options.material_factor
                          ? (2.0 * youngs1 * youngs2 / (youngs1 + youngs2)) / kSteelModulus
                          : 1.0;
  s.c_prime = s.c_prime_th * s.c_m * s.c_r * s.c_b * std::cos(beta) * s.material_factor;
  s.c_gamma_alpha = s.c_prime * (0.75 * contact_ratio_transverse + 0.25);
  s.c_gamma_beta = 0.85 * s.c_gamma_alpha;
  s.face_width = face_width;
  return s;
}

Iso6336Stiffness iso6336Stiffness(const GearPair& pair, const Iso6336Options& options) {
  const GearSpec& g1 = pair.spec().pinion;
  const GearSpec& g2 = pair.spec().gear;
  if (!(options.c_m > 0.0) || !std::isfinite(options.c_m)) {
    throw InputError("c_m", fmt::format("{:g}", options.c_m), "must be finite and > 0");
  }
  return iso6336Stiffness(g1.teeth, g2.teeth, g1.profile_shift, g2.profile_shift, g1.helix_angle,
                          pair.baseHelixAngle(), g1.normal_pressure_angle, g1.dedendum_coefficient,
                          g1.normal_module, pair.effectiveFaceWidth(),
                          pair.contactRatioTransverse(), g1.youngs_modulus, g2.youngs_modulus,
                          options);
}

Iso6336Stiffness iso6336Stiffness(const InternalGearPair& pair, const GearSpec& pinion,
                                  const GearSpec& ring, const Iso6336Options& options) {
  if (!(options.c_m > 0.0) || !std::isfinite(options.c_m)) {
    throw InputError("c_m", fmt::format("{:g}", options.c_m), "must be finite and > 0");
  }
  return iso6336Stiffness(
      pinion.teeth, std::numeric_limits<double>::infinity(), pinion.profile_shift,
      ring.profile_shift, pinion.helix_angle, pair.baseHelixAngle(), pinion.normal_pressure_angle,
      pinion.dedendum_coefficient, pinion.normal_module,
      std::min(pinion.face_width, ring.face_width), pair.contactRatioTransverse(),
      pinion.youngs_modulus, ring.youngs_modulus, options);
}

}  // namespace geardyn
