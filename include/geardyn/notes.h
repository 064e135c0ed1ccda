#pragma once
/// \file
/// Warnings that change no number of a result (an uncertainty, an extrapolation) start with
/// kNotePrefix: the command line prints them as notes and `--quiet` silences them (issue #33);
/// summary.json keeps them with the other warnings.

#include <string>
#include <string_view>

namespace geardyn {

/// The start of a warning that changes no number ("note: Sainsot's fit is extrapolated ...").
inline constexpr std::string_view kNotePrefix = "note: ";

/// Whether `warning` is a note (starts with kNotePrefix).
inline bool isNote(std::string_view warning) {
  return warning.substr(0, kNotePrefix.size()) == kNotePrefix;
}

/// `context` + ": " + `warning`, kept a note when it is one ("note: meshes.m1: ...").
inline std::string inContext(const std::string& context, const std::string& warning) {
  if (!isNote(warning)) return context + ": " + warning;
  return std::string(kNotePrefix) + context + ": " + warning.substr(kNotePrefix.size());
}

}  // namespace geardyn
