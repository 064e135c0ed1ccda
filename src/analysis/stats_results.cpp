#include "geardyn/analysis/stats_results.h"

#include <fmt/format.h>

#include "geardyn/analysis/geometry_results.h"
#include "geardyn/config/geometry_config.h"
#include "geardyn/config/output_section.h"
#include "geardyn/config/simulate_config.h"
#include "geardyn/config/stats_config.h"
#include "geardyn/config/stiffness_config.h"
#include "geardyn/error.h"
#include "geardyn/io/csv_reader.h"

namespace geardyn::analysis {

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

nlohmann::ordered_json monteCarloJson(const MonteCarloOptions& options,
                                      const std::vector<MonteCarloSample>& samples) {
  std::vector<double> ratio, load;
  for (const auto& s : samples) {
    ratio.push_back(s.ratio);
    load.push_back(s.dynamic_mean_excitation);
  }
  const auto json = [](const Distribution& d, double scale) {
    return nlohmann::ordered_json{{"mean", d.mean * scale}, {"std", d.std * scale},
                                  {"q05", d.q05 * scale},   {"q50", d.q50 * scale},
                                  {"q95", d.q95 * scale},   {"min", d.min * scale},
                                  {"max", d.max * scale}};
  };
  const Distribution l = describe(load);
  return {{"samples", options.samples},
          {"seed", options.seed},
          {"teeth", options.teeth},
          {"ratio", json(describe(ratio), 1.0)},
          {"dynamic_mean_excitation", json(l, 1.0)},
          {"dynamic_mean_load", json(l, options.baseload)}};
}

io::CsvTable monteCarloTable(const std::vector<MonteCarloSample>& samples) {
  io::CsvTable table({"sample", "ratio", "dynamic_mean_excitation", "r_ke", "d_k", "d_e",
                      "delta_m1_ef", "phase_fraction"});
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const auto& s = samples[i];
    table.addRow({static_cast<long long>(i), s.ratio, s.dynamic_mean_excitation, s.r_ke, s.d_k,
                  s.d_e, s.delta_m1_ef, s.phase});
  }
  return table;
}

io::CsvTable histogramTable(const std::vector<MonteCarloSample>& samples, int bins) {
  double lo = samples.front().ratio, hi = lo;
  for (const auto& s : samples) {
    lo = std::min(lo, s.ratio);
    hi = std::max(hi, s.ratio);
  }
  if (hi <= lo) hi = lo + 1e-12;
  std::vector<long long> counts(bins, 0);
  for (const auto& s : samples) {
    const int b = std::min(bins - 1, static_cast<int>((s.ratio - lo) / (hi - lo) * bins));
    ++counts[b];
  }
  io::CsvTable table({"ratio_low", "ratio_high", "count"});
  for (int b = 0; b < bins; ++b) {
    table.addRow({lo + (hi - lo) * b / bins, lo + (hi - lo) * (b + 1) / bins, counts[b]});
  }
  return table;
}

}  // namespace geardyn::analysis
