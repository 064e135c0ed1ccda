/// Case generation of parameter studies (see the header).

#include "geardyn/stats/study_design.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "geardyn/error.h"

namespace geardyn {
namespace {

/// SplitMix64 (Steele, Lea & Flood 2014): a well-mixed 64-bit stream from any seed.
struct SplitMix64 {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  /// Uniform in (0, 1): 53 random bits, never 0.
  double uniform() { return (static_cast<double>(next() >> 11) + 0.5) * 0x1.0p-53; }
  /// Standard normal by Box–Muller (both uniforms from this stream; no cached state, so the
  /// draws depend only on the stream position).
  double normal() {
    const double u1 = uniform(), u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }
};

std::string keyOf(const StudyParameter& p) {
  return "study.parameters." + p.key;
}

}  // namespace

std::uint64_t caseSeed(std::uint64_t study_seed, long long index) {
  SplitMix64 mix{study_seed ^ (0xd1b54a32d192ed03ULL * static_cast<std::uint64_t>(index + 1))};
  return mix.next();
}

long long StudyParameter::valueCount() const {
  return linspace_num > 0 ? linspace_num : static_cast<long long>(values.size());
}

nlohmann::json StudyParameter::valueAt(long long i) const {
  if (linspace_num <= 0) return values[static_cast<std::size_t>(i)];
  const double x = linspace_num == 1 ? min
                                     : min + (max - min) * static_cast<double>(i) /
                                                 static_cast<double>(linspace_num - 1);
  if (linspace_integers) return std::llround(x);
  return x;
}

void StudyParameter::validate(StudyDesign design) const {
  const std::string k = keyOf(*this);
  if (design != StudyDesign::kRandom) {
    if (distribution != StudyDistribution::kValues)
      throw InputError(k, toString(distribution),
                       "a list of values (or {min, max, num}) in a grid or zip design");
    if (valueCount() == 0) throw InputError(k, "[]", "at least one value");
    return;
  }
  auto finite = [&](double v, const char* name) {
    if (!std::isfinite(v))
      throw InputError(k + "." + name, fmt::format("{:g}", v), "a finite number");
  };
  switch (distribution) {
    case StudyDistribution::kValues:
      if (valueCount() == 0) throw InputError(k, "[]", "at least one value to draw from");
      break;
    case StudyDistribution::kUniform:
      finite(min, "min"), finite(max, "max");
      if (!(max > min)) throw InputError(k + ".max", fmt::format("{:g}", max), "max > min");
      break;
    case StudyDistribution::kNormal:
      finite(mean, "mean"), finite(std, "std");
      if (!(std > 0)) throw InputError(k + ".std", fmt::format("{:g}", std), "std > 0");
      break;
    case StudyDistribution::kTruncatedNormal:
      finite(mean, "mean"), finite(std, "std"), finite(min, "min"), finite(max, "max");
      if (!(std > 0)) throw InputError(k + ".std", fmt::format("{:g}", std), "std > 0");
      if (!(max > min)) throw InputError(k + ".max", fmt::format("{:g}", max), "max > min");
      if ((max - mean) / std < -6.0 || (min - mean) / std > 6.0)
        throw InputError(k, fmt::format("[{:g}, {:g}]", min, max),
                         "truncation bounds within 6 std of the mean (else nothing is drawn)");
      break;
  }
}

long long studyCaseCount(StudyDesign design, const std::vector<StudyParameter>& parameters,
                         long long samples) {
  if (parameters.empty()) throw InputError("study.parameters", "{}", "at least one parameter");
  for (const auto& p : parameters) p.validate(design);
  if (design == StudyDesign::kRandom) {
    if (samples < 1) throw InputError("study.samples", std::to_string(samples), "an integer >= 1");
    return samples;
  }
  long long count = design == StudyDesign::kGrid ? 1 : -1;
  for (const auto& p : parameters) {
    const long long n = p.valueCount();
    if (design == StudyDesign::kGrid) {
      if (count > (1LL << 40) / n)
        throw InputError("study.parameters", "", "a grid of at most 2^40 cases");
      count *= n;
    } else if (count < 0) {
      count = n;
    } else if (count != n) {
      throw InputError(keyOf(p), fmt::format("{} values", n),
                       fmt::format("{} values, as many as the other zipped parameters", count));
    }
  }
  return count;
}

StudyCase studyCase(StudyDesign design, const std::vector<StudyParameter>& parameters,
                    long long index, std::uint64_t seed) {
  StudyCase c;
  c.index = index;
  c.seed = caseSeed(seed, index);
  c.values.resize(parameters.size());
  if (design == StudyDesign::kGrid) {
    long long rest = index;
    for (std::size_t i = parameters.size(); i-- > 0;) {
      const long long n = parameters[i].valueCount();
      c.values[i] = parameters[i].valueAt(rest % n);
      rest /= n;
    }
  } else if (design == StudyDesign::kZip) {
    for (std::size_t i = 0; i < parameters.size(); ++i) c.values[i] = parameters[i].valueAt(index);
  } else {
    SplitMix64 stream{c.seed};
    for (std::size_t i = 0; i < parameters.size(); ++i) {
      const StudyParameter& p = parameters[i];
      switch (p.distribution) {
        case StudyDistribution::kValues:
          c.values[i] = p.valueAt(
              static_cast<long long>(stream.next() % static_cast<std::uint64_t>(p.valueCount())));
          break;
        case StudyDistribution::kUniform:
          c.values[i] = p.min + (p.max - p.min) * stream.uniform();
          break;
        case StudyDistribution::kNormal:
          c.values[i] = p.mean + p.std * stream.normal();
          break;
        case StudyDistribution::kTruncatedNormal: {
          double x = 0.0;
          for (int attempt = 0;; ++attempt) {  // rejection: acceptance >= ~1e-9 by validate()
            x = p.mean + p.std * stream.normal();
            if (x >= p.min && x <= p.max) break;
            if (attempt > 100000000)
              throw InputError(keyOf(p), "", "a truncation range that can be sampled");
          }
          c.values[i] = x;
          break;
        }
      }
    }
  }
  return c;
}

std::string toString(StudyDesign design) {
  switch (design) {
    case StudyDesign::kGrid:
      return "grid";
    case StudyDesign::kZip:
      return "zip";
    case StudyDesign::kRandom:
      return "random";
  }
  return "?";
}

std::string toString(StudyDistribution distribution) {
  switch (distribution) {
    case StudyDistribution::kValues:
      return "values";
    case StudyDistribution::kUniform:
      return "uniform";
    case StudyDistribution::kNormal:
      return "normal";
    case StudyDistribution::kTruncatedNormal:
      return "truncated_normal";
  }
  return "?";
}

}  // namespace geardyn
