/// `identify CONFIG`: the gear-mesh DTE parameters from full-spectrum whirl peaks
/// (Rao 2023 §4.6–4.7, ch. 5), by the thesis's three-step algorithm or the joint estimator.

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <numbers>

#include "geardyn/analysis/analyses.h"
#include "geardyn/analysis/identify_results.h"
#include "geardyn/analysis/rotor_results.h"
#include "geardyn/config/identify_config.h"
#include "geardyn/config/rotor_config.h"
#include "geardyn/config/rotor_gearbox.h"
#include "geardyn/error.h"
#include "geardyn/system/lateral_rotor_reduction.h"

namespace geardyn::analysis {

namespace {

/// The spectra `input.spectra` names (result folders, relative to the configuration's folder).
std::vector<analysis::WhirlSpectrumInput> readInputs(const config::Config& config,
                                                     const std::filesystem::path& base) {
  std::vector<analysis::WhirlSpectrumInput> inputs;
  for (const auto& entry : config.stringList("input.spectra")) {
    std::filesystem::path folder = entry;
    if (folder.is_relative()) folder = base / folder;
    inputs.push_back(analysis::readWhirlSpectrum(folder, "input.spectra"));
  }
  if (inputs.empty()) throw InputError("input.spectra", "[]", "name at least one result folder");
  return inputs;
}

/// The rotor the spectra were simulated with, when known: `truth.rotor_config`, or the first
/// input that records one; it must have the known rotor's tooth counts.
std::optional<LateralRotorSpec> truthOf(const config::Config& config,
                                        const std::filesystem::path& base,
                                        const std::vector<analysis::WhirlSpectrumInput>& inputs,
                                        const LateralRotorSpec& known) {
  std::optional<LateralRotorSpec> truth;
  if (config.has("truth.rotor_config")) {
    std::filesystem::path file = config.string("truth.rotor_config");
    if (file.is_relative()) file = base / file;
    truth = config::lateralRotorSpecFromConfig(config::loadConfigFile(file, config::rotorSchema()));
  } else {
    for (const auto& in : inputs)
      if (in.truth && !truth) truth = in.truth;
  }
  if (truth &&
      (truth->pinion_teeth != known.pinion_teeth || truth->gear_teeth != known.gear_teeth)) {
    throw InputError(
        "rotor.pinion_teeth", fmt::format("{}/{}", known.pinion_teeth, known.gear_teeth),
        fmt::format("the truth's rotor has {}/{} teeth", truth->pinion_teeth, truth->gear_teeth));
  }
  return truth;
}

/// resimulated_peaks.csv: the measured peaks against the identified model's (thesis Figs.
/// 5.12/5.14); returns the largest difference and the largest measured amplitude [m].
std::pair<double, double> addResimulatedPeaks(const DteIdentification& r,
                                              const std::vector<MeasuredWhirlPeaks>& data,
                                              AnalysisResult& result) {
  io::CsvTable resim({"speed_rpm", "shaft", "component", "frequency_hz", "measured_re_m",
                      "measured_im_m", "measured_amplitude_m", "model_re_m", "model_im_m",
                      "model_amplitude_m"});
  double worst = 0.0, largest = 0.0;
  for (const auto& d : data) {
    LateralRotorSpec at = r.spec;
    at.pinion_speed = d.pinion_speed;
    const auto model = modelWhirlPeaks(at);
    for (int s = 0; s < 2; ++s) {
      for (const auto& m : model[s]) {
        std::complex<double> measured = 0.0;
        for (const auto& c : d.peaks[s])
          if (c.name == m.name) measured = c.value;
        resim.addRow({60.0 * d.pinion_speed, std::string(analysis::kShaftNames[s]), m.name,
                      m.frequency, measured.real(), measured.imag(), std::abs(measured),
                      m.value.real(), m.value.imag(), std::abs(m.value)});
        worst = std::max(worst, std::abs(measured - m.value));
        largest = std::max(largest, std::abs(measured));
      }
    }
  }
  result.addTable("resimulated_peaks.csv", resim);
  return {worst, largest};
}

/// summary.json's priors: the mesh stiffness and damping the fit was told.
nlohmann::ordered_json priorsJson(const config::Config& config,
                                  const IdentificationOptions& id_options,
                                  const DteIdentification& r) {
  nlohmann::ordered_json priors = nlohmann::ordered_json::object();
  if (id_options.mesh_stiffness.value) {
    priors["mesh_stiffness"] = {{"value", *id_options.mesh_stiffness.value},
                                {"relative_sd", id_options.mesh_stiffness.relative_sd},
                                {"source", config.string("prior.mesh_stiffness_from") == "iso6336"
                                               ? "ISO 6336-1 method B, c_gamma_alpha b"
                                               : "prior.mesh_stiffness"}};
  }
  if (id_options.mesh_damping.value) {
    priors["mesh_damping"] = {{"value", *id_options.mesh_damping.value},
                              {"relative_sd", id_options.mesh_damping.relative_sd}};
  } else if (r.method == IdentificationMethod::kJoint) {
    priors["mesh_damping_ratio"] = {{"value", id_options.mesh_damping_ratio},
                                    {"relative_sd", id_options.mesh_damping_ratio_sd}};
  }
  return priors;
}

/// The parameters the spectra do not determine, with a warning for the mesh stiffness of a
/// joint fit (it is seen only through the small static deflection).
std::vector<std::string> notIdentifiable(const DteIdentification& r,
                                         const IdentificationOptions& id_options,
                                         std::vector<std::string>& warnings) {
  std::vector<std::string> not_identifiable;
  if (!r.mesh_stiffness.identifiable) not_identifiable.push_back("mesh_stiffness");
  if (!r.mesh_damping.identifiable) not_identifiable.push_back("mesh_damping");
  if (!r.mean_te.identifiable) not_identifiable.push_back("mean_te");
  for (std::size_t i = 0; i < r.te_x.size(); ++i) {
    if (!r.te_x[i].amplitude.identifiable)
      not_identifiable.push_back(fmt::format("te_x_{}", i + 1));
    if (!r.te_y[i].amplitude.identifiable)
      not_identifiable.push_back(fmt::format("te_y_{}", i + 1));
  }
  for (const auto& name : not_identifiable) {
    if (name == "mesh_stiffness" && r.method == IdentificationMethod::kJoint) {
      warnings.push_back(fmt::format(
          "mesh_stiffness is not identifiable from these spectra{} (95 % interval [{:.3g}, {:.3g}] "
          "N/m): the lateral probes see the mesh only through its small static relative "
          "deflection, and the TE amplitudes depend on it; {}",
          id_options.mesh_stiffness.value ? " and its prior" : "", r.mesh_stiffness.low,
          r.mesh_stiffness.high,
          id_options.mesh_stiffness.value
              ? "the estimates' intervals include this uncertainty"
              : "give prior.mesh_stiffness or prior.mesh_stiffness_from = \"iso6336\" with the "
                "gear pair"));
    }
  }
  return not_identifiable;
}

/// The identified values against the rotor the spectra were simulated with.
nlohmann::ordered_json truthComparison(const DteIdentification& r, const LateralRotorSpec& truth) {
  double te = 0.0, phase = 0.0;
  for (std::size_t i = 0; i < r.te_x.size() && i < truth.te_x.size(); ++i) {
    te = std::max({te, std::abs(r.te_x[i].amplitude.value / truth.te_x[i].amplitude - 1.0),
                   std::abs(r.te_y[i].amplitude.value / truth.te_y[i].amplitude - 1.0)});
    phase = std::max({phase,
                      std::abs(std::remainder(r.te_x[i].phase.value - truth.te_x[i].phase,
                                              2 * std::numbers::pi)),
                      std::abs(std::remainder(r.te_y[i].phase.value - truth.te_y[i].phase,
                                              2 * std::numbers::pi))});
  }
  return {
      {"mesh_stiffness_relative_error", r.mesh_stiffness.value / truth.mesh_stiffness - 1.0},
      {"mean_te_relative_error", r.mean_te.value / truth.mean_te - 1.0},
      {"mesh_damping_relative_error", r.mesh_damping.value / truth.mesh_damping - 1.0},
      {"te_amplitude_max_relative_error", te},
      {"te_phase_max_error_rad", phase},
      {"pinion_runout_relative_error", r.pinion_runout.amplitude.value / truth.pinion_runout - 1.0},
      {"gear_runout_relative_error", r.gear_runout.amplitude.value / truth.gear_runout - 1.0}};
}

/// The printed lines: the fit's message, each value with its 95 % interval, TE and runouts.
std::string identifyReport(const DteIdentification& r, double seconds) {
  const auto ci = [](const IdentifiedValue& v, double scale, const char* unit) {
    return fmt::format("{:.5g} {}, 95 % interval {:.4g} {} to {:.4g} {}{}", v.value * scale, unit,
                       v.low * scale, unit, v.high * scale, unit,
                       v.identifiable ? "" : " (not identifiable)");
  };
  std::string text = fmt::format("{} ({:.3g} ms)\n", r.message, 1e3 * seconds);
  text += fmt::format("  k_m  = {}\n", ci(r.mesh_stiffness, 1.0, "N/m"));
  text += fmt::format("  e_m  = {}\n", ci(r.mean_te, 1e6, "um"));
  text += fmt::format("  c_m  = {}\n", ci(r.mesh_damping, 1.0, "N s/m"));
  for (std::size_t i = 0; i < r.te_x.size(); ++i) {
    text += fmt::format("  TE {}: x {:.4g} um at {:.4g} rad, y {:.4g} um at {:.4g} rad\n", i + 1,
                        1e6 * r.te_x[i].amplitude.value, r.te_x[i].phase.value,
                        1e6 * r.te_y[i].amplitude.value, r.te_y[i].phase.value);
  }
  text += fmt::format("  runouts: pinion {:.4g} um at {:.4g} rad, gear {:.4g} um at {:.4g} rad\n",
                      1e6 * r.pinion_runout.amplitude.value, r.pinion_runout.phase.value,
                      1e6 * r.gear_runout.amplitude.value, r.gear_runout.phase.value);
  return text;
}

}  // namespace

AnalysisResult identifyAnalysis(const config::Config& config, const AnalysisContext& context) {
  AnalysisResult result("identify", config, context);
  const std::filesystem::path base = std::filesystem::path(config.source()).parent_path();
  // The rig is a gearbox (config/rotor_gearbox.h); the identification inverts the 4-DOF rotor
  // that gearbox reduces to (system/lateral_rotor_reduction.h: its closed form is the fast path).
  std::vector<std::string> translation_warnings;  // the translation's gearbox has none to give
  const LateralRotorSpec known = lateralRotorReduction(config::lateralRotorGearTrain(
      config::knownRotorFromConfig(config), config.source(), translation_warnings));
  const std::vector<analysis::WhirlSpectrumInput> inputs = readInputs(config, base);
  std::vector<MeasuredWhirlPeaks> data;
  for (const auto& in : inputs) data.push_back(in.peaks);
  const std::optional<LateralRotorSpec> truth = truthOf(config, base, inputs, known);

  IdentificationOptions id_options = config::identificationOptionsFromConfig(config);
  id_options.progress =
      id_options.method == IdentificationMethod::kJoint
          ? context.progressFor("identify: joint fit", "iterations of max_iterations")
          : context.progressFor("identify: three-step fit", "mesh harmonics");
  const auto start = std::chrono::steady_clock::now();
  const DteIdentification r = identifyDte(known, data, id_options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  io::RunSummary& summary = result.summary;
  summary.status = r.converged ? "ok" : "not_converged";
  result.addTable("identified.csv", analysis::identifiedTable(r, truth));
  const auto [worst, largest] = addResimulatedPeaks(r, data, result);

  nlohmann::ordered_json inputs_json = nlohmann::ordered_json::array();
  for (const auto& in : inputs) {
    inputs_json.push_back(
        {{"folder", in.folder.string()},
         {"file", in.file},
         {"speed_rpm", 60.0 * in.peaks.pinion_speed},
         {"coefficient_noise",
          {{"pinion", in.peaks.coefficient_sigma[0]}, {"gear", in.peaks.coefficient_sigma[1]}}}});
  }
  summary.results = {
      {"inputs", inputs_json},
      {"fit",
       {{"method", r.method == IdentificationMethod::kJoint ? "joint" : "three_step"},
        {"converged", r.converged},
        {"iterations", r.iterations},
        {"chi_square", r.chi_square},
        {"degrees_of_freedom", r.degrees_of_freedom},
        {"message", r.message},
        {"wall_time_s", seconds},
        {"resimulated_max_difference", worst},
        {"resimulated_relative_difference", largest > 0 ? worst / largest : 0.0}}},
      {"identified", analysis::identifiedJson(r)},
      {"phase_reference",
       "the spectra's (t = 0 of a simulation, the first keyphasor pulse of a "
       "record); probe frame"}};
  summary.results["priors"] = priorsJson(config, id_options, r);
  summary.results["not_identifiable"] = notIdentifiable(r, id_options, summary.warnings);
  if (truth) summary.results["truth_comparison"] = truthComparison(r, *truth);
  if (!r.converged) result.errors.push_back(r.message);
  context.warnings(summary.warnings);
  result.report = identifyReport(r, seconds);
  result.summary.numerical_failure = !r.converged;
  return result;
}

}  // namespace geardyn::analysis
