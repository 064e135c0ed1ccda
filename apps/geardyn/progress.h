#pragma once
/// \file
/// The one progress line of every long CLI run (simulate, hbm, rotor, stats Monte Carlo, ltca,
/// identify, sweep): "label: 45 % (900/2000 periods), 12 s elapsed, ETA 15 s" on stderr. Shown
/// when stderr is a terminal or `--progress` is given, never with `--quiet`; the first line
/// comes after `first_after` seconds (runs shorter than ~2 s print nothing), later ones at most
/// once a second (once every elapsed/20 on very long runs). The environment variable
/// GEARDYN_PROGRESS_AFTER (seconds) moves the first line.

#include <chrono>
#include <mutex>
#include <string>

#include "command.h"
#include "geardyn/progress.h"

namespace geardyn::cli {

class ProgressReporter {
 public:
  /// `label` starts each line ("simulate"), `unit` names what is counted ("periods").
  ProgressReporter(std::string label, std::string unit, bool enabled, double first_after = 2.0);
  ~ProgressReporter();
  ProgressReporter(const ProgressReporter&) = delete;
  ProgressReporter& operator=(const ProgressReporter&) = delete;

  /// Work done so far out of `total`; `failed` >= 0 is shown as "(n failed)". Thread-safe; a
  /// call while another thread prints is skipped.
  void update(double done, double total, long long failed = -1);
  /// A callback for a solver's options (empty when disabled, so solvers skip the calls).
  ProgressCallback callback();
  /// Seconds since construction.
  double elapsed() const;

  /// --progress or a terminal on stderr, and not --quiet.
  static bool enabledFor(const CommandOptions& options);

 private:
  std::string label_, unit_;
  bool enabled_;
  double first_after_;
  bool printed_ = false;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now(), last_{};
};

}  // namespace geardyn::cli
