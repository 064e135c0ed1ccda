#pragma once
/// \file
/// Real fields on the k-dimensional grid of a torus, θ_j = 2π s / M_j, to and from their
/// Fourier coefficients c_n (u(θ) = Σ_n c_n e^{i n·θ}) with FFTW's multi-dimensional real
/// transforms, planned once (under detail::fftwPlannerMutex) for a fixed number of fields and
/// executed on new arrays (thread-safe). Axis 0 is the fastest index of a grid point and the
/// halved axis of the spectra: a spectrum holds n_0 = 0..M_0/2 and every n_j mod M_j. Internal.

#include <fftw3.h>

#include <Eigen/Dense>
#include <complex>
#include <vector>

#include "geardyn/torus/train_torus.h"

namespace geardyn::detail {

class TorusFft {
 public:
  /// `fields` fields to the grid per call, `spectra` fields from it.
  TorusFft(std::vector<int> samples, int fields, int spectra);
  ~TorusFft();
  TorusFft(const TorusFft&) = delete;
  TorusFft& operator=(const TorusFft&) = delete;

  const std::vector<int>& samples() const noexcept { return M_; }
  long long points() const noexcept { return points_; }
  long long halfSize() const noexcept { return half_; }
  /// Position of tone n (n_0 >= 0, |n_0| < M_0/2, |n_j| < M_j/2) in one field's spectrum.
  long long halfIndex(const Eigen::Ref<const Eigen::VectorXi>& n) const;
  /// The tone at position i of a spectrum (n_j in (−M_j/2, M_j/2]).
  void toneAt(long long i, Eigen::VectorXi& n) const;
  /// grid (points × fields) = Σ_n c_n e^{i n·θ} from `half` (halfSize × fields; destroyed).
  void toGrid(Eigen::MatrixXcd& half, Eigen::MatrixXd& grid) const;
  /// half (halfSize × spectra) = c_n of `grid` (points × spectra; destroyed), divided by the
  /// number of points.
  void toSpectrum(Eigen::MatrixXd& grid, Eigen::MatrixXcd& half) const;

 private:
  std::vector<int> M_;
  long long points_ = 1, half_ = 1;
  int fields_ = 0, spectra_ = 0;
  fftw_plan to_grid_ = nullptr, to_spectrum_ = nullptr;
};

/// The lines of one field's spectrum (column of `half`, from toSpectrum) at positive
/// frequencies, tones |n_j| <= K_j (g_j [Hz]): n or −n of every entry of the half spectrum (at
/// n_0 = 0 both are in it); above 1e-9 of the largest, ascending frequency, amplitude 2|c_n|.
std::vector<TorusLine> torusLines(const Eigen::MatrixXcd& half, Eigen::Index column,
                                  const TorusFft& fft, const std::vector<int>& K,
                                  const std::vector<double>& g);

}  // namespace geardyn::detail
