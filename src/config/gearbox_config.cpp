/// The gearbox description file's reader (gearbox_config.h); its schema: gearbox_schema.cpp.

#include "geardyn/config/gearbox_config.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "geardyn/config/detail/gearbox_bearing.h"
#include "geardyn/config/detail/gearbox_excitation.h"
#include "geardyn/config/detail/gearbox_gear_defaults.h"
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

using detail::contactFromConfig;
using detail::defaultBoreDiameter;
using detail::readGearboxExcitations;
using detail::stiffnessFromConfig;
using detail::teFromConfig;

constexpr double kDeg = geardyn::units::kDegree;
using geardyn::units::kRpm;

/// meshes.*.driver: the first gear of the mesh (the pair's pinion) or the second.
Driver meshDriver(const config::Config& config, const std::string& p, const TrainMeshSpec& m) {
  if (!config.has(p + "driver")) return Driver::kPinion;
  const std::string driver = config.string(p + "driver");
  if (driver == m.gear_a) return Driver::kPinion;
  if (driver == m.gear_b) return Driver::kGear;
  throw InputError(p + "driver", "\"" + driver + "\"",
                   fmt::format("one of the mesh's gears, \"{}\" or \"{}\"", m.gear_a, m.gear_b));
}

/// The gear named `gear` (InputError on `key` naming it when there is none).
const TrainGearSpec& gearNamed(const GearTrainSpec& spec, const std::string& gear,
                               const std::string& key) {
  for (const auto& g : spec.gears) {
    if (g.name == gear) return g;
  }
  throw InputError(key, "\"" + gear + "\"", "the name of a gear in [gears.<name>]");
}

/// [shafts.*]: rigid bodies and flexible (beam) shafts.
void readShafts(const config::Config& config, GearTrainSpec& spec) {
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
}

/// [gears.*] on their shafts (a bore from the shaft's section when not given), with the
/// geometry's plausibility notes.
void readGears(const config::Config& config, GearTrainSpec& spec,
               std::vector<std::string>& warnings) {
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
}

/// [meshes.*]: each pair's stiffness model, transmission error and contact, from its gears
/// (external pairs and ring meshes).
void readMeshes(const config::Config& config, GearTrainSpec& spec,
                std::vector<std::string>& warnings) {
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
    const TrainGearSpec& a = gearNamed(spec, m.gear_a, p + "gears");
    const TrainGearSpec& b = gearNamed(spec, m.gear_b, p + "gears");
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
}

/// [bearings.*]: stiffness keys or a rolling bearing's geometry, clearance and law.
void readBearings(const config::Config& config, GearTrainSpec& spec) {
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
    b.full_law = detail::fullBearingLawFromConfig(config, p, b.rolling != nullptr);
    spec.bearings.push_back(b);
  }
}

/// [disks.*] and [couplings.*].
void readDisksAndCouplings(const config::Config& config, GearTrainSpec& spec) {
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
}

/// [planetary.*]: sun, ring and carrier by name, the planet gear, pins, and the sun-planet and
/// ring-planet meshes' stiffness, transmission error and contact.
void readPlanetaryStages(const config::Config& config, GearTrainSpec& spec,
                         std::vector<std::string>& warnings) {
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
    const TrainGearSpec& sun = gearNamed(spec, st.sun, p + "sun");
    const TrainGearSpec& ring = gearNamed(spec, st.ring, p + "ring");
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
}

/// [operating_point]: input and output shafts, speed (with its plausibility note) and torque.
void readOperatingPoint(const config::Config& config, GearTrainSpec& spec,
                        std::vector<std::string>& warnings) {
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
  readShafts(config, spec);
  readGears(config, spec, warnings);
  readMeshes(config, spec, warnings);
  readBearings(config, spec);
  readDisksAndCouplings(config, spec);
  readGearboxExcitations(config, spec);
  readPlanetaryStages(config, spec, warnings);
  readOperatingPoint(config, spec, warnings);
  return spec;
}

}  // namespace geardyn::config
