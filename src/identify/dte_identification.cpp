/// Shared parts of the DTE identification: data checks, the forward model, the three-step
/// algorithm of Rao 2023 §4.6 and the dispatch. The joint estimator is in
/// joint_identification.cpp.
///
/// The three steps, re-derived from the complex form of our model (z = x + jy, probe frame,
/// A(Ω) = K₂ − Ω²M₂ + jΩC₂, measured peaks p = (p₁, p₂)):
///   1. static (eq. 4.3): A(0) p₀ = k_m e_m (1 + j)(1, −1) − j g (m₁, m₂), linear in
///      (k_m, k_m e_m): 4 real equations per speed;
///   2. c_m = 2 ζ_m √(k_m m₁m₂/(m₁ + m₂)) (eqs. 4.9–4.10); per mesh harmonic i, with
///      X = e_fx e^{jϕx}, Y = e_fy e^{jϕy}:
///        forward  A(+Ω) p = ±(k_m + jΩc_m)/(2j) (X + jY),
///        backward A(−Ω) p = ∓(k_m − jΩc_m)/(2j) (X* + jY*),
///      8 real equations per speed in (Re X, Im X, Re Y, Im Y) (eq. 4.11; the printed 4.5–4.8
///      agree with this, reading "iω_e" as harmonic i times ω_e);
///   3. runouts (eqs. 4.15–4.17): A(−ω_p) (p + (U_p, 0)) = 0 with U_p = e_p e^{−jϕ_p} and
///      A(+ω_g) (p + (0, U_g)) = 0 with U_g = e_g e^{jϕ_g}, 4 real equations each.
/// Corrections: eqs. 4.14 and 4.20 take phases with acos/asin, which loses the quadrant; we
/// use atan2. Each step's 95 % intervals come from its own linear least squares
/// (σ̂² (AᵀA)⁻¹, σ̂² the residual variance; the earlier steps' errors are not propagated, as in
/// the published algorithm), so they are indicative only.

#include "geardyn/identify/dte_identification.h"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>

#include "detail/dte_internal.h"
#include "geardyn/error.h"
#include "geardyn/signal/gear_whirl.h"
#include "geardyn/solvers/rotor_response.h"

namespace geardyn {
namespace detail {

using Complex = std::complex<double>;

const std::complex<double>& peakOf(const MeasuredWhirlPeaks& data, int shaft,
                                   const std::string& name) {
  for (const auto& c : data.peaks[shaft])
    if (c.name == name) return c.value;
  throw InputError(
      "spectrum",
      fmt::format("{} shaft, {:g} rev/s", shaft == 0 ? "pinion" : "gear", data.pinion_speed),
      fmt::format("has no component '{}'", name));
}

int harmonicsIn(const MeasuredWhirlPeaks& data) {
  int n = 0;
  while (true) {
    const std::string name = fmt::format("mesh_{}_fwd", n + 1);
    bool found = false;
    for (const auto& c : data.peaks[0]) found = found || c.name == name;
    if (!found) return n;
    ++n;
  }
}

Eigen::Matrix2cd systemMatrix(const LateralRotorSpec& spec, double omega) {
  const LateralRotorModel model(spec);
  return model.stiffness2().cast<Complex>() - omega * omega * model.mass2().cast<Complex>() +
         Complex(0.0, omega) * model.damping2().cast<Complex>();
}

IdentifiedValue fromLinear(double value, double sd, double width, bool relative) {
  IdentifiedValue v;
  v.value = value;
  v.low = value - 1.96 * sd;
  v.high = value + 1.96 * sd;
  v.identifiable = std::isfinite(sd) && 1.96 * sd <= width * (relative ? std::abs(value) : 1.0);
  return v;
}

IdentifiedPhasor phasorFrom(Complex c, const Eigen::Matrix2d& covariance, double width,
                            bool conjugate_phase) {
  // Delta method: a = |c|, ϕ = arg c (or −arg c for a runout written e e^{−jϕ}).
  const double a = std::abs(c);
  IdentifiedPhasor out;
  Eigen::Vector2d ga(c.real() / a, c.imag() / a);
  Eigen::Vector2d gp(-c.imag() / (a * a), c.real() / (a * a));
  const double sa = a > 0 ? std::sqrt(std::max(0.0, ga.dot(covariance * ga))) : INFINITY;
  const double sp = a > 0 ? std::sqrt(std::max(0.0, gp.dot(covariance * gp))) : INFINITY;
  out.amplitude = fromLinear(a, sa, width, true);
  out.phase = fromLinear(conjugate_phase ? -std::arg(c) : std::arg(c), sp, width, false);
  out.phase.identifiable = out.phase.identifiable && out.amplitude.identifiable;
  return out;
}

void writeBack(DteIdentification& r) {
  r.spec.mesh_stiffness = r.mesh_stiffness.value;
  r.spec.mesh_damping = std::max(0.0, r.mesh_damping.value);
  r.spec.mean_te = r.mean_te.value;
  r.spec.te_x.clear();
  r.spec.te_y.clear();
  for (std::size_t i = 0; i < r.te_x.size(); ++i) {
    r.spec.te_x.push_back({r.te_x[i].amplitude.value, r.te_x[i].phase.value});
    r.spec.te_y.push_back({r.te_y[i].amplitude.value, r.te_y[i].phase.value});
  }
  r.spec.pinion_runout = r.pinion_runout.amplitude.value;
  r.spec.pinion_runout_phase = r.pinion_runout.phase.value;
  r.spec.gear_runout = r.gear_runout.amplitude.value;
  r.spec.gear_runout_phase = r.gear_runout.phase.value;
}

namespace {

/// Real least squares A x = b: solution, covariance σ̂²(AᵀA)⁻¹ (σ̂² = |r|²/(m − n), or 0 when
/// the system is square).
struct LinearFit {
  Eigen::VectorXd x;
  Eigen::MatrixXd covariance;
};

LinearFit solveLinear(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, const char* step) {
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  if (qr.rank() < a.cols()) {
    throw InputError("identify.method", "three_step",
                     fmt::format("{}: the equations do not determine the unknowns (rank {} < {})",
                                 step, qr.rank(), a.cols()));
  }
  LinearFit fit;
  fit.x = qr.solve(b);
  const double dof = static_cast<double>(a.rows() - a.cols());
  const double variance = dof > 0 ? (a * fit.x - b).squaredNorm() / dof : 0.0;
  fit.covariance = variance * (a.transpose() * a).inverse();
  return fit;
}

/// Appends the real and imaginary parts of Σ_k u_k col_k = rhs (complex) as two real rows.
void addComplexRow(std::vector<Eigen::VectorXd>& rows, std::vector<double>& rhs,
                   const std::vector<Complex>& columns, Complex value) {
  Eigen::VectorXd re(columns.size()), im(columns.size());
  for (std::size_t k = 0; k < columns.size(); ++k) {
    re[k] = columns[k].real();
    im[k] = columns[k].imag();
  }
  rows.push_back(re);
  rhs.push_back(value.real());
  rows.push_back(im);
  rhs.push_back(value.imag());
}

LinearFit solveRows(const std::vector<Eigen::VectorXd>& rows, const std::vector<double>& rhs,
                    const char* step) {
  Eigen::MatrixXd a(rows.size(), rows.front().size());
  Eigen::VectorXd b(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    a.row(i) = rows[i].transpose();
    b[i] = rhs[i];
  }
  return solveLinear(a, b, step);
}

DteIdentification threeStep(const LateralRotorSpec& known,
                            const std::vector<MeasuredWhirlPeaks>& data, int harmonics,
                            const IdentificationOptions& options) {
  DteIdentification r;
  r.method = IdentificationMethod::kThreeStep;
  r.spec = known;
  const double m1 = known.pinion_mass, m2 = known.gear_mass, g = known.gravity;
  const double w = options.identifiable_width;

  // Step 1: (k_m, k_m e_m) from the static components.
  std::vector<Eigen::VectorXd> rows;
  std::vector<double> rhs;
  for (const auto& d : data) {
    const Complex p1 = peakOf(d, 0, "static"), p2 = peakOf(d, 1, "static");
    // k_m (p₁ − p₂) − (1 + j) k_m e_m = −k_s1 p₁ − j m₁ g
    addComplexRow(rows, rhs, {p1 - p2, Complex(-1.0, -1.0)},
                  -known.pinion_shaft_stiffness * p1 - Complex(0.0, m1 * g));
    // k_m (p₂ − p₁) + (1 + j) k_m e_m = −k_s2 p₂ − j m₂ g
    addComplexRow(rows, rhs, {p2 - p1, Complex(1.0, 1.0)},
                  -known.gear_shaft_stiffness * p2 - Complex(0.0, m2 * g));
  }
  const LinearFit s1 = solveRows(rows, rhs, "step 1 (static)");
  const double km = s1.x[0], kme = s1.x[1];
  r.mesh_stiffness = fromLinear(km, std::sqrt(s1.covariance(0, 0)), w, true);
  // e_m = (k_m e_m)/k_m, first-order propagation.
  Eigen::Vector2d ge(-kme / (km * km), 1.0 / km);
  r.mean_te = fromLinear(kme / km, std::sqrt(std::max(0.0, ge.dot(s1.covariance * ge))), w, true);
  if (!(km > 0.0)) {
    r.converged = false;
    r.message = fmt::format(
        "step 1 gave a non-positive mesh stiffness ({:.4g} N/m): the static components cannot "
        "resolve k_m (noise); steps 2-3 use |k_m|",
        km);
  }
  LateralRotorSpec s = known;
  s.mesh_stiffness = std::max(std::abs(km), 1e-12);
  s.mesh_damping = dashpotFromRatio(options.mesh_damping_ratio, s.mesh_stiffness,
                                    meshDampingMass(m1, m2));  // eqs. 4.9–4.10
  r.mesh_damping = {s.mesh_damping, s.mesh_damping, s.mesh_damping, true};

  // Step 2: X_i, Y_i from the mesh harmonics.
  const Complex j(0.0, 1.0);
  for (int i = 1; i <= harmonics; ++i) {
    if (options.progress) options.progress(i - 1, harmonics);
    rows.clear();
    rhs.clear();
    for (const auto& d : data) {
      s.pinion_speed = d.pinion_speed;
      const double omega = i * 2.0 * std::numbers::pi * d.pinion_speed * known.pinion_teeth;
      for (int dir : {+1, -1}) {
        const std::string name = fmt::format("mesh_{}_{}", i, dir > 0 ? "fwd" : "bwd");
        const Eigen::Vector2cd p(peakOf(d, 0, name), peakOf(d, 1, name));
        const Eigen::Vector2cd ap = systemMatrix(s, dir * omega) * p;
        // Unknowns u = (Re X, Im X, Re Y, Im Y): forward X + jY, backward X* + jY*.
        const std::vector<Complex> q =
            dir > 0 ? std::vector<Complex>{1.0, j, j, -1.0} : std::vector<Complex>{1.0, -j, j, 1.0};
        const Complex factor = dir > 0
                                   ? (s.mesh_stiffness + j * omega * s.mesh_damping) / (2.0 * j)
                                   : -(s.mesh_stiffness - j * omega * s.mesh_damping) / (2.0 * j);
        for (int shaft = 0; shaft < 2; ++shaft) {
          std::vector<Complex> columns;
          for (const Complex& e : q) columns.push_back((shaft == 0 ? 1.0 : -1.0) * factor * e);
          addComplexRow(rows, rhs, columns, ap(shaft));
        }
      }
    }
    const LinearFit s2 = solveRows(rows, rhs, "step 2 (mesh harmonics)");
    r.te_x.push_back(phasorFrom({s2.x[0], s2.x[1]}, s2.covariance.block<2, 2>(0, 0), w, false));
    r.te_y.push_back(phasorFrom({s2.x[2], s2.x[3]}, s2.covariance.block<2, 2>(2, 2), w, false));
  }

  // Step 3: runouts from the pinion (backward) and gear (forward) 1× components.
  for (int which = 0; which < 2; ++which) {
    rows.clear();
    rhs.clear();
    for (const auto& d : data) {
      s.pinion_speed = d.pinion_speed;
      const double wp = 2.0 * std::numbers::pi * d.pinion_speed;
      const double omega =
          which == 0 ? -wp : wp * known.pinion_teeth / static_cast<double>(known.gear_teeth);
      const std::string name = which == 0 ? "pinion_1x_bwd" : "gear_1x_fwd";
      const Eigen::Vector2cd p(peakOf(d, 0, name), peakOf(d, 1, name));
      const Eigen::Matrix2cd a = systemMatrix(s, omega);
      const Eigen::Vector2cd ap = a * p;
      for (int shaft = 0; shaft < 2; ++shaft) {
        // a(shaft, which) U = −(A p)_shaft, U = Re U + j Im U.
        addComplexRow(rows, rhs, {a(shaft, which), j * a(shaft, which)}, -ap(shaft));
      }
    }
    const LinearFit s3 = solveRows(rows, rhs, "step 3 (runouts)");
    (which == 0 ? r.pinion_runout : r.gear_runout) =
        phasorFrom({s3.x[0], s3.x[1]}, s3.covariance, w, which == 0);
  }
  writeBack(r);
  if (r.message.empty()) r.message = "three-step least squares (Rao 2023 §4.6)";
  return r;
}

}  // namespace
}  // namespace detail

std::array<std::vector<WhirlComponent>, 2> whirlPeaksOf(
    const std::vector<RotorWhirlResponse>& parts) {
  std::array<std::vector<WhirlComponent>, 2> out;
  for (int s = 0; s < 2; ++s)
    for (const auto& p : parts)
      out[s].push_back({p.name, p.omega / (2.0 * std::numbers::pi), p.response(s)});
  return out;
}

std::array<std::vector<WhirlComponent>, 2> modelWhirlPeaks(const LateralRotorSpec& spec) {
  return whirlPeaksOf(solveRotorFrequencyResponse(LateralRotorModel(spec)));
}

DteIdentification identifyDte(const LateralRotorSpec& known,
                              const std::vector<MeasuredWhirlPeaks>& data,
                              const IdentificationOptions& options) {
  if (data.empty()) throw InputError("input.spectra", "[]", "give at least one spectrum");
  int available = detail::harmonicsIn(data.front());
  for (const auto& d : data) {
    available = std::min(available, detail::harmonicsIn(d));
    if (!(d.pinion_speed > 0.0) || !std::isfinite(d.pinion_speed)) {
      throw InputError("spectrum pinion speed", fmt::format("{:g}", d.pinion_speed),
                       "must be > 0 [rev/s]");
    }
  }
  const int harmonics = options.harmonics < 0 ? available : options.harmonics;
  if (harmonics > available) {
    throw InputError("identify.harmonics", fmt::format("{}", options.harmonics),
                     fmt::format("the spectra hold {} mesh harmonics", available));
  }
  LateralRotorSpec base = known;
  base.te_x.assign(harmonics, {});
  base.te_y.assign(harmonics, {});
  base.validate();
  if (options.method == IdentificationMethod::kThreeStep) {
    return detail::threeStep(base, data, harmonics, options);
  }
  return detail::jointIdentification(base, data, harmonics, options,
                                     detail::threeStep(base, data, harmonics, options));
}

}  // namespace geardyn
