/// A mesh-stiffness model times a constant factor (stiffness/scaled_stiffness.h).

#include "geardyn/stiffness/scaled_stiffness.h"

#include <fmt/format.h>

#include <cmath>

#include "geardyn/error.h"

namespace geardyn {

ScaledMeshStiffness::ScaledMeshStiffness(std::shared_ptr<const MeshStiffness> model, double factor)
    : model_(std::move(model)), factor_(factor) {
  if (!model_) throw InputError("stiffness", "(none)", "a mesh-stiffness model to scale");
  if (!(factor_ > 0.0) || !std::isfinite(factor_)) {
    throw InputError("stiffness", fmt::format("factor {:g}", factor_), "a finite factor > 0");
  }
}

std::shared_ptr<const MeshStiffness> scaledMeshStiffness(
    const std::shared_ptr<const MeshStiffness>& model, double factor) {
  if (factor == 1.0) return model;
  if (const auto* scaled = dynamic_cast<const ScaledMeshStiffness*>(model.get())) {
    // Share the underlying model: the wrapper holds it by shared_ptr through `model`.
    return std::make_shared<ScaledMeshStiffness>(
        std::shared_ptr<const MeshStiffness>(model, &scaled->unscaled()),
        scaled->factor() * factor);
  }
  return std::make_shared<ScaledMeshStiffness>(model, factor);
}

}  // namespace geardyn
