/// FFTW transforms between the torus grid and its Fourier coefficients (detail/torus_fft.h).

#include "geardyn/torus/detail/torus_fft.h"

#include <algorithm>
#include <cmath>
#include <mutex>

#include "geardyn/signal/detail/fftw_planner.h"

namespace geardyn::detail {

TorusFft::TorusFft(std::vector<int> samples, int fields, int spectra)
    : M_(std::move(samples)), fields_(fields), spectra_(spectra) {
  const int k = static_cast<int>(M_.size());
  // FFTW's dimensions are row-major (last fastest): axis 0 is the last and the halved one.
  std::vector<int> dims(M_.rbegin(), M_.rend());
  for (int m : M_) points_ *= m;
  half_ = points_ / M_[0] * (M_[0] / 2 + 1);
  const std::lock_guard<std::mutex> lock(fftwPlannerMutex());
  // FFTW_ESTIMATE does not touch the arrays; FFTW_UNALIGNED lets solve() pass its own buffers.
  Eigen::MatrixXcd half(half_, std::max(fields, spectra));
  Eigen::MatrixXd grid(points_, std::max(fields, spectra));
  auto* c = reinterpret_cast<fftw_complex*>(half.data());
  const int h = static_cast<int>(half_), p = static_cast<int>(points_);
  to_grid_ = fftw_plan_many_dft_c2r(k, dims.data(), fields, c, nullptr, 1, h, grid.data(), nullptr,
                                    1, p, FFTW_ESTIMATE | FFTW_UNALIGNED);
  to_spectrum_ = fftw_plan_many_dft_r2c(k, dims.data(), spectra, grid.data(), nullptr, 1, p, c,
                                        nullptr, 1, h, FFTW_ESTIMATE | FFTW_UNALIGNED);
}

TorusFft::~TorusFft() {
  const std::lock_guard<std::mutex> lock(fftwPlannerMutex());
  fftw_destroy_plan(to_grid_);
  fftw_destroy_plan(to_spectrum_);
}

long long TorusFft::halfIndex(const Eigen::Ref<const Eigen::VectorXi>& n) const {
  long long index = n(0), stride = M_[0] / 2 + 1;
  for (std::size_t j = 1; j < M_.size(); ++j) {
    index += ((n(j) % M_[j] + M_[j]) % M_[j]) * stride;
    stride *= M_[j];
  }
  return index;
}

void TorusFft::toneAt(long long i, Eigen::VectorXi& n) const {
  n.resize(static_cast<int>(M_.size()));
  n(0) = static_cast<int>(i % (M_[0] / 2 + 1));
  i /= M_[0] / 2 + 1;
  for (std::size_t j = 1; j < M_.size(); ++j) {
    const int s = static_cast<int>(i % M_[j]);
    n(j) = s > M_[j] / 2 ? s - M_[j] : s;
    i /= M_[j];
  }
}

void TorusFft::toGrid(Eigen::MatrixXcd& half, Eigen::MatrixXd& grid) const {
  grid.resize(points_, fields_);
  fftw_execute_dft_c2r(to_grid_, reinterpret_cast<fftw_complex*>(half.data()), grid.data());
}

void TorusFft::toSpectrum(Eigen::MatrixXd& grid, Eigen::MatrixXcd& half) const {
  half.resize(half_, spectra_);
  fftw_execute_dft_r2c(to_spectrum_, grid.data(), reinterpret_cast<fftw_complex*>(half.data()));
  half /= static_cast<double>(points_);
}

std::vector<TorusLine> torusLines(const Eigen::MatrixXcd& half, Eigen::Index column,
                                  const TorusFft& fft, const std::vector<int>& K,
                                  const std::vector<double>& g) {
  // Lines below this fraction of the largest are not listed (round-off).
  constexpr double kLineFloor = 1e-9;
  std::vector<TorusLine> lines;
  const int k = static_cast<int>(K.size());
  Eigen::VectorXi n(k);
  // Entry i's frequency when it is a line (|n_j| <= K_j, n·g > 0 or the positive one of ±n
  // at n_0 = 0), else 0; |c|² throughout (no hypot per entry).
  const auto lineFrequency = [&](long long i) {
    fft.toneAt(i, n);
    double frequency = 0.0;
    for (int j = 0; j < k; ++j) {
      if (std::abs(n(j)) > K[j]) return 0.0;
      frequency += n(j) * g[j];
    }
    if (std::abs(frequency) <= 1e-9 * g[0] || (n(0) == 0 && frequency < 0.0)) return 0.0;
    return frequency;
  };
  double largest2 = 0.0;
  for (long long i = 0; i < fft.halfSize(); ++i) {
    const double a2 = std::norm(half(i, column));
    if (a2 > largest2 && lineFrequency(i) != 0.0) largest2 = a2;
  }
  for (long long i = 0; i < fft.halfSize(); ++i) {
    const double a2 = std::norm(half(i, column));
    if (a2 < kLineFloor * kLineFloor * largest2) continue;
    double frequency = lineFrequency(i);
    if (frequency == 0.0) continue;
    if (frequency < 0.0) n = -n, frequency = -frequency;
    lines.push_back({std::vector<int>(n.data(), n.data() + k), frequency, 2.0 * std::sqrt(a2)});
  }
  std::sort(lines.begin(), lines.end(),
            [](const TorusLine& a, const TorusLine& b) { return a.frequency < b.frequency; });
  return lines;
}

}  // namespace geardyn::detail
