#include "geardyn/geometry/gear.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/units.h"

namespace geardyn {
namespace {

using geardyn::units::kDegree;

void requireFinite(const std::string& key, double value) {
  if (!std::isfinite(value)) throw InputError(key, fmt::format("{}", value), "must be finite");
}

void requireRange(const std::string& key, double value, double low, bool low_open, double high,
                  bool high_open, const std::string& what) {
  requireFinite(key, value);
  const bool below = low_open ? value <= low : value < low;
  const bool above = high_open ? value >= high : value > high;
  if (below || above) {
    throw InputError(key, fmt::format("{:g}", value),
                     fmt::format("{} must be in {}{:g}, {:g}{}", what, low_open ? "(" : "[", low,
                                 high, high_open ? ")" : "]"));
  }
}

}  // namespace

double GearSpec::rackStraightFlankDepth() const {
  return (dedendum_coefficient -
          root_fillet_coefficient * (1.0 - std::sin(normal_pressure_angle))) *
         normal_module;
}

void GearSpec::validate(const std::string& name) const {
  const auto key = [&](const char* field) {
    return name.empty() ? std::string(field) : name + "." + field;
  };
  if (teeth < 3) {
    throw InputError(key("teeth"), std::to_string(teeth),
                     "number of teeth must be an integer >= 3");
  }
  constexpr double kInf = std::numeric_limits<double>::infinity();
  requireRange(key("module"), normal_module, 0.0, true, kInf, true, "normal module [m]");
  // Angles are validated in degrees, the unit of the configuration keys.
  requireRange(key("pressure_angle_deg"), normal_pressure_angle / kDegree, 0.0, true, 45.0, true,
               "normal pressure angle [deg]");
  requireRange(key("helix_angle_deg"), helix_angle / kDegree, -60.0, false, 60.0, false,
               "helix angle [deg]");
  requireRange(key("face_width"), face_width, 0.0, true, kInf, true, "face width [m]");
  requireRange(key("profile_shift"), profile_shift, -2.0, false, 3.0, false,
               "profile shift coefficient [-]");
  requireRange(key("addendum_coefficient"), addendum_coefficient, 0.0, true, 3.0, false,
               "addendum coefficient h_a* [-]");
  requireRange(key("dedendum_coefficient"), dedendum_coefficient, 0.0, true, 3.0, false,
               "dedendum coefficient h_f* [-]");
  requireRange(key("root_fillet_coefficient"), root_fillet_coefficient, 0.0, false, 1.0, false,
               "root fillet radius coefficient ρ_fP* [-]");
  if (rackStraightFlankDepth() <= 0.0) {
    throw InputError(key("root_fillet_coefficient"), fmt::format("{:g}", root_fillet_coefficient),
                     fmt::format("the generating rack's tip rounding ρ_fP* (1 − sin α_n) must be "
                                 "smaller than the dedendum coefficient h_f* = {:g}",
                                 dedendum_coefficient));
  }
  requireFinite(key("tip_radius_modification"), tip_radius_modification);
  requireRange(key("bore_diameter"), bore_diameter, 0.0, false, kInf, true, "bore diameter [m]");
  requireRange(key("youngs_modulus"), youngs_modulus, 0.0, true, kInf, true,
               "Young's modulus [Pa]");
  requireRange(key("poisson_ratio"), poisson_ratio, -1.0, true, 0.5, true, "Poisson's ratio [-]");
  requireRange(key("density"), density, 0.0, true, kInf, true, "density [kg/m^3]");
}

GearBodyMass gearBodyMass(const GearSpec& g) {
  const double r = 0.5 * g.teeth * g.normal_module / std::cos(g.helix_angle);
  const double r_bore = 0.5 * g.bore_diameter;
  const double b = g.face_width;
  GearBodyMass out;
  out.mass = g.density * std::numbers::pi * (r * r - r_bore * r_bore) * b;
  out.polar_inertia = 0.5 * out.mass * (r * r + r_bore * r_bore);
  out.diametral_inertia = out.mass * (3.0 * (r * r + r_bore * r_bore) + b * b) / 12.0;
  return out;
}

std::vector<std::string> plausibilityNotes(const GearSpec& gear, const std::string& name) {
  std::vector<std::string> notes;
  if (gear.normal_module < 0.1e-3 || gear.normal_module > 0.1)
    notes.push_back(fmt::format(
        "{}.module = {:g} m is outside the usual 0.1 mm to 100 mm: lengths are in metres "
        "(a 3 mm module is 0.003)",
        name, gear.normal_module));
  if (gear.face_width < 1e-3 || gear.face_width > 2.0)
    notes.push_back(fmt::format(
        "{}.face_width = {:g} m is outside the usual 1 mm to 2 m: lengths are in metres", name,
        gear.face_width));
  return notes;
}

std::string speedPlausibilityNote(double rpm, const std::string& key) {
  if (!(std::abs(rpm) > kPlausibleMaxRpm)) return {};
  return fmt::format("{} = {:g} rpm is above {:g} rpm: is it in rpm (not rad/s or Hz)?", key, rpm,
                     kPlausibleMaxRpm);
}

}  // namespace geardyn
