#pragma once
/// \file
/// The derived truncation (train_truncation.h) as options of the torus balance (train_torus.h):
/// the one step from the estimate to L, L_m, the group threshold and the product index set,
/// shared by `train` [forced], the bench and the tests (docs/theory/torus_harmonic_balance.md,
/// "The default truncation" and "The index set").

#include "geardyn/solvers/train_truncation.h"
#include "geardyn/torus/train_torus.h"

namespace geardyn {

/// `options` with the estimate's truncation: L = the largest L_m, L_m per mesh, the group
/// threshold (forced.torus_above) raised to L when below it (a mesh alone needs L harmonics of
/// its own frequency), and with `truncation` = kProduct the product index set weighted by the
/// estimate's envelope over the sweep (kBox and kDiamond keep their index set, unweighted).
TrainTorusOptions torusOptionsFromEstimate(const MeshHarmonicsEstimate& estimate,
                                           TrainTorusOptions options,
                                           TorusTruncation truncation = TorusTruncation::kProduct);

}  // namespace geardyn
