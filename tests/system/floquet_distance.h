#pragma once
/// \file
/// Comparing two sets of Floquet exponents in the tests of Hill's method.

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

namespace geardyn::testing {

/// The largest distance from an exponent of `a` to the nearest of `b` [1/s], modulo iω (an
/// exponent on the strip's edge may come as a + iω/2 or as a − iω/2).
inline double farthestExponent(const std::vector<std::complex<double>>& a,
                               const std::vector<std::complex<double>>& b, double omega) {
  double worst = 0.0;
  for (const std::complex<double>& x : a) {
    double nearest = HUGE_VAL;
    for (const std::complex<double>& y : b) {
      const double im = x.imag() - y.imag();
      nearest =
          std::min(nearest, std::hypot(x.real() - y.real(), im - omega * std::round(im / omega)));
    }
    worst = std::max(worst, nearest);
  }
  return worst;
}

}  // namespace geardyn::testing
