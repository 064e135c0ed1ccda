#include "geardyn/solvers/time_response.h"

#include <fmt/format.h>

#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <deque>

#include "geardyn/error.h"

namespace geardyn {
namespace {

using OscillatorState = std::array<double, 2>;

/// Size of the deflection, for relative tolerances: static deflection, error, clearance.
double deflectionScale(const GearPairModel& model) {
  double scale = std::abs(model.meanForce()) / model.stiffness(0.0) + model.backlash();
  for (int i = 0; i < 16; ++i)
    scale = std::max(scale, std::abs(model.transmissionError().value(i / 16.0)));
  return scale > 0.0 ? scale : 1.0;
}

double staticDeflection(const GearPairModel& model) {
  const double f = model.meanForce();
  const double y = f / model.stiffness(0.0);
  double shift = 0.0;
  if (model.contact() == ContactLaw::kBacklash && f != 0.0)
    shift = f > 0 ? model.backlash() : -model.backlash();
  if (model.contact() == ContactLaw::kOneSided && f <= 0.0) return model.error(0.0);
  return y + shift + model.error(0.0);
}

struct OdeSystem {
  const GearPairModel& model;
  void operator()(const OscillatorState& s, OscillatorState& ds, double t) const {
    ds[0] = s[1];
    ds[1] = model.acceleration(t, s[0], s[1]);
  }
};

}  // namespace

std::string toString(TimeResponseStatus status) {
  switch (status) {
    case TimeResponseStatus::kSteadyState:
      return "converged";
    case TimeResponseStatus::kMaxPeriods:
      return "max_periods";
    case TimeResponseStatus::kDiverged:
      return "diverged";
    case TimeResponseStatus::kNewtonFailure:
      return "newton_failure";
  }
  return "?";
}

void TimeResponseOptions::validate() const {
  newmark.validate();
  const auto positive_int = [](const char* key, int value, int low) {
    if (value < low)
      throw InputError(key, std::to_string(value), fmt::format("must be >= {}", low));
  };
  positive_int("solver.output_points_per_period", output_points_per_period, 4);
  positive_int("solver.steps_per_period", steps_per_period, 4);
  if (steps_per_period % output_points_per_period != 0) {
    throw InputError("solver.steps_per_period", std::to_string(steps_per_period),
                     fmt::format("must be a multiple of solver.output_points_per_period = {}",
                                 output_points_per_period));
  }
  positive_int("solver.min_periods", min_periods, 2);
  positive_int("solver.max_periods", max_periods, min_periods);
  positive_int("solver.output_periods", output_periods, 1);
  positive_int("solver.max_newton_iterations", max_newton_iterations, 1);
  for (const auto& [key, value] : {std::pair{"solver.relative_tolerance", relative_tolerance},
                                   std::pair{"solver.absolute_tolerance", absolute_tolerance},
                                   std::pair{"solver.newton_tolerance", newton_tolerance},
                                   std::pair{"solver.steady_tolerance", steady_tolerance}}) {
    if (!(value > 0.0) || !std::isfinite(value)) {
      throw InputError(key, fmt::format("{:g}", value), "must be finite and > 0");
    }
  }
}

NewmarkState integrateNewmark(const GearPairModel& model, NewmarkParameters parameters, double t0,
                              double h, long long n, double x, double v, double newton_tolerance) {
  const NewmarkStepper<GearPairModel> stepper(model, parameters,
                                              newton_tolerance * deflectionScale(model));
  NewmarkState s{x, v, stepper.initialAcceleration(t0, x, v)};
  for (long long i = 0; i < n; ++i) stepper.step(t0 + i * h, h, s);
  return s;
}

std::pair<double, double> integrateDormandPrince(const GearPairModel& model, double t0, double t1,
                                                 double x, double v, double rtol, double atol) {
  namespace odeint = boost::numeric::odeint;
  OscillatorState s{x, v};
  auto stepper =
      odeint::make_dense_output(atol, rtol, odeint::runge_kutta_dopri5<OscillatorState>());
  odeint::integrate_adaptive(stepper, OdeSystem{model}, s, t0, t1, (t1 - t0) / 100.0);
  return {s[0], s[1]};
}

TimeResponse solveTimeResponse(const GearPairModel& model, const TimeResponseOptions& options) {
  options.validate();
  TimeResponse out;
  const double f_m = model.meshFrequency();
  out.period = f_m > 0.0 ? 1.0 / f_m : options.period;
  if (!(out.period > 0.0) || !std::isfinite(out.period)) {
    throw InputError("TimeResponseOptions.period", fmt::format("{:g} s", options.period),
                     "with a mesh frequency of 0 the period of the extra forces must be given "
                     "(> 0)");
  }
  const double T = out.period;
  const int m = options.output_points_per_period;
  const double scale = deflectionScale(model);

  double x = options.start_from_static ? staticDeflection(model) : options.initial_displacement;
  double v = options.start_from_static ? 0.0 : options.initial_velocity;

  const NewmarkStepper<GearPairModel> stepper(
      model, options.newmark, options.newton_tolerance * scale, options.max_newton_iterations);
  NewmarkState s{x, v, stepper.initialAcceleration(0.0, x, v)};
  const int substeps = options.steps_per_period / m;
  const double h = T / options.steps_per_period;

  namespace odeint = boost::numeric::odeint;
  OscillatorState ode{x, v};

  struct Period {
    std::vector<double> x, v;
  };
  std::deque<Period> recent;  // the last output_periods periods
  std::vector<double> previous;
  int steady_at = -1;
  out.status = TimeResponseStatus::kMaxPeriods;

  for (int p = 0; p < options.max_periods; ++p) {
    const double t_start = p * T;
    Period period;
    period.x.reserve(m);
    period.v.reserve(m);
    if (options.method == TimeIntegrator::kNewmark) {
      for (int k = 0; k < m; ++k) {
        period.x.push_back(s.x);
        period.v.push_back(s.v);
        for (int j = 0; j < substeps; ++j) {
          const NewmarkStepReport report = stepper.step(t_start + (k * substeps + j) * h, h, s);
          out.max_newton_iterations = std::max(out.max_newton_iterations, report.iterations);
          if (!report.converged) ++out.newton_failures;
        }
        out.steps += substeps;
      }
    } else {
      std::vector<double> times(m + 1);
      for (int k = 0; k <= m; ++k) times[k] = t_start + k * T / m;
      auto dense =
          odeint::make_dense_output(options.absolute_tolerance * scale, options.relative_tolerance,
                                    odeint::runge_kutta_dopri5<OscillatorState>());
      int index = 0;
      out.steps += static_cast<long long>(
          odeint::integrate_times(dense, OdeSystem{model}, ode, times.begin(), times.end(), T / m,
                                  [&](const OscillatorState& state, double) {
                                    if (index++ < m) {
                                      period.x.push_back(state[0]);
                                      period.v.push_back(state[1]);
                                    }
                                  }));
    }
    out.periods = p + 1;
    if (options.progress) options.progress(out.periods, options.max_periods);

    double peak = 0.0;
    bool finite = true;
    for (double value : period.x) {
      finite = finite && std::isfinite(value);
      peak = std::max(peak, std::abs(value));
    }
    if (!finite || peak > 1e8 * scale) {
      out.status = TimeResponseStatus::kDiverged;
      out.message = fmt::format(
          "the response grew without bound (|x| = {:.3g} after {} periods): "
          "parametric instability or an unstable integrator step",
          peak, out.periods);
      recent.push_back(std::move(period));
      if (static_cast<int>(recent.size()) > options.output_periods) recent.pop_front();
      break;
    }
    if (!previous.empty()) {
      double change = 0.0;
      for (int k = 0; k < m; ++k) change = std::max(change, std::abs(period.x[k] - previous[k]));
      out.last_change = change / std::max(peak, scale);
    }
    previous = period.x;
    recent.push_back(std::move(period));
    if (static_cast<int>(recent.size()) > options.output_periods) recent.pop_front();

    // Steady once a period agrees with the one before, and only while every later one does:
    // a change that rises again (a beat, a chaotic or quasi-periodic response) starts the count
    // anew, so that the returned periods all agree to steady_tolerance (issue 21).
    if (out.periods >= options.min_periods && out.last_change <= options.steady_tolerance) {
      if (steady_at < 0) steady_at = out.periods;
    } else {
      steady_at = -1;
    }
    // Once steady, keep integrating until output_periods steady periods are at hand.
    if (steady_at >= 0 && out.periods >= steady_at + options.output_periods - 1) {
      out.status = TimeResponseStatus::kSteadyState;
      break;
    }
  }

  if (out.newton_failures > 0 && out.status != TimeResponseStatus::kDiverged) {
    out.status = TimeResponseStatus::kNewtonFailure;
  }
  const int first_period = out.periods - static_cast<int>(recent.size());
  for (std::size_t q = 0; q < recent.size(); ++q) {
    for (int k = 0; k < m; ++k) {
      out.t.push_back((first_period + static_cast<double>(q)) * T + k * T / m);
      out.x.push_back(recent[q].x[k]);
      out.v.push_back(recent[q].v[k]);
    }
  }
  if (out.message.empty()) {
    switch (out.status) {
      case TimeResponseStatus::kSteadyState:
        out.message = fmt::format("steady state after {} periods (relative change [-] {:.2g})",
                                  out.periods, out.last_change);
        break;
      case TimeResponseStatus::kMaxPeriods:
        out.message =
            steady_at < 0
                ? fmt::format("no steady state after {} periods (last change {:.2g} > {:.2g})",
                              out.periods, out.last_change, options.steady_tolerance)
                : fmt::format(
                      "no steady state after {} periods: the change between periods (last "
                      "{:.2g}) stayed within {:.2g} for only the last {} of the {} periods "
                      "needed (output_periods)",
                      out.periods, out.last_change, options.steady_tolerance,
                      out.periods - steady_at + 1, options.output_periods);
        break;
      case TimeResponseStatus::kNewtonFailure:
        out.message = fmt::format("{} Newmark steps did not converge in {} Newton iterations",
                                  out.newton_failures, options.max_newton_iterations);
        break;
      case TimeResponseStatus::kDiverged:
        break;
    }
  }
  return out;
}

}  // namespace geardyn
