#include "geardyn/stiffness/tooth_beam.h"

#include <fmt/format.h>

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/geometry/involute.h"

namespace geardyn {
namespace {

/// Sainsot, Velex & Duverger (2004) fillet-foundation fit X* = A/θ_f² + B h_fi² + C h_fi/θ_f +
/// D/θ_f + E h_fi + F for X = L, M, P, Q (shared/reference/mesh_stiffness.md).
constexpr double kSainsot[4][6] = {
    {-5.574e-5, -1.9986e-3, -2.3015e-4, 4.7702e-3, 0.0271, 6.8045},    // L*
    {60.111e-5, 28.100e-3, -83.431e-4, -9.9256e-3, 0.1624, 0.9086},    // M*
    {-50.952e-5, 185.50e-3, 0.0538e-4, 53.300e-3, 0.2895, 0.9236},     // P*
    {-6.2042e-5, 9.0889e-3, -4.0964e-4, 7.8297e-3, -0.1472, 0.6904}};  // Q*
/// Ranges over which the fit was made (same reference); outside them we warn.
constexpr double kSainsotRange[4][2] = {{6.82, 6.94}, {1.08, 3.29}, {2.56, 13.47}, {0.141, 0.62}};

/// Composite Gauss–Legendre over [a, b]: 20 points per panel, 3 panels (the integrands are
/// smooth; 60 points give ~1e-13 relative accuracy, checked against direct integration).
template <typename F>
double gaussLegendre(const F& f, double a, double b) {
  constexpr int kPanels = 3;
  const double width = (b - a) / kPanels;
  double total = 0.0;
  for (int p = 0; p < kPanels; ++p) {
    total += boost::math::quadrature::gauss<double, 20>::integrate(f, a + p * width,
                                                                   a + (p + 1) * width);
  }
  return total;
}

}  // namespace

double hertzStiffnessPerWidth(double youngs1, double poisson1, double youngs2, double poisson2) {
  return std::numbers::pi /
         (2.0 * ((1.0 - poisson1 * poisson1) / youngs1 + (1.0 - poisson2 * poisson2) / youngs2));
}

ToothBeam::ToothBeam(const GearPair& pair, Member member, ToothRoot root, FoundationArm arm,
                     bool foundation, double hub_radius)
    : root_(root), arm_(arm), foundation_(foundation) {
  const bool is_pinion = member == Member::kPinion;
  const GearSpec& spec = is_pinion ? pair.spec().pinion : pair.spec().gear;
  const GearGeometry& g = is_pinion ? pair.pinion() : pair.gear();
  const std::string name = is_pinion ? "pinion" : "gear";
  rb_ = g.base_radius;
  rf_ = g.root_radius;
  youngs_ = spec.youngs_modulus;
  poisson_ = spec.poisson_ratio;
  // α₂ = half the tooth angle at the base circle; π/(2z) + inv α for unshifted teeth.
  alpha2_ = involuteHalfAngle(pair, member, rb_);

  if (root == ToothRoot::kStraight) {
    if (rb_ > rf_) {
      // Ma et al. 2014: a rectangle of the base-circle half-thickness h_b = r_b sin α₂ down to
      // the root circle, where it meets it at α₃ = asin(r_b sin α₂ / r_f).
      involute_start_roll_ = 0.0;
      straight_half_thickness_ = rb_ * std::sin(alpha2_);
      theta_f_ = std::asin(straight_half_thickness_ / rf_);
      straight_length_ = rb_ * std::cos(alpha2_) - rf_ * std::cos(theta_f_);
    } else {
      // The involute reaches down to the root circle.
      involute_start_roll_ = std::sqrt(rf_ * rf_ / (rb_ * rb_) - 1.0);
      theta_f_ = alpha2_ - involute(std::acos(rb_ / rf_));
    }
  } else {
    // The rack-generated fillet: involute down to the form circle, then the profile's fillet.
    const ToothProfile profile = computeToothProfile(pair, member, 200);
    involute_start_roll_ = std::sqrt(std::max(0.0, std::pow(profile.form_radius / rb_, 2) - 1.0));
    std::vector<double> ys, hs;  // fillet from the root circle up to the form circle
    bool on_flank = false;
    for (const auto& p : profile.points) {
      const double radius = p.norm();
      if (!on_flank && radius <= rf_ * (1.0 + 1e-12)) continue;  // the root-circle arc
      on_flank = true;
      if (radius > profile.form_radius * (1.0 + 1e-12)) break;
      const double angle = std::atan2(p.x(), p.y());
      ys.push_back(radius * std::cos(angle));
      hs.push_back(radius * std::sin(angle));
    }
    if (ys.size() < 2) throw std::logic_error("tooth profile without a fillet");
    theta_f_ = std::atan2(hs.front(), ys.front());
    // Height of the involute's lower end: y(α) = r_b [cos α − (α₂ − α) sin α] at α = α₂ − roll.
    fillet_top_y_ = rb_ * (std::cos(alpha2_ - involute_start_roll_) -
                           involute_start_roll_ * std::sin(alpha2_ - involute_start_roll_));
    // Moments by the trapezoidal rule on the (dense) profile polyline.
    for (std::size_t i = 0; i + 1 < ys.size(); ++i) {
      const double dy = ys[i + 1] - ys[i];
      const auto at = [&](std::size_t k, int power) {
        const double inertia = (2.0 / 3.0) * hs[k] * hs[k] * hs[k];
        return std::pow(ys[k] - fillet_top_y_, power) / inertia;
      };
      for (int power = 0; power < 3; ++power) {
        fillet_inertia_moments_[power] += 0.5 * dy * (at(i, power) + at(i + 1, power));
      }
      fillet_area_integral_ += 0.5 * dy * (1.0 / (2.0 * hs[i]) + 1.0 / (2.0 * hs[i + 1]));
    }
  }
  root_y_ = rf_ * std::cos(theta_f_);

  if (foundation_) {
    if (!(hub_radius > 0.0) || hub_radius >= rf_) {
      throw InputError(
          name + ".bore_diameter",
          fmt::format("{:g} m (hub radius r_int = {:g} m)", 2.0 * hub_radius, hub_radius),
          fmt::format("the fillet-foundation model (Sainsot 2004) needs the radius of the gear "
                      "body's bore, 0 < r_int < r_f = {:g} m: set {}.bore_diameter, or "
                      "mesh_stiffness.potential_energy.{}_hub_radius, or "
                      "mesh_stiffness.potential_energy.foundation = false",
                      rf_, name, name));
    }
    const double h = rf_ / hub_radius;
    const double t = theta_f_;
    static const char* const kNames[4] = {"L*", "M*", "P*", "Q*"};
    for (int x = 0; x < 4; ++x) {
      const double* c = kSainsot[x];
      lmpq_[x] = c[0] / (t * t) + c[1] * h * h + c[2] * h / t + c[3] / t + c[4] * h + c[5];
      if (lmpq_[x] < kSainsotRange[x][0] || lmpq_[x] > kSainsotRange[x][1]) {
        extrapolated_ +=
            fmt::format("{}{} = {:.5g} (data {} to {})", extrapolated_.empty() ? "" : ", ",
                        kNames[x], lmpq_[x], kSainsotRange[x][0], kSainsotRange[x][1]);
      }
    }
  }
}

ToothBeam ToothBeam::withFoundationFitClamped() const {
  ToothBeam clamped = *this;
  for (int x = 0; x < 4; ++x)
    clamped.lmpq_[x] = std::clamp(lmpq_[x], kSainsotRange[x][0], kSainsotRange[x][1]);
  clamped.extrapolated_.clear();
  return clamped;
}

ToothCompliance ToothBeam::compliance(double roll) const {
  const double a2 = alpha2_;
  const double a1 = roll - a2;  // angle between the force and the normal to the centreline
  const double c1 = std::cos(a1), s1 = std::sin(a1);
  const double e = youngs_;
  const double shear_modulus = e / (2.0 * (1.0 + poisson_));
  ToothCompliance out;

  // Involute part, α from −α₁ (contact) to α₂ − roll_start (lower end of the involute).
  const double lower = -a1;
  const double upper = a2 - involute_start_roll_;
  if (upper > lower) {
    out.bending = gaussLegendre(
        [&](double a) {
          const double w = (a2 - a);
          const double m = 1.0 + c1 * (w * std::sin(a) - std::cos(a));
          const double h = std::sin(a) + w * std::cos(a);
          return 3.0 * m * m * w * std::cos(a) / (2.0 * e * h * h * h);
        },
        lower, upper);
    const double thickness_integral = gaussLegendre(
        [&](double a) {
          const double w = (a2 - a);
          return w * std::cos(a) / (std::sin(a) + w * std::cos(a));
        },
        lower, upper);
    out.shear = 1.2 * (1.0 + poisson_) * c1 * c1 * thickness_integral / e;
    out.axial = s1 * s1 * thickness_integral / (2.0 * e);
  }

  if (root_ == ToothRoot::kStraight && straight_length_ > 0.0) {
    // Rectangle below the base circle (reference eqs. "between base circle and root circle").
    const double x1 = straight_length_;
    const double hb = straight_half_thickness_;
    const double inertia = (2.0 / 3.0) * hb * hb * hb;
    const double area = 2.0 * hb;
    const double e0 = rb_ * (1.0 - c1 * std::cos(a2));  // moment arm at the base circle
    out.bending +=
        (x1 * e0 * e0 + x1 * x1 * e0 * c1 + x1 * x1 * x1 * c1 * c1 / 3.0) / (e * inertia);
    out.shear += 1.2 * c1 * c1 * x1 / (shear_modulus * area);
    out.axial += s1 * s1 * x1 / (e * area);
  } else if (root_ == ToothRoot::kTrochoid) {
    // M/F = cos α₁ (y_c − y) − sin α₁ h_c = B − cos α₁ (y − y₀) over the fillet.
    const double y_c = rb_ * (c1 + (a1 + a2) * s1);
    const double h_c = rb_ * ((a1 + a2) * c1 - s1);
    const double b = c1 * (y_c - fillet_top_y_) - s1 * h_c;
    const auto& m = fillet_inertia_moments_;
    // The moments run from the root upward (dy > 0), the beam energy is positive.
    out.bending += (b * b * m[0] - 2.0 * b * c1 * m[1] + c1 * c1 * m[2]) / e;
    out.shear += 1.2 * c1 * c1 * fillet_area_integral_ / shear_modulus;
    out.axial += s1 * s1 * fillet_area_integral_ / e;
  }

  if (foundation_) {
    const double u = arm_ == FoundationArm::kForceLine ? rb_ / c1 - root_y_
                                                       : rb_ * (c1 + (a1 + a2) * s1) - root_y_;
    const double ratio = u / (2.0 * rf_ * theta_f_);
    const double t1 = s1 / c1;
    out.foundation =
        c1 * c1 / e *
        (lmpq_[0] * ratio * ratio + lmpq_[1] * ratio + lmpq_[2] * (1.0 + lmpq_[3] * t1 * t1));
  }
  return out;
}

}  // namespace geardyn
