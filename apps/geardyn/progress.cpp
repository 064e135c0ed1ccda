/// The CLI's progress line (see progress.h).

#include "progress.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>

namespace geardyn::cli {

ProgressReporter::ProgressReporter(std::string label, std::string unit, bool enabled,
                                   double first_after)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      enabled_(enabled),
      first_after_(first_after) {
  // GEARDYN_PROGRESS_AFTER=SECONDS moves the first line (0: from the start; tests use it).
  if (const char* env = std::getenv("GEARDYN_PROGRESS_AFTER")) {
    char* end = nullptr;
    const double seconds = std::strtod(env, &end);
    if (end != env && *end == '\0' && seconds >= 0.0) first_after_ = seconds;
  }
}

ProgressReporter::~ProgressReporter() {
  if (printed_) std::cerr << fmt::format("{}: finished in {:.3g} s\n", label_, elapsed());
}

bool ProgressReporter::enabledFor(const CommandOptions& options) {
  return !options.quiet && options.progress;
}

double ProgressReporter::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

ProgressCallback ProgressReporter::callback() {
  if (!enabled_) return {};
  return [this](double done, double total) { update(done, total); };
}

void ProgressReporter::update(double done, double total, long long failed) {
  if (!enabled_) return;
  std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock()) return;
  const auto now = std::chrono::steady_clock::now();
  const double t = std::chrono::duration<double>(now - start_).count();
  const double since = std::chrono::duration<double>(now - last_).count();
  if (t < first_after_ || (printed_ && since < std::max(1.0, t / 20.0))) return;
  last_ = now;
  printed_ = true;
  const double fraction = total > 0 ? std::clamp(done / total, 0.0, 1.0) : 0.0;
  const std::string eta = fraction > 0 ? fmt::format("ETA {:.0f} s", t * (1 - fraction) / fraction)
                                       : std::string("ETA unknown");
  std::string counts =
      unit_.empty() ? std::string() : fmt::format("{:.6g}/{:.6g} {}", done, total, unit_);
  if (failed >= 0) counts += fmt::format(", {} failed", failed);
  std::cerr << fmt::format("{}: {:.0f} %{}, {:.0f} s elapsed, {}\n", label_, 100 * fraction,
                           counts.empty() ? std::string() : " (" + counts + ")", t, eta);
}

}  // namespace geardyn::cli
