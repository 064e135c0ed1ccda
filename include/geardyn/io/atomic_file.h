#pragma once
/// \file
/// Atomic file output: a result file is either absent, or complete and whole.

#include <filesystem>
#include <string_view>

namespace geardyn::io {

/// Writes `content` to `path` atomically: to a temporary file in the same folder, flushed to
/// disk (fsync), then renamed over `path`. Creates missing parent folders. An interrupted run
/// leaves at most a stray temporary file (named `.<name>.tmp-<pid>-<n>`), never a half-written
/// result. Throws IoError naming the path and the system's reason.
void writeFileAtomic(const std::filesystem::path& path, std::string_view content);

}  // namespace geardyn::io
