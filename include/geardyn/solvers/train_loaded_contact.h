#pragma once
/// \file
/// The gearbox's own deflection and the loaded tooth contact of its meshes, coupled (issue 36).
///
/// At the static load case the train deflects (solveTrainStatic); the relative tilt of the two
/// gears of every external mesh is a mesh misalignment f_ma (system/mesh_misalignment.h), which
/// enters that mesh's loaded tooth contact as a separation across the face
/// (contact/profile_modification.h) and moves its load: the centre of load z_c leaves the
/// mid-face. The mesh force of the train acts at the mid-face, so the moved load is the mesh
/// force plus the couple F z_c (x̂ × n) on gear a and its opposite on gear b (n the contact
/// normal); the train is solved again under those couples, and so on to a fixed point:
///     z_c^{k+1} = LTCA(f_ma(q(z_c^k))),   q(z_c) = q₀ + K⁺ ΔF(z_c),
/// stopped when no mesh's z_c moves by more than `tolerance` × its face width
/// (docs/theory/gear_whine.md). K is the train's mean stiffness (with rolling bearings: the
/// tangent at q₀, so a step from q₀ is Newton's first step).
///
/// At the fixed point each mesh's loaded static transmission error δ(φ) and tangent stiffness
/// k_t(φ) over a mesh cycle give its whine excitation: the train mesh with k_t(φ) and the
/// error e(φ) = δ(φ) − F / k_t(φ) reproduces δ(φ) at the static load and is linear about it.

#include <complex>
#include <memory>
#include <vector>

#include "geardyn/contact/face_load.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/system/mesh_misalignment.h"

namespace geardyn {

struct TrainLoadedContactOptions {
  int slices = 40;          ///< face slices per tooth pair
  int positions = 64;       ///< mesh positions over one mesh period
  int harmonics = 8;        ///< STE harmonics kept
  double tolerance = 1e-4;  ///< on every |Δz_c| / b [-]
  int max_iterations = 50;
  void validate() const;
};

struct TrainMeshLoadedContact {
  int mesh = 0;                                     ///< index in model.meshes()
  MeshMisalignment misalignment;                    ///< at the fixed point
  FaceLoadDistribution face;                        ///< the loaded contact at the fixed point
  double force_transverse = 0.0;                    ///< F_n cos β_b [N]
  double ste_mean = 0.0;                            ///< transverse [m]
  double ste_peak_to_peak = 0.0;                    ///< transverse [m]
  double mean_tangent_stiffness = 0.0;              ///< transverse [N/m]
  std::vector<std::complex<double>> ste_harmonics;  ///< c_n, n = 1.. (steHarmonics) [m]
};

struct TrainLoadedContactResult {
  TrainStaticResult statics;                   ///< at the fixed point
  std::vector<TrainMeshLoadedContact> meshes;  ///< the external meshes analysed
  std::vector<double> change;                  ///< max |Δz_c|/b per iteration [-]
  int iterations = 0;
  bool converged = false;
};

/// The loaded contact model of every external mesh of `model` (null for the others): a
/// potential-energy pair of its two gears at its centre distance, `slices` face slices, and
/// `modifications` (one per mesh, or empty: unmodified).
std::vector<std::shared_ptr<const LoadedToothContact>> trainMeshContacts(
    const GearTrainModel& model, int slices,
    const std::vector<PairModifications>& modifications = {});

/// The fixed point of system deflection and load distribution (above) at the model's
/// operating point.
TrainLoadedContactResult solveTrainLoadedContact(
    const GearTrainModel& model,
    const std::vector<std::shared_ptr<const LoadedToothContact>>& contacts,
    const TrainLoadedContactOptions& options = {});

/// The spec of `model` with every mesh i with `meshes[i]` excited by its loaded contact in `r`
/// (above): the table k_t(φ) / cos² β_b and e(φ) = cos β_b (δ(φ) − F / k_t(φ)) along the contact
/// normal at the contact's positions, in place of its stiffness model and transmission error.
GearTrainSpec loadedContactExcitation(const GearTrainModel& model,
                                      const TrainLoadedContactResult& r,
                                      const std::vector<bool>& meshes);

}  // namespace geardyn
