#pragma once
/// \file
/// The Fourier (sinusoidal) mesh stiffness, Visnadi & de Castro 2021 eq. 8 (corrected: the OCR
/// lost the brackets and wrote j for i; ω_m is the mesh frequency in rad/s, 2π/T_m):
///   k(t) = k₀ + Σ_{i=1..n} s_i k₀ cos(i ω_m t − φ_i),   i.e. in mesh phase
///   k(φ) = k₀ [1 + Σ s_i cos(2π i φ − φ_i)].

#include <vector>

#include "geardyn/stiffness/mesh_stiffness.h"

namespace geardyn {

class FourierMeshStiffness final : public MeshStiffness {
 public:
  /// \param mean k₀ [N/m] > 0; \param relative_amplitudes s_i [-] >= 0;
  /// \param phases φ_i [rad] (same length); \param contact_ratio ε [-] (for reference).
  /// Throws InputError if k would become <= 0 somewhere (Σ s_i >= 1).
  FourierMeshStiffness(double mean, std::vector<double> relative_amplitudes,
                       std::vector<double> phases, double contact_ratio);

  /// The first `order` harmonics of another model, with its mean or, if `mean` > 0, that mean
  /// (relative amplitudes kept: Visnadi's "sinusoid with the API mean").
  static FourierMeshStiffness fit(const MeshStiffness& source, int order, double mean = 0.0);

  std::string model() const override { return "fourier"; }
  double stiffness(double phase) const override;
  double contactRatio() const override { return contact_ratio_; }

  double mean() const noexcept { return mean_; }
  const std::vector<double>& relativeAmplitudes() const noexcept { return s_; }
  const std::vector<double>& phases() const noexcept { return phases_; }

 private:
  double mean_;
  std::vector<double> s_, phases_;
  double contact_ratio_;
};

}  // namespace geardyn
