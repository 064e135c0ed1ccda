#include "geardyn/config/simulate_config.h"

#include <fmt/format.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "geardyn/config/gear_pair_gearbox.h"
#include "geardyn/config/geometry_config.h"
#include "geardyn/config/ltca_config.h"
#include "geardyn/config/stiffness_config.h"
#include "geardyn/contact/loaded_contact.h"
#include "geardyn/error.h"
#include "geardyn/geometry/gear_pair.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "geardyn/stiffness/mesh_stiffness_summary.h"
#include "geardyn/stiffness/potential_energy_stiffness.h"
#include "geardyn/stiffness/step_stiffness.h"
#include "geardyn/stiffness/tabulated_stiffness.h"

namespace geardyn::config {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

using Json = nlohmann::ordered_json;

}  // namespace

GearPairModelBuild readGearPairModel(const Config& config, bool require_speed) {
  GearPairModelBuild b;
  b.nondimensional = config.string("model.units") == "nondimensional";
  std::optional<GearPair> pair;
  if (hasGearPair(config)) pair.emplace(gearPairSpecFromConfig(config));

  // The transmitted force (also needed by the loaded contact analysis below).
  const auto meanForce = [&]() {
    if (config.has("model.mean_force") == config.has("model.torque")) {
      throw InputError("model.mean_force", "",
                       config.has("model.mean_force") ? "give mean_force or torque, not both"
                                                      : "required (or model.torque)");
    }
    if (config.has("model.mean_force")) return config.real("model.mean_force");
    if (config.has("model.pinion_base_radius"))
      return config.real("model.torque") / config.real("model.pinion_base_radius");
    if (pair) return config.real("model.torque") / pair->pinion().base_radius;
    throw InputError("model.pinion_base_radius", "", "required (or give [pinion] and [gear])");
  };
  std::vector<double> ltca_phases, ltca_error;  // δ − F/K of the loaded contact (type ltca)

  // Stiffness.
  const bool contacts = config.string("model.type") == "gear_pair_contacts";
  if (config.string("model.type") == "gear_pair_ltca") {
    // One contact element per tooth pair (and slice): Σ_j k_j max(0, y − g_j) with the
    // potential-energy stiffness and the modifications as gaps; k(φ) stays the unmodified
    // potential-energy stiffness (scales, k̄, the linear start).
    if (!pair) {
      throw InputError("model.type", "\"gear_pair_ltca\"",
                       "needs the gear pair: [pinion], [gear] (and [pair])");
    }
    if (b.nondimensional) {
      throw InputError("model.type", "\"gear_pair_ltca\"", "needs SI units (model.units)");
    }
    const auto contact = loadedContactFromConfig(
        config, *pair, static_cast<int>(config.integer("model.stiffness.ltca_slices")));
    b.spec.contact_elements = std::make_shared<LoadedContactElements>(contact);
  }
  const std::string type = contacts                  ? "contacts"
                           : b.spec.contact_elements ? "potential_energy"
                                                     : config.string("model.stiffness.type");
  const double contact_ratio = config.has("model.stiffness.contact_ratio")
                                   ? config.real("model.stiffness.contact_ratio")
                               : pair ? pair->contactRatioTotal()
                                      : 1.0;
  if (contacts) {
    // Saletti et al. 2025 (eqs. 13–14, Figs. 3–4): n_c = ⌈ε⌉ + 1 elements of stiffness k_c, each
    // with a gap that is 0 in its contact window (length ε T_m, shifted by T_m from element to
    // element) and open outside it. With Saletti's x (positive when the teeth separate) the
    // element force is −k_c (x + g) for x + g < 0. In our deflection y = −x (> 0 when loaded)
    // the elements in their windows add up to k(t) max(0, y) with k(t) = k_c × (windows open at
    // t): exactly our model with a one-sided contact and the step stiffness n k_c / (n+1) k_c.
    if (!config.has("model.contact_stiffness")) {
      throw InputError("model.contact_stiffness", "",
                       "required for type = \"gear_pair_contacts\" [N/m]");
    }
    if (!config.has("model.stiffness.contact_ratio") && !pair) {
      throw InputError("model.stiffness.contact_ratio", "",
                       "required for type = \"gear_pair_contacts\" without a gear pair");
    }
    const double k_c = config.real("model.contact_stiffness");
    const double n = std::floor(contact_ratio);
    b.spec.stiffness = std::make_shared<StepMeshStiffness>(n * k_c, (n + 1.0) * k_c, contact_ratio);
    if (config.string("model.contact") != "one_sided") {
      b.warnings.push_back(
          "gear_pair_contacts uses the elements' one-sided contact; model.contact is ignored");
    }
  } else if (type == "fourier") {
    auto c = config.realList("model.stiffness.cos");
    auto s = config.realList("model.stiffness.sin");
    if (s.empty()) s.assign(c.size(), 0.0);  // only cosines given
    if (c.empty()) c.assign(s.size(), 0.0);
    if (c.size() != s.size()) {
      throw InputError("model.stiffness.sin", fmt::format("{} values", s.size()),
                       fmt::format("need one sine per cosine coefficient ({})", c.size()));
    }
    double mean = b.nondimensional ? 1.0 : 0.0;
    if (config.has("model.stiffness.mean")) mean = config.real("model.stiffness.mean");
    if (mean <= 0.0)
      throw InputError("model.stiffness.mean", "", "required for type = \"fourier\" [N/m]");
    std::vector<double> amplitudes, phases;
    for (std::size_t i = 0; i < c.size(); ++i) {
      // cos_i cos x + sin_i sin x = A cos(x − φ) with A = √(cos² + sin²), φ = atan2(sin, cos).
      amplitudes.push_back(std::hypot(c[i], s[i]));
      phases.push_back(std::atan2(s[i], c[i]));
    }
    b.spec.stiffness =
        std::make_shared<FourierMeshStiffness>(mean, amplitudes, phases, contact_ratio);
  } else if (type == "step") {
    if (config.has("model.stiffness.k_min") && config.has("model.stiffness.k_max")) {
      b.spec.stiffness =
          std::make_shared<StepMeshStiffness>(config.real("model.stiffness.k_min"),
                                              config.real("model.stiffness.k_max"), contact_ratio);
    } else if (config.has("model.stiffness.mean") || b.nondimensional) {
      const double mean =
          config.has("model.stiffness.mean") ? config.real("model.stiffness.mean") : 1.0;
      b.spec.stiffness =
          std::make_shared<StepMeshStiffness>(StepMeshStiffness::fromMean(mean, contact_ratio));
    } else {
      throw InputError("model.stiffness.k_min", "",
                       "type = \"step\" needs k_min and k_max, or mean [N/m]");
    }
  } else {
    if (!pair) {
      throw InputError("model.stiffness.type", "\"" + type + "\"",
                       "computes the stiffness from the gears: give [pinion], [gear] (and [pair])");
    }
    if (type == "ltca") {
      // The mesh linearised about the mean force F: F = K(φ)(δ − E(φ)) with K the tangent
      // stiffness of the loaded contact and E = δ − F/K (contact/load_statistics.h).
      if (b.nondimensional) {
        throw InputError("model.stiffness.type", "\"ltca\"", "needs SI units (model.units)");
      }
      const auto contact = loadedContactFromConfig(
          config, *pair, static_cast<int>(config.integer("model.stiffness.ltca_slices")));
      const double force = meanForce();
      std::vector<double> tangent;
      for (const auto& p : contact->sweep(
               force, static_cast<int>(config.integer("model.stiffness.ltca_positions")))) {
        ltca_phases.push_back(p.phase);
        tangent.push_back(p.tangent);
        ltca_error.push_back(p.ste - force / p.tangent);
      }
      b.spec.stiffness = std::make_shared<TabulatedMeshStiffness>(
          ltca_phases, tangent, contact->stiffness().contactRatio(), "ltca");
    } else {
      b.spec.stiffness = buildMeshStiffnessModel(type, config, *pair, b.warnings);
    }
  }
  b.mean_stiffness = summarizeMeshStiffness(*b.spec.stiffness, 0).mean;

  // Mass.
  const auto base_radius = [&](const char* key, bool pinion) {
    if (config.has(key)) return config.real(key);
    if (pair) return pinion ? pair->pinion().base_radius : pair->gear().base_radius;
    throw InputError(key, "", "required (or give [pinion] and [gear])");
  };
  if (b.nondimensional) {
    if (config.has("model.mass")) {
      throw InputError("model.mass", fmt::format("{:g}", config.real("model.mass")),
                       "not used in nondimensional units (m = 1): remove it");
    }
    b.spec.mass = 1.0;
  } else if (config.has("model.mass")) {
    b.spec.mass = config.real("model.mass");
  } else {
    const bool given = config.has("model.pinion_inertia") && config.has("model.gear_inertia");
    if (!given && !pair) {
      throw InputError("model.mass", "",
                       "required: the equivalent mass, or pinion_inertia and gear_inertia with the "
                       "base radii, or [pinion] and [gear]");
    }
    const double i1 = config.has("model.pinion_inertia") ? config.real("model.pinion_inertia")
                                                         : pair->pinion().polar_inertia;
    const double i2 = config.has("model.gear_inertia") ? config.real("model.gear_inertia")
                                                       : pair->gear().polar_inertia;
    b.spec.mass = equivalentMass(i1, base_radius("model.pinion_base_radius", true), i2,
                                 base_radius("model.gear_base_radius", false));
  }
  b.natural_frequency = std::sqrt(b.mean_stiffness / b.spec.mass);

  // Damping.
  const bool ratio = config.has("model.damping_ratio"), absolute = config.has("model.damping");
  if (ratio == absolute) {
    throw InputError(
        "model.damping_ratio", "",
        ratio ? "give damping_ratio or damping, not both" : "required (or model.damping)");
  }
  b.damping_ratio =
      ratio ? config.real("model.damping_ratio")
            : config.real("model.damping") / (2.0 * std::sqrt(b.mean_stiffness * b.spec.mass));
  b.spec.damping = ratio ? 2.0 * b.damping_ratio * std::sqrt(b.mean_stiffness * b.spec.mass)
                         : config.real("model.damping");
  if (b.damping_ratio >= 1.0) {
    b.warnings.push_back(fmt::format(
        "damping ratio ζ = {:.3g} >= 1: the mesh is overdamped (typical gear meshes: 0.02–0.1)",
        b.damping_ratio));
  }

  // Load.
  b.spec.mean_force = meanForce();

  // Contact elements are one-sided each; model.contact applies to the single-law models only.
  b.spec.contact = contacts || b.spec.contact_elements             ? ContactLaw::kOneSided
                   : config.string("model.contact") == "linear"    ? ContactLaw::kLinear
                   : config.string("model.contact") == "one_sided" ? ContactLaw::kOneSided
                                                                   : ContactLaw::kBacklash;
  // The file gives the full clearance j (as a gearbox); the law's half clearance is b = j/2.
  b.spec.backlash = 0.5 * config.real("model.normal_backlash");
  if (b.spec.contact != ContactLaw::kBacklash && b.spec.backlash > 0.0) {
    b.warnings.push_back("model.normal_backlash is ignored unless model.contact = \"backlash\"");
  }

  // Speed (not needed when the caller sweeps the frequency): excitation.mesh_frequency, or the
  // pinion speed excitation.speed_rpm, or the gear pair's own pair.speed_rpm (the file that
  // drives geometry and stiffness drives the dynamics at the same speed).
  const bool has_frequency = config.has("excitation.mesh_frequency");
  std::string speed_key = config.has("excitation.speed_rpm") ? "excitation.speed_rpm" : "";
  if (pair && config.has("pair.speed_rpm")) {
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
    b.spec.mesh_frequency = 0.0;  // the caller sets it
  } else if (has_frequency) {
    const double f = config.real("excitation.mesh_frequency");
    b.spec.mesh_frequency = b.nondimensional ? f / kTwoPi : f;  // Ω in rad per unit t₁
  } else {
    if (!pair) throw InputError(speed_key, "", "needs [pinion] teeth; or give mesh_frequency");
    if (b.nondimensional)
      throw InputError(speed_key, "",
                       "not available in nondimensional units: give mesh_frequency (Ω)");
    const double rpm = config.real(speed_key);
    b.spec.mesh_frequency = pair->spec().pinion.teeth * rpm / 60.0;
    if (auto note = speedPlausibilityNote(rpm, speed_key); !note.empty())
      b.warnings.push_back(std::move(note));
  }
  b.spec.initial_phase = config.real("excitation.initial_phase");

  // Extra harmonic forces.
  const auto f_amp = config.realList("model.extra_force_amplitudes");
  const auto f_freq = config.realList("model.extra_force_frequencies");
  auto f_phase = config.realList("model.extra_force_phases_deg");
  for (double& p : f_phase) p *= std::numbers::pi / 180.0;
  if (f_freq.size() != f_amp.size() || f_phase.size() != f_amp.size()) {
    throw InputError("model.extra_force_frequencies",
                     fmt::format("{} and {} values", f_freq.size(), f_phase.size()),
                     fmt::format("need one frequency and one phase per amplitude ({} amplitudes)",
                                 f_amp.size()));
  }
  for (std::size_t j = 0; j < f_amp.size(); ++j) {
    // Hz → rad/s; nondimensional: ω_j/ω_n is already the angular frequency in t₁ = ω_n t.
    b.spec.extra_forces.push_back(
        {f_amp[j], b.nondimensional ? f_freq[j] : kTwoPi * f_freq[j], f_phase[j]});
  }

  // At rest the mesh does not turn: a time response needs a period from somewhere.
  if (require_speed && !(b.spec.mesh_frequency > 0.0)) {
    const bool rpm = !speed_key.empty();
    const std::string key = rpm ? speed_key : "excitation.mesh_frequency";
    throw InputError(
        key,
        fmt::format("{:g}{}", config.real(key), rpm ? " rpm" : (b.nondimensional ? "" : " Hz")),
        "must be > 0: at rest the mesh does not turn and there is no mesh period to "
        "integrate over (the static deflection is F / k)");
  }

  // Transmission error.
  const std::string te = "model.transmission_error";
  auto te_phases = config.realList(te + ".phases_deg");
  for (double& p : te_phases) p *= std::numbers::pi / 180.0;
  b.spec.transmission_error.addFourier(config.realList(te + ".amplitudes"), te_phases, te);
  if (config.real(te + ".rectangular_amplitude") != 0.0) {
    b.spec.transmission_error.addRectangular(config.real(te + ".rectangular_amplitude"),
                                             config.real(te + ".rectangular_duty"),
                                             config.real(te + ".rectangular_start"), te);
  }
  if (!config.realList(te + ".table_phases").empty() ||
      !config.realList(te + ".table_values").empty()) {
    if (!ltca_phases.empty()) {
      throw InputError(te + ".table_phases", "(given)",
                       "model.stiffness.type = \"ltca\" supplies the error table itself");
    }
    b.spec.transmission_error.addTable(config.realList(te + ".table_phases"),
                                       config.realList(te + ".table_values"), te);
  }
  if (!ltca_phases.empty()) b.spec.transmission_error.addTable(ltca_phases, ltca_error, te);

  // Time step against the mesh and natural periods.
  const int steps = static_cast<int>(config.integer("solver.steps_per_period"));
  if (config.string("solver.method") == "newmark" && steps < 10 && b.spec.mesh_frequency > 0.0) {
    b.warnings.push_back(
        fmt::format("time step = mesh period / {} is larger than a tenth of the mesh period: raise "
                    "solver.steps_per_period to at least 10 (128 or more for the harmonics)",
                    steps));
  }
  if (config.string("solver.method") == "newmark" && b.spec.mesh_frequency > 0.0) {
    const double h = 1.0 / (b.spec.mesh_frequency * steps);
    const double natural_period = kTwoPi / b.natural_frequency;
    if (h > natural_period / 10.0) {
      const int needed =
          static_cast<int>(std::ceil(10.0 / (b.spec.mesh_frequency * natural_period)));
      b.warnings.push_back(
          fmt::format("time step {:.3g} is larger than a tenth of the natural period {:.3g}: raise "
                      "solver.steps_per_period to at least {} for accuracy",
                      h, natural_period, needed));
    }
  }
  return b;
}

GearPairModelBuild buildGearPairModel(const Config& config, bool require_speed) {
  GearPairModelBuild b = readGearPairModel(config, require_speed);
  if (!gearPairGearboxObstacle(config, b).empty()) return b;  // no gearbox form yet
  GearPairModel{b.spec};  // bad values named by the gear-pair model, in the file's terms
  // The file's gearbox, read back through the gearbox reader and reduced: the gear-pair solvers
  // are the one-pair train's fast path (system/sdof_reduction.h).
  b.spec = gearPairFromGearbox(gearPairGearboxToml(config, b), config.source() + " (gearbox)");
  b.mean_stiffness = summarizeMeshStiffness(*b.spec.stiffness, 0).mean;
  b.natural_frequency = std::sqrt(b.mean_stiffness / b.spec.mass);
  return b;
}

TimeResponseOptions timeResponseOptionsFromConfig(const Config& config) {
  TimeResponseOptions o;
  o.method = config.string("solver.method") == "newmark" ? TimeIntegrator::kNewmark
                                                         : TimeIntegrator::kDormandPrince;
  const std::string preset = config.string("solver.newmark");
  o.newmark = preset == "average_acceleration" ? NewmarkParameters::averageAcceleration()
              : preset == "linear_acceleration"
                  ? NewmarkParameters::linearAcceleration()
                  : NewmarkParameters{config.real("solver.beta"), config.real("solver.gamma")};
  o.steps_per_period = static_cast<int>(config.integer("solver.steps_per_period"));
  o.output_points_per_period = static_cast<int>(config.integer("solver.output_points_per_period"));
  o.relative_tolerance = config.real("solver.relative_tolerance");
  o.absolute_tolerance = config.real("solver.absolute_tolerance");
  o.steady_tolerance = config.real("solver.steady_tolerance");
  o.min_periods = static_cast<int>(config.integer("solver.min_periods"));
  o.max_periods = static_cast<int>(config.integer("solver.max_periods"));
  o.output_periods = static_cast<int>(config.integer("solver.output_periods"));
  o.start_from_static = config.string("solver.start") == "static";
  return o;
}

}  // namespace geardyn::config
