#pragma once
/// \file
/// The configuration's spelling suggestions: geardyn/did_you_mean.h under config:: names.

#include "geardyn/did_you_mean.h"

namespace geardyn::config {

using geardyn::closestMatch;
using geardyn::editDistance;

}  // namespace geardyn::config
