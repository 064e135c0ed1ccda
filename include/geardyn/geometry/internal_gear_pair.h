#pragma once
/// \file
/// An internal involute gear pair: an external pinion (a planet) inside a ring gear with
/// internal teeth. Operating centre distance and pressure angle, base and pitch radii, tip
/// radii, path of contact and contact ratios (ISO 21771:2007 with z₂ < 0, written here with
/// the ring's tooth count z_r > 0).
///
///   a = (z_r − z_p) m_t / 2,   inv α_wt = inv α_t + 2 tan α_n (x_p + x_r) / (z_p − z_r)
///   a_w = (r_br − r_bp) / cos α_wt,   r_ar = r_r − (h_a* + x_r) m_n (the ring's tip circle is
///   its inner one; x_r in ISO 21771's sign: x_r > 0 lengthens the ring's teeth inwards)
///   g_α = √(r_ap² − r_bp²) − √(r_ar² − r_br²) + a_w sin α_wt,   ε_α = g_α / p_bt.

#include <optional>
#include <string>

#include "geardyn/geometry/gear.h"

namespace geardyn {

class InternalGearPair {
 public:
  /// \param pinion the external member; \param ring the internal one (teeth > pinion teeth,
  /// same normal module and pressure angle, same helix angle and hand);
  /// \param centre_distance operating a_w [m]; absent: the zero-backlash distance.
  /// \param key_prefix configuration path of the pair for messages ("stages.s1").
  /// Throws InputError naming the key when the pair cannot mesh.
  InternalGearPair(const GearSpec& pinion, const GearSpec& ring,
                   std::optional<double> centre_distance, const std::string& key_prefix);

  double centreDistance() const noexcept { return a_w_; }               ///< a_w [m]
  double operatingPressureAngle() const noexcept { return alpha_wt_; }  ///< α_wt [rad]
  double transversePressureAngle() const noexcept { return alpha_t_; }  ///< α_t [rad]
  double baseHelixAngle() const noexcept { return beta_b_; }            ///< β_b [rad] >= 0
  double pinionBaseRadius() const noexcept { return rb_p_; }            ///< [m]
  double ringBaseRadius() const noexcept { return rb_r_; }              ///< [m]
  double pinionTipRadius() const noexcept { return ra_p_; }             ///< [m]
  double ringTipRadius() const noexcept { return ra_r_; }               ///< inner tip circle [m]
  double basePitchTransverse() const noexcept { return p_bt_; }         ///< [m]
  double pathOfContactLength() const noexcept { return g_alpha_; }      ///< g_α [m]
  double contactRatioTransverse() const noexcept { return eps_alpha_; }
  double overlapRatio() const noexcept { return eps_beta_; }

 private:
  double a_w_ = 0, alpha_wt_ = 0, alpha_t_ = 0, beta_b_ = 0, rb_p_ = 0, rb_r_ = 0;
  double ra_p_ = 0, ra_r_ = 0, p_bt_ = 0, g_alpha_ = 0, eps_alpha_ = 0, eps_beta_ = 0;
};

}  // namespace geardyn
