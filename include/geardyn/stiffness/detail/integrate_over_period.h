#pragma once
// Implementation of integrateOverPeriod (header-only: it is a template over the integrand).

#include <boost/math/quadrature/gauss.hpp>
#include <vector>

namespace geardyn {

template <typename F>
double integrateOverPeriod(const F& f, const std::vector<double>& breaks, int panels) {
  std::vector<double> edges;
  edges.reserve(breaks.size() + 2);
  edges.push_back(0.0);
  for (double b : breaks) {
    if (b > edges.back()) edges.push_back(b);
  }
  if (edges.back() < 1.0) edges.push_back(1.0);
  double total = 0.0;
  for (std::size_t piece = 0; piece + 1 < edges.size(); ++piece) {
    const double width = (edges[piece + 1] - edges[piece]) / panels;
    for (int p = 0; p < panels; ++p) {
      const double a = edges[piece] + p * width;
      total += boost::math::quadrature::gauss<double, 20>::integrate(f, a, a + width);
    }
  }
  return total;
}

}  // namespace geardyn
