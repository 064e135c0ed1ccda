#pragma once
/// \file
/// Mesh misalignment from a static deflection of the train (issue 36): the relative tilt and
/// displacement of the two gears of every mesh, projected into the plane of action — the mesh
/// misalignment f_ma of ISO 6336-1 (§7.5: the mismatch of the flanks across the face width,
/// measured in the plane of action along the transverse base tangent) — and out of it, and the
/// change of the centre distance (docs/theory/gear_whine.md).
///
/// With six DOFs per body a gear's centre at its mid-face moves by u = (u_y, u_z) + θ × (Δx x̂)
/// and its axis turns so that the centre line's slope across the face is du/dx = (θ_z, −θ_y)
/// (Δx from the body's reference point to the mid-face). For mesh m with the transverse line of
/// action n_t (TrainMesh::normal, a pushing b) and its in-plane perpendicular p = x̂ × n_t:
///     f_ma     = b n_tᵀ (s_a − s_b),   f_out = b pᵀ (s_a − s_b),   s = du/dx,
///     δ_n      = n_tᵀ (u_a − u_b)  (the mesh approach at mid-face),
///     Δa       = e_abᵀ (u_b − u_a)  (e_ab: unit vector from a's centre to b's),
/// with b the overlap of the two faces. f_ma > 0: the flanks approach more (the load grows)
/// towards +x; the separation across the face is g(z) = −f_ma z / b, z from the mid-face.

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "geardyn/system/gear_train_model.h"

namespace geardyn {

struct MeshMisalignment {
  std::string mesh;
  double face_width = 0.0;  ///< b: overlap of the two faces [m]
  double mid_face = 0.0;    ///< global x of the overlap's middle [m]
  double contact_x = 0.0;   ///< global x of the model's mesh contact point (between mid-faces) [m]
  double mismatch = 0.0;    ///< f_ma: in the plane of action across b [m]
  double mismatch_out_of_plane = 0.0;   ///< f_out: normal to the plane of action across b [m]
  double tilt_in_plane = 0.0;           ///< n_tᵀ(s_a − s_b) [rad]
  double tilt_out_of_plane = 0.0;       ///< pᵀ(s_a − s_b) [rad]
  double approach = 0.0;                ///< δ_n: relative displacement along n_t at mid-face [m]
  double centre_distance_change = 0.0;  ///< Δa > 0: the centres move apart [m]
};

/// The misalignment of every mesh of `model` (in model.meshes() order) at the state q (all the
/// model's DOFs, e.g. TrainStaticResult::displacement). Tilts are 0 unless the DOFs are full;
/// empty with torsional DOFs (no translations).
std::vector<MeshMisalignment> meshMisalignment(const GearTrainModel& model,
                                               const Eigen::Ref<const Eigen::VectorXd>& q);

}  // namespace geardyn
