#pragma once
/// \file
/// A REXS file as a gearbox description: io/rexs maps the REXS model onto the gearbox keys, and
/// this supplies what the mapping cannot know by itself, the gearbox kinematics (a torque given on
/// another shaft than the input is carried to the input by the speed ratio of the described
/// gearbox), and validates the result as a gearbox file.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "geardyn/config/config.h"
#include "geardyn/io/rexs/rexs_gearbox.h"

namespace geardyn::config {

/// io::rexs::importRexsGearbox with the gearbox kinematics supplied (options.speed_ratio, when
/// empty, from the gearbox model of the mapped description).
io::rexs::RexsImport importRexsGearbox(const io::rexs::Document& document,
                                       io::rexs::RexsImportOptions options = {});

/// Reads a .rexs/.rexsj/.rexsz file and imports it (importRexsGearbox).
io::rexs::RexsImport importRexsFile(const std::filesystem::path& file,
                                    io::rexs::RexsImportOptions options = {});

/// A gearbox file as a validated configuration: TOML read directly, a REXS file imported in
/// memory first (its load case from `load_case`; the import's warnings appended). `overrides`
/// are --set strings applied to the gearbox keys.
Config loadGearboxConfig(const std::filesystem::path& file,
                         const std::vector<std::string>& overrides, std::optional<int> load_case,
                         std::vector<std::string>& warnings);

}  // namespace geardyn::config
