#include "command.h"

#include <iostream>

namespace geardyn::cli {

std::filesystem::path CommandOptions::resultFolder() const {
  if (!out_dir.empty()) return out_dir;
  return std::filesystem::path("results") / config_file.stem();
}

void report(const CommandOptions& options, const std::string& text) {
  if (!options.quiet) std::cout << text << std::flush;
}

}  // namespace geardyn::cli
