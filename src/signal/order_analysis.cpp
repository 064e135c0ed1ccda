/// Harmonic amplitudes, amplitude spectra and order tracking of real signals.

#include "geardyn/signal/order_analysis.h"

#include <fmt/format.h>

#include <cmath>

#include "geardyn/error.h"
#include "geardyn/signal/full_spectrum.h"

namespace geardyn {
namespace {
constexpr double kTwoPi = 6.283185307179586;
}

std::vector<double> harmonicAmplitudes(const Eigen::Ref<const Eigen::VectorXd>& x,
                                       double sample_rate, const std::vector<double>& frequencies) {
  const Eigen::Index n = x.size();
  const int m = static_cast<int>(frequencies.size());
  for (double f : frequencies) {
    if (!(f > 0.0) || !(f < sample_rate / 2))
      throw InputError("frequencies", fmt::format("{:g} Hz", f),
                       fmt::format("frequencies in (0, {:g}) Hz", sample_rate / 2));
  }
  if (n < 2 * m + 1) {
    throw InputError("signal", fmt::format("{} samples", n),
                     fmt::format("at least {} samples for {} frequencies", 2 * m + 1, m));
  }
  Eigen::MatrixXd A(n, 2 * m + 1);
  for (Eigen::Index k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) / sample_rate;
    A(k, 0) = 1.0;
    for (int j = 0; j < m; ++j) {
      A(k, 1 + 2 * j) = std::cos(kTwoPi * frequencies[j] * t);
      A(k, 2 + 2 * j) = std::sin(kTwoPi * frequencies[j] * t);
    }
  }
  const auto qr = A.colPivHouseholderQr();
  if (qr.rank() < A.cols()) {
    throw InputError("frequencies", "", "distinct frequencies resolvable in the record");
  }
  const Eigen::VectorXd c = qr.solve(x);
  std::vector<double> amplitude(m);
  for (int j = 0; j < m; ++j) amplitude[j] = std::hypot(c(1 + 2 * j), c(2 + 2 * j));
  return amplitude;
}

AmplitudeSpectrum amplitudeSpectrum(const Eigen::Ref<const Eigen::VectorXd>& x,
                                    double sample_rate) {
  const std::vector<double> re(x.data(), x.data() + x.size()), im(x.size(), 0.0);
  const FullSpectrum full = fullSpectrum(re, im, sample_rate);
  AmplitudeSpectrum s;
  const std::size_t n = full.frequency.size();
  for (std::size_t k = 0; k < n; ++k) {
    if (full.frequency[k] < 0.0) continue;
    s.frequency.push_back(full.frequency[k]);
    s.amplitude.push_back((full.frequency[k] == 0.0 ? 1.0 : 2.0) * std::abs(full.coefficient[k]));
  }
  return s;
}

OrderTrack trackOrders(const Eigen::Ref<const Eigen::VectorXd>& x, double sample_rate,
                       const std::vector<double>& speed, const std::vector<double>& orders,
                       int window) {
  if (static_cast<Eigen::Index>(speed.size()) != x.size())
    throw InputError("speed", std::to_string(speed.size()), "one speed per sample");
  if (window < 8) throw InputError("window", std::to_string(window), "at least 8 samples");
  OrderTrack track;
  track.amplitude.resize(orders.size());
  for (Eigen::Index start = 0; start + window <= x.size(); start += window) {
    double mean = 0.0;
    for (int k = 0; k < window; ++k) mean += speed[start + k];
    mean /= window;
    track.time.push_back((start + 0.5 * window) / sample_rate);
    track.speed.push_back(mean);
    std::vector<double> freqs;
    for (double o : orders) freqs.push_back(o * std::abs(mean) / kTwoPi);
    bool usable = true;
    for (std::size_t i = 0; i < freqs.size(); ++i) {
      if (!(freqs[i] > 0.0 && freqs[i] < sample_rate / 2)) usable = false;
      for (std::size_t j = 0; j < i; ++j) usable = usable && freqs[i] != freqs[j];
    }
    const std::vector<double> a =
        usable ? harmonicAmplitudes(x.segment(start, window), sample_rate, freqs)
               : std::vector<double>(orders.size(), std::nan(""));
    for (std::size_t o = 0; o < orders.size(); ++o) track.amplitude[o].push_back(a[o]);
  }
  return track;
}

}  // namespace geardyn
