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

#include "geardyn/config/config.h"
#include "geardyn/config/config_schema.h"
#include "geardyn/geometry/gear_pair.h"
#include "geardyn/io/csv_table.h"
#include "geardyn/models/transmission_error.h"
#include "geardyn/stiffness/iso6336_stiffness.h"
#include "geardyn/stiffness/mesh_stiffness.h"
#include "geardyn/stiffness/potential_energy_stiffness.h"

namespace geardyn::config {

/// The model names `[mesh_stiffness] models` accepts.
const std::vector<std::string>& meshStiffnessModelNames();

/// Adds [mesh_stiffness] and its model subsections ([mesh_stiffness.api], .step, .fourier,
/// .potential_energy, .iso6336) to a schema.
void addMeshStiffnessSections(ConfigSchema& schema);

/// Adds only the per-model subsections ([mesh_stiffness.api], .step, .fourier,
/// .potential_energy, .iso6336); the caller declares [mesh_stiffness] itself.
void addMeshStiffnessModelSections(ConfigSchema& schema);

/// The schema of `geardyn stiffness`: gear pair, mesh stiffness, output.
ConfigSchema stiffnessSchema();

PotentialEnergyOptions potentialEnergyOptionsFromConfig(const Config& config);
Iso6336Options iso6336OptionsFromConfig(const Config& config);

/// The models a configuration asks for, in its order (the first is the primary one), built for
/// a pair. Models derived from others (step levels, Fourier fit) build their source once.
struct MeshStiffnessModels {
  std::vector<std::shared_ptr<const MeshStiffness>> models;
  std::vector<std::string> warnings;
};
MeshStiffnessModels buildMeshStiffnessModels(const Config& config, const GearPair& pair);

/// One model by name, configured by the [mesh_stiffness.<name>] subsections; appends the
/// model's warnings.
std::shared_ptr<const MeshStiffness> buildMeshStiffnessModel(const std::string& name,
                                                             const Config& config,
                                                             const GearPair& pair,
                                                             std::vector<std::string>& warnings);

/// The loaded static transmission error along the line of action at phase φ,
/// δ(φ) = F / k(φ) + e(φ), with the geometric error / profile-modification term e a Fourier
/// series in mesh orders, e = Σ e_i cos(2π i φ + φ_i), and/or a table over one period [m].
struct TransmissionErrorSpec {
  double force = 0.0;       ///< transmitted force along the line of action F [N]
  TransmissionError error;  ///< e(φ) [m]
  double at(const MeshStiffness& k, double phase) const {
    return force / k.stiffness(phase) + error.value(phase);
  }
};
TransmissionErrorSpec transmissionErrorFromConfig(const Config& config);

}  // namespace geardyn::config
