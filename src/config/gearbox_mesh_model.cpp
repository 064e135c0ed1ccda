/// The keys of a gearbox mesh's model and their readers (config/detail/gearbox_mesh_model.h).

#include "geardyn/config/detail/gearbox_mesh_model.h"

#include <fmt/format.h>

#include <numbers>

#include "geardyn/config/stiffness_config.h"
#include "geardyn/error.h"
#include "geardyn/stiffness/api_stiffness.h"

namespace geardyn::config::detail {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
using Json = nlohmann::ordered_json;

}  // namespace

namespace {
const std::vector<std::string> kStiffnessChoices = {"constant", "api",  "potential_energy",
                                                    "iso6336",  "step", "fourier"};
}  // namespace

void addMeshModelKeys(config::ConfigSchema& schema, const std::string& prefix,
                      const std::string& what) {
  schema.string(prefix + "stiffness")
      .choices(kStiffnessChoices)
      .defaultValue("potential_energy")
      .doc("mesh-stiffness model of " + what +
           " (options in [mesh_stiffness.<model>]; ring meshes: constant or api)");
  schema.real(prefix + "stiffness_value")
      .unit("N/m")
      .positive()
      .optional()
      .doc(
          "k when stiffness = \"constant\"; every mesh model's k acts along the contact normal, "
          "inclined by β_b to the transverse plane (torsional stiffness k cos² β_b r_b²)");
  schema.real(prefix + "damping_ratio")
      .unit("-")
      .min(0.0)
      .max(1.0)
      .defaultValue(0.05)
      .doc("damping ratio of the mesh on its equivalent torsional mass");
  schema.realList(prefix + "te_amplitudes")
      .unit("m")
      .defaultValue(Json::array())
      .doc("transmission error e(φ) = Σ a_r cos(2π r φ + φ_r) over mesh orders r = 1, 2, …");
  schema.realList(prefix + "te_phases_deg")
      .unit("deg")
      .defaultValue(Json::array())
      .doc("phases φ_r of the TE orders (one per amplitude; empty: 0)");
  schema.string(prefix + "contact")
      .choices({"linear", "one_sided", "backlash"})
      .optional()
      .doc("tooth contact of " + what +
           ": linear (never separates), one_sided (contact loss) or backlash (free play, then "
           "the back flank); absent: backlash when the backlash key is given, else linear. "
           "The nonlinear analysis uses it; the linear ones keep the teeth in contact");
  schema.real(prefix + "backlash")
      .unit("m")
      .positive()
      .optional()
      .doc("normal backlash j along the line of action (contact = \"backlash\")");
}

TrainMeshContact contactFromConfig(const config::Config& config, const std::string& prefix) {
  TrainMeshContact c;
  const bool has_backlash = config.has(prefix + "backlash");
  const std::string law = config.has(prefix + "contact") ? config.string(prefix + "contact")
                          : has_backlash                 ? "backlash"
                                                         : "linear";
  if (law == "backlash" && !has_backlash) {
    throw InputError(prefix + "backlash", "(absent)",
                     "the normal backlash along the line of action [m] when contact = "
                     "\"backlash\"");
  }
  if (law != "backlash" && has_backlash) {
    throw InputError(prefix + "backlash", fmt::format("{:g} m", config.real(prefix + "backlash")),
                     fmt::format("only with contact = \"backlash\" (contact = \"{}\")", law));
  }
  c.law = law == "backlash"    ? ContactLaw::kBacklash
          : law == "one_sided" ? ContactLaw::kOneSided
                               : ContactLaw::kLinear;
  if (has_backlash) c.backlash = config.real(prefix + "backlash");
  return c;
}

TransmissionError teFromConfig(const config::Config& config, const std::string& prefix) {
  TransmissionError te;
  const auto amplitudes = config.realList(prefix + "te_amplitudes");
  auto phases = config.realList(prefix + "te_phases_deg");
  if (phases.empty()) phases.assign(amplitudes.size(), 0.0);
  for (double& p : phases) p *= kDeg;
  if (!amplitudes.empty()) te.addFourier(amplitudes, phases, prefix + "te_phases_deg");
  return te;
}

std::shared_ptr<const MeshStiffness> stiffnessFromConfig(const config::Config& config,
                                                         const std::string& prefix,
                                                         const GearPair* pair, double face_width,
                                                         double helix, double contact_ratio,
                                                         std::vector<std::string>& warnings) {
  const std::string model = config.string(prefix + "stiffness");
  if (model == "constant") {
    if (!config.has(prefix + "stiffness_value")) {
      throw InputError(prefix + "stiffness_value", "",
                       "required with stiffness = \"constant\" [N/m]");
    }
    return std::make_shared<ConstantMeshStiffness>(
        "constant", config.real(prefix + "stiffness_value"), contact_ratio);
  }
  if (model == "api") {
    return std::make_shared<ConstantMeshStiffness>("api", apiMeshStiffness(face_width, helix),
                                                   contact_ratio);
  }
  if (!pair) {
    throw InputError(prefix + "stiffness", "\"" + model + "\"",
                     "\"constant\" or \"api\" on a ring (internal) mesh: the tooth models are "
                     "written for external pairs");
  }
  std::vector<std::string> own;
  auto k = config::buildMeshStiffnessModel(model, config, *pair, own);
  const std::string where = prefix.substr(0, prefix.size() - 1);
  for (const auto& w : own) warnings.push_back(where + " (" + model + " model): " + w);
  return k;
}

}  // namespace geardyn::config::detail
