#include "geardyn/analysis/simulate_results.h"

#include <fmt/format.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "geardyn/config/geometry_config.h"
#include "geardyn/config/ltca_config.h"
#include "geardyn/config/simulate_config.h"
#include "geardyn/config/stiffness_config.h"
#include "geardyn/contact/loaded_contact.h"
#include "geardyn/error.h"
#include "geardyn/geometry/gear_pair.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "geardyn/stiffness/mesh_stiffness_summary.h"
#include "geardyn/stiffness/potential_energy_stiffness.h"
#include "geardyn/stiffness/step_stiffness.h"
#include "geardyn/stiffness/tabulated_stiffness.h"

namespace geardyn::analysis {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

using Json = nlohmann::ordered_json;

Json statistics(const std::vector<double>& values, int samples_per_period, int harmonics) {
  const std::size_t n = values.size();
  double mean = 0.0, square = 0.0, lo = values.front(), hi = values.front();
  for (double v : values) {
    mean += v;
    square += v * v;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  mean /= n;
  const double rms = std::sqrt(square / n);
  double variance = 0.0;
  for (double v : values) variance += (v - mean) * (v - mean);
  // Amplitude of mesh order r over whole periods: (2/N) |Σ v_j exp(−2πi r j / M)|.
  std::vector<double> amplitudes;
  for (int r = 1; r <= harmonics; ++r) {
    std::complex<double> sum = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
      sum += values[j] * std::polar(1.0, -kTwoPi * r * static_cast<double>(j) / samples_per_period);
    }
    amplitudes.push_back(2.0 * std::abs(sum) / n);
  }
  return Json{{"mean", mean},
              {"rms", rms},
              {"std", std::sqrt(variance / n)},
              {"min", lo},
              {"max", hi},
              {"peak_to_peak", hi - lo},
              {"harmonic_amplitudes", amplitudes}};
}

}  // namespace

TimeResponseChannels channelsOf(const GearPairModel& model, const TimeResponse& response) {
  TimeResponseChannels c;
  c.t = response.t;
  c.x = response.x;
  c.v = response.v;
  for (std::size_t j = 0; j < response.t.size(); ++j) {
    const double t = response.t[j];
    c.y.push_back(response.x[j] - model.error(t));
    c.force.push_back(model.meshForce(t, response.x[j]));
    c.k.push_back(model.stiffness(t));
  }
  return c;
}

nlohmann::ordered_json timeResponseResultsJson(const config::GearPairModelBuild& build,
                                               const GearPairModel& model,
                                               const TimeResponse& response,
                                               const TimeResponseChannels& channels,
                                               int harmonics) {
  Json results;
  results["status"] = toString(response.status);
  results["steady_state"] = response.converged();
  results["message"] = response.message;
  results["periods"] = response.periods;
  results["last_change"] = response.last_change;
  results["steps"] = response.steps;
  results["max_newton_iterations"] = response.max_newton_iterations;
  results["newton_failures"] = response.newton_failures;
  const double omega_m = kTwoPi * model.meshFrequency();
  results["model"] = {{"units", build.nondimensional ? "nondimensional" : "SI"},
                      {"mass", model.mass()},
                      {"damping", model.damping()},
                      {"damping_ratio", build.damping_ratio},
                      {"mean_stiffness", build.mean_stiffness},
                      {"natural_frequency", build.natural_frequency},
                      {"mesh_frequency", model.meshFrequency()},
                      {"frequency_ratio", omega_m / build.natural_frequency},
                      {"mean_force", model.meanForce()},
                      {"stiffness_model", model.meshStiffness().model()}};
  if (channels.t.empty()) return results;
  const int m = static_cast<int>(std::lround(response.period / (channels.t[1] - channels.t[0])));
  results["relative_deflection"] = statistics(channels.y, m, harmonics);
  results["mesh_force"] = statistics(channels.force, m, harmonics);
  double peak = 0.0;
  int lost = 0;
  for (std::size_t j = 0; j < channels.t.size(); ++j) {
    peak = std::max(peak, std::abs(channels.force[j]));
    double slope = 0.0;
    model.contactLaw(channels.y[j], &slope);
    lost += slope == 0.0;
  }
  results["dynamic_factor"] =
      model.meanForce() != 0.0 ? Json(peak / std::abs(model.meanForce())) : Json(nullptr);
  results["contact_loss_fraction"] = static_cast<double>(lost) / channels.t.size();
  return results;
}

io::CsvTable timeResponseTable(const TimeResponseChannels& c, bool nondimensional) {
  // Along the transverse line of action (docs/theory/mesh_stiffness.md, "Which plane"); the
  // unit ends each name, or "nondim" for Gelman's nondimensional form.
  const auto unit = [&](const char* si) { return std::string(nondimensional ? "nondim" : si); };
  io::CsvTable table({"t_" + unit("s"), "x_transverse_" + unit("m"),
                      "v_transverse_" + unit("m_per_s"), "y_transverse_" + unit("m"),
                      "mesh_force_transverse_" + unit("n"), "k_transverse_" + unit("n_per_m")});
  for (std::size_t j = 0; j < c.t.size(); ++j)
    table.addRow({c.t[j], c.x[j], c.v[j], c.y[j], c.force[j], c.k[j]});
  return table;
}

}  // namespace geardyn::analysis
