/// A train's steady state recorded from rest (train_periodic_record.h).

#include "geardyn/solvers/train_periodic_record.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "geardyn/error.h"

namespace geardyn {
namespace {

/// Integrates onto `times` and stores the sample of times[i] in row `row_of(i)` of `rows`
/// (a second matrix takes the samples the caller tags as shifted).
template <class Store>
void integrateOnto(const GearTrainModel& model, double input_speed, const std::vector<int>& dofs,
                   const std::vector<double>& times, const TrainRecordOptions& options,
                   TrainRecord& out, Store store) {
  const TrainDormandPrinceRun run = integrateTrainDormandPrince(
      model, input_speed, times, dofs, options.integrator,
      [&](std::size_t i, const Eigen::VectorXd& q, const Eigen::VectorXd&, const Eigen::VectorXd&) {
        store(i, q);
      });
  out.steps = run.steps;
  out.rhs_evaluations = run.rhs_evaluations;
  if (!run.finite) {
    out.status = TrainRecordStatus::kNonFinite;
    out.message = "the integration produced non-finite values";
  }
}

}  // namespace

void TrainRecordOptions::validate() const {
  if (!(duration > 0.0) || !std::isfinite(duration)) {
    throw InputError("time.duration", fmt::format("{:g}", duration), "must be finite and > 0 [s]");
  }
  if (samples < 16 || samples > 200'000'000) {
    throw InputError("time.samples", fmt::format("{}", samples), "an integer in [16, 2e8]");
  }
  if (!(steady_tolerance > 0.0 && steady_tolerance < 1.0)) {
    throw InputError("time.steady_tolerance", fmt::format("{:g}", steady_tolerance),
                     "a number in (0, 1)");
  }
  integrator.validate();
}

std::string toString(TrainRecordStatus status) {
  switch (status) {
    case TrainRecordStatus::kSteadyState:
      return "steady_state";
    case TrainRecordStatus::kTransient:
      return "transient_not_decayed";
    case TrainRecordStatus::kNonFinite:
      return "non_finite";
  }
  return "unknown";
}

TrainRecord recordTrainFromRest(const GearTrainModel& model, double input_speed,
                                const std::vector<int>& dofs, double common_period,
                                const TrainRecordOptions& options) {
  options.validate();
  if (!(common_period > 0.0) || !std::isfinite(common_period)) {
    throw InputError("common_period", fmt::format("{:g} s", common_period), "finite and > 0");
  }
  TrainRecord out;
  out.common_period = common_period;
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
  const auto channels = static_cast<Eigen::Index>(dofs.size());
  out.displacement.resize(count, channels);
  // On a grid not aligned to T_c the periodicity check needs q(t_k + T_c) off the grid: the
  // integrator's dense output gives it, on the merged grid (tagged: ≥ count = shifted sample).
  Eigen::MatrixXd shifted;
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
    shifted.resize(static_cast<Eigen::Index>(merged.size()) - count, channels);
    integrateOnto(model, input_speed, dofs, times, options, out,
                  [&](std::size_t i, const Eigen::VectorXd& q) {
                    const long long tag = merged[i].second;
                    if (tag < count) {
                      out.displacement.row(tag) = q.transpose();
                    } else {
                      shifted.row(tag - count) = q.transpose();
                    }
                  });
  } else {
    integrateOnto(model, input_speed, dofs, out.t, options, out,
                  [&](std::size_t i, const Eigen::VectorXd& q) {
                    out.displacement.row(static_cast<Eigen::Index>(i)) = q.transpose();
                  });
  }
  if (out.status == TrainRecordStatus::kNonFinite) return out;
  // Transient: q(t + T_c) = q(t) once the homogeneous part has decayed (the steady state is
  // T_c-periodic). Scale: the largest |q| over the last common period.
  const long long n = out.samples_per_period > 0
                          ? out.samples_per_period
                          : std::llround(out.common_period * out.sample_rate);
  if (n >= count) {
    out.status = TrainRecordStatus::kTransient;
    out.message = fmt::format(
        "the record ({:g} s) is shorter than one common period ({:g} s): lengthen time.duration",
        out.t.back(), out.common_period);
    return out;
  }
  const double scale =
      channels == 0 ? 0.0 : out.displacement.bottomRows(n + 1).cwiseAbs().maxCoeff();
  const double limit = options.steady_tolerance * scale;
  long long last_bad = -1;
  const long long comparable = shifted.size() == 0 && out.samples_per_period > 0
                                   ? count - n
                                   : static_cast<long long>(shifted.rows());
  for (long long k = 0; k < comparable && channels > 0; ++k) {
    const auto later = shifted.rows() == 0 ? out.displacement.row(k + n) : shifted.row(k);
    if ((later - out.displacement.row(k)).cwiseAbs().maxCoeff() > limit) last_bad = k;
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
    out.status = TrainRecordStatus::kTransient;
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

}  // namespace geardyn
