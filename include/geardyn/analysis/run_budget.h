#pragma once
/// \file
/// The resource check every run (CLI and Python) makes before it allocates (issue #18, item 1): an
/// estimate of the memory of its large arrays and of its wall time, from its inputs alone. A run
/// that would not fit in the memory limit is refused (InputError: exit 2, naming the key that
/// drives the size, the estimate and the limit); a run estimated to take longer than
/// kLongRunSeconds says so on stderr and proceeds.
///
/// The limit is 80 % of MemAvailable in /proc/meminfo (the kernel's estimate of what can be
/// allocated without swapping; the other 20 % is headroom for what the estimate leaves out), or
/// the environment variable GEARDYN_MEMORY_LIMIT in bytes (e.g. "2e9") when set.

#include <string>

namespace geardyn::analysis {

/// Runs estimated to take longer than this many seconds say so before they start.
inline constexpr double kLongRunSeconds = 30.0;
/// The fraction of MemAvailable a run may use.
inline constexpr double kMemoryFraction = 0.8;

/// What a run will need, estimated before it starts.
struct RunEstimate {
  std::string key;       ///< the configuration key that drives the size ("monte_carlo.samples")
  std::string value;     ///< its value as the user gave it
  double bytes = 0.0;    ///< peak memory of the run's large arrays [B]
  double seconds = 0.0;  ///< wall time [s] (an upper bound for runs that may stop early)
  std::string basis;     ///< how it was estimated ("1e+08 samples × 420 B")
};

/// The memory a run may use [B] (see the file comment); +inf when it cannot be determined.
double memoryLimitBytes();

/// "2.3 GB", "512 MB", "17 kB".
std::string formatBytes(double bytes);
/// "45 s", "12 min", "33 h", "4.1 years".
std::string formatDuration(double seconds);

/// Refuses a run that does not fit (InputError naming the key that drives its size). Returns
/// a note for a run estimated to take longer than kLongRunSeconds ("" otherwise), to be shown
/// before it starts; `label` starts the note ("simulate").
std::string checkRunEstimate(const RunEstimate& estimate, const std::string& label);

}  // namespace geardyn::analysis
