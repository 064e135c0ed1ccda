/// Hertz point contact (hertz_point_contact.h).

#include "geardyn/contact/hertz_point_contact.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace geardyn {
namespace {

constexpr double kPi = std::numbers::pi;

/// (K(e) − E(e)) / e², with its series π/4 + 3π e²/32 + 45π e⁴/1024 where the difference
/// cancels (e² < 1e-6: the next term is below 1e-18 relative).
double kMinusEOverE2(double e) {
  const double e2 = e * e;
  if (e2 < 1e-6) return kPi / 4.0 + 3.0 * kPi / 32.0 * e2 + 45.0 * kPi / 1024.0 * e2 * e2;
  return (std::comp_ellint_1(e) - std::comp_ellint_2(e)) / e2;
}

/// B/A of the eccentricity e (Johnson eq. 3.70 over 3.69), increasing from 1 at e = 0.
double curvatureRatio(double e) {
  const double e2 = e * e;
  const double E = std::comp_ellint_2(e);
  // [E/(1−e²) − K] / (K − E) = [E/(1−e²) − E − (K − E)] / (K − E) = E/((1−e²)·f) − 1,
  // f = (K − E)/e² (E e²/(1−e²) over (K − E)).
  return E / ((1.0 - e2) * kMinusEOverE2(e)) - 1.0;
}

}  // namespace

double contactModulus(double youngs_1, double poisson_1, double youngs_2, double poisson_2) {
  return 1.0 /
         ((1.0 - poisson_1 * poisson_1) / youngs_1 + (1.0 - poisson_2 * poisson_2) / youngs_2);
}

HertzPointContact hertzPointContact(double curvature_a, double curvature_b,
                                    double contact_modulus) {
  if (!(curvature_a > 0.0) || !(curvature_b > 0.0) || !std::isfinite(curvature_a) ||
      !std::isfinite(curvature_b) || !(contact_modulus > 0.0) || !std::isfinite(contact_modulus)) {
    throw std::invalid_argument(
        "hertzPointContact: curvatures and contact modulus must be > 0 "
        "and finite (got A " +
        std::to_string(curvature_a) + ", B " + std::to_string(curvature_b) + ", E* " +
        std::to_string(contact_modulus) + ")");
  }
  double A = curvature_a, B = curvature_b;
  if (A > B) std::swap(A, B);
  const double ratio = B / A;
  // Bisection on e for B/A (monotone); the circle exactly when the ratio is 1 to round-off.
  double e = 0.0;
  if (ratio - 1.0 > 1e-14) {
    double lo = 0.0, hi = 1.0 - 1e-16;
    for (int i = 0; i < 200 && hi - lo > 1e-17; ++i) {
      const double mid = 0.5 * (lo + hi);
      (curvatureRatio(mid) < ratio ? lo : hi) = mid;
    }
    e = 0.5 * (lo + hi);
  }
  const double f = kMinusEOverE2(e);  // (K − E)/e²
  const double K = std::comp_ellint_1(e);
  HertzPointContact c;
  c.eccentricity = e;
  // a³ = 3 P f / (2π A E*) per unit P; b = a √(1 − e²); δ = A a² K / f; p₀ = 3P/(2π a b).
  c.semi_major = std::cbrt(3.0 * f / (2.0 * kPi * A * contact_modulus));
  c.semi_minor = c.semi_major * std::sqrt(1.0 - e * e);
  c.deflection = A * c.semi_major * c.semi_major * K / f;
  c.pressure = 3.0 / (2.0 * kPi * c.semi_major * c.semi_minor);
  return c;
}

}  // namespace geardyn
