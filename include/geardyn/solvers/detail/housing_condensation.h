#pragma once
/// \file
/// The flexible housing condensed out of a harmonic block exactly (issue #37; derivation in
/// docs/theory/housing_superelement.md §6). On its own the housing's dynamic stiffness
/// D_h0(ω) = (1 + iωβ_h) K_h − ω² M_h is diagonal in its modes (K_h Φ = M_h Φ Λ, Φᵀ M_h Φ = I):
/// d_k = (1 + iωβ_h) λ_k − ω². The train sees it only through its r linked bearing rows,
/// deformation J q_t − J_H q_h and Z = k + iω c, so with W = J_H Φ (r × n_h),
///   G = W diag(1/d) Wᵀ (the seats' receptance at the bearings, r × r),
///   Z_eff = (I + Z G)⁻¹ Z (each bearing in series with the housing),
///   [D_tt − Jᵀ Z J + Jᵀ Z_eff J] q_t = f_t + Jᵀ Z_eff g,   g = W diag(1/d) Φᵀ f_h,
///   q_h = Φ diag(1/d) (Wᵀ F + Φᵀ f_h),   F = Z_eff (J q_t − g) (the bearing forces).
/// Per frequency: r² n_h for G, r³ for Z_eff and the train's own n_t × n_t LU, instead of an LU
/// of n_t + n_h. G is one real (r(r + 1)/2 × n_h) product with the complex 1/d (its upper
/// triangle: G is symmetric), with P's column k the outer product w_k w_kᵀ precomputed, and Φ,
/// W, J enter the solves as real matrices times [Re x, Im x] of a complex operand x: half the
/// work of a complex product, the real matrix read once (bench/housing_bench.cpp,
/// BM_ForcedPerSpeed).

#include <Eigen/Dense>
#include <memory>
#include <vector>

#include "geardyn/system/gear_train_model.h"

namespace geardyn::detail {

/// What does not depend on the frequency (nor on the speed): built once per model.
struct HousingCondensation {
  int first = 0;           ///< the housing's first DOF (n_t)
  Eigen::MatrixXd J;       ///< r × n_t: the linked bearings' rows on the train's DOFs
  Eigen::MatrixXd W;       ///< r × n_h: J_H Φ
  Eigen::MatrixXd Phi;     ///< n_h × n_h, mass-normalised modes of (K_h, M_h)
  Eigen::VectorXd lambda;  ///< ω_k² [1/s²]
  Eigen::MatrixXd k, c;    ///< r × r: the rows' stiffness and damping (with the gearbox's β k)
  double beta = 0.0;       ///< the housing's β_h [s]
  /// r(r + 1)/2 × n_h: column k holds the upper triangle of w_k w_kᵀ column by column, w_k =
  /// W's column k (G = W diag(1/d) Wᵀ, symmetric, as P (1/d)).
  Eigen::MatrixXd P;
  /// The static receptances (w = 0, the same at every speed): 1/λ_k and G(0)'s upper triangle.
  Eigen::VectorXcd dinv_static, g_static;
  /// The train's DOFs J reads (its nonzero columns; a bearing row reads a few of them) and J
  /// on them (r × c): Z_eff J is formed on these c columns only.
  std::vector<Eigen::Index> J_columns;
  Eigen::MatrixXd Jc;
  Eigen::MatrixXcd JcT;     ///< Jcᵀ as complex (c × r), for Jᵀ (Z_eff − Z) J per frequency
  bool Z_diagonal = false;  ///< k and c diagonal: Z G is a scaling of G's rows
  /// The housing's DOFs (counted from `first`) that the train's elements read (the bearing
  /// seats) and Φ on them: the rows a forced sweep needs of every harmonic (the elements' forces
  /// are sampled from them), TrainSteadySolver::solve without all housing rows.
  std::vector<Eigen::Index> read_rows;
  /// R Φ (3 P × n_h), R the reduced housing's recovery at its P response points: their
  /// displacements [m] from modal amplitudes; no rows without points.
  Eigen::MatrixXd points_Phi;
  /// [Φ on read_rows; R Φ]: both in one product.
  Eigen::MatrixXd Phi_kept;
  /// The condensation of `model`'s housing; null without a housing or when the housing is not
  /// held (a zero eigenvalue: the exact path then factorises the whole block).
  static std::shared_ptr<const HousingCondensation> of(const GearTrainModel& model);
  /// Φ y: the housing's reduced coordinates from modal amplitudes y (n_h × any).
  Eigen::MatrixXcd physical(const Eigen::MatrixXcd& y) const;
  /// Wᵀ F: the bearing forces F (r × any) on the housing's modes.
  Eigen::MatrixXcd modal(const Eigen::MatrixXcd& F) const;
  /// [Φ_read y; R Φ y]: the rows `read_rows` of Φ y over the response points' displacements.
  Eigen::MatrixXcd keptRows(const Eigen::MatrixXcd& y) const;
  /// R Φ y: the response points' displacements (3 P × any) [m].
  Eigen::MatrixXcd points(const Eigen::MatrixXcd& y) const;
};

/// The housing's frequency-dependent terms at several frequencies w_j [rad/s] at once (the
/// harmonics of one speed): 1/d_k(w_j) (n_h × count) and G(w_j)'s upper triangle
/// (r(r + 1)/2 × count) from one real product P [Re 1/d, Im 1/d] for all of them, so P is read
/// (and packed) once per speed instead of once per harmonic.
struct HousingReceptances {
  std::vector<double> w;  ///< the frequencies [rad/s]
  Eigen::MatrixXcd dinv;  ///< column j: 1/d_k(w_j) = 1/((1 + i w_j β_h) λ_k − w_j²) [s²]
  Eigen::MatrixXcd g;     ///< column j: G(w_j)'s upper triangle, column by column [m/N]
  static HousingReceptances at(const HousingCondensation& h, const std::vector<double>& w);
};

/// LU factors of a small complex matrix, partial pivoting on |Re| + |Im| (LAPACK zgetrf's
/// izamax): I + Z G of the condensation, r × r (r the linked bearings' rows).
class SmallComplexLU {
 public:
  void compute(const Eigen::MatrixXcd& A);
  /// B ← A⁻¹ B.
  void solveInPlace(Eigen::MatrixXcd& B) const;

 private:
  Eigen::MatrixXcd lu_;
  std::vector<Eigen::Index> pivots_;
  Eigen::VectorXcd inverse_;  // 1/u_kk
};

/// One frequency's condensation: the train's LU and the housing's terms.
class CondensedHousingBlock {
 public:
  using Complex = std::complex<double>;
  /// Factorises the train's block D_tt of K̄ − ω²M + iωC (with any rigid-body penalty) with the
  /// housing condensed out at ω [rad/s].
  void factorize(const HousingCondensation& h, Eigen::MatrixXcd Dtt, double w);
  /// The same with 1/d and G's upper triangle at w given (HousingReceptances' columns).
  void factorize(const HousingCondensation& h, Eigen::MatrixXcd Dtt, double w,
                 const Eigen::Ref<const Eigen::VectorXcd>& dinv,
                 const Eigen::Ref<const Eigen::VectorXcd>& g);
  /// D⁻¹ rhs over all n_t + n_h DOFs.
  Eigen::MatrixXcd solve(const HousingCondensation& h, const Eigen::MatrixXcd& rhs) const;
  /// The train's rows of D⁻¹ rhs for loads on the train only (`rhs_t`: n_t rows; the housing's
  /// rows of the load are zero): the train's LU alone.
  Eigen::MatrixXcd solveTrain(const Eigen::MatrixXcd& rhs_t) const { return lu_.solve(rhs_t); }
  /// The housing's rows of that solution from its train rows q_t:
  /// q_h = Φ diag(1/d) Wᵀ Z_eff J q_t (the loads on the housing zero).
  Eigen::MatrixXcd housingRows(const HousingCondensation& h, const Eigen::MatrixXcd& q_t) const;
  /// Its modal amplitudes y = diag(1/d) Wᵀ Z_eff J q_t (q_h = Φ y; n_h × q_t's columns), so that
  /// a caller with several blocks forms Φ [y_0, y_1, ...] in one product.
  Eigen::MatrixXcd modalAmplitudes(const HousingCondensation& h, const Eigen::MatrixXcd& q_t) const;
  /// The bearing forces F = Z_eff J q_t on the housing (r × q_t's columns).
  Eigen::MatrixXcd bearingForces(const HousingCondensation& h, const Eigen::MatrixXcd& q_t) const;
  /// The same for one column q_t, written to `F` (r) without temporaries.
  void bearingForces(const HousingCondensation& h, const Eigen::Ref<const Eigen::VectorXcd>& q_t,
                     Eigen::Ref<Eigen::VectorXcd> F) const;
  /// 1/d_k at this block's frequency.
  const Eigen::VectorXcd& receptances() const noexcept { return dinv_; }

 private:
  /// Z_eff x = (I + Z G)⁻¹ Z x.
  Eigen::MatrixXcd zeff(const Eigen::MatrixXcd& x) const;

  Eigen::PartialPivLU<Eigen::MatrixXcd> lu_;
  SmallComplexLU seat_lu_;  // I + Z G
  Eigen::MatrixXcd Z_;      // k + iωc (r × r); empty when diagonal (then z_)
  Eigen::VectorXcd z_;      // its diagonal when k and c are diagonal
  Eigen::MatrixXcd ZeffJ_;  // Z_eff J on J's columns (r × c)
  Eigen::VectorXcd dinv_;
};

}  // namespace geardyn::detail
