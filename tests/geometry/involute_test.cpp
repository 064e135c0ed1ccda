#include "geardyn/geometry/involute.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "geardyn/error.h"
#include "support/numeric_assertions.h"

namespace geardyn {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

TEST(Involute, KnownValue) {
  // inv 20° = tan 20° − 20° (gear tables: 0.014904384).
  EXPECT_CLOSE(involute(20.0 * kDegree), 0.014904383867336446, testing::kRoundOff);
  EXPECT_EQ(involute(0.0), 0.0);
}

TEST(Involute, InverseRoundTripsOverTheUsefulRange) {
  // Pressure angles from 0.1° to 80°. The residual inv(α) − v is at round-off; the angle itself
  // is as well determined as inv allows: tan α − α cancels for small α, so a rounding error
  // ε·α in inv moves α by ε·α / tan²α (4 ulps of margin).
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  for (double degrees = 0.1; degrees < 80.0; degrees += 0.37) {
    const double alpha = degrees * kDegree;
    const double value = involute(alpha);
    const double found = inverseInvolute(value);
    EXPECT_CLOSE(involute(found), value, 4 * kEps, 4 * kEps * alpha) << degrees << " deg";
    const double conditioning = 1.0 + 1.0 / std::pow(std::tan(alpha), 2);
    EXPECT_CLOSE(found, alpha, 4 * kEps * conditioning) << degrees << " deg";
  }
  EXPECT_EQ(inverseInvolute(0.0), 0.0);
}

TEST(Involute, InverseRejectsNegativeAndNonFinite) {
  EXPECT_THROW(inverseInvolute(-1e-3), InputError);
  EXPECT_THROW(inverseInvolute(std::nan("")), InputError);
  EXPECT_THROW(inverseInvolute(INFINITY), InputError);
}

}  // namespace
}  // namespace geardyn
