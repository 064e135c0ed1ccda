#pragma once
// Implementation of integrateOverPeriod (header-only: it is a template over the integrand).
// Allocation-free: it walks the breaks in place.

#include <boost/math/quadrature/gauss.hpp>
#include <vector>

namespace geardyn {

template <typename F>
double integrateOverPeriod(const F& f, const std::vector<double>& breaks, int panels) {
  double total = 0.0;
  const auto piece = [&](double from, double to) {
    const double width = (to - from) / panels;
    for (int p = 0; p < panels; ++p) {
      const double a = from + p * width;
      total += boost::math::quadrature::gauss<double, 20>::integrate(f, a, a + width);
    }
  };
  double start = 0.0;
  for (double b : breaks) {
    if (b > start && b < 1.0) {
      piece(start, b);
      start = b;
    }
  }
  piece(start, 1.0);
  return total;
}

}  // namespace geardyn
