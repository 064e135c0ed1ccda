/// The analysis file of `geardyn train` (train_analysis.h).

#include "geardyn/config/train_analysis.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "geardyn/config/gearbox_config.h"
#include "geardyn/config/output_section.h"
#include "geardyn/error.h"

namespace geardyn::config {
namespace {
constexpr double kRpm = std::numbers::pi / 30.0;

void addSpeedRange(config::ConfigSchema& schema, const std::string& s, int points,
                   const std::string& default_min) {
  schema.real(s + ".speed_min_rpm")
      .unit("rpm")
      .min(0.0)
      .optional()
      .doc("lowest input speed (default: " + default_min + ")");
  schema.real(s + ".speed_max_rpm")
      .unit("rpm")
      .positive()
      .optional()
      .doc("highest input speed (default: 1.5 × the operating speed)");
  schema.integer(s + ".points").min(2).max(100000).defaultValue(points).doc("speeds in the range");
}
}  // namespace

config::ConfigSchema trainSchema(bool inline_gearbox) {
  config::ConfigSchema schema(
      "train",
      "Any gear train (shafts, gears, meshes, bearings, couplings, planetary stages): kinematics "
      "and mesh phasing, static load sharing, modal analysis with Lin & Parker mode types, "
      "Campbell diagram with critical speeds of every shaft and mesh order, frequency-domain "
      "forced response (linear harmonic balance over the common period) and Newmark time "
      "response with the time-varying stiffness of every mesh.");
  if (inline_gearbox) {
    addGearboxSections(schema);
  } else {
    schema.section("gearbox", "The gearbox this analysis is run on.");
  }
  schema.string("gearbox.file")
      .optional()
      .doc(
          "the gearbox description file, relative to this file (absent: the gearbox sections are "
          "in this file)");
  schema.integer("gearbox.load_case")
      .min(0)
      .optional()
      .doc(
          "with a REXS gearbox file (.rexs, .rexsj, .rexsz): the REXS id of the load case that "
          "becomes the operating point (default: the first)");
  schema.boolean("gearbox.all_load_cases")
      .defaultValue(false)
      .doc(
          "with a REXS gearbox file: run the analyses at every load case of its spectrum, each "
          "into <out>/load_case_<id>/");
  schema.section("analysis", "What to run.");
  schema.stringList("analysis.run")
      .choices({"static", "modal", "campbell", "forced", "time"})
      .defaultValue(nlohmann::ordered_json::array({"static", "modal"}))
      .doc("analyses, in any combination");
  schema.section("modal", "Modes at one speed.");
  schema.integer("modal.modes").min(0).defaultValue(0).doc("lowest modes reported (0: all)");
  schema.real("modal.speed_rpm")
      .unit("rpm")
      .optional()
      .doc("input speed (default: the operating point's)");
  schema.section("campbell", "Modes over a speed range, tracked by MAC; critical speeds.");
  addSpeedRange(schema, "campbell", 101, "0");
  schema.integer("campbell.modes").min(1).defaultValue(12).doc("tracked modes");
  schema.integer("campbell.mesh_harmonics")
      .min(1)
      .max(20)
      .defaultValue(3)
      .doc("mesh-order lines 1× … n× of every mesh frequency");
  schema.section("forced", "Frequency-domain steady state over a speed range (gear whine).");
  addSpeedRange(schema, "forced", 200, "0.1 × the operating speed");
  schema.integer("forced.mesh_harmonics")
      .min(1)
      .max(200)
      .defaultValue(10)
      .doc("harmonics of each mesh frequency in the balance");
  schema.integer("forced.max_base_harmonics")
      .min(1)
      .defaultValue(4000)
      .doc("refuse trains whose common period needs more harmonics (use time)");
  schema.section("time", "Newmark time response at one speed to the periodic steady state.");
  schema.real("time.speed_rpm").unit("rpm").optional().doc("input speed (default: operating)");
  schema.real("time.duration")
      .unit("s")
      .min(0.0)
      .defaultValue(0.0)
      .doc("simulated time (0: until the slowest mode has decayed by 1e-6, then the window)");
  schema.real("time.time_step")
      .unit("s")
      .min(0.0)
      .defaultValue(0.0)
      .doc("Δt (0: the fastest mesh period / steps_per_mesh_period)");
  schema.integer("time.steps_per_mesh_period").min(8).defaultValue(128).doc("for the default Δt");
  schema.integer("time.record_periods")
      .min(1)
      .max(1000)
      .defaultValue(2)
      .doc("common periods recorded at the end");
  schema.boolean("time.start_from_static")
      .defaultValue(true)
      .doc("start from the static deflection (else from rest)");
  schema.integer("time.mesh_harmonics")
      .min(1)
      .max(200)
      .defaultValue(20)
      .doc("harmonics of the frequency-domain steady state it is compared with");
  config::addOutputSection(schema);
  return schema;
}

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
  o.mesh_harmonics = static_cast<int>(analysis.integer("forced.mesh_harmonics"));
  o.max_base_harmonics = static_cast<int>(analysis.integer("forced.max_base_harmonics"));
  return o;
}

TrainTimeOptions trainTimeOptionsFromConfig(const config::Config& analysis) {
  TrainTimeOptions o;
  o.duration = analysis.real("time.duration");
  o.time_step = analysis.real("time.time_step");
  o.steps_per_mesh_period = static_cast<int>(analysis.integer("time.steps_per_mesh_period"));
  o.record_periods = static_cast<int>(analysis.integer("time.record_periods"));
  o.start_from_static = analysis.boolean("time.start_from_static");
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

}  // namespace geardyn::config
