/// Gearbox bearings from their geometry: keys and reader (detail/gearbox_bearing.h).

#include <fmt/format.h>

#include "geardyn/config/detail/gearbox_bearing.h"
#include "geardyn/error.h"
#include "geardyn/units.h"

namespace geardyn::config::detail {
namespace {

constexpr double kDeg = geardyn::units::kDegree;

RollingBearingType typeOf(const std::string& s) {
  if (s == "deep_groove_ball") return RollingBearingType::kDeepGrooveBall;
  if (s == "angular_contact_ball") return RollingBearingType::kAngularContactBall;
  if (s == "cylindrical_roller") return RollingBearingType::kCylindricalRoller;
  if (s == "spherical_roller") return RollingBearingType::kSphericalRoller;
  return RollingBearingType::kTaperedRoller;
}

}  // namespace

void addRollingBearingKeys(ConfigSchema& schema, const std::string& prefix) {
  schema.string(prefix + "type")
      .choices({"stiffness", "deep_groove_ball", "angular_contact_ball", "cylindrical_roller",
                "tapered_roller", "spherical_roller"})
      .defaultValue("stiffness")
      .doc(
          "\"stiffness\": the stiffness keys (kyy, ...); else a rolling bearing from its "
          "geometry (ISO/TS 16281): nonlinear and coupled in (y, z, x, tilts), solved in the "
          "static deflection and linearised there for the linear analyses");
  schema.string(prefix + "model")
      .choices({"linearised", "nonlinear"})
      .defaultValue("linearised")
      .doc(
          "with a `type` from the geometry, what the train nonlinear analysis (its harmonic "
          "balance and Newmark checks) and `time` use: \"linearised\", the tangent stiffness at "
          "the static deflection (as every linear analysis); \"nonlinear\", the full "
          "load-deflection law with the clearance (elements leave contact) on the radial "
          "displacement (planar DOFs) or on all five of the bearing's coordinates (full DOFs); "
          "`time` then integrates with the nonlinear Newmark and compares with the nonlinear "
          "balance; the torus balance takes it too (planar and full DOFs)");
  schema.string(prefix + "arrangement")
      .choices({"single", "back_to_back", "face_to_face"})
      .defaultValue("single")
      .doc("rows: one, or a pair (a double-row bearing is back_to_back) row_spacing apart");
  schema.boolean(prefix + "reversed")
      .defaultValue(false)
      .doc(
          "a single row takes the shaft's axial load towards +x; reversed: towards -x (one "
          "reversed at each shaft's other end: an X or O pair across the shaft)");
  schema.integer(prefix + "elements").optional().min(3).doc("rolling elements per row (geometry)");
  schema.real(prefix + "element_diameter")
      .unit("m")
      .optional()
      .positive()
      .doc("ball diameter D_w, or the rollers' mean diameter D_we");
  schema.real(prefix + "pitch_diameter")
      .unit("m")
      .optional()
      .positive()
      .doc("pitch diameter d_m of the element centres");
  schema.real(prefix + "contact_angle_deg")
      .unit("deg")
      .defaultValue(0.0)
      .min(0.0)
      .max(60.0)
      .doc(
          "nominal contact angle (angular contact: of the touching rows; tapered: the cup "
          "angle; spherical roller: of each row, its rows' lines meet at the bearing's centre); "
          "0 for deep-groove and cylindrical bearings");
  schema.real(prefix + "inner_groove_radius")
      .unit("m")
      .optional()
      .positive()
      .doc("inner raceway groove radius r_i (balls; > D_w/2)");
  schema.real(prefix + "outer_groove_radius")
      .unit("m")
      .optional()
      .positive()
      .doc("outer raceway groove radius r_e (balls; > D_w/2)");
  schema.real(prefix + "roller_length")
      .unit("m")
      .optional()
      .positive()
      .doc("effective roller length L_we (rollers)");
  schema.string(prefix + "profile")
      .choices({"logarithmic", "crowned", "straight"})
      .defaultValue("logarithmic")
      .doc(
          "roller profile: ISO/TS 16281's logarithmic one, a parabolic crown of crown_drop, or "
          "none");
  schema.real(prefix + "crown_drop")
      .unit("m")
      .defaultValue(0.0)
      .min(0.0)
      .doc("crown drop at the roller ends (profile = \"crowned\")");
  schema.integer(prefix + "slices")
      .defaultValue(20)
      .min(1)
      .max(200)
      .doc("slices of a roller's line contact");
  schema.real(prefix + "row_spacing")
      .unit("m")
      .defaultValue(0.0)
      .min(0.0)
      .doc("axial distance of the two rows (arrangement of a pair)");
  schema.real(prefix + "youngs_modulus")
      .unit("Pa")
      .defaultValue(2.1e11)
      .positive()
      .doc("Young's modulus of the rings");
  schema.real(prefix + "poisson_ratio")
      .defaultValue(0.3)
      .greaterThan(-1.0)
      .lessThan(0.5)
      .doc("Poisson's ratio of the rings");
  schema.real(prefix + "element_youngs_modulus")
      .unit("Pa")
      .optional()
      .positive()
      .doc("Young's modulus of the rolling elements (default: the rings')");
  schema.real(prefix + "element_poisson_ratio")
      .optional()
      .greaterThan(-1.0)
      .lessThan(0.5)
      .doc("Poisson's ratio of the rolling elements (default: the rings')");
  schema.real(prefix + "dynamic_load_rating")
      .unit("N")
      .defaultValue(0.0)
      .min(0.0)
      .doc(
          "basic dynamic load rating C: with it the static analysis gives the ISO/TS 16281 "
          "reference rating life L10r (0: none)");
}

std::shared_ptr<const RollingBearing> rollingBearingFromConfig(const Config& config,
                                                               const std::string& prefix,
                                                               double radial_clearance) {
  const std::string type = config.string(prefix + "type");
  if (type == "stiffness") return nullptr;
  RollingBearingGeometry g;
  g.type = typeOf(type);
  const std::string arrangement = config.string(prefix + "arrangement");
  g.arrangement = arrangement == "back_to_back"   ? BearingArrangement::kBackToBack
                  : arrangement == "face_to_face" ? BearingArrangement::kFaceToFace
                                                  : BearingArrangement::kSingle;
  auto required = [&](const std::string& name) {
    if (!config.has(prefix + name)) {
      throw InputError(prefix + name, "(missing)",
                       fmt::format("a value: required for a bearing with type = \"{}\"", type));
    }
  };
  for (const char* name : {"elements", "element_diameter", "pitch_diameter"}) required(name);
  g.elements = static_cast<int>(config.integer(prefix + "elements"));
  g.element_diameter = config.real(prefix + "element_diameter");
  g.pitch_diameter = config.real(prefix + "pitch_diameter");
  g.contact_angle = config.real(prefix + "contact_angle_deg") * kDeg;
  if (g.ball()) {
    for (const char* name : {"inner_groove_radius", "outer_groove_radius"}) required(name);
    g.inner_groove_radius = config.real(prefix + "inner_groove_radius");
    g.outer_groove_radius = config.real(prefix + "outer_groove_radius");
  } else {
    required("roller_length");
    g.roller_length = config.real(prefix + "roller_length");
    const std::string profile = config.string(prefix + "profile");
    g.profile = profile == "crowned"    ? RollerProfile::kCrowned
                : profile == "straight" ? RollerProfile::kStraight
                                        : RollerProfile::kLogarithmic;
    g.crown_drop = config.real(prefix + "crown_drop");
    g.slices = static_cast<int>(config.integer(prefix + "slices"));
  }
  g.clearance = 2.0 * radial_clearance;  // ISO/TS 16281's s_r is the diametral play
  g.row_spacing = config.real(prefix + "row_spacing");
  g.reversed = config.boolean(prefix + "reversed");
  g.youngs_modulus = config.real(prefix + "youngs_modulus");
  g.poisson_ratio = config.real(prefix + "poisson_ratio");
  g.element_youngs_modulus = config.has(prefix + "element_youngs_modulus")
                                 ? config.real(prefix + "element_youngs_modulus")
                                 : g.youngs_modulus;
  g.element_poisson_ratio = config.has(prefix + "element_poisson_ratio")
                                ? config.real(prefix + "element_poisson_ratio")
                                : g.poisson_ratio;
  g.dynamic_load_rating = config.real(prefix + "dynamic_load_rating");
  // Keys named as the file spells them: "bearings.<name>" + the geometry's field, except the
  // clearance (radial_clearance) and the contact angle (contact_angle_deg).
  const std::string key = prefix.substr(0, prefix.size() - 1);
  try {
    return std::make_shared<const RollingBearing>(g, key);
  } catch (const InputError& e) {
    if (e.key() == key + ".clearance") {
      throw InputError(key + ".radial_clearance", fmt::format("{:g} m", radial_clearance),
                       fmt::format(">= {:g} m (a negative clearance is a preload; deeper than "
                                   "0.1 % of the element diameter is beyond what a fit gives)",
                                   -1e-3 * g.element_diameter));
    }
    if (e.key() == key + ".contact_angle") {
      throw InputError(key + ".contact_angle_deg", e.value(), e.allowed());
    }
    throw;
  }
}

bool fullBearingLawFromConfig(const Config& config, const std::string& prefix, bool rolling) {
  const std::string model = config.string(prefix + "model");
  if (model == "nonlinear" && !rolling) {
    throw InputError(
        prefix + "model", "\"nonlinear\"",
        "\"linearised\" with type = \"stiffness\": the full law is a rolling bearing's "
        "from its geometry (a stiffness bearing with play: radial_clearance)");
  }
  return model == "nonlinear";
}

}  // namespace geardyn::config::detail
