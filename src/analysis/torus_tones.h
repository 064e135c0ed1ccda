#pragma once
/// The name of a torus tone for the result tables (forced_tones.csv, nonlinear_tones.csv).

#include <fmt/format.h>

#include <cstdlib>
#include <string>
#include <vector>

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

}  // namespace geardyn::analysis::detail
