/// The one reading of a gear-pair file (config/gear_pair_keys.h).

#include "geardyn/config/gear_pair_keys.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "geardyn/config/geometry_config.h"
#include "geardyn/config/ltca_config.h"
#include "geardyn/config/stiffness_config.h"
#include "geardyn/contact/loaded_contact.h"
#include "geardyn/error.h"
#include "geardyn/geometry/gear.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "geardyn/stiffness/mesh_stiffness_summary.h"
#include "geardyn/stiffness/step_stiffness.h"
#include "geardyn/stiffness/tabulated_stiffness.h"

namespace geardyn::config {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kDeg = std::numbers::pi / 180.0;

/// model.mean_force, or model.torque over the pinion's base radius.
double meanForce(const Config& config, const GearPairKeys& k) {
  if (config.has("model.mean_force") == config.has("model.torque")) {
    throw InputError("model.mean_force", "",
                     config.has("model.mean_force") ? "give mean_force or torque, not both"
                                                    : "required (or model.torque)");
  }
  if (config.has("model.mean_force")) return config.real("model.mean_force");
  if (!(k.pinion_base_radius > 0.0)) {
    throw InputError("model.pinion_base_radius", "", "required (or give [pinion] and [gear])");
  }
  return config.real("model.torque") / k.pinion_base_radius;
}

/// The equivalent mass: model.mass, or the inertias (given or of the gear bodies) on the base
/// radii; 1 in nondimensional units.
double equivalentMassOf(const Config& config, const GearPairKeys& k) {
  if (k.nondimensional) {
    if (config.has("model.mass")) {
      throw InputError("model.mass", fmt::format("{:g}", config.real("model.mass")),
                       "not used in nondimensional units (m = 1): remove it");
    }
    return 1.0;
  }
  if (config.has("model.mass")) return config.real("model.mass");
  const bool given = config.has("model.pinion_inertia") && config.has("model.gear_inertia");
  if (!given && !k.pair) {
    throw InputError("model.mass", "",
                     "required: the equivalent mass, or pinion_inertia and gear_inertia with the "
                     "base radii, or [pinion] and [gear]");
  }
  const auto base_radius = [&](const char* key, bool pinion) {
    if (config.has(key)) return config.real(key);
    if (k.pair) return pinion ? k.pair->pinion().base_radius : k.pair->gear().base_radius;
    throw InputError(key, "", "required (or give [pinion] and [gear])");
  };
  const double i1 = config.has("model.pinion_inertia") ? config.real("model.pinion_inertia")
                                                       : k.pair->pinion().polar_inertia;
  const double i2 = config.has("model.gear_inertia") ? config.real("model.gear_inertia")
                                                     : k.pair->gear().polar_inertia;
  return equivalentMass(i1, base_radius("model.pinion_base_radius", true), i2,
                        base_radius("model.gear_base_radius", false));
}

/// model.damping_ratio or model.damping (one of them).
void readDamping(const Config& config, GearPairKeys& k) {
  const bool ratio = config.has("model.damping_ratio"), absolute = config.has("model.damping");
  if (ratio == absolute) {
    throw InputError(
        "model.damping_ratio", "",
        ratio ? "give damping_ratio or damping, not both" : "required (or model.damping)");
  }
  if (absolute) {
    k.damping = config.real("model.damping");
  } else {
    k.damping_ratio = config.real("model.damping_ratio");
  }
}

/// The contact law; the file gives the full clearance j (as a gearbox).
void readContact(const Config& config, GearPairKeys& k) {
  const bool elements = config.string("model.type") != "gear_pair";
  const std::string law = config.string("model.contact");
  k.contact = elements || law == "one_sided" ? ContactLaw::kOneSided
              : law == "linear"              ? ContactLaw::kLinear
                                             : ContactLaw::kBacklash;
  k.backlash = config.real("model.normal_backlash");
  if (k.contact == ContactLaw::kBacklash && !(k.backlash > 0.0)) {
    throw InputError("model.normal_backlash", fmt::format("{:g} m", k.backlash),
                     "> 0 with model.contact = \"backlash\" (no clearance: contact = \"linear\")");
  }
  if (k.contact != ContactLaw::kBacklash && k.backlash > 0.0) {
    k.warnings.push_back("model.normal_backlash is ignored unless model.contact = \"backlash\"");
    k.backlash = 0.0;
  }
  if (config.string("model.type") == "gear_pair_contacts" && law != "one_sided") {
    k.warnings.push_back(
        "gear_pair_contacts uses the elements' one-sided contact; model.contact is ignored");
  }
}

/// The mesh frequency: excitation.mesh_frequency, or the pinion speed excitation.speed_rpm, or
/// the gear pair's own pair.speed_rpm (the file that drives geometry and stiffness drives the
/// dynamics at the same speed).
void readSpeed(const Config& config, bool require_speed, GearPairKeys& k) {
  const bool has_frequency = config.has("excitation.mesh_frequency");
  std::string speed_key = config.has("excitation.speed_rpm") ? "excitation.speed_rpm" : "";
  if (k.pair && config.has("pair.speed_rpm")) {
    if (!speed_key.empty() &&
        config.real("pair.speed_rpm") != config.real("excitation.speed_rpm")) {
      throw InputError("excitation.speed_rpm",
                       fmt::format("{:g} rpm", config.real("excitation.speed_rpm")),
                       fmt::format("must equal pair.speed_rpm = {:g} rpm when both are given "
                                   "(better: give the speed once, as pair.speed_rpm)",
                                   config.real("pair.speed_rpm")));
    }
    if (speed_key.empty() && !has_frequency) speed_key = "pair.speed_rpm";
  }
  if (has_frequency && !speed_key.empty()) {
    throw InputError("excitation.mesh_frequency", "",
                     fmt::format("give mesh_frequency or {}, not both", speed_key));
  }
  if (!has_frequency && speed_key.empty()) {
    if (require_speed)
      throw InputError("excitation.mesh_frequency", "",
                       "required (or excitation.speed_rpm, or pair.speed_rpm with [pinion])");
    k.mesh_frequency = 0.0;  // the caller sets it
  } else if (has_frequency) {
    const double f = config.real("excitation.mesh_frequency");
    k.mesh_frequency = k.nondimensional ? f / kTwoPi : f;  // Ω in rad per unit t₁
  } else {
    if (!k.pair) throw InputError(speed_key, "", "needs [pinion] teeth; or give mesh_frequency");
    if (k.nondimensional)
      throw InputError(speed_key, "",
                       "not available in nondimensional units: give mesh_frequency (Ω)");
    const double rpm = config.real(speed_key);
    k.mesh_frequency = k.pair->spec().pinion.teeth * rpm / 60.0;
    if (auto note = speedPlausibilityNote(rpm, speed_key); !note.empty())
      k.warnings.push_back(std::move(note));
  }
  // At rest the mesh does not turn: a time response needs a period from somewhere.
  if (require_speed && !(k.mesh_frequency > 0.0)) {
    const bool rpm = !speed_key.empty();
    const std::string key = rpm ? speed_key : "excitation.mesh_frequency";
    throw InputError(
        key,
        fmt::format("{:g}{}", config.real(key), rpm ? " rpm" : (k.nondimensional ? "" : " Hz")),
        "must be > 0: at rest the mesh does not turn and there is no mesh period to "
        "integrate over (the static deflection is F / k)");
  }
  k.initial_phase = config.real("excitation.initial_phase");
}

/// The Fourier series, the step or Saletti's contact elements as a stiffness model.
std::shared_ptr<const MeshStiffness> numericStiffness(const Config& config, const GearPairKeys& k) {
  const double contact_ratio = config.has("model.stiffness.contact_ratio")
                                   ? config.real("model.stiffness.contact_ratio")
                               : k.pair ? k.pair->contactRatioTotal()
                                        : 1.0;
  if (config.string("model.type") == "gear_pair_contacts") {
    // Saletti et al. 2025 (eqs. 13–14, Figs. 3–4): n_c = ⌈ε⌉ + 1 elements of stiffness k_c,
    // each with a gap that is 0 in its contact window (length ε T_m, shifted by T_m from element
    // to element) and open outside it. In our deflection y = −x (> 0 when loaded) the elements
    // in their windows add up to k(t) max(0, y) with k(t) = k_c × (windows open at t): a
    // one-sided contact with the step stiffness n k_c / (n+1) k_c.
    if (!config.has("model.contact_stiffness")) {
      throw InputError("model.contact_stiffness", "",
                       "required for type = \"gear_pair_contacts\" [N/m]");
    }
    if (!config.has("model.stiffness.contact_ratio") && !k.pair) {
      throw InputError("model.stiffness.contact_ratio", "",
                       "required for type = \"gear_pair_contacts\" without a gear pair");
    }
    const double k_c = config.real("model.contact_stiffness");
    const double n = std::floor(contact_ratio);
    return std::make_shared<StepMeshStiffness>(n * k_c, (n + 1.0) * k_c, contact_ratio);
  }
  const std::string type = config.string("model.stiffness.type");
  if (type == "fourier") {
    auto c = config.realList("model.stiffness.cos");
    auto s = config.realList("model.stiffness.sin");
    if (s.empty()) s.assign(c.size(), 0.0);  // only cosines given
    if (c.empty()) c.assign(s.size(), 0.0);
    if (c.size() != s.size()) {
      throw InputError("model.stiffness.sin", fmt::format("{} values", s.size()),
                       fmt::format("need one sine per cosine coefficient ({})", c.size()));
    }
    double mean = k.nondimensional ? 1.0 : 0.0;
    if (config.has("model.stiffness.mean")) mean = config.real("model.stiffness.mean");
    if (mean <= 0.0)
      throw InputError("model.stiffness.mean", "", "required for type = \"fourier\" [N/m]");
    std::vector<double> amplitudes, phases;
    for (std::size_t i = 0; i < c.size(); ++i) {
      // cos_i cos x + sin_i sin x = A cos(x − φ) with A = √(cos² + sin²), φ = atan2(sin, cos).
      amplitudes.push_back(std::hypot(c[i], s[i]));
      phases.push_back(std::atan2(s[i], c[i]));
    }
    return std::make_shared<FourierMeshStiffness>(mean, amplitudes, phases, contact_ratio);
  }
  if (type == "step") {
    if (config.has("model.stiffness.k_min") && config.has("model.stiffness.k_max")) {
      return std::make_shared<StepMeshStiffness>(config.real("model.stiffness.k_min"),
                                                 config.real("model.stiffness.k_max"),
                                                 contact_ratio);
    }
    if (config.has("model.stiffness.mean") || k.nondimensional) {
      const double mean =
          config.has("model.stiffness.mean") ? config.real("model.stiffness.mean") : 1.0;
      return std::make_shared<StepMeshStiffness>(StepMeshStiffness::fromMean(mean, contact_ratio));
    }
    throw InputError("model.stiffness.k_min", "",
                     "type = \"step\" needs k_min and k_max, or mean [N/m]");
  }
  return nullptr;  // from the gears
}

/// The stiffness: given as numbers, or from the gears (checked here: the pair is needed).
void readStiffness(const Config& config, GearPairKeys& k) {
  const std::string model = config.string("model.type");
  const std::string type = config.string("model.stiffness.type");
  k.tooth_pairs = model == "gear_pair_ltca";
  if (k.tooth_pairs) {
    // One contact element per tooth pair (and slice): Σ_j k_j max(0, y − g_j) with the
    // potential-energy stiffness and the modifications as gaps.
    if (!k.pair) {
      throw InputError("model.type", "\"gear_pair_ltca\"",
                       "needs the gear pair: [pinion], [gear] (and [pair])");
    }
    if (k.nondimensional) {
      throw InputError("model.type", "\"gear_pair_ltca\"", "needs SI units (model.units)");
    }
    return;
  }
  k.numeric_stiffness = numericStiffness(config, k);
  if (k.numeric_stiffness) return;
  if (!k.pair) {
    throw InputError("model.stiffness.type", "\"" + type + "\"",
                     "computes the stiffness from the gears: give [pinion], [gear] (and [pair])");
  }
  if (type == "ltca") {
    // The mesh linearised about the mean force F: F = K(φ)(δ − E(φ)) with K the tangent
    // stiffness of the loaded contact and E = δ − F/K (stats/load_statistics.h).
    if (k.nondimensional) {
      throw InputError("model.stiffness.type", "\"ltca\"", "needs SI units (model.units)");
    }
    const auto contact = loadedContactFromConfig(
        config, *k.pair, static_cast<int>(config.integer("model.stiffness.ltca_slices")));
    k.mean_force = meanForce(config, k);
    LinearisedContactTables t;
    t.contact_ratio = contact->stiffness().contactRatio();
    for (const auto& p : contact->sweep(
             k.mean_force, static_cast<int>(config.integer("model.stiffness.ltca_positions")))) {
      t.phases.push_back(p.phase);
      t.tangent.push_back(p.tangent);
      t.error.push_back(p.ste - k.mean_force / p.tangent);
    }
    k.linearised = std::move(t);
  }
}

/// The file's transmission error (series, rectangular wave, table).
void readError(const Config& config, GearPairKeys& k) {
  const std::string te = "model.transmission_error";
  auto te_phases = config.realList(te + ".phases_deg");
  for (double& p : te_phases) p *= kDeg;
  k.error.addFourier(config.realList(te + ".amplitudes"), te_phases, te + ".amplitudes",
                     te + ".phases_deg");
  if (config.real(te + ".rectangular_amplitude") != 0.0) {
    k.error.addRectangular(config.real(te + ".rectangular_amplitude"),
                           config.real(te + ".rectangular_duty"),
                           config.real(te + ".rectangular_start"), te);
  }
  if (!config.realList(te + ".table_phases").empty() ||
      !config.realList(te + ".table_values").empty()) {
    if (k.linearised) {
      throw InputError(te + ".table_phases", "(given)",
                       "model.stiffness.type = \"ltca\" supplies the error table itself");
    }
    k.error.addTable(config.realList(te + ".table_phases"), config.realList(te + ".table_values"),
                     te);
  }
}

/// Extra harmonic forces along the line of action.
void readExtraForces(const Config& config, GearPairKeys& k) {
  const auto f_amp = config.realList("model.extra_force_amplitudes");
  const auto f_freq = config.realList("model.extra_force_frequencies");
  auto f_phase = config.realList("model.extra_force_phases_deg");
  for (double& p : f_phase) p *= kDeg;
  if (f_freq.size() != f_amp.size() || f_phase.size() != f_amp.size()) {
    throw InputError("model.extra_force_frequencies",
                     fmt::format("{} and {} values", f_freq.size(), f_phase.size()),
                     fmt::format("need one frequency and one phase per amplitude ({} amplitudes)",
                                 f_amp.size()));
  }
  for (std::size_t j = 0; j < f_amp.size(); ++j) {
    // Hz → rad/s; nondimensional: ω_j/ω_n is already the angular frequency in t₁ = ω_n t.
    k.extra_forces.push_back(
        {f_amp[j], k.nondimensional ? f_freq[j] : kTwoPi * f_freq[j], f_phase[j]});
  }
}

}  // namespace

GearPairKeys readGearPairKeys(const Config& config, bool require_speed) {
  GearPairKeys k;
  k.nondimensional = config.string("model.units") == "nondimensional";
  if (hasGearPair(config)) k.pair.emplace(gearPairSpecFromConfig(config));
  k.pinion_base_radius = config.has("model.pinion_base_radius")
                             ? config.real("model.pinion_base_radius")
                         : k.pair ? k.pair->pinion().base_radius
                                  : 0.0;
  readStiffness(config, k);
  k.mass = equivalentMassOf(config, k);
  readDamping(config, k);
  k.mean_force = meanForce(config, k);
  readContact(config, k);
  readSpeed(config, require_speed, k);
  readExtraForces(config, k);
  readError(config, k);
  return k;
}

GearPairModelSpec directGearPairModel(const Config& config, const GearPairKeys& keys,
                                      std::vector<std::string>& warnings) {
  GearPairModelSpec s;
  s.mass = keys.mass;
  s.mean_force = keys.mean_force;
  s.mesh_frequency = keys.mesh_frequency;
  s.initial_phase = keys.initial_phase;
  s.contact = keys.contact;
  s.backlash = 0.5 * keys.backlash;  // the law's half clearance b = j/2
  s.transmission_error = keys.error;
  s.extra_forces = keys.extra_forces;
  if (keys.numeric_stiffness) {
    s.stiffness = keys.numeric_stiffness;
  } else if (keys.linearised) {
    const auto& t = *keys.linearised;
    s.stiffness =
        std::make_shared<TabulatedMeshStiffness>(t.phases, t.tangent, t.contact_ratio, "ltca");
    s.transmission_error.addTable(t.phases, t.error, "model.transmission_error");
  } else {
    if (keys.tooth_pairs) {
      s.contact_elements = std::make_shared<LoadedContactElements>(loadedContactFromConfig(
          config, *keys.pair, static_cast<int>(config.integer("model.stiffness.ltca_slices"))));
    }
    s.stiffness = buildMeshStiffnessModel(
        keys.tooth_pairs ? "potential_energy" : config.string("model.stiffness.type"), config,
        *keys.pair, warnings);
  }
  s.damping = keys.damping ? *keys.damping
                           : 2.0 * keys.damping_ratio *
                                 std::sqrt(summarizeMeshStiffness(*s.stiffness, 0).mean * s.mass);
  return s;
}

}  // namespace geardyn::config
