#pragma once
/// \file
/// Reading REXS files: XML (.rexs, pugixml), JSON (.rexsj, nlohmann-json) and zipped (.rexsz: a
/// zip archive holding one .rexs or .rexsj model, read with Debian's minizip). A file that is
/// not well formed (truncated, not XML/JSON, no <model>) is an InputError naming the file and,
/// where the parser knows it, the offset.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "geardyn/io/rexs/rexs_document.h"

namespace geardyn::io::rexs {

/// True for the REXS file name extensions .rexs, .rexsj and .rexsz (case-insensitive).
bool isRexsPath(const std::filesystem::path& file);

Document parseRexsXml(std::string_view text, const std::string& source);
Document parseRexsJson(std::string_view text, const std::string& source);
/// Largest uncompressed REXS model read from a .rexsz [bytes]: 256 MiB, some fifty times the
/// largest published gearbox models; a zip bomb is refused when it passes this, whatever its
/// entry declares.
inline constexpr std::uint64_t kMaxRexsModelBytes = std::uint64_t{256} << 20;
/// The model inside a .rexsz archive (the first .rexs or .rexsj entry).
Document readRexsZip(const std::filesystem::path& file);

/// Reads any REXS file by its extension, applies the alias table (normalize) and checks the
/// relations' references. Renames and vendor attributes are appended to `warnings`.
Document readRexsFile(const std::filesystem::path& file, std::vector<std::string>& warnings);

}  // namespace geardyn::io::rexs
