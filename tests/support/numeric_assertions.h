#pragma once
/// \file
/// Shared numerical assertions (STYLE.md): relative-or-absolute closeness for scalars and Eigen
/// objects, printing both values and the tolerance on failure.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <sstream>
#include <string>

namespace geardyn::testing {

/// Round-off of a handful of double operations: for closed forms evaluated two ways.
inline constexpr double kRoundOff = 1e-12;

/// |actual − expected| <= max(rtol · |expected|, atol).
inline ::testing::AssertionResult isClose(double actual, double expected, double rtol,
                                          double atol = 0.0) {
  const double error = std::abs(actual - expected);
  const double allowed = std::max(rtol * std::abs(expected), atol);
  if (std::isfinite(actual) && error <= allowed) return ::testing::AssertionSuccess();
  std::ostringstream out;
  out.precision(17);
  out << "actual " << actual << " vs expected " << expected << ": |error| " << error
      << " > allowed " << allowed << " (rtol " << rtol << ", atol " << atol << ")";
  return ::testing::AssertionFailure() << out.str();
}

/// Element-wise isClose for Eigen objects of equal shape; reports the worst element.
template <typename DerivedA, typename DerivedB>
::testing::AssertionResult isClose(const Eigen::MatrixBase<DerivedA>& actual,
                                   const Eigen::MatrixBase<DerivedB>& expected, double rtol,
                                   double atol = 0.0) {
  if (actual.rows() != expected.rows() || actual.cols() != expected.cols()) {
    return ::testing::AssertionFailure()
           << "shape " << actual.rows() << "x" << actual.cols() << " vs expected "
           << expected.rows() << "x" << expected.cols();
  }
  for (Eigen::Index j = 0; j < actual.cols(); ++j) {
    for (Eigen::Index i = 0; i < actual.rows(); ++i) {
      auto result = isClose(static_cast<double>(actual(i, j)), static_cast<double>(expected(i, j)),
                            rtol, atol);
      if (!result) return result << " at (" << i << ", " << j << ")";
    }
  }
  return ::testing::AssertionSuccess();
}

}  // namespace geardyn::testing

/// EXPECT_CLOSE(actual, expected, rtol[, atol]) for scalars and Eigen objects.
#define EXPECT_CLOSE(actual, expected, ...) \
  EXPECT_TRUE(::geardyn::testing::isClose((actual), (expected), __VA_ARGS__))
#define ASSERT_CLOSE(actual, expected, ...) \
  ASSERT_TRUE(::geardyn::testing::isClose((actual), (expected), __VA_ARGS__))
