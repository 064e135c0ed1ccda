#include "geardyn/config/hbm_config.h"

#include <cmath>

namespace geardyn::config {

ConfigSchema hbmSchema() {
  ConfigSchema schema("hbm",
                      "Harmonic-balance forced response of the gear-pair model (coupled static/"
                      "dynamic, AFT), continued in frequency through folds, with stability.");
  schema.string("title").optional().doc("free text describing the study");
  schema.section("hbm", "Harmonic balance.");
  schema.integer("hbm.harmonics")
      .min(1)
      .max(512)
      .defaultValue(14)
      .doc("H, harmonics of the mesh frequency");
  schema.integer("hbm.samples")
      .min(3)
      .max(1 << 20)
      .defaultValue(256)
      .doc("N, AFT samples per period (> 2H), as a gearbox's nonlinear.samples");
  schema.alias("hbm.samples_per_period", "hbm.samples");
  schema.real("hbm.tolerance")
      .unit("-")
      .positive()
      .defaultValue(1e-10)
      .doc("relative residual ‖R‖ / (|F| + k̄‖q‖ + ‖F_ext‖)");
  schema.integer("hbm.max_iterations").min(1).defaultValue(40).doc("Newton iterations per point");
  schema.realList("hbm.detail_frequencies")
      .unit("Hz")
      .min(0.0)
      .defaultValue(nlohmann::ordered_json::array())
      .doc(
          "frequencies at which one period of response, contact force and mesh stiffness is "
          "written");
  schema.section("sweep", "Continuation in the mesh frequency.");
  schema.real("sweep.start")
      .unit("Hz")
      .positive()
      .required()
      .doc("lower end of the range (nondimensional: Ω)");
  schema.real("sweep.stop").unit("Hz").positive().required().doc("upper end of the range");
  schema.real("sweep.initial_step")
      .unit("Hz")
      .positive()
      .optional()
      .doc("first arclength step (in frequency units); absent: derived (a fifth of max_step)");
  schema.real("sweep.min_step")
      .unit("Hz")
      .positive()
      .optional()
      .doc("smallest step before a failure is reported; absent: derived (1e-6 max_step)");
  schema.real("sweep.max_step")
      .unit("Hz")
      .positive()
      .optional()
      .doc(
          "largest step; absent: derived from the problem, min(range / 50, zeta f_n / j) with j "
          "the highest superharmonic order (<= H) whose resonance f_n / j lies in the range");
  schema.real("sweep.fold_tolerance")
      .unit("Hz")
      .positive()
      .optional()
      .doc(
          "how far the branch must go back in frequency to confirm a fold; absent: 1e-3 of "
          "the range");
  schema.string("sweep.direction")
      .choices({"up", "down", "both"})
      .defaultValue("both")
      .doc("sweep up from start, down from stop, or both");
  schema.boolean("sweep.stability").defaultValue(true).doc("stability of every point");
  schema.string("sweep.stability_method")
      .choices({"hill", "monodromy"})
      .defaultValue("monodromy")
      .doc(
          "the sampled monodromy matrix (O(N), the default), or Hill's method (sorted Floquet "
          "exponents, ~40x dearer; the cross-check)");
  schema.realList("sweep.newmark_frequencies")
      .unit("Hz")
      .min(0.0)
      .defaultValue(nlohmann::ordered_json::array())
      .doc("frequencies checked by Newmark time integration (overlaid on the plot)");
  addGearPairDynamicsSections(schema);
  return schema;
}

HarmonicBalanceOptions harmonicBalanceOptionsFromConfig(const Config& config) {
  HarmonicBalanceOptions o;
  o.harmonics = static_cast<int>(config.integer("hbm.harmonics"));
  o.samples_per_period = static_cast<int>(config.integer("hbm.samples"));
  o.tolerance = config.real("hbm.tolerance");
  o.max_iterations = static_cast<int>(config.integer("hbm.max_iterations"));
  o.validate();
  return o;
}

}  // namespace geardyn::config
