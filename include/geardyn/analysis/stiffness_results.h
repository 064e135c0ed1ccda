#pragma once
/// \file
/// Configuration and results of `geardyn stiffness`: the [mesh_stiffness] section and its
/// per-model subsections, building the requested models for a gear pair, and their JSON / CSV
/// forms (summary statistics, Fourier coefficients, curves over one mesh period, loaded static
/// transmission error).

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "geardyn/config/config_schema.h"
#include "geardyn/config/stiffness_config.h"
#include "geardyn/geometry/gear_pair.h"
#include "geardyn/io/csv_table.h"
#include "geardyn/models/transmission_error.h"
#include "geardyn/stiffness/iso6336_stiffness.h"
#include "geardyn/stiffness/mesh_stiffness.h"
#include "geardyn/stiffness/potential_energy_stiffness.h"

namespace geardyn::analysis {

/// results.mesh_stiffness (the primary model) and results.models (every model): mean, min, max,
/// std, contact ratio, Fourier coefficients; plus the API directional matrix, the ISO factors
/// and the static transmission error where they apply; results.plane: the plane of k, F and the
/// STE (transverse) and their normal-plane values k / cos² β_b, F / cos β_b, STE cos β_b.
nlohmann::ordered_json stiffnessResultsJson(const config::Config& config, const GearPair& pair,
                                            const config::MeshStiffnessModels& models);

/// mesh_stiffness.csv: roll_angle_rad, mesh_fraction, [t_s,] k_total_transverse_n_per_m
/// (primary), k_pair_1..n_transverse_n_per_m (primary), k_<model>_transverse_n_per_m for the
/// others, [ste_transverse_m]: every k and the STE along the transverse line of action.
io::CsvTable stiffnessCurveTable(const config::Config& config, const GearPair& pair,
                                 const config::MeshStiffnessModels& models);

/// fourier.csv from results.models (stiffnessResultsJson): model, order, cosine, sine,
/// amplitude, phase_rad, relative_amplitude; order 0 holds the mean.
io::CsvTable fourierTable(const nlohmann::ordered_json& results_models);

}  // namespace geardyn::analysis
