#pragma once
/// \file
/// Loaded tooth contact analysis (LTCA) of a gear pair: at each mesh position, every tooth pair
/// in its contact window (each face slice of it, for helical gears or crowning) is a linear
/// spring — the potential-energy pair compliance (bending, shear, axial, foundation, Hertz;
/// stiffness/potential_energy_stiffness.h) — with an initial separation from the flank
/// modifications and errors (contact/profile_modification.h). The load sharing is the
/// complementarity problem
///     p_i = k_i max(0, δ − g_i),   Σ p_i = F,
/// whose solution (the approach δ, the loaded static transmission error along the line of
/// action) is found exactly by sorting the separations (the load is a piecewise-linear,
/// increasing function of δ). Outputs: δ(φ, F), the load per pair, the secant stiffness F/δ and
/// the tangent stiffness dF/dδ = Σ of the loaded slices' k_i.

#include <complex>
#include <memory>
#include <vector>

#include "geardyn/contact/profile_modification.h"
#include "geardyn/models/mesh_contact_elements.h"
#include "geardyn/progress.h"
#include "geardyn/stiffness/potential_energy_stiffness.h"

namespace geardyn {

struct LoadedContactPoint {
  double phase = 0.0;       ///< mesh phase φ
  double ste = 0.0;         ///< loaded static transmission error δ along the line of action [m]
  double no_load_te = 0.0;  ///< δ at F → 0: the smallest separation in contact [m]
  double secant = 0.0;      ///< F / δ [N/m] (0 at F = 0)
  double tangent = 0.0;     ///< dF/dδ [N/m]
  std::vector<double> pair_loads;  ///< load per pair slot j (pairCount()) [N]
  /// Load per face slice i (slices(), at z_i = (i + ½) b / slices − b/2), summed over the
  /// pairs [N]: the load distribution across the face.
  std::vector<double> face_loads;
  int loaded_slices = 0;
};

class LoadedToothContact {
 public:
  /// `stiffness` supplies the kinematics and the pair compliance per unit width; `slices` face
  /// slices per pair (≥ 1; spur without crowning needs 1).
  LoadedToothContact(std::shared_ptr<const PotentialEnergyMeshStiffness> stiffness,
                     PairModifications modifications, int slices);

  int pairCount() const { return stiffness_->pairCount(); }
  const PotentialEnergyMeshStiffness& stiffness() const { return *stiffness_; }
  const std::shared_ptr<const PotentialEnergyMeshStiffness>& sharedStiffness() const {
    return stiffness_;
  }
  const PairModifications& modifications() const { return modifications_; }

  /// The contact at mesh phase φ (in mesh period `period`, which picks the teeth for pitch
  /// errors) under the transmitted force F >= 0 [N] along the line of action.
  LoadedContactPoint solve(double phase, double force, int period = 0) const;

  int slices() const { return slices_; }
  /// Stiffness [N/m] (0 when out of contact) and separation [m] of slice `slice` of pair slot
  /// `pair` at mesh phase φ (in mesh period `period`).
  void slice(double phase, int pair, int slice, double& stiffness, double& separation,
             int period = 0) const;

  /// `positions` evenly spaced phases of mesh periods first..first+periods−1; `progress` is
  /// called once per period with the positions done.
  std::vector<LoadedContactPoint> sweep(double force, int positions, int periods = 1,
                                        const ProgressCallback& progress = {}) const;

 private:
  struct Slice {
    double k, g;
    int pair, face;
  };
  void gather(double phase, int period, std::vector<Slice>& out) const;

  std::shared_ptr<const PotentialEnergyMeshStiffness> stiffness_;
  PairModifications modifications_;
  int slices_;
};

/// The slices of a loaded tooth contact as the contact elements of a dynamic mesh model
/// (models/mesh_contact_elements.h): element e = pair (e / slices), slice (e % slices), with
/// the slice's stiffness and its separation as the gap — tooth entry and exit follow the flank
/// modifications instead of a step gap.
class LoadedContactElements final : public MeshContactElements {
 public:
  explicit LoadedContactElements(std::shared_ptr<const LoadedToothContact> contact)
      : contact_(std::move(contact)) {}
  int count() const override { return contact_->pairCount() * contact_->slices(); }
  void element(double phase, int j, double& stiffness, double& gap) const override {
    contact_->slice(phase, j / contact_->slices(), j % contact_->slices(), stiffness, gap);
  }

 private:
  std::shared_ptr<const LoadedToothContact> contact_;
};

/// Complex mesh harmonics c_n (n = 1..harmonics) of the loaded STE over one period sampled at
/// evenly spaced phases: δ(φ) ≈ mean + Σ Re(c_n e^{j2πnφ}) [m].
std::vector<std::complex<double>> steHarmonics(const std::vector<LoadedContactPoint>& period,
                                               int harmonics);

/// One load of a Harris map: the loaded STE over the sampled positions.
struct HarrisPoint {
  double force = 0.0;             ///< [N]
  double peak_to_peak = 0.0;      ///< of δ [m]
  double mean = 0.0;              ///< of δ [m]
  std::vector<double> harmonics;  ///< amplitudes of the first mesh harmonics of δ [m]
};

/// Peak-to-peak (and the first `harmonics` mesh harmonics) of the loaded STE over `positions`
/// phases of one mesh period, for each force (`progress`: forces done of all).
std::vector<HarrisPoint> harrisMap(const LoadedToothContact& contact,
                                   const std::vector<double>& forces, int positions,
                                   int harmonics = 3, const ProgressCallback& progress = {});

}  // namespace geardyn
