/// Finding and loading geardyn's optional modules (see the header).

#include "geardyn/module_loader.h"

#include <dlfcn.h>
#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <vector>

#include "geardyn/error.h"

namespace geardyn {
namespace fs = std::filesystem;

void* loadModuleSymbol(const std::string& file_name, const char* symbol, bool global) {
  std::vector<fs::path> folders;
  if (const char* dir = std::getenv("GEARDYN_MODULE_DIR"); dir && *dir) folders.emplace_back(dir);
  Dl_info self{};
  if (dladdr(reinterpret_cast<void*>(&loadModuleSymbol), &self) != 0 && self.dli_fname) {
    std::error_code ec;
    const fs::path image = fs::canonical(self.dli_fname, ec);
    if (!ec) {
      folders.push_back(image.parent_path());
      folders.push_back(image.parent_path().parent_path() / "lib");
    }
  }
  folders.emplace_back(GEARDYN_MODULE_BUILD_DIR);

  std::string reasons;
  for (const auto& folder : folders) {
    const fs::path candidate = folder / file_name;
    std::error_code ec;
    if (!fs::exists(candidate, ec)) {
      reasons += fmt::format("\n  {}: absent", candidate.string());
      continue;
    }
    void* handle = dlopen(candidate.c_str(), RTLD_NOW | (global ? RTLD_GLOBAL : RTLD_LOCAL));
    if (!handle) {
      reasons += fmt::format("\n  {}: {}", candidate.string(), dlerror());
      continue;
    }
    if (void* address = dlsym(handle, symbol)) return address;
    reasons += fmt::format("\n  {}: no symbol {}", candidate.string(), symbol);
  }
  throw IoError(
      fmt::format("cannot load geardyn's module {} (set GEARDYN_MODULE_DIR to its "
                  "folder):{}",
                  file_name, reasons));
}

}  // namespace geardyn
