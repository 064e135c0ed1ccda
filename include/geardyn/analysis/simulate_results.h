#pragma once
/// \file
/// Configuration and results of `geardyn simulate`: the [model] (type "gear_pair"), its
/// [model.stiffness] and [model.transmission_error], [excitation] and [solver] sections; the
/// GearPairModel and TimeResponseOptions they describe; and the results of a time response.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "geardyn/config/config_schema.h"
#include "geardyn/config/simulate_config.h"
#include "geardyn/io/csv_table.h"
#include "geardyn/solvers/time_response.h"
#include "geardyn/system/gear_pair_model.h"

namespace geardyn::analysis {

/// The time response with derived channels: y = x − e, mesh force k g(y), k.
struct TimeResponseChannels {
  std::vector<double> t, x, v, y, force, k;
};
TimeResponseChannels channelsOf(const GearPairModel& model, const TimeResponse& response);

/// results: status, periods, the statistics of y and the mesh force, harmonic amplitudes by
/// mesh order, contact-loss fraction, dynamic factor.
nlohmann::ordered_json timeResponseResultsJson(const config::GearPairModelBuild& build,
                                               const GearPairModel& model,
                                               const TimeResponse& response,
                                               const TimeResponseChannels& channels, int harmonics);

/// time_response.csv: t_s, x_transverse_m, v_transverse_m_per_s, y_transverse_m,
/// mesh_force_transverse_n, k_transverse_n_per_m (nondimensional: each unit is "nondim").
io::CsvTable timeResponseTable(const TimeResponseChannels& channels, bool nondimensional = false);

}  // namespace geardyn::analysis
