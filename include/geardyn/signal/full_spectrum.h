#pragma once
/// \file
/// Full spectrum of a shaft orbit (Bently Nevada; Goldman & Muszynska; Rao 2023 §4.3–4.4;
/// shared/reference/full_spectrum.md): from two orthogonal probes x, y ordered so that turning
/// from x to y follows the shaft's rotation, z(t) = x(t) + j y(t). Each frequency's orbit is an
/// ellipse = a forward circle (radius A₊, turning with the shaft) + a backward circle (A₋).
///
/// Conventions: FFT with e^{−j2πkn/N} and scaling 1/N, so that bin +k holds the forward and bin
/// −k the backward 0-peak circle radius (not the 2/N of one-sided spectra); phases are those of
/// z's components at t = 0 of the record.

#include <complex>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace geardyn {

/// Two-sided spectrum of z = x + jy, frequencies ascending from −f_s/2 to below +f_s/2 [Hz].
struct FullSpectrum {
  std::vector<double> frequency;                  ///< [Hz]
  std::vector<std::complex<double>> coefficient;  ///< Z_k / N: 0-peak whirl circle (complex)
};

/// Window applied before the FFT (for display; the rectangular window keeps exact bins exact).
enum class SpectrumWindow { kRectangular, kHann };

/// The full spectrum of a record of N samples at `sample_rate` [Hz] (FFTW). With the Hann
/// window the coefficients are divided by the window's mean (coherent gain), so that a
/// component on a bin keeps its amplitude.
FullSpectrum fullSpectrum(const std::vector<double>& x, const std::vector<double>& y,
                          double sample_rate, SpectrumWindow window = SpectrumWindow::kRectangular);

/// Forward and backward circles of one frequency from the phasors of x and y
/// (x = Re(X e^{jωt}), y = Re(Y e^{jωt})): c₊ = (X + jY)/2, c₋ = (X* + jY*)/2 (complex radii
/// with phase), |c₊| = A₊, |c₋| = A₋.
std::pair<std::complex<double>, std::complex<double>> whirlCircles(std::complex<double> X,
                                                                   std::complex<double> Y);

/// A named whirl component: frequency > 0 forward, < 0 backward, 0 static.
struct WhirlComponent {
  std::string name;
  double frequency = 0.0;            ///< signed [Hz]
  std::complex<double> value = 0.0;  ///< 0-peak complex radius (static: the mean of z)
};

/// Least-squares fit of z(t) = Σ_k c_k e^{j2π f_k t} at the given signed frequencies (leakage-
/// free whatever the record length, as long as the frequencies are distinct and resolvable):
/// fills `value` of each component. t_k = k / sample_rate. Throws InputError for duplicate
/// frequencies or a singular fit.
void fitWhirlComponents(const std::vector<double>& x, const std::vector<double>& y,
                        double sample_rate, std::vector<WhirlComponent>& components);

/// How whirl components are read from a record.
enum class WhirlExtraction {
  kAuto,          ///< exact FFT bins when every frequency falls on a bin, else least squares
  kExactBins,     ///< FFT bins; InputError when a frequency is not on a bin (leakage)
  kLeastSquares,  ///< fitWhirlComponents
};

/// Fills `value` of each component from the record (0-peak complex radius at sample 0). Returns
/// the method used. A frequency is on a bin when f N / f_s is within 1e-6 of an integer.
WhirlExtraction extractWhirlComponents(const std::vector<double>& x, const std::vector<double>& y,
                                       double sample_rate, std::vector<WhirlComponent>& components,
                                       WhirlExtraction method = WhirlExtraction::kAuto);

/// Adds white Gaussian noise of standard deviation level × std(channel) (Rao 2023 §5 studies);
/// the generator is the caller's (seeded) so that studies are reproducible.
void addRelativeNoise(std::vector<double>& channel, double level, std::mt19937_64& rng);

}  // namespace geardyn
