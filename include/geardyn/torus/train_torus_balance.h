#pragma once
/// \file
/// Nonlinear steady state of a gear train on the torus of its mesh phases: multi-dimensional
/// harmonic balance (Kim & Noah 1996; Guskov, Sinou & Thouverez 2008) of the trains of
/// train_harmonic_balance.h — contact loss and backlash at the meshes, tooth pairs, bearings
/// with radial clearance — when the mesh frequencies have no short common period
/// (docs/theory/torus_harmonic_balance.md, "Nonlinear steady state on the torus").
///
/// The nonlinear coordinates w = Wᵀq (mesh deflections, then (u_y, u_z) of every clearance
/// bearing; W = GearTrainModel::nonlinearVectors) are functions on the k-torus of the generator
/// phases (train_torus.h), w(θ) = w₀ + Σ_{n∈T⁺} 2 Re(w_n e^{i n·θ}) over the positive half T⁺
/// of the tone box |n_j| <= N_j. With K̄ holding the mean meshes and the linear bearings,
/// eliminating every other DOF per tone exactly (D(ω_n) X_n = F₀δ_{n0} + W(d_n − F̃_n)) leaves
///
///   R_n(w, ω) = w_n − B(ω_n) (d_n − F̃_n(w)) − b₀ δ_{n0} = 0,   B(ω) = Wᵀ D(ω)⁻¹ W,
///
/// ω_n = n·(2π g) the tone's angular frequency, d_n the mesh dashpots' forcing c ė, F̃ the
/// nonlinear forces less their linear part (k g(δ − e) − k̄δ; f(u) − k u), evaluated by AFT on
/// the k-dimensional grid of generator phases (FFTW plans made once, detail/torus_fft.h). The
/// Jacobian is analytic: ∂F̃_n/∂w_{n'} is the grid spectrum of the slopes at n − n' and n + n'
/// (the multi-dimensional Toeplitz + Hankel form of the 1-D AFT Jacobian), which the grid
/// resolves without aliasing (M_j > 4 N_j). The continuation parameter ω is the first
/// generator's angular frequency 2π g₁ [rad/s]; every generator moves with it (g_j ∝ |Ω|), and
/// so does every tone.
///
/// Stability: a quasi-periodic solution has no monodromy matrix. It is checked by a Newmark
/// run of the nonlinear train started on the solution (torusNewmarkCheck): stable when the
/// run stays on the torus solution over a long window. classify() leaves the point unclassified
/// (max_floquet_real = NaN).

#include <Eigen/Dense>
#include <complex>
#include <memory>
#include <utility>
#include <vector>

#include "geardyn/solvers/continuation.h"
#include "geardyn/system/bearing_law.h"
#include "geardyn/system/gear_train_model.h"
#include "geardyn/system/train_tooth_pairs.h"
#include "geardyn/torus/train_torus.h"

namespace geardyn {
namespace detail {
class HarmonicBlocks;
class ToneBlockDerivative;
}  // namespace detail

struct TrainTorusBalanceOptions {
  int mesh_harmonics = 5;     ///< L: harmonics of each mesh frequency (N_j = L max P_m) [-]
  int group_harmonics = 100;  ///< as TrainTorusOptions::group_harmonics [-]
  /// Grid points per highest harmonic of each generator (M_j = this × N_j, at least 16;
  /// more than 4 so that the Jacobian's n ± n' are resolved) [-].
  int samples_per_harmonic = 8;
  double tolerance = 1e-10;  ///< ‖R‖ / (‖w‖ + ‖b₀‖)
  int max_iterations = 40;
  int sparse_dofs = 64;  ///< as TrainSteadyOptions::sparse_dofs
  void validate() const;
};

class TrainTorusBalance final : public ContinuationProblem {
 public:
  TrainTorusBalance(const GearTrainModel& model, const TrainTorusBalanceOptions& options);
  ~TrainTorusBalance() override;
  TrainTorusBalance(const TrainTorusBalance&) = delete;
  TrainTorusBalance& operator=(const TrainTorusBalance&) = delete;

  int size() const override { return r_ * n_; }
  int coordinateCount() const noexcept { return r_; }
  int meshCount() const noexcept { return meshes_; }
  /// Tones of T⁺ with the zero tone first (k × (P + 1)).
  const Eigen::MatrixXi& tones() const noexcept { return tones_; }
  const TrainTorusGenerators& generators() const noexcept { return generators_; }
  const std::vector<int>& gridSamples() const noexcept { return samples_; }
  /// ω = 2π g₁ [rad/s] at input speed Ω [rad/s], and back (Ω takes the model's sign).
  double baseFrequency(double input_speed) const;
  double inputSpeed(double omega) const;
  /// Angular frequency of tone p of tones() at ω [rad/s].
  double toneFrequency(int p, double omega) const { return omega * tone_ratio_(p); }

  void residual(const Eigen::VectorXd& u, double omega, Eigen::VectorXd& r, Eigen::MatrixXd* dr_du,
                Eigen::VectorXd* dr_domega) override;
  double residualNorm(const Eigen::VectorXd& u, const Eigen::VectorXd& r,
                      double omega) const override;
  /// The linear time-varying solution (contacts closed, bearings linear), then each clearance
  /// bearing's mean displacement moved onto the bearing surface (as TrainHarmonicBalance).
  Eigen::VectorXd startingGuess(double omega) override;
  void solve(HarmonicBalancePoint& point) override;
  /// Unclassified (quasi-periodic: no monodromy matrix): max_floquet_real = NaN, stable kept.
  void classify(HarmonicBalancePoint& point, StabilityMethod method, bool samples_current) override;
  bool frequencyChangeIsCostly() const override { return true; }

  /// The complex harmonics w_p of coordinate c (p = 0..P over tones()) of a solution [m].
  Eigen::VectorXcd coordinateHarmonics(const Eigen::VectorXd& u, int c) const;
  /// The nonlinear coordinates along the trajectory θ_j = 2π g_j t + θ_j0 at the times [s]
  /// (rows: times, cols: coordinates) [m].
  Eigen::MatrixXd coordinatesAt(const Eigen::VectorXd& u, double omega,
                                const Eigen::VectorXd& times) const;
  /// Every DOF's harmonics X_p (n_dofs × (P + 1)) of a solution, q(t) = Σ 2 Re(X_p e^{iω_p t})
  /// (the zero tone once) [m, rad].
  Eigen::MatrixXcd displacementHarmonics(const HarmonicBalancePoint& point);
  /// (q, q̇) at t = 0 [m, rad; m/s, rad/s]: where a Newmark check starts.
  std::pair<Eigen::VectorXd, Eigen::VectorXd> initialState(const HarmonicBalancePoint& point);
  /// The nonlinear coordinates on the grid (rows: grid points, axis 0 fastest) [m].
  Eigen::MatrixXd gridCoordinates(const Eigen::VectorXd& u);
  /// Mesh contact forces k g(δ − e) (tooth pairs: Σ k_j max(0, y − g_j)) on the grid (rows:
  /// grid points, axis 0 fastest; cols: meshes) [N].
  Eigen::MatrixXd gridMeshForces(const Eigen::VectorXd& u);
  /// Their spectrum: lines of every mesh force at the tones |n_j| <= 2 N_j (train_torus.h's
  /// TorusLine; amplitudes above 1e-9 of the largest, ascending frequency) at ω.
  std::vector<std::vector<TorusLine>> meshForceLines(const Eigen::VectorXd& u, double omega);

 private:
  void prepare(double omega);                 // B, dB, b₀ at ω (cached)
  void gridForces(const Eigen::VectorXd& u);  // F̃ and slopes on the grid, then spectra
  std::complex<double> spectrumAt(int column, long long code) const;  // ±index (conj)
  // Mesh m's contact force at sample i of its axis for the tooth deformation y [N], dF/dy.
  double meshForceAt(int m, int i, double y, double* slope) const;
  void setUpBearings();      // laws_, the coordinate and slope columns of every bearing
  void gridBearingForces();  // f̃ and its w × w slope of every bearing on the grid
  // The coordinates coordinate a acts on through the slopes (a itself for a mesh, its
  // bearing's w): the first and the count.
  void coupledCoordinates(int a, int* first, int* count) const;
  // The slope column of ∂F̃_b/∂w_a (b and a coordinates of one bearing, or a == b a mesh).
  int slopeColumn(int b, int a) const;

  const GearTrainModel& model_;
  TrainTorusBalanceOptions options_;
  TrainTorusGenerators generators_;
  int k_ = 0, P_ = 0, n_ = 0, r_ = 0, meshes_ = 0, bearings_ = 0, dofs_ = 0, slopes_ = 0;
  double speed_sign_ = 1.0;
  Eigen::MatrixXi tones_;                                // k × (P + 1)
  Eigen::VectorXd tone_ratio_;                           // ω_p / ω
  std::vector<int> samples_;                             // M_j
  std::vector<long long> tone_index_, tone_conj_index_;  // half index of n_p and of −n_p
  // Half index codes (+(i + 1): c_i, −(i + 1): conj c_i) of n_p − n_q and n_p + n_q.
  std::vector<long long> diff_code_, sum_code_;
  std::vector<long long> axis_stride_;
  std::vector<Eigen::VectorXd> k_axis_, e_axis_;  // per mesh, along its generator's axis
  std::vector<ToothPairTable> tooth_pairs_;
  // Per clearance bearing: its law over (u_y, u_z), or over the five (u_y, u_z, u_x, θ_y, θ_z)
  // of a rolling bearing's full law with full DOFs (bearing_law.h).
  std::vector<TrainBearingLaw> laws_;
  // Per bearing: its first coordinate and the first of its w² slope columns (column-major,
  // offsets from r_); per coordinate: its bearing (−1 for a mesh).
  std::vector<int> bearing_first_, slope_first_, bearing_of_;
  Eigen::MatrixXcd dash_unit_;  // d_p / ω per coordinate (rows) and tone (cols) [m/s / ...]
  Eigen::MatrixXd W_, rigid_;
  std::unique_ptr<detail::TorusFft> fft_;
  // AFT work arrays (sized once).
  Eigen::MatrixXcd half_in_, half_out_;
  Eigen::MatrixXd grid_, grid_out_;
  bool linearized_ = false;
  // Condensation at the cached ω.
  double cached_omega_ = -1.0;
  Eigen::MatrixXd Kbar_, C_;
  std::unique_ptr<detail::HarmonicBlocks> blocks_;           // the latest tone's factors only
  std::unique_ptr<detail::ToneBlockDerivative> derivative_;  // dD/dω, sparse
  std::vector<Eigen::MatrixXcd> B_, dB_;
  Eigen::VectorXd b0_, db0_;
};

/// A Newmark run of the nonlinear train (train_nonlinear_time.h) started on a torus solution
/// at t = 0 over `window` [s], compared with the torus solution along the same trajectory.
struct TorusNewmarkCheck {
  /// max |w_newmark − w_torus| over the last half of the window, per coordinate, relative to the
  /// coordinate's p2p on the torus solution [-].
  std::vector<double> deviation;
  std::vector<double> p2p_newmark, p2p_torus;  ///< over the last half of the window [m]
  /// The deviation did not grow: largest over the last quarter <= 2 × the largest over the
  /// second quarter, and below `tolerance` (a perturbation of an unstable solution grows).
  bool stable = false;
  std::string status;  ///< "completed" or the Newmark failure
};
TorusNewmarkCheck torusNewmarkCheck(const GearTrainModel& model, TrainTorusBalance& balance,
                                    const HarmonicBalancePoint& point, double window,
                                    int steps_per_mesh_period = 256, double tolerance = 0.05);

}  // namespace geardyn
