/// The gearbox description file's schema (gearbox_config.h): one step per group of sections.

#include "geardyn/config/detail/gearbox_bearing.h"
#include "geardyn/config/detail/gearbox_excitation.h"
#include "geardyn/config/detail/gearbox_mesh_model.h"
#include "geardyn/config/gearbox_config.h"
#include "geardyn/config/gearbox_housing.h"
#include "geardyn/config/geometry_config.h"
#include "geardyn/config/stiffness_config.h"

namespace geardyn::config {
namespace {

using detail::addGearboxExcitationSections;
using detail::addMeshModelKeys;
using Json = nlohmann::ordered_json;

/// The gearbox as a whole and its shafts.
void addGearboxAndShaftKeys(ConfigSchema& schema) {
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
}

/// Gears on the shafts and the meshes between them.
void addGearAndMeshKeys(ConfigSchema& schema) {
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
  schema.string("meshes.*.excitation")
      .choices({"input", "ltca"})
      .defaultValue("input")
      .doc(
          "input: the mesh's stiffness model and te_* keys; ltca (full DOFs, external meshes): "
          "the loaded tooth contact under the gearbox's own deflection (train [contact]) gives "
          "the tangent stiffness k_t(phi) and the error e = STE - F/k_t, with the mesh's "
          "[modifications] (issue 36)");
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
}

/// Bearings (to the housing or between shafts) and disks.
void addBearingAndDiskKeys(ConfigSchema& schema) {
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
}

/// Unbalances, runouts, bearing excitations; couplings.
void addExcitationAndCouplingKeys(ConfigSchema& schema) {
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
}

/// Planetary stages and their meshes.
void addPlanetaryKeys(ConfigSchema& schema) {
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
}

/// The operating point and the mesh-stiffness models' options.
void addOperatingPointKeys(ConfigSchema& schema) {
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
                                                 "bearing_excitations",
                                                 "housing"};
  return names;
}

void addGearboxSections(config::ConfigSchema& schema) {
  addGearboxAndShaftKeys(schema);
  addGearAndMeshKeys(schema);
  addBearingAndDiskKeys(schema);
  addExcitationAndCouplingKeys(schema);
  addPlanetaryKeys(schema);
  addOperatingPointKeys(schema);
  addHousingKeys(schema);
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

}  // namespace geardyn::config
