#pragma once
/// \file
/// The keys of a gearbox bearing given by its geometry (`[bearings.<name>] type = ...`,
/// issue 35) and their reader.

#include <memory>
#include <string>

#include "geardyn/config/config.h"
#include "geardyn/config/config_schema.h"
#include "geardyn/contact/rolling_bearing.h"

namespace geardyn::config::detail {

/// type, arrangement and the geometry keys under `prefix` ("bearings.*.").
void addRollingBearingKeys(ConfigSchema& schema, const std::string& prefix);

/// The bearing a `type` other than "stiffness" describes (null for "stiffness"); InputError
/// naming the key for a missing or impossible geometry value. `radial_clearance` [m] is the
/// bearing's radial play from the centred position (s_r/2; < 0: preload).
std::shared_ptr<const RollingBearing> rollingBearingFromConfig(const Config& config,
                                                               const std::string& prefix,
                                                               double radial_clearance);

/// `model` = "nonlinear" (true) or "linearised"; InputError naming the key for "nonlinear"
/// without a bearing from its geometry (`rolling` false).
bool fullBearingLawFromConfig(const Config& config, const std::string& prefix, bool rolling);

}  // namespace geardyn::config::detail
