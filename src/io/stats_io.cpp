#include "geardyn/io/stats_io.h"

#include "geardyn/error.h"
#include "geardyn/io/geometry_io.h"
#include "geardyn/io/output_section.h"
#include "geardyn/io/simulate_io.h"
#include "geardyn/io/stiffness_io.h"

namespace geardyn::io {

ConfigSchema statsSchema() {
  ConfigSchema schema("stats",
                      "Statistics of the dynamic mean excitation (Gelman et al. 2005): the mean "
                      "excitation ratio R from the gear-pair model or from given moments, with an "
                      "optional simulated check.");
  schema.string("title").optional().doc("free text describing the study");
  schema.section("stats", "What to compute.");
  schema.string("stats.source")
      .choices({"model", "moments"})
      .defaultValue("model")
      .doc("statistics of the [model] curves, or the moments given below (as in the paper)");
  schema.real("stats.baseload")
      .unit("N")
      .positive()
      .optional()
      .doc(
          "F₀, the load the profile modification was designed for (SI model); default: the mean "
          "force (a = 1)");
  schema.boolean("stats.simulate")
      .defaultValue(false)
      .doc(
          "also simulate the steady state and report the time average of k·y (= L_d for a linear "
          "contact)");
  schema.real("stats.a").unit("-").positive().optional().doc("moments: normalised load a = F/F₀");
  schema.real("stats.m1_k").unit("-").defaultValue(1.0).doc("moments: mean of k = K/K̄");
  schema.real("stats.m1_ef").unit("-").optional().doc("moments: mean of e_f (or delta_m1_ef)");
  schema.real("stats.delta_m1_ef").unit("-").optional().doc("moments: Δm₁(e_f) = m₁(e_f) − a");
  schema.real("stats.d_k").unit("-").min(0.0).optional().doc("moments: standard deviation of k");
  schema.real("stats.d_e").unit("-").min(0.0).optional().doc("moments: standard deviation of e_f");
  schema.real("stats.r_ke")
      .unit("-")
      .min(-1.0)
      .max(1.0)
      .optional()
      .doc("moments: correlation of k and e_f");
  schema.real("stats.m1_edot")
      .unit("-")
      .defaultValue(0.0)
      .doc("moments: mean of de/dt₁ (eq. 14: 0)");
  schema.real("stats.zeta").unit("-").min(0.0).defaultValue(0.0).doc("moments: damping ratio");
  addGearPairDynamicsSections(schema);
  return schema;
}

nlohmann::ordered_json toJson(const MeanExcitation& s) {
  return {{"m1_k", s.m1_k},
          {"m1_ef", s.m1_ef},
          {"d_k", s.d_k},
          {"d_e", s.d_e},
          {"r_ke", s.r_ke},
          {"m1_edot", s.m1_edot},
          {"a", s.a},
          {"zeta", s.zeta},
          {"delta_m1_ef", s.delta_m1_ef},
          {"dynamic_mean_excitation", s.dynamic_mean_excitation},
          {"ratio", s.ratio},
          {"variable_term", s.variable_term},
          {"ratio_eq15", s.ratio_eq15},
          {"ratio_eq11", s.ratio_eq11},
          {"classification",
           "dynamic mean excitation " + s.classification() + " the transmitted mean load"}};
}

MeanExcitation meanExcitationFromConfigMoments(const Config& config) {
  for (const char* key : {"stats.a", "stats.d_k", "stats.d_e", "stats.r_ke"}) {
    if (!config.has(key)) throw InputError(key, "", "required when stats.source = \"moments\"");
  }
  const double a = config.real("stats.a");
  if (config.has("stats.m1_ef") == config.has("stats.delta_m1_ef")) {
    throw InputError("stats.m1_ef", "", "give m1_ef or delta_m1_ef (one of them)");
  }
  const double m1_ef =
      config.has("stats.m1_ef") ? config.real("stats.m1_ef") : a + config.real("stats.delta_m1_ef");
  return meanExcitationFromMoments(config.real("stats.m1_k"), m1_ef, config.real("stats.d_k"),
                                   config.real("stats.d_e"), config.real("stats.r_ke"),
                                   config.real("stats.m1_edot"), a, config.real("stats.zeta"));
}

}  // namespace geardyn::io
