#pragma once
/// \file
/// Spelling suggestions for unknown keys, choices and names (configuration keys, CSV columns,
/// housing node sets): used by every layer, so it depends on nothing.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace geardyn {

/// Optimal-string-alignment edit distance (insertions, deletions, substitutions and adjacent
/// transpositions each cost 1) between a and b.
int editDistance(std::string_view a, std::string_view b);

/// The candidate closest to `word` if it is close enough to be a plausible misspelling: an edit
/// distance of at most max(1, |word| / 3), or `word` being a prefix of it; none otherwise.
std::optional<std::string> closestMatch(std::string_view word,
                                        const std::vector<std::string>& candidates);

}  // namespace geardyn
