#include "geardyn/solvers/rotor_response.h"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>

#include "geardyn/error.h"

namespace geardyn {
namespace {

using State = std::array<double, 8>;  // (η, η̇)
using Complex = std::complex<double>;

/// The state is scaled, s = (η / L, η̇ / (L ω)), with L the response scale and ω the highest
/// forcing frequency, so that one absolute tolerance means the same for displacements and
/// velocities (as a per-component atol = tol·(L, Lω) would in scipy's solve_ivp):
/// ṡ = (ω s_v, M⁻¹(f(t) − C η̇ − K η) / (L ω)); M is diagonal. No allocation.
struct RotorOde {
  const LateralRotorModel* model;
  Eigen::Vector4d inverse_mass;
  double length, omega;
  long long* evaluations;

  void operator()(const State& s, State& ds, double t) const {
    ++*evaluations;
    const Eigen::Vector4d eta = Eigen::Map<const Eigen::Vector4d>(s.data()) * length;
    const Eigen::Vector4d rate = Eigen::Map<const Eigen::Vector4d>(s.data() + 4) * (length * omega);
    Eigen::Vector4d a = model->force(t);
    a.noalias() -= model->damping() * rate;
    a.noalias() -= model->stiffness() * eta;
    Eigen::Map<Eigen::Vector4d>(ds.data()) =
        Eigen::Map<const Eigen::Vector4d>(s.data() + 4) * omega;
    Eigen::Map<Eigen::Vector4d>(ds.data() + 4) = a.cwiseProduct(inverse_mass) / (length * omega);
  }
};

RotorOde odeOf(const LateralRotorModel& model, long long* evaluations) {
  return {&model, model.mass().diagonal().cwiseInverse(), rotorResponseScale(model),
          rotorVelocityFrequency(model), evaluations};
}

/// Integrates from rest and hands every sample to `observe(index, η)`; returns the steps taken.
template <class Observer>
long long integrateOnGrid(const LateralRotorModel& model, const std::vector<double>& times,
                          double rtol, double atol, long long* evaluations, Observer observe,
                          const ProgressCallback& progress = {}) {
  namespace odeint = boost::numeric::odeint;
  State s{};
  auto dense = odeint::make_dense_output(atol, rtol, odeint::runge_kutta_dopri5<State>());
  std::size_t index = 0;
  const double scale = rotorResponseScale(model);
  const double first_step = 0.05 / std::max(model.meshOmega(), model.pinionOmega());
  return static_cast<long long>(odeint::integrate_times(
      dense, odeOf(model, evaluations), s, times.begin(), times.end(), first_step,
      [&](const State& state, double t) {
        observe(index++, Eigen::Vector4d(state[0], state[1], state[2], state[3]) * scale);
        if (progress && index % 1024 == 0) progress(t, times.back());
      }));
}

}  // namespace

double rotorResponseScale(const LateralRotorModel& model) {
  const auto& s = model.spec();
  double scale = std::max({std::abs(s.mean_te), s.pinion_runout, s.gear_runout,
                           s.pinion_mass * s.gravity / s.pinion_shaft_stiffness,
                           s.gear_mass * s.gravity / s.gear_shaft_stiffness});
  for (std::size_t i = 0; i < s.te_x.size(); ++i)
    scale = std::max({scale, s.te_x[i].amplitude, s.te_y[i].amplitude});
  return scale > 0.0 ? scale : 1e-6;
}

double rotorVelocityFrequency(const LateralRotorModel& model) {
  return model.meshOmega() * std::max(1, model.harmonics());
}

void RotorTimeOptions::validate() const {
  if (!(duration > 0.0) || !std::isfinite(duration)) {
    throw InputError("time.duration", fmt::format("{:g}", duration), "must be finite and > 0 [s]");
  }
  if (samples < 16 || samples > 200'000'000) {
    throw InputError("time.samples", fmt::format("{}", samples), "an integer in [16, 2e8]");
  }
  if (!(relative_tolerance > 0.0 && relative_tolerance < 0.1)) {
    throw InputError("time.relative_tolerance", fmt::format("{:g}", relative_tolerance),
                     "a number in (0, 0.1)");
  }
  if (!(absolute_tolerance > 0.0) || !std::isfinite(absolute_tolerance)) {
    throw InputError("time.absolute_tolerance", fmt::format("{:g}", absolute_tolerance),
                     "must be finite and > 0");
  }
  if (!(steady_tolerance > 0.0 && steady_tolerance < 1.0)) {
    throw InputError("time.steady_tolerance", fmt::format("{:g}", steady_tolerance),
                     "a number in (0, 1)");
  }
}

std::string toString(RotorTimeStatus status) {
  switch (status) {
    case RotorTimeStatus::kSteadyState:
      return "steady_state";
    case RotorTimeStatus::kTransient:
      return "transient_not_decayed";
    case RotorTimeStatus::kNonFinite:
      return "non_finite";
  }
  return "unknown";
}

RotorTimeResponse solveRotorTimeResponse(const LateralRotorModel& model,
                                         const RotorTimeOptions& options) {
  options.validate();
  RotorTimeResponse out;
  out.common_period = model.commonPeriod();
  double dt = options.duration / static_cast<double>(options.samples - 1);
  long long count = options.samples;
  if (options.align_to_common_period) {
    out.samples_per_period = std::max<long long>(1, std::llround(out.common_period / dt));
    dt = out.common_period / static_cast<double>(out.samples_per_period);
    count = static_cast<long long>(std::floor(options.duration / dt * (1.0 + 1e-12))) + 1;
  }
  out.sample_rate = 1.0 / dt;
  out.t.resize(count);
  for (long long k = 0; k < count; ++k) out.t[k] = k * dt;
  out.eta.resize(count);
  // On a grid not aligned to T_c the periodicity check needs η(t_k + T_c) off the grid: the
  // integrator's dense output gives it, on the merged grid (tagged: ≥ count = shifted sample).
  std::vector<Eigen::Vector4d> shifted;
  if (out.samples_per_period == 0) {
    std::vector<std::pair<double, long long>> merged;
    for (long long k = 0; k < count; ++k) {
      merged.push_back({out.t[k], k});
      if (out.t[k] + out.common_period <= out.t.back()) {
        merged.push_back({out.t[k] + out.common_period, count + k});
      }
    }
    std::sort(merged.begin(), merged.end());
    std::vector<double> times;
    for (const auto& m : merged) times.push_back(m.first);
    shifted.resize(merged.size());
    out.steps = integrateOnGrid(
        model, times, options.relative_tolerance, options.absolute_tolerance, &out.rhs_evaluations,
        [&](std::size_t i, const Eigen::Vector4d& eta) {
          const long long tag = merged[i].second;
          (tag < count ? out.eta[tag] : shifted[tag - count]) = eta;
        },
        options.progress);
    shifted.resize(static_cast<std::size_t>(std::count_if(
        merged.begin(), merged.end(), [&](const auto& m) { return m.second >= count; })));
  } else {
    out.steps = integrateOnGrid(
        model, out.t, options.relative_tolerance, options.absolute_tolerance, &out.rhs_evaluations,
        [&](std::size_t i, const Eigen::Vector4d& eta) { out.eta[i] = eta; }, options.progress);
  }

  double scale = 0.0;
  for (const auto& eta : out.eta) {
    if (!eta.allFinite()) {
      out.status = RotorTimeStatus::kNonFinite;
      out.message = "the integration produced non-finite values";
      return out;
    }
  }
  // Transient: z(t + T_c) = z(t) once the homogeneous part has decayed (the steady state is
  // T_c-periodic). Scale: the largest |η| over the last common period.
  const long long n = out.samples_per_period > 0
                          ? out.samples_per_period
                          : std::llround(out.common_period * out.sample_rate);
  if (n >= count) {
    out.status = RotorTimeStatus::kTransient;
    out.message = fmt::format(
        "the record ({:g} s) is shorter than one common period ({:g} s): lengthen time.duration",
        out.t.back(), out.common_period);
    return out;
  }
  for (long long k = count - 1 - n; k < count; ++k)
    scale = std::max(scale, out.eta[k].cwiseAbs().maxCoeff());
  const double limit = options.steady_tolerance * scale;
  long long last_bad = -1;
  const long long comparable = shifted.empty() ? count - n : static_cast<long long>(shifted.size());
  for (long long k = 0; k < comparable; ++k) {
    const Eigen::Vector4d& later = shifted.empty() ? out.eta[k + n] : shifted[k];
    if ((later - out.eta[k]).cwiseAbs().maxCoeff() > limit) last_bad = k;
  }
  out.transient_end = last_bad + 1;
  if (out.samples_per_period == 0) {
    // Not aligned: no whole-period window exists on this grid; report the steady span.
    out.window_begin = out.transient_end;
    out.window_end = count;
    out.window_periods = 0;
  } else {
    // The latest whole common periods (farthest from the transient), ending at the last sample.
    out.window_periods = static_cast<int>((count - out.transient_end) / n);
    out.window_end = count;
    out.window_begin = count - static_cast<long long>(out.window_periods) * n;
  }
  if (last_bad + 1 >= comparable || (out.samples_per_period > 0 && out.window_periods < 1)) {
    out.status = RotorTimeStatus::kTransient;
    out.message = fmt::format(
        "the transient has not decayed to {:g} of the response within {:g} s "
        "(one common period T_c = {:g} s must follow it): lengthen time.duration",
        options.steady_tolerance, out.t.back(), out.common_period);
    return out;
  }
  out.message =
      out.samples_per_period > 0
          ? fmt::format("steady after {:.4g} s; {} common period(s) of {:.6g} s analysed",
                        out.t[out.transient_end], out.window_periods, out.common_period)
          : fmt::format(
                "steady after {:.4g} s; the remaining {:.4g} s analysed (grid not aligned "
                "to the common period: least squares)",
                out.t[out.transient_end], out.t.back() - out.t[out.transient_end]);
  return out;
}

std::vector<Eigen::Vector4d> sampleRotorTimeResponse(const LateralRotorModel& model,
                                                     const std::vector<double>& times,
                                                     double relative_tolerance,
                                                     double absolute_tolerance) {
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (!std::isfinite(times[i]) || times[i] < 0.0 || (i > 0 && !(times[i] > times[i - 1]))) {
      throw InputError("times", fmt::format("index {}: {:g}", i, times[i]),
                       "times must be finite, >= 0 and increasing");
    }
  }
  std::vector<double> grid;
  grid.reserve(times.size() + 1);
  if (times.empty() || times.front() > 0.0) grid.push_back(0.0);
  grid.insert(grid.end(), times.begin(), times.end());
  const std::size_t offset = grid.size() - times.size();
  std::vector<Eigen::Vector4d> out(times.size());
  long long evaluations = 0;
  integrateOnGrid(model, grid, relative_tolerance, absolute_tolerance, &evaluations,
                  [&](std::size_t i, const Eigen::Vector4d& eta) {
                    if (i >= offset) out[i - offset] = eta;
                  });
  return out;
}

std::vector<RotorWhirlResponse> solveRotorFrequencyResponse(const LateralRotorModel& model) {
  const Eigen::Matrix2cd k = model.stiffness2().cast<Complex>();
  const Eigen::Matrix2cd m = model.mass2().cast<Complex>();
  const Eigen::Matrix2cd c = model.damping2().cast<Complex>();
  std::vector<RotorWhirlResponse> out;
  for (const WhirlForcing& f : model.whirlForcing()) {
    const double w = f.omega;
    const Eigen::Matrix2cd a = k - w * w * m + Complex(0.0, w) * c;
    out.push_back({f.name, w, a.partialPivLu().solve(f.force)});
  }
  return out;
}

std::vector<Eigen::Vector4d> superposeWhirlResponse(const std::vector<RotorWhirlResponse>& parts,
                                                    const std::vector<double>& times) {
  std::vector<Eigen::Vector4d> out(times.size(), Eigen::Vector4d::Zero());
  for (std::size_t i = 0; i < times.size(); ++i) {
    Complex z1 = 0.0, z2 = 0.0;
    for (const auto& p : parts) {
      const Complex e = std::polar(1.0, p.omega * times[i]);
      z1 += p.response(0) * e;
      z2 += p.response(1) * e;
    }
    out[i] = Eigen::Vector4d(z1.real(), z1.imag(), z2.real(), z2.imag());
  }
  return out;
}

}  // namespace geardyn
