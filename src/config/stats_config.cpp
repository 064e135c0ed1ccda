#include "geardyn/config/stats_config.h"

#include <fmt/format.h>

#include <algorithm>

#include "geardyn/config/geometry_config.h"
#include "geardyn/config/output_section.h"
#include "geardyn/config/simulate_config.h"
#include "geardyn/config/stiffness_config.h"
#include "geardyn/error.h"
#include "geardyn/io/csv_reader.h"

namespace geardyn::config {

ConfigSchema statsSchema() {
  ConfigSchema schema("stats",
                      "Statistics of the dynamic mean excitation (Gelman et al. 2005): the mean "
                      "excitation ratio R from the gear-pair model or from given moments, with an "
                      "optional simulated check.");
  schema.string("title").optional().doc("free text describing the study");
  schema.section("stats", "What to compute.");
  schema.string("stats.source")
      .choices({"model", "moments", "csv"})
      .defaultValue("model")
      .doc(
          "statistics of the [model] curves, of a CSV record (csv_file), or the moments given "
          "below (as in the paper)");
  schema.string("stats.csv_file")
      .optional()
      .doc(
          "csv: a table with K [N/m] and E_f [m] sampled evenly over whole mesh periods (e.g. "
          "mesh_stiffness.csv of geardyn stiffness)");
  schema.string("stats.csv_stiffness_column")
      .defaultValue("k_total_transverse_n_per_m")
      .doc("csv: column of the mesh stiffness K (the name before 2026-11, k_total, still reads)");
  schema.string("stats.csv_error_column")
      .defaultValue("ste_transverse_m")
      .doc("csv: column of the static transmission error E_f = E + F/K (or the older ste_m)");
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
  schema.real("stats.a").unit("-").positive().optional().doc(
      "moments, csv: normalised load a = F/F₀");
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
  schema.real("stats.zeta").unit("-").min(0.0).defaultValue(0.0).doc("moments, csv: damping ratio");
  schema.section("monte_carlo",
                 "Random per-tooth errors: the distribution of R (source = \"model\").");
  schema.integer("monte_carlo.samples")
      .min(0)
      .max(100000000)
      .defaultValue(0)
      .doc("number of samples (0: no Monte Carlo)");
  schema.integer("monte_carlo.seed")
      .min(0)
      .defaultValue(1)
      .doc("random seed (results are bit-identical for a seed, whatever --threads)");
  schema.integer("monte_carlo.teeth")
      .min(1)
      .optional()
      .doc("mesh periods per sample (default: pinion teeth, else 1)");
  schema.real("monte_carlo.pitch_error_std")
      .unit("m")
      .min(0.0)
      .defaultValue(0.0)
      .doc("σ of the per-tooth pitch error (nondimensional: in x₀)");
  schema.real("monte_carlo.profile_error_std")
      .unit("m")
      .min(0.0)
      .defaultValue(0.0)
      .doc("σ of the per-tooth profile slope error over a mesh period");
  schema.real("monte_carlo.stiffness_std")
      .unit("-")
      .min(0.0)
      .lessThan(0.3)
      .defaultValue(0.0)
      .doc("σ of the per-tooth stiffness factor (mean 1)");
  schema.boolean("monte_carlo.random_phase")
      .defaultValue(true)
      .doc("random phase of the gear error relative to the stiffness");
  schema.integer("monte_carlo.histogram_bins")
      .min(2)
      .max(10000)
      .defaultValue(30)
      .doc("bins of histogram.csv");
  addGearPairDynamicsSections(schema);
  return schema;
}

MonteCarloOptions monteCarloOptionsFromConfig(const Config& config, double baseload, int threads) {
  MonteCarloOptions o;
  o.samples = static_cast<int>(config.integer("monte_carlo.samples"));
  o.seed = static_cast<std::uint64_t>(config.integer("monte_carlo.seed"));
  o.teeth = config.has("monte_carlo.teeth") ? static_cast<int>(config.integer("monte_carlo.teeth"))
            : hasGearPair(config)           ? static_cast<int>(config.integer("pinion.teeth"))
                                            : 1;
  o.pitch_error_std = config.real("monte_carlo.pitch_error_std");
  o.profile_error_std = config.real("monte_carlo.profile_error_std");
  o.stiffness_std = config.real("monte_carlo.stiffness_std");
  o.random_phase = config.boolean("monte_carlo.random_phase");
  o.baseload = baseload;
  o.threads = threads;
  return o;
}

MeanExcitation meanExcitationFromConfigCsv(const Config& config) {
  for (const char* key : {"stats.csv_file", "stats.baseload", "stats.a"}) {
    if (!config.has(key)) throw InputError(key, "", "required when stats.source = \"csv\"");
  }
  // A relative path is relative to the configuration file's folder.
  std::filesystem::path file = config.string("stats.csv_file");
  if (file.is_relative()) file = std::filesystem::path(config.source()).parent_path() / file;
  const io::NumericCsv csv(file, "stats.csv_file");
  // The names geardyn stiffness wrote before its columns carried their plane and unit still read.
  const auto column = [&](const std::string& key, const char* current,
                          const char* legacy) -> const std::vector<double>& {
    const std::string name = config.string(key);
    const auto& names = csv.columns();
    if (name == current && std::find(names.begin(), names.end(), name) == names.end() &&
        std::find(names.begin(), names.end(), legacy) != names.end()) {
      return csv.column(legacy, key);
    }
    return csv.column(name, key);
  };
  const auto& stiffness =
      column("stats.csv_stiffness_column", "k_total_transverse_n_per_m", "k_total");
  const auto& error = column("stats.csv_error_column", "ste_transverse_m", "ste_m");
  double k_mean = 0.0;
  for (double k : stiffness) {
    if (!(k > 0.0))
      throw InputError("stats.csv_stiffness_column", fmt::format("{:g}", k),
                       "stiffness samples must be > 0");
    k_mean += k / stiffness.size();
  }
  const double baseload = config.real("stats.baseload");
  std::vector<double> k, e_f;
  for (std::size_t i = 0; i < stiffness.size(); ++i) {
    k.push_back(stiffness[i] / k_mean);
    e_f.push_back(error[i] * k_mean / baseload);
  }
  return meanExcitationFromSamples(k, e_f, config.real("stats.a"), config.real("stats.zeta"));
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

}  // namespace geardyn::config
