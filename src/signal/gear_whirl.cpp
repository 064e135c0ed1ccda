#include "geardyn/signal/gear_whirl.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "geardyn/error.h"

namespace geardyn {

void GearWhirlSetup::validate() const {
  if (!(pinion_speed > 0.0) || !std::isfinite(pinion_speed)) {
    throw InputError("pinion_speed", fmt::format("{:g}", pinion_speed),
                     "must be finite and > 0 [rev/s]");
  }
  if (pinion_teeth < 2 || gear_teeth < 2) {
    throw InputError(pinion_teeth < 2 ? "pinion_teeth" : "gear_teeth",
                     fmt::format("{}", pinion_teeth < 2 ? pinion_teeth : gear_teeth),
                     "an integer >= 2");
  }
  if (harmonics < 0 || harmonics > 1000) {
    throw InputError("harmonics", fmt::format("{}", harmonics), "an integer in [0, 1000]");
  }
}

double GearWhirlSetup::commonPeriod() const {
  return (gear_teeth / std::gcd(pinion_teeth, gear_teeth)) / pinion_speed;
}

std::vector<WhirlComponent> gearWhirlComponents(const GearWhirlSetup& setup) {
  setup.validate();
  std::vector<WhirlComponent> out;
  out.push_back({"static", 0.0, 0.0});
  for (int i = 1; i <= setup.harmonics; ++i) {
    out.push_back({fmt::format("mesh_{}_fwd", i), i * setup.meshFrequency(), 0.0});
    out.push_back({fmt::format("mesh_{}_bwd", i), -i * setup.meshFrequency(), 0.0});
  }
  out.push_back({"pinion_1x_fwd", setup.pinion_speed, 0.0});
  out.push_back({"pinion_1x_bwd", -setup.pinion_speed, 0.0});
  out.push_back({"gear_1x_fwd", setup.gearSpeed(), 0.0});
  out.push_back({"gear_1x_bwd", -setup.gearSpeed(), 0.0});
  return out;
}

WhirlComponent inShaftFrame(const WhirlComponent& c, bool shaft_turns_negative) {
  if (!shaft_turns_negative) return c;
  WhirlComponent out{c.name, -c.frequency, std::conj(c.value)};
  const auto swap = [&](const std::string& from, const std::string& to) {
    const auto at = c.name.rfind(from);
    if (at != std::string::npos && at + from.size() == c.name.size())
      out.name = c.name.substr(0, at) + to;
  };
  swap("_fwd", "_bwd");
  swap("_bwd", "_fwd");
  return out;
}

GearPairSpectrum analyseGearPairRecord(const std::array<std::vector<double>, 4>& channels,
                                       double sample_rate, double first_sample_time,
                                       double reference_time, const GearWhirlSetup& setup,
                                       const GearPairSpectrumOptions& options) {
  GearPairSpectrum out;
  for (int shaft = 0; shaft < 2; ++shaft) {
    const auto& x = channels[2 * shaft];
    const auto& y = channels[2 * shaft + 1];
    std::vector<WhirlComponent> components = gearWhirlComponents(setup);
    out.method = extractWhirlComponents(x, y, sample_rate, components, options.method);
    // The residual after removing every component (phasors by recurrence: one rotation each).
    {
      const std::size_t n = x.size(), m = components.size();
      std::vector<std::complex<double>> phasor(m), step(m);
      for (std::size_t c = 0; c < m; ++c) {
        phasor[c] = components[c].value;
        step[c] = std::polar(1.0, 2.0 * std::numbers::pi * components[c].frequency / sample_rate);
      }
      double power = 0.0;
      for (std::size_t k = 0; k < n; ++k) {
        std::complex<double> r(x[k], y[k]);
        for (std::size_t c = 0; c < m; ++c) {
          r -= phasor[c];
          phasor[c] *= step[c];
        }
        power += std::norm(r);
      }
      const double dof = static_cast<double>(n > m ? n - m : 1);
      out.coefficient_sigma[shaft] = std::sqrt(power / dof / static_cast<double>(n));
    }
    const bool turns_negative = shaft == 0 && options.frame == WhirlFrame::kShaft;
    for (auto& c : components) {
      c.value *= std::polar(
          1.0, 2.0 * std::numbers::pi * c.frequency * (reference_time - first_sample_time));
      c = inShaftFrame(c, turns_negative);
    }
    out.peaks[shaft] = std::move(components);
    FullSpectrum display = fullSpectrum(x, y, sample_rate, options.display_window);
    if (turns_negative) {  // z* has the spectrum Z*(−f): reverse and conjugate
      FullSpectrum flipped;
      for (std::size_t i = display.frequency.size(); i-- > 0;) {
        flipped.frequency.push_back(-display.frequency[i]);
        flipped.coefficient.push_back(std::conj(display.coefficient[i]));
      }
      display = std::move(flipped);
    }
    out.display[shaft] = std::move(display);
  }
  return out;
}

std::array<std::vector<WhirlComponent>, 2> inFrame(std::array<std::vector<WhirlComponent>, 2> peaks,
                                                   WhirlFrame frame) {
  if (frame == WhirlFrame::kShaft)
    for (auto& c : peaks[0]) c = inShaftFrame(c, true);
  return peaks;
}

KeyphasorPulses findKeyphasorPulses(const std::vector<double>& keyphasor, double sample_rate,
                                    double start_time, double threshold,
                                    double max_speed_variation) {
  if (!(sample_rate > 0.0) || !std::isfinite(sample_rate)) {
    throw InputError("sample_rate", fmt::format("{:g}", sample_rate),
                     "must be finite and > 0 [Hz]");
  }
  for (std::size_t i = 0; i < keyphasor.size(); ++i) {
    if (!std::isfinite(keyphasor[i])) {
      throw InputError("keyphasor", fmt::format("sample {} = {}", i, keyphasor[i]),
                       "keyphasor samples must be finite");
    }
  }
  KeyphasorPulses out;
  if (keyphasor.size() < 2) {
    throw InputError("keyphasor", fmt::format("{} samples", keyphasor.size()),
                     "need a record with at least two once-per-revolution pulses");
  }
  const auto [lo, hi] = std::minmax_element(keyphasor.begin(), keyphasor.end());
  out.threshold = std::isnan(threshold) ? 0.5 * (*lo + *hi) : threshold;
  if (!(*hi > out.threshold && *lo < out.threshold)) {
    throw InputError(
        "keyphasor", fmt::format("values in [{:g}, {:g}]", *lo, *hi),
        fmt::format("no pulses: the channel never crosses the threshold {:g}", out.threshold));
  }
  for (std::size_t i = 1; i < keyphasor.size(); ++i) {
    const double a = keyphasor[i - 1], b = keyphasor[i];
    if (a < out.threshold && b >= out.threshold) {
      const double fraction = (out.threshold - a) / (b - a);
      out.times.push_back(start_time + (static_cast<double>(i - 1) + fraction) / sample_rate);
    }
  }
  if (out.times.size() < 2) {
    throw InputError("keyphasor", fmt::format("{} pulse(s)", out.times.size()),
                     "need at least two once-per-revolution pulses (one whole revolution)");
  }
  std::vector<double> intervals;
  for (std::size_t i = 1; i < out.times.size(); ++i)
    intervals.push_back(out.times[i] - out.times[i - 1]);
  std::vector<double> sorted = intervals;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double median = sorted[sorted.size() / 2];
  for (std::size_t i = 0; i < intervals.size(); ++i) {
    if (std::abs(intervals[i] / median - 1.0) > max_speed_variation) {
      throw InputError("keyphasor",
                       fmt::format("revolution {} ({:.6g} s to {:.6g} s) lasts {:.6g} s", i + 1,
                                   out.times[i], out.times[i + 1], intervals[i]),
                       fmt::format("revolutions must last the median {:.6g} s within {:g} % "
                                   "(missing or extra pulse, or a speed change)",
                                   median, 100 * max_speed_variation));
    }
  }
  out.speed = static_cast<double>(out.times.size() - 1) / (out.times.back() - out.times.front());
  return out;
}

double keyphasorSignal(double t, double speed, double sample_rate) {
  double phase = std::fmod(t * speed, 1.0);
  if (phase < 0.0) phase += 1.0;
  const double since = phase / speed, to_next = (1.0 - phase) / speed;
  const double ramp = 4.0 / sample_rate, high = 0.1 / speed;
  if (to_next < ramp / 2) return 0.5 - to_next / ramp;
  if (since < ramp / 2) return 0.5 + since / ramp;
  if (since < high) return 1.0;
  if (since < high + ramp) return 1.0 - (since - high) / ramp;
  return 0.0;
}

}  // namespace geardyn
