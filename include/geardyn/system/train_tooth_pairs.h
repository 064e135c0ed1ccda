#pragma once
/// \file
/// The tooth-pair contact elements of a train mesh (TrainMeshContact::tooth_pairs) tabulated at
/// the mesh phases a solver samples, so that the solvers' inner loops read arrays: no virtual
/// calls and no allocation per iteration. The mesh force on the tooth deformation y = δ − e is
///     f(y) = Σ_j k_j(φ) max(0, y − g_j(φ))
/// (Saletti et al. 2025 in the general form of models/mesh_contact_elements.h), piecewise
/// linear in y with slope Σ_{j: y > g_j} k_j (docs/theory/nonlinear_gear_trains.md).

#include <vector>

#include "geardyn/models/mesh_contact_elements.h"

namespace geardyn {

/// The measure of {λ ∈ [0, 1]: d0 + λ (d1 − d0) > 0}: the fraction of a straight segment on
/// which an element whose margin y − g goes linearly from d0 to d1 [m] is in contact [-].
double positiveFraction(double d0, double d1);

class ToothPairTable {
 public:
  /// Tabulates the elements at `count` mesh phases [mesh periods]. Allocates only when the
  /// element count or the sample count grow (refilling at as many phases does not).
  void tabulate(const MeshContactElements& elements, const double* phases, int count);

  int elementCount() const noexcept { return elements_; }
  int sampleCount() const noexcept { return samples_; }
  /// k_j [N/m] and g_j [m] of element j at sample i.
  double stiffness(int i, int j) const { return k_[i * elements_ + j]; }
  double gap(int i, int j) const { return g_[i * elements_ + j]; }

  /// f(y) at sample i [N] and df/dy [N/m] in *slope.
  double force(int i, double y, double* slope) const {
    const double* k = &k_[i * elements_];
    const double* g = &g_[i * elements_];
    double f = 0.0, s = 0.0;
    for (int j = 0; j < elements_; ++j) {
      if (y > g[j]) {
        f += k[j] * (y - g[j]);
        s += k[j];
      }
    }
    if (slope) *slope = s;
    return f;
  }
  /// The linearised force: every element of positive stiffness in contact, Σ_{k_j > 0} k_j
  /// (y − g_j) [N] (the linear start of the harmonic balance, as the 1-DOF model's).
  double linearForce(int i, double y, double* slope) const;
  /// The slope over the straight segment from (sample i0, y0) to (sample i1, y1):
  /// Σ_j ½ (k_j(i0) + k_j(i1)) × the fraction of the segment with y > g_j (g_j linear between
  /// the samples) [N/m] — the monodromy's slope per sample interval, second order in a contact
  /// change inside it.
  double meanSlope(int i0, double y0, int i1, double y1) const;

 private:
  int elements_ = 0, samples_ = 0;
  std::vector<double> k_, g_;  // [sample × elements + element]
};

}  // namespace geardyn
