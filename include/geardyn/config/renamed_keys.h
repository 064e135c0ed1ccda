#pragma once
/// \file
/// Renamed keys whose value changes with the name (issue #31): the old key had another unit or
/// meaning, so the loader converts its value when it reads it as the new key (a radian phase
/// read as degrees, the gear pair's half clearance read as the full one). A schema declares the
/// rename itself with ConfigSchema::alias; this table, one for all commands, says how the value
/// converts. docs/config/renamed-keys.md lists them.

#include <string_view>

namespace geardyn::config {

/// How the value of a renamed key converts: new = scale × old.
struct ValueConversion {
  double scale = 1.0;
  std::string_view text;  ///< for the warning, e.g. "× 180/π: the old key was in radians"
};

/// The conversion of the rename old_path → new_path, or nullptr when the value is unchanged.
const ValueConversion* renameConversion(std::string_view old_path, std::string_view new_path);

}  // namespace geardyn::config
