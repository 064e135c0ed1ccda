#include "geardyn/system/lateral_rotor.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <numeric>

#include "geardyn/error.h"

namespace geardyn {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
using Complex = std::complex<double>;
constexpr Complex kJ(0.0, 1.0);

void requireAtLeast(const char* key, double value, double minimum, const char* unit) {
  if (!std::isfinite(value) || value < minimum) {
    throw InputError(key, fmt::format("{:g}", value),
                     fmt::format("must be finite and >= {:g} [{}]", minimum, unit));
  }
}

void requirePositive(const char* key, double value, const char* unit) {
  if (!std::isfinite(value) || !(value > 0.0)) {
    throw InputError(key, fmt::format("{:g}", value),
                     fmt::format("must be finite and > 0 [{}]", unit));
  }
}

void requireFinite(const char* key, double value) {
  if (!std::isfinite(value)) throw InputError(key, fmt::format("{}", value), "must be finite");
}

}  // namespace

void LateralRotorSpec::validate() const {
  requirePositive("rotor.pinion_mass", pinion_mass, "kg");
  requirePositive("rotor.gear_mass", gear_mass, "kg");
  requirePositive("rotor.pinion_shaft_stiffness", pinion_shaft_stiffness, "N/m");
  requirePositive("rotor.gear_shaft_stiffness", gear_shaft_stiffness, "N/m");
  requireAtLeast("rotor.pinion_shaft_damping", pinion_shaft_damping, 0.0, "N s/m");
  requireAtLeast("rotor.gear_shaft_damping", gear_shaft_damping, 0.0, "N s/m");
  requirePositive("mesh.stiffness", mesh_stiffness, "N/m");
  requireAtLeast("mesh.damping", mesh_damping, 0.0, "N s/m");
  requireFinite("mesh.mean_te", mean_te);
  requireAtLeast("runout.pinion", pinion_runout, 0.0, "m");
  requireAtLeast("runout.gear", gear_runout, 0.0, "m");
  requireFinite("runout.pinion_phase_deg", pinion_runout_phase);
  requireFinite("runout.gear_phase_deg", gear_runout_phase);
  requireAtLeast("rotor.gravity", gravity, 0.0, "m/s^2");
  requirePositive("rotor.pinion_speed", pinion_speed, "rev/s");
  if (pinion_teeth < 2 || gear_teeth < 2) {
    throw InputError(pinion_teeth < 2 ? "rotor.pinion_teeth" : "rotor.gear_teeth",
                     fmt::format("{}", pinion_teeth < 2 ? pinion_teeth : gear_teeth),
                     "a gear needs at least 2 teeth (distinct whirl frequencies)");
  }
  if (te_x.size() != te_y.size()) {
    throw InputError("mesh.te_y", fmt::format("{} harmonics", te_y.size()),
                     fmt::format("must list as many harmonics as mesh.te_x ({})", te_x.size()));
  }
  for (std::size_t i = 0; i < te_x.size(); ++i) {
    for (const auto& [key, h] :
         {std::pair{"mesh.te_x", te_x[i]}, std::pair{"mesh.te_y", te_y[i]}}) {
      if (!std::isfinite(h.amplitude) || h.amplitude < 0.0 || !std::isfinite(h.phase)) {
        throw InputError(key,
                         fmt::format("harmonic {}: {:g} m, {:g} rad", i + 1, h.amplitude, h.phase),
                         "amplitudes must be finite and >= 0 [m], phases finite [rad]");
      }
    }
  }
}

double meshDampingMass(double pinion_mass, double gear_mass, MeshDampingMass kind) {
  return kind == MeshDampingMass::kArithmeticMean
             ? 0.5 * (pinion_mass + gear_mass)
             : pinion_mass * gear_mass / (pinion_mass + gear_mass);
}

double dashpotFromRatio(double ratio, double stiffness, double mass) {
  return 2.0 * ratio * std::sqrt(stiffness * mass);
}

void lateralRotorDamping(LateralRotorSpec& spec, double shaft_ratio, double mesh_ratio,
                         MeshDampingMass mesh_mass) {
  requireAtLeast("rotor.shaft_damping_ratio", shaft_ratio, 0.0, "-");
  requireAtLeast("mesh.damping_ratio", mesh_ratio, 0.0, "-");
  spec.pinion_shaft_damping =
      dashpotFromRatio(shaft_ratio, spec.pinion_shaft_stiffness, spec.pinion_mass);
  spec.gear_shaft_damping =
      dashpotFromRatio(shaft_ratio, spec.gear_shaft_stiffness, spec.gear_mass);
  spec.mesh_damping =
      dashpotFromRatio(mesh_ratio, spec.mesh_stiffness,
                       meshDampingMass(spec.pinion_mass, spec.gear_mass, mesh_mass));
}

LateralRotorSpec raoTable41Spec() {
  LateralRotorSpec s;  // masses, stiffnesses, teeth, speed, e_m: the defaults are Table 4.1
  const double ax[] = {40e-6, 25e-6, 35e-6, 20e-6, 10e-6};
  const double ay[] = {30e-6, 15e-6, 25e-6, 10e-6, 5e-6};
  for (int i = 0; i < 5; ++i) {
    s.te_x.push_back({ax[i], 0.785});
    s.te_y.push_back({ay[i], 1.570});
  }
  s.pinion_runout = 200e-6;
  s.gear_runout = 300e-6;
  s.pinion_runout_phase = 1.047;
  s.gear_runout_phase = 2.094;
  lateralRotorDamping(s, 0.01, 0.01);
  return s;
}

LateralRotorModel::LateralRotorModel(LateralRotorSpec spec) : spec_(std::move(spec)) {
  spec_.validate();
  pinion_omega_ = kTwoPi * spec_.pinion_speed;
  mesh_omega_ = pinion_omega_ * spec_.pinion_teeth;
  gear_omega_ = mesh_omega_ / spec_.gear_teeth;
  const double m1 = spec_.pinion_mass, m2 = spec_.gear_mass;
  m_ = Eigen::Vector4d(m1, m1, m2, m2).asDiagonal();
  for (std::size_t i = 0; i < spec_.te_x.size(); ++i) {
    te_x_phasor_.push_back(spec_.te_x[i].amplitude * std::polar(1.0, spec_.te_x[i].phase));
    te_y_phasor_.push_back(spec_.te_y[i].amplitude * std::polar(1.0, spec_.te_y[i].phase));
  }
  const auto coupled = [](double a, double b, double mesh) {
    Eigen::Matrix4d k = Eigen::Matrix4d::Zero();
    k(0, 0) = k(1, 1) = a + mesh;
    k(2, 2) = k(3, 3) = b + mesh;
    k(0, 2) = k(2, 0) = k(1, 3) = k(3, 1) = -mesh;
    return k;
  };
  c_ = coupled(spec_.pinion_shaft_damping, spec_.gear_shaft_damping, spec_.mesh_damping);
  k_ = coupled(spec_.pinion_shaft_stiffness, spec_.gear_shaft_stiffness, spec_.mesh_stiffness);
}

double LateralRotorModel::commonPeriod() const noexcept {
  const int d = std::gcd(spec_.pinion_teeth, spec_.gear_teeth);
  return (spec_.gear_teeth / d) / spec_.pinion_speed;
}

Eigen::Matrix2d LateralRotorModel::mass2() const {
  return Eigen::Vector2d(spec_.pinion_mass, spec_.gear_mass).asDiagonal();
}
Eigen::Matrix2d LateralRotorModel::damping2() const {
  return c_({0, 2}, {0, 2});
}
Eigen::Matrix2d LateralRotorModel::stiffness2() const {
  return k_({0, 2}, {0, 2});
}

void LateralRotorModel::transmissionError(double t, double& ex, double& ey, double& dex,
                                          double& dey) const {
  // e = e_m + Σ a_i sin(iω_e t + ϕ_i) = e_m + Σ Im(a_i e^{jϕ_i} u^i), u = e^{jω_e t}; the powers
  // by recurrence (one sincos per call).
  const Complex u(std::cos(mesh_omega_ * t), std::sin(mesh_omega_ * t));
  Complex ui(1.0, 0.0);
  ex = ey = spec_.mean_te;
  dex = dey = 0.0;
  for (std::size_t i = 0; i < spec_.te_x.size(); ++i) {
    ui *= u;
    const double order = static_cast<double>(i + 1) * mesh_omega_;
    const Complex px = te_x_phasor_[i] * ui;
    const Complex py = te_y_phasor_[i] * ui;
    ex += px.imag();
    ey += py.imag();
    dex += order * px.real();
    dey += order * py.real();
  }
}

Eigen::Vector4d LateralRotorModel::force(double t) const {
  const double phase_p = pinion_omega_ * t + spec_.pinion_runout_phase;
  const double phase_g = gear_omega_ * t + spec_.gear_runout_phase;
  const double cp = std::cos(phase_p), sp = std::sin(phase_p);
  const double cg = std::cos(phase_g), sg = std::sin(phase_g);
  const double ep = spec_.pinion_runout, eg = spec_.gear_runout;
  const double wp = pinion_omega_, wg = gear_omega_;
  // Runout offsets of the gear centres and their derivatives (eq. 2.3).
  const Eigen::Vector4d w(ep * cp, -ep * sp, eg * cg, eg * sg);
  const Eigen::Vector4d dw(-ep * wp * sp, -ep * wp * cp, -eg * wg * sg, eg * wg * cg);
  const Eigen::Vector4d ddw(-wp * wp * w(0), -wp * wp * w(1), -wg * wg * w(2), -wg * wg * w(3));
  double ex, ey, dex, dey;
  transmissionError(t, ex, ey, dex, dey);
  const double qx = spec_.mesh_stiffness * ex + spec_.mesh_damping * dex;
  const double qy = spec_.mesh_stiffness * ey + spec_.mesh_damping * dey;
  Eigen::Vector4d f(qx, qy - spec_.pinion_mass * spec_.gravity, -qx,
                    -qy - spec_.gear_mass * spec_.gravity);
  f.noalias() -= m_ * ddw;
  f.noalias() -= c_ * dw;
  f.noalias() -= k_ * w;
  return f;
}

std::vector<WhirlForcing> LateralRotorModel::whirlForcing() const {
  std::vector<WhirlForcing> out;
  const double km = spec_.mesh_stiffness, cm = spec_.mesh_damping;
  // Static: weights along −y and the mean TE in x and y.
  const Complex mean = km * spec_.mean_te * Complex(1.0, 1.0);
  out.push_back({"static", 0.0,
                 Eigen::Vector2cd(mean - kJ * spec_.pinion_mass * spec_.gravity,
                                  -mean - kJ * spec_.gear_mass * spec_.gravity)});
  // Mesh harmonics: (k_m e + c_m ė) for e = a sin(Ωt + ϕ) is Im[(k_m + jΩc_m) a e^{jϕ} e^{jΩt}];
  // Im(v) = (v − v*)/2j splits it into a forward (+Ω) and a backward (−Ω) part, and
  // F_z = F_x + j F_y combines the x and y TE of each.
  for (std::size_t i = 0; i < spec_.te_x.size(); ++i) {
    const double omega = static_cast<double>(i + 1) * mesh_omega_;
    const auto& hx = spec_.te_x[i];
    const auto& hy = spec_.te_y[i];
    const Complex fwd =
        (km + kJ * omega * cm) / (2.0 * kJ) *
        (hx.amplitude * std::polar(1.0, hx.phase) + kJ * hy.amplitude * std::polar(1.0, hy.phase));
    const Complex bwd = -(km - kJ * omega * cm) / (2.0 * kJ) *
                        (hx.amplitude * std::polar(1.0, -hx.phase) +
                         kJ * hy.amplitude * std::polar(1.0, -hy.phase));
    out.push_back({fmt::format("mesh_{}_fwd", i + 1), omega, Eigen::Vector2cd(fwd, -fwd)});
    out.push_back({fmt::format("mesh_{}_bwd", i + 1), -omega, Eigen::Vector2cd(bwd, -bwd)});
  }
  // Runouts: the force −(K − Ω²M + jΩC) W of the offsets W e^{jΩt}: the pinion's
  // e_p e^{−jφ_p} turns backward (−ω_p), the gear's e_g e^{jφ_g} forward (+ω_g).
  const auto runout = [&](double omega, const Eigen::Vector2cd& offset) -> Eigen::Vector2cd {
    const Eigen::Matrix2cd a = stiffness2().cast<Complex>() -
                               omega * omega * mass2().cast<Complex>() +
                               kJ * omega * damping2().cast<Complex>();
    return -(a * offset);
  };
  const Eigen::Vector2cd zero = Eigen::Vector2cd::Zero();
  out.push_back({"pinion_1x_fwd", pinion_omega_, zero});
  out.push_back(
      {"pinion_1x_bwd", -pinion_omega_,
       runout(-pinion_omega_,
              Eigen::Vector2cd(spec_.pinion_runout * std::polar(1.0, -spec_.pinion_runout_phase),
                               0.0))});
  out.push_back(
      {"gear_1x_fwd", gear_omega_,
       runout(gear_omega_, Eigen::Vector2cd(0.0, spec_.gear_runout *
                                                     std::polar(1.0, spec_.gear_runout_phase)))});
  out.push_back({"gear_1x_bwd", -gear_omega_, zero});
  return out;
}

}  // namespace geardyn
