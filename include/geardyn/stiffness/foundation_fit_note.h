#pragma once
/// \file
/// The note raised when Sainsot's (2004) fillet-foundation fit is extrapolated (issue #34), in
/// one place: its text (potential_energy_stiffness.cpp raises it per mesh), its parse (the run's
/// summary.json lists the affected meshes under `foundation_fit_extrapolated`) and the one line
/// per run that stands for all of a run's such notes (analysis/warning_groups.cpp).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace geardyn {

/// One mesh whose members' foundation fits are extrapolated.
struct FoundationFitExtrapolation {
  std::string subject;               ///< the mesh ("meshes.stage1 (fourier model)"; "" for a pair)
  std::vector<std::string> members;  ///< "pinion", "gear" or both
  std::string
      detail;  ///< the coefficients and their data ("pinion: M* = 1.04 (data 1.08 to 3.29)")
  /// Relative change of the mean mesh stiffness k̄ with the fits held at their data range
  /// (-0.0309: -3.09 %), the expected size of k̄'s error; as printed, to 1e-4.
  double mean_stiffness_change = 0.0;
};

/// The note for one pair: "note: Sainsot's (2004) fillet-foundation fit is extrapolated
/// (<detail>): held at its data range the mean mesh stiffness changes by <±x.xx> %, ...".
std::string foundationFitWarning(const std::string& detail, double mean_stiffness_change);

/// The note's parts when `warning` is such a note (in context: "note: <subject>: ..."), else none.
std::optional<FoundationFitExtrapolation> parseFoundationFitWarning(std::string_view warning);

/// One line for several notes: the affected meshes and members (at most `max_named` named) and
/// the largest change of k̄ with its mesh; where the list is (summary.json).
std::string foundationFitSummaryLine(const std::vector<FoundationFitExtrapolation>& notes,
                                     int max_named = 8);

}  // namespace geardyn
