#pragma once
/// \file
/// Modal analysis of a gear train at an input speed: the damped complex modes of
///   M q̈ + (C + Ω G₁) q̇ + (K + Ω² K_Ω + Σ k̄_m v_m v_mᵀ) q = 0,
/// or, when the model has no damping and no speed-dependent terms at Ω, the real modes of the
/// symmetric problem K φ = ω² M φ (exact multiplicities: Lin & Parker's degenerate pairs stay
/// degenerate to round-off). Each mode carries the strain-energy fraction of every mesh and
/// element, the kinetic-energy fraction of every body, and, for each planetary stage, its type
/// after Lin & Parker (1999): rotational, translational or planet mode. The Campbell diagram
/// tracks modes over speeds by MAC and finds where shaft and mesh orders cross them.

#include <Eigen/Dense>
#include <complex>
#include <string>
#include <vector>

#include "geardyn/progress.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn {

struct TrainMode {
  std::complex<double> eigenvalue;            ///< λ [1/s]
  double frequency = 0.0;                     ///< Im λ / 2π, or ω / 2π for real modes [Hz]
  double damping_ratio = 0.0;                 ///< −Re λ / |λ| [-]
  Eigen::VectorXcd shape;                     ///< displacement, largest entry 1
  std::vector<double> body_kinetic_energy;    ///< fraction per body [-], sums to 1
  std::vector<double> mesh_strain_energy;     ///< fraction per mesh (of the total) [-]
  std::vector<double> element_strain_energy;  ///< fraction per element [-]
  double translational_fraction = 0.0;        ///< kinetic energy in translations [-]
  /// Kinetic energy in the flexible housing's DOFs (train_housing.h) [-]; the bodies' fractions
  /// sum to 1 − housing_fraction.
  double housing_fraction = 0.0;
  /// Strain energy ½ x̄ᵀ K_h x of the housing's DOFs, a fraction of the total [-].
  double housing_strain_energy = 0.0;
  /// Per planetary stage: "rotational", "translational", "planet" or "mixed" (Lin & Parker
  /// 1999 §3), judged from the central members' kinetic energy; with full DOFs also
  /// "out_of_plane" (axial and tilting motion only); "outside" for modes not in the stage.
  std::vector<std::string> stage_type;
  int multiplicity = 1;  ///< modes within 1e-6 relative of this frequency (itself included)
  /// Shares of the diagonal kinetic energy Σ M_ii |x_i|² in the lateral motion (u_y, u_z, θ_y,
  /// θ_z), the torsion θ_x and the axial u_x [-] (they sum to 1).
  double lateral_fraction = 0.0, torsional_fraction = 0.0, axial_fraction = 0.0;
  /// Whirl (planar and full DOFs): each body's lateral motion r = u_y + i u_z of e^{iωt} is a
  /// circle (U_y + iU_z)/2 turning about +x and one (U_y − iU_z)/2 about −x; forward is the
  /// sense of the body's own spin. The mass-weighted share of the forward circles [-] (0.5
  /// without lateral motion), Lalanne & Ferraris (1998) §2.
  double forward_fraction = 0.5;
  /// "housing" (housing_fraction > 1/2: a mode of the flexible housing),
  /// "torsional" (torsional share > 1/2), "axial" (axial share > 1/2), else "forward" (forward
  /// share > 0.75), "backward" (< 0.25) or "mixed".
  std::string whirl;
  /// A static divergence: λ real and > 0 (growth rate [1/s]), frequency 0, damping ratio −1.
  /// Listed before the oscillating modes and not counted in TrainModalOptions::modes.
  bool divergent = false;
  /// Re λ when the mode grows (flutter or divergence) beyond round-off (1e-9 |λ|), else 0 [1/s].
  double growthRate() const {
    return eigenvalue.real() > 1e-9 * std::abs(eigenvalue) ? eigenvalue.real() : 0.0;
  }
};

struct TrainModalOptions {
  int modes = 0;  ///< lowest modes returned; 0: all
  /// Eigenvalues with |λ|/2π below this are rigid-body modes [Hz]; < 0: derived from the
  /// model (1e-6 × the largest natural frequency).
  double rigid_frequency = -1.0;
  /// Return rigid-body modes (0 Hz) too; only undamped models at rest (symmetric eigenproblem)
  /// have them in their list, damped ones report elastic modes only.
  bool keep_rigid = true;
  /// Modes more damped than this are skipped: overdamped high modes (stiffness-proportional
  /// damping) that round-off turns into "modes" of a fraction of a hertz with ζ ≈ 1.
  double max_damping_ratio = 0.99;
  void validate() const;
};

/// DOF count from which a request for a few modes (options.modes > 0, fewer than a quarter of
/// the DOFs) is answered by shift-invert Arnoldi on sparse matrices (Spectra) instead of the
/// dense eigensolver; rigid-body modes are then not reported.
inline constexpr int kSparseModalDofs = 150;

/// Modes at input speed Ω [rad/s], ascending in frequency.
std::vector<TrainMode> trainModes(const GearTrainModel& model, double input_speed,
                                  const TrainModalOptions& options = {});

/// An order line of the Campbell diagram: frequency = slope × |Ω| [Hz per rad/s].
struct TrainOrderLine {
  std::string name;  ///< "1x input", "mesh stage1", "2x mesh stage1"
  double slope = 0.0;
};
/// 1× every shaft and planet set that turns, and harmonics 1..mesh_harmonics of every distinct
/// mesh frequency.
std::vector<TrainOrderLine> trainOrderLines(const GearTrainModel& model, int mesh_harmonics);

struct TrainCriticalSpeed {
  int mode = 0;            ///< tracked mode index
  std::string line;        ///< order line name
  double speed = 0.0;      ///< input speed [rad/s]
  double frequency = 0.0;  ///< [Hz]
  std::string whirl;       ///< TrainMode::whirl of the mode at the nearer speed
};

struct TrainCampbell {
  std::vector<double> speeds;                 ///< input speeds [rad/s]
  std::vector<std::vector<TrainMode>> modes;  ///< modes[i][j]: tracked mode j at speed i
  std::vector<TrainOrderLine> lines;
  std::vector<TrainCriticalSpeed> critical_speeds;  ///< ascending in speed
  /// Per speed, the largest growth rate λ of a divergent mode (not tracked) [1/s]; 0: none.
  std::vector<double> divergence_rate;
};

/// Modes over ascending speeds, tracked by the MAC of neighbouring speeds' shapes. `progress`
/// (speeds solved of all) is called on the calling thread only.
TrainCampbell trainCampbell(const GearTrainModel& model, const std::vector<double>& speeds,
                            const TrainModalOptions& options,
                            const std::vector<TrainOrderLine>& lines,
                            const ProgressCallback& progress = {});

}  // namespace geardyn
