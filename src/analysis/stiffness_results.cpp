#include "geardyn/analysis/stiffness_results.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geardyn/config/geometry_config.h"
#include "geardyn/config/output_section.h"
#include "geardyn/config/stiffness_config.h"
#include "geardyn/error.h"
#include "geardyn/stiffness/api_stiffness.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "geardyn/stiffness/mesh_stiffness_summary.h"
#include "geardyn/stiffness/step_stiffness.h"
#include "geardyn/units.h"

namespace geardyn::analysis {
namespace {

using geardyn::units::kDegree;

nlohmann::ordered_json summaryJson(const MeshStiffness& k, int order) {
  const MeshStiffnessSummary s = summarizeMeshStiffness(k, order);
  nlohmann::ordered_json json;
  json["model"] = k.model();
  json["mean"] = s.mean;
  json["min"] = s.min;
  json["max"] = s.max;
  json["std"] = s.std;
  json["peak_to_peak"] = s.max - s.min;
  json["contact_ratio"] = k.contactRatio();
  std::vector<double> relative;
  for (double a : s.amplitude) relative.push_back(a / s.mean);
  json["fourier"] = {{"cosine", s.cosine},
                     {"sine", s.sine},
                     {"amplitude", s.amplitude},
                     {"phase", s.phase},
                     {"relative_amplitude", relative}};
  return json;
}

/// Where k, F and the STE are taken (docs/theory/mesh_stiffness.md, "Which plane"): along the
/// transverse line of action, F = T₁/r_b1 and δ = r_b1 θ₁ + r_b2 θ₂. The normal-plane values
/// follow from the tooth force's inclination β_b to the transverse plane: F_n = F / cos β_b,
/// δ_n = δ cos β_b (the approach along the contact normal), k_n = F_n / δ_n = k / cos² β_b.
nlohmann::ordered_json planeJson(const GearPair& pair, const nlohmann::ordered_json& results) {
  const double cb = std::cos(pair.baseHelixAngle());
  nlohmann::ordered_json normal;
  normal["stiffness_mean"] = results["mesh_stiffness"]["mean"].get<double>() / (cb * cb);
  normal["stiffness_min"] = results["mesh_stiffness"]["min"].get<double>() / (cb * cb);
  normal["stiffness_max"] = results["mesh_stiffness"]["max"].get<double>() / (cb * cb);
  if (results.contains("static_transmission_error")) {
    const auto& ste = results["static_transmission_error"];
    normal["force"] = ste["force"].get<double>() / cb;
    normal["ste_mean"] = ste["mean"].get<double>() * cb;
    normal["ste_peak_to_peak"] = ste["peak_to_peak"].get<double>() * cb;
  }
  return {{"plane", "transverse"},
          {"line_of_action",
           "k [N/m], F [N] and the STE [m] act along the transverse line of action: F = T1/r_b1, "
           "STE = r_b1 theta1 + r_b2 theta2 (the transverse approach of the flanks)"},
          {"base_helix_angle_deg", pair.baseHelixAngle() / kDegree},
          {"normal", normal}};
}

}  // namespace

nlohmann::ordered_json stiffnessResultsJson(const config::Config& config, const GearPair& pair,
                                            const config::MeshStiffnessModels& models) {
  const int order = static_cast<int>(config.integer("mesh_stiffness.fourier_order"));
  nlohmann::ordered_json results;
  nlohmann::ordered_json all = nlohmann::ordered_json::object();
  for (const auto& model : models.models) {
    nlohmann::ordered_json json = summaryJson(*model, order);
    if (const auto* step = dynamic_cast<const StepMeshStiffness*>(model.get())) {
      json["k_min"] = step->kMin();
      json["k_max"] = step->kMax();
    }
    if (const auto* pe = dynamic_cast<const PotentialEnergyMeshStiffness*>(model.get())) {
      json["hertz_stiffness"] = pe->hertzPerWidth() * pair.effectiveFaceWidth();
      json["contact_start"] = pe->contactStart();
      json["contact_end"] = pe->contactEnd();
    }
    if (model->model() == "api") {
      const double gamma =
          apiMeshDirection(pair.spec().pinion.normal_pressure_angle,
                           config.string("mesh_stiffness.api.loading") == "down" ? ApiLoading::kDown
                                                                                 : ApiLoading::kUp,
                           config.string("mesh_stiffness.api.rotation") == "clockwise"
                               ? ApiRotation::kClockwise
                               : ApiRotation::kCounterClockwise);
      const Eigen::Matrix2d k = apiDirectionalStiffness(model->stiffness(0.0), gamma);
      json["gamma_deg"] = gamma / kDegree;
      json["directional_matrix"] = {{k(0, 0), k(0, 1)}, {k(1, 0), k(1, 1)}};
    }
    if (model->model() == "iso6336") {
      const Iso6336Stiffness s = iso6336Stiffness(pair, config::iso6336OptionsFromConfig(config));
      json["iso"] = {{"zn1", s.zn1},
                     {"zn2", s.zn2},
                     {"q_prime", s.q_prime},
                     {"c_prime_th", s.c_prime_th},
                     {"c_m", s.c_m},
                     {"c_r", s.c_r},
                     {"c_b", s.c_b},
                     {"material_factor", s.material_factor},
                     {"c_prime", s.c_prime},
                     {"c_gamma_alpha", s.c_gamma_alpha},
                     {"c_gamma_beta", s.c_gamma_beta},
                     {"units", "N/(mm um)"}};
    }
    all[model->model()] = json;
  }
  results["mesh_stiffness"] = all[models.models.front()->model()];
  results["models"] = all;

  const config::TransmissionErrorSpec te = config::transmissionErrorFromConfig(config);
  if (te.force > 0.0) {
    const MeshStiffness& k = *models.models.front();
    const std::vector<double> breaks = k.discontinuities();
    const auto delta = [&](double phase) { return te.at(k, phase); };
    const double mean = integrateOverPeriod(delta, breaks);
    double lo = delta(0.0), hi = lo;
    const int n = static_cast<int>(config.integer("mesh_stiffness.positions"));
    for (int i = 0; i < n; ++i) {
      const double v = delta(static_cast<double>(i) / n);
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    for (double b : breaks) {
      for (double phase : {b, b - 1e-12}) {
        lo = std::min(lo, delta(phase));
        hi = std::max(hi, delta(phase));
      }
    }
    std::vector<double> amplitude;
    for (int i = 1; i <= std::min(order, 10); ++i) {
      const double w = 2.0 * std::numbers::pi * i;
      const double a =
          2.0 * integrateOverPeriod([&](double p) { return delta(p) * std::cos(w * p); }, breaks);
      const double b =
          2.0 * integrateOverPeriod([&](double p) { return delta(p) * std::sin(w * p); }, breaks);
      amplitude.push_back(std::hypot(a, b));
    }
    results["static_transmission_error"] = {{"model", k.model()},
                                            {"force", te.force},
                                            {"mean", mean},
                                            {"min", lo},
                                            {"max", hi},
                                            {"peak_to_peak", hi - lo},
                                            {"harmonic_amplitudes", amplitude}};
  }
  results["plane"] = planeJson(pair, results);
  return results;
}

io::CsvTable stiffnessCurveTable(const config::Config& config, const GearPair& pair,
                                 const config::MeshStiffnessModels& models) {
  const MeshStiffness& primary = *models.models.front();
  const auto f_m = pair.meshFrequency();
  const config::TransmissionErrorSpec te = config::transmissionErrorFromConfig(config);
  std::vector<std::string> columns = {"roll_angle_rad", "mesh_fraction"};
  if (f_m && *f_m > 0.0) columns.push_back("t_s");
  // k, F and the STE along the transverse line of action (planeJson): the names say so.
  columns.push_back("k_total_transverse_n_per_m");
  for (int j = 0; j < primary.pairCount(); ++j)
    columns.push_back(fmt::format("k_pair_{}_transverse_n_per_m", j + 1));
  for (std::size_t m = 1; m < models.models.size(); ++m) {
    columns.push_back("k_" + models.models[m]->model() + "_transverse_n_per_m");
  }
  if (te.force > 0.0) columns.push_back("ste_transverse_m");
  io::CsvTable table(columns);
  const int n = static_cast<int>(config.integer("mesh_stiffness.positions"));
  const int z1 = pair.spec().pinion.teeth;
  for (int i = 0; i < n; ++i) {
    const double phase = static_cast<double>(i) / n;
    std::vector<io::CsvCell> row = {rollAngleFromMeshPhase(phase, z1), phase};
    if (f_m && *f_m > 0.0) row.emplace_back(phase / *f_m);
    row.emplace_back(primary.stiffness(phase));
    for (int j = 0; j < primary.pairCount(); ++j) row.emplace_back(primary.pairStiffness(phase, j));
    for (std::size_t m = 1; m < models.models.size(); ++m)
      row.emplace_back(models.models[m]->stiffness(phase));
    if (te.force > 0.0) row.emplace_back(te.at(primary, phase));
    table.addRow(std::move(row));
  }
  return table;
}

io::CsvTable fourierTable(const nlohmann::ordered_json& results_models) {
  io::CsvTable table({"model", "order", "cosine_n_per_m", "sine_n_per_m", "amplitude_n_per_m",
                      "phase_rad", "relative_amplitude"});
  for (const auto& [name, json] : results_models.items()) {
    const double mean = json["mean"].get<double>();
    table.addRow({name, 0LL, mean, 0.0, mean, 0.0, 1.0});
    const auto& f = json["fourier"];
    for (std::size_t i = 0; i < f["cosine"].size(); ++i) {
      table.addRow({name, static_cast<long long>(i + 1), f["cosine"][i].get<double>(),
                    f["sine"][i].get<double>(), f["amplitude"][i].get<double>(),
                    f["phase"][i].get<double>(), f["relative_amplitude"][i].get<double>()});
    }
  }
  return table;
}

}  // namespace geardyn::analysis
