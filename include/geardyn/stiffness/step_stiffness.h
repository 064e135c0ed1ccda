#pragma once
/// \file
/// The step (rectangular) mesh stiffness (Visnadi & de Castro 2021, eq. 7; Gelman et al. 2005,
/// Case 2): for a contact ratio ε with n = ⌊ε⌋, n + 1 pairs carry the load during the first
/// (ε − n) of each mesh period, with stiffness k_max, and n pairs the rest, with k_min.

#include "geardyn/stiffness/mesh_stiffness.h"

namespace geardyn {

class StepMeshStiffness final : public MeshStiffness {
 public:
  /// \param k_min stiffness with n pairs in contact [N/m] > 0
  /// \param k_max stiffness with n + 1 pairs in contact [N/m] >= k_min
  /// \param contact_ratio ε >= 1 [-] (any value, also above 2)
  StepMeshStiffness(double k_min, double k_max, double contact_ratio);

  /// Levels for a given mean with stiffness proportional to the number of pairs:
  /// k_pair = mean / ε, k_min = n k_pair, k_max = (n + 1) k_pair (Gelman's normalised step).
  static StepMeshStiffness fromMean(double mean, double contact_ratio);
  /// Levels from another model, preserving its mean: k_max is its mean over the n + 1-pair part
  /// of the period, k_min its mean over the rest.
  static StepMeshStiffness fromModel(const MeshStiffness& source);

  std::string model() const override { return "step"; }
  double stiffness(double phase) const override;
  std::vector<double> discontinuities() const override;
  double contactRatio() const override { return contact_ratio_; }

  double kMin() const noexcept { return k_min_; }
  double kMax() const noexcept { return k_max_; }
  /// Fraction of the period with n + 1 pairs: ε − n [-].
  double multiContactFraction() const noexcept { return fraction_; }

 private:
  double k_min_, k_max_, contact_ratio_, fraction_;
};

}  // namespace geardyn
