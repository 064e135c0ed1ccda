#pragma once
/// \file
/// The number of harmonics of each mesh frequency a frequency-domain steady state of a train
/// needs, derived from the problem (docs/theory/torus_harmonic_balance.md, "The default
/// truncation"): per mesh, the smallest L whose neglected mesh-force orders stay below a stated
/// fraction of the largest order at every speed, the orders estimated by the mesh's own
/// one-generator balance with the train's dynamic compliance at the mesh.

#include <vector>

#include "geardyn/system/gear_train_model.h"

namespace geardyn {

struct MeshHarmonicsOptions {
  /// Neglected orders below this fraction of the largest (per mesh and speed) [-]: the floor
  /// of the lines the balance is checked against Newmark with (issue 32: every line above 1e-3
  /// of the largest within 1e-3 of it), so every such line is a kept order or a product of
  /// kept ones. On the hunting-tooth reducer the estimate gives the highest order above the
  /// fraction within 0–2 orders of the balance's own (train_truncation_test.cpp).
  double fraction = 1e-3;
  /// E: orders of the estimate, and the largest L returned (a larger L would make the torus
  /// of two generators (2E + 1)² tones: past E the balance is better chosen by hand) [-].
  int max_harmonics = 48;
  int min_harmonics = 1;  ///< the smallest [-]
  void validate() const;
};

struct MeshHarmonicsEstimate {
  int harmonics = 1;                   ///< L = the largest of per_mesh [-]
  std::vector<int> per_mesh;           ///< L_m: the smallest L meeting the fraction [-]
  std::vector<int> worst_speed_index;  ///< the speed (index in `speeds`) that set L_m
  /// Per mesh: the estimated force orders at that speed, l = 1..E, relative to the largest [-].
  std::vector<std::vector<double>> relative_orders;
  bool capped = false;  ///< some mesh needs more than max_harmonics
  /// Per speed (index in `speeds`) and mesh: the smallest L meeting the fraction at that speed
  /// alone, in [min_harmonics, max_harmonics] (the per-speed truncation of the forced sweep).
  std::vector<std::vector<int>> per_speed;
  /// Per mesh: the envelope over the speeds of the estimated force orders relative to each
  /// speed's largest, l = 1..E [-] (the weights of the torus's product truncation).
  std::vector<std::vector<double>> envelope;
};

/// For every mesh m and input speed Ω [rad/s]: the mesh alone, its deflection harmonics
/// δ_l (l = 1..E, δ₀ = δ̄ the static mean under the mean meshes) from its one-generator balance
///   δ_l + B_mm(lω) Σ_{l'≠l} k̂_{l−l'} δ_{l'} = B_mm(lω) ((k e)^_l + i lω c ê_l),
/// ω = 2π f_m(Ω), B_mm(ω) = v_mᵀ D(ω)⁻¹ v_m the train's dynamic compliance at the mesh (mean
/// meshes in K̄; undamped modes at the operating speed with their modal damping φᵢᵀCφᵢ), then
/// its force orders F_l = (k (δ − e))^_l: the stiffness harmonics weighted by the response's
/// dynamic amplification, the products k̂ δ included. L_m is the smallest L with
/// |F_l| <= fraction × max |F| for every l > L at every Ω (capped at E: `capped`).
MeshHarmonicsEstimate estimateMeshHarmonics(const GearTrainModel& model,
                                            const std::vector<double>& speeds,
                                            const MeshHarmonicsOptions& options = {});

}  // namespace geardyn
