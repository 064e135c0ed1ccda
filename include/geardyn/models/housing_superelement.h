#pragma once
/// \file
/// A flexible housing as a Craig–Bampton superelement (issue #37, item 2; derivation in
/// docs/theory/housing_superelement.md).
///
/// 1. Seat condensation: each bearing seat's node set is tied to one 6-DOF interface node at the
///    seats' centroid c by a rigid multi-point constraint (RBE2-like), u_n = u_c + θ_c × (x_n − c):
///    the bearing's outer ring is pressed into the bore and is far stiffer in its plane than the
///    housing wall, so the bore keeps its shape; the constraint eliminates the seat nodes'
///    translations exactly (no penalty, no Lagrange multiplier), K' = Tᵀ K T, M' = Tᵀ M T.
/// 2. Craig & Bampton (1968), "Coupling of substructures for dynamic analyses", AIAA J. 6(7),
///    1313-1319, eqs. (4)-(9): the interior DOFs o are the static constraint modes
///    Ψ = −K_oo⁻¹ K_ob of the interface DOFs b plus the fixed-interface normal modes Φ
///    (K_oo φ = ω² M_oo φ, mass-normalised) below a cut-off:
///      K_cb = [K_bb + K_bo Ψ, 0; 0, Λ],
///      M_cb = [M_bb + M_bo Ψ + Ψᵀ M_ob + Ψᵀ M_oo Ψ, (M_bo + Ψᵀ M_oo) Φ; sym, I].
///    The modes are found by shift-invert Lanczos (Spectra's SymGEigsShiftSolver) on the sparse
///    K_oo, M_oo with K_oo factorised once (CHOLMOD's supernodal Cholesky with METIS ordering in
///    libgeardyn_cholmod.so, or Eigen's SimplicialLDLT without it; the factor the constraint
///    modes use): twice as many are asked for until the highest found lies above the cut-off.
///    Optionally (CraigBamptonOptions::residual_vectors) six residual vectors a seat,
///    K_oo⁻¹ (M_ob + M_oo Ψ) less their part in the kept modes (Kim & Lee 2015's residual
///    flexibility term), are appended to the modes as Ritz vectors: the truncated modes' static
///    share, which takes the frequencies below the usual cut-off to 0.1 % (docs/theory §3, §4).
/// With no modes and no residual vectors the superelement is Guyan's static condensation
/// K_bb − K_bo K_oo⁻¹ K_ob.

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <map>
#include <string>
#include <vector>

#include "geardyn/io/fe_matrices.h"

namespace geardyn {

/// A deck's unit system: the factors from the deck's length and mass units to SI (time in s in
/// both, so force and stiffness follow: an mm-t-s deck's N/mm × 1e3 = N/m, its t × 1e3 = kg).
struct FeUnits {
  double length_m = 1.0;  ///< metres per deck length unit
  double mass_kg = 1.0;   ///< kilograms per deck mass unit
};

/// FeUnits from a `units` key's value: "si" (m, kg, s) or "mm_t_s" (mm, t, s). InputError(key,
/// value, the allowed values) otherwise.
FeUnits feUnits(const std::string& name, const std::string& key);

/// A named node set of the housing's mesh: a bearing seat or a response point.
struct HousingNodeSet {
  std::string name;        ///< the deck's *NSET name
  std::vector<int> nodes;  ///< node numbers
};

/// What the reduction keeps.
struct CraigBamptonOptions {
  /// Fixed-interface modes up to this frequency are kept [Hz] (issue #37: 2 × the highest
  /// frequency the analyses ask for).
  double cutoff_hz = 0.0;
  /// When >= 0, exactly this many lowest modes instead (0: Guyan); the cut-off is then unused.
  int modes = -1;
  /// Append the residual vectors K_oo⁻¹ (M_ob + M_oo Ψ) (6 a seat, less their part in the
  /// kept modes; modal truncation augmentation, docs/theory/housing_superelement.md §3) to the
  /// fixed-interface modes: the truncated modes' static share of the interface's inertia load.
  bool residual_vectors = false;
  std::string key = "housing";  ///< the configuration key errors name ("housing.cutoff_hz")
};

/// The reduced housing in SI units: interface DOFs first (6 a seat: u_x, u_y, u_z [m], θ_x,
/// θ_y, θ_z [rad] of the seat's centre), then the modal coordinates (mass-normalised).
struct ReducedHousing {
  Eigen::MatrixXd K;                     ///< reduced stiffness [N/m, N, N m/rad]
  Eigen::MatrixXd M;                     ///< reduced mass [kg, kg m, kg m²]
  std::vector<std::string> seats;        ///< seat names, in interface order
  std::vector<Eigen::Vector3d> centres;  ///< each seat's centre (node centroid) [m]
  /// The modal coordinates' frequencies [Hz]: the kept fixed-interface modes', then the
  /// residual vectors' Ritz frequencies (the last `residual_vectors`).
  Eigen::VectorXd mode_frequencies_hz;
  Eigen::Index residual_vectors = 0;  ///< how many of the modal coordinates are residual vectors
  std::vector<std::string> points;    ///< response point names
  /// Response point translations [m] from the reduced coordinates: rows 3i..3i+2 are point i's
  /// x, y, z (the mean over its nodes).
  Eigen::MatrixXd recovery;
  /// Wall times of the reduction that made it [s] (0 when read from a cache): the factorisation
  /// of K_oo, the fixed-interface modes (Lanczos), the rest (tie, projections, constraint modes).
  double factorisation_s = 0.0, modes_s = 0.0, other_s = 0.0;
  Eigen::Index interfaceDofs() const { return 6 * static_cast<Eigen::Index>(seats.size()); }
};

/// Reduces an assembled housing (`fe` and `nodes` already in SI) onto its seats. InputError
/// naming `options.key` and the set when a seat or point node is not in the mesh or is fixed by
/// *BOUNDARY, when two seats share a node, when a seat has fewer than three nodes or they are
/// collinear, and when the cut-off lies below the first fixed-interface mode (no mode kept).
ReducedHousing reduceHousing(const io::FeMatrices& fe, const std::map<int, Eigen::Vector3d>& nodes,
                             const std::vector<HousingNodeSet>& seats,
                             const std::vector<HousingNodeSet>& points,
                             const CraigBamptonOptions& options);

/// Scales a deck's matrices and coordinates to SI in place.
void scaleToSi(io::FeMatrices& fe, std::map<int, Eigen::Vector3d>& nodes, const FeUnits& units);

}  // namespace geardyn
