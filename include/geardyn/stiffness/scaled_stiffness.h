#pragma once
/// \file
/// A mesh-stiffness model times a constant factor: the same model read in another plane. A
/// helical pair's stiffness given in the transverse plane k_t acts along the contact normal as
/// k_n = k_t / cos² β_b, and a normal-plane k_n reduces to the transverse line of action as
/// k_t = k_n cos² β_b (docs/theory/mesh_stiffness.md, "Which plane").

#include <memory>
#include <string>
#include <vector>

#include "geardyn/stiffness/mesh_stiffness.h"

namespace geardyn {

class ScaledMeshStiffness final : public MeshStiffness {
 public:
  /// `factor` > 0 and finite (InputError naming "stiffness" otherwise); `model` not null.
  ScaledMeshStiffness(std::shared_ptr<const MeshStiffness> model, double factor);

  /// The underlying model's name: the plane changes the values, not the model.
  std::string model() const override { return model_->model(); }
  double stiffness(double phase) const override { return factor_ * model_->stiffness(phase); }
  std::vector<double> discontinuities() const override { return model_->discontinuities(); }
  int pairCount() const override { return model_->pairCount(); }
  double pairStiffness(double phase, int pair) const override {
    return factor_ * model_->pairStiffness(phase, pair);
  }
  double contactRatio() const override { return model_->contactRatio(); }

  double factor() const noexcept { return factor_; }
  const MeshStiffness& unscaled() const noexcept { return *model_; }

 private:
  std::shared_ptr<const MeshStiffness> model_;
  double factor_;
};

/// `model` times `factor`; a ScaledMeshStiffness is rescaled (one wrapper, the factors
/// multiplied), and a factor of exactly 1 returns `model` itself.
std::shared_ptr<const MeshStiffness> scaledMeshStiffness(
    const std::shared_ptr<const MeshStiffness>& model, double factor);

}  // namespace geardyn
