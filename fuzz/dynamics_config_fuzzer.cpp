/// libFuzzer target: arbitrary bytes through the `geardyn simulate` / `hbm` input path (TOML,
/// schema, model building with every stiffness source and contact law, a few periods of
/// Newmark and one harmonic-balance solve, kept small so that each input is cheap). Bad input
/// may only end in geardyn::InputError; solver trouble must end in a status, not a crash.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "geardyn/config/config.h"
#include "geardyn/config/hbm_config.h"
#include "geardyn/config/simulate_config.h"
#include "geardyn/error.h"
#include "geardyn/solvers/harmonic_balance.h"
#include "geardyn/solvers/time_response.h"
#include "geardyn/system/gear_pair_model.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const geardyn::config::ConfigSchema schema = geardyn::config::hbmSchema();
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto config = geardyn::config::parseConfig(text, "fuzz.toml", schema);
    if (config.integer("hbm.harmonics") > 8 || config.integer("hbm.samples") > 128 ||
        config.integer("mesh_stiffness.potential_energy.table_points") > 1025) {
      return 0;
    }
    const auto build = geardyn::config::buildGearPairModel(config, false);
    geardyn::GearPairModelSpec spec = build.spec;
    if (!(spec.mesh_frequency > 0.0)) spec.mesh_frequency = build.natural_frequency / 7.0;
    const geardyn::GearPairModel model(spec);
    auto options = geardyn::config::timeResponseOptionsFromConfig(config);
    options.max_periods = 4;
    options.min_periods = 2;
    options.steps_per_period = 64;
    options.output_points_per_period = 16;
    options.output_periods = 1;
    const auto response = geardyn::solveTimeResponse(model, options);
    volatile double sink = response.x.empty() ? 0.0 : response.x.back();
    geardyn::HarmonicBalance hbm(model, geardyn::config::harmonicBalanceOptionsFromConfig(config));
    geardyn::HarmonicBalancePoint point;
    point.omega = 2.0 * 3.141592653589793 * spec.mesh_frequency;
    point.q = hbm.linearGuess(point.omega);
    hbm.solve(point);
    hbm.stabilityMonodromy(point);
    sink = sink + point.residual;
    (void)sink;
  } catch (const geardyn::InputError&) {
    // the expected outcome for bad input
  }
  return 0;
}
