#pragma once
/// \file
/// One line per kind of warning (issue #33): a gearbox whose five meshes share a condition, or
/// a REXS file with 24 capped bearing stiffnesses, gets one line naming the components, not one
/// line each. summary.json keeps every warning as it was raised.
///
/// A warning of the form "<subject>: <text>" (or "note: <subject>: <text>", geardyn/notes.h) is
/// of the same kind as another when their texts agree once their numbers are masked ("+0.73 %"
/// and "+1.1 %" agree).

#include <string>
#include <vector>

#include "geardyn/notes.h"

namespace geardyn::analysis {

/// `warnings` with every kind that occurs more than once folded into its first occurrence:
/// "<first warning> (the same for <n> more: <subject>, …; each in summary.json)", at most
/// `max_named` subjects named. Order of first occurrences kept; exact duplicates dropped.
/// Sainsot's fillet-foundation notes of several meshes are one line naming the meshes and the
/// largest change of k̄ (stiffness/foundation_fit_note.h).
std::vector<std::string> groupedWarnings(const std::vector<std::string>& warnings,
                                         int max_named = 8);

}  // namespace geardyn::analysis
