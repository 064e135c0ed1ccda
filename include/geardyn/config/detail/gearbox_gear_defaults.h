#pragma once
/// \file
/// What a gearbox gear takes when its file leaves a key out and the value follows from the rest
/// of the gearbox (issue #33: defaults that work).

#include <vector>

#include "geardyn/system/gear_train.h"

namespace geardyn::config::detail {

/// The bore of a gear whose file gives none: the outer diameter of its shaft's section under
/// its mid-face when that is below the root diameter d_f (a gear mounted on the shaft, whose
/// body mass then does not double the shaft's), else 0 (no section there, or a pinion cut
/// into its shaft) [m].
double defaultBoreDiameter(const TrainGearSpec& gear, const std::vector<TrainShaftSpec>& shafts);

}  // namespace geardyn::config::detail
