#pragma once
/// \file
/// Unit conversions at the library's edges: everything inside is SI (rad, rad/s); keys and
/// results in degrees and rpm convert with these factors.

#include <numbers>

namespace geardyn::units {

inline constexpr double kDegree = std::numbers::pi / 180.0;  ///< rad per degree
inline constexpr double kRpm = std::numbers::pi / 30.0;      ///< rad/s per rpm

}  // namespace geardyn::units
