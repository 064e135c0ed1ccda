/// The derived truncation as torus options (train_torus_truncation.h).

#include "geardyn/torus/train_torus_truncation.h"

#include <algorithm>

namespace geardyn {

TrainTorusOptions torusOptionsFromEstimate(const MeshHarmonicsEstimate& estimate,
                                           TrainTorusOptions options, TorusTruncation truncation) {
  options.mesh_harmonics = estimate.harmonics;
  options.per_mesh_harmonics = estimate.per_mesh;
  options.group_harmonics = std::max(options.group_harmonics, estimate.harmonics);
  options.truncation = truncation;
  options.mesh_order_weights.clear();
  if (truncation == TorusTruncation::kProduct) options.mesh_order_weights = estimate.envelope;
  return options;
}

}  // namespace geardyn
