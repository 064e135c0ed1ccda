/// Internal gear pair geometry (ISO 21771:2007 with a negative ring tooth count).

#include "geardyn/geometry/internal_gear_pair.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/geometry/involute.h"
#include "geardyn/units.h"

namespace geardyn {
namespace {
constexpr double kDeg = geardyn::units::kDegree;
}

InternalGearPair::InternalGearPair(const GearSpec& pinion, const GearSpec& ring,
                                   std::optional<double> centre_distance,
                                   const std::string& key_prefix) {
  const std::string pkey = key_prefix + ".pinion", rkey = key_prefix + ".ring";
  pinion.validate(pkey);
  ring.validate(rkey);
  if (ring.teeth <= pinion.teeth) {
    throw InputError(rkey + ".teeth", std::to_string(ring.teeth),
                     fmt::format("a ring needs more teeth than its pinion ({})", pinion.teeth));
  }
  if (std::abs(ring.normal_module - pinion.normal_module) > 1e-9 * pinion.normal_module) {
    throw InputError(rkey + ".normal_module", fmt::format("{:g} m", ring.normal_module),
                     fmt::format("must equal the pinion's {:g} m: gears of different normal "
                                 "modules cannot mesh",
                                 pinion.normal_module));
  }
  if (std::abs(ring.normal_pressure_angle - pinion.normal_pressure_angle) > 1e-9) {
    throw InputError(
        rkey + ".pressure_angle_deg", fmt::format("{:g}", ring.normal_pressure_angle / kDeg),
        fmt::format("must equal the pinion's {:g} deg", pinion.normal_pressure_angle / kDeg));
  }
  if (std::abs(ring.helix_angle - pinion.helix_angle) > 1e-9) {
    throw InputError(rkey + ".helix_angle_deg", fmt::format("{:g}", ring.helix_angle / kDeg),
                     fmt::format("an internal pair needs the pinion's helix angle and hand "
                                 "({:g} deg)",
                                 pinion.helix_angle / kDeg));
  }
  const double m_n = pinion.normal_module, alpha_n = pinion.normal_pressure_angle;
  const double beta = std::abs(pinion.helix_angle);
  const double m_t = m_n / std::cos(beta);
  alpha_t_ = std::atan(std::tan(alpha_n) / std::cos(beta));
  beta_b_ = std::atan(std::tan(beta) * std::cos(alpha_t_));
  p_bt_ = std::numbers::pi * m_t * std::cos(alpha_t_);
  const double r_p = 0.5 * pinion.teeth * m_t, r_r = 0.5 * ring.teeth * m_t;
  rb_p_ = r_p * std::cos(alpha_t_);
  rb_r_ = r_r * std::cos(alpha_t_);
  ra_p_ = r_p + (pinion.addendum_coefficient + pinion.profile_shift) * m_n +
          pinion.tip_radius_modification;
  ra_r_ =
      r_r - (ring.addendum_coefficient + ring.profile_shift) * m_n - ring.tip_radius_modification;

  const double inv_tight = involute(alpha_t_) + 2.0 * std::tan(alpha_n) *
                                                    (pinion.profile_shift + ring.profile_shift) /
                                                    (pinion.teeth - ring.teeth);
  if (!(inv_tight > 0.0)) {
    throw InputError(rkey + ".profile_shift", fmt::format("{:g}", ring.profile_shift),
                     "the profile shifts leave no centre distance at which the teeth mesh");
  }
  const double a_tight = (rb_r_ - rb_p_) / std::cos(inverseInvolute(inv_tight));
  a_w_ = centre_distance.value_or(a_tight);
  if (!std::isfinite(a_w_) || a_w_ <= rb_r_ - rb_p_) {
    throw InputError(key_prefix + ".centre_distance", fmt::format("{:g} m", a_w_),
                     fmt::format("must exceed r_br − r_bp = {:g} m", rb_r_ - rb_p_));
  }
  alpha_wt_ = std::acos((rb_r_ - rb_p_) / a_w_);
  if (!(ra_r_ > rb_r_)) {
    throw InputError(rkey + ".addendum_coefficient", fmt::format("{:g}", ring.addendum_coefficient),
                     fmt::format("the ring's tip circle (r = {:g} m) lies inside its base circle "
                                 "(r_b = {:g} m): an involute internal tooth cannot reach it",
                                 ra_r_, rb_r_));
  }
  // Involute interference: the ring's inner tip circle must meet the line of action at or beyond
  // the pinion's tangent point T₁ (√(r_ar² − r_br²) >= a_w sin α_wt from the ring's tangent
  // point); closer, the ring's tip would cut into the pinion below its base circle.
  const double ring_tip_roll = std::sqrt(ra_r_ * ra_r_ - rb_r_ * rb_r_);
  if (ring_tip_roll < a_w_ * std::sin(alpha_wt_) * (1.0 - 1e-12)) {
    throw InputError(
        rkey + ".profile_shift", fmt::format("{:g}", ring.profile_shift),
        fmt::format("no involute interference: the ring's tip circle (d = {:g} mm) meets the line "
                    "of action {:g} mm inside the pinion's base-circle tangent point; lower the "
                    "ring's profile shift or addendum (tip circle d >= {:g} mm)",
                    2e3 * ra_r_, 1e3 * (a_w_ * std::sin(alpha_wt_) - ring_tip_roll),
                    2e3 * std::hypot(rb_r_, a_w_ * std::sin(alpha_wt_))));
  }
  g_alpha_ = std::sqrt(ra_p_ * ra_p_ - rb_p_ * rb_p_) - ring_tip_roll + a_w_ * std::sin(alpha_wt_);
  eps_alpha_ = g_alpha_ / p_bt_;
  const double b = std::min(pinion.face_width, ring.face_width);
  eps_beta_ = b * std::sin(beta) / (std::numbers::pi * m_n);
  if (!(eps_alpha_ + eps_beta_ >= 1.0)) {
    throw InputError(key_prefix + ".centre_distance", fmt::format("{:g} m", a_w_),
                     fmt::format("total contact ratio {:.3f} < 1: the pair cannot mesh "
                                 "continuously",
                                 eps_alpha_ + eps_beta_));
  }
}

}  // namespace geardyn
