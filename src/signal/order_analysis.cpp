/// Harmonic amplitudes, amplitude spectra and order tracking of real signals.

#include "geardyn/signal/order_analysis.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "geardyn/error.h"
#include "geardyn/signal/full_spectrum.h"

namespace geardyn {
namespace {
constexpr double kTwoPi = 6.283185307179586;
}

namespace {
// Least-squares fit of every column of `signals` to a₀ + Σ_j [a_j cos p_kj + b_j sin p_kj],
// p_kj = phase(k, j) [rad]: amplitudes[column][j] = √(a_j² + b_j²); false when the design is
// rank-deficient (components not resolvable in the record).
template <class Phase>
bool fitAmplitudes(const Eigen::Ref<const Eigen::MatrixXd>& signals, int m, const Phase& phase,
                   std::vector<std::vector<double>>& amplitude) {
  const Eigen::Index n = signals.rows();
  Eigen::MatrixXd A(n, 2 * m + 1);
  for (Eigen::Index k = 0; k < n; ++k) {
    A(k, 0) = 1.0;
    for (int j = 0; j < m; ++j) {
      const double p = phase(k, j);
      A(k, 1 + 2 * j) = std::cos(p);
      A(k, 2 + 2 * j) = std::sin(p);
    }
  }
  const auto qr = A.colPivHouseholderQr();
  if (qr.rank() < A.cols()) return false;
  const Eigen::MatrixXd c = qr.solve(signals);
  amplitude.assign(signals.cols(), std::vector<double>(m));
  for (Eigen::Index col = 0; col < signals.cols(); ++col)
    for (int j = 0; j < m; ++j)
      amplitude[col][j] = std::hypot(c(1 + 2 * j, col), c(2 + 2 * j, col));
  return true;
}
}  // namespace

std::vector<std::vector<double>> harmonicAmplitudesPerColumn(
    const Eigen::Ref<const Eigen::MatrixXd>& signals, double sample_rate,
    const std::vector<double>& frequencies) {
  const Eigen::Index n = signals.rows();
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
  std::vector<std::vector<double>> amplitude;
  const auto phase = [&](Eigen::Index k, int j) {
    return kTwoPi * frequencies[j] * (static_cast<double>(k) / sample_rate);
  };
  if (!fitAmplitudes(signals, m, phase, amplitude)) {
    throw InputError("frequencies", "", "distinct frequencies resolvable in the record");
  }
  return amplitude;
}

std::vector<double> harmonicAmplitudes(const Eigen::Ref<const Eigen::VectorXd>& x,
                                       double sample_rate, const std::vector<double>& frequencies) {
  return harmonicAmplitudesPerColumn(x, sample_rate, frequencies).front();
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

std::vector<OrderTrack> trackOrdersPerColumn(const Eigen::Ref<const Eigen::MatrixXd>& signals,
                                             double sample_rate, const std::vector<double>& speed,
                                             const std::vector<double>& orders, int window) {
  if (static_cast<Eigen::Index>(speed.size()) != signals.rows())
    throw InputError("speed", std::to_string(speed.size()), "one speed per sample");
  if (window < 8) throw InputError("window", std::to_string(window), "at least 8 samples");
  std::vector<OrderTrack> tracks(signals.cols());
  for (auto& track : tracks) track.amplitude.resize(orders.size());
  for (Eigen::Index start = 0; start + window <= signals.rows(); start += window) {
    double mean = 0.0;
    for (int k = 0; k < window; ++k) mean += speed[start + k];
    mean /= window;
    std::vector<double> freqs;
    for (double o : orders) freqs.push_back(o * std::abs(mean) / kTwoPi);
    bool usable = true;
    for (std::size_t i = 0; i < freqs.size(); ++i) {
      if (!(freqs[i] > 0.0 && freqs[i] < sample_rate / 2)) usable = false;
      for (std::size_t j = 0; j < i; ++j) usable = usable && freqs[i] != freqs[j];
    }
    // One design per window, solved for every signal.
    const auto a =
        usable ? harmonicAmplitudesPerColumn(signals.middleRows(start, window), sample_rate, freqs)
               : std::vector<std::vector<double>>(signals.cols(),
                                                  std::vector<double>(orders.size(), std::nan("")));
    for (Eigen::Index c = 0; c < signals.cols(); ++c) {
      tracks[c].time.push_back((start + 0.5 * window) / sample_rate);
      tracks[c].speed.push_back(mean);
      for (std::size_t o = 0; o < orders.size(); ++o) tracks[c].amplitude[o].push_back(a[c][o]);
    }
  }
  return tracks;
}

OrderTrack trackOrders(const Eigen::Ref<const Eigen::VectorXd>& x, double sample_rate,
                       const std::vector<double>& speed, const std::vector<double>& orders,
                       int window) {
  return trackOrdersPerColumn(x, sample_rate, speed, orders, window).front();
}

std::vector<OrderTrack> trackOrdersByAngle(const Eigen::Ref<const Eigen::MatrixXd>& signals,
                                           double sample_rate,
                                           const Eigen::Ref<const Eigen::VectorXd>& angle,
                                           const std::vector<double>& speed,
                                           const std::vector<double>& orders, int window,
                                           double period_angle) {
  if (angle.size() != signals.rows() || static_cast<Eigen::Index>(speed.size()) != signals.rows())
    throw InputError("angle", std::to_string(angle.size()), "one angle and speed per sample");
  if (window < 8) throw InputError("window", std::to_string(window), "at least 8 samples");
  const int m = static_cast<int>(orders.size());
  std::vector<double> sorted{0.0};
  for (double o : orders) sorted.push_back(std::abs(o));
  std::sort(sorted.begin(), sorted.end());
  double spacing = HUGE_VAL;
  for (std::size_t i = 1; i < sorted.size(); ++i) {
    if (sorted[i] - sorted[i - 1] > 1e-9 * sorted[i])
      spacing = std::min(spacing, sorted[i] - sorted[i - 1]);
  }
  // (Plus one period when windows are cut to whole periods, so that the cut one still does.)
  const double resolving_angle =
      std::isfinite(spacing) ? kTwoPi / spacing + std::max(period_angle, 0.0) : 0.0;
  std::vector<OrderTrack> tracks(signals.cols());
  for (auto& track : tracks) track.amplitude.resize(orders.size());
  std::vector<std::vector<double>> a;
  for (Eigen::Index start = 0; start + window <= signals.rows();) {
    // Long enough to resolve the orders: the window grows until θ has turned by 2π over the
    // smallest spacing of the orders (and of the lowest order from 0, the mean).
    Eigen::Index stop = start + window;  // exclusive
    while (stop < signals.rows() && angle(stop - 1) - angle(start) < resolving_angle) ++stop;
    if (angle(stop - 1) - angle(start) < resolving_angle) break;  // the record's end
    Eigen::Index length = stop - start;
    if (period_angle > 0.0) {
      // Whole periods of the angle within the window: the samples up to the one nearest the
      // last whole period's end (exclusive).
      const double span = angle(stop - 1) - angle(start);
      const double periods = std::floor(span / period_angle);
      if (periods >= 1.0) {
        const double target = angle(start) + periods * period_angle;
        Eigen::Index end = stop - 1;
        while (end > start && angle(end - 1) >= target) --end;
        if (end - 1 > start && target - angle(end - 1) < angle(end) - target) --end;
        length = end - start;
      }
    }
    double mean = 0.0;
    for (Eigen::Index k = 0; k < length; ++k) mean += speed[start + k];
    mean /= static_cast<double>(length);
    // Phases from the window's first angle: cos and sin of small arguments, whatever the run.
    const double origin = angle(start);
    const auto phase = [&](Eigen::Index k, int j) {
      return orders[j] * (angle(start + k) - origin);
    };
    if (length < 2 * m + 1 || !fitAmplitudes(signals.middleRows(start, length), m, phase, a)) {
      a.assign(signals.cols(), std::vector<double>(orders.size(), std::nan("")));
    }
    for (Eigen::Index c = 0; c < signals.cols(); ++c) {
      tracks[c].time.push_back((static_cast<double>(start) + 0.5 * static_cast<double>(length)) /
                               sample_rate);
      tracks[c].speed.push_back(mean);
      for (std::size_t o = 0; o < orders.size(); ++o) tracks[c].amplitude[o].push_back(a[c][o]);
    }
    start += length;
  }
  return tracks;
}

}  // namespace geardyn
