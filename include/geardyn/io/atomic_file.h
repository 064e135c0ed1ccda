#pragma once
/// \file
/// Atomic file output: a result file is either absent, or complete and whole.

#include <filesystem>
#include <string_view>

namespace geardyn::io {

/// Writes `content` to `path` atomically: to a temporary file in the same folder, flushed to
/// disk (fsync) when `durable`, then renamed over `path`. Creates missing parent folders. An
/// interrupted run leaves at most a stray temporary file (named `.<name>.tmp-<pid>-<n>`), never a
/// half-written result; without `durable` a power failure soon after may still lose the content.
/// Throws IoError naming the path and the system's reason.
void writeFileAtomic(const std::filesystem::path& path, std::string_view content,
                     bool durable = true);

/// Flushes a file, or a folder's entries (renames), to disk (fsync); IoError on failure.
void syncToDisk(const std::filesystem::path& path);

/// For writers that need a file of their own (HDF5): a temporary path beside `path`, named as
/// above; write it, then commitTemporary.
std::filesystem::path temporaryPathFor(const std::filesystem::path& path);
/// Renames `temporary` over `path`; on failure removes it and throws IoError.
void commitTemporary(const std::filesystem::path& temporary, const std::filesystem::path& path);

}  // namespace geardyn::io
