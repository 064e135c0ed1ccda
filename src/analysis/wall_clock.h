#pragma once
/// \file
/// Wall time of an analysis step, for summary.json's `wall_time_s` entries.

#include <chrono>

namespace geardyn::analysis::detail {

using Clock = std::chrono::steady_clock;

/// Seconds since `start` [s].
inline double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace geardyn::analysis::detail
