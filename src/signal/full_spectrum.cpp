#include "geardyn/signal/full_spectrum.h"

#include <fftw3.h>
#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <mutex>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/signal/detail/fftw_planner.h"

namespace geardyn {

std::mutex& detail::fftwPlannerMutex() {
  static std::mutex m;
  return m;
}

namespace {

using detail::fftwPlannerMutex;

constexpr double kTwoPi = 2.0 * std::numbers::pi;

void requireRecord(const std::vector<double>& x, const std::vector<double>& y, double sample_rate) {
  if (x.size() != y.size() || x.size() < 2) {
    throw InputError("record", fmt::format("{} and {} samples", x.size(), y.size()),
                     "x and y need the same number of samples (at least 2)");
  }
  if (!(sample_rate > 0.0) || !std::isfinite(sample_rate)) {
    throw InputError("sample_rate", fmt::format("{:g}", sample_rate),
                     "must be finite and > 0 [Hz]");
  }
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i])) {
      throw InputError("record", fmt::format("sample {}", i), "x and y must be finite");
    }
  }
}

}  // namespace

FullSpectrum fullSpectrum(const std::vector<double>& x, const std::vector<double>& y,
                          double sample_rate, SpectrumWindow window) {
  requireRecord(x, y, sample_rate);
  const int n = static_cast<int>(x.size());
  fftw_complex* data = fftw_alloc_complex(n);
  double gain = 0.0;
  for (int i = 0; i < n; ++i) {
    const double w = window == SpectrumWindow::kHann ? 0.5 - 0.5 * std::cos(kTwoPi * i / n) : 1.0;
    gain += w / n;
    data[i][0] = w * x[i];
    data[i][1] = w * y[i];
  }
  fftw_plan plan;
  {
    const std::lock_guard<std::mutex> lock(fftwPlannerMutex());
    plan = fftw_plan_dft_1d(n, data, data, FFTW_FORWARD, FFTW_ESTIMATE);
  }
  fftw_execute(plan);
  FullSpectrum s;
  // Bins in ascending frequency: k = −⌊N/2⌋ … ⌈N/2⌉ − 1.
  for (int j = 0; j < n; ++j) {
    const int k = j - n / 2;
    const int bin = (k + n) % n;
    s.frequency.push_back(k * sample_rate / n);
    s.coefficient.emplace_back(data[bin][0] / (n * gain), data[bin][1] / (n * gain));
  }
  {
    const std::lock_guard<std::mutex> lock(fftwPlannerMutex());
    fftw_destroy_plan(plan);
  }
  fftw_free(data);
  return s;
}

std::pair<std::complex<double>, std::complex<double>> whirlCircles(std::complex<double> X,
                                                                   std::complex<double> Y) {
  const std::complex<double> j(0.0, 1.0);
  return {(X + j * Y) / 2.0, (std::conj(X) + j * std::conj(Y)) / 2.0};
}

void fitWhirlComponents(const std::vector<double>& x, const std::vector<double>& y,
                        double sample_rate, std::vector<WhirlComponent>& components) {
  requireRecord(x, y, sample_rate);
  const std::size_t m = components.size();
  if (m == 0) return;
  for (std::size_t a = 0; a < m; ++a) {
    for (std::size_t b = a + 1; b < m; ++b) {
      if (components[a].frequency == components[b].frequency) {
        throw InputError(components[b].name, fmt::format("{:g} Hz", components[b].frequency),
                         fmt::format("duplicates the frequency of {}", components[a].name));
      }
    }
  }
  const std::size_t n = x.size();
  // Normal equations G c = r with G_ab = Σ e^{j(ω_b − ω_a)t}, r_a = Σ z e^{−jω_a t}.
  Eigen::MatrixXcd g(m, m);
  Eigen::VectorXcd r = Eigen::VectorXcd::Zero(m);
  for (std::size_t a = 0; a < m; ++a) {
    for (std::size_t b = 0; b < m; ++b) {
      // Σ_{i<n} e^{jθi}: a geometric series, n when θ is a multiple of 2π.
      const double theta =
          kTwoPi * (components[b].frequency - components[a].frequency) / sample_rate;
      const std::complex<double> step = std::polar(1.0, theta);
      g(a, b) = std::abs(1.0 - step) < 1e-14 ? std::complex<double>(static_cast<double>(n), 0.0)
                                             : (1.0 - std::polar(1.0, theta * n)) / (1.0 - step);
    }
    const double w = kTwoPi * components[a].frequency / sample_rate;
    for (std::size_t i = 0; i < n; ++i) {
      r[a] += std::complex<double>(x[i], y[i]) * std::polar(1.0, -w * static_cast<double>(i));
    }
  }
  const Eigen::FullPivLU<Eigen::MatrixXcd> lu(g);
  if (lu.rank() < static_cast<Eigen::Index>(m)) {
    throw InputError("components", fmt::format("{} frequencies", m),
                     "cannot be separated by this record (too short for their spacing)");
  }
  const Eigen::VectorXcd c = lu.solve(r);
  for (std::size_t a = 0; a < m; ++a) components[a].value = c[a];
}

WhirlExtraction extractWhirlComponents(const std::vector<double>& x, const std::vector<double>& y,
                                       double sample_rate, std::vector<WhirlComponent>& components,
                                       WhirlExtraction method) {
  requireRecord(x, y, sample_rate);
  const double n = static_cast<double>(x.size());
  const auto offBin = [&](const WhirlComponent& c) {
    const double bin = c.frequency * n / sample_rate;
    return std::abs(bin - std::round(bin)) > 1e-6 || std::abs(bin) >= n / 2.0;
  };
  const auto off = std::find_if(components.begin(), components.end(), offBin);
  if (method == WhirlExtraction::kAuto) {
    method = off == components.end() ? WhirlExtraction::kExactBins : WhirlExtraction::kLeastSquares;
  }
  if (method == WhirlExtraction::kLeastSquares) {
    fitWhirlComponents(x, y, sample_rate, components);
    return method;
  }
  if (off != components.end()) {
    throw InputError(off->name, fmt::format("{:.9g} Hz", off->frequency),
                     fmt::format("is not on a bin of this record ({} samples at {:.9g} Hz): use "
                                 "whole common periods or the least-squares fit",
                                 x.size(), sample_rate));
  }
  const FullSpectrum s = fullSpectrum(x, y, sample_rate);
  const std::size_t zero = x.size() / 2;  // index of 0 Hz in the ascending spectrum
  for (auto& c : components) {
    const long long bin = std::llround(c.frequency * n / sample_rate);
    c.value = s.coefficient[static_cast<std::size_t>(static_cast<long long>(zero) + bin)];
  }
  return method;
}

void addRelativeNoise(std::vector<double>& channel, double level, std::mt19937_64& rng) {
  if (!(level >= 0.0) || !std::isfinite(level)) {
    throw InputError("noise_level", fmt::format("{:g}", level), "must be finite and >= 0");
  }
  if (channel.empty() || level == 0.0) return;
  double mean = 0.0, variance = 0.0;
  for (double v : channel) mean += v / channel.size();
  for (double v : channel) variance += (v - mean) * (v - mean) / channel.size();
  std::normal_distribution<double> normal(0.0, level * std::sqrt(variance));
  for (double& v : channel) v += normal(rng);
}

}  // namespace geardyn
