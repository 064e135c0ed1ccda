/// Memory limit and the up-front resource check of CLI runs (see run_budget.h).

#include "geardyn/analysis/run_budget.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

#include "geardyn/error.h"

namespace geardyn::analysis {

double memoryLimitBytes() {
  if (const char* env = std::getenv("GEARDYN_MEMORY_LIMIT")) {
    char* end = nullptr;
    const double v = std::strtod(env, &end);
    if (end == env || *end != '\0' || !(v > 0) || !std::isfinite(v))
      throw InputError("GEARDYN_MEMORY_LIMIT", env, "a number of bytes > 0 (e.g. 2e9)");
    return v;
  }
  std::ifstream meminfo("/proc/meminfo");
  std::string line;
  while (std::getline(meminfo, line)) {
    if (line.rfind("MemAvailable:", 0) != 0) continue;
    std::istringstream fields(line.substr(13));
    double kib = 0;
    if (fields >> kib) return kMemoryFraction * kib * 1024.0;
  }
  return std::numeric_limits<double>::infinity();
}

std::string formatBytes(double bytes) {
  const char* units[] = {"B", "kB", "MB", "GB", "TB", "PB"};
  int u = 0;
  while (bytes >= 1000.0 && u < 5) bytes /= 1000.0, ++u;
  return fmt::format("{:.3g} {}", bytes, units[u]);
}

std::string formatDuration(double seconds) {
  if (seconds < 120) return fmt::format("{:.2g} s", seconds);
  if (seconds < 7200) return fmt::format("{:.2g} min", seconds / 60);
  if (seconds < 3 * 86400) return fmt::format("{:.3g} h", seconds / 3600);
  if (seconds < 365.25 * 86400) return fmt::format("{:.3g} days", seconds / 86400);
  return fmt::format("{:.3g} years", seconds / (365.25 * 86400));
}

std::string checkRunEstimate(const RunEstimate& estimate, const std::string& label) {
  const double limit = memoryLimitBytes();
  if (estimate.bytes > limit) {
    throw InputError(
        estimate.key, estimate.value,
        fmt::format("too large for this machine: the run would need about {} ({}), over the "
                    "memory limit of {} ({})",
                    formatBytes(estimate.bytes), estimate.basis, formatBytes(limit),
                    std::getenv("GEARDYN_MEMORY_LIMIT")
                        ? "GEARDYN_MEMORY_LIMIT"
                        : fmt::format("{:.0f} % of MemAvailable", 100 * kMemoryFraction)));
  }
  if (estimate.seconds > kLongRunSeconds) {
    return fmt::format(
        "{}: note: this run is estimated to take up to {} ({} = {}; {}) and about {} of "
        "memory; proceeding\n",
        label, formatDuration(estimate.seconds), estimate.key, estimate.value, estimate.basis,
        formatBytes(estimate.bytes));
  }
  return "";
}

}  // namespace geardyn::analysis
