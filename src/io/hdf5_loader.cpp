/// Loading libgeardyn_hdf5.so on the first use of an .h5 file, and the atomic HDF5 writer built
/// on it (see hdf5_module.h).

#include <fmt/format.h>

#include <filesystem>
#include <mutex>

#include "geardyn/error.h"
#include "geardyn/io/atomic_file.h"
#include "geardyn/io/hdf5_lock.h"
#include "geardyn/module_loader.h"
#include "hdf5_module.h"

namespace geardyn::io::detail {

const Hdf5ModuleApi& hdf5Module() {
  static const Hdf5ModuleApi* api = [] {
    using Entry = const Hdf5ModuleApi* (*)();
    const auto entry =
        reinterpret_cast<Entry>(loadModuleSymbol("libgeardyn_hdf5.so", "geardyn_hdf5_module"));
    const Hdf5ModuleApi* loaded = entry();
    if (loaded->version != kHdf5ModuleVersion) {
      throw IoError(fmt::format("libgeardyn_hdf5.so is version {}, this geardyn needs {}: rebuild",
                                loaded->version, kHdf5ModuleVersion));
    }
    return loaded;
  }();
  return *api;
}

}  // namespace geardyn::io::detail

namespace geardyn::io {

void writeHdf5File(const std::string& path, const Hdf5Content& content) {
  using namespace detail;
  const std::filesystem::path target(path);
  const std::filesystem::path folder = target.has_parent_path() ? target.parent_path() : ".";
  std::filesystem::create_directories(folder);
  const std::filesystem::path temp = temporaryPathFor(target);
  const Hdf5ModuleApi& h5 = hdf5Module();
  const char* error = nullptr;
  {
    const std::lock_guard<std::mutex> lock(hdf5Mutex());
    error = h5.write(temp.c_str(), content);
  }
  if (error) {
    std::error_code ec;
    std::filesystem::remove(temp, ec);
    throw IoError(fmt::format("cannot write {}: {}", temp.string(), error));
  }
  commitTemporary(temp, target);
}

}  // namespace geardyn::io
