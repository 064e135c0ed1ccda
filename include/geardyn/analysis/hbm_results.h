#pragma once
/// \file
/// Configuration and results of `geardyn hbm`: the [hbm] and [sweep] sections, the forced
/// response sweep table and the one-period details at requested frequencies.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "geardyn/config/config_schema.h"
#include "geardyn/config/hbm_config.h"
#include "geardyn/config/simulate_config.h"
#include "geardyn/io/csv_table.h"
#include "geardyn/solvers/harmonic_balance.h"

namespace geardyn::analysis {

/// One row of sweep.csv: a continuation point with its response measures (of the relative
/// deflection y = x − e).
struct SweepRow {
  std::string sweep;       ///< "up" or "down"
  double frequency = 0.0;  ///< [Hz] (nondimensional: Ω)
  int branch = 0;
  double p2p = 0, mean = 0, max = 0, min = 0, rms = 0, contact_loss = 0;
  bool stable = true;
  int newton_iterations = 0;
  std::vector<double> harmonics;  ///< |y_h|, h = 0..H
};
SweepRow sweepRow(HarmonicBalance& hbm, const GearPairModel& model, const SweepPoint& point,
                  const std::string& sweep, double frequency_scale);

io::CsvTable sweepTable(const std::vector<SweepRow>& rows, int harmonics,
                        bool nondimensional = false);

}  // namespace geardyn::analysis
