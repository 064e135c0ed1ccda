/// The options of `geardyn train`'s analyses read from its validated analysis file
/// (train_analysis.h; the schema is train_analysis.cpp).

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "geardyn/config/train_analysis.h"
#include "geardyn/error.h"
#include "geardyn/units.h"

namespace geardyn::config {

using geardyn::units::kRpm;

double analysisSpeed(const config::Config& analysis, const std::string& section, double operating) {
  return analysis.has(section + ".speed_rpm") ? analysis.real(section + ".speed_rpm") * kRpm
                                              : operating;
}

TrainModalOptions trainModalOptionsFromConfig(const config::Config& analysis,
                                              const std::string& section) {
  TrainModalOptions o;
  o.modes = static_cast<int>(analysis.integer(section + ".modes"));
  return o;
}

TrainSteadyOptions trainSteadyOptionsFromConfig(const config::Config& analysis) {
  TrainSteadyOptions o;
  if (analysis.has("forced.mesh_harmonics")) {
    o.mesh_harmonics = static_cast<int>(analysis.integer("forced.mesh_harmonics"));
  }
  o.max_base_harmonics = static_cast<int>(analysis.integer("forced.max_base_harmonics"));
  return o;
}

TrainTorusOptions trainTorusOptionsFromConfig(const config::Config& analysis) {
  TrainTorusOptions o;
  if (analysis.has("forced.mesh_harmonics")) {
    o.mesh_harmonics = static_cast<int>(analysis.integer("forced.mesh_harmonics"));
  }
  o.group_harmonics = static_cast<int>(analysis.integer("forced.torus_above"));
  const std::string truncation = analysis.string("forced.torus_truncation");
  o.truncation = truncation == "diamond" ? TorusTruncation::kDiamond : TorusTruncation::kBox;
  o.product_floor = analysis.real("forced.torus_floor");
  o.validate();
  // The product truncation weighs the tones by the derived truncation's estimate: the forced
  // analysis sets it (mesh_order_weights) when mesh_harmonics is derived; "auto" is the box here.
  if (truncation == "product") {
    if (analysis.has("forced.mesh_harmonics")) {
      throw InputError("forced.torus_truncation", truncation,
                       "\"box\" or \"diamond\" with forced.mesh_harmonics given (the product "
                       "truncation weighs the tones by the derived truncation's estimate)");
    }
    o.truncation = TorusTruncation::kProduct;
  }
  return o;
}

TrainTimeOptions trainTimeOptionsFromConfig(const config::Config& analysis) {
  TrainTimeOptions o;
  o.duration = analysis.real("time.duration");
  o.time_step = analysis.real("time.time_step");
  o.steps_per_mesh_period = static_cast<int>(analysis.integer("time.steps_per_mesh_period"));
  o.record_periods = static_cast<int>(analysis.integer("time.record_periods"));
  o.start_from_static = analysis.boolean("time.start_from_static");
  o.method = analysis.string("time.method") == "dormand_prince" ? TrainTimeMethod::kDormandPrince
                                                                : TrainTimeMethod::kNewmark;
  o.relative_tolerance = analysis.real("time.relative_tolerance");
  o.record_rates = !analysis.stringList("probes.stations").empty();
  return o;
}

TrainHarmonicBalanceOptions trainHarmonicBalanceOptionsFromConfig(const config::Config& analysis) {
  TrainHarmonicBalanceOptions o;
  o.harmonics = static_cast<int>(analysis.integer("nonlinear.harmonics"));
  o.samples = static_cast<int>(analysis.integer("nonlinear.samples"));
  o.tolerance = analysis.real("nonlinear.tolerance");
  o.max_iterations = static_cast<int>(analysis.integer("nonlinear.max_iterations"));
  o.validate();
  return o;
}

namespace {
/// (lowest, highest) input speed [rad/s] of a section's speed_min_rpm and speed_max_rpm, by
/// default the given fractions of the operating speed; InputError naming the key when it is
/// absent and the operating speed is 0. The order is the caller's to check.
std::pair<double, double> sectionSpeeds(const config::Config& analysis, const std::string& s,
                                        double operating, double min_fraction,
                                        double max_fraction) {
  const double op = std::abs(operating);
  for (const std::string& key : {s + ".speed_min_rpm", s + ".speed_max_rpm"}) {
    if (!analysis.has(key) && op == 0.0) {
      throw InputError(key, "",
                       "required when the operating speed is 0 rpm (the default range is "
                       "relative to it)");
    }
  }
  const double lo = analysis.has(s + ".speed_min_rpm") ? analysis.real(s + ".speed_min_rpm") * kRpm
                                                       : min_fraction * op;
  const double hi = analysis.has(s + ".speed_max_rpm") ? analysis.real(s + ".speed_max_rpm") * kRpm
                                                       : max_fraction * op;
  return {lo, hi};
}
}  // namespace

std::pair<double, double> nonlinearSpeedRange(const config::Config& analysis, double operating) {
  const auto [lo, hi] = sectionSpeeds(analysis, "nonlinear", operating, 0.5, 1.5);
  if (!(hi > lo)) {
    throw InputError("nonlinear.speed_max_rpm", fmt::format("{:g} rpm", hi / kRpm),
                     fmt::format("more than nonlinear.speed_min_rpm = {:g} rpm", lo / kRpm));
  }
  return {lo, hi};
}

TrainSpeedRamp runUpRampFromConfig(const config::Config& analysis, double operating) {
  const auto [lo, hi] = sectionSpeeds(analysis, "runup", operating, 0.1, 1.5);
  if (!(hi >= lo)) {
    throw InputError("runup.speed_max_rpm", fmt::format("{:g} rpm", hi / kRpm),
                     fmt::format("at least runup.speed_min_rpm = {:g} rpm", lo / kRpm));
  }
  // The operating speed's sense of rotation.
  const double sign = operating < 0.0 ? -1.0 : 1.0;
  TrainSpeedRamp ramp;
  const bool up = analysis.string("runup.direction") == "up";
  ramp.start = sign * (up ? lo : hi);
  ramp.end = sign * (up ? hi : lo);
  ramp.duration = analysis.real("runup.duration");  // 0: derived by the analysis
  return ramp;
}

TrainRunUpOptions trainRunUpOptionsFromConfig(const config::Config& analysis) {
  TrainRunUpOptions o;
  o.time_step = analysis.real("runup.time_step");
  o.steps_per_mesh_period = static_cast<int>(analysis.integer("runup.steps_per_mesh_period"));
  o.speed_tolerance = analysis.real("runup.speed_tolerance");
  const std::string start = analysis.string("runup.start");
  o.start = start == "steady_state" ? TrainRunUpOptions::Start::kSteadyState
            : start == "static"     ? TrainRunUpOptions::Start::kStatic
                                    : TrainRunUpOptions::Start::kRest;
  return o;
}

std::vector<double> speedRangeFromConfig(const config::Config& analysis, const std::string& s,
                                         double operating, double default_min_fraction) {
  const double op = std::abs(operating);
  if (!analysis.has(s + ".speed_max_rpm") && op == 0.0) {
    throw InputError(s + ".speed_max_rpm", "",
                     "required when the operating speed is 0 rpm (the default range is "
                     "relative to it)");
  }
  const double hi =
      analysis.has(s + ".speed_max_rpm") ? analysis.real(s + ".speed_max_rpm") * kRpm : 1.5 * op;
  const double lo = analysis.has(s + ".speed_min_rpm") ? analysis.real(s + ".speed_min_rpm") * kRpm
                                                       : default_min_fraction * op;
  if (!(hi > lo)) {
    throw InputError(s + ".speed_max_rpm", fmt::format("{:g} rpm", hi / kRpm),
                     fmt::format("more than {}.speed_min_rpm = {:g} rpm", s, lo / kRpm));
  }
  const int n = static_cast<int>(analysis.integer(s + ".points"));
  std::vector<double> speeds(n);
  for (int i = 0; i < n; ++i) speeds[i] = lo + (hi - lo) * i / (n - 1.0);
  return speeds;
}

std::vector<double> forcedSpeedsFromConfig(const config::Config& analysis, double operating) {
  return speedRangeFromConfig(analysis, "forced", operating, 0.1);
}

}  // namespace geardyn::config
