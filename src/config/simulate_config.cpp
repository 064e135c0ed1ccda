#include "geardyn/config/simulate_config.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "geardyn/config/gear_pair_gearbox.h"
#include "geardyn/config/gear_pair_keys.h"
#include "geardyn/stiffness/mesh_stiffness_summary.h"

namespace geardyn::config {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// The quantities derived from the model (k̄, ζ, ω_n) and the warnings about them and about
/// the time step.
void deriveFromModel(const Config& config, GearPairModelBuild& b) {
  b.mean_stiffness = summarizeMeshStiffness(*b.spec.stiffness, 0).mean;
  b.natural_frequency = std::sqrt(b.mean_stiffness / b.spec.mass);
  b.damping_ratio = b.spec.damping / (2.0 * std::sqrt(b.mean_stiffness * b.spec.mass));
  if (b.damping_ratio >= 1.0) {
    b.warnings.push_back(fmt::format(
        "damping ratio ζ = {:.3g} >= 1: the mesh is overdamped (typical gear meshes: 0.02–0.1)",
        b.damping_ratio));
  }
  // Time step against the mesh and natural periods.
  if (config.string("solver.method") != "newmark" || !(b.spec.mesh_frequency > 0.0)) return;
  const int steps = static_cast<int>(config.integer("solver.steps_per_period"));
  if (steps < 10) {
    b.warnings.push_back(
        fmt::format("time step = mesh period / {} is larger than a tenth of the mesh period: raise "
                    "solver.steps_per_period to at least 10 (128 or more for the harmonics)",
                    steps));
  }
  const double h = 1.0 / (b.spec.mesh_frequency * steps);
  const double natural_period = kTwoPi / b.natural_frequency;
  if (h > natural_period / 10.0) {
    const int needed = static_cast<int>(std::ceil(10.0 / (b.spec.mesh_frequency * natural_period)));
    b.warnings.push_back(
        fmt::format("time step {:.3g} is larger than a tenth of the natural period {:.3g}: raise "
                    "solver.steps_per_period to at least {} for accuracy",
                    h, natural_period, needed));
  }
}

}  // namespace

GearPairModelBuild buildGearPairModel(const Config& config, bool require_speed) {
  GearPairKeys keys = readGearPairKeys(config, require_speed);
  GearPairModelBuild b;
  b.nondimensional = keys.nondimensional;
  b.warnings = std::move(keys.warnings);
  // The file's gearbox, read by the gearbox reader and reduced: the gear-pair solvers are the
  // one-pair train's fast path (system/sdof_reduction.h).
  b.spec = gearPairFromGearbox(gearPairGearboxToml(config, keys), config.source() + " (gearbox)",
                               &b.warnings);
  // The gearbox has no harmonic load yet: the file's extra forces act on the reduced model.
  b.spec.extra_forces = keys.extra_forces;
  GearPairModel{b.spec};  // bad values named by the gear-pair model, in the file's terms
  deriveFromModel(config, b);
  return b;
}

TimeResponseOptions timeResponseOptionsFromConfig(const Config& config) {
  TimeResponseOptions o;
  o.method = config.string("solver.method") == "newmark" ? TimeIntegrator::kNewmark
                                                         : TimeIntegrator::kDormandPrince;
  const std::string preset = config.string("solver.newmark");
  o.newmark = preset == "average_acceleration" ? NewmarkParameters::averageAcceleration()
              : preset == "linear_acceleration"
                  ? NewmarkParameters::linearAcceleration()
                  : NewmarkParameters{config.real("solver.beta"), config.real("solver.gamma")};
  o.steps_per_period = static_cast<int>(config.integer("solver.steps_per_period"));
  o.output_points_per_period = static_cast<int>(config.integer("solver.output_points_per_period"));
  o.relative_tolerance = config.real("solver.relative_tolerance");
  o.absolute_tolerance = config.real("solver.absolute_tolerance");
  o.steady_tolerance = config.real("solver.steady_tolerance");
  o.min_periods = static_cast<int>(config.integer("solver.min_periods"));
  o.max_periods = static_cast<int>(config.integer("solver.max_periods"));
  o.output_periods = static_cast<int>(config.integer("solver.output_periods"));
  o.start_from_static = config.string("solver.start") == "static";
  return o;
}

}  // namespace geardyn::config
