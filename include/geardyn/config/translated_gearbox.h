#pragma once
/// \file
/// `geardyn <command> FILE --print-gearbox` (issue #31): the gearbox description a command's
/// older file form is translated into, for every command that has a translation.

#include <optional>
#include <string>

#include "geardyn/config/config.h"

namespace geardyn::config {

/// The gearbox TOML text `command`'s configuration translates into (config::gearboxSchema()
/// reads it, `geardyn train` analyses it); nullopt when `command` has no translation. A command
/// with one throws InputError naming the key when this file's form has none yet.
std::optional<std::string> translatedGearbox(const std::string& command, const Config& config);

}  // namespace geardyn::config
