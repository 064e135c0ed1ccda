#pragma once
/// \file
/// Configuration and results of `geardyn simulate`: the [model] (type "gear_pair"), its
/// [model.stiffness] and [model.transmission_error], [excitation] and [solver] sections; the
/// GearPairModel and TimeResponseOptions they describe; and the results of a time response.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "geardyn/config/config.h"
#include "geardyn/config/config_schema.h"
#include "geardyn/io/csv_table.h"
#include "geardyn/solvers/time_response.h"
#include "geardyn/system/gear_pair_model.h"

namespace geardyn::config {

/// Adds [model], [model.stiffness], [model.transmission_error] and [excitation].
void addGearPairModelSections(ConfigSchema& schema);
/// Adds [solver] (time integration).
void addTimeSolverSection(ConfigSchema& schema);

/// Everything a gear-pair dynamics command reads: the model sections, [solver], the optional
/// gear pair ([pinion], [gear], [pair]), the mesh-stiffness model options and [output].
void addGearPairDynamicsSections(ConfigSchema& schema);

/// The schema of `geardyn simulate`.
ConfigSchema simulateSchema();

/// The model a configuration describes, with the quantities derived on the way.
struct GearPairModelBuild {
  GearPairModelSpec spec;
  double mean_stiffness = 0.0;     ///< k̄ over a mesh period [N/m] (1 when nondimensional)
  double damping_ratio = 0.0;      ///< ζ = c / (2 √(k̄ m))
  double natural_frequency = 0.0;  ///< ω_n = √(k̄/m) [rad/s] (1 when nondimensional)
  bool nondimensional = false;
  std::vector<std::string> warnings;
};
/// `require_speed` false: [excitation] may be left out (harmonic balance sweeps the frequency).
/// The file is read once (config/gear_pair_keys.h) and translated into its gearbox
/// (config/gear_pair_gearbox.h); the model is the gearbox's one-pair train reduced
/// (system/sdof_reduction.h), with the file's extra harmonic forces added. k̄, ζ,
/// ω_n and the warnings about the time step are derived from that model.
GearPairModelBuild buildGearPairModel(const Config& config, bool require_speed = true);

TimeResponseOptions timeResponseOptionsFromConfig(const Config& config);

}  // namespace geardyn::config
