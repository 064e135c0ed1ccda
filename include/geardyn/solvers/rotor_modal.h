#pragma once
/// \file
/// Modal analysis of the finite-element geared rotor: damped complex modes of
///   M q̈ + (C + Ω_p G₁) q̇ + (K + k̄_m v vᵀ) q = 0
/// at a pinion speed (state-space eigenproblem), forward/backward whirl classification, and the
/// Campbell diagram over a speed range with modes tracked by their shapes (MAC), with the
/// critical speeds where tracked modes cross the 1× and mesh-order lines.
///
/// Whirl of a mode e^{λt}, λ = −σ + iω: each node's lateral motion r = u_y + i u_z is the sum of
/// a circle (U_y + iU_z)/2 e^{iωt}, turning about +x, and a circle (U_y − iU_z)/2 turning about
/// −x. Forward is the sense of the node's own shaft (the gear shaft spins about −x). The forward
/// fraction is the mass-weighted share of forward circles over all nodes; "forward" above 0.75,
/// "backward" below 0.25, "mixed" between; modes whose kinetic energy is mostly torsional
/// (axial) are labelled "torsional" ("axial").

#include <Eigen/Dense>
#include <complex>
#include <string>
#include <vector>

#include "geardyn/models/fe_geared_rotor.h"

namespace geardyn {

struct RotorMode {
  std::complex<double> eigenvalue;  ///< λ [1/s]
  double frequency = 0.0;           ///< damped natural frequency Im λ / 2π [Hz]
  double damping_ratio = 0.0;       ///< −Re λ / |λ|
  double forward_fraction = 0.0;    ///< share of forward whirl in the lateral motion
  double lateral_fraction = 0.0;  ///< share of the (diagonal) kinetic energy in u_y, u_z, θ_y, θ_z
  double torsional_fraction = 0.0;  ///< … in θ_x
  double axial_fraction = 0.0;      ///< … in u_x
  std::string whirl;                ///< "forward", "backward", "mixed", "torsional", "axial"
  Eigen::VectorXcd shape;           ///< displacement part, largest entry 1
};

struct ModalOptions {
  int modes = 12;                 ///< lowest elastic modes returned
  double mesh_stiffness = 0.0;    ///< k_m [N/m]; 0: the model's mean
  double rigid_frequency = 1e-2;  ///< |λ|/2π below this [Hz]: rigid-body mode, skipped
  /// Modes more damped than this are skipped: the pairs of real eigenvalues of overdamped high
  /// modes (stiffness-proportional damping) that gyroscopic coupling turns into "modes" of a
  /// fraction of a hertz with ζ ≈ 1.
  double max_damping_ratio = 0.99;
  void validate() const;
};

/// The lowest elastic modes at pinion speed Ω_p [rad/s], ascending in frequency (rigid-body and
/// overdamped eigenvalues are skipped).
std::vector<RotorMode> modalAnalysis(const FeGearedRotor& model, double pinion_speed,
                                     const ModalOptions& options = {});

/// An excitation order line: frequency = order × pinion rotation frequency.
struct OrderLine {
  std::string name;  ///< "1x pinion", "1x gear", "mesh"
  double order = 1.0;
};
/// 1× pinion, 1× gear (z_p/z_g) and the mesh (z_p) lines of a model.
std::vector<OrderLine> standardOrderLines(const FeGearedRotor& model);

struct CriticalSpeed {
  int mode = 0;            ///< tracked mode index
  std::string line;        ///< order line name
  double speed = 0.0;      ///< pinion speed [rad/s]
  double frequency = 0.0;  ///< [Hz]
  std::string whirl;       ///< whirl of the mode there
};

struct CampbellDiagram {
  std::vector<double> speeds;                 ///< pinion speeds [rad/s]
  std::vector<std::vector<RotorMode>> modes;  ///< modes[i][j]: tracked mode j at speed i
  std::vector<OrderLine> lines;
  std::vector<CriticalSpeed> critical_speeds;  ///< ascending in speed
};

/// Modes over the speeds (ascending), tracked by MAC of their shapes between neighbouring speeds
/// (each mode takes the unclaimed candidate of highest MAC; 2× the modes are computed as
/// candidates so that modes entering from above do not steal a track).
CampbellDiagram campbellDiagram(const FeGearedRotor& model, const std::vector<double>& speeds,
                                const ModalOptions& options, const std::vector<OrderLine>& lines);

}  // namespace geardyn
