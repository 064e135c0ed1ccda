#pragma once
/// \file
/// Mode tracking over a speed sweep by the modal assurance criterion, and the crossings of
/// tracked modes with excitation-order lines — shared by the FE rotor's and the gear train's
/// Campbell diagrams. `Mode` has `Eigen::VectorXcd shape` and `double frequency` [Hz].

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

namespace geardyn::detail {

/// |aᴴb|² / (|a|² |b|²).
inline double modalAssurance(const Eigen::VectorXcd& a, const Eigen::VectorXcd& b) {
  const double den = a.squaredNorm() * b.squaredNorm();
  return den > 0.0 ? std::norm(a.dot(b)) / den : 0.0;
}

/// Each previous mode takes the unclaimed candidate of highest MAC (greedy over all pairs in
/// descending MAC); a track with no candidate left keeps its previous mode.
template <typename Mode>
std::vector<Mode> trackByMac(const std::vector<Mode>& previous, const std::vector<Mode>& found) {
  struct Pair {
    double mac;
    std::size_t track, candidate;
  };
  std::vector<Pair> pairs;
  for (std::size_t a = 0; a < previous.size(); ++a)
    for (std::size_t b = 0; b < found.size(); ++b)
      pairs.push_back({modalAssurance(previous[a].shape, found[b].shape), a, b});
  std::sort(pairs.begin(), pairs.end(), [](const Pair& x, const Pair& y) { return x.mac > y.mac; });
  std::vector<int> assigned(previous.size(), -1);
  std::vector<bool> taken(found.size(), false);
  for (const Pair& p : pairs) {
    if (assigned[p.track] >= 0 || taken[p.candidate]) continue;
    assigned[p.track] = static_cast<int>(p.candidate);
    taken[p.candidate] = true;
  }
  std::vector<Mode> tracked;
  for (std::size_t a = 0; a < previous.size(); ++a) {
    tracked.push_back(assigned[a] >= 0 ? found[assigned[a]] : previous[a]);
  }
  return tracked;
}

/// Where tracked mode j crosses the line f = slope × speed: calls
/// on_crossing(j, speed, frequency, s) with s in [0, 1) the position between speeds i−1 and i.
template <typename Mode, typename OnCrossing>
void findCrossings(const std::vector<double>& speeds, const std::vector<std::vector<Mode>>& modes,
                   double slope, OnCrossing on_crossing) {
  if (modes.empty()) return;
  for (std::size_t j = 0; j < modes.front().size(); ++j) {
    for (std::size_t i = 1; i < speeds.size(); ++i) {
      const double g0 = modes[i - 1][j].frequency - slope * speeds[i - 1];
      const double g1 = modes[i][j].frequency - slope * speeds[i];
      if (g0 == 0.0 || g0 * g1 >= 0.0) continue;
      const double s = g0 / (g0 - g1);
      const double speed = speeds[i - 1] + s * (speeds[i] - speeds[i - 1]);
      on_crossing(j, i, speed, slope * speed, s);
    }
  }
}

}  // namespace geardyn::detail
