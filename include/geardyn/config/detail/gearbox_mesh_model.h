#pragma once
/// \file
/// The keys of a gearbox mesh's model — stiffness model, damping, transmission error, tooth
/// contact — shared by the fixed-axis meshes ("meshes.*") and a planetary stage's sun and ring
/// meshes ("planetary.*.sun_planet", "planetary.*.ring_planet"), and their readers.

#include <memory>
#include <string>
#include <vector>

#include "geardyn/config/config.h"
#include "geardyn/config/config_schema.h"
#include "geardyn/geometry/gear_pair.h"
#include "geardyn/geometry/internal_gear_pair.h"
#include "geardyn/stiffness/mesh_stiffness.h"
#include "geardyn/system/gear_train.h"

namespace geardyn::config::detail {

/// Mesh stiffness, damping and transmission error keys under `prefix` (ending in "."); `what`
/// names the meshes in the documentation.
void addMeshModelKeys(ConfigSchema& schema, const std::string& prefix, const std::string& what);

/// The tooth-pair keys of an external mesh under `prefix` (ending in "."): the face slices per
/// pair and the flank modifications (`prefix`modifications.*, the keys of the hbm and ltca
/// commands' [modifications]) of contact = "tooth_pairs".
void addToothPairKeys(ConfigSchema& schema, const std::string& prefix);

/// The tooth contact of a mesh from its keys (see addMeshModelKeys). contact = "tooth_pairs"
/// builds the elements of the loaded tooth contact of `pair` with the mesh's modifications
/// (addToothPairKeys); `pair` is null for ring (internal) meshes, which refuse it (InputError
/// naming `prefix`contact).
TrainMeshContact contactFromConfig(const Config& config, const std::string& prefix,
                                   const GearPair* pair);

/// The transmission error of a mesh (te_amplitudes [m], te_phases_deg).
TransmissionError teFromConfig(const Config& config, const std::string& prefix);

/// What a mesh's stiffness models are computed from: an external pair (every model), or an
/// internal one with its two members (constant, api, iso6336, table), and the paths of the
/// members and the mesh for messages.
struct MeshStiffnessInputs {
  const GearPair* external = nullptr;
  const InternalGearPair* internal = nullptr;
  const GearSpec* pinion = nullptr;  ///< the internal pair's external member (a planet)
  const GearSpec* ring = nullptr;    ///< the internal pair's ring
  double face_width = 0.0;           ///< [m]
  double helix = 0.0;                ///< β of the first member [rad]
  double contact_ratio = 0.0;        ///< total ε [-]
  PairKeyNames keys;
};

/// The stiffness model a mesh asks for (`prefix`stiffness). Absent, it is potential_energy on
/// an external mesh and iso6336 on a ring mesh (the tooth models are written for external
/// teeth). An input error of a model names the mesh's gears' keys ("gears.z19.bore_diameter",
/// not "pinion.bore_diameter"); the models' notes go to `warnings`.
std::shared_ptr<const MeshStiffness> stiffnessFromConfig(const Config& config,
                                                         const std::string& prefix,
                                                         const MeshStiffnessInputs& inputs,
                                                         std::vector<std::string>& warnings);

/// meshes.*.stiffness_plane = "transverse": the mesh's stiffness model, dashpot, transmission
/// error and backlash were given along the transverse line of action (the gear-pair commands'
/// reading); the mesh acts along the contact normal, inclined by the base helix angle β_b:
/// k_n = k_t / cos² β_b, c_n = c_t / cos² β_b, e_n = e_t cos β_b, j_n = j_t cos β_b (the same
/// work F_n δ_n = F_t δ_t; docs/theory/mesh_stiffness.md, "Which plane"), and so do the
/// tooth-pair contact elements' stiffnesses and gaps. Spur meshes are unchanged.
void transverseToNormal(TrainMeshSpec& mesh, double base_helix, const std::string& prefix);

}  // namespace geardyn::config::detail
