/// Tooth-pair contact elements of a train mesh tabulated at sampled phases
/// (train_tooth_pairs.h).

#include "geardyn/system/train_tooth_pairs.h"

#include <algorithm>
#include <cstddef>

namespace geardyn {

double positiveFraction(double d0, double d1) {
  if (d0 == d1) return d0 > 0.0 ? 1.0 : 0.0;
  // d(λ) = d0 + λ (d1 − d0) crosses 0 at λ* = d0 / (d0 − d1).
  const double crossing = std::clamp(d0 / (d0 - d1), 0.0, 1.0);
  return d1 > d0 ? 1.0 - crossing : crossing;
}

void ToothPairTable::tabulate(const MeshContactElements& elements, const double* phases,
                              int count) {
  elements_ = elements.count();
  samples_ = count;
  const std::size_t size = static_cast<std::size_t>(elements_) * static_cast<std::size_t>(count);
  k_.resize(size);
  g_.resize(size);
  for (int i = 0; i < count; ++i) {
    for (int j = 0; j < elements_; ++j) {
      elements.element(phases[i], j, k_[i * elements_ + j], g_[i * elements_ + j]);
    }
  }
}

double ToothPairTable::linearForce(int i, double y, double* slope) const {
  double f = 0.0, s = 0.0;
  for (int j = 0; j < elements_; ++j) {
    const double k = stiffness(i, j);
    if (k > 0.0) {
      f += k * (y - gap(i, j));
      s += k;
    }
  }
  if (slope) *slope = s;
  return f;
}

double ToothPairTable::meanSlope(int i0, double y0, int i1, double y1) const {
  double s = 0.0;
  for (int j = 0; j < elements_; ++j) {
    const double k = 0.5 * (stiffness(i0, j) + stiffness(i1, j));
    if (k > 0.0) s += k * positiveFraction(y0 - gap(i0, j), y1 - gap(i1, j));
  }
  return s;
}

}  // namespace geardyn
