#pragma once
/// \file
/// Contact elements read in another plane: every element's stiffness times one factor and its
/// gap times another. A helical pair's tooth-pair elements given along the transverse line of
/// action (k_t, g_t) act along the contact normal as k_t / cos² β_b with gaps g_t cos β_b, and
/// back (docs/theory/mesh_stiffness.md, "Which plane").

#include <cmath>
#include <memory>

#include "geardyn/models/mesh_contact_elements.h"

namespace geardyn {

class ScaledContactElements final : public MeshContactElements {
 public:
  /// `elements` not null; the factors > 0 (asserted by scaledContactElements).
  ScaledContactElements(std::shared_ptr<const MeshContactElements> elements,
                        double stiffness_factor, double gap_factor)
      : elements_(std::move(elements)),
        stiffness_factor_(stiffness_factor),
        gap_factor_(gap_factor) {}

  int count() const override { return elements_->count(); }
  void element(double phase, int j, double& stiffness, double& gap) const override {
    elements_->element(phase, j, stiffness, gap);
    stiffness *= stiffness_factor_;
    gap *= gap_factor_;
  }

  const std::shared_ptr<const MeshContactElements>& unscaled() const noexcept { return elements_; }
  double stiffnessFactor() const noexcept { return stiffness_factor_; }
  double gapFactor() const noexcept { return gap_factor_; }

 private:
  std::shared_ptr<const MeshContactElements> elements_;
  double stiffness_factor_, gap_factor_;
};

/// `elements` with stiffnesses × `stiffness_factor` and gaps × `gap_factor`; scaled elements
/// are rescaled (one wrapper, the factors multiplied); factors of exactly 1 return `elements`.
inline std::shared_ptr<const MeshContactElements> scaledContactElements(
    const std::shared_ptr<const MeshContactElements>& elements, double stiffness_factor,
    double gap_factor) {
  if (stiffness_factor == 1.0 && gap_factor == 1.0) return elements;
  if (const auto* s = dynamic_cast<const ScaledContactElements*>(elements.get())) {
    return std::make_shared<ScaledContactElements>(
        s->unscaled(), s->stiffnessFactor() * stiffness_factor, s->gapFactor() * gap_factor);
  }
  return std::make_shared<ScaledContactElements>(elements, stiffness_factor, gap_factor);
}

}  // namespace geardyn
