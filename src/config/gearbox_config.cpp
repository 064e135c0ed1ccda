/// The gearbox description file: schema and reader (gearbox_config.h).

#include "geardyn/config/gearbox_config.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "geardyn/config/detail/gearbox_bearing.h"
#include "geardyn/config/detail/gearbox_gear_defaults.h"
#include "geardyn/config/detail/gearbox_excitation.h"
#include "geardyn/config/detail/gearbox_mesh_model.h"
#include "geardyn/config/geometry_config.h"
#include "geardyn/config/stiffness_config.h"
#include "geardyn/error.h"
#include "geardyn/geometry/gear_pair.h"
#include "geardyn/geometry/internal_gear_pair.h"
#include "geardyn/stiffness/api_stiffness.h"
#include "geardyn/units.h"

namespace geardyn::config {
namespace {

using detail::addGearboxExcitationSections;
using detail::addMeshModelKeys;
using detail::contactFromConfig;
using detail::defaultBoreDiameter;
using detail::readGearboxExcitations;
using detail::stiffnessFromConfig;
using detail::teFromConfig;

constexpr double kDeg = geardyn::units::kDegree;
using geardyn::units::kRpm;
using Json = nlohmann::ordered_json;

}  // namespace

const std::vector<std::string>& gearboxSectionNames() {
  static const std::vector<std::string> names = {"gearbox",
                                                 "shafts",
                                                 "gears",
                                                 "meshes",
                                                 "bearings",
                                                 "couplings",
                                                 "disks",
                                                 "planetary",
                                                 "operating_point",
                                                 "mesh_stiffness",
                                                 "unbalances",
                                                 "runouts",
                                                 "bearing_excitations"};
  return names;
}

void addGearboxSections(config::ConfigSchema& schema) {
  schema.section("gearbox", "The gearbox as a whole.");
  schema.string("gearbox.name").defaultValue("").doc("free text");
  schema.string("gearbox.dofs")
      .choices({"torsional", "planar", "full"})
      .defaultValue("planar")
      .doc(
          "DOFs of every body: rotation only; rotation and the translation of its centre; or "
          "all six per node (axial, tilts; required by flexible shafts)");
  schema.real("gearbox.gravity")
      .unit("m/s^2")
      .min(0.0)
      .defaultValue(0.0)
      .doc("gravity along −z on every mass (planar and full DOFs; e.g. 9.81)");
  schema.real("gearbox.mass_proportional_damping")
      .unit("1/s")
      .min(0.0)
      .defaultValue(0.0)
      .doc("α of the Rayleigh damping α M + β K");
  schema.real("gearbox.stiffness_proportional_damping")
      .unit("s")
      .min(0.0)
      .defaultValue(0.0)
      .doc("β of the Rayleigh damping (on bearings, couplings and mean meshes)");

  schema.collection("shafts",
                    "Rigid bodies turning about axes parallel to x: shafts with what is "
                    "mounted on them, carriers, a housing-held ring.");
  schema.section("shafts.*", "One shaft; its gears' bodies are added to it.");
  schema.real("shafts.*.mass").unit("kg").min(0.0).defaultValue(0.0).doc("own mass");
  schema.real("shafts.*.polar_inertia")
      .unit("kg m^2")
      .min(0.0)
      .defaultValue(0.0)
      .doc("own polar moment of inertia");
  schema.real("shafts.*.diametral_inertia")
      .unit("kg m^2")
      .min(0.0)
      .defaultValue(0.0)
      .doc("own inertia about a transverse axis through its mass centre (dofs = \"full\")");
  schema.realList("shafts.*.section_lengths")
      .unit("m")
      .defaultValue(Json::array())
      .doc("solid-of-revolution sections added to mass and inertia");
  schema.realList("shafts.*.outer_diameters")
      .unit("m")
      .defaultValue(Json::array())
      .doc("one per section, or one for all");
  schema.realList("shafts.*.inner_diameters")
      .unit("m")
      .defaultValue(Json::array())
      .doc("bores: one per section, one for all, or none (solid)");
  schema.real("shafts.*.density").unit("kg/m^3").positive().defaultValue(7850.0).doc("ρ");
  schema.boolean("shafts.*.flexible")
      .defaultValue(false)
      .doc("Timoshenko beam elements over the sections (dofs = \"full\"); false: rigid body");
  schema.real("shafts.*.youngs_modulus")
      .unit("Pa")
      .positive()
      .defaultValue(2.1e11)
      .doc("E of a flexible shaft");
  schema.real("shafts.*.poisson_ratio")
      .unit("-")
      .min(0.0)
      .max(0.5)
      .defaultValue(0.3)
      .doc("ν of a flexible shaft (G = E / 2(1 + ν))");
  schema.real("shafts.*.max_element_length")
      .unit("m")
      .positive()
      .optional()
      .doc("longest beam element (default: one per section, split at every gear, bearing, disk)");
  schema.real("shafts.*.stiffness_proportional_damping")
      .unit("s")
      .min(0.0)
      .defaultValue(0.0)
      .doc(
          "β_s: material damping β_s K_e of a flexible shaft's beam elements only (the "
          "gearbox's β also damps bearings and meshes); 0 on a rigid shaft");
  schema.real("shafts.*.axial_offset")
      .unit("m")
      .defaultValue(0.0)
      .doc("global x of the first section's start; positions on the shaft count from it");

  schema.collection("gears", "Gears on shafts.");
  config::addGearSection(schema, "gears.*", "gear (internal = true makes it a ring gear)", true,
                         "the outer diameter of its shaft's section under the gear when that "
                         "is below the root diameter (a gear on a shaft), else 0 (solid; a "
                         "pinion cut into its shaft needs one for the potential-energy tooth "
                         "model's hub)");
  schema.string("gears.*.shaft").required().doc("the shaft it sits on");
  schema.boolean("gears.*.internal").defaultValue(false).doc("a ring gear with internal teeth");
  schema.boolean("gears.*.body")
      .defaultValue(true)
      .doc("add the gear body's mass and inertia to its shaft (external gears)");
  schema.real("gears.*.position")
      .unit("m")
      .defaultValue(0.0)
      .doc("mid-face position along the shaft from its first section's start");

  schema.collection("meshes",
                    "Meshes between two gears on fixed axes (planetary meshes come "
                    "from their stage).");
  schema.section("meshes.*", "One mesh.");
  schema.stringList("meshes.*.gears").required().doc("the two gears [a, b]");
  schema.real("meshes.*.position_angle_deg")
      .unit("deg")
      .defaultValue(0.0)
      .doc("direction from gear a's centre to gear b's, from +y towards +z");
  schema.real("meshes.*.centre_distance")
      .unit("m")
      .positive()
      .optional()
      .doc("operating centre distance (default: zero backlash)");
  schema.real("meshes.*.phase")
      .unit("-")
      .optional()
      .doc("mesh phase at t = 0 in mesh periods (default 0)");
  addMeshModelKeys(schema, "meshes.*.", "this mesh");
  detail::addToothPairKeys(schema, "meshes.*.");
  schema.real("meshes.*.damping")
      .unit("N s/m")
      .min(0.0)
      .optional()
      .doc("mesh dashpot along the line of action (replaces damping_ratio)");
  schema.string("meshes.*.driver")
      .optional()
      .doc(
          "external meshes: the gear of `gears` that drives (default: the first); the stiffness "
          "model's and the loaded contact's path of contact runs from the driven gear's tip to "
          "the driver's (a gear-pair file's pair.driver)");
  schema.string("meshes.*.stiffness_plane")
      .choices({"normal", "transverse"})
      .defaultValue("normal")
      .doc(
          "the plane of the stiffness model's k, and of the dashpot, transmission error, "
          "backlash and tooth-pair elements given: normal (along the contact normal, where the "
          "mesh acts) or transverse "
          "(along the transverse line of action, as the gear-pair commands read every model: "
          "a helical mesh then acts with k / cos^2 beta_b along the normal; "
          "docs/theory/mesh_stiffness.md)");

  schema.collection("bearings",
                    "Bearings from a shaft to the housing or to another shaft, linear or with a "
                    "radial clearance; a torsional stiffness to the housing holds the shaft.");
  schema.section("bearings.*", "One bearing.");
  schema.string("bearings.*.shaft").required().doc("the shaft it carries");
  schema.string("bearings.*.other_shaft")
      .defaultValue("")
      .doc("the other shaft of an inter-shaft bearing (empty: the housing)");
  for (auto [key, unit, doc] : std::initializer_list<std::array<const char*, 3>>{
           {"kyy", "N/m", "stiffness along y"},
           {"kzz", "N/m", "stiffness along z"},
           {"kyz", "N/m", "cross stiffness (force y per displacement z)"},
           {"kzy", "N/m", "cross stiffness (force z per displacement y)"},
           {"cyy", "N s/m", "damping along y"},
           {"czz", "N s/m", "damping along z"},
           {"cyz", "N s/m", "cross damping"},
           {"czy", "N s/m", "cross damping"},
           {"k_torsion", "N m/rad", "torsional stiffness (to the housing: the shaft is held)"},
           {"c_torsion", "N m s/rad", "torsional damping"},
           {"k_axial", "N/m", "axial stiffness (dofs = \"full\")"},
           {"c_axial", "N s/m", "axial damping"},
           {"k_tilt", "N m/rad", "tilt stiffness about each transverse axis (dofs = \"full\")"},
           {"c_tilt", "N m s/rad", "tilt damping"}}) {
    auto k = schema.real(std::string("bearings.*.") + key).unit(unit).defaultValue(0.0).doc(doc);
    if (std::string(key).size() == 3 && key[1] == key[2]) k.min(0.0);
    if (std::string(key).rfind("k_", 0) == 0 || std::string(key).rfind("c_", 0) == 0) k.min(0.0);
  }

  schema.real("bearings.*.position")
      .unit("m")
      .defaultValue(0.0)
      .doc("position along `shaft` from its first section's start");
  schema.real("bearings.*.other_position")
      .unit("m")
      .defaultValue(0.0)
      .doc("position along `other_shaft`");
  schema.real("bearings.*.radial_clearance")
      .unit("m")
      .defaultValue(0.0)
      .doc(
          "radial clearance c, the radial play from the centred position: with the stiffness "
          "keys (c >= 0) the radial stiffness (kyy = kzz, no cross terms) acts only beyond it, "
          "f = k (|u| - c) u/|u|, damping stays linear, only the train nonlinear analysis uses "
          "it (0: linear bearing); with a `type` from the geometry, half ISO/TS 16281's "
          "operating clearance s_r (< 0: a preload)");
  detail::addRollingBearingKeys(schema, "bearings.*.");

  schema.collection("disks", "Rigid disks (inertias) on shafts: flywheels, motor rotors.");
  schema.section("disks.*", "One disk.");
  schema.string("disks.*.shaft").required().doc("the shaft it sits on");
  schema.real("disks.*.position").unit("m").defaultValue(0.0).doc("position along the shaft");
  schema.real("disks.*.mass").unit("kg").min(0.0).defaultValue(0.0).doc("mass");
  schema.real("disks.*.polar_inertia")
      .unit("kg m^2")
      .min(0.0)
      .defaultValue(0.0)
      .doc("about the shaft axis");
  schema.real("disks.*.diametral_inertia")
      .unit("kg m^2")
      .min(0.0)
      .defaultValue(0.0)
      .doc("about a transverse axis");

  addGearboxExcitationSections(schema);
  schema.collection("couplings",
                    "Couplings between two coaxial shafts (one speed, or a kinematic ratio).");
  schema.section("couplings.*", "One coupling.");
  schema.stringList("couplings.*.shafts").required().doc("the two shafts");
  schema.real("couplings.*.k_torsion")
      .unit("N m/rad")
      .positive()
      .required()
      .doc("torsional stiffness");
  schema.real("couplings.*.c_torsion")
      .unit("N m s/rad")
      .min(0.0)
      .defaultValue(0.0)
      .doc("torsional damping");
  schema.real("couplings.*.k_lateral")
      .unit("N/m")
      .min(0.0)
      .defaultValue(0.0)
      .doc("lateral stiffness (planar DOFs)");
  schema.real("couplings.*.c_lateral")
      .unit("N s/m")
      .min(0.0)
      .defaultValue(0.0)
      .doc("lateral damping");
  schema.real("couplings.*.ratio")
      .defaultValue(1.0)
      .doc(
          "speed of the second shaft per speed of the first (signed, != 0): 1 for a coupling; "
          "another value is a gear ratio whose mesh the model leaves out (the torsional spring "
          "acts on ratio θ_a − θ_b)");

  schema.collection("planetary",
                    "Planetary (epicyclic) stages: sun and ring are gears on "
                    "shafts, the carrier a shaft; the stage adds the planets.");
  schema.section("planetary.*", "One stage.");
  schema.string("planetary.*.sun").required().doc("the sun gear");
  schema.string("planetary.*.ring").required().doc("the ring gear (internal = true)");
  schema.string("planetary.*.carrier").required().doc("the carrier shaft");
  schema.integer("planetary.*.planets").min(1).max(32).defaultValue(3).doc("number N");
  schema.realList("planetary.*.planet_angles_deg")
      .unit("deg")
      .defaultValue(Json::array())
      .doc("planet positions in the carrier (empty: equally spaced)");
  schema.real("planetary.*.planet_mass")
      .unit("kg")
      .min(0.0)
      .defaultValue(0.0)
      .doc("extra to the planet gear's body");
  schema.real("planetary.*.planet_inertia")
      .unit("kg m^2")
      .min(0.0)
      .defaultValue(0.0)
      .doc("extra to the planet gear's body");
  schema.boolean("planetary.*.planet_body")
      .defaultValue(true)
      .doc("add the planet gear's body mass and inertia");
  schema.real("planetary.*.pin_radial_stiffness")
      .unit("N/m")
      .min(0.0)
      .defaultValue(0.0)
      .doc("planet bearing on its pin, radial (required > 0 with planar or full DOFs)");
  schema.real("planetary.*.pin_tangential_stiffness")
      .unit("N/m")
      .min(0.0)
      .defaultValue(0.0)
      .doc("planet bearing, tangential");
  schema.real("planetary.*.pin_axial_stiffness")
      .unit("N/m")
      .min(0.0)
      .optional()
      .doc("full DOFs: planet bearing, axial (default: the mean of radial and tangential)");
  schema.real("planetary.*.pin_tilt_stiffness")
      .unit("N m/rad")
      .min(0.0)
      .optional()
      .doc(
          "full DOFs: planet bearing, tilting (default: that mean spread over the planet's "
          "face width b, k b^2/12)");
  schema.real("planetary.*.planet_diametral_inertia")
      .unit("kg m^2")
      .min(0.0)
      .optional()
      .doc(
          "full DOFs: extra to the planet gear's body, about a transverse axis (default: "
          "planet_inertia/2 + planet_mass b^2/12, a disk of face width b)");
  schema.real("planetary.*.pin_damping")
      .unit("N s/m")
      .min(0.0)
      .defaultValue(0.0)
      .doc("planet bearing damping");
  schema.realList("planetary.*.pin_position_errors")
      .unit("m")
      .defaultValue(Json::array())
      .doc("tangential pin position errors, one per planet (load sharing)");
  schema.boolean("planetary.*.carrier_frame_terms")
      .defaultValue(true)
      .doc("Coriolis and centripetal terms of the carrier frame (Lin & Parker 1999)");
  config::addGearSection(schema, "planetary.*.planet", "planet gear", true);
  schema.section("planetary.*.sun_planet", "The sun–planet meshes.");
  addMeshModelKeys(schema, "planetary.*.sun_planet.", "the sun–planet meshes");
  detail::addToothPairKeys(schema, "planetary.*.sun_planet.");
  schema.section("planetary.*.ring_planet", "The ring–planet meshes.");
  addMeshModelKeys(schema, "planetary.*.ring_planet.", "the ring–planet meshes");

  schema.section("operating_point", "Where the power goes in and out.");
  schema.string("operating_point.input").required().doc("the input shaft");
  schema.real("operating_point.speed_rpm")
      .unit("rpm")
      .defaultValue(0.0)
      .doc("input speed, signed (positive about +x)");
  schema.real("operating_point.torque")
      .unit("N m")
      .defaultValue(0.0)
      .doc("torque applied to the input shaft, signed");
  schema.string("operating_point.output")
      .required()
      .doc("the shaft that takes the balancing load (lossless train)");
  schema.real("operating_point.input_position")
      .unit("m")
      .optional()
      .doc("where the input torque acts along a flexible input shaft (default: its start)");
  schema.real("operating_point.output_position")
      .unit("m")
      .optional()
      .doc("where the load torque acts along a flexible output shaft (default: its end)");

  schema.section("mesh_stiffness", "Options of the mesh-stiffness models, shared by the meshes.");
  config::addMeshStiffnessModelSections(schema);
}

config::ConfigSchema gearboxSchema() {
  config::ConfigSchema schema("gearbox",
                              "A gearbox description: shafts, gears, meshes, bearings, couplings, "
                              "planetary stages and the operating point, read by `geardyn train` "
                              "([gearbox] file = \"gearbox.toml\" in the analysis file).");
  schema.setTitle("Gearbox description file");
  schema.setPrintedBy("train");  // after the train analysis file's reference
  addGearboxSections(schema);
  return schema;
}

namespace {

/// meshes.*.driver: the first gear of the mesh (the pair's pinion) or the second.
Driver meshDriver(const config::Config& config, const std::string& p, const TrainMeshSpec& m) {
  if (!config.has(p + "driver")) return Driver::kPinion;
  const std::string driver = config.string(p + "driver");
  if (driver == m.gear_a) return Driver::kPinion;
  if (driver == m.gear_b) return Driver::kGear;
  throw InputError(p + "driver", "\"" + driver + "\"",
                   fmt::format("one of the mesh's gears, \"{}\" or \"{}\"", m.gear_a, m.gear_b));
}

}  // namespace

GearTrainSpec gearTrainFromConfig(const config::Config& config,
                                  std::vector<std::string>& warnings) {
  GearTrainSpec spec;
  spec.name = config.string("gearbox.name");
  spec.dofs = parseTrainDofs(config.string("gearbox.dofs"), "gearbox.dofs");
  spec.mass_proportional_damping = config.real("gearbox.mass_proportional_damping");
  spec.gravity = config.real("gearbox.gravity");
  spec.stiffness_proportional_damping = config.real("gearbox.stiffness_proportional_damping");
  for (const std::string& name : config.names("shafts")) {
    const std::string p = "shafts." + name + ".";
    TrainShaftSpec s;
    s.name = name;
    s.mass = config.real(p + "mass");
    s.polar_inertia = config.real(p + "polar_inertia");
    s.diametral_inertia = config.real(p + "diametral_inertia");
    s.section_lengths = config.realList(p + "section_lengths");
    s.outer_diameters = config.realList(p + "outer_diameters");
    s.inner_diameters = config.realList(p + "inner_diameters");
    s.density = config.real(p + "density");
    s.flexible = config.boolean(p + "flexible");
    s.youngs_modulus = config.real(p + "youngs_modulus");
    s.poisson_ratio = config.real(p + "poisson_ratio");
    s.max_element_length = config.optionalReal(p + "max_element_length");
    s.axial_offset = config.real(p + "axial_offset");
    s.stiffness_proportional_damping = config.real(p + "stiffness_proportional_damping");
    spec.shafts.push_back(std::move(s));
  }
  for (const std::string& name : config.names("gears")) {
    const std::string p = "gears." + name;
    spec.gears.push_back({name, config.string(p + ".shaft"), config::gearSpecFromConfig(config, p),
                          config.boolean(p + ".internal"), config.boolean(p + ".body"),
                          config.real(p + ".position")});
    TrainGearSpec& gear = spec.gears.back();
    if (!config.has(p + ".bore_diameter") && !gear.internal) {
      gear.gear.bore_diameter = defaultBoreDiameter(gear, spec.shafts);
    }
    for (auto& note : plausibilityNotes(spec.gears.back().gear, p)) warnings.push_back(note);
  }
  auto gear_named = [&](const std::string& gear, const std::string& key) -> const TrainGearSpec& {
    for (const auto& g : spec.gears) {
      if (g.name == gear) return g;
    }
    throw InputError(key, "\"" + gear + "\"", "the name of a gear in [gears.<name>]");
  };
  for (const std::string& name : config.names("meshes")) {
    const std::string p = "meshes." + name + ".";
    const auto gears = config.stringList(p + "gears");
    if (gears.size() != 2) {
      throw InputError(p + "gears", fmt::format("{} names", gears.size()), "two gear names");
    }
    TrainMeshSpec m;
    m.name = name;
    m.gear_a = gears[0];
    m.gear_b = gears[1];
    m.position_angle = config.real(p + "position_angle_deg") * kDeg;
    m.centre_distance = config.optionalReal(p + "centre_distance");
    if (config.has(p + "phase")) m.phase = config.real(p + "phase");
    m.damping_ratio = config.real(p + "damping_ratio");
    m.damping = config.optionalReal(p + "damping");
    m.transmission_error = teFromConfig(config, p);
    const TrainGearSpec& a = gear_named(m.gear_a, p + "gears");
    const TrainGearSpec& b = gear_named(m.gear_b, p + "gears");
    const double width = std::min(a.gear.face_width, b.gear.face_width);
    double base_helix = 0.0;  // β_b [rad]
    if (a.internal || b.internal) {
      const TrainGearSpec& ring = a.internal ? a : b;
      const TrainGearSpec& pinion = a.internal ? b : a;
      const InternalGearPair pair(pinion.gear, ring.gear, m.centre_distance, "meshes." + name);
      m.stiffness =
          stiffnessFromConfig(config, p,
                              {nullptr,
                               &pair,
                               &pinion.gear,
                               &ring.gear,
                               width,
                               a.gear.helix_angle,
                               pair.contactRatioTransverse() + pair.overlapRatio(),
                               {"gears." + pinion.name, "gears." + ring.name, "meshes." + name}},
                              warnings);
      m.contact = contactFromConfig(config, p, nullptr);
      base_helix = pair.baseHelixAngle();
      if (config.has(p + "driver")) {
        throw InputError(p + "driver", "\"" + config.string(p + "driver") + "\"",
                         "external meshes only (a ring mesh's stiffness has no path of contact)");
      }
    } else {
      GearPairSpec pair_spec;
      pair_spec.pinion = a.gear;
      pair_spec.gear = b.gear;
      pair_spec.centre_distance = m.centre_distance;
      pair_spec.driver = meshDriver(config, p, m);
      const GearPair pair =
          makeGearPair(pair_spec, "gears." + a.name, "gears." + b.name, "meshes." + name);
      m.stiffness = stiffnessFromConfig(config, p,
                                        {&pair,
                                         nullptr,
                                         nullptr,
                                         nullptr,
                                         width,
                                         a.gear.helix_angle,
                                         pair.contactRatioTotal(),
                                         {"gears." + a.name, "gears." + b.name, "meshes." + name}},
                                        warnings);
      m.contact = contactFromConfig(config, p, &pair);
      base_helix = pair.baseHelixAngle();
    }
    if (config.string(p + "stiffness_plane") == "transverse") {
      detail::transverseToNormal(m, base_helix, p);
    }
    spec.meshes.push_back(std::move(m));
  }
  for (const std::string& name : config.names("bearings")) {
    const std::string p = "bearings." + name + ".";
    TrainBearingSpec b;
    b.name = name;
    b.shaft = config.string(p + "shaft");
    b.other_shaft = config.string(p + "other_shaft");
    b.kyy = config.real(p + "kyy"), b.kzz = config.real(p + "kzz");
    b.kyz = config.real(p + "kyz"), b.kzy = config.real(p + "kzy");
    b.cyy = config.real(p + "cyy"), b.czz = config.real(p + "czz");
    b.cyz = config.real(p + "cyz"), b.czy = config.real(p + "czy");
    b.k_torsion = config.real(p + "k_torsion"), b.c_torsion = config.real(p + "c_torsion");
    b.k_axial = config.real(p + "k_axial"), b.c_axial = config.real(p + "c_axial");
    b.k_tilt = config.real(p + "k_tilt"), b.c_tilt = config.real(p + "c_tilt");
    b.position = config.real(p + "position");
    b.other_position = config.real(p + "other_position");
    b.radial_clearance = config.real(p + "radial_clearance");
    b.rolling = detail::rollingBearingFromConfig(config, p, b.radial_clearance);
    if (b.rolling) b.radial_clearance = 0.0;  // in the geometry
    spec.bearings.push_back(b);
  }
  for (const std::string& name : config.names("disks")) {
    const std::string p = "disks." + name + ".";
    spec.disks.push_back({name, config.string(p + "shaft"), config.real(p + "position"),
                          config.real(p + "mass"), config.real(p + "polar_inertia"),
                          config.real(p + "diametral_inertia")});
  }
  for (const std::string& name : config.names("couplings")) {
    const std::string p = "couplings." + name + ".";
    const auto shafts = config.stringList(p + "shafts");
    if (shafts.size() != 2) {
      throw InputError(p + "shafts", fmt::format("{} names", shafts.size()), "two shaft names");
    }
    spec.couplings.push_back({name, shafts[0], shafts[1], config.real(p + "k_torsion"),
                              config.real(p + "c_torsion"), config.real(p + "k_lateral"),
                              config.real(p + "c_lateral"), config.real(p + "ratio")});
  }
  readGearboxExcitations(config, spec);
  for (const std::string& name : config.names("planetary")) {
    const std::string p = "planetary." + name + ".";
    PlanetaryStageSpec st;
    st.name = name;
    st.sun = config.string(p + "sun");
    st.ring = config.string(p + "ring");
    st.carrier = config.string(p + "carrier");
    st.planet = config::gearSpecFromConfig(config, p + "planet");
    for (auto& note : plausibilityNotes(st.planet, p + "planet")) warnings.push_back(note);
    st.planets = static_cast<int>(config.integer(p + "planets"));
    st.planet_angles = config.realList(p + "planet_angles_deg");
    for (double& a : st.planet_angles) a *= kDeg;
    st.planet_mass = config.real(p + "planet_mass");
    st.planet_inertia = config.real(p + "planet_inertia");
    st.planet_body = config.boolean(p + "planet_body");
    st.pin_radial_stiffness = config.real(p + "pin_radial_stiffness");
    st.pin_tangential_stiffness = config.real(p + "pin_tangential_stiffness");
    st.pin_damping = config.real(p + "pin_damping");
    if (config.has(p + "pin_axial_stiffness")) {
      st.pin_axial_stiffness = config.real(p + "pin_axial_stiffness");
    }
    if (config.has(p + "pin_tilt_stiffness")) {
      st.pin_tilt_stiffness = config.real(p + "pin_tilt_stiffness");
    }
    if (config.has(p + "planet_diametral_inertia")) {
      st.planet_diametral_inertia = config.real(p + "planet_diametral_inertia");
    }
    st.pin_position_errors = config.realList(p + "pin_position_errors");
    st.carrier_frame_terms = config.boolean(p + "carrier_frame_terms");
    const TrainGearSpec& sun = gear_named(st.sun, p + "sun");
    const TrainGearSpec& ring = gear_named(st.ring, p + "ring");
    GearPairSpec sp;
    sp.pinion = sun.gear;
    sp.gear = st.planet;
    const GearPair sun_pair =
        makeGearPair(sp, "gears." + st.sun, p + "planet", "planetary." + name);
    const InternalGearPair ring_pair(st.planet, ring.gear, sun_pair.centreDistance(),
                                     "planetary." + name);
    st.sun_planet_stiffness =
        stiffnessFromConfig(config, p + "sun_planet.",
                            {&sun_pair,
                             nullptr,
                             nullptr,
                             nullptr,
                             std::min(sun.gear.face_width, st.planet.face_width),
                             sun.gear.helix_angle,
                             sun_pair.contactRatioTotal(),
                             {"gears." + st.sun, p + "planet", p + "sun_planet"}},
                            warnings);
    st.ring_planet_stiffness =
        stiffnessFromConfig(config, p + "ring_planet.",
                            {nullptr,
                             &ring_pair,
                             &st.planet,
                             &ring.gear,
                             std::min(ring.gear.face_width, st.planet.face_width),
                             ring.gear.helix_angle,
                             ring_pair.contactRatioTransverse() + ring_pair.overlapRatio(),
                             {p + "planet", "gears." + st.ring, p + "ring_planet"}},
                            warnings);
    st.sun_planet_damping_ratio = config.real(p + "sun_planet.damping_ratio");
    st.ring_planet_damping_ratio = config.real(p + "ring_planet.damping_ratio");
    st.sun_planet_error = teFromConfig(config, p + "sun_planet.");
    st.ring_planet_error = teFromConfig(config, p + "ring_planet.");
    st.sun_planet_contact = contactFromConfig(config, p + "sun_planet.", &sun_pair);
    st.ring_planet_contact = contactFromConfig(config, p + "ring_planet.", nullptr);
    spec.stages.push_back(std::move(st));
  }
  spec.operating.input_shaft = config.string("operating_point.input");
  spec.operating.output_shaft = config.string("operating_point.output");
  spec.operating.input_speed = config.real("operating_point.speed_rpm") * kRpm;
  if (auto note = speedPlausibilityNote(config.real("operating_point.speed_rpm"),
                                        "operating_point.speed_rpm");
      !note.empty()) {
    warnings.push_back(std::move(note));
  }
  spec.operating.input_torque = config.real("operating_point.torque");
  spec.operating.input_position = config.optionalReal("operating_point.input_position");
  spec.operating.output_position = config.optionalReal("operating_point.output_position");
  return spec;
}

}  // namespace geardyn::config
