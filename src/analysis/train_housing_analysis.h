#pragma once
/// \file
/// `train` with a flexible housing (issue #37): the housing's default cut-off from the analyses
/// asked for, and the forced response's acceleration at the housing's response points.

#include <string>
#include <vector>

#include "geardyn/analysis/analysis_result.h"
#include "geardyn/config/config.h"
#include "geardyn/io/csv_table.h"
#include "geardyn/io/result_writer.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn::analysis::detail {

/// Mesh orders whose housing response is reported (and that the default cut-off covers).
inline constexpr int kHousingResponseOrders = 3;

/// The highest frequency [Hz] `analyses` ask for on the train `rigid` (the housing not yet
/// attached): the modal speed's highest mesh frequency; Campbell's and the forced, time and
/// run-up analyses' highest speed × the highest mesh frequency per unit speed ×
/// min(their mesh harmonics, kHousingResponseOrders). 0 for statics alone.
double highestAnalysedFrequencyHz(const GearTrainModel& rigid, const config::Config& analysis,
                                  const std::vector<std::string>& analyses);

/// Attaches the gearbox's [housing] (if any) to `spec`, its cut-off defaulting to 2 ×
/// highestAnalysedFrequencyHz (Guyan for statics alone). The report line, "" without a housing.
std::string attachTrainHousing(const config::Config& gearbox, const config::Config& analysis,
                               const std::vector<std::string>& analyses, GearTrainSpec& spec);

/// The housing's response points in the forced response: per speed, mesh and order l ≤
/// kHousingResponseOrders, the acceleration amplitude |(lω_m)² R q_l| of each point's
/// translation (R: ReducedHousing::recovery) [m/s²], its magnitude over x, y, z, and the level
/// 20 log10(a / 1e-6 m/s²) [dB].
class HousingResponseTable {
 public:
  explicit HousingResponseTable(const GearTrainModel& model);
  bool active() const noexcept { return active_; }
  /// Adds one speed's common-period steady state.
  void add(const TrainSteadyState& state);
  /// housing_response.csv, summary.results.forced.housing (per point: the largest level and its
  /// speed, mesh and order) and report lines.
  void write(AnalysisResult& result, io::RunSummary& summary, std::string& text) const;

 private:
  const GearTrainModel& model_;
  bool active_ = false;
  io::CsvTable table_;
  struct Peak {
    double level_db = -1e300, speed_rpm = 0.0, frequency_hz = 0.0;
    std::string mesh;
    int order = 0;
  };
  std::vector<Peak> peaks_;
};

}  // namespace geardyn::analysis::detail
