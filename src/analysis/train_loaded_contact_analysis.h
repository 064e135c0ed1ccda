#pragma once
/// \file
/// `train` analyses of the gearbox's own deflection at its meshes (issue 36): the mesh
/// misalignment table of `static`, and `contact`: the system deflection coupled with the loaded
/// tooth contact across the face of every mesh (solvers/train_loaded_contact.h).

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "geardyn/analysis/analysis_result.h"
#include "geardyn/config/config.h"
#include "geardyn/io/result_writer.h"
#include "geardyn/solvers/train_loaded_contact.h"
#include "geardyn/system/mesh_misalignment.h"

namespace geardyn::analysis::detail {

/// mesh_misalignment.csv and the report's lines; returns the summary's per-mesh object.
nlohmann::ordered_json writeMeshMisalignment(const std::vector<MeshMisalignment>& meshes,
                                             AnalysisResult& result, std::string& text);

/// <name>.csv (the line load per mesh phase and face position, long form) and <name>_mean.csv
/// (its cycle mean) of a load distribution across the face.
void addFaceLoadTables(const FaceLoadDistribution& face, const std::string& name,
                       AnalysisResult& result);

/// The options of [contact] (InputError naming the key).
TrainLoadedContactOptions loadedContactOptions(const config::Config& analysis);

/// The loaded contact model of every external mesh, with the modifications of its
/// [meshes.<name>.modifications] when the gearbox file gives them.
std::vector<std::shared_ptr<const LoadedToothContact>> gearboxMeshContacts(
    const GearTrainModel& model, const config::Config& gearbox, int slices);

/// `contact`: the coupled fixed point, its tables (mesh_contact.csv, face_load_<mesh>.csv,
/// face_load_<mesh>_mean.csv, ste_harmonics.csv) and summary; returns the result.
TrainLoadedContactResult runTrainContact(const GearTrainModel& model,
                                         const config::Config& analysis,
                                         const config::Config& gearbox, AnalysisResult& result,
                                         io::RunSummary& summary, std::string& text);

/// The train with every mesh of excitation = "ltca" taking its loaded contact at the coupled
/// fixed point: the tangent stiffness k_t(φ) / cos² β_b and the error
/// e(φ) = cos β_b (δ(φ) − F / k_t(φ)) along the contact normal, tabulated at the contact's
/// positions (solvers/train_loaded_contact.h); nullopt when no mesh asks for it.
std::optional<GearTrainModel> withLoadedContactExcitation(const GearTrainModel& model,
                                                          const config::Config& analysis,
                                                          const config::Config& gearbox,
                                                          io::RunSummary& summary,
                                                          std::string& text);

}  // namespace geardyn::analysis::detail
