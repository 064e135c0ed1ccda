#pragma once
/// \file
/// How long-running solvers report progress: an optional callback in their options, called on
/// the calling thread with the work done so far and the total, in the solver's own unit
/// (periods, samples, frequency points, ...). An empty callback costs nothing. The CLI turns the
/// calls into a progress line with an ETA on stderr (apps/geardyn/progress.h).

#include <functional>

namespace geardyn {

/// done ∈ [0, total]; total > 0. When the total is an upper bound (a run that stops at its
/// steady state), the reported ETA is an upper bound too.
using ProgressCallback = std::function<void(double done, double total)>;

}  // namespace geardyn
