/// Python bindings of geometry/: Gear (GearSpec), GearGeometry, GearPair.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <numbers>

#include "geardyn/analysis/geometry_results.h"
#include "geardyn/config/config.h"
#include "geardyn/config/geometry_config.h"
#include "geardyn/geometry/gear_pair.h"
#include "geardyn/units.h"

namespace py = pybind11;

namespace geardyn::python {
namespace {

using geardyn::units::kDegree;

py::object jsonToPython(const nlohmann::ordered_json& json) {
  return py::module_::import("json").attr("loads")(json.dump());
}

}  // namespace

void bindGeometry(py::module_& m) {
  py::class_<GearSpec>(
      m, "Gear",
      "One external involute gear (spur or helical) cut by a standard basic rack.\n"
      "Arguments are those of a [pinion] / [gear] configuration section; SI units,\n"
      "angles in degrees as the key names say.")
      .def(py::init([](int teeth, double module, double face_width, double pressure_angle_deg,
                       double helix_angle_deg, double profile_shift, double addendum_coefficient,
                       double dedendum_coefficient, double root_fillet_coefficient,
                       double tip_radius_modification, double bore_diameter, double youngs_modulus,
                       double poisson_ratio, double density) {
             GearSpec g;
             g.teeth = teeth;
             g.normal_module = module;
             g.face_width = face_width;
             g.normal_pressure_angle = pressure_angle_deg * kDegree;
             g.helix_angle = helix_angle_deg * kDegree;
             g.profile_shift = profile_shift;
             g.addendum_coefficient = addendum_coefficient;
             g.dedendum_coefficient = dedendum_coefficient;
             g.root_fillet_coefficient = root_fillet_coefficient;
             g.tip_radius_modification = tip_radius_modification;
             g.bore_diameter = bore_diameter;
             g.youngs_modulus = youngs_modulus;
             g.poisson_ratio = poisson_ratio;
             g.density = density;
             g.validate("");
             return g;
           }),
           py::kw_only(), py::arg("teeth"), py::arg("module"), py::arg("face_width"),
           py::arg("pressure_angle_deg") = 20.0, py::arg("helix_angle_deg") = 0.0,
           py::arg("profile_shift") = 0.0, py::arg("addendum_coefficient") = 1.0,
           py::arg("dedendum_coefficient") = 1.25, py::arg("root_fillet_coefficient") = 0.38,
           py::arg("tip_radius_modification") = 0.0, py::arg("bore_diameter") = 0.0,
           py::arg("youngs_modulus") = 206e9, py::arg("poisson_ratio") = 0.3,
           py::arg("density") = 7850.0,
           "teeth: number of teeth; module: normal module [m]; face_width [m]; "
           "pressure_angle_deg: normal pressure angle [deg]; helix_angle_deg [deg] (> 0 right "
           "hand); profile_shift x [-]; addendum_coefficient h_a* [-]; dedendum_coefficient "
           "h_f* [-]; root_fillet_coefficient: tip radius of the generating rack / m_n [-]; "
           "tip_radius_modification [m]; bore_diameter [m]; youngs_modulus [Pa]; "
           "poisson_ratio [-]; density [kg/m^3]. Raises ValueError naming the bad argument.")
      .def_readonly("teeth", &GearSpec::teeth, "number of teeth z")
      .def_readonly("module", &GearSpec::normal_module, "normal module m_n [m]")
      .def_property_readonly(
          "pressure_angle_deg", [](const GearSpec& g) { return g.normal_pressure_angle / kDegree; },
          "normal pressure angle [deg]")
      .def_property_readonly(
          "helix_angle_deg", [](const GearSpec& g) { return g.helix_angle / kDegree; },
          "helix angle [deg]")
      .def_readonly("face_width", &GearSpec::face_width, "face width [m]")
      .def_readonly("profile_shift", &GearSpec::profile_shift, "profile shift coefficient [-]")
      .def_readonly("addendum_coefficient", &GearSpec::addendum_coefficient, "h_a* [-]")
      .def_readonly("dedendum_coefficient", &GearSpec::dedendum_coefficient, "h_f* [-]")
      .def_readonly("root_fillet_coefficient", &GearSpec::root_fillet_coefficient, "ρ_fP* [-]")
      .def_readonly("tip_radius_modification", &GearSpec::tip_radius_modification, "[m]")
      .def_readonly("bore_diameter", &GearSpec::bore_diameter, "[m]")
      .def_readonly("youngs_modulus", &GearSpec::youngs_modulus, "[Pa]")
      .def_readonly("poisson_ratio", &GearSpec::poisson_ratio, "[-]")
      .def_readonly("density", &GearSpec::density, "[kg/m^3]")
      .def("__repr__", [](const GearSpec& g) {
        return "Gear(teeth=" + std::to_string(g.teeth) +
               ", module=" + py::repr(py::float_(g.normal_module)).cast<std::string>() + ", ...)";
      });

  py::class_<GearGeometry>(m, "GearGeometry",
                           "Geometry of one member of a GearPair in its operating condition "
                           "(radii in m, mass in kg, inertias in kg m^2).")
      .def_readonly("transverse_module", &GearGeometry::transverse_module, "m_t [m]")
      .def_readonly("pitch_radius", &GearGeometry::pitch_radius, "reference radius [m]")
      .def_readonly("base_radius", &GearGeometry::base_radius, "[m]")
      .def_readonly("tip_radius", &GearGeometry::tip_radius, "[m]")
      .def_readonly("root_radius", &GearGeometry::root_radius, "[m]")
      .def_readonly("operating_pitch_radius", &GearGeometry::operating_pitch_radius, "[m]")
      .def_readonly("form_radius", &GearGeometry::form_radius,
                    "start of the rack-generated involute [m]")
      .def_readonly("active_profile_start_radius", &GearGeometry::active_profile_start_radius,
                    "start of active profile (SAP) [m]")
      .def_readonly("tip_thickness_normal", &GearGeometry::tip_thickness_normal, "[m]")
      .def_readonly("tip_clearance", &GearGeometry::tip_clearance, "[m]")
      .def_readonly("undercut", &GearGeometry::undercut, "tooth undercut by the rack")
      .def_readonly("mass", &GearGeometry::mass, "body mass [kg]")
      .def_readonly("polar_inertia", &GearGeometry::polar_inertia, "[kg m^2]")
      .def_readonly("diametral_inertia", &GearGeometry::diametral_inertia, "[kg m^2]");

  py::class_<GearPair>(m, "GearPair",
                       "An external involute gear pair in mesh: operating geometry, contact "
                       "ratios, backlash, checks and mass properties. Raises ValueError (naming "
                       "the configuration key) when the pair cannot exist or mesh continuously.")
      .def(py::init([](const GearSpec& pinion, const GearSpec& gear,
                       std::optional<double> centre_distance, std::optional<double> speed_rpm,
                       const std::string& driver) {
             GearPairSpec spec;
             spec.pinion = pinion;
             spec.gear = gear;
             spec.centre_distance = centre_distance;
             spec.pinion_speed_rpm = speed_rpm;
             spec.driver = parseDriver(driver, "driver");
             return GearPair(spec);
           }),
           py::kw_only(), py::arg("pinion"), py::arg("gear"),
           py::arg("centre_distance") = py::none(), py::arg("speed_rpm") = py::none(),
           py::arg("driver") = "pinion",
           "pinion, gear: Gear; centre_distance: operating centre distance [m] (None: the "
           "zero-backlash distance); speed_rpm: pinion speed [rpm] (None: no mesh frequency); "
           "driver: 'pinion' or 'gear'.")
      .def_static(
          "from_config",
          [](const std::string& path, const std::vector<std::string>& overrides) {
            return GearPair(config::gearPairSpecFromConfig(
                config::loadConfigFile(path, config::geometrySchema(), overrides)));
          },
          py::arg("path"), py::arg("overrides") = std::vector<std::string>{},
          "The pair of a `geardyn geometry` TOML file; overrides are 'section.key=value' strings.")
      .def_property_readonly("pinion", &GearPair::pinion, "GearGeometry of the pinion")
      .def_property_readonly("gear", &GearPair::gear, "GearGeometry of the gear")
      .def_property_readonly("gear_ratio", &GearPair::gearRatio, "z2 / z1 [-]")
      .def_property_readonly("transverse_pressure_angle", &GearPair::transversePressureAngle,
                             "[rad]")
      .def_property_readonly("base_helix_angle", &GearPair::baseHelixAngle, "[rad]")
      .def_property_readonly("base_pitch_transverse", &GearPair::basePitchTransverse, "[m]")
      .def_property_readonly("base_pitch_normal", &GearPair::basePitchNormal, "[m]")
      .def_property_readonly("reference_centre_distance", &GearPair::referenceCentreDistance, "[m]")
      .def_property_readonly("tight_mesh_centre_distance", &GearPair::tightMeshCentreDistance,
                             "[m]")
      .def_property_readonly("centre_distance", &GearPair::centreDistance, "operating [m]")
      .def_property_readonly("operating_pressure_angle", &GearPair::operatingPressureAngle, "[rad]")
      .def_property_readonly("backlash_circumferential", &GearPair::backlashCircumferential, "[m]")
      .def_property_readonly("backlash_normal", &GearPair::backlashNormal, "[m]")
      .def_property_readonly("line_of_action_length", &GearPair::lineOfActionLength, "T1T2 [m]")
      .def_property_readonly("path_of_contact_start", &GearPair::pathOfContactStart, "from T1 [m]")
      .def_property_readonly("path_of_contact_end", &GearPair::pathOfContactEnd, "from T1 [m]")
      .def_property_readonly("path_of_contact_length", &GearPair::pathOfContactLength, "[m]")
      .def_property_readonly("contact_ratio_transverse", &GearPair::contactRatioTransverse, "[-]")
      .def_property_readonly("overlap_ratio", &GearPair::overlapRatio, "[-]")
      .def_property_readonly("contact_ratio_total", &GearPair::contactRatioTotal, "[-]")
      .def_property_readonly("effective_face_width", &GearPair::effectiveFaceWidth,
                             "common face width [m]")
      .def_property_readonly(
          "pinion_spec", [](const GearPair& p) { return p.spec().pinion; }, "the pinion's Gear")
      .def_property_readonly(
          "gear_spec", [](const GearPair& p) { return p.spec().gear; }, "the gear's Gear")
      .def_property_readonly("mesh_frequency", &GearPair::meshFrequency, "[Hz] or None")
      .def_property_readonly("warnings", &GearPair::warnings, "design warnings (sentences)")
      .def(
          "to_dict", [](const GearPair& pair) { return jsonToPython(analysis::toJson(pair)); },
          "The headline numbers, exactly as in summary.json 'results' of `geardyn geometry`.");
}

}  // namespace geardyn::python
