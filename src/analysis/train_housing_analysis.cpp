/// `train` with a flexible housing (train_housing_analysis.h).

#include "train_housing_analysis.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "geardyn/analysis/run_budget.h"
#include "geardyn/config/gearbox_housing.h"
#include "geardyn/config/train_analysis.h"
#include "geardyn/system/train_housing.h"
#include "geardyn/units.h"

namespace geardyn::analysis::detail {
namespace {

using geardyn::units::kRpm;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
/// Reference acceleration of the levels [m/s²] (ISO 1683: 1e-6 m/s²).
constexpr double kReferenceAcceleration = 1e-6;

}  // namespace

double highestAnalysedFrequencyHz(const GearTrainModel& rigid, const config::Config& analysis,
                                  const std::vector<std::string>& analyses) {
  double ratio = 0.0;  // the highest mesh frequency per unit input speed [Hz per rad/s]
  for (const TrainMesh& m : rigid.meshes()) ratio = std::max(ratio, m.frequency_ratio);
  const double operating = std::abs(rigid.inputSpeed());
  auto has = [&](const char* a) {
    return std::find(analyses.begin(), analyses.end(), a) != analyses.end();
  };
  auto orders = [&](const std::string& key) {
    return std::min<double>(kHousingResponseOrders,
                            analysis.has(key) ? static_cast<double>(analysis.integer(key)) : 1.0);
  };
  auto top = [&](const std::string& section) {
    return analysis.has(section + ".speed_max_rpm")
               ? analysis.real(section + ".speed_max_rpm") * kRpm
               : 1.5 * operating;
  };
  double f = 0.0;
  if (has("modal"))
    f = std::max(f, ratio * std::abs(config::analysisSpeed(analysis, "modal", operating)));
  if (has("campbell")) f = std::max(f, ratio * top("campbell") * orders("campbell.mesh_harmonics"));
  if (has("forced")) f = std::max(f, ratio * top("forced") * orders("forced.mesh_harmonics"));
  if (has("runup")) f = std::max(f, ratio * top("runup") * orders("runup.mesh_harmonics"));
  if (has("nonlinear")) f = std::max(f, ratio * top("nonlinear") * orders("nonlinear.harmonics"));
  if (has("time") || has("stats")) {
    const double speed = std::abs(config::analysisSpeed(analysis, "time", operating));
    f = std::max(f, ratio * speed * orders("time.mesh_harmonics"));
  }
  return f;
}

std::string attachTrainHousing(const config::Config& gearbox, const config::Config& analysis,
                               const std::vector<std::string>& analyses, GearTrainSpec& spec) {
  if (!config::hasHousing(gearbox)) return "";
  double f = 0.0;
  if (!gearbox.has("housing.cutoff_hz") && !gearbox.has("housing.modes")) {
    f = highestAnalysedFrequencyHz(GearTrainModel(spec, memoryLimitBytes()), analysis, analyses);
  }
  return config::attachHousing(gearbox, spec, 2.0 * f, memoryLimitBytes());
}

HousingResponseTable::HousingResponseTable(const GearTrainModel& model)
    : model_(model),
      active_(model.housingFirstDof() >= 0 && !model.spec().housing->reduced.points.empty()),
      table_({"speed_rpm", "mesh", "order", "frequency_hz", "point", "acceleration_x_m_per_s2",
              "acceleration_y_m_per_s2", "acceleration_z_m_per_s2", "acceleration_m_per_s2",
              "level_db"}) {
  if (active_) peaks_.resize(model.spec().housing->reduced.points.size());
}

void HousingResponseTable::add(const TrainSteadyState& s) {
  if (!active_) return;
  const ReducedHousing& h = model_.spec().housing->reduced;
  const double speed_rpm = s.input_speed / kRpm;
  for (std::size_t m = 0; m < model_.meshes().size(); ++m) {
    const double f_m = model_.meshes()[m].frequency_ratio * std::abs(s.input_speed);
    for (int l = 1; l <= kHousingResponseOrders; ++l) {
      const int k = l * s.mesh_multiple[m];
      if (k > s.harmonics) break;
      const double w = kTwoPi * l * f_m;
      // q(t) = Re[X_0 + 2 Σ X_k e^{ikω₀t}]: the amplitude of harmonic k is 2 X_k; a = −ω² u.
      const Eigen::VectorXcd u = 2.0 * s.housing_points.col(k);
      for (std::size_t p = 0; p < h.points.size(); ++p) {
        const Eigen::Vector3d a = w * w * u.segment(3 * static_cast<Eigen::Index>(p), 3).cwiseAbs();
        const double total = a.norm();
        const double level = 20.0 * std::log10(std::max(total, 1e-30) / kReferenceAcceleration);
        table_.addRow({speed_rpm, model_.meshes()[m].name, l, l * f_m, h.points[p], a.x(), a.y(),
                       a.z(), total, level});
        Peak& peak = peaks_[p];
        if (level > peak.level_db) {
          peak = {level, speed_rpm, l * f_m, model_.meshes()[m].name, l};
        }
      }
    }
  }
}

void HousingResponseTable::write(AnalysisResult& result, io::RunSummary& summary,
                                 std::string& text) const {
  if (!active_) return;
  result.addTable("housing_response.csv", table_);
  nlohmann::ordered_json points = nlohmann::ordered_json::object();
  const auto& names = model_.spec().housing->reduced.points;
  for (std::size_t p = 0; p < names.size(); ++p) {
    const Peak& peak = peaks_[p];
    points[names[p]] = {{"max_level_db", peak.level_db},
                        {"max_acceleration_m_per_s2",
                         kReferenceAcceleration * std::pow(10.0, peak.level_db / 20.0)},
                        {"at_speed_rpm", peak.speed_rpm},
                        {"mesh", peak.mesh},
                        {"order", peak.order},
                        {"frequency_hz", peak.frequency_hz}};
    text += fmt::format(
        "  housing point {}: max {:.1f} dB re 1e-6 m/s^2 ({} order {}, {:.0f} Hz, at {:.0f} rpm)\n",
        names[p], peak.level_db, peak.mesh, peak.order, peak.frequency_hz, peak.speed_rpm);
  }
  summary.results["forced"]["housing"] = {{"reference_m_per_s2", kReferenceAcceleration},
                                          {"orders", kHousingResponseOrders},
                                          {"points", points}};
}

}  // namespace geardyn::analysis::detail
