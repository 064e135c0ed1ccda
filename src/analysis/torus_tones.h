#pragma once
/// The name of a torus tone for the result tables (forced_tones.csv, nonlinear_tones.csv).

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "geardyn/io/csv_table.h"
#include "geardyn/torus/train_torus.h"

namespace geardyn::analysis::detail {

/// "2g1-g2": the tone n as a combination of the generators.
inline std::string toneName(const std::vector<int>& n) {
  std::string out;
  for (std::size_t j = 0; j < n.size(); ++j) {
    if (n[j] == 0) continue;
    out += n[j] < 0 ? "-" : (out.empty() ? "" : "+");
    if (std::abs(n[j]) != 1) out += std::to_string(std::abs(n[j]));
    out += fmt::format("g{}", j + 1);
  }
  return out;
}

/// One row per line of `lines` at or above `floor` × the largest: speed [rpm], mesh, n_j, the
/// tone's name, frequency [Hz], amplitude [N] and amplitude / largest (forced_tones.csv,
/// nonlinear_tones.csv).
inline void addToneRows(io::CsvTable& table, double speed_rpm, const std::string& mesh,
                        const std::vector<TorusLine>& lines, double floor) {
  double largest = 0.0;
  for (const TorusLine& line : lines) largest = std::max(largest, line.amplitude);
  for (const TorusLine& line : lines) {
    if (line.amplitude < floor * largest) continue;
    std::vector<io::CsvCell> row{speed_rpm, mesh};
    for (int n : line.tone) row.push_back(n);
    row.push_back(toneName(line.tone));
    row.push_back(line.frequency);
    row.push_back(line.amplitude);
    row.push_back(line.amplitude / largest);
    table.addRow(row);
  }
}

}  // namespace geardyn::analysis::detail
