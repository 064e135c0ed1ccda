/// The joint DTE estimator: weighted nonlinear least squares of every whirl component of every
/// speed at once (output error), Levenberg–Marquardt with a numerical Jacobian.
///
/// Parameters θ = (s, ln ζ_m, e_m/L, Re X_i/L, Im X_i/L, Re Y_i/L, Im Y_i/L, …, Re U_p/L,
/// Im U_p/L, Re U_g/L, Im U_g/L):
///   - s = k_ref / k_m, the mesh compliance in units of the shafts' (k_ref = k_s1 + k_s2). A stiff
///     mesh sits near s = 0, where the data constrain s linearly and without bias; ln k_m would
///     put the rigid limit at infinity and drift there (or away) with the noise. s may leave the
///     physical range in a noisy fit: its interval says so (k_m interval open to +inf);
///   - ζ_m with c_m = 2 ζ_m √(|k_m| m₁m₂/(m₁ + m₂)) (eq. 4.9–4.10): the peaks do not see c_m —
///     each harmonic's forcing factor (k_m ± jΩc_m) is absorbed by the TE phasors, and the two
///     rows of each harmonic's equations sum to an identity free of k_m and c_m — so ζ_m stays at
///     its log-normal prior (centre options.mesh_damping_ratio, relative sd
///     options.mesh_damping_ratio_sd; or the c_m prior when given), whose uncertainty the
///     covariance carries into the TE intervals;
///   - X = e_fx e^{jϕx}, Y = e_fy e^{jϕy}, U_p = e_p e^{−jϕ_p}, U_g = e_g e^{jϕ_g}, e_m, all
///     scaled by L (the largest measured peak): the peaks are linear in them.
/// Residuals (measured − modelled)/σ for the real and imaginary parts, σ = σ_c/√2 from each
/// shaft's coefficient noise (floored at 1e-8 L for noise-free data), plus the priors.
///
/// Start: for s on a grid (and the three-step estimate) the linear parameters are solved exactly
/// (one Gauss–Newton step); the best point starts Levenberg–Marquardt on all parameters, then
/// undamped Gauss–Newton steps polish. Covariance: (JᵀJ)⁻¹ by SVD (unresolved directions get an
/// infinite variance) × max(1, χ²/dof).

#include <fmt/format.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <numbers>

#include "detail/dte_internal.h"
#include "geardyn/error.h"

namespace geardyn::detail {
namespace {

using Complex = std::complex<double>;
constexpr Complex kJ(0.0, 1.0);
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// One component of the data: which speed, its name split into kind and order.
struct Component {
  std::string name;
  enum Kind {
    kStatic,
    kMeshForward,
    kMeshBackward,
    kPinionForward,
    kPinionBackward,
    kGearForward,
    kGearBackward
  } kind;
  int harmonic = 0;
};

struct Problem {
  Problem(const LateralRotorSpec& known_, const std::vector<MeasuredWhirlPeaks>& data_,
          int harmonics_, const IdentificationOptions& options_)
      : known(known_), data(data_), harmonics(harmonics_), options(options_) {}

  const LateralRotorSpec& known;
  const std::vector<MeasuredWhirlPeaks>& data;
  int harmonics;
  const IdentificationOptions& options;
  double scale = 1.0;  // L [m]
  double k_ref = 1.0;  // k_s1 + k_s2 [N/m]
  double m_eff = 1.0;  // m₁m₂/(m₁ + m₂) [kg]
  std::array<bool, 2> free{true, true};
  std::array<double, 2> fixed{0.0, 0.0};
  std::vector<Component> components;
  std::vector<std::array<double, 2>> sigma;                   // per speed and shaft, of Re/Im parts
  std::vector<std::array<std::vector<Complex>, 2>> measured;  // per speed, shaft, component

  int parameters() const { return 3 + 4 * harmonics + 4; }
  double compliance(const Eigen::VectorXd& t) const { return free[0] ? t[0] : fixed[0]; }
  double logRatio(const Eigen::VectorXd& t) const { return free[1] ? t[1] : fixed[1]; }
  double stiffness(const Eigen::VectorXd& t) const { return k_ref / compliance(t); }
  double damping(const Eigen::VectorXd& t) const {
    return dashpotFromRatio(std::exp(logRatio(t)), std::abs(stiffness(t)), m_eff);
  }
  bool stiffnessPrior() const {
    return free[0] && options.mesh_stiffness.value && options.mesh_stiffness.relative_sd > 0.0;
  }
  bool dampingPrior() const { return free[1]; }

  /// The data cannot inform c_m (see the file comment), so ln ζ_m sits at its prior's centre
  /// during the fit (ζ₀, or the ζ giving the c_m prior at this k_m); it stays a parameter of the
  /// covariance, so that its prior uncertainty reaches the other intervals.
  void anchorDamping(Eigen::VectorXd& t) const {
    if (!free[1]) return;
    if (options.mesh_damping.value) {
      t[1] =
          std::log(*options.mesh_damping.value / (2.0 * std::sqrt(std::abs(stiffness(t)) * m_eff)));
    } else {
      t[1] = std::log(options.mesh_damping_ratio);
    }
  }

  int residuals() const {
    return static_cast<int>(data.size() * 2 * components.size() * 2) + (stiffnessPrior() ? 1 : 0) +
           (dampingPrior() ? 1 : 0);
  }

  /// The model's peaks of both shafts at one speed (probe frame), in `components` order.
  std::array<std::vector<Complex>, 2> predict(const Eigen::VectorXd& t, double pinion_speed) const {
    const double km = stiffness(t), cm = damping(t);
    const double k1 = known.pinion_shaft_stiffness, k2 = known.gear_shaft_stiffness;
    const double c1 = known.pinion_shaft_damping, c2 = known.gear_shaft_damping;
    const double m1 = known.pinion_mass, m2 = known.gear_mass, g = known.gravity;
    const double wp = 2.0 * std::numbers::pi * pinion_speed;
    const double we = wp * known.pinion_teeth;
    const auto solve = [&](double omega, Complex f) {  // A(Ω) p = (f, −f) + extra
      Eigen::Matrix2cd a;
      a << k1 + km - omega * omega * m1 + kJ * omega * (c1 + cm), -km - kJ * omega * cm,
          -km - kJ * omega * cm, k2 + km - omega * omega * m2 + kJ * omega * (c2 + cm);
      return Eigen::Vector2cd(a.inverse() * Eigen::Vector2cd(f, -f));
    };
    std::array<std::vector<Complex>, 2> out;
    const double L = scale;
    const int r = 3 + 4 * harmonics;
    for (const Component& c : components) {
      Eigen::Vector2cd p = Eigen::Vector2cd::Zero();
      switch (c.kind) {
        case Component::kStatic: {
          const Complex f = km * t[2] * L * Complex(1.0, 1.0);
          Eigen::Matrix2d a;
          a << k1 + km, -km, -km, k2 + km;
          const Eigen::Vector2cd s(f - kJ * m1 * g, -f - kJ * m2 * g);
          p = a.cast<Complex>().inverse() * s;
          break;
        }
        case Component::kMeshForward:
        case Component::kMeshBackward: {
          const int i = c.harmonic - 1;
          const Complex x(t[3 + 4 * i] * L, t[4 + 4 * i] * L),
              y(t[5 + 4 * i] * L, t[6 + 4 * i] * L);
          const double omega = c.harmonic * we;
          if (c.kind == Component::kMeshForward) {
            p = solve(omega, (km + kJ * omega * cm) / (2.0 * kJ) * (x + kJ * y));
          } else {
            p = solve(-omega,
                      -(km - kJ * omega * cm) / (2.0 * kJ) * (std::conj(x) + kJ * std::conj(y)));
          }
          break;
        }
        case Component::kPinionBackward:  // η = −w exactly (see system/lateral_rotor.h)
          p(0) = -Complex(t[r] * L, t[r + 1] * L);
          break;
        case Component::kGearForward:
          p(1) = -Complex(t[r + 2] * L, t[r + 3] * L);
          break;
        default:
          break;
      }
      out[0].push_back(p(0));
      out[1].push_back(p(1));
    }
    return out;
  }

  Eigen::VectorXd residual(const Eigen::VectorXd& t) const {
    Eigen::VectorXd r(residuals());
    if (!(std::abs(compliance(t)) > 1e-300) || !(std::abs(logRatio(t)) < 600.0)) {
      r.setConstant(kNaN);
      return r;
    }
    int row = 0;
    for (std::size_t d = 0; d < data.size(); ++d) {
      const auto model = predict(t, data[d].pinion_speed);
      for (int s = 0; s < 2; ++s) {
        for (std::size_t c = 0; c < components.size(); ++c) {
          const Complex e = (measured[d][s][c] - model[s][c]) / sigma[d][s];
          r[row++] = e.real();
          r[row++] = e.imag();
        }
      }
    }
    if (stiffnessPrior()) {  // on k_m, relative: (k_m − k₀)/(sd k₀) in compliance form
      const double s0 = k_ref / *options.mesh_stiffness.value;
      r[row++] = (compliance(t) - s0) / (options.mesh_stiffness.relative_sd * s0);
    }
    if (dampingPrior()) {
      if (options.mesh_damping.value) {  // log-normal on c_m
        const double sd = std::max(options.mesh_damping.relative_sd, 1e-9);
        r[row++] = (std::log(damping(t)) - std::log(*options.mesh_damping.value)) / sd;
      } else {  // log-normal on ζ_m
        r[row++] =
            (logRatio(t) - std::log(options.mesh_damping_ratio)) / options.mesh_damping_ratio_sd;
      }
    }
    return r;
  }

  Eigen::MatrixXd jacobian(const Eigen::VectorXd& t) const {
    Eigen::MatrixXd j = Eigen::MatrixXd::Zero(residuals(), parameters());
    for (int k = 0; k < parameters(); ++k) {
      if (k < 2 && !free[k]) continue;
      // Large steps: the linear parameters are exact at any step and s, ln ζ are smooth
      // (truncation ~h²); small steps would let residual round-off (~1e-16 L/σ) swamp the
      // weakly seen columns.
      const double h = 1e-4 * std::max(1.0, std::abs(t[k]));
      Eigen::VectorXd a = t, b = t;
      a[k] += h;
      b[k] -= h;
      j.col(k) = (residual(a) - residual(b)) / (2.0 * h);
    }
    return j;
  }
};

/// The exact linear parameters (indices ≥ 2) for fixed s and ln ζ: one Gauss–Newton step.
Eigen::VectorXd solveLinearPart(const Problem& p, Eigen::VectorXd t) {
  p.anchorDamping(t);
  const Eigen::VectorXd r = p.residual(t);
  if (!r.allFinite()) return t;
  const Eigen::MatrixXd j = p.jacobian(t);
  const Eigen::VectorXd step = j.rightCols(p.parameters() - 2).colPivHouseholderQr().solve(-r);
  t.tail(p.parameters() - 2) += step;
  return t;
}

Component::Kind kindOf(const std::string& name) {
  if (name == "pinion_1x_fwd") return Component::kPinionForward;
  if (name == "pinion_1x_bwd") return Component::kPinionBackward;
  if (name == "gear_1x_fwd") return Component::kGearForward;
  return Component::kGearBackward;
}

/// The components compared, their measured values and weights, and the priors that fix a
/// parameter (p.scale set: the largest measured peak).
void setUpProblem(Problem& p) {
  p.k_ref = p.known.pinion_shaft_stiffness + p.known.gear_shaft_stiffness;
  p.m_eff = meshDampingMass(p.known.pinion_mass, p.known.gear_mass);
  p.components.push_back({"static", Component::kStatic, 0});
  for (int i = 1; i <= p.harmonics; ++i) {
    p.components.push_back({fmt::format("mesh_{}_fwd", i), Component::kMeshForward, i});
    p.components.push_back({fmt::format("mesh_{}_bwd", i), Component::kMeshBackward, i});
  }
  for (const char* n : {"pinion_1x_fwd", "pinion_1x_bwd", "gear_1x_fwd", "gear_1x_bwd"})
    p.components.push_back({n, kindOf(n), 0});
  for (const auto& d : p.data) {
    std::array<double, 2> s;
    std::array<std::vector<Complex>, 2> values;
    for (int k = 0; k < 2; ++k) {
      s[k] = std::max(d.coefficient_sigma[k], 1e-8 * p.scale) / std::sqrt(2.0);
      for (const auto& c : p.components) values[k].push_back(peakOf(d, k, c.name));
    }
    p.sigma.push_back(s);
    p.measured.push_back(values);
  }
  const auto& ks = p.options.mesh_stiffness;
  if (ks.value) {
    if (!(*ks.value > 0.0) || !(ks.relative_sd >= 0.0)) {
      throw InputError("prior.mesh_stiffness",
                       fmt::format("{:g} (relative sd {:g})", *ks.value, ks.relative_sd),
                       "a value > 0 and a relative standard deviation >= 0");
    }
    if (ks.relative_sd == 0.0) {
      p.free[0] = false;
      p.fixed[0] = p.k_ref / *ks.value;
    }
  }
  const auto& cs = p.options.mesh_damping;
  if (cs.value && (!(*cs.value > 0.0) || !(cs.relative_sd >= 0.0))) {
    throw InputError("prior.mesh_damping",
                     fmt::format("{:g} (relative sd {:g})", *cs.value, cs.relative_sd),
                     "a value > 0 and a relative standard deviation >= 0");
  }
}

/// Starting point: the best of a grid in the compliance s and the three-step estimate `start`.
Eigen::VectorXd bestStart(Problem& p, const DteIdentification& start) {
  const int n = p.parameters();
  const auto& ks = p.options.mesh_stiffness;
  const auto& cs = p.options.mesh_damping;
  const IdentificationOptions& options = p.options;
  std::vector<double> candidates;
  if (start.mesh_stiffness.value > 0.0 && std::isfinite(start.mesh_stiffness.value))
    candidates.push_back(p.k_ref / start.mesh_stiffness.value);
  if (ks.value) candidates.push_back(p.k_ref / *ks.value);
  for (int g = 0; g <= 24; ++g) candidates.push_back(std::pow(10.0, 2.0 - g * 8.0 / 24.0));
  Eigen::VectorXd best;
  double best_cost = std::numeric_limits<double>::infinity();
  for (double s : candidates) {
    Eigen::VectorXd t = Eigen::VectorXd::Zero(n);
    t[0] = p.free[0] ? s : p.fixed[0];
    t[1] = std::log(options.mesh_damping_ratio);
    if (cs.value) {  // ζ that gives the prior's c_m at this stiffness
      t[1] = std::log(*cs.value / (2.0 * std::sqrt(p.k_ref / std::abs(t[0]) * p.m_eff)));
    }
    t = solveLinearPart(p, t);
    const double cost = p.residual(t).squaredNorm();
    if (cost < best_cost) {
      best_cost = cost;
      best = t;
    }
  }
  if (best.size() == 0) {
    throw InputError("input.spectra", "(no finite start)", "the data give no finite fit");
  }

  return best;
}

/// Levenberg–Marquardt from `t`, then undamped Gauss–Newton polish while it does not raise the
/// cost: the fitted parameters, with r.iterations and r.converged, `res` and `cost` at them.
Eigen::VectorXd leastSquares(Problem& p, const Eigen::VectorXd& best, DteIdentification& r,
                             Eigen::VectorXd& res, double& cost) {
  const int n = p.parameters();
  const IdentificationOptions& options = p.options;
  Eigen::VectorXd t = best;
  res = p.residual(t);
  cost = res.squaredNorm();
  double lambda = 1e-3;
  r.converged = false;
  for (r.iterations = 0; r.iterations < options.max_iterations; ++r.iterations) {
    if (options.progress) options.progress(r.iterations, options.max_iterations);
    const Eigen::MatrixXd j = p.jacobian(t);
    const Eigen::MatrixXd jtj = j.transpose() * j;
    const Eigen::VectorXd g = j.transpose() * res;
    bool improved = false;
    for (int attempt = 0; attempt < 30 && !improved; ++attempt) {
      Eigen::MatrixXd a = jtj;
      for (int k = 0; k < n; ++k) a(k, k) += lambda * std::max(jtj(k, k), 1e-12);
      const Eigen::VectorXd step = a.ldlt().solve(-g);
      Eigen::VectorXd trial = t + step;
      p.anchorDamping(trial);
      const Eigen::VectorXd trial_res = p.residual(trial);
      const double trial_cost = trial_res.squaredNorm();
      if (std::isfinite(trial_cost) && trial_cost < cost) {
        t = trial;
        res = trial_res;
        cost = trial_cost;
        lambda = std::max(lambda / 10.0, 1e-12);
        improved = true;
        if (step.norm() < 1e-11 * (1.0 + t.norm())) r.converged = true;
      } else {
        lambda *= 10.0;
      }
    }
    if (!improved) {
      r.converged = true;  // no descent at any damping: a minimum
      break;
    }
    if (r.converged) break;
  }
  // Polish with undamped Gauss–Newton steps while they do not raise the cost.
  for (int polish = 0; polish < 5; ++polish) {
    const Eigen::VectorXd step = p.jacobian(t).completeOrthogonalDecomposition().solve(-res);
    Eigen::VectorXd trial = t + step;
    p.anchorDamping(trial);
    const Eigen::VectorXd trial_res = p.residual(trial);
    if (!(trial_res.squaredNorm() <= cost)) break;
    t = trial;
    res = trial_res;
    cost = res.squaredNorm();
    if (step.norm() < 1e-14 * (1.0 + t.norm())) break;
  }

  return t;
}

/// The parameters' covariance: the SVD pseudo-inverse of JᵀJ at `t`, inflated by χ²/dof when
/// above 1, rows of fixed parameters zero; r.chi_square and r.degrees_of_freedom set.
Eigen::MatrixXd parameterCovariance(Problem& p, const Eigen::VectorXd& t,
                                    const Eigen::VectorXd& res, double cost, DteIdentification& r) {
  const int n = p.parameters();
  const Eigen::MatrixXd j = p.jacobian(t);
  const int free_count = n - (p.free[0] ? 0 : 1) - (p.free[1] ? 0 : 1);
  r.chi_square = cost;
  r.degrees_of_freedom = static_cast<int>(res.size()) - free_count;
  const double inflate =
      r.degrees_of_freedom > 0 ? std::max(1.0, cost / r.degrees_of_freedom) : 1.0;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(j, Eigen::ComputeThinV);
  const Eigen::VectorXd sv = svd.singularValues();
  Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(n, n);
  const double cutoff = sv.size() ? sv[0] * 1e-13 : 0.0;
  for (int k = 0; k < sv.size(); ++k) {
    const Eigen::VectorXd v = svd.matrixV().col(k);
    cov += (sv[k] > cutoff ? 1.0 / (sv[k] * sv[k]) : 1e300) * v * v.transpose();
  }
  cov *= inflate;
  for (int k = 0; k < 2; ++k)
    if (!p.free[k]) cov.row(k).setZero(), cov.col(k).setZero();

  return cov;
}

/// The identified values with their 95 % intervals (k_m, c_m, mean TE, TE harmonics, runouts).
void identifiedValues(Problem& p, const Eigen::VectorXd& t, const Eigen::MatrixXd& cov,
                      DteIdentification& r) {
  const IdentificationOptions& options = p.options;
  const auto& ks = p.options.mesh_stiffness;
  const int harmonics = p.harmonics;
  const double w = options.identifiable_width;
  // k_m = k_ref / s: the interval of s mapped; open to +inf when it reaches s <= 0.
  {
    const double s = p.compliance(t), sd = std::sqrt(std::max(0.0, cov(0, 0)));
    IdentifiedValue& v = r.mesh_stiffness;
    v.value = s > 0.0 ? p.k_ref / s : INFINITY;
    const double lo = s - 1.96 * sd, hi = s + 1.96 * sd;
    v.low = hi > 0.0 ? p.k_ref / hi : -INFINITY;
    v.high = lo > 0.0 ? p.k_ref / lo : INFINITY;
    v.identifiable = !p.free[0] || (std::isfinite(v.high) && std::isfinite(v.value) &&
                                    (v.high - v.low) / 2.0 <= w * v.value);
    if (!p.free[0]) v.value = v.low = v.high = *ks.value;
  }
  // c_m: ln c = ln 2ζ + ½ ln(k_ref m_eff) − ½ ln |s|, delta method in (s, ln ζ).
  {
    const double s = p.compliance(t);
    const Eigen::Vector2d g(-0.5 / s, 1.0);
    const double sd = std::sqrt(std::max(0.0, g.dot(cov.block<2, 2>(0, 0) * g)));
    IdentifiedValue& v = r.mesh_damping;
    v.value = p.damping(t);
    v.low = v.value * std::exp(-1.96 * std::min(sd, 300.0));
    v.high = sd > 300.0 ? INFINITY : v.value * std::exp(1.96 * sd);
    v.identifiable = std::isfinite(v.high) && (v.high - v.low) / 2.0 <= w * v.value;
  }
  const double L = p.scale;
  r.mean_te = fromLinear(t[2] * L, std::sqrt(std::max(0.0, cov(2, 2))) * L, w, true);
  for (int i = 0; i < harmonics; ++i) {
    for (int xy = 0; xy < 2; ++xy) {
      const int k = 3 + 4 * i + 2 * xy;
      const Eigen::Matrix2d c = cov.block<2, 2>(k, k) * (L * L);
      (xy == 0 ? r.te_x : r.te_y).push_back(phasorFrom({t[k] * L, t[k + 1] * L}, c, w, false));
    }
  }
  const int k = 3 + 4 * harmonics;
  r.pinion_runout = phasorFrom({t[k] * L, t[k + 1] * L}, cov.block<2, 2>(k, k) * (L * L), w, true);
  r.gear_runout =
      phasorFrom({t[k + 2] * L, t[k + 3] * L}, cov.block<2, 2>(k + 2, k + 2) * (L * L), w, false);
}

}  // namespace

DteIdentification jointIdentification(const LateralRotorSpec& known,
                                      const std::vector<MeasuredWhirlPeaks>& data, int harmonics,
                                      const IdentificationOptions& options,
                                      const DteIdentification& start) {
  double largest = 0.0;
  for (const auto& d : data)
    for (int s = 0; s < 2; ++s)
      for (const auto& c : d.peaks[s]) largest = std::max(largest, std::abs(c.value));
  if (!(largest > 0.0)) {
    throw InputError("input.spectra", "all peaks zero", "nothing to identify from");
  }
  if (!(options.mesh_damping_ratio > 0.0) || !(options.mesh_damping_ratio_sd > 0.0)) {
    throw InputError(
        "identify.mesh_damping_ratio",
        fmt::format("{:g} (sd {:g})", options.mesh_damping_ratio, options.mesh_damping_ratio_sd),
        "the damping-ratio prior needs a ratio > 0 and a relative sd > 0 (fix c_m "
        "with prior.mesh_damping instead)");
  }
  Problem p{known, data, harmonics, options};
  p.scale = largest;
  setUpProblem(p);
  DteIdentification r;
  r.method = IdentificationMethod::kJoint;
  r.spec = known;
  Eigen::VectorXd res;
  double cost = 0.0;
  const Eigen::VectorXd t = leastSquares(p, bestStart(p, start), r, res, cost);
  identifiedValues(p, t, parameterCovariance(p, t, res, cost, r), r);
  writeBack(r);
  if (!std::isfinite(r.spec.mesh_stiffness) || !(r.spec.mesh_stiffness > 0.0)) {
    // The fit's compliance is not physical (≤ 0): the model to re-simulate uses a rigid-like
    // mesh at the interval's finite end.
    r.spec.mesh_stiffness = std::isfinite(r.mesh_stiffness.low) && r.mesh_stiffness.low > 0.0
                                ? r.mesh_stiffness.low
                                : 1e6 * p.k_ref;
    r.spec.mesh_damping = dashpotFromRatio(std::exp(p.logRatio(t)), r.spec.mesh_stiffness, p.m_eff);
  }
  r.message = fmt::format(
      "joint weighted least squares: {} iterations, chi^2 [-] = {:.4g} for {} degrees of "
      "freedom{}",
      r.iterations, r.chi_square, r.degrees_of_freedom,
      r.converged ? "" : " (iteration limit reached)");
  return r;
}

}  // namespace geardyn::detail
