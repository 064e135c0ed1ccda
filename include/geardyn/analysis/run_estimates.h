#pragma once
/// \file
/// What each long-running command will need, from its configuration alone (issue #18, item 1):
/// the memory of its large arrays and its wall time on one core. The per-item costs are
/// measured on the reference machine (Release build; see docs/cli.md, "Resource limits") and
/// rounded up: an estimate errs on the large side.

#include <string>

#include "geardyn/analysis/run_budget.h"
#include "geardyn/config/config.h"

namespace geardyn::analysis {

/// simulate (and stats with stats.simulate): solver.steps_per_period × solver.max_periods
/// steps; output_points_per_period × output_periods samples kept.
RunEstimate estimateTimeResponse(const config::Config& config);
/// stats: monte_carlo.samples samples, each over monte_carlo.teeth mesh periods.
RunEstimate estimateMonteCarlo(const config::Config& config, int threads);
/// hbm: (2H+1) unknowns, samples_per_period AFT samples, the frequency range over max_step.
RunEstimate estimateHarmonicBalance(const config::Config& config);
/// rotor (Rao): time.samples samples (time and frequency domain, spectra, tables).
RunEstimate estimateRotorTime(const config::Config& config);
/// rotor (finite element, analysis "time"): duration / time_step Newmark steps.
RunEstimate estimateFeRotorTime(const config::Config& config, int dofs);
/// train runup: `steps` Newmark steps of a train of `dofs` DOFs, every step kept for `channels`
/// tracked channels and `meshes` mesh forces (order tracking needs the whole record); `key` and
/// `value` name what drives the size (runup.duration).
RunEstimate estimateTrainRunUp(double steps, int dofs, int channels, int meshes,
                               const std::string& key, const std::string& value);
/// train time: `steps` Newmark steps of a train of `dofs` DOFs, `recorded` steps kept (the DOFs,
/// with their rates when `rates`, and the mesh forces).
RunEstimate estimateTrainTime(double steps, int dofs, double recorded, bool rates, int meshes,
                              const std::string& key, const std::string& value);
/// The estimate of a stage an analysis reports through AnalysisContext::check_budget
/// ("simulate", "stats_time", "hbm", "rotor_time", "rotor_fe_time" with `size` = DOFs,
/// "stats_monte_carlo" with `size` = threads); {} for other stages.
RunEstimate estimateStage(const std::string& stage, long long size, const config::Config& config);
/// The estimate of one run of `command` with this configuration ({} when it is small).
RunEstimate estimateCommand(const std::string& command, const config::Config& config);

}  // namespace geardyn::analysis
