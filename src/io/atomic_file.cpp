#include "geardyn/io/atomic_file.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>

#include "geardyn/error.h"

namespace geardyn::io {
namespace {

std::atomic<unsigned long> temporary_counter{0};

[[noreturn]] void fail(const std::filesystem::path& path, const char* what, int error) {
  throw IoError(fmt::format("cannot {} {}: {}", what, path.string(), std::strerror(error)));
}

}  // namespace

void writeFileAtomic(const std::filesystem::path& path, std::string_view content, bool durable) {
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : ".";
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec) fail(folder, "create folder", ec.value());

  const std::filesystem::path temporary = temporaryPathFor(path);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail(temporary, "create", errno);

  const char* data = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int error = errno;
      ::close(fd);
      ::unlink(temporary.c_str());
      fail(temporary, "write", error);
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  if ((durable && ::fsync(fd) != 0) || ::close(fd) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    fail(temporary, "flush", error);
  }
  commitTemporary(temporary, path);
}

void syncToDisk(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) fail(path, "open", errno);
  if (::fsync(fd) != 0) {
    const int error = errno;
    ::close(fd);
    fail(path, "flush", error);
  }
  ::close(fd);
}

std::filesystem::path temporaryPathFor(const std::filesystem::path& path) {
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : ".";
  return folder / fmt::format(".{}.tmp-{}-{}", path.filename().string(), ::getpid(),
                              temporary_counter.fetch_add(1));
}

void commitTemporary(const std::filesystem::path& temporary, const std::filesystem::path& path) {
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    fail(path, "rename a temporary file to", error);
  }
}

}  // namespace geardyn::io
