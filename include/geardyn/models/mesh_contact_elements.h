#pragma once
/// \file
/// Tooth-pair contact elements of a gear mesh (Saletti et al. 2025, in the general form): the
/// mesh force on the deflection y = x − e(t) is
///     F = Σ_j k_j(φ) max(0, y − g_j(φ)),
/// each element a one-sided spring with its own stiffness and gap (initial separation) at mesh
/// phase φ — e.g. the tooth pairs (and face slices) of a loaded tooth contact analysis with
/// their flank modifications, which make contact gradually instead of through a step gap.

namespace geardyn {

class MeshContactElements {
 public:
  virtual ~MeshContactElements() = default;
  /// Number of elements.
  virtual int count() const = 0;
  /// Stiffness [N/m] (0 out of contact) and gap [m] of element j at mesh phase φ.
  virtual void element(double phase, int j, double& stiffness, double& gap) const = 0;
};

}  // namespace geardyn
