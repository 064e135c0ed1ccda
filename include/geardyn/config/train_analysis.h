#pragma once
/// \file
/// The analysis file of `geardyn train`: which analyses to run on a gearbox (static, modal,
/// campbell, forced, time, runup, nonlinear, stats) and their options. The gearbox is named by
/// `[gearbox] file = "path"` (relative to the analysis file) or written inline in the same file.

#include <utility>
#include <vector>

#include "geardyn/config/config.h"
#include "geardyn/config/config_schema.h"
#include "geardyn/solvers/train_harmonic_balance.h"
#include "geardyn/solvers/train_modal.h"
#include "geardyn/solvers/train_nonlinear_time.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/solvers/train_runup.h"
#include "geardyn/solvers/train_time.h"
#include "geardyn/torus/train_torus.h"

namespace geardyn::config {

/// The analysis sections; with `inline_gearbox` also the gearbox sections (gearbox_config.h).
config::ConfigSchema trainSchema(bool inline_gearbox);

/// Input speed [rad/s] of a section's optional speed_rpm (default: the operating point's).
double analysisSpeed(const config::Config& analysis, const std::string& section, double operating);

TrainModalOptions trainModalOptionsFromConfig(const config::Config& analysis,
                                              const std::string& section);
TrainSteadyOptions trainSteadyOptionsFromConfig(const config::Config& analysis);
/// [forced] mesh_harmonics, torus_above, torus_truncation (validated).
TrainTorusOptions trainTorusOptionsFromConfig(const config::Config& analysis);
TrainTimeOptions trainTimeOptionsFromConfig(const config::Config& analysis);
/// [nonlinear] harmonics, samples, tolerance, max_iterations (validated: InputError naming the
/// key, e.g. nonlinear.samples <= 2 × harmonics, which aliases).
TrainHarmonicBalanceOptions trainHarmonicBalanceOptionsFromConfig(const config::Config& analysis);
/// The nonlinear sweep's input speeds |Ω| [rad/s], (lowest, highest): [nonlinear]
/// speed_min_rpm (default 0.5 × the operating speed) and speed_max_rpm (1.5 ×); InputError
/// naming the key when the range is empty or the operating speed is 0 and no range is given.
std::pair<double, double> nonlinearSpeedRange(const config::Config& analysis, double operating);

/// [runup] speed_min_rpm (default 0.1 × the operating speed), speed_max_rpm (1.5 ×) and
/// direction as a ramp in the operating speed's sense of rotation [rad/s], with
/// runup.duration (0: to be derived). InputError naming runup.speed_max_rpm when it is below
/// speed_min_rpm.
TrainSpeedRamp runUpRampFromConfig(const config::Config& analysis, double operating);
/// runup.time_step, steps_per_mesh_period, speed_tolerance, start.
TrainRunUpOptions trainRunUpOptionsFromConfig(const config::Config& analysis);

/// Ascending input speeds [rad/s] of a section with speed_min_rpm, speed_max_rpm (defaults: 0
/// and 1.5 × the operating speed) and points; InputError naming the keys when the range is
/// empty or the operating speed is 0 and no maximum is given.
std::vector<double> speedRangeFromConfig(const config::Config& analysis, const std::string& section,
                                         double operating, double default_min_fraction);
/// The speeds of `train` [forced] [rad/s]: speedRangeFromConfig of the section with the default
/// minimum 0.1 × the operating speed (default 200 points, 0.1–1.5 × the operating speed).
std::vector<double> forcedSpeedsFromConfig(const config::Config& analysis, double operating);

}  // namespace geardyn::config
