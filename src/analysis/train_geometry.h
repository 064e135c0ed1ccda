#pragma once
/// \file
/// The `geometry` block of `geardyn train`'s summary.json (train_geometry.cpp): where every
/// part of the train is and how big it is, for drawing it (the report's 3-D view,
/// python/geardyn/view3d.py). Positions in the train's global frame: x along the shafts, (y, z)
/// across, gravity along −z [m].

#include <nlohmann/json.hpp>

#include "geardyn/system/gear_train_model.h"

namespace geardyn::analysis::detail {

/// shafts (sections, their bodies in axial order), gears (body, radii, face width, helix
/// angle and hand), planets, carriers, bearings, couplings and disks of `model`, each naming the
/// body (bodies.csv, mode_shapes.csv) it moves with.
nlohmann::ordered_json trainGeometry(const GearTrainModel& model);

}  // namespace geardyn::analysis::detail
