#include "command.h"

#include <fmt/format.h>

#include <iostream>
#include <mutex>
#include <set>

#include "geardyn/analysis/warning_groups.h"

namespace geardyn::cli {

std::filesystem::path CommandOptions::resultFolder() const {
  if (!out_dir.empty()) return out_dir;
  return std::filesystem::path("results") / config_file.stem();
}

void report(const CommandOptions& options, const std::string& text) {
  if (!options.quiet) std::cout << text << std::flush;
}

void warn(const std::string& text, bool quiet) {
  static std::mutex mutex;
  static std::set<std::string> shown;
  const bool note = isNote(text);
  if (note && quiet) return;
  const std::lock_guard<std::mutex> lock(mutex);
  if (shown.insert(text).second) std::cerr << (note ? "" : "warning: ") << text << "\n";
}

void warnAll(const std::vector<std::string>& texts, bool quiet) {
  for (const auto& line : analysis::groupedWarnings(texts)) warn(line, quiet);
}

std::string exitCodesText() {
  const std::pair<int, const char*> codes[] = {
      {kExitOk, "success"},
      {kExitNumericalFailure, "numerical failure (results written, their status says so)"},
      {kExitBadInput, "bad input (usage, configuration or data)"},
      {kExitIoFailure, "I/O failure (a file could not be read or written)"},
      {kExitInternalError, "internal error (a bug in geardyn; please report it)"}};
  std::string text = "Exit codes:";
  for (const auto& [code, meaning] : codes) text += fmt::format("\n  {}  {}", code, meaning);
  return text;
}

}  // namespace geardyn::cli
