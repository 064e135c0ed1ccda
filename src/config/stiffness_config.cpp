#include "geardyn/config/stiffness_config.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geardyn/config/geometry_config.h"
#include "geardyn/config/output_section.h"
#include "geardyn/error.h"
#include "geardyn/stiffness/api_stiffness.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "geardyn/stiffness/mesh_stiffness_summary.h"
#include "geardyn/stiffness/step_stiffness.h"
#include "geardyn/units.h"

namespace geardyn::config {
namespace {

using geardyn::units::kDegree;

/// Everything the models of one configuration share, built on first use.
class ModelFactory {
 public:
  ModelFactory(const Config& config, const GearPair& pair) : config_(config), pair_(pair) {}

  std::shared_ptr<const MeshStiffness> make(const std::string& name) {
    if (name == "api") return api();
    if (name == "iso6336") return iso();
    if (name == "potential_energy") return potentialEnergy();
    if (name == "step") return step();
    if (name == "fourier") return fourier();
    throw InputError("mesh_stiffness.models", "\"" + name + "\"", "unknown model");
  }
  std::vector<std::string> warnings;

 private:
  std::shared_ptr<const MeshStiffness> api() {
    if (!api_) {
      const double k =
          apiMeshStiffness(pair_.effectiveFaceWidth(), pair_.spec().pinion.helix_angle);
      api_ = std::make_shared<ConstantMeshStiffness>("api", k, pair_.contactRatioTotal());
    }
    return api_;
  }
  std::shared_ptr<const MeshStiffness> iso() {
    if (!iso_) {
      const double k = iso6336Stiffness(pair_, iso6336OptionsFromConfig(config_)).meshStiffness();
      iso_ = std::make_shared<ConstantMeshStiffness>("iso6336", k, pair_.contactRatioTotal());
    }
    return iso_;
  }
  std::shared_ptr<const MeshStiffness> potentialEnergy() {
    if (!pe_) {
      auto pe = std::make_shared<PotentialEnergyMeshStiffness>(
          pair_, potentialEnergyOptionsFromConfig(config_));
      warnings.insert(warnings.end(), pe->warnings().begin(), pe->warnings().end());
      pe_ = pe;
    }
    return pe_;
  }
  std::shared_ptr<const MeshStiffness> step() {
    const std::string levels = config_.string("mesh_stiffness.step.levels");
    const double eps = contactRatio("mesh_stiffness.step.contact_ratio");
    if (levels == "given") {
      for (const char* key : {"mesh_stiffness.step.k_min", "mesh_stiffness.step.k_max"}) {
        if (!config_.has(key)) {
          throw InputError(key, "", "required when mesh_stiffness.step.levels = \"given\" [N/m]");
        }
      }
      return std::make_shared<StepMeshStiffness>(config_.real("mesh_stiffness.step.k_min"),
                                                 config_.real("mesh_stiffness.step.k_max"), eps);
    }
    if (levels == "potential_energy") {
      return std::make_shared<StepMeshStiffness>(StepMeshStiffness::fromModel(*potentialEnergy()));
    }
    const double mean = (levels == "api" ? api() : iso())->stiffness(0.0);
    return std::make_shared<StepMeshStiffness>(StepMeshStiffness::fromMean(mean, eps));
  }
  std::shared_ptr<const MeshStiffness> fourier() {
    const std::string mean_from = config_.string("mesh_stiffness.fourier.mean");
    double mean = 0.0;  // 0: the fitted model's own mean
    if (mean_from == "api") mean = api()->stiffness(0.0);
    if (mean_from == "iso6336") mean = iso()->stiffness(0.0);
    if (mean_from == "given") {
      if (!config_.has("mesh_stiffness.fourier.mean_value")) {
        throw InputError("mesh_stiffness.fourier.mean_value", "",
                         "required when mesh_stiffness.fourier.mean = \"given\" [N/m]");
      }
      mean = config_.real("mesh_stiffness.fourier.mean_value");
    }
    if (config_.string("mesh_stiffness.fourier.fit") == "potential_energy") {
      const int order = static_cast<int>(config_.integer("mesh_stiffness.fourier.order"));
      return std::make_shared<FourierMeshStiffness>(
          FourierMeshStiffness::fit(*potentialEnergy(), order, mean));
    }
    if (mean <= 0.0) {
      throw InputError("mesh_stiffness.fourier.mean", "\"fit\"",
                       "with fit = \"given\" the mean must come from \"api\", \"iso6336\" or "
                       "\"given\" (mean_value)");
    }
    std::vector<double> phases = config_.realList("mesh_stiffness.fourier.phases_deg");
    for (double& p : phases) p *= kDegree;
    return std::make_shared<FourierMeshStiffness>(
        mean, config_.realList("mesh_stiffness.fourier.amplitudes"), phases,
        contactRatio("mesh_stiffness.fourier.contact_ratio"));
  }
  /// ε of a given step or series: the key when given (e.g. a gear-pair file's
  /// model.stiffness.contact_ratio translated into a gearbox), else the pair's total one.
  double contactRatio(const std::string& key) const {
    return config_.has(key) ? config_.real(key) : pair_.contactRatioTotal();
  }

  const Config& config_;
  const GearPair& pair_;
  std::shared_ptr<const MeshStiffness> api_, iso_, pe_;
};

}  // namespace

const std::vector<std::string>& meshStiffnessModelNames() {
  static const std::vector<std::string> names = {"potential_energy", "api", "step", "fourier",
                                                 "iso6336"};
  return names;
}

void addMeshStiffnessSections(ConfigSchema& schema) {
  schema.section("mesh_stiffness",
                 "Mesh-stiffness models to compute and compare, and the output grid. Every k(φ) "
                 "[N/m] is taken along the transverse line of action: it relates the transverse "
                 "force F = T₁/r_b1 to the transverse approach of the flanks r_b1θ₁ + r_b2θ₂ "
                 "(helical: the normal-plane stiffness is k / cos² β_b).");
  schema.stringList("mesh_stiffness.models")
      .choices(meshStiffnessModelNames())
      .defaultValue(nlohmann::ordered_json::array({"potential_energy"}))
      .doc(
          "models to compute; the first is the primary one (k_total_transverse_n_per_m in the "
          "CSV)");
  schema.integer("mesh_stiffness.positions")
      .min(8)
      .max(1000000)
      .defaultValue(1000)
      .doc("positions per mesh period in mesh_stiffness.csv");
  schema.integer("mesh_stiffness.fourier_order")
      .min(0)
      .max(200)
      .defaultValue(10)
      .doc("Fourier coefficients reported per model");
  schema.real("mesh_stiffness.transmitted_force")
      .unit("N")
      .min(0.0)
      .defaultValue(0.0)
      .doc(
          "transmitted force F = T₁/r_b1 along the transverse line of action (helical: the "
          "normal tooth force is F / cos β_b); > 0 adds the loaded static transmission error "
          "δ = F/k + e, along the transverse line of action too");
  schema.realList("mesh_stiffness.error_amplitudes")
      .unit("m")
      .defaultValue(nlohmann::ordered_json::array())
      .doc("geometric error / profile modification e(φ): amplitude per mesh order 1, 2, ...");
  schema.realList("mesh_stiffness.error_phases_deg")
      .unit("deg")
      .defaultValue(nlohmann::ordered_json::array())
      .doc("phase per mesh order of e(φ) = Σ e_i cos(2π i φ + φ_i) (one per amplitude; empty: 0)");
  schema.realList("mesh_stiffness.error_table_phases")
      .unit("-")
      .min(0.0)
      .lessThan(1.0)
      .defaultValue(nlohmann::ordered_json::array())
      .doc("e(φ) as a table too: mesh phases, ascending in [0, 1) (periodic, linear)");
  schema.realList("mesh_stiffness.error_table_values")
      .unit("m")
      .defaultValue(nlohmann::ordered_json::array())
      .doc("e at error_table_phases (added to the Fourier series)");

  addMeshStiffnessModelSections(schema);
}

void addMeshStiffnessModelSections(ConfigSchema& schema) {
  schema.section("mesh_stiffness.api", "API constant stiffness (Visnadi eqs. 1–6).");
  schema.string("mesh_stiffness.api.loading")
      .choices({"down", "up"})
      .defaultValue("down")
      .doc("A = +1 (rotor loaded down) or −1 (up)");
  schema.string("mesh_stiffness.api.rotation")
      .choices({"clockwise", "counterclockwise"})
      .defaultValue("clockwise")
      .doc("B = 90° or 270°, looking into the coupling end");

  schema.section("mesh_stiffness.step", "Step function (Visnadi eq. 7).");
  schema.string("mesh_stiffness.step.levels")
      .choices({"potential_energy", "api", "iso6336", "given"})
      .defaultValue("potential_energy")
      .doc(
          "levels: zone means of the potential-energy curve, pair-proportional levels around the "
          "API / ISO mean, or k_min / k_max");
  schema.real("mesh_stiffness.step.k_min")
      .unit("N/m")
      .positive()
      .optional()
      .doc("stiffness with n pairs in contact");
  schema.real("mesh_stiffness.step.k_max")
      .unit("N/m")
      .positive()
      .optional()
      .doc("stiffness with n + 1 pairs in contact");

  schema.real("mesh_stiffness.step.contact_ratio")
      .unit("-")
      .min(1.0)
      .optional()
      .doc("ε of the step (default: the pair's total contact ratio ε_γ)");

  schema.section("mesh_stiffness.fourier", "Fourier series (Visnadi eq. 8).");
  schema.string("mesh_stiffness.fourier.fit")
      .choices({"potential_energy", "given"})
      .defaultValue("potential_energy")
      .doc("harmonics fitted to the potential-energy curve, or given (amplitudes, phases_deg)");
  schema.integer("mesh_stiffness.fourier.order")
      .min(1)
      .max(200)
      .defaultValue(1)
      .doc("harmonics kept when fitting");
  schema.string("mesh_stiffness.fourier.mean")
      .choices({"fit", "api", "iso6336", "given"})
      .defaultValue("fit")
      .doc("k₀: the fitted curve's mean, the API or ISO value (Visnadi's choice), or mean_value");
  schema.real("mesh_stiffness.fourier.mean_value")
      .unit("N/m")
      .positive()
      .optional()
      .doc("k₀ when mean = \"given\"");
  schema.realList("mesh_stiffness.fourier.amplitudes")
      .unit("-")
      .min(0.0)
      .defaultValue(nlohmann::ordered_json::array())
      .doc("relative amplitudes s_i when fit = \"given\"");
  schema.realList("mesh_stiffness.fourier.phases_deg")
      .unit("deg")
      .defaultValue(nlohmann::ordered_json::array())
      .doc("phases φ_i when fit = \"given\"");
  schema.real("mesh_stiffness.fourier.contact_ratio")
      .unit("-")
      .min(1.0)
      .optional()
      .doc("ε recorded with a given series (default: the pair's total contact ratio ε_γ)");

  schema.section("mesh_stiffness.potential_energy",
                 "Potential-energy beam model (Ma 2014, Sainsot 2004, Wan 2015).");
  schema.string("mesh_stiffness.potential_energy.root")
      .choices({"straight", "trochoid"})
      .defaultValue("straight")
      .doc("tooth below the involute: straight segment (Ma 2014) or the rack-generated fillet");
  schema.string("mesh_stiffness.potential_energy.foundation_arm")
      .choices({"force_line", "contact_height"})
      .defaultValue("force_line")
      .doc(
          "where the foundation moment arm u_f ends: force line on the centreline (Sainsot) or "
          "contact height");
  schema.boolean("mesh_stiffness.potential_energy.foundation")
      .defaultValue(true)
      .doc("include the fillet-foundation compliance");
  schema.real("mesh_stiffness.potential_energy.pinion_hub_radius")
      .unit("m")
      .positive()
      .optional()
      .doc("r_int of the pinion body; default: pinion bore / 2");
  schema.real("mesh_stiffness.potential_energy.gear_hub_radius")
      .unit("m")
      .positive()
      .optional()
      .doc("r_int of the gear body; default: gear bore / 2");
  schema.integer("mesh_stiffness.potential_energy.slices")
      .min(0)
      .max(100000)
      .defaultValue(0)
      .doc("helical: face slices (0: exact integral over the face)");
  schema.boolean("mesh_stiffness.potential_energy.helical_cos2_beta_b")
      .defaultValue(false)
      .doc(
          "helical: false (Wan 2015): the sum of the transverse spur slices is the transverse "
          "stiffness k; true: that sum is taken as the normal-plane stiffness k_n and projected "
          "to the transverse plane, k = k_n cos² β_b (F_t = F_n cos β_b, δ_n = δ_t cos β_b)");
  schema.integer("mesh_stiffness.potential_energy.table_points")
      .min(16)
      .max(1000000)
      .defaultValue(257)
      .doc("nodes of the pair-stiffness table along the path of contact");

  schema.section("mesh_stiffness.iso6336", "ISO 6336-1 method B (§9).");
  schema.real("mesh_stiffness.iso6336.c_m")
      .unit("-")
      .positive()
      .defaultValue(0.8)
      .doc("theoretical correction factor C_M (0.8 solid discs)");
  schema.real("mesh_stiffness.iso6336.web_width")
      .unit("m")
      .positive()
      .optional()
      .doc("web width b_s (with rim_thickness: C_R of ISO eq. 78)");
  schema.real("mesh_stiffness.iso6336.rim_thickness")
      .unit("m")
      .positive()
      .optional()
      .doc("rim thickness s_R");
  schema.boolean("mesh_stiffness.iso6336.material_factor")
      .defaultValue(true)
      .doc("scale by E / 206 GPa (ISO §9.3.1)");
}

ConfigSchema stiffnessSchema() {
  ConfigSchema schema("stiffness",
                      "Mesh stiffness of a gear pair over one mesh period: API, step, Fourier, "
                      "potential-energy beam (spur and helical) and ISO 6336 models, their "
                      "statistics and Fourier coefficients, and the loaded static transmission "
                      "error.");
  schema.string("title").optional().doc("free text describing the study");
  addGearPairSections(schema);
  addMeshStiffnessSections(schema);
  addOutputSection(schema);
  return schema;
}

PotentialEnergyOptions potentialEnergyOptionsFromConfig(const Config& config) {
  const std::string p = "mesh_stiffness.potential_energy.";
  PotentialEnergyOptions o;
  o.root = config.string(p + "root") == "trochoid" ? ToothRoot::kTrochoid : ToothRoot::kStraight;
  o.foundation_arm = config.string(p + "foundation_arm") == "contact_height"
                         ? FoundationArm::kContactHeight
                         : FoundationArm::kForceLine;
  o.foundation = config.boolean(p + "foundation");
  o.pinion_hub_radius = config.optionalReal(p + "pinion_hub_radius");
  o.gear_hub_radius = config.optionalReal(p + "gear_hub_radius");
  o.slices = static_cast<int>(config.integer(p + "slices"));
  o.helical_cos2_beta_b = config.boolean(p + "helical_cos2_beta_b");
  o.table_points = static_cast<int>(config.integer(p + "table_points"));
  return o;
}

Iso6336Options iso6336OptionsFromConfig(const Config& config) {
  Iso6336Options o;
  o.c_m = config.real("mesh_stiffness.iso6336.c_m");
  o.web_width = config.optionalReal("mesh_stiffness.iso6336.web_width");
  o.rim_thickness = config.optionalReal("mesh_stiffness.iso6336.rim_thickness");
  o.material_factor = config.boolean("mesh_stiffness.iso6336.material_factor");
  if (o.web_width.has_value() != o.rim_thickness.has_value()) {
    throw InputError("mesh_stiffness.iso6336.rim_thickness", "",
                     "web_width and rim_thickness go together (ISO eq. 78); give both or neither");
  }
  return o;
}

std::shared_ptr<const MeshStiffness> buildMeshStiffnessModel(const std::string& name,
                                                             const Config& config,
                                                             const GearPair& pair,
                                                             std::vector<std::string>& warnings) {
  ModelFactory factory(config, pair);
  auto model = factory.make(name);
  warnings.insert(warnings.end(), factory.warnings.begin(), factory.warnings.end());
  return model;
}

MeshStiffnessModels buildMeshStiffnessModels(const Config& config, const GearPair& pair) {
  const auto names = config.stringList("mesh_stiffness.models");
  if (names.empty()) {
    throw InputError("mesh_stiffness.models", "[]", "name at least one model");
  }
  ModelFactory factory(config, pair);
  MeshStiffnessModels out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (std::find(names.begin(), names.begin() + i, names[i]) != names.begin() + i) {
      throw InputError("mesh_stiffness.models", "\"" + names[i] + "\"", "listed twice");
    }
    out.models.push_back(factory.make(names[i]));
  }
  out.warnings = factory.warnings;
  return out;
}

TransmissionErrorSpec transmissionErrorFromConfig(const Config& config) {
  TransmissionErrorSpec spec;
  spec.force = config.real("mesh_stiffness.transmitted_force");
  std::vector<double> phases = config.realList("mesh_stiffness.error_phases_deg");
  for (double& p : phases) p *= kDegree;
  spec.error.addFourier(config.realList("mesh_stiffness.error_amplitudes"), phases,
                        "mesh_stiffness.error_amplitudes", "mesh_stiffness.error_phases_deg");
  const auto table_phases = config.realList("mesh_stiffness.error_table_phases");
  if (!table_phases.empty() || !config.realList("mesh_stiffness.error_table_values").empty()) {
    spec.error.addTable(table_phases, config.realList("mesh_stiffness.error_table_values"),
                        "mesh_stiffness.error");
  }
  return spec;
}

}  // namespace geardyn::config
