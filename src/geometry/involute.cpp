#include "geardyn/geometry/involute.h"

#include <cmath>
#include <string>

#include "geardyn/error.h"

namespace geardyn {

double involute(double alpha) {
  return std::tan(alpha) - alpha;
}

double inverseInvolute(double value) {
  if (!(value >= 0.0) || !std::isfinite(value)) {
    throw InputError("inverseInvolute(value)", std::to_string(value), "must be finite and >= 0");
  }
  if (value == 0.0) return 0.0;
  // inv(α) = α³/3 + 2α⁵/15 + ...: the cube root is a start from which Newton converges
  // monotonically (inv is convex on [0, π/2)); inv'(α) = tan²α.
  double alpha = std::cbrt(3.0 * value);
  if (alpha > 1.5) alpha = 1.5;
  for (int iteration = 0; iteration < 60; ++iteration) {
    const double t = std::tan(alpha);
    const double step = (t - alpha - value) / (t * t);
    alpha -= step;
    if (std::abs(step) <= 1e-15 * alpha)
      break;  // quadratic convergence: one more step is round-off
  }
  return alpha;
}

}  // namespace geardyn
