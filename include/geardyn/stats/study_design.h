#pragma once
/// \file
/// The cases of a parameter study (issue #9): a full-factorial or zipped grid over lists of
/// values, or a random sample from per-parameter distributions. Every case's random draws come
/// from its own stream, seeded from (study seed, case index) by SplitMix64, so a case's values
/// are bit-identical whatever the number of threads or MPI ranks and whichever subset is run
/// (resuming a sweep recomputes exactly the missing cases).

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace geardyn {

enum class StudyDesign { kGrid, kZip, kRandom };
enum class StudyDistribution { kValues, kUniform, kNormal, kTruncatedNormal };

/// One swept configuration key.
struct StudyParameter {
  std::string key;                     ///< dotted configuration key ("excitation.torque")
  std::vector<nlohmann::json> values;  ///< grid / zip: numbers, strings or booleans
  /// {min, max, num}: `num` evenly spaced values from min to max, generated on demand (never
  /// materialised, so a billion-point axis costs nothing until its cases run); 0: use `values`.
  long long linspace_num = 0;
  bool linspace_integers = false;  ///< integer endpoints and steps: the values are integers
  StudyDistribution distribution = StudyDistribution::kValues;
  double mean = 0.0, std = 0.0;  ///< normal, truncated normal
  double min = 0.0, max = 0.0;   ///< uniform; truncation bounds
  /// Throws InputError naming "study.parameters.<key>" for an inconsistent definition.
  void validate(StudyDesign design) const;
  /// Number of listed values (linspace_num or values.size()).
  long long valueCount() const;
  /// Listed value i (0 ≤ i < valueCount()).
  nlohmann::json valueAt(long long i) const;
};

/// The value of each parameter in one case (same order as the parameters).
struct StudyCase {
  long long index = 0;
  std::vector<nlohmann::json> values;
  std::uint64_t seed = 0;  ///< the case's own seed (also handed to the command if asked)
};

/// SplitMix64 of the study seed and the case index: the case's stream seed.
std::uint64_t caseSeed(std::uint64_t study_seed, long long index);

/// Number of cases of a design: the product of the list lengths (grid), their common length
/// (zip; InputError when they differ) or `samples` (random).
long long studyCaseCount(StudyDesign design, const std::vector<StudyParameter>& parameters,
                         long long samples);

/// Case `index` of the design (0 ≤ index < studyCaseCount). Grid order: the last parameter
/// varies fastest.
StudyCase studyCase(StudyDesign design, const std::vector<StudyParameter>& parameters,
                    long long index, std::uint64_t seed);

std::string toString(StudyDesign design);
std::string toString(StudyDistribution distribution);

}  // namespace geardyn
