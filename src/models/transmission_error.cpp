#include "geardyn/models/transmission_error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/stiffness/mesh_stiffness.h"

namespace geardyn {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
/// A phase this close to a table point [mesh periods] is on it: far above the round-off of a
/// phase of up to 10⁶ periods (2e-10), far below any table spacing (tables have at most 10⁶
/// points per period).
constexpr double kOnTablePoint = 1e-9;

void requireFinite(const std::vector<double>& values, const std::string& key) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) {
      throw InputError(fmt::format("{}[{}]", key, i), fmt::format("{}", values[i]),
                       "must be finite");
    }
  }
}

}  // namespace

void TransmissionError::addFourier(std::vector<double> amplitudes, std::vector<double> phases,
                                   const std::string& amplitudes_key,
                                   const std::string& phases_key) {
  if (phases.empty()) phases.assign(amplitudes.size(), 0.0);
  if (amplitudes.size() != phases.size()) {
    throw InputError(phases_key, fmt::format("{} values", phases.size()),
                     fmt::format("one phase per amplitude of {} ({} values), or none (all 0)",
                                 amplitudes_key, amplitudes.size()));
  }
  requireFinite(amplitudes, amplitudes_key);
  requireFinite(phases, phases_key);
  if (amplitudes.size() > amplitudes_.size()) {
    amplitudes_.resize(amplitudes.size(), 0.0);
    phases_.resize(amplitudes.size(), 0.0);
  }
  // Sum harmonic by harmonic (a cos(x + p) + b cos(x + q) is again one harmonic).
  for (std::size_t r = 0; r < amplitudes.size(); ++r) {
    const double re = amplitudes_[r] * std::cos(phases_[r]) + amplitudes[r] * std::cos(phases[r]);
    const double im = amplitudes_[r] * std::sin(phases_[r]) + amplitudes[r] * std::sin(phases[r]);
    amplitudes_[r] = std::hypot(re, im);
    phases_[r] = std::atan2(im, re);
  }
}

void TransmissionError::addRectangular(double amplitude, double duty, double start,
                                       const std::string& key) {
  if (!std::isfinite(amplitude))
    throw InputError(key + ".rectangular_amplitude", fmt::format("{}", amplitude),
                     "must be finite");
  if (!(duty > 0.0 && duty < 1.0)) {
    throw InputError(key + ".rectangular_duty", fmt::format("{:g}", duty), "must be in (0, 1)");
  }
  if (!std::isfinite(start))
    throw InputError(key + ".rectangular_start", fmt::format("{}", start), "must be finite");
  rect_amplitude_ = amplitude;
  rect_duty_ = duty;
  rect_start_ = wrapPhase(start);
}

void TransmissionError::addTable(std::vector<double> phases, std::vector<double> values,
                                 const std::string& key) {
  if (phases.size() != values.size()) {
    throw InputError(key + ".table_values", fmt::format("{} values", values.size()),
                     fmt::format("need one value per phase ({} phases)", phases.size()));
  }
  requireFinite(phases, key + ".table_phases");
  requireFinite(values, key + ".table_values");
  for (std::size_t i = 0; i < phases.size(); ++i) {
    if (phases[i] < 0.0 || phases[i] >= 1.0 || (i > 0 && !(phases[i] > phases[i - 1]))) {
      throw InputError(fmt::format("{}.table_phases[{}]", key, i), fmt::format("{:g}", phases[i]),
                       "the phases must increase strictly within [0, 1)");
    }
  }
  table_phases_ = std::move(phases);
  table_values_ = std::move(values);
}

TransmissionError TransmissionError::scaled(double factor) const {
  TransmissionError e = *this;
  for (double& a : e.amplitudes_) a *= factor;
  e.rect_amplitude_ *= factor;
  for (double& v : e.table_values_) v *= factor;
  return e;
}

bool TransmissionError::isZero() const noexcept {
  for (double a : amplitudes_) {
    if (a != 0.0) return false;
  }
  return rect_amplitude_ == 0.0 && table_phases_.empty();
}

TransmissionError::TableSegment TransmissionError::tableSegment(double phase) const {
  // Periodic linear interpolation: after the last point the table runs to the first point + 1.
  const double p = wrapPhase(phase);
  const std::size_t n = table_phases_.size();
  const std::size_t hi =
      static_cast<std::size_t>(std::upper_bound(table_phases_.begin(), table_phases_.end(), p) -
                               table_phases_.begin()) %
      n;
  const std::size_t lo = (hi + n - 1) % n;
  const double x0 = table_phases_[lo];
  const double x1 = table_phases_[hi] <= x0 ? table_phases_[hi] + 1.0 : table_phases_[hi];
  return {lo, hi, x0, x1, p < x0 ? p + 1.0 : p};
}

double TransmissionError::value(double phase) const {
  double e = 0.0;
  for (std::size_t r = 0; r < amplitudes_.size(); ++r) {
    e += amplitudes_[r] * std::cos(kTwoPi * (r + 1) * phase + phases_[r]);
  }
  if (rect_amplitude_ != 0.0 && wrapPhase(phase - rect_start_) < rect_duty_) e += rect_amplitude_;
  if (!table_phases_.empty()) {
    const TableSegment t = tableSegment(phase);
    const double w = t.x1 > t.x0 ? (t.x - t.x0) / (t.x1 - t.x0) : 0.0;
    e += table_values_[t.lo] + w * (table_values_[t.hi] - table_values_[t.lo]);
  }
  return e;
}

double TransmissionError::derivative(double phase) const {
  double d = 0.0;
  for (std::size_t r = 0; r < amplitudes_.size(); ++r) {
    d -= amplitudes_[r] * kTwoPi * (r + 1) * std::sin(kTwoPi * (r + 1) * phase + phases_[r]);
  }
  if (table_phases_.size() > 1) {
    // The slope of segment i (from table point i to the next, periodically).
    const std::size_t n = table_phases_.size();
    const auto slope = [&](std::size_t i) {
      const std::size_t j = (i + 1) % n;
      const double width = table_phases_[j] - table_phases_[i] + (j <= i ? 1.0 : 0.0);
      return (table_values_[j] - table_values_[i]) / width;
    };
    // On a table point the slope jumps. A fixed-step integrator lands there (Newmark with a
    // multiple of the table's points per period), and round-off in the phase, which grows with
    // time, would pick either side from one period to the next: the discrete system would not
    // be periodic and never settle (issue 21). The mean of the one-sided slopes is the same
    // every period, and with it the trapezoidal rule integrates the jump exactly.
    const TableSegment t = tableSegment(phase);
    if (t.x - t.x0 <= kOnTablePoint) {
      d += 0.5 * (slope((t.lo + n - 1) % n) + slope(t.lo));
    } else if (t.x1 - t.x <= kOnTablePoint) {
      d += 0.5 * (slope(t.lo) + slope(t.hi));
    } else {
      d += slope(t.lo);
    }
  }
  return d;
}

}  // namespace geardyn
