#include "geardyn/analysis/ltca_results.h"

#include <fmt/format.h>

#include "geardyn/config/geometry_config.h"
#include "geardyn/config/ltca_config.h"
#include "geardyn/config/output_section.h"
#include "geardyn/config/stiffness_config.h"
#include "geardyn/error.h"

namespace geardyn::analysis {

io::CsvTable ltcaTable(const std::vector<LoadedContactPoint>& points, double force) {
  const std::size_t pairs = points.empty() ? 0 : points.front().pair_loads.size();
  // The STE, the stiffnesses and the loads along the transverse line of action (the force is
  // T1 / r_b1): the names say so, as in mesh_stiffness.csv of geardyn stiffness.
  std::vector<std::string> columns{"mesh_fraction", "ste_transverse_m", "no_load_te_transverse_m",
                                   "secant_stiffness_transverse_n_per_m",
                                   "tangent_stiffness_transverse_n_per_m"};
  for (std::size_t j = 0; j < pairs; ++j)
    columns.push_back(fmt::format("load_pair_{}_transverse_n", j));
  for (std::size_t j = 0; j < pairs; ++j) columns.push_back(fmt::format("share_pair_{}", j));
  io::CsvTable t(columns);
  for (const auto& p : points) {
    std::vector<io::CsvCell> row{p.phase, p.ste, p.no_load_te, p.secant, p.tangent};
    for (double load : p.pair_loads) row.push_back(load);
    for (double load : p.pair_loads) row.push_back(force > 0.0 ? load / force : 0.0);
    t.addRow(row);
  }
  return t;
}

io::CsvTable harrisTable(const std::vector<HarrisPoint>& map) {
  // The loaded STE (peak to peak, mean, harmonics) under the transverse force T1 / r_b1.
  std::vector<std::string> columns{"force_transverse_n", "peak_to_peak_m", "mean_m"};
  const std::size_t h = map.empty() ? 0 : map.front().harmonics.size();
  for (std::size_t i = 0; i < h; ++i) columns.push_back(fmt::format("harmonic_{}_m", i + 1));
  io::CsvTable t(columns);
  for (const auto& p : map) {
    std::vector<io::CsvCell> row{p.force, p.peak_to_peak, p.mean};
    for (double v : p.harmonics) row.push_back(v);
    t.addRow(row);
  }
  return t;
}

io::CsvTable loadStatisticsTable(const std::vector<LoadStatistics>& stats) {
  io::CsvTable t({"a", "m1_k", "m1_ef", "d_k", "d_e", "r_ke", "delta_m1_ef", "variable_term_v",
                  "ratio_eq7", "ratio_eq11"});
  for (const auto& s : stats) {
    const auto& m = s.statistics;
    t.addRow({s.a, m.m1_k, m.m1_ef, m.d_k, m.d_e, m.r_ke, m.delta_m1_ef, m.variable_term, m.ratio,
              m.ratio_eq11});
  }
  return t;
}

}  // namespace geardyn::analysis
