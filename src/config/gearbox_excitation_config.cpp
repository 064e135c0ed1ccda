/// The gearbox's unbalances, runouts and prescribed bearing displacements
/// (config/detail/gearbox_excitation.h).

#include "geardyn/config/detail/gearbox_excitation.h"
#include "geardyn/units.h"

namespace geardyn::config::detail {
namespace {
constexpr double kDeg = geardyn::units::kDegree;
}  // namespace

void addGearboxExcitationSections(ConfigSchema& schema) {
  schema.collection("unbalances",
                    "Mass unbalances: a rotating force m e ω² at 1x the speed of the shaft "
                    "that carries them.");
  schema.section("unbalances.*", "One unbalance.");
  schema.string("unbalances.*.shaft")
      .required()
      .doc("the shaft (or the shaft of the gear) it is on");
  schema.real("unbalances.*.position")
      .unit("m")
      .defaultValue(0.0)
      .doc("along the shaft from its first section start (flexible shafts, full DOFs)");
  schema.real("unbalances.*.mass_eccentricity")
      .unit("kg m")
      .min(0.0)
      .required()
      .doc("m e: the unbalanced mass times its distance from the axis");
  schema.real("unbalances.*.phase_deg")
      .unit("deg")
      .defaultValue(0.0)
      .doc("its angle at t = 0 from +y towards +z; it turns with the shaft");

  schema.collection("runouts",
                    "Gear runouts (eccentricities): the gear's centre off its shaft's axis, "
                    "turning with it; a displacement excitation of its meshes along their "
                    "lines of action at the gear's shaft order.");
  schema.section("runouts.*", "One runout.");
  schema.string("runouts.*.gear").required().doc("the gear");
  schema.real("runouts.*.amplitude").unit("m").min(0.0).required().doc("the eccentricity e");
  schema.real("runouts.*.phase_deg")
      .unit("deg")
      .defaultValue(0.0)
      .doc("the offset's angle at t = 0 from +y towards +z; it turns with the gear");

  schema.collection("bearing_excitations",
                    "Prescribed relative displacements across a linear bearing: its spring and "
                    "dashpot act on the relative displacement minus d(t), with d_y = mean_y + "
                    "Σ a_y cos(order · the reference's angle + phase_y) (likewise z).");
  schema.section("bearing_excitations.*", "One prescribed displacement.");
  schema.string("bearing_excitations.*.bearing").required().doc("the bearing it acts across");
  schema.string("bearing_excitations.*.reference")
      .defaultValue("")
      .doc(
          "a shaft (orders of its speed) or a mesh (orders of its mesh frequency, from its "
          "phase); needed with orders");
  schema.real("bearing_excitations.*.mean_y").unit("m").defaultValue(0.0).doc("constant part in y");
  schema.real("bearing_excitations.*.mean_z").unit("m").defaultValue(0.0).doc("constant part in z");
  schema.realList("bearing_excitations.*.orders")
      .defaultValue(nlohmann::ordered_json::array())
      .doc("the harmonics' orders (> 0) of the reference's speed or mesh frequency");
  schema.realList("bearing_excitations.*.amplitude_y")
      .unit("m")
      .defaultValue(nlohmann::ordered_json::array())
      .doc("one amplitude >= 0 per order, along y");
  schema.realList("bearing_excitations.*.phase_y_deg")
      .unit("deg")
      .defaultValue(nlohmann::ordered_json::array())
      .doc("one phase per order, y (cosine)");
  schema.realList("bearing_excitations.*.amplitude_z")
      .unit("m")
      .defaultValue(nlohmann::ordered_json::array())
      .doc("one amplitude >= 0 per order, along z");
  schema.realList("bearing_excitations.*.phase_z_deg")
      .unit("deg")
      .defaultValue(nlohmann::ordered_json::array())
      .doc("one phase per order, z (cosine)");
}

void readGearboxExcitations(const Config& config, GearTrainSpec& spec) {
  for (const std::string& name : config.names("unbalances")) {
    const std::string p = "unbalances." + name + ".";
    spec.unbalances.push_back({name, config.string(p + "shaft"), config.real(p + "position"),
                               config.real(p + "mass_eccentricity"),
                               config.real(p + "phase_deg") * kDeg});
  }
  for (const std::string& name : config.names("runouts")) {
    const std::string p = "runouts." + name + ".";
    spec.runouts.push_back({name, config.string(p + "gear"), config.real(p + "amplitude"),
                            config.real(p + "phase_deg") * kDeg});
  }
  for (const std::string& name : config.names("bearing_excitations")) {
    const std::string p = "bearing_excitations." + name + ".";
    TrainBearingExcitationSpec e;
    e.name = name;
    e.bearing = config.string(p + "bearing");
    e.reference = config.string(p + "reference");
    e.mean_y = config.real(p + "mean_y");
    e.mean_z = config.real(p + "mean_z");
    e.orders = config.realList(p + "orders");
    e.amplitude_y = config.realList(p + "amplitude_y");
    e.amplitude_z = config.realList(p + "amplitude_z");
    e.phase_y = config.realList(p + "phase_y_deg");
    e.phase_z = config.realList(p + "phase_z_deg");
    for (double& a : e.phase_y) a *= kDeg;
    for (double& a : e.phase_z) a *= kDeg;
    spec.bearing_excitations.push_back(std::move(e));
  }
}

}  // namespace geardyn::config::detail
