#pragma once
/// \file
/// Steady state of a linear time-varying gear train on the torus of its mesh phases
/// (multi-frequency harmonic balance; docs/theory/torus_harmonic_balance.md).
///
/// The meshes are grouped so that the mesh frequencies of a group share a base g_j with a
/// short common period (f_m = P_m g_{j(m)}, P_m integer); the k groups' bases are the
/// generators. The response is written as a function of the generator phases,
/// q(t) = u(θ₁, …, θ_k) at θ_j = 2π g_j t, u(θ) = Σ_{n∈T} X_n e^{i n·θ}, with
/// d/dt = Σ_j 2π g_j ∂/∂θ_j (Kim & Noah 1996, eq. 9; Guskov, Sinou & Thouverez 2008, eq. 4).
/// Mesh m's stiffness depends on θ_{j(m)} only, k_m = Σ_l k̂_{m,l} e^{i l P_m θ_{j(m)}}, so
///
///   D(n·ω) X_n + Σ_m v_m Σ_{l≠0} k̂_{m,l} δ_{m, n − l P_m e_{j(m)}} = F_n,   δ_{m,n} = v_mᵀ X_n,
///
/// D(ω) = K̄ + iω(C + ΩG₁) − ω²M as in train_response.h. It is condensed exactly onto the mesh
/// deflections (r |T| unknowns, sparse: a tone couples only along its meshes' own generator),
/// solved by GMRES preconditioned with the exact solve of every mesh group's line of tones
/// (a direct sparse LU when GMRES stalls). With one generator the tone set is that of the
/// common-period balance and the two solvers solve the same equations. The index set T is the
/// box |n_j| <= N_j = L max_{m∈j} P_m (default) or the diamond Σ_j |n_j| / N_j <= 1.

#include <Eigen/Dense>
#include <complex>
#include <memory>
#include <string>
#include <vector>

#include "geardyn/system/gear_train_model.h"

namespace geardyn {
namespace detail {
class TorusFft;
struct TorusWorkspace;
}  // namespace detail

enum class TorusTruncation { kBox, kDiamond, kProduct };

struct TrainTorusOptions {
  int mesh_harmonics = 10;  ///< L: harmonics of each mesh frequency kept (>= 1)
  /// L_m per mesh (empty: L for every mesh; else each in [1, L], L their largest): generator
  /// j keeps N_j = max_{m∈j} L_m P_m harmonics (train_truncation.h derives them).
  std::vector<int> per_mesh_harmonics;
  /// The most base harmonics (L × the largest multiple P_m of the group's base) a group of
  /// meshes sharing one generator may need; a mesh that would exceed it starts a new generator.
  int group_harmonics = 100;
  TorusTruncation truncation = TorusTruncation::kBox;
  /// kProduct: per mesh, the estimated relative force orders a_m(l), l = 1, 2, ...
  /// (MeshHarmonicsEstimate::envelope). Generator j's weight at harmonic n is the largest
  /// a_m(⌈n / P_m⌉) over its meshes made non-increasing in n (a_j(0) = 1, never below the
  /// floor: every pure harmonic of the box is kept); tone n is kept when
  /// Π_j a_j(|n_j|) >= product_floor (docs/theory/torus_harmonic_balance.md, "The index set").
  std::vector<std::vector<double>> mesh_order_weights;
  double product_floor = 1e-2;  ///< [-]
  /// Grid points per generator period for the mesh forces' peaks and spectra; 0: derived,
  /// max(4 N_j + 2, 80 × the group's largest P_m, 32) rounded up to a 2^a 3^b 5^c size, the
  /// grid capped at 2^20 points.
  int samples = 0;
  int sparse_dofs = 64;      ///< as TrainSteadyOptions::sparse_dofs
  double tolerance = 1e-13;  ///< GMRES: ‖b − A x‖ <= tolerance ‖b‖ on the condensed system
  /// B_n = Vᵀ D(n·ω)⁻¹ V of every tone from one modal decomposition of the train per speed
  /// (detail/modal_compliance.h) when the train has fewer than sparse_dofs DOFs and the
  /// decomposition holds; false: D factorised per tone pair (the reference it is checked with).
  bool modal_compliance = true;
  /// A thread keeps its line preconditioner over its next speeds (within 5 % of the one it was
  /// factorised at) while their GMRES solves take at most this many iterations more than that
  /// speed's; −1: factorised at every speed. Any preconditioner gives the same δ.
  int preconditioner_reuse_iterations = 2;
  void validate() const;
};

/// The generators of a train's mesh frequencies: groups of meshes with a short common period.
struct TrainTorusGenerators {
  std::vector<double> ratio;        ///< g_j / |Ω| [Hz per rad/s]
  std::vector<int> mesh_generator;  ///< j(m)
  std::vector<int> mesh_multiple;   ///< P_m: f_m = P_m g_{j(m)}
  std::vector<int> harmonics;       ///< N_j = L max_{m∈j} P_m
};
TrainTorusGenerators trainTorusGenerators(const GearTrainModel& model, int mesh_harmonics,
                                          int group_harmonics);
/// The same with L_m per mesh: a group keeps max L_m P_m within group_harmonics.
TrainTorusGenerators trainTorusGenerators(const GearTrainModel& model,
                                          const std::vector<int>& mesh_harmonics,
                                          int group_harmonics);

/// One spectral line of a mesh force: the tone n (the frequency n·g) and its amplitude.
struct TorusLine {
  std::vector<int> tone;
  double frequency = 0.0;  ///< n·g [Hz] (> 0)
  double amplitude = 0.0;  ///< 2 |c_n| [N]
};

struct TrainTorusState {
  double input_speed = 0.0;                 ///< Ω [rad/s]
  std::vector<double> generator_frequency;  ///< g_j [Hz]
  std::vector<int> mesh_generator, mesh_multiple;
  Eigen::MatrixXi tones;           ///< k × |T|: n of every tone (symmetric set)
  Eigen::VectorXd tone_frequency;  ///< n·g [Hz]
  /// X_n (column per tone); q(t) = Σ_n X_n e^{i 2π n·g t} (real: X_{−n} = conj X_n).
  Eigen::MatrixXcd harmonic;
  /// Over the torus grid (every phase relation of the generators; the actual trajectory is a
  /// line on it): mean, largest and smallest elastic mesh force k(φ)(vᵀq − e) [N].
  std::vector<double> mesh_force_mean, mesh_force_max, mesh_force_min;
  std::vector<double> dynamic_factor;  ///< max |F| / |mean F| per mesh [-]
  /// Amplitude of the mesh force at orders 1..L of each mesh's own frequency [N].
  std::vector<std::vector<double>> mesh_force_harmonics;
  /// Per mesh: its force's lines above 1e-9 of its largest, ascending frequency.
  std::vector<std::vector<TorusLine>> mesh_force_lines;
  std::vector<double> element_dynamic_force;  ///< as TrainSteadyState [N, N m]
  int iterations = 0;                         ///< GMRES iterations (0: direct)
  double residual = 0.0;      ///< ‖b − A δ‖ / ‖b‖ of the condensed system
  std::string linear_solver;  ///< "gmres" or "direct"
  /// q(t) at the times (rows: times, cols: DOFs).
  Eigen::MatrixXd displacement(const Eigen::VectorXd& times) const;
};

/// The buffers of TrainTorusSolver::solve on one thread, reused from speed to speed (no
/// allocation after the first speed but the returned state), and that thread's latest solutions:
/// the condensed system's GMRES starts from their extrapolation to the next speed (a sweep in
/// speed order on one thread; any order is correct, only slower).
class TrainTorusWorkspace {
 public:
  TrainTorusWorkspace();
  ~TrainTorusWorkspace();
  TrainTorusWorkspace(TrainTorusWorkspace&&) noexcept;
  TrainTorusWorkspace& operator=(TrainTorusWorkspace&&) noexcept;

 private:
  friend class TrainTorusSolver;
  std::unique_ptr<detail::TorusWorkspace> impl_;
};

/// The torus solver of one model: generators, tone set and the meshes' Fourier coefficients
/// once; per speed one factorisation of D(n·ω) per tone pair ±n and the condensed solve.
/// Thread-safe for concurrent solve() calls.
class TrainTorusSolver {
 public:
  TrainTorusSolver(const GearTrainModel& model, const TrainTorusOptions& options = {});
  ~TrainTorusSolver();
  TrainTorusSolver(const TrainTorusSolver&) = delete;
  TrainTorusSolver& operator=(const TrainTorusSolver&) = delete;
  TrainTorusState solve(double input_speed) const;
  /// The same with the buffers and the previous solutions of `workspace` (one per thread).
  TrainTorusState solve(double input_speed, TrainTorusWorkspace& workspace) const;
  const TrainTorusGenerators& generators() const noexcept { return generators_; }
  int toneCount() const noexcept { return static_cast<int>(tones_.cols()); }

 private:
  /// B_n of every tone and the right-hand side into the workspace (ws.B, ws.rhs): from the
  /// train's modal decomposition when it holds, else one factorisation of D per tone pair.
  void compliances(TrainTorusState& s, detail::TorusWorkspace& ws) const;
  /// y = A x for the condensed matrix A (B_n of tone t: ws.B's columns t r .. t r + r − 1).
  void applyCondensed(detail::TorusWorkspace& ws, const Eigen::Ref<const Eigen::VectorXcd>& x,
                      Eigen::VectorXcd& y) const;
  /// ws.delta from the condensed system A δ = ws.rhs: preconditioned GMRES from the previous
  /// speeds' extrapolation, else a sparse LU.
  void solveCondensed(detail::TorusWorkspace& ws, TrainTorusState& s) const;
  /// X_n from δ (D(n·ω)⁻¹ V modally or factorised, D(0)⁻¹ F₀, the mesh loads φ_n).
  void recover(TrainTorusState& s, detail::TorusWorkspace& ws) const;
  /// Mesh forces, element forces and spectra on the torus grid (train_torus_grid.cpp).
  void postProcess(TrainTorusState& s, detail::TorusWorkspace& ws) const;

  const GearTrainModel& model_;
  TrainTorusOptions options_;
  TrainTorusGenerators generators_;
  Eigen::MatrixXi tones_;      // k × |T|, zero tone first, then ±n in pairs
  std::vector<int> negative_;  // index of −n
  std::vector<int> block_;     // HarmonicBlocks index of n (>0: n itself, <0: conj of −n)
  // [tone * r + m][L + l]: index of the tone n − l P_m e_{j(m)} (−1: outside T).
  std::vector<int> neighbour_;  // flat, 2L + 1 per unknown (tone * r + m)
  int stride_ = 1;              // 2L + 1
  const int* neighbourRow(std::size_t unknown) const noexcept {
    return neighbour_.data() + unknown * static_cast<std::size_t>(stride_);
  }
  std::vector<std::vector<std::complex<double>>> k_hat_, ke_hat_, e_hat_;
  // The stiffness-variation coupling w_{n,m} = Σ_{l≠0} k̂_{m,l} δ_{m, n − l P_m e_j} as
  // compressed rows per unknown t r + m (speed-independent; the matrix-free product's).
  std::vector<int> coupling_start_, coupling_index_;
  std::vector<std::complex<double>> coupling_value_;
  std::vector<std::vector<int>> lines_;  // preconditioner blocks: unknown indices t r + m
  std::vector<int> line_of_, local_of_;  // unknown → its line and its place in it
  Eigen::MatrixXd rigid_;
  bool rigid_at_every_speed_ = false;
  Eigen::MatrixXd fields_;                 // rows vᵀ per mesh, then J of every element
  std::vector<int> samples_;               // grid points per generator
  std::unique_ptr<detail::TorusFft> fft_;  // the grid's transforms, planned once
};

}  // namespace geardyn
