#pragma once
/// \file
/// The 4-DOF lateral geared rotor with asymmetric transmission error of the Rao thesis
/// (shared/seeds/rao2023_thesis_geared_rotor_dte_identification.txt, Fig. 2.1, eqs. 2.1–2.38):
/// pinion (m₁) and gear (m₂) at mid-span of shafts with lateral stiffness k_s1, k_s2 on rigid
/// bearings, coupled in x and in y by the mesh spring k_m and damper c_m, excited by the mean and
/// fluctuating transmission error e_x(t), e_y(t) (eqs. 2.8–2.9), the runouts of both gears with
/// their unbalance forces (eqs. 2.2–2.4) and gravity (eq. 2.17, along −y).
///
/// Coordinates η = (x₁, y₁, x₂, y₂) [m] are the shaft centres at the gears (eq. 2.10). The
/// pinion turns in the −z sense (the thesis's angle −φ_z1 in eq. 2.2) and the gear in the +z
/// sense; with φ_p = ω_p t + ϕ_p and φ_g = ω_g t + ϕ_g the gear centres are
///   x_p = x₁ + e_p cos φ_p,  y_p = y₁ − e_p sin φ_p,  x_g = x₂ + e_g cos φ_g,  y_g = y₂ + e_g sin
///   φ_g.
///
/// Equations of motion re-derived from the energies 2.11–2.13 and the gravity 2.17 (the shaft
/// springs and dampers act on the gear centres, the mesh on δ_x = x_p − x_g − e_x and
/// δ_y = y_p − y_g − e_y; the r_b φ terms of eq. 2.5 cancel at constant ratio):
///   M η̈ + C η̇ + K η = P − M ẅ − C ẇ − K w + B (k_m e + c_m ė)
/// with w(t) = (e_p cos φ_p, −e_p sin φ_p, e_g cos φ_g, e_g sin φ_g) the runout offsets, P the
/// weights, e = (e_x, e_y) and B = [I; −I]. Written out this is eqs. 2.30–2.33 with these
/// corrections of the printed text:
///   - eqs. 2.31, 2.33, 2.37, 2.38: the y equations carry ė_y, not ė_x;
///   - eq. 2.37 (row x₂): the shaft terms are c_s2 e_g ω_g sin φ_g − k_s2 e_g cos φ_g, not the
///     pinion's c_s1, k_s1 terms;
///   - eq. 2.7 prints cos(−ω_p t + ϕ_p), sin(−ω_p t + ϕ_p); eq. 2.3 and the energies 2.14–2.16
///     have cos(ω_p t + ϕ_p), −sin(ω_p t + ϕ_p), which is what is implemented;
///   - eqs. 2.16, 2.25: r_b1 ω_p − r_b2 ω_g is zero (ω_e = t_p ω_p = t_g ω_g) and is dropped.
/// A consequence worth knowing: since the shafts, dampers and masses all act on the gear centres,
/// the runout response is exactly η = −w: a pinion circle at −f_p (backward in the probe frame)
/// and a gear circle at +f_g, with no resonant amplification (thesis §4.4).
///
/// The system matrices act identically in x and y, so z = x + jy obeys the same 2×2 system with
/// real M₂, C₂, K₂: the basis of the frequency-domain form (thesis ch. 3, eqs. 3.135–3.138).

#include <Eigen/Core>
#include <complex>
#include <string>
#include <vector>

namespace geardyn {

/// One harmonic of the fluctuating transmission error: a sin(i ω_e t + ϕ) (eq. 2.9).
struct TeHarmonic {
  double amplitude = 0.0;  ///< [m]
  double phase = 0.0;      ///< [rad]
};

/// How damping ratios map to dashpots (thesis Table 4.1 gives ratios, §4.5 the mesh's mass).
enum class MeshDampingMass {
  /// c_m = 2 ζ_m √(k_m m₁m₂/(m₁ + m₂)): the thesis's "average gearing mass" m_avg of eq. 4.9
  /// (the two-mass relative mode; §4.5 words it "average mass"), used by its identification.
  kEffective,
  kArithmeticMean,  ///< c_m = 2 ζ_m √(k_m (m₁ + m₂)/2)
};

/// Physical data of the rotor, SI units. Damping is given as dashpots; see
/// lateralRotorDamping() for the ratios of Table 4.1.
struct LateralRotorSpec {
  double pinion_mass = 0.310;           ///< m₁ [kg]
  double gear_mass = 1.270;             ///< m₂ [kg]
  double pinion_shaft_stiffness = 1e6;  ///< k_s1 [N/m]
  double gear_shaft_stiffness = 1e6;    ///< k_s2 [N/m]
  double pinion_shaft_damping = 0.0;    ///< c_s1 [N s/m]
  double gear_shaft_damping = 0.0;      ///< c_s2 [N s/m]
  double mesh_stiffness = 6e8;          ///< k_m [N/m]
  double mesh_damping = 0.0;            ///< c_m [N s/m]
  double mean_te = 50e-6;               ///< e_m [m], in x and in y (eq. 2.8)
  std::vector<TeHarmonic> te_x;         ///< e_fx,i, ϕ_ex,i, i = 1..n (eq. 2.9)
  std::vector<TeHarmonic> te_y;         ///< e_fy,i, ϕ_ey,i (same n as te_x)
  double pinion_runout = 0.0;           ///< e_p [m]
  double pinion_runout_phase = 0.0;     ///< ϕ_p [rad]
  double gear_runout = 0.0;             ///< e_g [m]
  double gear_runout_phase = 0.0;       ///< ϕ_g [rad]
  double gravity = 9.81;                ///< g [m/s²], acting along −y
  int pinion_teeth = 16;                ///< t_p
  int gear_teeth = 35;                  ///< t_g
  double pinion_speed = 660.0 / 60.0;   ///< N_p [rev/s]; ω_p = 2π N_p

  /// Throws InputError naming the field for non-physical data (negative or non-finite values,
  /// TE lists of different lengths, fewer than 1 tooth).
  void validate() const;
};

/// The mass a mesh damping ratio refers to [kg]: m₁m₂/(m₁ + m₂) (eq. 4.9) or (m₁ + m₂)/2.
double meshDampingMass(double pinion_mass, double gear_mass,
                       MeshDampingMass kind = MeshDampingMass::kEffective);
/// A dashpot from a damping ratio, c = 2 ζ √(k m) [N s/m].
double dashpotFromRatio(double ratio, double stiffness, double mass);

/// Dashpots from damping ratios: c_s1 = 2 ζ_s √(k_s1 m₁), c_s2 = 2 ζ_s √(k_s2 m₂) (each shaft
/// with its own gear, a one-mass oscillator), c_m = 2 ζ_m √(k_m m_mesh) with m_mesh as chosen.
void lateralRotorDamping(LateralRotorSpec& spec, double shaft_ratio, double mesh_ratio,
                         MeshDampingMass mesh_mass = MeshDampingMass::kEffective);

/// The Table 4.1 data set (with ζ_s = ζ_m = 0.01, the eq. 4.9 mesh mass).
LateralRotorSpec raoTable41Spec();

/// A steady-state whirl component of the forcing or of the response: z = c e^{jΩt}.
struct WhirlForcing {
  std::string name;        ///< "static", "mesh_1_fwd", ..., "pinion_1x_bwd", "gear_1x_fwd"
  double omega = 0.0;      ///< signed angular frequency Ω [rad/s] in the probe frame (+z)
  Eigen::Vector2cd force;  ///< complex force on (z₁, z₂) [N]
};

class LateralRotorModel {
 public:
  explicit LateralRotorModel(LateralRotorSpec spec);

  const LateralRotorSpec& spec() const noexcept { return spec_; }
  int harmonics() const noexcept { return static_cast<int>(spec_.te_x.size()); }
  double pinionOmega() const noexcept { return pinion_omega_; }  ///< ω_p [rad/s]
  double gearOmega() const noexcept { return gear_omega_; }      ///< ω_g [rad/s]
  double meshOmega() const noexcept { return mesh_omega_; }      ///< ω_e = t_p ω_p [rad/s]
  /// The common period of every component (pinion, gear, mesh): t_g/d pinion revolutions with
  /// d = gcd(t_p, t_g) (shared/reference/full_spectrum.md) [s].
  double commonPeriod() const noexcept;

  /// 4×4 matrices of eqs. 2.35–2.36 (η = x₁, y₁, x₂, y₂).
  const Eigen::Matrix4d& mass() const noexcept { return m_; }
  const Eigen::Matrix4d& damping() const noexcept { return c_; }
  const Eigen::Matrix4d& stiffness() const noexcept { return k_; }
  /// The same system for z = (x₁ + jy₁, x₂ + jy₂).
  Eigen::Matrix2d mass2() const;
  Eigen::Matrix2d damping2() const;
  Eigen::Matrix2d stiffness2() const;

  /// Transmission error e_x(t), e_y(t) and their rates [m], [m/s] (eqs. 2.8–2.9).
  void transmissionError(double t, double& ex, double& ey, double& dex, double& dey) const;
  /// The force vector f_r(t) of eq. 2.34 (corrected as in the file comment) [N]. No allocation.
  Eigen::Vector4d force(double t) const;

  /// The forcing as a sum of whirl components (static, mesh harmonics forward/backward, pinion
  /// and gear 1× forward/backward), each a complex force on (z₁, z₂): Σ s_k e^{jΩ_k t} equals
  /// f_x + j f_y of force(t) exactly.
  std::vector<WhirlForcing> whirlForcing() const;

 private:
  LateralRotorSpec spec_;
  double pinion_omega_ = 0, gear_omega_ = 0, mesh_omega_ = 0;
  Eigen::Matrix4d m_, c_, k_;
  std::vector<std::complex<double>> te_x_phasor_, te_y_phasor_;  ///< a_i e^{jϕ_i}
};

}  // namespace geardyn
