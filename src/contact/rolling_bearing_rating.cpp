/// Rolling bearing geometry checks, names and the ISO/TS 16281 reference rating life
/// (rolling_bearing.h).

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "geardyn/contact/rolling_bearing.h"
#include "geardyn/error.h"

namespace geardyn {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

void requirePositive(double v, const std::string& key, const char* unit) {
  if (!(v > 0.0) || !std::isfinite(v)) {
    throw InputError(key, fmt::format("{:g} {}", v, unit),
                     fmt::format("a finite value > 0 {}", unit));
  }
}

}  // namespace

std::string toString(RollingBearingType type) {
  switch (type) {
    case RollingBearingType::kDeepGrooveBall:
      return "deep_groove_ball";
    case RollingBearingType::kAngularContactBall:
      return "angular_contact_ball";
    case RollingBearingType::kCylindricalRoller:
      return "cylindrical_roller";
    case RollingBearingType::kTaperedRoller:
      return "tapered_roller";
    case RollingBearingType::kSphericalRoller:
      return "spherical_roller";
  }
  return "?";
}

std::string toString(BearingArrangement arrangement) {
  switch (arrangement) {
    case BearingArrangement::kSingle:
      return "single";
    case BearingArrangement::kBackToBack:
      return "back_to_back";
    case BearingArrangement::kFaceToFace:
      return "face_to_face";
  }
  return "?";
}

std::string toString(RollerProfile profile) {
  switch (profile) {
    case RollerProfile::kStraight:
      return "straight";
    case RollerProfile::kCrowned:
      return "crowned";
    case RollerProfile::kLogarithmic:
      return "logarithmic";
  }
  return "?";
}

double RollingBearingGeometry::outerRacewayRadius() const noexcept {
  return 0.5 * pitch_diameter / std::cos(contact_angle) + 0.5 * element_diameter;
}

void RollingBearingGeometry::validate(const std::string& key) const {
  if (elements < 3) {
    throw InputError(key + ".elements", std::to_string(elements), "an integer >= 3");
  }
  requirePositive(element_diameter, key + ".element_diameter", "m");
  requirePositive(pitch_diameter, key + ".pitch_diameter", "m");
  // Z elements of diameter D_w fit on the pitch circle when the chord between neighbours,
  // d_m sin(π/Z), is at least D_w.
  const double chord = pitch_diameter * std::sin(kPi / elements);
  if (!(chord >= element_diameter) || !(pitch_diameter > 2.0 * element_diameter)) {
    throw InputError(
        key + ".elements", std::to_string(elements),
        fmt::format("at most {} elements of diameter {:g} m on a pitch circle of "
                    "{:g} m (neighbours' centres d_m sin(π/Z) >= D_w apart; d_m > "
                    "2 D_w)",
                    static_cast<int>(std::floor(
                        kPi / std::asin(std::min(1.0, element_diameter / pitch_diameter)))),
                    element_diameter, pitch_diameter));
  }
  const bool angled = type == RollingBearingType::kAngularContactBall ||
                      type == RollingBearingType::kTaperedRoller ||
                      type == RollingBearingType::kSphericalRoller;
  const double max_angle = ball() ? 60.0 : 45.0;
  if (angled ? !(contact_angle > 0.0 && contact_angle <= max_angle * kDeg) : contact_angle != 0.0) {
    throw InputError(
        key + ".contact_angle", fmt::format("{:g} deg", contact_angle / kDeg),
        angled ? fmt::format("in (0, {:g}] deg for a {} bearing", max_angle, toString(type))
               : fmt::format("0 for a {} bearing (a deep-groove bearing's contact "
                             "angle follows from its clearance and load)",
                             toString(type)));
  }
  if (type == RollingBearingType::kSphericalRoller && arrangement != BearingArrangement::kSingle) {
    throw InputError(key + ".arrangement", toString(arrangement),
                     "single: a spherical roller bearing is two rows by construction (their "
                     "spacing follows from the contact angle)");
  }
  if (ball()) {
    for (auto [r, name] : {std::pair{inner_groove_radius, ".inner_groove_radius"},
                           std::pair{outer_groove_radius, ".outer_groove_radius"}}) {
      if (!(r > 0.5 * element_diameter) || !(r < element_diameter)) {
        throw InputError(key + name, fmt::format("{:g} m", r),
                         fmt::format("a groove radius in ({:g}, {:g}) m: above the ball radius "
                                     "D_w/2 (osculation f = r/D_w in (0.5, 1))",
                                     0.5 * element_diameter, element_diameter));
      }
    }
  } else {
    requirePositive(roller_length, key + ".roller_length", "m");
    if (slices < 1 || slices > 200) {
      throw InputError(key + ".slices", std::to_string(slices), "an integer in [1, 200]");
    }
    if (profile == RollerProfile::kCrowned &&
        !(crown_drop >= 0.0 && crown_drop < 0.01 * roller_length)) {
      throw InputError(
          key + ".crown_drop", fmt::format("{:g} m", crown_drop),
          fmt::format("in [0, {:g}) m (1 % of the roller length)", 0.01 * roller_length));
    }
  }
  // A preload from interference fits compresses each contact by a few µm at most; beyond
  // 0.2 % of the element diameter the contacts would be past their elastic range.
  const double min_clearance = -2e-3 * element_diameter;
  if (!std::isfinite(clearance) || clearance < min_clearance) {
    throw InputError(key + ".clearance", fmt::format("{:g} m", clearance),
                     fmt::format(">= {:g} m (a negative clearance is a preload; deeper than 0.2 % "
                                 "of the element diameter is beyond what a fit gives)",
                                 min_clearance));
  }
  if (!(row_spacing >= 0.0) || !std::isfinite(row_spacing)) {
    throw InputError(key + ".row_spacing", fmt::format("{:g} m", row_spacing),
                     "a finite value >= 0 m");
  }
  requirePositive(youngs_modulus, key + ".youngs_modulus", "Pa");
  requirePositive(element_youngs_modulus, key + ".element_youngs_modulus", "Pa");
  for (auto [v, name] : {std::pair{poisson_ratio, ".poisson_ratio"},
                         std::pair{element_poisson_ratio, ".element_poisson_ratio"}}) {
    if (!(v > -1.0 && v < 0.5)) {
      throw InputError(key + name, fmt::format("{:g}", v), "in (-1, 0.5)");
    }
  }
  if (!(dynamic_load_rating >= 0.0) || !std::isfinite(dynamic_load_rating)) {
    throw InputError(key + ".dynamic_load_rating", fmt::format("{:g} N", dynamic_load_rating),
                     "a finite value >= 0 N (0: no rating life)");
  }
}

/// ISO/TS 16281:2008 eqs. (19)–(29) for ball bearings, (47)–(65) for roller bearings (without the
/// edge-stress factor), inner ring rotating; the rows' and rings' lives combined in the
/// standard's Weibull sum. Equations as transcribed in github.com/minzhun/ISO16281.
double RollingBearing::ratingLife(const std::vector<RollingElementState>& elements,
                                  const std::vector<double>& slice_loads) const {
  const double C = g_.dynamic_load_rating;
  if (!(C > 0.0)) return 0.0;
  const double Z = g_.elements, rows = g_.rows(), D = g_.element_diameter;
  const double gamma = D * std::cos(g_.contact_angle) / g_.pitch_diameter;
  const double ca = std::cos(g_.contact_angle);
  const double ratio = (1.0 - gamma) / (1.0 + gamma);
  double sum = 0.0;
  if (g_.ball()) {
    const double ri = g_.inner_groove_radius, re = g_.outer_groove_radius;
    const double m =
        1.044 * std::pow(ratio, 1.72) * std::pow(ri / re * (2.0 * re - D) / (2.0 * ri - D), 0.41);
    const double qci =
        C / (0.407 * Z * ca * std::pow(rows, 0.7)) * std::pow(1 + std::pow(m, 10.0 / 3.0), 0.3);
    const double qce =
        C / (0.389 * Z * ca * std::pow(rows, 0.7)) * std::pow(1 + std::pow(m, -10.0 / 3.0), 0.3);
    for (int row = 0; row < rows; ++row) {
      double s3 = 0.0, s103 = 0.0;  // Σ Q³, Σ Q^{10/3} over the row
      for (const RollingElementState& e : elements) {
        if (e.row != row) continue;
        s3 += std::pow(e.load, 3.0), s103 += std::pow(e.load, 10.0 / 3.0);
      }
      const double qei = std::cbrt(s3 / Z), qee = std::pow(s103 / Z, 0.3);
      sum += std::pow(qei / qci, 10.0 / 3.0) + std::pow(qee / qce, 10.0 / 3.0);
    }
    return sum > 0.0 ? std::pow(sum, -0.9) : std::numeric_limits<double>::infinity();
  }
  const double ns = g_.slices;
  const double m = 1.038 * std::pow(ratio, 143.0 / 108.0);
  const double qci = C / (0.83 * 0.378 * Z * ca * std::pow(rows, 7.0 / 9.0)) *
                     std::pow(1 + std::pow(m, 4.5), 2.0 / 9.0) * std::pow(ns, -7.0 / 9.0);
  const double qce = C / (0.83 * 0.364 * Z * ca * std::pow(rows, 7.0 / 9.0)) *
                     std::pow(1 + std::pow(m, -4.5), 2.0 / 9.0) * std::pow(ns, -7.0 / 9.0);
  const int n = g_.slices;
  for (int row = 0; row < rows; ++row) {
    for (int k = 0; k < n; ++k) {
      double s4 = 0.0, s45 = 0.0;
      for (std::size_t j = 0; j < elements.size(); ++j) {
        if (elements[j].row != row) continue;
        const double q = slice_loads[j * n + k];
        s4 += std::pow(q, 4.0), s45 += std::pow(q, 4.5);
      }
      const double qkei = std::pow(s4 / Z, 0.25), qkee = std::pow(s45 / Z, 1.0 / 4.5);
      sum += std::pow(qkei / qci, 4.5) + std::pow(qkee / qce, 4.5);
    }
  }
  return sum > 0.0 ? std::pow(sum, -8.0 / 9.0) : std::numeric_limits<double>::infinity();
}

}  // namespace geardyn
