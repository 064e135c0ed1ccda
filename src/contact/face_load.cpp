/// Load distribution across the face (contact/face_load.h).

#include "geardyn/contact/face_load.h"

#include <algorithm>
#include <cmath>

namespace geardyn {

double faceLoadFactor(const std::vector<double>& w) {
  const std::size_t n = w.size();
  if (n == 0) return 1.0;
  double mean = 0.0;
  for (double v : w) mean += v / static_cast<double>(n);
  if (!(mean > 0.0)) return 1.0;
  double peak = *std::max_element(w.begin(), w.end());
  if (n >= 2) {
    // The slice centres sit half a slice inside the face ends: a line load rising towards an
    // end is extrapolated to the edge (w_0 + (w_0 − w_1)/2), exact when it is linear there.
    for (auto [e, f] : {std::pair{w[0], w[1]}, std::pair{w[n - 1], w[n - 2]}}) {
      if (e > f && f > 0.0) peak = std::max(peak, e + 0.5 * (e - f));
    }
  }
  return peak / mean;
}

FaceLoadDistribution faceLoadDistribution(const LoadedToothContact& contact, double force,
                                          int positions) {
  return faceLoadDistribution(contact, force, contact.sweep(force, positions));
}

FaceLoadDistribution faceLoadDistribution(const LoadedToothContact& contact, double force,
                                          std::vector<LoadedContactPoint> points) {
  FaceLoadDistribution d;
  d.force = force;
  const int n = contact.slices();
  const double b = contact.stiffness().faceWidth(), width = b / n;
  d.face_width = b;
  d.z.resize(n);
  for (int i = 0; i < n; ++i) d.z[i] = (i + 0.5) * width - 0.5 * b;
  d.points = std::move(points);
  d.mean_line_load.assign(n, 0.0);
  d.line_load.reserve(d.points.size());
  for (const auto& p : d.points) {
    std::vector<double> w(n);
    for (int i = 0; i < n; ++i) {
      w[i] = p.face_loads[i] / width;
      d.mean_line_load[i] += w[i] / static_cast<double>(d.points.size());
    }
    d.k_hbeta_max = std::max(d.k_hbeta_max, faceLoadFactor(w));
    d.line_load.push_back(std::move(w));
  }
  d.k_hbeta = faceLoadFactor(d.mean_line_load);
  double sum = 0.0, moment = 0.0, peak = 0.0;
  for (int i = 0; i < n; ++i) {
    sum += d.mean_line_load[i], moment += d.z[i] * d.mean_line_load[i];
    peak = std::max(peak, d.mean_line_load[i]);
  }
  d.centre_of_load = sum > 0.0 ? moment / sum : 0.0;
  int loaded = 0;
  for (double v : d.mean_line_load) loaded += v > 1e-9 * peak ? 1 : 0;
  d.loaded_fraction = static_cast<double>(loaded) / n;
  return d;
}

}  // namespace geardyn
