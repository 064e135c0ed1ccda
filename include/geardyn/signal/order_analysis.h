#pragma once
/// \file
/// Amplitudes of real vibration signals at known frequencies (mesh orders), their one-sided
/// amplitude spectrum (the DFT amplitude plots of Visnadi 2021 Figs. 3–7), and order tracking
/// along a run-up (amplitude of an order in consecutive windows: the cascade / waterfall).

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace geardyn {

/// Least-squares fit of x(t_k) = a₀ + Σ_j [a_j cos 2πf_j t_k + b_j sin 2πf_j t_k], t_k = k/f_s:
/// the 0-peak amplitudes √(a_j² + b_j²) [unit of x]; exact for whole periods and free of leakage
/// otherwise. Frequencies must be distinct, > 0 and below f_s/2 (InputError otherwise).
std::vector<double> harmonicAmplitudes(const Eigen::Ref<const Eigen::VectorXd>& x,
                                       double sample_rate, const std::vector<double>& frequencies);
/// The same for every column of `signals` (samples × channels), with the least-squares design
/// factorised once: amplitudes[column][frequency].
std::vector<std::vector<double>> harmonicAmplitudesPerColumn(
    const Eigen::Ref<const Eigen::MatrixXd>& signals, double sample_rate,
    const std::vector<double>& frequencies);

/// One-sided amplitude spectrum: amplitude[0] = |mean|, amplitude[k] = 2|X_k|/N (0-peak of a
/// sinusoid on a bin), frequencies k f_s/N up to f_s/2 (FFTW).
struct AmplitudeSpectrum {
  std::vector<double> frequency;  ///< [Hz]
  std::vector<double> amplitude;  ///< 0-peak [unit of x]
};
AmplitudeSpectrum amplitudeSpectrum(const Eigen::Ref<const Eigen::VectorXd>& x, double sample_rate);

/// Order tracking: the signal cut into consecutive windows of `window` samples; in each, the
/// mean speed and the least-squares amplitude of each order at order × mean speed / 2π.
struct OrderTrack {
  std::vector<double> time;                    ///< window centres [s]
  std::vector<double> speed;                   ///< mean reference speed [rad/s]
  std::vector<std::vector<double>> amplitude;  ///< amplitude[o][w] of order o in window w
};
OrderTrack trackOrders(const Eigen::Ref<const Eigen::VectorXd>& x, double sample_rate,
                       const std::vector<double>& speed, const std::vector<double>& orders,
                       int window);
/// The same for every column of `signals` (one design per window for all of them).
std::vector<OrderTrack> trackOrdersPerColumn(const Eigen::Ref<const Eigen::MatrixXd>& signals,
                                             double sample_rate, const std::vector<double>& speed,
                                             const std::vector<double>& orders, int window);
/// Order tracking against the reference shaft's rotation θ_k [rad] (computed order tracking):
/// in each window the least-squares fit x_k = a₀ + Σ_o [a_o cos o θ_k + b_o sin o θ_k], exact in
/// phase however the speed changes inside the window (the fixed-frequency fit of
/// trackOrdersPerColumn drifts by o Δω t²/2 there). `speed` [rad/s] gives each window's mean
/// speed; `time` is the window centre, counting samples from 0 at `sample_rate`. A window is
/// `window` samples, longer where θ turns by less than 2π / (the smallest spacing of the orders
/// and of the lowest order from 0) in them (slow speeds: the orders could not be told apart);
/// a last window that cannot reach that is dropped. With
/// `period_angle` > 0 [rad] each window of at most `window` samples is cut to a whole number of
/// those periods of θ (a gear train's common period): every harmonic of it, tracked or not, is
/// then orthogonal to the tracked ones and does not leak into them (an uncut window leaks a few
/// % of the parametric harmonics into the mesh orders); windows shorter than one period stay
/// uncut. Windows where the orders cannot be resolved (too little rotation, equal orders) hold
/// NaN.
std::vector<OrderTrack> trackOrdersByAngle(const Eigen::Ref<const Eigen::MatrixXd>& signals,
                                           double sample_rate,
                                           const Eigen::Ref<const Eigen::VectorXd>& angle,
                                           const std::vector<double>& speed,
                                           const std::vector<double>& orders, int window,
                                           double period_angle = 0.0);

}  // namespace geardyn
