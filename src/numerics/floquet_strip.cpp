/// The Floquet exponents among Hill eigenvalues (detail/floquet_strip.h).

#include "geardyn/numerics/floquet_strip.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace geardyn::detail {

using Complex = std::complex<double>;

std::vector<std::complex<double>> floquetStrip(const Eigen::VectorXcd& values, double omega,
                                               int n) {
  std::vector<Complex> strip;
  const double tolerance = 1e-3 * omega;
  for (const Complex& v : values) {
    const double edge = std::abs(v.imag()) - 0.5 * omega;
    if (edge > tolerance) continue;
    if (std::abs(edge) <= tolerance && v.imag() < 0.0) continue;  // a + iω/2's copy a − iω/2
    strip.push_back(v);
  }
  // Lazarus & Thomas (2010): the Floquet exponents are the 2n with the smallest |Im λ|.
  std::sort(strip.begin(), strip.end(), [](const Complex& a, const Complex& b) {
    return std::abs(a.imag()) < std::abs(b.imag());
  });
  if (static_cast<int>(strip.size()) > 2 * n) strip.resize(2 * n);
  std::sort(strip.begin(), strip.end(),
            [](const Complex& a, const Complex& b) { return a.real() > b.real(); });
  return strip;
}

Complex floquetMultiplier(Complex exponent, double omega) {
  const double half = 0.5 * omega, T = 2.0 * std::numbers::pi / omega;
  if (std::abs(std::abs(exponent.imag()) - half) <= 1e-4 * omega) {
    return -std::exp(exponent.real() * T);
  }
  if (std::abs(exponent.imag()) <= 1e-4 * omega) return std::exp(exponent.real() * T);
  return std::exp(exponent * T);
}

}  // namespace geardyn::detail
