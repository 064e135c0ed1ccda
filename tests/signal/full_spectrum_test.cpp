// Full spectrum conventions (shared/reference/full_spectrum.md): forward and backward circles,
// 1/N scaling, exact bins, the least-squares fit at known frequencies, seeded noise.
#include "geardyn/signal/full_spectrum.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geardyn/error.h"
#include "support/numeric_assertions.h"

namespace geardyn {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

/// An orbit sampled at fs: a forward circle at f1, an ellipse at f2 (phasors X2, Y2) and an
/// offset (static deflection).
void orbit(std::size_t n, double fs, std::vector<double>& x, std::vector<double>& y) {
  x.resize(n);
  y.resize(n);
  const std::complex<double> X2(3e-6, 1e-6), Y2(-0.5e-6, 2e-6);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = i / fs;
    x[i] = 5e-6 * std::cos(kTwoPi * 11.0 * t + 0.4) +
           std::real(X2 * std::polar(1.0, kTwoPi * 176.0 * t)) + 20e-6;
    y[i] = 5e-6 * std::sin(kTwoPi * 11.0 * t + 0.4) +
           std::real(Y2 * std::polar(1.0, kTwoPi * 176.0 * t)) - 7e-6;
  }
}

std::complex<double> at(const FullSpectrum& s, double f) {
  for (std::size_t k = 0; k < s.frequency.size(); ++k) {
    if (std::abs(s.frequency[k] - f) < 1e-9) return s.coefficient[k];
  }
  ADD_FAILURE() << "no bin at " << f;
  return 0.0;
}

TEST(FullSpectrum, ForwardCircleBackwardEllipseAndStaticOnExactBins) {
  // 1 s at 1024 Hz: 11 Hz and 176 Hz fall on bins.
  std::vector<double> x, y;
  orbit(1024, 1024.0, x, y);
  const FullSpectrum s = fullSpectrum(x, y, 1024.0);
  // Forward circle: radius 5 µm at +11 Hz, nothing at −11 Hz.
  EXPECT_CLOSE(std::abs(at(s, 11.0)), 5e-6, 1e-12);
  EXPECT_CLOSE(std::arg(at(s, 11.0)), 0.4, 1e-12);
  EXPECT_NEAR(std::abs(at(s, -11.0)), 0.0, 1e-18);
  // Ellipse: the bins hold exactly the circles of the phasor formulas.
  const auto [forward, backward] = whirlCircles({3e-6, 1e-6}, {-0.5e-6, 2e-6});
  EXPECT_CLOSE(std::abs(at(s, 176.0) - forward), 0.0, 0.0, 1e-18);
  EXPECT_CLOSE(std::abs(at(s, -176.0) - backward), 0.0, 0.0, 1e-18);
  // Semi-axes of the ellipse: A₊ + A₋ and |A₊ − A₋|.
  EXPECT_GT(std::abs(forward), 0.0);
  // Static: the mean of z.
  EXPECT_CLOSE(at(s, 0.0).real(), 20e-6, 1e-12);
  EXPECT_CLOSE(at(s, 0.0).imag(), -7e-6, 1e-12);
}

TEST(FullSpectrum, LeastSquaresFitIsLeakageFree) {
  // 0.93 s: the frequencies are off-bin, the FFT leaks, the fit at known frequencies does not.
  const double fs = 1000.0;
  std::vector<double> x, y;
  orbit(930, fs, x, y);
  std::vector<WhirlComponent> c = {{"static", 0.0},
                                   {"pinion_1x_fwd", 11.0},
                                   {"pinion_1x_bwd", -11.0},
                                   {"mesh_1_fwd", 176.0},
                                   {"mesh_1_bwd", -176.0}};
  fitWhirlComponents(x, y, fs, c);
  const auto [forward, backward] = whirlCircles({3e-6, 1e-6}, {-0.5e-6, 2e-6});
  EXPECT_CLOSE(c[0].value.real(), 20e-6, 1e-10);
  EXPECT_CLOSE(std::abs(c[1].value), 5e-6, 1e-10);
  EXPECT_NEAR(std::abs(c[2].value), 0.0, 1e-16);
  EXPECT_NEAR(std::abs(c[3].value - forward), 0.0, 1e-16);
  EXPECT_NEAR(std::abs(c[4].value - backward), 0.0, 1e-16);
  std::vector<WhirlComponent> twice = {{"a", 11.0}, {"b", 11.0}};
  EXPECT_THROW(fitWhirlComponents(x, y, fs, twice), InputError);
}

TEST(FullSpectrum, HannWindowKeepsOnBinAmplitudes) {
  std::vector<double> x, y;
  orbit(1024, 1024.0, x, y);
  const FullSpectrum s = fullSpectrum(x, y, 1024.0, SpectrumWindow::kHann);
  EXPECT_CLOSE(std::abs(at(s, 11.0)), 5e-6, 1e-9);
}

TEST(FullSpectrum, RelativeNoiseIsSeededAndScaled) {
  std::vector<double> x, y;
  orbit(20000, 1024.0, x, y);
  std::vector<double> a = x, b = x;
  std::mt19937_64 first(7), second(7);
  addRelativeNoise(a, 0.1, first);
  addRelativeNoise(b, 0.1, second);
  EXPECT_EQ(a, b);  // same seed, same noise
  double mean = 0, var = 0, noise_var = 0;
  for (double v : x) mean += v / x.size();
  for (std::size_t i = 0; i < x.size(); ++i) {
    var += (x[i] - mean) * (x[i] - mean) / x.size();
    noise_var += (a[i] - x[i]) * (a[i] - x[i]) / x.size();
  }
  // 20000 samples estimate a standard deviation to ±0.5 % (1σ); 3 % is 6σ.
  EXPECT_NEAR(std::sqrt(noise_var), 0.1 * std::sqrt(var), 0.03 * 0.1 * std::sqrt(var));
  EXPECT_THROW(addRelativeNoise(a, -1.0, first), InputError);
  EXPECT_THROW(fullSpectrum({1.0, NAN}, {0.0, 0.0}, 10.0), InputError);
}

}  // namespace
}  // namespace geardyn
